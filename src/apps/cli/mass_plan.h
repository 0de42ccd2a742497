// What `insula mass` builds on each footprint, decided before the parallel build so warnings stay
// in input order: the building's form from its tags or attributes (io/building_tags.h), the
// OpenStreetMap building:part features that replace their outline, and the materials of tagged
// colours (docs/osm-buildings.md).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "io/building_tags.h"
#include "io/geojson_reader.h"
#include "kernel/mass.h"
#include "kernel/polygon_overlaps.h"
#include "shape/scene.h"

namespace insula::cli {

struct MassOptions;

// A warning of the mass stage: its code (docs/cli.md, "Warnings") and its text.
struct Warning {
  std::string code;
  std::string text;
};

// What the build needs of a footprint's io::BuildingForm besides its MassSpec: the heights and
// where they and the roof came from. The whole form (roof name, colours and their names: about
// 200 bytes) stays in plan_mass, since a city holds the plan of every footprint for its whole run.
struct FormSummary {
  double base = 0;  // bottom of the walls
  double eave = 10;
  io::ValueSource height_source = io::ValueSource::kDefault;
  io::ValueSource roof_source = io::ValueSource::kDefault;
  bool osm = false;      // S3DB rules apply
  bool is_part = false;  // a building:part
};

struct FootprintPlan {
  FormSummary form;
  kernel::MassSpec spec;
  // The outline this building:part stands in (S3DB: parts inside an outline replace it).
  std::optional<std::size_t> outline;
  bool replaced = false;  // an outline whose parts are built instead of it
  kernel::MaterialId wall_material = 0;
  kernel::MaterialId roof_material = 0;
};

// Footprints drawn over each other (two buildings in one place), leaving out a building:part
// and its outline, and parts of one outline (stacked parts overlap in plan by design).
struct OverlapSummary {
  std::size_t pairs = 0;
  double largest_area = 0;                            // square meters
  std::size_t largest_first = 0, largest_second = 0;  // footprint indices of the largest
};

struct MassPlan {
  std::vector<FootprintPlan> footprints;   // in input order
  std::vector<shape::Material> materials;  // the scene's: "default", then one per tagged colour
  std::vector<kernel::Overlap> overlaps;   // every overlapping pair of footprints
  OverlapSummary overlap_summary;
};

std::string feature_name(const io::Footprint& footprint);

MassPlan plan_mass(const MassOptions& options, const io::FootprintSet& set,
                   std::vector<Warning>& warnings);

// The attributes that say where a building's height and roof came from (docs/osm-buildings.md,
// "Where each value came from"). An input property of one of these names is replaced, with
// warning MAS009 (plan_mass).
inline constexpr std::array<const char*, 6> kFormAttributes{
    "insula:height",        "insula:eave_height", "insula:min_height",
    "insula:height_source", "insula:roof",        "insula:roof_source"};
// Sets kFormAttributes; `top` is the built height.
void add_form_attributes(const FormSummary& form, kernel::RoofType built_roof, double top,
                         shape::AttributeMap& attributes);

}  // namespace insula::cli
