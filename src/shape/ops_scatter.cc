// CityEngine's scatter operation (CGA reference, "scatter": scatter(domain, nPoints,
// distributionType) and scatter(domain, nPoints, gaussian, scatterMean, scatterStddev)): point
// shapes at random places on the faces, inside the closed mesh or inside the scope box, for
// trees on a lot, stones on a wall. The reference says the children have a zero-size scope and
// no geometry to speak of (one vertex: "you might want to use the i operation"), and that scatter
// "does not affect the rotation of child shapes unless domain is set to surface", where the
// child's y is the surface normal. Differences from CityEngine: docs/operations-cityengine.md.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel/mesh_sample.h"
#include "shape/ops.h"

namespace insula::shape {

using kernel::Vec3;

namespace {

// Rejection sampling (inside a mesh, a gaussian inside the box) gives up on a point after this
// many draws and takes the nearest admissible place instead, so a thin mesh in a large bounding
// box or a mean far outside the shape cannot hang a derivation.
constexpr int kMaxDraws = 1000;
// Mixed into the shape's seed so the points do not repeat the stream its children's seeds come
// from (rng.h: child_seed).
constexpr std::uint64_t kScatterSalt = 0x5ca7'7e25'ca77'e2d1ULL;

struct Box {
  Vec3 min;
  Vec3 max;
  bool contains(Vec3 p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
           p.z <= max.z;
  }
  Vec3 clamp(Vec3 p) const {
    return {std::clamp(p.x, min.x, max.x), std::clamp(p.y, min.y, max.y),
            std::clamp(p.z, min.z, max.z)};
  }
};

// How a candidate point is drawn, in the shape's scope space.
struct Distribution {
  bool gaussian = false;
  Vec3 mean;
  Vec3 sigma;  // per scope axis
};

// A standard normal deviate (Box-Muller; 1 - u keeps the logarithm's argument in (0, 1]).
double normal_deviate(Rng& rng) {
  const double radius = std::sqrt(-2.0 * std::log(1.0 - rng.unit()));
  return radius * std::cos(2.0 * std::numbers::pi * rng.unit());
}

Vec3 draw(Rng& rng, const Distribution& d, const Box& box) {
  if (!d.gaussian) {
    return {rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y),
            rng.uniform(box.min.z, box.max.z)};
  }
  return {d.mean.x + d.sigma.x * normal_deviate(rng), d.mean.y + d.sigma.y * normal_deviate(rng),
          d.mean.z + d.sigma.z * normal_deviate(rng)};
}

// CityEngine's scatterMean words as fractions of its scope (x, y up, z towards the front).
std::optional<Vec3> mean_fractions(std::string_view word) {
  if (word == "center") return Vec3{0.5, 0.5, 0.5};
  if (word == "left") return Vec3{0, 0.5, 0.5};
  if (word == "right") return Vec3{1, 0.5, 0.5};
  if (word == "bottom") return Vec3{0.5, 0, 0.5};
  if (word == "top") return Vec3{0.5, 1, 0.5};
  if (word == "back") return Vec3{0.5, 0.5, 0};
  if (word == "front") return Vec3{0.5, 0.5, 1};
  return std::nullopt;
}

// A point in CityEngine's scope frame in Insula's scope space: a flat shape's CityEngine y is its
// normal (Insula's z) and its CityEngine z runs along -y from the far side (ops_primitive.cc).
Vec3 from_cityengine(const Shape& s, Vec3 fractions) {
  const Vec3 size = s.scope.size;
  if (s.is_flat()) return {fractions.x * size.x, size.y - fractions.z * size.y, 0};
  return {fractions.x * size.x, fractions.y * size.y, fractions.z * size.z};
}

struct Placed {
  Vec3 local;   // scope space
  Vec3 normal;  // scope space; zero: keep the shape's axes
};

std::vector<Placed> in_scope(Rng& rng, const Distribution& d, Vec3 size, std::size_t count) {
  // A mirrored scope (negative size, CityEngine's s(-w, ...)) spans [size, 0] on that axis.
  const Box box{{std::min(size.x, 0.0), std::min(size.y, 0.0), std::min(size.z, 0.0)},
                {std::max(size.x, 0.0), std::max(size.y, 0.0), std::max(size.z, 0.0)}};
  std::vector<Placed> out;
  for (std::size_t k = 0; k < count; ++k) {
    Vec3 p = draw(rng, d, box);
    for (int tries = 1; !box.contains(p) && tries < kMaxDraws; ++tries) p = draw(rng, d, box);
    out.push_back({box.clamp(p), {}});
  }
  return out;
}

// Uniform points by area; gaussian ones as the surface point nearest to a gaussian draw, which
// keeps the cluster on the faces (on a flat lot: the 2D gaussian, clamped to the outline).
std::vector<Placed> on_surface(Rng& rng, const Distribution& d, const kernel::MeshSurface& surface,
                               std::size_t count) {
  std::vector<Placed> out;
  for (std::size_t k = 0; k < count; ++k) {
    kernel::SurfacePoint p;
    if (d.gaussian) {
      p = surface.nearest(draw(rng, d, {}));
    } else {
      const double pick = rng.unit();
      const double u = rng.unit();
      p = surface.at(pick, u, rng.unit());
    }
    out.push_back({p.position, p.normal});
  }
  return out;
}

// Rejection sampling inside the mesh's bounds by the winding number; after kMaxDraws misses the
// surface point nearest to the last draw.
std::vector<Placed> in_volume(Rng& rng, const Distribution& d, const kernel::MeshSurface& surface,
                              const kernel::Bounds3& bounds, std::size_t count) {
  const Box box{bounds.min, bounds.max};
  std::vector<Placed> out;
  for (std::size_t k = 0; k < count; ++k) {
    Vec3 p = draw(rng, d, box);
    bool inside = surface.winding_number(p) > 0.5;
    for (int tries = 1; !inside && tries < kMaxDraws; ++tries) {
      p = draw(rng, d, box);
      inside = surface.winding_number(p) > 0.5;
    }
    out.push_back({inside ? p : surface.nearest(p).position, {}});
  }
  return out;
}

// The child's axes: the shape's as CityEngine sees them (a flat shape's normal is y, its z runs
// along -y), or on a surface y = the face's normal with x the shape's x laid into the face (its
// z where x is the normal).
Scope point_scope(const Shape& s, const Placed& p) {
  Scope scope = s.scope;
  scope.origin = s.scope.to_world(p.local);
  scope.size = {};
  if (s.is_flat()) {
    scope.y = s.scope.z;
    scope.z = -s.scope.y;
  }
  if (kernel::length(p.normal) == 0) return scope;
  const Vec3 up = kernel::normalized(s.scope.direction_to_world(p.normal));
  Vec3 x = scope.x - up * kernel::dot(scope.x, up);
  if (kernel::length(x) < 1e-9) x = scope.z - up * kernel::dot(scope.z, up);
  scope.x = kernel::normalized(x);
  scope.y = up;
  scope.z = kernel::cross(scope.x, up);
  return scope;
}

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Checks what the registry's declarations cannot: a usable scope, mesh and deviation.
std::string invalid_input(const Shape& s, const ScatterOptions& o) {
  if (o.count > kMaxScatterPoints) {
    return "at most " + std::to_string(kMaxScatterPoints) + " points; got " +
           std::to_string(o.count);
  }
  if (!finite(s.scope.origin) || !finite(s.scope.size)) return "the scope is not finite";
  if (!mean_fractions(o.mean)) return "unknown mean '" + o.mean + "'";
  if (o.stddev.mode == SizeMode::kFloating || !(o.stddev.value >= 0) ||
      !std::isfinite(o.stddev.value)) {
    return "the standard deviation must be meters or relative ('), >= 0 and finite";
  }
  if (o.domain == ScatterDomain::kScope) return {};
  if (!s.mesh || s.mesh->empty()) return "the shape has no faces to scatter on";
  for (const Vec3& p : s.mesh->positions()) {
    if (!finite(p)) return "the geometry has non-finite coordinates";
  }
  return {};
}

Distribution distribution_of(const Shape& s, const ScatterOptions& o) {
  Distribution d;
  d.gaussian = o.gaussian;
  d.mean = from_cityengine(s, mean_fractions(o.mean).value_or(Vec3{0.5, 0.5, 0.5}));
  const double v = o.stddev.value;
  d.sigma = o.stddev.mode == SizeMode::kRelative ? s.scope.size * v : Vec3{v, v, v};
  // No spread along an axis the scope has no extent on (a flat shape's normal), where an
  // absolute deviation would only make draws that fall off the scope.
  const Vec3 size = s.scope.size;
  d.sigma = {size.x == 0 ? 0 : std::abs(d.sigma.x), size.y == 0 ? 0 : std::abs(d.sigma.y),
             size.z == 0 ? 0 : std::abs(d.sigma.z)};
  return d;
}

// The points for a shape that has faces (surface or volume), with the volume's fallback.
std::vector<Placed> on_mesh(Rng& rng, const Distribution& d, const Shape& s,
                            const ScatterOptions& o, OpResult& result) {
  const kernel::MeshSurface surface(*s.mesh);
  if (surface.empty()) {
    result.error = "the shape's faces have no area";
    return {};
  }
  if (o.domain == ScatterDomain::kVolume) {
    if (kernel::is_watertight(*s.mesh)) {
      return in_volume(rng, d, surface, s.mesh->bounds(), o.count);
    }
    // CityEngine: "volume only works if applied to a closed surface geometry; if the mesh is
    // not closed, the operation falls back to surface".
    result.warning = "the mesh is not closed: points placed on its surface instead of inside";
  }
  return on_surface(rng, d, surface, o.count);
}

}  // namespace

