// Positions in JSON text, for a reader whose parser keeps none (simdjson's DOM): a byte pre-scan
// that finds how deep the text nests and where a top-level "features" array's elements start, a
// locator that finds a value again by its path, and the first syntax error with its offset
// (nlohmann::json's validating SAX pass, whose messages users read). io/geojson_reader.cc reads
// through these; the scan works on any bytes, the locator on text a parser accepted.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace insula::io::json_text {

// An offset that is nowhere: what the locator returns for a value it cannot find.
inline constexpr std::size_t kNoOffset = std::numeric_limits<std::size_t>::max();

// Offset just past the string whose opening quote is at `pos`; text.size() when unterminated.
std::size_t skip_string(std::string_view text, std::size_t pos);

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// What one pass over the bytes finds: the first bracket that nests deeper than the limit (outside
// strings), and, when the root is an object, its last "features" member's array (the byte range
// from '[' to just past ']') and the offsets where that array's elements start. Exact on valid
// JSON; on anything else the pieces parsed from it do not parse, or their glue does not check.
struct Layout {
  std::optional<std::size_t> too_deep;
  std::size_t features_at = kNoOffset;
  std::size_t features_end = kNoOffset;
  std::vector<std::size_t> elements;
};

// Scans `text` whose root value starts at `root`. Never reads past the end.
Layout scan_layout(std::string_view text, std::size_t root, std::size_t max_depth);

// One step of a path into a JSON value: an object member (key) or an array element (index).
struct PathStep {
  std::string_view key;
  std::size_t index = 0;
};

// Finds values again in text that a parser accepted. Offsets are byte offsets of the first
// character of a value; kNoOffset propagates.
class TextLocator {
 public:
  explicit TextLocator(std::string_view text) : text_(text) {}

  // The first offset from `pos` that is not whitespace (past a byte order mark at 0).
  std::size_t skip_space(std::size_t pos) const;
  // Offset just past the value starting at `pos`.
  std::size_t skip_value(std::size_t pos) const;
  // Offset of the value of member `key` (the last one, as nlohmann keeps the last duplicate).
  std::size_t member(std::size_t pos, std::string_view key) const;
  // Offset of the array element `index` of the array at `pos`.
  std::size_t element(std::size_t pos, std::size_t index) const;
  // The deepest offset reachable along `path` from `pos` (best effort: stops where a step fails).
  std::size_t follow(std::size_t pos, const std::vector<PathStep>& path) const;

 private:
  std::string_view text_;
};

// The first syntax error of a JSON text: where it shows and nlohmann's words for it (without
// their "[json.exception...] parse error at line..." prefix, bytes outside printable ASCII
// escaped). An empty message: the text is valid JSON.
struct SyntaxError {
  std::size_t offset = 0;
  std::string message;
};

SyntaxError first_syntax_error(std::string_view text);

}  // namespace insula::io::json_text
