// The 3D builder's driver (seed 000, §3.4 and §4.1: "the walls are extruded considering the doors
// and windows previously flagged. Ground and ceilings are also placed in each room. Then, the
// geometry of the roof is created according to the type of roof defined for each building part.
// [...] producing entrance's stairs, rooms' footers, frame portals for doors and windows"), and the
// solids the stages share.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "kernel/boolean2d.h"
#include "lang/bldg/builder_detail.h"

namespace insula::lang::bldg {
namespace detail {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The builder's own materials (linear RGB), then one per restriction-rule colour.
std::vector<shape::Material> base_materials() {
  return {
      {"default", {0.8F, 0.8F, 0.8F, 1.0F}},  {"plinth", {0.42F, 0.40F, 0.37F, 1.0F}},
      {"frame", {0.23F, 0.13F, 0.06F, 1.0F}}, {"glass", {0.45F, 0.62F, 0.75F, 0.6F}},
      {"floor", {0.55F, 0.36F, 0.22F, 1.0F}}, {"footer", {0.30F, 0.22F, 0.16F, 1.0F}},
      {"stair", {0.62F, 0.58F, 0.52F, 1.0F}},
  };
}

// Restriction-rule colours (`color.<Class>`) override every face of their class.
void apply_colors(const Restrictions& rules, BuildResult& result) {
  std::array<kernel::MaterialId, kernel::kSemanticClassCount> by_class{};
  for (const auto& [name, rgba] : rules.colors) {
    const auto semantic = kernel::semantic_from_name(name);
    if (!semantic) continue;
    by_class[static_cast<std::size_t>(*semantic)] =
        static_cast<kernel::MaterialId>(result.materials.size());
    result.materials.push_back({"color." + name, rgba});
  }
  if (std::all_of(by_class.begin(), by_class.end(), [](auto m) { return m == 0; })) return;
  for (shape::Part& part : result.building.parts) {
    for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
      kernel::FaceTag& tag = part.mesh.tag(f);
      const kernel::MaterialId m = by_class[static_cast<std::size_t>(tag.semantic)];
      if (m != 0) tag.material = m;
    }
  }
}

}  // namespace

double Context::floor_z(int storey) const {
  return rules.base_height + plan.storeys[static_cast<std::size_t>(storey)].elevation;
}

double Context::storey_height(int storey) const {
  const double h = plan.storeys[static_cast<std::size_t>(storey)].height;
  return h > 0 ? h : rules.storey_height;
}

kernel::Polygon WallGeometry::rect(double u0, double u1, double across0, double across1) const {
  kernel::Polygon p;
  p.outer = {at(u0, across0), at(u1, across0), at(u1, across1), at(u0, across1)};
  const kernel::Ring& r = p.outer;
  if (r.front() == r.back()) {  // degenerate: normalize drops the repeated corner
    kernel::normalize(p);
    return p;
  }
  // What normalize does with four distinct-ended corners: reverse them when signed_area < 0. The
  // sign comes from the same shoelace sum signed_area takes (relative to the first corner, in the
  // same order, so the same bits), without the moment terms and the call (walls, plan walls and
  // door gaps take thousands of these per building).
  double twice_area = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    twice_area += kernel::cross(r[i] - r[0], r[(i + 1) % 4] - r[0]);
  }
  if (0.5 * twice_area < 0) std::reverse(p.outer.begin(), p.outer.end());
  return p;
}

