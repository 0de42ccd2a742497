// CityEngine's envelope operation (CGA reference, "envelope operation"): a building envelope
// erected over a flat shape. Each edge of the outline gets a base height and, above it, a plane
// sloping inwards at the edge's angle; the volume is the prism up to the maximum height ("If this
// height is reached, the volume is cut and sealed horizontally") below those planes.
//
// Method: kernel::extrude builds the prism up to the maximum height; each sloped edge then takes
// away the space above its plane within its zone (bounded where its plane meets its neighbours'),
// a convex solid cut from a box by kernel::split, subtracted with kernel::boolean3d. Limiting
// each plane to its zone keeps an L's inner planes out of the other wing and hole edges' planes
// out of the rest; every step keeps the mesh closed.
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "kernel/boolean3d.h"
#include "kernel/extrude.h"
#include "kernel/plane_split.h"
#include "shape/ops.h"

namespace insula::shape {

using kernel::Vec3;

namespace {

constexpr double kUnset = -1;  // the default of an optional side: outside the declared range
constexpr double kZoneOverlap = 1e-5;  // meters neighbouring zones overlap (zone_boundary)

// The side an edge belongs to by its outward direction in the object frame read as CityEngine's
// (x, y up, z = front): the reference classifies edges with street.* selectors and falls back to
// object.* without street data, as Insula always does.
const EnvelopeSide& side_of(const EnvelopeSpec& spec, Vec3 outward_world, const Scope& object) {
  const Vec3 z_front = object.size.z == 0 ? -object.y : object.z;
  const double along_x = kernel::dot(outward_world, object.x);
  const double along_z = kernel::dot(outward_world, z_front);
  if (std::fabs(along_z) >= std::fabs(along_x)) return along_z >= 0 ? spec.front : spec.back;
  return along_x >= 0 ? spec.right : spec.left;
}

std::string check_side(const EnvelopeSide& side) {
  if (!(side.base_height >= 0) || !std::isfinite(side.base_height)) {
    return "base heights must be finite and >= 0";
  }
  if (!(side.angle >= 0 && side.angle <= 90)) return "angles must lie in [0, 90] degrees";
  return {};
}

std::string check_spec(const EnvelopeSpec& spec) {
  if (!(spec.max_height > 0) || !std::isfinite(spec.max_height)) {
    return "the maximum height must be finite and > 0";
  }
  for (const EnvelopeSide* side : {&spec.front, &spec.back, &spec.right, &spec.left}) {
    if (std::string error = check_side(*side); !error.empty()) return error;
  }
  return {};
}

// The plane of an edge from a to b (scope space, z = 0) whose material lies on the side
// `outward` points away from: it contains the edge raised by the base height along `up` and
// leans inwards at `angle` degrees from the horizontal (90: the wall itself).
kernel::Plane slope_plane(Vec3 a, Vec3 b, Vec3 outward, Vec3 up, const EnvelopeSide& side) {
  const Vec3 edge = kernel::normalized(b - a);
  const Vec3 rise = kernel::normalized(up - edge * kernel::dot(up, edge));
  const double angle = side.angle * std::numbers::pi / 180;
  const Vec3 normal = outward * std::sin(angle) + rise * std::cos(angle);
  return {normal, kernel::dot(normal, a + up * side.base_height)};
}

struct EdgePlane {
  Vec3 a, b;  // the edge, scope space
  kernel::Plane plane;
  bool sloped = false;
};

// One plane per outline edge, per ring (outer ring, then holes, as the outline stores them).
std::vector<std::vector<EdgePlane>> edge_planes(const kernel::Polygon& outline,
                                                const EnvelopeSpec& spec, Vec3 up,
                                                const Scope& scope, const Scope& object) {
  std::vector<std::vector<EdgePlane>> rings;
  const auto ring_planes = [&](const kernel::Ring& ring, bool hole) {
    // Material lies left of a counter-clockwise outer ring and right of a clockwise hole.
    const bool ccw = kernel::signed_area(ring) > 0;
    const double sign = ccw != hole ? 1 : -1;
    std::vector<EdgePlane>& planes = rings.emplace_back();
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const kernel::Vec2 p = ring[i];
      const kernel::Vec2 q = ring[(i + 1) % ring.size()];
      const Vec3 a{p.x, p.y, 0};
      const Vec3 b{q.x, q.y, 0};
      if (kernel::length(b - a) < 1e-12) continue;
      const Vec3 outward = kernel::normalized(kernel::cross(b - a, up)) * sign;
      const EnvelopeSide& side = side_of(spec, scope.direction_to_world(outward), object);
      planes.push_back({a, b, slope_plane(a, b, outward, up, side), side.angle < 90});
    }
  };
  ring_planes(outline.outer, false);
  for (const kernel::Ring& hole : outline.holes) ring_planes(hole, true);
  return rings;
}

// Where edge e's plane stops governing next to its neighbour f (sharing a vertex): the vertical
// plane through the line where their planes meet (f's wall when f does not slope), as a weighted
// straight skeleton's first bisector; oriented so e lies on its negative side. Only neighbours
// are considered, so later skeleton events are not (exact for rectangles and L shapes).
kernel::Plane zone_boundary(const EdgePlane& e, const EdgePlane& f, Vec3 up) {
  const Vec3 v = kernel::length(f.a - e.b) < kernel::length(f.b - e.a) ? e.b : e.a;
  Vec3 normal = kernel::cross(f.b - f.a, up);
  Vec3 point = v;
  if (f.sloped) {
    const Vec3 ne = e.plane.normal;
    const Vec3 nf = f.plane.normal;
    normal = kernel::cross(kernel::cross(ne, nf), up);
    const double c = kernel::dot(ne, nf);
    const double det = 1 - c * c;
    if (kernel::length(normal) < 1e-9 || det < 1e-12) {
      normal = e.b - e.a;  // parallel planes: straight across at the shared vertex
    } else {
      const double re = e.plane.offset - kernel::dot(ne, v);
      const double rf = f.plane.offset - kernel::dot(nf, v);
      point = v + ne * ((re - c * rf) / det) + nf * ((rf - c * re) / det);
    }
  }
  normal = kernel::normalized(normal);
  if (kernel::dot(normal, (e.a + e.b) * 0.5 - point) > 0) normal = normal * -1;
  // A little past the boundary, so neighbouring zones overlap instead of sharing a plane (the
  // corefinement of coplanar faces leaves slivers); the overlap takes nothing a neighbour keeps,
  // but at a valley a strip kZoneOverlap wide.
  return {normal, kernel::dot(normal, point) + kZoneOverlap};
}

// Keeps the part of `mesh` on the negative side of `plane`; caps tagged `tag`.
kernel::Mesh keep_below(const kernel::Mesh& mesh, const kernel::Plane& plane, kernel::FaceTag tag) {
  kernel::SplitOptions options;
  options.cap_tag = tag;
  kernel::SplitResult cut = kernel::split(mesh, plane, options);
  return cut.ok() ? std::move(cut.negative) : kernel::Mesh{};
}

// A closed box around `bounds` grown by `margin` on every side.
kernel::Mesh big_box(const kernel::Bounds3& bounds, double margin) {
  const Vec3 lo = bounds.min - Vec3{margin, margin, margin};
  const Vec3 size = bounds.size() + Vec3{2 * margin, 2 * margin, 2 * margin};
  const std::array<kernel::FaceTag, 6> tags = mass_box_tags();
  kernel::Mesh box = *box_mesh(size, tags);
  for (Vec3& p : box.positions()) p = p + lo;
  return box;
}

// What edge e takes away: the space above its plane within its zone, a convex solid cut from a
// box larger than the prism.
kernel::Mesh removed_by(std::span<const EdgePlane> ring, std::size_t k, Vec3 up,
                        const kernel::Bounds3& bounds, kernel::FaceTag tag) {
  const EdgePlane& e = ring[k];
  const EdgePlane& before = ring[(k + ring.size() - 1) % ring.size()];
  const EdgePlane& after = ring[(k + 1) % ring.size()];
  const double margin = kernel::length(bounds.size()) + 1;
  kernel::Mesh solid = big_box(bounds, margin);
  solid = keep_below(solid, {e.plane.normal * -1, -e.plane.offset}, tag);
  solid = keep_below(solid, zone_boundary(e, before, up), tag);
  return keep_below(solid, zone_boundary(e, after, up), tag);
}

// The erection direction in scope space: the normal, or world up (+Z) for world.up.
std::optional<Vec3> up_direction(const Scope& scope, bool world_up) {
  if (!world_up) return Vec3{0, 0, 1};
  const Vec3 up = kernel::normalized(scope.direction_to_local({0, 0, 1}));
  if (!(up.z > 1e-6)) return std::nullopt;  // a vertical or downward face
  return up;
}

// Prism over the outline erected `height` meters along `up`: the extrusion along the normal
// sheared so that its sides run along `up` (the identity for the normal; up.z > 0 keeps the
// faces outward).
kernel::ExtrudeResult prism(const kernel::Polygon& outline, Vec3 up, double height) {
  kernel::ExtrudeResult result = kernel::extrude(outline, 0, height);
  for (Vec3& p : result.mesh.positions()) p = Vec3{p.x, p.y, 0} + up * p.z;
  return result;
}

// Takes every sloped edge's zone above its plane out of the prism (kernel::boolean3d), so
// each plane governs only its own side of a valley at a reflex corner or around a hole.
std::string cut_slopes(kernel::Mesh& mesh, const std::vector<std::vector<EdgePlane>>& rings,
                       Vec3 up) {
  const kernel::Bounds3 bounds = mesh.bounds();
  std::uint32_t face_id = 2;
  for (const std::vector<EdgePlane>& ring : rings)
    face_id += static_cast<std::uint32_t>(ring.size());
  for (const std::vector<EdgePlane>& ring : rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      if (!ring[k].sloped) continue;  // a vertical plane through the edge is the wall: no cut
      const kernel::FaceTag tag{kernel::SemanticClass::kRoofSurface, 0, face_id++};
      const kernel::Mesh removed = removed_by(ring, k, up, bounds, tag);
      if (removed.empty()) continue;
      kernel::Boolean3dResult cut =
          kernel::boolean3d(mesh, removed, kernel::BooleanOp::kDifference);
      if (cut.status != kernel::Boolean3dStatus::kOk) return "slope cut failed: " + cut.message;
      mesh = std::move(cut.mesh);
      if (mesh.empty()) return "the slopes leave no volume above the shape";
    }
  }
  return {};
}

}  // namespace

