// The CSS named colours (CSS Color Module Level 4, section 6.1): OpenStreetMap's building:colour
// and roof:colour use them (the S3DB scheme refers to them), so mass models (io/tag_colours.cc)
// and CGA's color() read them.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace insula::base {

// A colour by name (other tables of named colours use it too: io/tag_colours.cc's materials).
struct NamedColour {
  std::string_view name;
  std::uint32_t rgb;  // sRGB, 0xRRGGBB
};

// The sRGB value (0xRRGGBB) of a CSS colour name, in any case and with spaces ignored ("Light
// Grey" is lightgrey); nullopt for anything else.
std::optional<std::uint32_t> css_colour(std::string_view name);

}  // namespace insula::base
