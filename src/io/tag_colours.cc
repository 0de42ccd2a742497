// Colours of S3DB building:colour / roof:colour values (hex or the CSS Color Module Level 4 named
// colours, which the S3DB scheme refers to) and typical colours of building:material and
// roof:material values, for the materials of mass models (docs/osm-buildings.md, "Colours").
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "base/css_colours.h"
#include "io/building_tags.h"

namespace insula::io {
namespace {

using base::NamedColour;

// Typical colours of S3DB material values (our choice: a plausible mid-tone for each).
constexpr std::array<NamedColour, 27> kMaterialColours = {{
    {"asbestos", 0x9A9A96},     {"asphalt", 0x404040},        {"brick", 0x9C4A32},
    {"cement_block", 0xB0ACA4}, {"concrete", 0xB8B5AE},       {"copper", 0x5E9C84},
    {"eternit", 0x8A8A86},      {"glass", 0x8FB2C4},          {"grass", 0x6C8C3C},
    {"gravel", 0x9A9488},       {"limestone", 0xE0D8C0},      {"marble", 0xEAE6E0},
    {"metal", 0x9AA0A6},        {"metal_sheet", 0x9AA0A6},    {"mud", 0xA0825A},
    {"plaster", 0xE8E0CC},      {"plastic", 0xC8C8C8},        {"roof_tiles", 0xB4553A},
    {"sandstone", 0xD8C08C},    {"slate", 0x4A5058},          {"steel", 0x9AA0A6},
    {"stone", 0xB4AA96},        {"tar_paper", 0x3A3A3A},      {"thatch", 0xB49A5A},
    {"tile", 0xB4553A},         {"timber_framing", 0xE6DCC6}, {"wood", 0x9A7047},
}};

float srgb_to_linear(std::uint32_t channel) {
  const double c = channel / 255.0;
  return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

std::array<float, 3> linear(std::uint32_t rgb) {
  return {srgb_to_linear((rgb >> 16) & 0xFF), srgb_to_linear((rgb >> 8) & 0xFF),
          srgb_to_linear(rgb & 0xFF)};
}

std::optional<std::uint32_t> hex_colour(std::string_view hex) {
  if (hex.size() != 3 && hex.size() != 6) return std::nullopt;
  std::uint32_t rgb = 0;
  for (const char c : hex) {
    if (!std::isxdigit(static_cast<unsigned char>(c))) return std::nullopt;
    const std::uint32_t digit = std::isdigit(static_cast<unsigned char>(c))
                                    ? static_cast<std::uint32_t>(c - '0')
                                    : static_cast<std::uint32_t>(std::tolower(c) - 'a' + 10);
    // #rgb is #rrggbb with each digit doubled.
    rgb = hex.size() == 3 ? (rgb << 8) | (digit << 4) | digit : (rgb << 4) | digit;
  }
  return rgb;
}

template <std::size_t N>
std::optional<std::uint32_t> find_named(const std::array<NamedColour, N>& table,
                                        std::string_view name) {
  std::string key;
  for (const char c : name) {
    if (c != ' ') key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  for (const NamedColour& entry : table) {
    if (entry.name == key) return entry.rgb;
  }
  return std::nullopt;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

}  // namespace

std::optional<std::array<float, 3>> parse_colour(std::string_view text) {
  text = trimmed(text);
  std::optional<std::uint32_t> rgb =
      !text.empty() && text.front() == '#' ? hex_colour(text.substr(1)) : base::css_colour(text);
  if (!rgb) return std::nullopt;
  return linear(*rgb);
}

std::optional<std::array<float, 3>> material_colour(std::string_view material) {
  std::optional<std::uint32_t> rgb = find_named(kMaterialColours, trimmed(material));
  if (!rgb) return std::nullopt;
  return linear(*rgb);
}

}  // namespace insula::io
