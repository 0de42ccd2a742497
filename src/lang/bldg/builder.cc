// The 3D builder's driver (seed 000, §3.4 and §4.1: "the walls are extruded considering the doors
// and windows previously flagged. Ground and ceilings are also placed in each room. Then, the
// geometry of the roof is created according to the type of roof defined for each building part.
// [...] producing entrance's stairs, rooms' footers, frame portals for doors and windows").
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
