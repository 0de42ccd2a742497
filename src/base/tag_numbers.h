// Numbers as map data writes them in text (OpenStreetMap tags, register attributes): lengths
// with units and counts of levels (docs/osm-buildings.md, "Values"). Mass models read S3DB tags
// with them (io/building_tags.h) and CGA attrs read lot properties (lang/cga).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace insula::base {

// `text` in ASCII lower case (tag values compare case-insensitively: "Hipped", "M").
std::string lower_ascii(std::string_view text);
// `name` as an identifier: every character other than a letter, digit or '_' written as '_'
// (OpenStreetMap's `building:levels` is `building_levels`, as Esri's OSM layers name it).
std::string identifier_spelling(std::string_view name);
// Whether identifier_spelling(name) == identifier, without making the spelling (asked for every
// lot property by each attr the lot does not name exactly).
bool spells_identifier(std::string_view name, std::string_view identifier);
// `text` without leading and trailing white space.
std::string_view trim_space(std::string_view text);
// Reads a non-negative decimal number at the start of `text` ("12", "12.5", "3,5": a decimal
// comma is common in European data), removes it and the white space after it from `text`.
std::optional<double> take_number(std::string_view& text);
// A length as OSM and registers write it: "12", "12.5 m", "40 ft", "12'6\"", "3,5"; meters.
std::optional<double> parse_length(std::string_view text);
// A count of levels: "3", "2.5"; nullopt for anything else.
std::optional<double> parse_levels(std::string_view text);

}  // namespace insula::base