namespace {

// Six quads over a box's corners, corner (i, j, k) being i + 2j + 4k: outward for a right-handed
// (u, v, w).
constexpr std::array<std::uint32_t, 24> kBoxFaces{
    0, 2, 3, 1,  // k = 0
    4, 5, 7, 6,  // k = 1
    0, 1, 5, 4,  // j = 0
    2, 6, 7, 3,  // j = 1
    0, 4, 6, 2,  // i = 0
    1, 3, 7, 5,  // i = 1
};

// Writes a box's eight corners to `corners`, corner (i, j, k) at i + 2j + 4k, as
// ((origin + u i) + v j) + w k with the partial sums shared between corners (x * 1.0 is x, so the
// terms are u or u * 0.0, ...: the same bits as the full expression). A left-handed (u, v, w) is
// turned right-handed first, from the opposite w face. Always inlined: its four Vec3 arguments
// would otherwise be copied through the stack for every box (frames and footers make most of a
// building's boxes), as much work as the corners themselves.
[[gnu::always_inline]] inline void write_box_corners(Vec3* corners, Vec3 origin, Vec3 u, Vec3 v,
                                                     Vec3 w) {
  if (kernel::dot(kernel::cross(u, v), w) < 0) {
    origin = origin + w;
    w = -w;
  }
  const std::array<Vec3, 2> us{u * 0.0, u};
  const std::array<Vec3, 2> vs{v * 0.0, v};
  const std::array<Vec3, 2> ws{w * 0.0, w};
  const std::array<Vec3, 2> along_u{origin + us[0], origin + us[1]};
  const std::array<Vec3, 4> along_uv{along_u[0] + vs[0], along_u[1] + vs[0], along_u[0] + vs[1],
                                     along_u[1] + vs[1]};
  for (int k = 0; k < 2; ++k) {
    for (int ij = 0; ij < 4; ++ij) corners[4 * k + ij] = along_uv[ij] + ws[k];
  }
}

}  // namespace

void add_box(kernel::Mesh& mesh, Vec3 origin, Vec3 u, Vec3 v, Vec3 w, FaceTag tag) {
  // The corners go straight into the position array (frames and footers make most of a building's
  // boxes, and this is their inner loop).
  std::vector<Vec3>& positions = mesh.positions();
  const auto base = static_cast<std::uint32_t>(positions.size());
  positions.resize(base + std::size_t{8});
  write_box_corners(positions.data() + base, origin, u, v, w);
  mesh.add_faces(kBoxFaces, 4, base, tag);
}

void add_boxes(kernel::Mesh& mesh, std::span<const BoxEdges> boxes, FaceTag tag) {
  // add_box's vertices and faces box after box, with each of the mesh's arrays grown once for
  // all of them (a window's frame is eight boxes).
  std::vector<Vec3>& positions = mesh.positions();
  const std::size_t first = positions.size();
  positions.resize(first + 8 * boxes.size());
  const kernel::Mesh::FaceSlots slots = mesh.add_face_slots(6 * boxes.size(), 24 * boxes.size());
  std::uint32_t* index = slots.indices.data();
  std::uint32_t end = slots.first_index;
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const BoxEdges& box = boxes[b];
    const auto base = static_cast<std::uint32_t>(first + 8 * b);
    write_box_corners(positions.data() + base, box.origin, box.u, box.v, box.w);
    for (const std::uint32_t corner : kBoxFaces) *index++ = base + corner;
    for (std::size_t f = 0; f < 6; ++f) {
      slots.ends[6 * b + f] = end += 4;
      slots.tags[6 * b + f] = tag;
    }
  }
}

bool add_prism(kernel::Mesh& mesh, const kernel::Polygon& polygon, double z0, double z1,
               FaceTag bottom, FaceTag top, FaceTag side) {
  kernel::ExtrudeOptions options;
  options.bottom = bottom;
  options.top = top;
  options.side = side;
  options.tolerance = 1e-6;
  // Straight into the storey mesh: no temporary prism mesh to build, copy and free per slab.
  const std::size_t first = mesh.face_count();
  if (kernel::extrude_between_append(mesh, polygon, z0, z1, options) != kernel::ExtrudeStatus::kOk)
    return false;
  // extrude numbers side faces from side.face_id; keep the caller's id on every side face.
  for (std::size_t f = first; f < mesh.face_count(); ++f) {
    kernel::FaceTag& tag = mesh.tag(f);
    if (tag.semantic == side.semantic && tag.material == side.material) tag.face_id = side.face_id;
  }
  return true;
}

void add_staircase(kernel::Mesh& mesh, Vec2 foot, Vec2 dir, double width, double z0, int steps,
                   double run, double rise, FaceTag tag) {
  if (steps < 1 || !(run > 0) || !(rise > 0) || !(width > 0)) return;
  // The profile in the vertical plane through the flight's right edge, climbing along `dir`:
  // (0, 0), (0, r), (d, r), (d, 2r), ... (n d, n r), (n d, 0).
  const Vec2 side = kernel::perp(dir);
  const Vec2 right = foot - side * (width / 2);
  const auto p = [&](double along, double up) {
    return kernel::lift(right + dir * along, z0 + up);
  };
  std::vector<Vec3> loop;
  loop.push_back(p(0, 0));
  for (int i = 0; i < steps; ++i) {
    loop.push_back(p(i * run, (i + 1) * rise));
    loop.push_back(p((i + 1) * run, (i + 1) * rise));
  }
  loop.push_back(p(steps * run, 0));
  // extrude_loop grows the solid along the loop's normal: orient the loop so that it points
  // across the flight, towards its left edge.
  const Vec3 normal = kernel::cross(loop[1] - loop[0], loop.back() - loop[0]);
  if (kernel::dot(normal, kernel::lift(side, 0)) < 0) std::reverse(loop.begin(), loop.end());
  kernel::ExtrudeOptions options;
  options.bottom = tag;
  options.top = tag;
  options.side = tag;
  const kernel::ExtrudeResult solid = kernel::extrude_loop(loop, width, options);
  if (solid.ok()) mesh.append(solid.mesh);
}

