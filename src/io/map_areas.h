// Map areas that are not buildings (docs/osm-buildings.md, "Map areas that are not buildings"):
// a map export's forests, parks, school grounds and rivers beside its buildings, told apart by
// their OpenStreetMap tags. Readers leave them out before any geometry check when
// FootprintOptions::leave_out_non_buildings asks, so an invalid forest polygon neither fails the
// read nor counts as invalid.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "io/property_table.h"

namespace insula::io {

// Whether tag `key` is present with a value other than null or "no" (S3DB: building=no is not one).
bool tagged(const PropertyRow& properties, std::string_view key);

// Tagged building or building:part: a feature of a map export whose buildings carry their tag.
bool tagged_building(const PropertyRow& properties);

// An OpenStreetMap area that is not a building: a feature tagged neither building nor
// building:part whose tags say what it is instead (landuse, natural, leisure, amenity, highway,
// waterway, boundary, ...). Returns that tag as "key=value"; nothing for any other feature, so a
// register's or a hand-made file's untagged footprints stay buildings. Whether to leave it out
// also depends on the rest of the file (tagged_building() of some feature).
std::optional<std::string> non_building_area(const PropertyRow& properties);

}  // namespace insula::io
