// CityEngine's insertAlongUV (CGA reference, "insertAlongUV operation"): an asset bent along the
// shape's texture coordinates. The asset's x extent maps to u over [0, 1] and its z extent to -v
// over [0, 1], both repeated wherever the uv set runs past a whole number; its y extent becomes
// `height` meters along the scope's y axis or the shape's vertex normals.
//
// Method: the asset is moved into (u, v, h) space (h in [0, 1]). A uv set is an affine map of
// world space (uv_map.h), so on each planar face it is invertible unless the face is seen edge-on
// in uv. A convex face is one region (a concave one, or any face whose heights follow vertex
// normals, is triangulated in uv); for every whole-number tile the region's uv bounds touch, a
// copy of the asset is cut by the region's edge planes the tile crosses (kernel::split without
// caps, so vertical faces of the asset are cut too; a tile inside needs no cut) and carried back
// to the face by the plane's affine map, lifted by h * height along the height direction. As
// CityEngine notes, the cuts leave coplanar edges and collinear vertices (cleanupGeometry
// removes them). docs/operations-cityengine.md, "insertAlongUV".
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "kernel/planar.h"
#include "kernel/plane_split.h"
#include "kernel/triangulate.h"
#include "shape/ops.h"
#include "shape/uv_map.h"

namespace insula::shape {

using kernel::Vec2;
using kernel::Vec3;

namespace {

constexpr std::size_t kMaxCopies = 200000;  // asset pieces one call may cut (a runaway uv scale)
// Asset faces one call may place, copies times faces: a large asset on many tiles would otherwise
// run for minutes and gigabytes (1 million faces, 50 copies of 20,000, took 11 s here, most of it
// welding the result; 20 million took 3 minutes and 5.8 GB).
constexpr std::size_t kMaxFaceCuts = 2000000;

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

// A convex region of one face in uv: the whole face when it is convex and heights follow a scope
// axis, else one triangle of it. A uv set is affine, so one affine map takes the face's (u, v)
// back to its plane in the world.
struct UvRegion {
  std::vector<Vec2> uv;  // counter-clockwise
  Vec2 uv0;
  Vec3 world0, per_u, per_v;   // world = world0 + per_u (u - uv0.x) + per_v (v - uv0.y)
  std::array<Vec2, 3> tri{};   // where the heights' directions are given (vertex normals)
  std::array<Vec3, 3> lift{};  // unit height directions at tri (all equal for a scope axis)
};

// The region of the corners `uv` (counter-clockwise) at `world`, its affine map taken from the
// largest triangle of its fan; false when the region is seen edge-on in uv.
bool make_region(std::vector<Vec2> uv, std::span<const Vec3> world, std::array<Vec3, 3> lift,
                 UvRegion& out) {
  std::size_t best = 0;
  double area = 0;
  for (std::size_t k = 1; k + 1 < uv.size(); ++k) {
    const double a = kernel::cross(uv[k] - uv[0], uv[k + 1] - uv[0]);
    if (a > area) area = a, best = k;
  }
  if (!(area > 1e-12)) return false;
  const Vec2 e1 = uv[best] - uv[0], e2 = uv[best + 1] - uv[0];
  // (s, t) = M^-1 (q - uv0) with M = [e1 e2]; world = w0 + (w1 - w0) s + (w2 - w0) t.
  const double i00 = e2.y / area, i01 = -e2.x / area, i10 = -e1.y / area, i11 = e1.x / area;
  const Vec3 a = world[best] - world[0], b = world[best + 1] - world[0];
  out.uv0 = uv[0];
  out.world0 = world[0];
  out.per_u = a * i00 + b * i10;
  out.per_v = a * i01 + b * i11;
  out.tri = {uv[0], uv[best], uv[best + 1]};
  out.lift = lift;
  out.uv = std::move(uv);
  return true;
}

Vec3 lift_at(const UvRegion& r, Vec2 p) {
  if (r.lift[0] == r.lift[1] && r.lift[1] == r.lift[2]) return r.lift[0];
  const double area = kernel::cross(r.tri[1] - r.tri[0], r.tri[2] - r.tri[0]);
  const double a = kernel::cross(r.tri[1] - p, r.tri[2] - p) / area;
  const double b = kernel::cross(r.tri[2] - p, r.tri[0] - p) / area;
  return r.lift[0] * a + r.lift[1] * b + r.lift[2] * (1 - a - b);
}

// The part of the copy of the asset on tile (i, j) over the region: cut by each edge's plane,
// the inside kept. Planes the whole tile lies inside of are skipped; a tile wholly outside one
// gives nothing, uncut.
kernel::Mesh clip_to(const kernel::Mesh& uvh, int i, int j, const UvRegion& r) {
  const std::array<Vec2, 4> box = {Vec2{i + 0.0, j + 0.0}, Vec2{i + 1.0, j + 0.0},
                                   Vec2{i + 1.0, j + 1.0}, Vec2{i + 0.0, j + 1.0}};
  std::vector<kernel::Plane> cuts;
  for (std::size_t k = 0; k < r.uv.size(); ++k) {
    const Vec2 a = r.uv[k], e = r.uv[(k + 1) % r.uv.size()] - a;
    // Inside (left of a counter-clockwise edge): cross(e, p - a) >= 0.
    std::size_t inside = 0;
    for (const Vec2& c : box) inside += kernel::cross(e, c - a) >= 0 ? 1 : 0;
    if (inside == 0) return {};
    if (inside < box.size()) cuts.push_back({Vec3{e.y, -e.x, 0}, e.y * a.x - e.x * a.y});
  }
  kernel::Mesh kept = kernel::transformed(
      uvh, kernel::translation({static_cast<double>(i), static_cast<double>(j), 0}));
  kernel::SplitOptions options;
  options.cap = false;
  for (const kernel::Plane& plane : cuts) {
    if (kept.empty()) break;
    kernel::SplitResult cut = kernel::split(kept, plane, options);
    if (!cut.ok()) return {};
    kept = std::move(cut.negative);
  }
  return kept;
}

// Carries `piece` (uvh space, inside the region) to world space and appends it to `out`,
// turning its faces round where the mapping mirrors them.
void place(const kernel::Mesh& piece, const UvRegion& r, double height, kernel::Mesh& out) {
  const auto map = [&](Vec3 q) {
    const Vec2 p{q.x, q.y};
    return r.world0 + r.per_u * (p.x - r.uv0.x) + r.per_v * (p.y - r.uv0.y) +
           lift_at(r, p) * (q.z * height);
  };
  kernel::Mesh placed = piece;
  for (Vec3& p : placed.positions()) p = map(p);
  // (u, v, h) -> world keeps orientation when d/du x d/dv points along the lift.
  const Vec3 centre_lift = r.lift[0] + r.lift[1] + r.lift[2];
  if (dot(kernel::cross(r.per_u, r.per_v), centre_lift) * height < 0) placed.flip();
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

// The shape's faces as convex regions in uv (faces seen edge-on in uv are skipped).
std::vector<UvRegion> uv_regions(const Shape& s, const UvMap& map, HeightDirection direction) {
  std::vector<UvRegion> out;
  const kernel::Mesh& mesh = *s.mesh;
  std::vector<Vec3> normals;
  if (direction == HeightDirection::kVertexNormal) normals = vertex_normals(mesh);
  const Vec3 axis = s.scope.direction_to_world(
      direction == HeightDirection::kScopeZ ? Vec3{0, 0, 1} : Vec3{0, 1, 0});
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::span<const std::uint32_t> loop = mesh.face(f);
    kernel::Polygon polygon;
    std::vector<Vec3> world;
    std::vector<Vec3> lifts;
    for (std::uint32_t v : loop) {
      world.push_back(s.scope.to_world(mesh.position(v)));
      polygon.outer.push_back(map.at(world.back()));
      lifts.push_back(normals.empty() ? axis : s.scope.direction_to_world(normals[v]));
    }
    if (kernel::signed_area(polygon.outer) < 0) {
      std::reverse(polygon.outer.begin(), polygon.outer.end());
      std::reverse(world.begin(), world.end());
      std::reverse(lifts.begin(), lifts.end());
    }
    UvRegion region;
    if (normals.empty() && kernel::is_convex(polygon.outer)) {
      if (make_region(polygon.outer, world, {axis, axis, axis}, region)) out.push_back(region);
      continue;
    }
    kernel::Triangulation tri;
    if (!kernel::triangulate(polygon, tri)) continue;
    for (const std::array<std::uint32_t, 3>& c : tri.triangles) {
      const std::array<Vec3, 3> corners = {world[c[0]], world[c[1]], world[c[2]]};
      if (make_region({tri.vertices[c[0]], tri.vertices[c[1]], tri.vertices[c[2]]}, corners,
                      {lifts[c[0]], lifts[c[1]], lifts[c[2]]}, region)) {
        out.push_back(region);
      }
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

TileRange tiles_of(const UvRegion& t) {
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
  const std::vector<UvRegion> regions = uv_regions(s, *map, options.direction);
  std::size_t copies = 0;
  for (const UvRegion& region : regions) copies += tiles_of(region).count();
  if (copies > kMaxCopies) {
    return OpResult::failure("the uv set repeats the asset " + std::to_string(copies) +
                             " times (at most " + std::to_string(kMaxCopies) +
                             "): scale the uv set down");
  }
  if (copies * asset.face_count() > kMaxFaceCuts) {
    return OpResult::failure(std::to_string(copies) + " copies of an asset of " +
                             std::to_string(asset.face_count()) + " faces are more than " +
                             std::to_string(kMaxFaceCuts) +
                             " faces to cut: use a simpler asset or fewer repeats");
  }
  const kernel::Mesh uvh = to_uvh(asset, options.keep_position);
  kernel::Mesh world;
  for (const UvRegion& region : regions) {
    const TileRange r = tiles_of(region);
    for (int i = r.u0; i < r.u1; ++i) {
      for (int j = r.v0; j < r.v1; ++j) {
        const kernel::Mesh kept = clip_to(uvh, i, j, region);
        if (!kept.empty()) place(kept, region, options.height, world);
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
