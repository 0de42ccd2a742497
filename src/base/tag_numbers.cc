#include "base/tag_numbers.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

namespace insula::base {
namespace {

constexpr double kFoot = 0.3048;
constexpr double kInch = 0.0254;

// The size in meters of a unit word, or nullopt for an unknown unit.
std::optional<double> unit_size(std::string_view unit) {
  const std::string u = lower_ascii(unit);
  if (u.empty() || u == "m" || u == "meter" || u == "meters" || u == "metre" || u == "metres") {
    return 1.0;
  }
  if (u == "ft" || u == "feet" || u == "foot" || u == "'") return kFoot;
  if (u == "in" || u == "inch" || u == "inches" || u == "\"") return kInch;
  if (u == "cm") return 0.01;
  return std::nullopt;
}

// A character of a name as identifier_spelling writes it.
char identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_' ? '_' : c;
}

}  // namespace

std::string lower_ascii(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string identifier_spelling(std::string_view name) {
  std::string out(name);
  for (char& c : out) c = identifier_char(c);
  return out;
}

bool spells_identifier(std::string_view name, std::string_view identifier) {
  if (name.size() != identifier.size()) return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (identifier_char(name[i]) != identifier[i]) return false;
  }
  return true;
}

std::string_view trim_space(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
    text.remove_prefix(1);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
    text.remove_suffix(1);
  }
  return text;
}

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
  text = trim_space(text);
  return value;
}

std::optional<double> parse_length(std::string_view text) {
  text = trim_space(text);
  std::optional<double> value = take_number(text);
  if (!value) return std::nullopt;
  // Feet and inches: 12'6" (OSM's documented form), 12' 6", 12 ft 6 in.
  std::size_t unit_end = 0;
  while (unit_end < text.size() && !std::isdigit(static_cast<unsigned char>(text[unit_end]))) {
    ++unit_end;
  }
  const std::optional<double> unit = unit_size(trim_space(text.substr(0, unit_end)));
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
  text = trim_space(text);
  std::optional<double> value = take_number(text);
  if (!value || !text.empty()) return std::nullopt;
  return value;
}

}  // namespace insula::base