OpResult scatter(ShapeTree& tree, ShapeId id, const ScatterOptions& options) {
  const Shape& s = tree[id];
  if (std::string error = invalid_input(s, options); !error.empty()) {
    return OpResult::failure(std::move(error));
  }
  OpResult result;
  if (options.count == 0) return result;  // nothing to place (no mesh needed either)
  Rng rng(mix64(s.seed ^ kScatterSalt));
  const Distribution d = distribution_of(s, options);
  std::vector<Placed> points = options.domain == ScatterDomain::kScope
                                   ? in_scope(rng, d, s.scope.size, options.count)
                                   : on_mesh(rng, d, s, options, result);
  if (!result.ok()) return result;
  for (const Placed& p : points) result.add(tree.add_child(id, point_scope(s, p)), 0);
  return finish(tree, id, std::move(result));
}

namespace {

OpResult run_scatter(ShapeTree& t, ShapeId id, const Arguments& a) {
  ScatterOptions o;
  const std::string& domain = a.string("domain");
  o.domain = domain == "volume"  ? ScatterDomain::kVolume
             : domain == "scope" ? ScatterDomain::kScope
                                 : ScatterDomain::kSurface;
  // CityEngine takes a float; a fraction of a point is dropped (its own plant library rounds
  // with rint() before it calls scatter).
  o.count = static_cast<std::size_t>(std::floor(a.number("count")));
  o.gaussian = a.string("distribution") == "gaussian";
  o.mean = a.string("mean");
  o.stddev = a.size("stddev");
  return scatter(t, id, o);
}

}  // namespace