OpResult envelope(ShapeTree& tree, ShapeId id, const EnvelopeSpec& spec, const Scope* object) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (std::string error = check_spec(spec); !error.empty()) return OpResult::failure(error);
  const std::optional<Vec3> up = up_direction(s.scope, spec.world_up);
  if (!up) return OpResult::failure("world.up needs a face that does not face sideways or down");
  kernel::ExtrudeResult built = prism(*s.outline, *up, spec.max_height);
  if (!built.ok()) {
    return OpResult::failure(std::string(kernel::extrude_status_message(built.status)));
  }
  const Scope& frame = object != nullptr ? *object : tree[tree.root_of(id)].scope;
  kernel::Mesh mesh = std::move(built.mesh);
  if (std::string error = cut_slopes(mesh, edge_planes(*s.outline, spec, *up, s.scope, frame), *up);
      !error.empty()) {
    return OpResult::failure(error);
  }
  // Oriented like an extrusion: x as before, y along the face normal (up), z = x cross y.
  return replace_with(tree, id, mesh, {1, 0, 0}, {0, 0, 1}, {0, -1, 0});
}

namespace {

ParamDecl height_param(std::string name, std::string doc, std::optional<ArgValue> fallback) {
  return {std::move(name), ParamType::kNumber, std::move(doc), std::move(fallback), {}, 0.0, {}};
}

ParamDecl angle_param(std::string name, std::string doc, std::optional<ArgValue> fallback) {
  return {std::move(name), ParamType::kNumber, std::move(doc), std::move(fallback), {}, 0.0, 90.0};
}

// An optional side's value, or `fallback`'s when the parameter kept its default.
EnvelopeSide side_from(const Arguments& a, const std::string& name, const EnvelopeSide& fallback) {
  EnvelopeSide side = fallback;
  if (a.number(name + "_base_height") != kUnset) side.base_height = a.number(name + "_base_height");
  if (a.number(name + "_angle") != kUnset) side.angle = a.number(name + "_angle");
  return side;
}

EnvelopeSpec spec_from(const Arguments& a) {
  EnvelopeSpec spec;
  spec.world_up = a.string("direction") == "world.up";
  spec.max_height = a.number("max_height");
  spec.front = {a.number("front_base_height"), a.number("front_angle")};
  spec.back = side_from(a, "back", spec.front);
  spec.right = side_from(a, "right", spec.front);
  spec.left = side_from(a, "left", spec.right);
  return spec;
}

}  // namespace