std::vector<kernel::Polygon> minus(const std::vector<kernel::Polygon>& a,
                                   const std::vector<kernel::Polygon>& b) {
  if (b.empty()) return a;
  kernel::BooleanResult r = kernel::subtract(a, b);
  return r.ok() ? std::move(r.polygons) : a;
}

}  // namespace detail

BuildResult build_building(const Building& building, const FloorPlan& plan,
                           const Restrictions& restrictions, const BuilderOptions& options) {
  using Clock = std::chrono::steady_clock;
  BuildResult result;
  result.materials = detail::base_materials();
  result.building.id = building.symbol.empty() ? "building" : building.symbol;
  if (!building.name.empty()) result.building.attributes["name"] = building.name;
  std::map<std::string, std::vector<kernel::Polygon>> compluvia;
  const detail::Context context{building, plan, restrictions, options, result, &compluvia};
  // Roofs first: a compluvium opens the ceilings below it.
  auto roof_start = Clock::now();
  std::vector<shape::Part> roof_parts;
  detail::build_roofs(context, roof_parts);
  result.stats.seconds_roofs += detail::seconds_since(roof_start);
  std::vector<shape::Part> room_parts;
  std::vector<shape::Part> storey_parts;
  std::vector<detail::StoreyWalls> storey_walls;
  for (std::size_t s = 0; s < plan.storeys.size(); ++s) {
    const int level = static_cast<int>(s);
    const PlanStorey& storey = plan.storeys[s];
    shape::StoreyPlan drawing;
    drawing.name = "storey " + std::to_string(storey.level);
    drawing.level = storey.level;
    drawing.elevation = context.floor_z(level);
    shape::Part part;
    part.name = drawing.name;
    part.kind = shape::PartKind::kStorey;
    part.attributes["storey"] = static_cast<double>(storey.level);
    part.attributes["elevation"] = drawing.elevation;
    part.attributes["height"] = context.storey_height(level);
    auto start = Clock::now();
    storey_walls.push_back(detail::build_walls(context, level, part.mesh, drawing));
    result.stats.seconds_walls += detail::seconds_since(start);
    start = Clock::now();
    detail::build_rooms(context, level, storey_walls.back(), room_parts, drawing);
    result.stats.seconds_slabs += detail::seconds_since(start);
    start = Clock::now();
    detail::build_stairs(context, level, part.mesh, drawing);
    result.stats.seconds_stairs += detail::seconds_since(start);
    storey_parts.push_back(std::move(part));
    result.building.plans.push_back(std::move(drawing));
  }
  result.stats.storeys = plan.storeys.size();
  auto start = Clock::now();
  shape::Part base;
  base.name = "base";
  base.kind = shape::PartKind::kBuildingPart;
  detail::build_base(context, storey_walls, base.mesh);
  result.stats.seconds_slabs += detail::seconds_since(start);

  std::vector<shape::Part>& parts = result.building.parts;
  if (!base.mesh.empty()) parts.push_back(std::move(base));
  for (auto* group : {&storey_parts, &room_parts, &roof_parts}) {
    for (shape::Part& part : *group) parts.push_back(std::move(part));
  }
  for (const shape::Part& part : parts) {
    result.stats.vertices += part.mesh.vertex_count();
    result.stats.triangles += part.mesh.triangle_count();
  }
  detail::apply_colors(restrictions, result);
  return result;
}

shape::Scene to_scene(BuildResult result) {
  shape::Scene scene;
  scene.materials = std::move(result.materials);
  scene.buildings.push_back(std::move(result.building));
  return scene;
}

}  // namespace insula::lang::bldg