std::vector<Operation> scatter_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"scatter",
       "Places `count` point shapes (zero-size scopes, no geometry) at random from the shape's "
       "seed: on the faces by area (surface), inside the closed mesh (volume; an open one falls "
       "back to surface) or inside the scope (scope); uniform, or gaussian around `mean` with "
       "deviation `stddev`. On a surface a point's scope y is the face normal (CGA scatter).",
       {{"domain",
         ParamType::kEnum,
         "where the points go",
         std::nullopt,
         {"surface", "volume", "scope"},
         {},
         {}},
        {"count",
         ParamType::kNumber,
         "number of points (a fraction is dropped)",
         std::nullopt,
         {},
         0.0,
         static_cast<double>(kMaxScatterPoints)},
        {"distribution",
         ParamType::kEnum,
         "random distribution",
         ArgValue{std::string("uniform")},
         {"uniform", "gaussian"},
         {},
         {}},
        {"mean",
         ParamType::kEnum,
         "gaussian only: the scope position the points cluster around",
         ArgValue{std::string("center")},
         {"center", "front", "back", "left", "right", "top", "bottom"},
         {},
         {}},
        {"stddev",
         ParamType::kSize,
         "gaussian only: standard deviation in meters, or relative ('): a fraction of each "
         "scope extent",
         ArgValue{SizeSpec{0.16, SizeMode::kRelative}},
         {},
         0.0,
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return run_scatter(t, id, a);
       }});
  return ops;
}

}  // namespace insula::shape
