#include "apps/cli/mass_plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "apps/cli/height_unit.h"
#include "apps/cli/mass_command.h"
#include "apps/cli/s3db_parts.h"
#include "kernel/party_walls.h"
#include "kernel/polygon_overlaps.h"
#include "kernel/roof_rise.h"

namespace insula::cli {
namespace {

io::BuildingTagOptions tag_options(const MassOptions& options) {
  io::BuildingTagOptions tags;
  tags.height = options.height;
  tags.height_attr = options.height_attr;
  tags.length_unit = meters_per_height_unit(options.height_unit);
  tags.levels_attr = options.levels_attr;
  tags.storey_height = options.storey_height;
  tags.default_height = options.default_height;
  if (options.roof_given) tags.roof = options.roof;
  tags.default_roof = options.roof;
  tags.pitch_deg = options.pitch_deg;
  tags.pitch_given = options.pitch_given;
  return tags;
}

// The highest rise of the roof over any polygon of the footprint.
io::RoofRise rise_over(const io::Footprint& footprint) {
  return [&footprint](const std::string& roof, double pitch_deg) {
    const kernel::RoofType type =
        kernel::roof_type_from_name(roof).value_or(kernel::RoofType::kHip);
    double rise = 0;
    for (const kernel::Polygon& polygon : footprint.polygons) {
      rise = std::max(rise, kernel::roof_rise(polygon, type, pitch_deg));
    }
    return rise;
  };
}

kernel::MassSpec mass_spec(const MassOptions& options, const io::BuildingForm& form) {
  kernel::MassSpec spec;
  spec.ground_z = form.base;
  spec.wall_height = form.eave - form.base;
  spec.pitch_deg = form.pitch_deg;
  spec.overhang = options.overhang;
  // read_building_form names only kernel roofs (unknown names are its MAS003 warnings).
  spec.roof = kernel::roof_type_from_name(form.roof).value_or(kernel::RoofType::kHip);
  spec.height = form.roof_height;
  spec.height_limit = form.roof_height_limit;
  spec.direction_deg = form.direction_deg;
  spec.orientation =
      form.orientation == io::RoofOrientation::kAlong    ? kernel::RidgeOrientation::kAlong
      : form.orientation == io::RoofOrientation::kAcross ? kernel::RidgeOrientation::kAcross
                                                         : kernel::RidgeOrientation::kAuto;
  spec.walls = form.walls;
  return spec;
}

// S3DB: building:part features inside a building outline are built instead of it
// (s3db_parts.h); only footprints with S3DB tags (FormSummary::osm) take part.
void assign_parts(const io::FootprintSet& set, MassPlan& plan,
                  const std::vector<kernel::Overlap>& overlaps) {
  std::vector<bool> is_part, is_outline;
  for (const FootprintPlan& footprint : plan.footprints) {
    is_part.push_back(footprint.form.is_part);
    is_outline.push_back(footprint.form.osm && !footprint.form.is_part);
  }
  const std::vector<std::optional<std::size_t>> outlines =
      part_outlines(set, overlaps, is_part, is_outline);
  for (std::size_t i = 0; i < outlines.size(); ++i) plan.footprints[i].outline = outlines[i];
  for (FootprintPlan& footprint : plan.footprints) {
    if (footprint.outline) plan.footprints[*footprint.outline].replaced = true;
  }
}

std::string material_key(const std::string& name) {
  std::string key = "osm-";
  for (const char c : name) {
    key += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '_';
  }
  return key;
}

// One material per colour name, in order of first use: the scene's materials, then the tagged
// colours' as footprints name them.
class ColourMaterials {
 public:
  explicit ColourMaterials(std::vector<shape::Material>& materials) : materials_(materials) {
    materials_ = shape::Scene().materials;
  }

  // The walls' and the roof's materials of one footprint, given its form and spec.
  void assign(io::BuildingForm& form, FootprintPlan& footprint) {
    footprint.wall_material = material(form.wall_colour, form.wall_colour_name);
    // The flat roofs of mapped buildings are mostly gravel, bitumen or membranes: grey, not the
    // terracotta of pitched roofs (docs/osm-buildings.md, "Colours").
    if (!form.roof_colour && form.osm && footprint.spec.roof == kernel::RoofType::kFlat) {
      form.roof_colour = io::material_colour("gravel");
      form.roof_colour_name = "flat_roof";
    }
    footprint.roof_material = material(form.roof_colour, form.roof_colour_name);
  }

 private:
  kernel::MaterialId material(const std::optional<std::array<float, 3>>& colour,
                              const std::string& name) {
    if (!colour) return 0;
    const std::string key = material_key(name);
    auto [it, added] = ids_.emplace(key, static_cast<kernel::MaterialId>(materials_.size()));
    if (added) materials_.push_back({key, {(*colour)[0], (*colour)[1], (*colour)[2], 1.0F}});
    return it->second;
  }

