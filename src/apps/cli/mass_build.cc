#include "apps/cli/mass_build.h"

#include <algorithm>

#include "kernel/mass.h"

namespace insula::cli {
namespace {

void paint(const FootprintPlan& plan, kernel::Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    kernel::FaceTag& tag = mesh.tag(f);
    if (tag.semantic == kernel::SemanticClass::kWallSurface) {
      tag.material = plan.wall_material;
    } else if (tag.semantic == kernel::SemanticClass::kRoofSurface ||
               tag.semantic == kernel::SemanticClass::kOuterCeilingSurface) {
      tag.material = plan.roof_material;
    }
  }
}

BuiltBuilding build_one(const io::Footprint& footprint, const FootprintPlan& plan) {
  BuiltBuilding out;
  out.building.id = footprint.id;
  out.building.attributes = footprint.properties.map();
  kernel::RoofType built_roof = plan.spec.roof;
  for (std::size_t i = 0; i < footprint.polygons.size(); ++i) {
    kernel::MassResult mass = kernel::build_mass(footprint.polygons[i], plan.spec);
    if (!mass.message.empty()) out.messages.push_back(mass.message);
    built_roof = mass.roof;
    shape::Part part;
    part.name =
        footprint.polygons.size() == 1 ? footprint.id : footprint.id + "-part-" + std::to_string(i);
    part.kind = shape::PartKind::kBuildingPart;
    part.mesh = std::move(mass.mesh);
    paint(plan, part.mesh);
    // build_mass promises shared vertices, so the topological check needs no welding.
    out.watertight = out.watertight && !part.mesh.empty() && kernel::check(part.mesh).closed &&
                     kernel::volume(part.mesh) > 0;
    if (!part.mesh.empty()) out.top = std::max(out.top, part.mesh.bounds().max.z);
    out.building.parts.push_back(std::move(part));
  }
  add_form_attributes(plan.form, built_roof, out.top, out.building.attributes);
  return out;
}

}  // namespace

BuildOutcome outcome_of(BuiltBuilding&& built) {
  return {
      std::move(built.building.id), built.feature, built.watertight, std::move(built.messages), {}};
}

std::vector<MassUnit> mass_units(const MassPlan& plan) {
  const std::size_t n = plan.footprints.size();
  std::vector<MassUnit> parts_of(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (plan.footprints[i].outline) parts_of[*plan.footprints[i].outline].push_back(i);
  }
  std::vector<MassUnit> units;
  for (std::size_t i = 0; i < n; ++i) {
    if (plan.footprints[i].outline) continue;
    MassUnit& unit = units.emplace_back(MassUnit{i});
    if (plan.footprints[i].replaced)
      unit.insert(unit.end(), parts_of[i].begin(), parts_of[i].end());
  }
  return units;
}

// S3DB: the building:part features of a replaced outline become the parts of one building named
// after the outline, with its properties; every other footprint is a building of its own.
BuiltBuilding build_unit(const io::FootprintSet& set, const MassPlan& plan, const MassUnit& unit) {
  const std::size_t first = unit.front();
  if (!plan.footprints[first].replaced) {
    BuiltBuilding built = build_one(set.footprints[first], plan.footprints[first]);
    built.feature = first;
    return built;
  }
  BuiltBuilding joined;
  joined.feature = first;
  joined.building.id = set.footprints[first].id;
  joined.building.attributes = set.footprints[first].properties.map();
  // The parts carry their own forms; of the outline's input `insula:*` properties (MAS009) none
  // describes the joined building, whose height is set below.
  for (const char* key : kFormAttributes) joined.building.attributes.erase(key);
  for (std::size_t k = 1; k < unit.size(); ++k) {
    BuiltBuilding part = build_one(set.footprints[unit[k]], plan.footprints[unit[k]]);
    joined.watertight = joined.watertight && part.watertight;
    joined.top = std::max(joined.top, part.top);
    for (std::string& m : part.messages) {
      joined.messages.push_back("part \"" + part.building.id + "\": " + m);
    }
    for (shape::Part& mesh_part : part.building.parts) {
      mesh_part.attributes = part.building.attributes;
      joined.building.parts.push_back(std::move(mesh_part));
    }
  }
  joined.building.attributes["insula:height"] = joined.top;
  return joined;
}

io::TileItem unit_tile_item(const io::FootprintSet& set, const MassUnit& unit, double overhang) {
  kernel::Vec2 lo{1e300, 1e300};
  kernel::Vec2 hi{-1e300, -1e300};
  std::size_t corners = 0;
  for (const std::size_t f : unit) {
    for (const kernel::Polygon& polygon : set.footprints[f].polygons) {
      for (const kernel::Vec2 p : polygon.outer) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
      }
      corners += polygon.outer.size();
      for (const kernel::Ring& hole : polygon.holes) corners += hole.size();
    }
  }
  if (corners == 0) return {{0, 0}, {0, 0}, 1};
  // A mass has a wall per edge, a roof face or two per edge and a floor.
  return {lo - kernel::Vec2{overhang, overhang}, hi + kernel::Vec2{overhang, overhang},
          2 * corners + 2};
}

}  // namespace insula::cli
