#include "io/map_areas.h"

#include <algorithm>
#include <array>

namespace insula::io {

bool tagged(const PropertyRow& properties, std::string_view key) {
  const std::optional<shape::Value> value = properties.find(key);
  if (!value || shape::is_null(*value)) return false;
  return shape::to_string(*value) != "no";
}

bool tagged_building(const PropertyRow& properties) {
  return tagged(properties, "building") || tagged(properties, "building:part");
}

namespace {

// A structure mapped without a building tag (a multi-storey car park, a hangar, a shelter) still
// says so by its height, levels or roof tags, or by its value.
bool structure(const shape::AttributeMap& properties) {
  const bool measured = std::any_of(properties.begin(), properties.end(), [](const auto& property) {
    const std::string_view key = property.first;
    return key == "height" || key == "min_height" || key.starts_with("building:") ||
           key.starts_with("roof:");
  });
  if (measured) return true;
  for (const auto& [key, value] :
       {std::pair{"parking", "multi-storey"}, std::pair{"aeroway", "hangar"},
        std::pair{"aeroway", "terminal"}, std::pair{"amenity", "shelter"}}) {
    const auto found = properties.find(key);
    const std::string* text =
        found == properties.end() ? nullptr : std::get_if<std::string>(&found->second);
    if (text != nullptr && *text == value) return true;
  }
  return false;
}

}  // namespace

std::optional<std::string> non_building_area(const PropertyRow& properties) {
  if (tagged_building(properties)) return std::nullopt;
  const shape::AttributeMap map = properties.map();
  if (structure(map)) return std::nullopt;
  // Into `map`, which outlives every use.
  const auto text_of = [&](std::string_view key) -> const std::string* {
    const auto found = map.find(key);
    return found == map.end() ? nullptr : std::get_if<std::string>(&found->second);
  };
  // OSM's keys for areas that are land, water, ways, grounds or pitches rather than structures;
  // man_made, historic and tourism are left out, since towers, castles and huts are mapped with
  // them alone. Only text values count: a register's numeric column of one of these names
  // (an `area` in m2) says nothing of the kind, and `area` counts only as OSM's `area=yes`.
  static constexpr std::array<std::string_view, 16> kAreaKeys{
      "landuse",  "natural", "leisure",    "amenity",  "highway", "area:highway",
      "waterway", "water",   "railway",    "boundary", "aeroway", "military",
      "golf",     "sport",   "piste:type", "barrier"};
  for (std::string_view key : kAreaKeys) {
    const std::string* text = text_of(key);
    if (text != nullptr && !text->empty() && *text != "no") return std::string(key) + "=" + *text;
  }
  const std::string* area = text_of("area");
  if (area != nullptr && *area == "yes") return "area=yes";
  return std::nullopt;
}

}  // namespace insula::io