  std::vector<shape::Material>& materials_;
  std::map<std::string, kernel::MaterialId> ids_;
};

FormSummary summary_of(const io::BuildingForm& form) {
  return {form.base, form.eave, form.height_source, form.roof_source, form.osm, form.is_part};
}

// How far a pitched roof's surface falls or rises over `overhang` metres (0 for a flat roof).
double pitch_drop(const FootprintPlan& footprint, double overhang) {
  if (footprint.spec.roof == kernel::RoofType::kFlat) return 0;
  return overhang * std::tan(footprint.spec.pitch_deg * std::numbers::pi / 180);
}

// Height of the soffit under `footprint`'s eave, and the highest its walls or roof rise within
// `overhang` of its edges: where a neighbour's rise is above this building's soffit, the eave would
// run into it.
double soffit_height(const FootprintPlan& footprint, double overhang) {
  const double fascia = footprint.spec.roof == kernel::RoofType::kFlat ? footprint.spec.fascia : 0;
  return footprint.form.eave - pitch_drop(footprint, overhang) - fascia;
}

double rise_near_edge(const FootprintPlan& footprint, double overhang) {
  return footprint.form.eave + pitch_drop(footprint, overhang);
}

// With an overhang, each footprint's party walls (kernel/party_walls.h) against built neighbours
// whose walls or roof reach above its soffit there (kernel-roofs.md, "Party walls"): those edges
// get no overhang. A lower neighbour (a garage against a house) lets the eave pass over it.
void assign_party_walls(const MassOptions& options,
                        std::vector<std::vector<kernel::Polygon>> regions, MassPlan& plan) {
  if (!(options.overhang > 0)) return;
  for (std::size_t i = 0; i < regions.size(); ++i) {
    if (plan.footprints[i].replaced) regions[i].clear();  // its parts stand there instead
  }
  for (const kernel::PartyWall& wall : kernel::find_party_walls(regions)) {
    FootprintPlan& self = plan.footprints[wall.footprint];
    const FootprintPlan& neighbour = plan.footprints[wall.neighbour];
    if (neighbour.form.base >= self.form.eave) continue;  // a part above this building's eave
    if (rise_near_edge(neighbour, options.overhang) <= soffit_height(self, options.overhang)) {
      continue;
    }
    self.spec.party_walls.push_back(wall);
  }
}

OverlapSummary summarize_overlaps(const MassPlan& plan) {
  OverlapSummary summary;
  for (const kernel::Overlap& overlap : plan.overlaps) {
    const FootprintPlan& a = plan.footprints[overlap.first];
    const FootprintPlan& b = plan.footprints[overlap.second];
    const auto owner = [&](const FootprintPlan& f, std::size_t index) {
      return f.outline.value_or(index);
    };
    if (owner(a, overlap.first) == owner(b, overlap.second)) continue;  // one building's parts
    ++summary.pairs;
    if (overlap.area > summary.largest_area) {
      summary.largest_area = overlap.area;
      summary.largest_first = overlap.first;
      summary.largest_second = overlap.second;
    }
  }
  return summary;
}

// MAS009: a property the program writes itself (kFormAttributes) is replaced, not silently.
void warn_replaced_properties(const io::Footprint& footprint, std::vector<Warning>& warnings) {
  for (const char* key : kFormAttributes) {
    const std::optional<shape::Value> value = footprint.properties.find(key);
    if (!value) continue;
    warnings.push_back({"MAS009", feature_name(footprint) + ": property '" + key + "' ('" +
                                      shape::to_string(*value) +
                                      "') is replaced by the value insula writes under that name"});
  }
}

// MAS010: a footprint larger than any building (the largest halls cover about 0.5 km2) is mostly
// an area a map export holds without a tag saying what it is; it is built as given, but the user
// should know why a slab covers the town.
void warn_vast_footprint(const io::Footprint& footprint, std::vector<Warning>& warnings) {
  constexpr double kLargestBuilding = 1e6;  // m2
  double area = 0;
  for (const kernel::Polygon& polygon : footprint.polygons) area += kernel::area(polygon);
  if (area <= kLargestBuilding) return;
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", area / 1e6);
  warnings.push_back({"MAS010", feature_name(footprint) + ": a footprint of " + text +
                                    " km2, larger than any building (an area mapped without a "
                                    "tag saying what it is?); built as given"});
}

}  // namespace

std::string feature_name(const io::Footprint& footprint) {
  return "feature " + std::to_string(footprint.feature_index) + " (id \"" + footprint.id + "\")";
}

MassPlan plan_mass(const MassOptions& options, const io::FootprintSet& set,
                   std::vector<Warning>& warnings) {
  const io::BuildingTagOptions tags = tag_options(options);
  MassPlan plan;
  ColourMaterials materials(plan.materials);
  plan.footprints.reserve(set.footprints.size());
  for (const io::Footprint& footprint : set.footprints) {
    std::vector<io::TagWarning> tag_warnings;
    io::BuildingForm form =
        io::read_building_form(footprint.properties, tags, rise_over(footprint), tag_warnings);
    for (io::TagWarning& w : tag_warnings) {
      warnings.push_back({w.code, feature_name(footprint) + ": " + w.text});
    }
    warn_replaced_properties(footprint, warnings);
    warn_vast_footprint(footprint, warnings);
    FootprintPlan& entry = plan.footprints.emplace_back();
    entry.spec = mass_spec(options, form);
    materials.assign(form, entry);
    entry.form = summary_of(form);
  }
  std::vector<std::vector<kernel::Polygon>> regions;
  regions.reserve(set.footprints.size());
  for (const io::Footprint& footprint : set.footprints) regions.push_back(footprint.polygons);
  plan.overlaps = kernel::find_overlaps(regions);
  assign_parts(set, plan, plan.overlaps);
  assign_party_walls(options, std::move(regions), plan);
  plan.overlap_summary = summarize_overlaps(plan);
  return plan;
}

void add_form_attributes(const FormSummary& form, kernel::RoofType built_roof, double top,
                         shape::AttributeMap& attributes) {
  attributes["insula:height"] = top;
  attributes["insula:eave_height"] = form.eave;
  attributes["insula:min_height"] = form.base;
  attributes["insula:height_source"] = std::string(io::source_name(form.height_source));
  attributes["insula:roof"] = std::string(kernel::roof_type_name(built_roof));
  attributes["insula:roof_source"] = std::string(io::source_name(form.roof_source));
}

}  // namespace insula::cli