std::vector<Operation> envelope_operations() {
  const ArgValue unset{kUnset};
  std::vector<Operation> ops;
  ops.push_back(
      {"envelope",
       "CityEngine's building envelope over a flat shape: each edge rises to its side's base "
       "height, then a plane slopes inwards at its angle; the volume is cut flat at the maximum "
       "height. Sides by the edge's outward direction in the object frame.",
       {{"direction",
         ParamType::kEnum,
         "erect along the face normal or world up",
         std::nullopt,
         {"normal", "world.up"},
         {},
         {}},
        {"max_height",
         ParamType::kNumber,
         "maximum height (meters, > 0): the volume is cut and sealed there",
         std::nullopt,
         {},
         0.0,
         {}},
        height_param("front_base_height", "front edges: base height (meters)", std::nullopt),
        angle_param("front_angle", "front edges: slope from the horizontal (degrees; 90: none)",
                    std::nullopt),
        height_param("back_base_height", "back edges: base height; -1: the front's", unset),
        angle_param("back_angle", "back edges: slope; -1: the front's", unset),
        height_param("right_base_height",
                     "right edges (both sides when no left is given): base height; -1: the "
                     "front's",
                     unset),
        angle_param("right_angle", "right edges (both sides without left): slope; -1: the front's",
                    unset),
        height_param("left_base_height", "left edges: base height; -1: the right's", unset),
        angle_param("left_angle", "left edges: slope; -1: the right's", unset)},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context& context) {
         return envelope(t, id, spec_from(a), context.object);
       }});
  return ops;
}

}  // namespace insula::shape
