// What a footprint's properties say about the building on it: OpenStreetMap's Simple 3D Buildings
// tags (S3DB: height, min_height, building:levels, roof:shape, roof:height, roof:direction,
// colours, building=roof) and the attributes of registers and municipal layers (a named height or
// levels attribute). Every value says where it came from, so a user can see why a building is 10 m.
// The rules, defaults and warning codes are in docs/osm-buildings.md.
#pragma once

#include "base/tag_numbers.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/property_table.h"
#include "shape/value.h"

namespace insula::io {

// Where a value used for a building came from.
enum class ValueSource : std::uint8_t {
  kOption,     // the command line (--height, --roof, --pitch)
  kTag,        // an S3DB tag (height, roof:shape, roof:height...)
  kAttribute,  // a register attribute (--height-attr, or the 'roof' property)
  kLevels,     // levels x storey height
  kDefault,    // nothing usable was given
};
std::string_view source_name(ValueSource source);  // "option", "tag", "attribute", ...

struct BuildingTagOptions {
  std::optional<double> height;        // --height: wall height for every building
  std::string height_attr = "height";  // --height-attr
  std::string levels_attr;             // --levels-attr (registers' storey counts)
  // --height-unit: meters per unit of a bare number in a height property of a feature that is not
  // an OpenStreetMap or Overture building (registers in feet: NYC's heightroof, Philadelphia's
  // approx_hgt). Texts with a unit ("40 ft") keep theirs; S3DB data is meters by definition.
  double length_unit = 1;
  double storey_height = 3;         // --storey-height
  double default_height = 10;       // --default-height: wall height when nothing says
  std::optional<std::string> roof;  // --roof: a kernel roof name, for every building
  double pitch_deg = 30;            // --pitch
  bool pitch_given = false;
  std::string default_roof = "hip";  // the roof of non-OSM features without a 'roof' property
};

// S3DB's roof:orientation.
enum class RoofOrientation : std::uint8_t { kAuto, kAlong, kAcross };

// What to build on one footprint. Heights are absolute above the ground (z = 0), in meters.
struct BuildingForm {
  bool osm = false;      // the feature is tagged building or building:part (S3DB rules apply)
  bool is_part = false;  // tagged building:part
  bool walls = true;     // false for building=roof: a roof on posts
  double base = 0;       // bottom of the walls (min_height)
  double eave = 10;      // top of the walls
  // The roof's rise above the eave when the data gives it (roof:height, roof:levels) or a total
  // height fixed it; unset: the roof follows from pitch_deg.
  std::optional<double> roof_height;
  // Unset roof_height and a pitch nobody gave (neither the data nor --pitch): the most the roof
  // may rise, the walls' height. S3DB's total height gives such a roof at most half the building
  // (the split); a register's height is the walls', and a default pitch over a large footprint
  // would dwarf them.
  std::optional<double> roof_height_limit;
  std::string roof = "flat";  // kernel roof name (kernel::roof_type_from_name)
  double pitch_deg = 30;
  std::optional<double> direction_deg;  // compass azimuth the main roof face looks toward
  RoofOrientation orientation = RoofOrientation::kAuto;
  std::optional<std::array<float, 3>> wall_colour;  // linear RGB
  std::optional<std::array<float, 3>> roof_colour;
  std::string wall_colour_name;  // as written ("#a0522d", "brick"), for material names
  std::string roof_colour_name;
  ValueSource height_source = ValueSource::kDefault;
  ValueSource roof_source = ValueSource::kDefault;
};

struct TagWarning {
  std::string code;  // MAS001...; docs/osm-buildings.md
  std::string text;  // without the feature's name
};

// Reads the form of one building from its properties. `roof_rise(roof, pitch_deg)` gives the height
// the feature's roof of that shape reaches at that pitch (the caller knows the footprint), so a
// total height (S3DB `height`, the top of the roof) can be split between walls and roof. Never
// throws.
using RoofRise = std::function<double(const std::string& roof, double pitch_deg)>;
BuildingForm read_building_form(const PropertyRow& properties, const BuildingTagOptions& options,
                                const RoofRise& roof_rise, std::vector<TagWarning>& warnings);

// Whether the feature follows Simple 3D Buildings: an OpenStreetMap building or part, or an
// Overture building, whose lengths are meters by definition; other features are registers'.
bool follows_s3db(const PropertyRow& properties);

// Lengths and level counts as OSM and registers write them (base/tag_numbers.h).
using base::parse_length;
using base::parse_levels;
// A compass direction: degrees ("135") or a point of the compass ("N", "SSW"); in [0, 360).
std::optional<double> parse_direction(std::string_view text);
// A colour: "#rgb", "#rrggbb" or a CSS colour name, as linear RGB.
std::optional<std::array<float, 3>> parse_colour(std::string_view text);
// A typical colour of an S3DB building:material or roof:material value ("brick", "roof_tiles").
std::optional<std::array<float, 3>> material_colour(std::string_view material);
// The kernel roof name of an S3DB roof:shape ("gabled" -> "gable"); nullopt if unknown.
std::optional<std::string> s3db_roof_name(std::string_view shape);

}  // namespace insula::io
