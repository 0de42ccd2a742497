// CityEngine's insertAlongUV (CGA reference, "insertAlongUV operation"): an asset bent along the
// shape's texture coordinates. The asset's x extent maps to u over [0, 1] and its z extent to -v
// over [0, 1], both repeated wherever the uv set runs past a whole number; its y extent becomes
// `height` meters along the scope's y axis or the shape's vertex normals.
//
// Method: the asset is moved into (u, v, h) space (h in [0, 1]). A uv set is an affine map of
// world space (uv_map.h), so on each planar face it is invertible unless the face is seen edge-on
// in uv. Each face is triangulated in uv; for every whole-number tile the triangle's uv bounds
// touch, a copy of the asset is cut by the triangle's three edge planes (kernel::split without
// caps, so vertical faces of the asset are cut too) and carried back to the face by the
// triangle's barycentric coordinates, lifted by h * height along the height direction. As
// CityEngine notes, the cuts leave coplanar edges and collinear vertices (cleanupGeometry
// removes them). docs/operations-cityengine.md, "insertAlongUV".
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "kernel/plane_split.h"
#include "kernel/triangulate.h"
#include "shape/ops.h"
#include "shape/uv_map.h"

namespace insula::shape {

using kernel::Vec2;
using kernel::Vec3;

namespace {

constexpr std::size_t kMaxCopies = 200000;  // asset pieces one call may cut (a runaway uv scale)

enum class HeightDirection : std::uint8_t { kScopeY, kScopeZ, kVertexNormal };

struct AlongUvOptions {
  int uv_set = 0;
  double height = 0;
  HeightDirection direction = HeightDirection::kScopeY;
  bool keep_position = false;  // CityEngine's keepPosition: h relative to the asset's origin
};

// The asset in (u, v, h) space: x over its extent -> u in [0, 1], z -> v = 1 - (z - zmin) / dz,
// y -> h in [0, 1] (keepPosition: y / dy, so the origin stays at h = 0). An axis of no extent
// maps to 0.
kernel::Mesh to_uvh(const kernel::Mesh& asset, bool keep_position) {
  const kernel::Bounds3 b = asset.bounds();
  const Vec3 size = b.size();
  const auto scale = [](double extent) { return extent > 0 ? 1 / extent : 0.0; };
  const double fx = scale(size.x), fy = scale(size.y), fz = scale(size.z);
  kernel::Mesh out = asset;
  for (Vec3& p : out.positions()) {
    const double h = keep_position ? p.y * fy : (p.y - b.min.y) * fy;
    p = {(p.x - b.min.x) * fx, 1 - (p.z - b.min.z) * fz, h};
  }
  return out;
}

// One triangle of the shape: its corners in uv and in world space, and the height direction
// at each corner.
struct UvTriangle {
  std::array<Vec2, 3> uv;  // counter-clockwise
  std::array<Vec3, 3> world;
  std::array<Vec3, 3> lift;  // unit height directions
};

std::array<double, 3> barycentric(const UvTriangle& t, Vec2 p) {
  const double area = kernel::cross(t.uv[1] - t.uv[0], t.uv[2] - t.uv[0]);
  const double a = kernel::cross(t.uv[1] - p, t.uv[2] - p) / area;
  const double b = kernel::cross(t.uv[2] - p, t.uv[0] - p) / area;
  return {a, b, 1 - a - b};
}

// The part of `piece` (uvh space) over the triangle: cut by each edge's plane, the inside kept.
kernel::Mesh clip_to(const kernel::Mesh& piece, const UvTriangle& t) {
  kernel::SplitOptions options;
  options.cap = false;
  kernel::Mesh kept = piece;
  for (std::size_t k = 0; k < 3 && !kept.empty(); ++k) {
    const Vec2 a = t.uv[k], e = t.uv[(k + 1) % 3] - a;
    // Inside (left of a counter-clockwise edge): dot((-e.y, e.x), p - a) >= 0.
    const Vec3 outward{e.y, -e.x, 0};
    kernel::SplitResult cut = kernel::split(kept, {outward, e.y * a.x - e.x * a.y}, options);
    if (!cut.ok()) return {};
    kept = std::move(cut.negative);
  }
  return kept;
}

// Carries `piece` (uvh space, inside the triangle) to world space and appends it to `out`,
// turning its faces round where the mapping mirrors them.
void place(const kernel::Mesh& piece, const UvTriangle& t, double height, kernel::Mesh& out) {
  const auto map = [&](Vec3 q) {
    const std::array<double, 3> w = barycentric(t, {q.x, q.y});
    const Vec3 lift = t.lift[0] * w[0] + t.lift[1] * w[1] + t.lift[2] * w[2];
    return t.world[0] * w[0] + t.world[1] * w[1] + t.world[2] * w[2] + lift * (q.z * height);
  };
  kernel::Mesh placed = piece;
  for (Vec3& p : placed.positions()) p = map(p);
  // (u, v, h) -> world keeps orientation when d/du x d/dv points along the lift.
  const Vec3 centre_lift = t.lift[0] + t.lift[1] + t.lift[2];
  const Vec3 du = map({1, 0, 0}) - map({0, 0, 0});
  const Vec3 dv = map({0, 1, 0}) - map({0, 0, 0});
  if (dot(kernel::cross(du, dv), centre_lift) * height < 0) placed.flip();
  out.append(placed);
}

// Per-vertex normals of `mesh` (scope space): area-weighted face normals summed over the
// vertices at one position (CityEngine computes them from adjacent faces once duplicates are
// merged), positions keyed on a 1e-6 m grid.
std::vector<Vec3> vertex_normals(const kernel::Mesh& mesh) {
  using Key = std::array<long long, 3>;
  const auto key = [&](std::uint32_t v) {
    const Vec3 p = mesh.position(v) * 1e6;
    return Key{std::llround(p.x), std::llround(p.y), std::llround(p.z)};
  };
  std::map<Key, Vec3> sums;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Vec3 n = kernel::face_normal(mesh, f) * kernel::face_area(mesh, f);
    for (std::uint32_t v : mesh.face(f)) sums[key(v)] = sums[key(v)] + n;
  }
  std::vector<Vec3> out(mesh.vertex_count());
  for (std::uint32_t v = 0; v < out.size(); ++v) {
    const Vec3 sum = sums[key(v)];
    const double n = kernel::length(sum);
    out[v] = n > 0 ? sum * (1 / n) : Vec3{0, 0, 1};
  }
  return out;
}

// The shape's faces as triangles in uv (faces seen edge-on in uv are skipped).
std::vector<UvTriangle> uv_triangles(const Shape& s, const UvMap& map, HeightDirection direction) {
  std::vector<UvTriangle> out;
  const kernel::Mesh& mesh = *s.mesh;
  std::vector<Vec3> normals;
  if (direction == HeightDirection::kVertexNormal) normals = vertex_normals(mesh);
  const Vec3 axis = s.scope.direction_to_world(
      direction == HeightDirection::kScopeZ ? Vec3{0, 0, 1} : Vec3{0, 1, 0});
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::span<const std::uint32_t> loop = mesh.face(f);
    kernel::Polygon polygon;
    std::vector<Vec3> world;
    for (std::uint32_t v : loop) {
      world.push_back(s.scope.to_world(mesh.position(v)));
      polygon.outer.push_back(map.at(world.back()));
    }
    kernel::Triangulation tri;
    if (!kernel::triangulate(polygon, tri)) continue;
    for (const std::array<std::uint32_t, 3>& corners : tri.triangles) {
      UvTriangle t;
      for (std::size_t k = 0; k < 3; ++k) {
        t.uv[k] = tri.vertices[corners[k]];
        t.world[k] = world[corners[k]];
        t.lift[k] = normals.empty() ? axis : s.scope.direction_to_world(normals[loop[corners[k]]]);
      }
      out.push_back(t);
    }
  }
  return out;
}

