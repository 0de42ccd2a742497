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

#include "base/tag_numbers.h"
#include "io/building_tags.h"

namespace insula::io {

using base::lower_ascii;

std::optional<double> parse_direction(std::string_view text) {
  text = base::trim_space(text);
  static constexpr std::array<std::string_view, 16> kPoints = {
      "n", "nne", "ne", "ene", "e", "ese", "se", "sse",
      "s", "ssw", "sw", "wsw", "w", "wnw", "nw", "nnw"};
  const std::string word = lower_ascii(text);
  for (std::size_t i = 0; i < kPoints.size(); ++i) {
    if (word == kPoints[i]) return 22.5 * static_cast<double>(i);
  }
  std::optional<double> degrees = base::take_number(text);
  if (!degrees || !text.empty()) return std::nullopt;
  return std::fmod(*degrees, 360.0);
}

std::optional<std::string> s3db_roof_name(std::string_view shape) {
  struct Name {
    std::string_view s3db;
    std::string_view kernel;
  };
  // S3DB's documented shapes, then values common in the data that have a close kernel shape, then
  // Overture's `spherical`.
  static constexpr std::array<Name, 23> kNames = {{
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
      {"spherical", "dome"},
  }};
  const std::string word = lower_ascii(base::trim_space(shape));
  for (const Name& name : kNames) {
    if (word == name.s3db) return std::string(name.kernel);
  }
  return std::nullopt;
}

}  // namespace insula::io
