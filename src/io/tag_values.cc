// Reading the values of S3DB tags and register attributes: lengths with units, level counts,
// compass directions, roof shape names (docs/osm-buildings.md, "Values").
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "io/building_tags.h"

namespace insula::io {
namespace {

std::string_view trim(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
    text.remove_prefix(1);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
    text.remove_suffix(1);
  }
  return text;
}

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Reads a non-negative decimal number at the start of `text` ("12", "12.5", "3,5": a decimal
// comma is common in European data) and removes it from `text`.
std::optional<double> take_number(std::string_view& text) {
  std::size_t end = 0;
  bool separator = false;
  while (end < text.size()) {
    const char c = text[end];
    if (std::isdigit(static_cast<unsigned char>(c))) {
      ++end;
    } else if ((c == '.' || c == ',') && !separator && end + 1 < text.size() &&
               std::isdigit(static_cast<unsigned char>(text[end + 1]))) {
      separator = true;
      ++end;
    } else {
      break;
    }
  }
  if (end == 0) return std::nullopt;
  std::string digits(text.substr(0, end));
  std::replace(digits.begin(), digits.end(), ',', '.');
  double value = 0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (result.ec != std::errc{} || result.ptr != digits.data() + digits.size()) return std::nullopt;
  text.remove_prefix(end);
  text = trim(text);
  return value;
}

constexpr double kFoot = 0.3048;
constexpr double kInch = 0.0254;

// The size in meters of a unit word, or nullopt for an unknown unit.
std::optional<double> unit_size(std::string_view unit) {
  const std::string u = lower(unit);
  if (u.empty() || u == "m" || u == "meter" || u == "meters" || u == "metre" || u == "metres") {
    return 1.0;
  }
  if (u == "ft" || u == "feet" || u == "foot" || u == "'") return kFoot;
  if (u == "in" || u == "inch" || u == "inches" || u == "\"") return kInch;
  if (u == "cm") return 0.01;
  return std::nullopt;
}

}  // namespace

std::optional<double> parse_length(std::string_view text) {
  text = trim(text);
  std::optional<double> value = take_number(text);
  if (!value) return std::nullopt;
  // Feet and inches: 12'6" (OSM's documented form), 12' 6", 12 ft 6 in.
  std::size_t unit_end = 0;
  while (unit_end < text.size() && !std::isdigit(static_cast<unsigned char>(text[unit_end]))) {
    ++unit_end;
  }
  const std::optional<double> unit = unit_size(trim(text.substr(0, unit_end)));
  if (!unit) return std::nullopt;
  double meters = *value * *unit;
  text.remove_prefix(unit_end);
  if (!text.empty()) {
    if (*unit != kFoot) return std::nullopt;
    const std::optional<double> inches = take_number(text);
    if (!inches || unit_size(text) != kInch) return std::nullopt;
    meters += *inches * kInch;
  }
  return std::isfinite(meters) ? std::optional<double>(meters) : std::nullopt;
}

std::optional<double> parse_levels(std::string_view text) {
  text = trim(text);
  std::optional<double> value = take_number(text);
  if (!value || !text.empty()) return std::nullopt;
  return value;
}

std::optional<double> parse_direction(std::string_view text) {
  text = trim(text);
  static constexpr std::array<std::string_view, 16> kPoints = {
      "n", "nne", "ne", "ene", "e", "ese", "se", "sse",
      "s", "ssw", "sw", "wsw", "w", "wnw", "nw", "nnw"};
  const std::string word = lower(text);
  for (std::size_t i = 0; i < kPoints.size(); ++i) {
    if (word == kPoints[i]) return 22.5 * static_cast<double>(i);
  }
  std::optional<double> degrees = take_number(text);
  if (!degrees || !text.empty()) return std::nullopt;
  return std::fmod(*degrees, 360.0);
}

std::optional<std::string> s3db_roof_name(std::string_view shape) {
  struct Name {
    std::string_view s3db;
    std::string_view kernel;
  };
  // S3DB's documented shapes, then values common in the data that have a close kernel shape.
  static constexpr std::array<Name, 22> kNames = {{
      {"flat", "flat"},
      {"skillion", "shed"},
      {"gabled", "gable"},
      {"half-hipped", "half_hipped"},
      {"hipped", "hip"},
      {"pyramidal", "pyramid"},
      {"gambrel", "gambrel"},
      {"mansard", "mansard"},
      {"dome", "dome"},
      {"onion", "onion"},
      {"round", "round"},
      {"saltbox", "saltbox"},
      {"cone", "pyramid"},
      {"side_hipped", "hip"},
      {"hipped-and-gabled", "half_hipped"},
      {"lean_to", "shed"},
      {"shed", "shed"},
      {"half_hipped", "half_hipped"},
      {"gable", "gable"},
      {"hip", "hip"},
      {"pyramid", "pyramid"},
      {"pitched", "gable"},
  }};
  const std::string word = lower(trim(shape));
  for (const Name& name : kNames) {
    if (word == name.s3db) return std::string(name.kernel);
  }
  return std::nullopt;
}

}  // namespace insula::io
