// Rooms, stairs and the building base (seed 000, §4.1: "Ground and ceilings are also placed in
// each room [...] producing entrance's stairs, rooms' footers"; §3.4 "building base and division
// footers"; §5 asks for several floors, which need stairs).
//
// A room's clear floor is its cell minus the wall footprints around it (kernel/boolean2d.h). It
// gets a floor slab (FloorSurface on top) at the storey's floor level and a ceiling slab
// (CeilingSurface below) under the next floor, both slab_thickness thick, with a stairwell cut
// where a flight arrives from below or leaves upwards; and footers (skirting) along its walls,
// footer_height tall and footer_depth deep, interrupted at door gaps and stairwells.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "kernel/boolean2d.h"
#include "lang/bldg/builder_detail.h"

namespace insula::lang::bldg::detail {
namespace {

bool boxes_overlap(const kernel::Bounds2& a, const kernel::Bounds2& b) {
  constexpr double kSlack = 1e-6;
  return a.min.x <= b.max.x + kSlack && b.min.x <= a.max.x + kSlack &&
         a.min.y <= b.max.y + kSlack && b.min.y <= a.max.y + kSlack;
}

std::vector<kernel::Polygon> clear_floor(const kernel::Polygon& cell, const StoreyWalls& walls) {
  const kernel::Bounds2 box = kernel::bounds(cell);
  std::vector<kernel::Polygon> near;
  for (const WallGeometry& w : walls.walls) {
    if (!w.footprint.outer.empty() && boxes_overlap(box, kernel::bounds(w.footprint))) {
      near.push_back(w.footprint);
    }
  }
  return minus({cell}, near);
}

// Footers: the band between the clear floor and its inset by footer_depth, less the gaps.
std::vector<kernel::Polygon> footer_band(const std::vector<kernel::Polygon>& clear, double depth,
                                         std::vector<kernel::Polygon> gaps) {
  kernel::BooleanResult inset = kernel::offset(clear, -depth);
  if (!inset.ok()) return {};
  for (kernel::Polygon& p : inset.polygons) gaps.push_back(std::move(p));
  return minus(clear, gaps);
}

std::string unique_name(const std::string& base, const std::vector<shape::Part>& parts) {
  std::string name = base;
  for (int k = 2; std::any_of(parts.begin(), parts.end(),
                              [&](const shape::Part& p) { return p.name == name; });
       ++k) {
    name = base + "#" + std::to_string(k);
  }
  return name;
}

}  // namespace

void build_rooms(const Context& c, int s, const StoreyWalls& walls, std::vector<shape::Part>& parts,
                 shape::StoreyPlan& plan) {
  const PlanStorey& storey = c.plan.storeys[static_cast<std::size_t>(s)];
  const double z0 = c.floor_z(s);
  const double h = c.storey_height(s);
  const double slab = c.options.slab_thickness;
  // Stairwells: flights arriving from the storey below cut this floor; flights leaving upwards cut
  // this storey's ceilings.
  std::vector<kernel::Polygon> floor_holes;
  if (s > 0) {
    for (const PlanStair& st : c.plan.storeys[static_cast<std::size_t>(s - 1)].stairs) {
      floor_holes.push_back(st.footprint);
    }
  }
  std::vector<kernel::Polygon> ceiling_holes;
  for (const PlanStair& st : storey.stairs) ceiling_holes.push_back(st.footprint);
  const FaceTag closure{SemanticClass::kClosureSurface, 0, 0};
  const FaceTag inner{SemanticClass::kInteriorWallSurface, 0, 2};
  for (const PlanRoom& room : storey.rooms) {
    const std::vector<kernel::Polygon> clear = clear_floor(room.cell, walls);
    shape::Part part;
    part.name = unique_name(room.symbol, parts);
    part.kind = shape::PartKind::kRoom;
    double area = 0;
    for (const kernel::Polygon& p : clear) area += kernel::area(p);
    part.attributes["name"] = room.symbol;
    part.attributes["type"] = room.type;
    part.attributes["storey"] = static_cast<double>(storey.level);
    part.attributes["area"] = std::round(area * 1000) / 1000;
    part.attributes["building_part"] = room.part;
    for (const kernel::Polygon& p : minus(clear, floor_holes)) {
      add_prism(part.mesh, p, z0, z0 + slab, closure,
                {SemanticClass::kFloorSurface, kFloorMaterial, 1}, inner);
    }
    for (const kernel::Polygon& p : minus(clear, ceiling_holes)) {
      add_prism(part.mesh, p, z0 + h - slab, z0 + h, {SemanticClass::kCeilingSurface, 0, 3},
                closure, inner);
    }
    if (c.options.footers && c.rules.footer_height > 0 && c.options.footer_depth > 0) {
      std::vector<kernel::Polygon> gaps = walls.door_gaps;
      gaps.insert(gaps.end(), floor_holes.begin(), floor_holes.end());
      for (const kernel::Polygon& p : footer_band(clear, c.options.footer_depth, gaps)) {
        add_prism(part.mesh, p, z0 + slab, z0 + slab + c.rules.footer_height, closure, closure,
                  {SemanticClass::kInteriorWallSurface, kFooterMaterial, 4});
      }
    }
    shape::PlanRoom drawn;
    drawn.name = room.symbol;
    drawn.type = room.type;
    drawn.area = area;
    if (!clear.empty()) drawn.outline = clear.front();  // boolean results: largest first
    plan.rooms.push_back(std::move(drawn));
    parts.push_back(std::move(part));
    ++c.result.stats.rooms;
  }
}

void build_stairs(const Context& c, int s, kernel::Mesh& mesh, shape::StoreyPlan& plan) {
  const PlanStorey& storey = c.plan.storeys[static_cast<std::size_t>(s)];
  const bool has_above = static_cast<std::size_t>(s + 1) < c.plan.storeys.size();
  const double rise = has_above ? c.floor_z(s + 1) - c.floor_z(s) : c.storey_height(s);
  for (const PlanStair& st : storey.stairs) {
    const double run = kernel::length(st.head - st.foot);
    if (!(run > 0) || !(rise > 0)) continue;
    const int risers = st.risers > 0 ? st.risers : static_cast<int>(std::ceil(rise / 0.18));
    // The last step's top is the upper floor's top: the flight starts on this floor's slab.
    add_staircase(mesh, st.foot, (st.head - st.foot) / run, st.width,
                  c.floor_z(s) + c.options.slab_thickness, risers, run / risers, rise / risers,
                  {SemanticClass::kStair, kStairMaterial, 0});
    plan.stairs.push_back({st.footprint, st.foot, st.head});
    ++c.result.stats.stairs;
  }
}

void build_base(const Context& c, const std::vector<StoreyWalls>& walls, kernel::Mesh& mesh) {
  const double base = c.rules.base_height;
  if (base > 0) {
    for (const kernel::Polygon& footprint : c.plan.footprint) {
      add_prism(mesh, footprint, 0, base, {SemanticClass::kGroundSurface, kPlinthMaterial, 0},
                {SemanticClass::kClosureSurface, kPlinthMaterial, 1},
                {SemanticClass::kWallSurface, kPlinthMaterial, 2});
    }
  }
  if (c.plan.storeys.empty() || walls.empty()) return;
  // Entrance steps (§4.1) outside every entrance door, from the ground up to its threshold.
  const PlanStorey& ground = c.plan.storeys.front();
  const double rise = base + c.options.slab_thickness;
  const int steps = static_cast<int>(std::ceil(rise / c.options.step_rise - 1e-9));
  for (const PlanDoor& e : ground.entrances) {
    if (e.wall < 0 || static_cast<std::size_t>(e.wall) >= walls.front().walls.size()) continue;
    const WallGeometry& g = walls.front().walls[static_cast<std::size_t>(e.wall)];
    const Vec2 outward = -g.left;
    const double depth = steps * c.options.step_run;
    add_staircase(mesh, e.center + outward * depth, -outward, e.width + 0.4, 0, steps,
                  c.options.step_run, rise / steps, {SemanticClass::kStair, kStairMaterial, 3});
  }
}

}  // namespace insula::lang::bldg::detail