struct TileRange {
  int u0, u1, v0, v1;  // whole-number tiles [u0, u1) x [v0, v1)
  std::size_t count() const {
    return static_cast<std::size_t>(u1 - u0) * static_cast<std::size_t>(v1 - v0);
  }
};

TileRange tiles_of(const UvTriangle& t) {
  double lo_u = t.uv[0].x, hi_u = lo_u, lo_v = t.uv[0].y, hi_v = lo_v;
  for (const Vec2& p : t.uv) {
    lo_u = std::min(lo_u, p.x), hi_u = std::max(hi_u, p.x);
    lo_v = std::min(lo_v, p.y), hi_v = std::max(hi_v, p.y);
  }
  // Bounds past what an int holds are caught by the copy limit before any tile is cut.
  const auto whole = [](double x) { return static_cast<int>(std::clamp(x, -1e9, 1e9)); };
  TileRange r{whole(std::floor(lo_u)), whole(std::ceil(hi_u)), whole(std::floor(lo_v)),
              whole(std::ceil(hi_v))};
  r.u1 = std::max(r.u1, r.u0 + 1);
  r.v1 = std::max(r.v1, r.v0 + 1);
  return r;
}

OpResult insert_along_uv(ShapeTree& tree, ShapeId id, const kernel::Mesh& asset,
                         const AlongUvOptions& options) {
  const Shape& s = tree[id];
  const Value* set = tree.attribute(id, uv_set_attribute(options.uv_set));
  const std::optional<UvMap> map = set != nullptr ? decode_uv_map(*set) : std::nullopt;
  OpResult empty;
  if (!map) {
    empty.warning = "the shape has no texture coordinates in uv set " +
                    std::to_string(options.uv_set) + " (projectUV first); nothing inserted";
  }
  if (!map || !s.mesh || asset.empty()) {  // CityEngine inserts nothing: no geometry
    empty.add(tree.add_child(id, s.scope), 0);
    return finish(tree, id, std::move(empty));
  }
  const std::vector<UvTriangle> triangles = uv_triangles(s, *map, options.direction);
  std::size_t copies = 0;
  for (const UvTriangle& t : triangles) copies += tiles_of(t).count();
  if (copies > kMaxCopies) {
    return OpResult::failure("the uv set repeats the asset " + std::to_string(copies) +
                             " times (at most " + std::to_string(kMaxCopies) +
                             "): scale the uv set down");
  }
  const kernel::Mesh uvh = to_uvh(asset, options.keep_position);
  kernel::Mesh world;
  for (const UvTriangle& t : triangles) {
    const TileRange r = tiles_of(t);
    for (int i = r.u0; i < r.u1; ++i) {
      for (int j = r.v0; j < r.v1; ++j) {
        kernel::Mesh tile = kernel::transformed(
            uvh, kernel::translation({static_cast<double>(i), static_cast<double>(j), 0}));
        const kernel::Mesh kept = clip_to(tile, t);
        if (!kept.empty()) place(kept, t, options.height, world);
      }
    }
  }
  if (world.empty()) {
    empty.add(tree.add_child(id, s.scope), 0);
    return finish(tree, id, std::move(empty));
  }
  const kernel::Mesh local = mesh_to_local(world, s.scope);
  return replace_with(tree, id, kernel::weld(local, 1e-7), {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
}

}  // namespace

std::vector<Operation> insert_along_uv_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"insertAlongUV",
       "Inserts an asset bent along the shape's texture coordinates (CityEngine's "
       "insertAlongUV): its x extent runs over u in [0, 1], its z extent over -v, both repeated "
       "where the uv set goes on; its y extent becomes `height` meters along the height "
       "direction. A shape without the uv set or a missing asset keeps no geometry.",
       {{"uvSet", ParamType::kInteger, "uv set 0..9 (projectUV first)", std::nullopt, {}, 0.0, 9.0},
        {"asset",
         ParamType::kString,
         "asset name, resolved by the asset provider",
         std::nullopt,
         {},
         {},
         {}},
        {"height",
         ParamType::kNumber,
         "meters the asset's height becomes (may be 0 or < 0)",
         std::nullopt,
         {},
         {},
         {}},
        {"heightDirection",
         ParamType::kEnum,
         "along the scope's y axis, its z axis (a flat shape's normal: CGA's scope.y on a lot) "
         "or the shape's vertex normals",
         ArgValue{std::string("scope.y")},
         {"scope.y", "scope.z", "vertex.normal"},
         {},
         {}},
        {"heightAlignment",
         ParamType::kEnum,
         "alignposition: the asset's bottom on the faces; keepposition: its origin there",
         ArgValue{std::string("alignposition")},
         {"alignposition", "keepposition"},
         {},
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context& context) {
         std::string error;
         const auto mesh = find_asset(context, a.string("asset"), error);
         if (!mesh) return OpResult::failure(error);
         AlongUvOptions options;
         options.uv_set = static_cast<int>(a.integer("uvSet"));
         options.height = a.number("height");
         const std::string& direction = a.string("heightDirection");
         options.direction = direction == "vertex.normal" ? HeightDirection::kVertexNormal
                             : direction == "scope.z"     ? HeightDirection::kScopeZ
                                                          : HeightDirection::kScopeY;
         options.keep_position = a.string("heightAlignment") == "keepposition";
         return insert_along_uv(t, id, *mesh, options);
       },
       uv_attributes()});
  return ops;
}

}  // namespace insula::shape
