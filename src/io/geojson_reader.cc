// GeoJSON footprint reader (RFC 7946 structure, GeoJSON-2008 "crs" member). Stages: byte
// pre-scan (empty input, nesting depth, where the features start) -> simdjson DOM parses, piece by
// piece (the top level without its features, then the features a chunk at a time; a GeoJSON text
// sequence has one Feature per line and no top level), which together validate the whole text ->
// structure walk collecting world-coordinate rings per feature -> the finishing steps shared with
// the OSM reader (io/footprint_finish.h: CRS and reprojection, origin shift, repair, id
// de-duplication). Only when simdjson rejects the text does nlohmann::json look at it: its SAX pass
// finds the error and words GEO001 (or, for the few texts nlohmann accepts and simdjson does not,
// such as integers beyond 64 bits, re-dumps the piece for simdjson). Values are read as nlohmann
// would read them: the last of duplicate keys wins, nested property values are nlohmann's compact
// dump. The DOM keeps no positions, so diagnostics find theirs again with a small scanner
// (io/json_text.h) over the (by then known valid) text: feature starts are listed once, deeper
// paths are scanned from the feature start only when a diagnostic needs them.
#include "io/geojson_reader.h"

#include <oneapi/tbb/parallel_for.h>

#include <simdjson.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "io/json_text.h"

namespace insula::io {
namespace {

using base::Diagnostic;
using nlohmann::json;
using Element = simdjson::dom::element;
using json_text::is_space;
using json_text::PathStep;
using json_text::SyntaxError;
using json_text::TextLocator;
using simdjson::dom::element_type;
constexpr std::size_t kNone = kNoIndex;
static_assert(kNone == json_text::kNoOffset);
constexpr std::array<std::string_view, 4> kSequenceSuffixes = {".geojsonl", ".geojsons",
                                                               ".geojsonseq", ".ndjson"};

// ---------------------------------------------------------------------------------------------
// Small helpers.

std::string type_name(Element value) {
  switch (value.type()) {
    case element_type::NULL_VALUE:
      return "null";
    case element_type::OBJECT:
      return "an object";
    case element_type::ARRAY:
      return "an array";
    case element_type::STRING:
      return "a string";
    case element_type::BOOL:
      return "a boolean";
    case element_type::INT64:
    case element_type::UINT64:
    case element_type::DOUBLE:
      return "a number";
  }
  return "an unsupported value";
}

bool is_number(Element value) {
  const element_type type = value.type();
  return type == element_type::INT64 || type == element_type::UINT64 ||
         type == element_type::DOUBLE;
}

// Any number as a double, as nlohmann's get<double>() converts (int64 and uint64 by cast).
double number(Element value) {
  double out = 0;
  if (value.get_double().get(out) != simdjson::SUCCESS) return 0;
  return out;
}

std::string_view string_of(Element value) {
  std::string_view out;
  if (value.get_string().get(out) != simdjson::SUCCESS) return {};
  return out;
}

// The object or array `value` is (by value: a range-for over a temporary simdjson_result's
// value_unsafe() would dangle). Only for a value of that type: the empty one cannot be iterated.
simdjson::dom::object object_of(Element value) {
  simdjson::dom::object out;
  if (value.get_object().get(out) != simdjson::SUCCESS) return {};
  return out;
}

simdjson::dom::array array_of(Element value) {
  simdjson::dom::array out;
  if (value.get_array().get(out) != simdjson::SUCCESS) return {};
  return out;
}

// Number of elements of an array (simdjson's count saturates at 2^24 - 1: count those).
std::size_t array_size(simdjson::dom::array array) {
  std::size_t n = array.size();
  if (n < 0xFFFFFF) return n;
  n = 0;
  for ([[maybe_unused]] Element item : array) ++n;
  return n;
}

std::size_t array_size(Element value) {
  simdjson::dom::array array;
  return value.get_array().get(array) == simdjson::SUCCESS ? array_size(array) : 0;
}

// The value as nlohmann::json holds it after parsing the same text (the last duplicate key wins).
json to_json(Element value) {
  switch (value.type()) {
    case element_type::OBJECT: {
      json out = json::object();
      for (const auto field : object_of(value)) {
        out[std::string(field.key)] = to_json(field.value);
      }
      return out;
    }
    case element_type::ARRAY: {
      json out = json::array();
      for (const Element item : array_of(value)) out.push_back(to_json(item));
      return out;
    }
    case element_type::STRING:
      return std::string(string_of(value));
    case element_type::BOOL:
      return value.get_bool().value_unsafe();
    case element_type::INT64: {
      const std::int64_t v = value.get_int64().value_unsafe();
      // nlohmann holds non-negative integers unsigned.
      return v >= 0 ? json(static_cast<std::uint64_t>(v)) : json(v);
    }
    case element_type::UINT64:
      return value.get_uint64().value_unsafe();
    case element_type::DOUBLE:
      return value.get_double().value_unsafe();
    case element_type::NULL_VALUE:
      break;
  }
  return nullptr;
}

std::string compact(Element value) {
  return to_json(value).dump(-1, ' ', false, json::error_handler_t::replace);
}

// A numeric or non-empty string id, as text.
std::optional<std::string> id_text(Element value) {
  if (value.type() == element_type::STRING && !string_of(value).empty()) {
    return std::string(string_of(value));
  }
  // Integers as written: through a double, 12345678901234567890 became ...7168 and then clashed.
  if (value.type() == element_type::INT64) return std::to_string(value.get_int64().value_unsafe());
  if (value.type() == element_type::UINT64) {
    return std::to_string(value.get_uint64().value_unsafe());
  }
  if (is_number(value)) return number_text(number(value));
  return std::nullopt;
}

// The values of members `keys` of an object in one pass over its members: the last of each.
template <std::size_t N>
std::array<std::optional<Element>, N> members(Element object,
                                              const std::array<std::string_view, N>& keys) {
  std::array<std::optional<Element>, N> found;
  simdjson::dom::object fields;
  if (object.get_object().get(fields) != simdjson::SUCCESS) return found;
  for (const auto field : fields) {
    for (std::size_t k = 0; k < N; ++k) {
      if (field.key == keys[k]) found[k] = field.value;
    }
  }
  return found;
}

// The value of member `key` of an object: the last one, as nlohmann keeps the last duplicate.
std::optional<Element> member(Element object, std::string_view key) {
  return members<1>(object, {key})[0];
}

bool is_geojson_geometry(std::string_view type) {
  return type == "Point" || type == "MultiPoint" || type == "LineString" ||
         type == "MultiLineString" || type == "GeometryCollection" || type == "Polygon" ||
         type == "MultiPolygon";
}

// The EPSG code named by a CRS string: "EPSG:25832", "urn:ogc:def:crs:EPSG::25832",
// "http://www.opengis.net/def/crs/EPSG/0/25832"; 0 when none.
int epsg_code(std::string_view name) {
  std::string upper(name);
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 32) : c; });
  if (upper.find("EPSG") == std::string::npos) return 0;
  std::size_t end = upper.size();
  std::size_t begin = end;
  while (begin > 0 && upper[begin - 1] >= '0' && upper[begin - 1] <= '9') --begin;
  if (begin == end || end - begin > 6) return 0;
  return std::stoi(upper.substr(begin));
}

// Where in a feature's geometry a problem is; kNone fields are absent.
struct Where {
  std::size_t polygon = kNone;  // index in a MultiPolygon; kNone for a Polygon
  std::size_t ring = kNone;
  std::size_t position = kNone;
  std::size_t coordinate = kNone;
};

std::string ring_label(const Where& where) {
  std::string out = "polygon";
  if (where.polygon != kNone) out += " " + std::to_string(where.polygon);
  if (where.ring != kNone) out += " ring " + std::to_string(where.ring);
  return out;
}

// What the GeoJSON reader keeps of a feature besides its RawFootprint (FootprintBuilder's
// features_[index]): where it is in the text, for diagnostics.
struct FeatureState {
  std::size_t index = 0;
  std::size_t offset = kNone;     // text offset of the feature (or bare geometry) value
  bool bare_geometry = false;     // paths start at the geometry itself
  std::vector<PathStep> id_path;  // where the id came from
};

// ---------------------------------------------------------------------------------------------
// simdjson pieces.

// A DOM parser with the text it parses (a copy: simdjson reads up to SIMDJSON_PADDING bytes past
// the end) and the document it holds.
struct ParsedPiece {
  simdjson::dom::parser parser;
  std::vector<char> bytes;
  Element root;

  // Parses the concatenation of `parts`, nesting up to `max_depth` deep. With `redump`, text
  // simdjson rejects is read by nlohmann (which takes integers beyond 64 bits as doubles) and its
  // compact dump is parsed instead.
  bool parse(std::initializer_list<std::string_view> parts, bool redump, std::size_t max_depth) {
    if (max_depth > parser.max_depth() &&
        parser.allocate(simdjson::dom::MINIMAL_DOCUMENT_CAPACITY, max_depth) != simdjson::SUCCESS) {
      return false;
    }
    if (parse_copy(parts)) return true;
    if (!redump) return false;
    const json value = json::parse(bytes.data(), bytes.data() + size_, nullptr, false);
    return !value.is_discarded() &&
           parse_copy({value.dump(-1, ' ', false, json::error_handler_t::replace)});
  }

 private:
  bool parse_copy(std::initializer_list<std::string_view> parts) {
    size_ = 0;
    for (std::string_view part : parts) size_ += part.size();
    if (bytes.size() < size_ + simdjson::SIMDJSON_PADDING) {
      bytes.resize(size_ + simdjson::SIMDJSON_PADDING);
    }
    char* out = bytes.data();
    for (std::string_view part : parts) out = std::copy(part.begin(), part.end(), out);
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    return parser.parse(data, size_, false).get(root) == simdjson::SUCCESS;
  }

  std::size_t size_ = 0;
};

// ---------------------------------------------------------------------------------------------

class Reader : public FootprintBuilder {
 public:
  Reader(std::string_view text, const std::string& name, const GeoJsonOptions& options)
      : FootprintBuilder(name, options, "GeoJsonOptions"),
        text_(text),
        geo_options_(options),
        locator_(text),
        sequence_(options.sequence || is_geojson_sequence_path(name)) {}

  base::Result<FootprintSet> run();

 private:
  // Diagnostics ----------------------------------------------------------------------------
  Location at(std::size_t offset);
  Location locate(std::size_t feature, const FootprintPlace& place) override;
  std::string feature_name(std::size_t index) const override {
    return "feature " + std::to_string(index);
  }
  // Once the feature's id is read, its messages give it: "feature 3 (id \"b12\")".
  std::string feature_label(std::size_t index) const override {
    const std::string& id = features_[index].id;
    return id.empty() ? feature_name(index) : feature_name(index) + " (id " + quote_text(id) + ")";
  }
  std::string fallback_id(std::size_t index) const override {
    return "feature-" + std::to_string(index);
  }
  // Diagnostics of the walk (report, feature_issue) are emitted only once the whole text is known
  // to be valid JSON: ensure_valid() parses what the walk has not reached yet.
  void emit(base::Severity severity, const char* code, std::string message, std::size_t offset,
            std::vector<std::string> notes = {}) {
    FootprintBuilder::report(severity, code, std::move(message), at(offset), std::move(notes));
  }
  void report(base::Severity severity, const char* code, std::string message, std::size_t offset,
              std::vector<std::string> notes = {}) {
    ensure_valid();
    emit(severity, code, std::move(message), offset, std::move(notes));
  }
  void ensure_valid();
  void feature_issue(FeatureState& feature, bool is_error, const char* code,
                     const std::string& message, const std::vector<PathStep>& path,
                     std::vector<std::string> notes = {});
  std::vector<PathStep> geometry_path(const FeatureState& feature, const Where& where) const;

  // Stages ---------------------------------------------------------------------------------
  bool prescan();
  bool prescan_lines();
  bool parse();
  std::size_t group_count() const;
  bool parse_group(std::size_t group, std::vector<ParsedPiece>& pieces);
  bool valid_group(std::size_t group, std::vector<ParsedPiece>& pieces);
  bool nlohmann_accepts();
  bool nlohmann_accepts_lines();
  void syntax_failure();
  void read_top_level(Element doc);
  void read_crs(Element doc);
  FeatureState& add_feature(std::size_t offset);
  void read_features();
  void read_feature(Element value, std::size_t offset);
  void read_geometry(FeatureState& feature, Element geometry);
  void read_collection(FeatureState& feature, Element geometry, const std::vector<PathStep>& here);
  void read_collection_member(FeatureState& feature, Element geometry,
                              const std::vector<PathStep>& here);
  void read_properties(FeatureState& feature, Element value);
  std::optional<kernel::Polygon> read_polygon(FeatureState& feature, Element rings, Where where);
  std::optional<kernel::Ring> read_ring(FeatureState& feature, Element ring, const Where& where);
  std::optional<kernel::Vec2> read_position(FeatureState& feature, Element position, Where where);

  std::string_view text_;
  const GeoJsonOptions& geo_options_;
  TextLocator locator_;
  // A GeoJSON text sequence: feature_offsets_ are the lines' values, feature_ends_ their ends.
  bool sequence_ = false;
  std::vector<std::size_t> feature_ends_;
  // Where each line starts, built on the first positioned diagnostic: line and column as
  // base::Source counts them (bytes, from 1), without a copy of a city-sized text.
  std::vector<std::size_t> line_starts_;
  bool warned_extra_dimensions_ = false;
  std::size_t crs_offset_ = kNone;
  std::size_t root_offset_ = 0;
  std::vector<FeatureState> states_;  // parallel to features_
  // Where each polygon of a GeometryCollection feature is (its rings array), by feature index.
  std::map<std::size_t, std::vector<std::vector<PathStep>>> collection_paths_;

  // A FeatureCollection's "features" array is cut out of the top-level piece (parsed as "[]") and
  // its elements are parsed kChunk at a time, "[" + their text + "]", kGroup chunks in parallel.
  static constexpr std::size_t kChunk = 256;
  static constexpr std::size_t kGroup = 32;
  ParsedPiece top_;
  std::size_t features_at_ = kNone;  // offset of the cut-out array
  std::size_t features_end_ = kNone;
  std::vector<std::size_t> feature_offsets_;
  std::vector<ParsedPiece> chunks_ = std::vector<ParsedPiece>(kGroup);
  std::size_t parsed_group_ = kNone;         // the group chunks_ holds
  bool validated_ = false;                   // every group has been parsed once
  std::optional<SyntaxError> syntax_error_;  // nlohmann's verdict, once asked
  bool redump_ = false;                      // nlohmann accepted a text simdjson rejected
};

// Thrown when a piece parsed after the walk began is not valid JSON; run() drops what was read.
struct SyntaxAbort {};

FootprintBuilder::Location Reader::at(std::size_t offset) {
  if (offset == kNone) return whole_input();
  if (line_starts_.empty()) {
    line_starts_.push_back(0);
    for (std::size_t i = text_.find('\n'); i != std::string_view::npos;
         i = text_.find('\n', i + 1)) {
      line_starts_.push_back(i + 1);
    }
  }
  const std::size_t at = std::min(offset, text_.size());
  const auto line = std::upper_bound(line_starts_.begin(), line_starts_.end(), at) - 1;
  return {offset, base::Span::at(name_, static_cast<std::uint32_t>(line - line_starts_.begin() + 1),
                                 static_cast<std::uint32_t>(at - *line + 1))};
}

FootprintBuilder::Location Reader::locate(std::size_t feature, const FootprintPlace& place) {
  const FeatureState& state = states_[feature];
  if (state.offset == kNone) return whole_input();
  const std::vector<PathStep> path =
      place.id ? state.id_path
               : geometry_path(state, Where{place.polygon, place.ring, place.position});
  return at(locator_.follow(state.offset, path));
}

void Reader::feature_issue(FeatureState& feature, bool is_error, const char* code,
                           const std::string& message, const std::vector<PathStep>& path,
                           std::vector<std::string> notes) {
  ensure_valid();
  const std::size_t offset =
      feature.offset == kNone ? kNone : locator_.follow(feature.offset, path);
  FootprintBuilder::feature_issue(feature.index, is_error, code, message, at(offset),
                                  std::move(notes));
}

std::vector<PathStep> Reader::geometry_path(const FeatureState& feature, const Where& where) const {
  std::vector<PathStep> path;
  const auto collection = collection_paths_.find(feature.index);
  if (collection != collection_paths_.end() && where.polygon < collection->second.size()) {
    path = collection->second[where.polygon];
  } else {
    if (!feature.bare_geometry) path.push_back({"geometry", 0});
    path.push_back({"coordinates", 0});
    if (where.polygon != kNone) path.push_back({{}, where.polygon});
  }
  for (std::size_t index : {where.ring, where.position, where.coordinate}) {
    if (index != kNone) path.push_back({{}, index});
  }
  return path;
}

// Stage 1: bytes. Empty input and hostile nesting are rejected before nlohmann's parser runs.
bool Reader::prescan() {
  if (sequence_) return prescan_lines();
  root_offset_ = locator_.skip_space(0);
  if (root_offset_ >= text_.size()) {
    emit(base::Severity::kError, "GEO002", "file is empty; expected a GeoJSON object", kNone);
    return false;
  }
  json_text::Layout layout = json_text::scan_layout(text_, root_offset_, geo_options_.max_depth);
  if (const auto deep = layout.too_deep) {
    emit(base::Severity::kError, "GEO003",
         "arrays and objects nest deeper than " + std::to_string(geo_options_.max_depth) +
             " levels (GeoJsonOptions::max_depth)",
         *deep);
    return false;
  }
  features_at_ = layout.features_at;
  features_end_ = layout.features_end;
  feature_offsets_ = std::move(layout.elements);
  return true;
}

// Stage 1 of a GeoJSON text sequence (RFC 8142): each line that holds more than blanks (and a
// leading record separator, 0x1E) is a feature, checked for depth on its own.
bool Reader::prescan_lines() {
  const auto blank = [](char c) { return is_space(c) || c == '\x1E'; };
  for (std::size_t begin = text_.starts_with("\xEF\xBB\xBF") ? 3 : 0; begin < text_.size();) {
    std::size_t end = std::min(text_.find('\n', begin), text_.size());
    const std::size_t next = end + 1;
    while (begin < end && blank(text_[begin])) ++begin;
    while (end > begin && blank(text_[end - 1])) --end;
    if (begin < end) {
      const std::string_view line = text_.substr(begin, end - begin);
      if (const auto deep =
              json_text::scan_layout(line, line.size(), geo_options_.max_depth).too_deep) {
        emit(base::Severity::kError, "GEO003",
             "arrays and objects nest deeper than " + std::to_string(geo_options_.max_depth) +
                 " levels (GeoJsonOptions::max_depth)",
             begin + *deep);
        return false;
      }
      feature_offsets_.push_back(begin);
      feature_ends_.push_back(end);
    }
    begin = next;
  }
  if (feature_offsets_.empty()) {
    emit(base::Severity::kError, "GEO002",
         "file is empty; expected a GeoJSON Feature on each line (a GeoJSON sequence)", kNone);
    return false;
  }
  return true;
}

// Stage 2: JSON. simdjson parses the text in pieces that together cover all of it (the glue
// between them is whitespace and commas, checked here): the top level with a FeatureCollection's
// "features" array cut out (parsed as "[]"), then that array's elements kChunk at a time, kGroup
// chunks in parallel, so a city's features are never all in memory as JSON. Here the top level and
// the first group are parsed; read_features() parses the other groups as it reaches them. A syntax
// error is the only diagnostic of a text: a diagnostic of the walk waits for ensure_valid(), and a
// syntax error found by the walk before any drops what was read (run()).
bool Reader::parse() {
  // A sequence has no top level: its lines are parsed as a collection's features are.
  const bool ok =
      sequence_ || (features_at_ == kNone
                        ? top_.parse({text_.substr(root_offset_)}, redump_, geo_options_.max_depth)
                        : top_.parse({text_.substr(root_offset_, features_at_ - root_offset_), "[]",
                                      text_.substr(features_end_)},
                                     redump_, geo_options_.max_depth));
  if (!ok) {
    if (redump_ || !nlohmann_accepts()) {
      syntax_failure();
      return false;
    }
    redump_ = true;  // nlohmann accepts what simdjson rejected (an integer beyond 64 bits)
    return parse();
  }
  if (features_at_ == kNone) return true;
  // The first element (or the closing bracket) follows '[' after whitespace only.
  const std::size_t first = locator_.skip_space(features_at_ + 1);
  if (first != (feature_offsets_.empty() ? features_end_ - 1 : feature_offsets_[0])) {
    syntax_failure();
    return false;
  }
  if (group_count() == 0) return true;
  if (!valid_group(0, chunks_)) return false;
  parsed_group_ = 0;
  return true;
}

std::size_t Reader::group_count() const {
  return (feature_offsets_.size() + kChunk * kGroup - 1) / (kChunk * kGroup);
}

// Parses the chunks of `group` into `pieces`, in parallel: "[" + the text from a chunk's first
// element to the next chunk's (less the comma between them) + "]". False when one is not valid
// JSON.
bool Reader::parse_group(std::size_t group, std::vector<ParsedPiece>& pieces) {
  const std::size_t count = feature_offsets_.size();
  const std::size_t first = group * kGroup * kChunk;
  const std::size_t chunks = std::min(kGroup, (count - first + kChunk - 1) / kChunk);
  pieces.resize(kGroup);
  std::vector<char> ok(chunks, 0);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
    const std::size_t begin = first + k * kChunk;
    const std::size_t end = std::min(begin + kChunk, count);
    std::string_view piece = text_.substr(feature_offsets_[begin]);
    piece = piece.substr(
        0, (end < count ? feature_offsets_[end] : features_end_ - 1) - feature_offsets_[begin]);
    const auto trim = [&piece] {
      while (!piece.empty() && is_space(piece.back())) piece.remove_suffix(1);
    };
    trim();
    if (end < count && !sequence_) {
      if (piece.empty() || piece.back() != ',') return;
      piece.remove_suffix(1);
      trim();
    }
    std::string lines;  // a sequence's lines, joined by commas
    if (sequence_) {
      for (std::size_t i = begin; i < end; ++i) {
        if (i > begin) lines += ',';
        lines += text_.substr(feature_offsets_[i], feature_ends_[i] - feature_offsets_[i]);
      }
      piece = lines;
    }
    ok[k] = pieces[k].parse({"[", piece, "]"}, redump_, geo_options_.max_depth) &&
            array_size(pieces[k].root) == end - begin;
  });
  return std::all_of(ok.begin(), ok.end(), [](char v) { return v != 0; });
}

// parse_group(), or, when simdjson rejects the text, GEO001 (false) unless nlohmann accepts it.
bool Reader::valid_group(std::size_t group, std::vector<ParsedPiece>& pieces) {
  if (parse_group(group, pieces)) return true;
  if (!redump_ && nlohmann_accepts()) {
    redump_ = true;  // nlohmann accepts what simdjson rejected (an integer beyond 64 bits)
    if (parse_group(group, pieces)) return true;
  }
  syntax_failure();
  return false;
}

void Reader::ensure_valid() {
  if (validated_) return;
  validated_ = true;
  if (parsed_group_ == kNone) return;  // no features, or not parsed yet
  std::vector<ParsedPiece> pieces;
  for (std::size_t group = parsed_group_ + 1; group < group_count(); ++group) {
    if (!valid_group(group, pieces)) throw SyntaxAbort{};
  }
}

// Whether nlohmann accepts the text: its validating SAX pass runs once, syntax_error_ keeps the
// error.
bool Reader::nlohmann_accepts() {
  if (sequence_) return nlohmann_accepts_lines();
  if (!syntax_error_) syntax_error_ = json_text::first_syntax_error(text_);
  return syntax_error_->message.empty();
}

// The same for a sequence, line by line: the first line it rejects holds the error.
bool Reader::nlohmann_accepts_lines() {
  if (!syntax_error_) {
    syntax_error_.emplace();
    for (std::size_t i = 0; i < feature_offsets_.size(); ++i) {
      SyntaxError line = json_text::first_syntax_error(
          text_.substr(feature_offsets_[i], feature_ends_[i] - feature_offsets_[i]));
      if (!line.message.empty()) {
        line.offset += feature_offsets_[i];
        syntax_error_ = std::move(line);
        break;
      }
    }
  }
  return syntax_error_->message.empty();
}

// GEO001 from nlohmann's message for the error its SAX pass finds.
void Reader::syntax_failure() {
  if (nlohmann_accepts()) {  // not expected: simdjson rejects a text nlohmann accepts
    emit(base::Severity::kError, "GEO001", "the JSON parser rejected this text", root_offset_);
    return;
  }
  const SyntaxError& error = *syntax_error_;
  std::string message = error.message;
  std::vector<std::string> notes;
  const std::string_view at = text_.substr(std::min(error.offset, text_.size()));
  const std::size_t before = text_.find_last_not_of(" \t\r\n", error.offset - (error.offset > 0));
  if (at.rfind("NaN", 0) == 0 || at.rfind("Infinity", 0) == 0 || at.rfind("nan", 0) == 0 ||
      at.rfind("inf", 0) == 0) {
    notes.push_back(message);
    message = "NaN and Infinity are not valid JSON numbers";
  } else if (!at.empty() && (at[0] == ']' || at[0] == '}') && error.offset > 0 &&
             before != std::string_view::npos && text_[before] == ',') {
    notes.push_back(message);
    message = std::string("trailing comma before '") + at[0] + "' is not allowed in JSON";
  } else if (error.offset >= text_.size()) {
    notes.push_back("the file ends in the middle of a value: is it truncated?");
  } else if (sequence_ && (error.offset + 1 >= text_.size() || text_[error.offset] == '\n' ||
                           text_[error.offset + 1] == '\n')) {
    notes.push_back("a GeoJSON sequence holds one whole Feature on each line");
  }
  emit(base::Severity::kError, "GEO001", message, error.offset, std::move(notes));
}

// Stage 3: structure.
void Reader::read_top_level(Element doc) {
  const char* expected = "expected a FeatureCollection, a Feature, a Polygon or a MultiPolygon";
  if (doc.type() != element_type::OBJECT) {
    report(base::Severity::kError, "GEO004",
           "the top-level value is " + type_name(doc) + "; " + expected, root_offset_);
    return;
  }
  const std::optional<Element> type = member(doc, "type");
  if (!type || type->type() != element_type::STRING) {
    report(base::Severity::kError, "GEO004",
           "the top-level object has no \"type\" string; " + std::string(expected),
           !type ? root_offset_ : locator_.member(root_offset_, "type"));
    return;
  }
  read_crs(doc);
  const std::string_view name = string_of(*type);
  if (name == "FeatureCollection") {
    const std::optional<Element> features = member(doc, "features");
    const std::size_t at =
        features_at_ != kNone ? features_at_ : locator_.member(root_offset_, "features");
    if (!features || features->type() != element_type::ARRAY) {
      report(base::Severity::kError, "GEO005",
             !features ? "the FeatureCollection has no \"features\" member"
                       : "\"features\" is " + type_name(*features) + "; expected an array",
             at == kNone ? root_offset_ : at);
      return;
    }
    read_features();
  } else if (name == "Feature") {
    read_feature(doc, root_offset_);
  } else if (name == "Polygon" || name == "MultiPolygon") {
    FeatureState& feature = add_feature(root_offset_);
    feature.bare_geometry = true;
    read_geometry(feature, doc);
  } else {
    report(base::Severity::kError, "GEO004",
           "the top-level type is " + quote_text(name) + "; " + expected,
           locator_.member(root_offset_, "type"));
  }
}

// GeoJSON 2008: {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}}, or
// {"type": "EPSG", "properties": {"code": 25832}}.
void Reader::read_crs(Element doc) {
  const std::optional<Element> crs = member(doc, "crs");
  if (!crs || crs->type() == element_type::NULL_VALUE) return;
  const std::size_t at = locator_.member(root_offset_, "crs");
  const std::optional<Element> props = member(*crs, "properties");
  const std::optional<Element> name = props ? member(*props, "name") : std::nullopt;
  const std::optional<Element> code = props ? member(*props, "code") : std::nullopt;
  int epsg = 0;
  std::string text = compact(*crs);
  if (name && name->type() == element_type::STRING) {
    text = std::string(string_of(*name));
    epsg = epsg_code(text);
  } else if (code && code->type() == element_type::INT64) {
    epsg = static_cast<int>(code->get_int64().value_unsafe());
  } else if (code && code->type() == element_type::UINT64) {
    epsg = static_cast<int>(code->get_uint64().value_unsafe());
  }
  crs_offset_ = at;
  if (epsg > 0) {
    declared_crs_ = "EPSG:" + std::to_string(epsg);
  } else if (text.find("CRS84") != std::string::npos) {
    declared_crs_ = "OGC:CRS84";
  } else {
    report(base::Severity::kWarning, "GEO007",
           "crs " + quote_text(text) + " names no EPSG code; ignored", at);
  }
}

// A new feature, numbered by its position in the file (a bare geometry is feature 0).
FeatureState& Reader::add_feature(std::size_t offset) {
  const std::size_t index = features_.size();
  add_raw();
  FeatureState& feature = states_.emplace_back();
  feature.index = index;
  feature.offset = offset;
  return feature;
}

// The FeatureCollection's features, parsed in parallel a group at a time (parse() left the first
// group in chunks_) and read in order.
void Reader::read_features() {
  const std::size_t count = feature_offsets_.size();
  features_.reserve(count);
  states_.reserve(count);
  for (std::size_t group = 0; group < group_count() && !stopped_; ++group) {
    if (parsed_group_ != group) {
      if (!valid_group(group, chunks_)) throw SyntaxAbort{};
      parsed_group_ = group;
    }
    for (std::size_t k = 0; k < kGroup && !stopped_; ++k) {
      std::size_t index = (group * kGroup + k) * kChunk;
      if (index >= count) break;
      for (const Element value : array_of(chunks_[k].root)) {
        if (stopped_) break;
        read_feature(value, feature_offsets_[index++]);
      }
    }
  }
  validated_ = true;
}

void Reader::read_feature(Element value, std::size_t offset) {
  FeatureState& feature = add_feature(offset);
  RawFootprint& raw = features_[feature.index];
  // In a sequence each line is a Feature: say which line is not.
  const std::string line =
      sequence_ ? "line " + std::to_string(at(offset).span.line) + " of the GeoJSON sequence"
                : std::string();
  if (value.type() != element_type::OBJECT) {
    feature_issue(feature, true, "GEO015",
                  sequence_ ? line + " is " + type_name(value) + "; expected a Feature object"
                            : "is " + type_name(value) + "; expected an object",
                  {});
    return;
  }
  const auto [id, type, props, geometry] =
      members<4>(value, {"id", "type", "properties", "geometry"});
  if (id && id->type() != element_type::NULL_VALUE) {
    if (auto text = id_text(*id)) {
      raw.id = *text;
      feature.id_path = {{"id", 0}};
    } else {
      const bool empty = id->type() == element_type::STRING;  // id_text takes any other string
      feature_issue(
          feature, false, "GEO018",
          empty ? std::string("\"id\" is an empty string; ignored")
                : "\"id\" is " + type_name(*id) + "; expected a string or a number; ignored",
          {{"id", 0}});
    }
  }
  for (const char* key : {"id", "name"}) {
    const std::optional<Element> alt = props ? member(*props, key) : std::nullopt;
    if (!raw.id.empty() || !alt) continue;
    if (auto text = id_text(*alt)) {
      raw.id = *text;
      feature.id_path = {{"properties", 0}, {key, 0}};
    }
  }
  if (!type || type->type() != element_type::STRING || string_of(*type) != "Feature") {
    feature_issue(feature, true, "GEO015",
                  (sequence_ ? line + ": " : line) +
                      (!type ? std::string("has no \"type\"; expected \"Feature\"")
                             : "\"type\" is " + compact(*type) + "; expected \"Feature\""),
                  {{"type", 0}});
    return;
  }
  if (props) read_properties(feature, *props);
  if (!geometry || geometry->type() == element_type::NULL_VALUE) {
    feature_issue(feature, false, "GEO017",
                  !geometry ? "has no geometry; skipped" : "geometry is null; skipped",
                  {{"geometry", 0}});
    return;
  }
  read_geometry(feature, *geometry);
}

void Reader::read_properties(FeatureState& feature, Element value) {
  if (value.type() == element_type::NULL_VALUE) return;
  if (value.type() != element_type::OBJECT) {
    feature_issue(feature, false, "GEO018",
                  "\"properties\" is " + type_name(value) + "; expected an object; ignored",
                  {{"properties", 0}});
    return;
  }
  // Duplicate keys: the last one wins (PropertyTable::set), as in nlohmann's map.
  for (const auto field : object_of(value)) {
    switch (field.value.type()) {
      case element_type::BOOL:
        properties_.set(feature.index, field.key, field.value.get_bool().value_unsafe());
        break;
      case element_type::INT64:
      case element_type::UINT64:
      case element_type::DOUBLE:
        properties_.set(feature.index, field.key, number(field.value));
        break;
      case element_type::STRING:
        properties_.set_text(feature.index, field.key, string_of(field.value));
        break;
      case element_type::OBJECT:
      case element_type::ARRAY:
        properties_.set_text(feature.index, field.key, compact(field.value));
        break;
      case element_type::NULL_VALUE:
        properties_.set(feature.index, field.key, std::monostate{});
        break;
    }
  }
}

void Reader::read_geometry(FeatureState& feature, Element geometry) {
  const std::vector<PathStep> here =
      feature.bare_geometry ? std::vector<PathStep>{} : std::vector<PathStep>{{"geometry", 0}};
  if (geometry.type() != element_type::OBJECT) {
    feature_issue(feature, true, "GEO016",
                  "geometry is " + type_name(geometry) + "; expected an object", here);
    return;
  }
  const auto [type, coordinates] = members<2>(geometry, {"type", "coordinates"});
  std::vector<PathStep> type_path = here;
  type_path.push_back({"type", 0});
  if (!type || type->type() != element_type::STRING) {
    feature_issue(feature, true, "GEO016", "geometry has no \"type\" string", type_path);
    return;
  }
  const std::string name(string_of(*type));
  if (!is_geojson_geometry(name)) {
    feature_issue(feature, true, "GEO016",
                  "geometry type " + quote_text(name) + " is not a GeoJSON geometry type",
                  type_path);
    return;
  }
  if (name == "GeometryCollection") {
    read_collection(feature, geometry, here);
    return;
  }
  if (name != "Polygon" && name != "MultiPolygon") {
    feature_issue(feature, false, "GEO017", "geometry type " + name + " is not a polygon; skipped",
                  type_path);
    return;
  }
  std::vector<PathStep> coordinates_path = here;
  coordinates_path.push_back({"coordinates", 0});
  if (!coordinates || coordinates->type() != element_type::ARRAY) {
    feature_issue(feature, true, "GEO014",
                  !coordinates ? name + " has no \"coordinates\""
                               : name + " \"coordinates\" is " + type_name(*coordinates) +
                                     "; expected an array",
                  !coordinates ? here : coordinates_path);
    return;
  }
  const simdjson::dom::array polygons = array_of(*coordinates);
  if (array_size(polygons) == 0) {
    feature_issue(feature, false, "GEO017", "empty " + name + "; skipped", coordinates_path);
    return;
  }
  if (name == "Polygon") {
    if (auto polygon = read_polygon(feature, *coordinates, Where{})) {
      features_[feature.index].polygons.push_back(std::move(*polygon));
    }
    return;
  }
  features_[feature.index].multi = true;
  std::size_t i = 0;
  for (const Element rings : polygons) {
    if (stopped_) break;
    Where where;
    where.polygon = i++;
    if (auto polygon = read_polygon(feature, rings, where)) {
      features_[feature.index].polygons.push_back(std::move(*polygon));
    }
  }
}

// A GeometryCollection's Polygons and MultiPolygons are the polygons of one MultiPolygon, numbered
// across its members in order; other members are left out with a warning.
void Reader::read_collection(FeatureState& feature, Element geometry,
                             const std::vector<PathStep>& here) {
  std::vector<PathStep> path = here;
  path.push_back({"geometries", 0});
  const std::optional<Element> members = member(geometry, "geometries");
  if (!members || members->type() != element_type::ARRAY) {
    feature_issue(feature, true, "GEO014",
                  !members ? std::string("GeometryCollection has no \"geometries\"")
                           : "GeometryCollection \"geometries\" is " + type_name(*members) +
                                 "; expected an array",
                  !members ? here : path);
    return;
  }
  features_[feature.index].multi = true;
  collection_paths_[feature.index];
  std::size_t m = 0;
  for (const Element item : array_of(*members)) {
    if (stopped_) break;
    std::vector<PathStep> at = path;
    at.push_back({{}, m++});
    read_collection_member(feature, item, at);
  }
  if (collection_paths_[feature.index].empty()) {
    feature_issue(feature, false, "GEO017", "GeometryCollection holds no polygon; skipped", path);
  }
}

void Reader::read_collection_member(FeatureState& feature, Element geometry,
                                    const std::vector<PathStep>& here) {
  const std::string label = "GeometryCollection member " + std::to_string(here.back().index);
  const auto [type, coordinates] = members<2>(geometry, {"type", "coordinates"});
  const std::string_view name =
      type && type->type() == element_type::STRING ? string_of(*type) : std::string_view();
  std::vector<PathStep> coordinates_path = here;
  coordinates_path.push_back({"coordinates", 0});
  const bool polygons = name == "Polygon" || name == "MultiPolygon";
  if (!polygons || !coordinates || coordinates->type() != element_type::ARRAY ||
      array_size(*coordinates) == 0) {
    std::vector<PathStep> type_path = here;
    type_path.push_back({"type", 0});
    feature_issue(feature, false, "GEO017",
                  label + " is " +
                      (polygons       ? "an empty " + std::string(name)
                       : name.empty() ? type_name(geometry) + " without a geometry type"
                                      : "a " + std::string(name)) +
                      "; left out",
                  polygons ? coordinates_path : type_path);
    return;
  }
  std::vector<std::vector<PathStep>>& paths = collection_paths_[feature.index];
  const auto read_one = [&](Element rings, std::vector<PathStep> rings_path) {
    Where where;
    where.polygon = paths.size();
    paths.push_back(std::move(rings_path));
    if (auto polygon = read_polygon(feature, rings, where)) {
      features_[feature.index].polygons.push_back(std::move(*polygon));
    }
  };
  if (name == "Polygon") {
    read_one(*coordinates, coordinates_path);
    return;
  }
  std::size_t j = 0;
  for (const Element rings : array_of(*coordinates)) {
    std::vector<PathStep> rings_path = coordinates_path;
    rings_path.push_back({{}, j++});
    read_one(rings, std::move(rings_path));
  }
}

std::optional<kernel::Polygon> Reader::read_polygon(FeatureState& feature, Element rings,
                                                    Where where) {
  const bool is_array = rings.type() == element_type::ARRAY;
  if (!is_array || array_size(rings) == 0) {
    feature_issue(feature, true, "GEO014",
                  ring_label(where) + " is " + (is_array ? "empty" : type_name(rings)) +
                      "; expected an array of rings",
                  geometry_path(feature, where));
    return std::nullopt;
  }
  kernel::Polygon polygon;
  bool ok = true;
  std::size_t r = 0;
  for (const Element item : array_of(rings)) {
    where.ring = r;
    auto ring = read_ring(feature, item, where);
    if (!ring) {
      ok = false;
    } else if (r == 0) {
      polygon.outer = std::move(*ring);
    } else {
      polygon.holes.push_back(std::move(*ring));
    }
    ++r;
  }
  if (!ok) return std::nullopt;
  return polygon;
}

// A ring must be closed (RFC 7946 3.1.6); an open one is closed with a warning, since adding the
// closing position cannot change the intended shape.
std::optional<kernel::Ring> Reader::read_ring(FeatureState& feature, Element ring,
                                              const Where& where) {
  if (ring.type() != element_type::ARRAY) {
    feature_issue(feature, true, "GEO014",
                  ring_label(where) + " is " + type_name(ring) + "; expected an array of positions",
                  geometry_path(feature, where));
    return std::nullopt;
  }
  const simdjson::dom::array positions = array_of(ring);
  kernel::Ring out;
  out.reserve(array_size(positions));
  Where at = where;
  at.position = 0;
  for (const Element position : positions) {
    auto p = read_position(feature, position, at);
    if (!p) return std::nullopt;
    out.push_back(*p);
    ++at.position;
  }
  const std::size_t n = out.size();
  const bool closed = n >= 2 && out.front() == out.back();
  if (closed ? n < 4 : n < 3) {
    feature_issue(feature, true, "GEO010",
                  ring_label(where) + " has " + std::to_string(n) + " position" +
                      (n == 1 ? "" : "s") + "; a closed ring needs at least 4",
                  geometry_path(feature, where));
    return std::nullopt;
  }
  if (closed) {
    out.pop_back();
  } else {
    feature_issue(feature, false, "GEO011",
                  ring_label(where) +
                      " is not closed (its last position differs from the first); "
                      "closed it",
                  geometry_path(feature, where));
  }
  return out;
}

// The label of a position in messages: "polygon 1 ring 0 position 3".
std::string position_label(const Where& where) {
  return ring_label(where) + " position " + std::to_string(where.position);
}

std::optional<kernel::Vec2> Reader::read_position(FeatureState& feature, Element position,
                                                  Where where) {
  const bool is_array = position.type() == element_type::ARRAY;
  const std::size_t size = is_array ? array_size(position) : 0;
  if (size < 2) {
    feature_issue(feature, true, "GEO014",
                  position_label(where) + " is " +
                      (is_array ? "an array of " + std::to_string(size) : type_name(position)) +
                      "; expected [x, y] or [x, y, z]",
                  geometry_path(feature, where));
    return std::nullopt;
  }
  double xyz[3] = {0, 0, 0};
  std::size_t c = 0;
  for (const Element v : array_of(position)) {
    if (c == 3) break;
    where.coordinate = c;
    if (!is_number(v)) {
      feature_issue(
          feature, true, "GEO012",
          position_label(where) + " coordinate " + std::to_string(c) + " is " + type_name(v) +
              (v.type() == element_type::STRING ? " (" + quote_text(string_of(v)) + ")" : "") +
              "; expected a number",
          geometry_path(feature, where));
      return std::nullopt;
    }
    xyz[c] = number(v);
    if (!std::isfinite(xyz[c]) || std::abs(xyz[c]) > geo_options_.max_abs_coordinate) {
      feature_issue(feature, true, "GEO013",
                    position_label(where) + " coordinate " +
                        (std::isfinite(xyz[c]) ? number_text(xyz[c]) + " is beyond +-" +
                                                     number_text(geo_options_.max_abs_coordinate) +
                                                     " m (GeoJsonOptions::max_abs_coordinate)"
                                               : std::string("is not finite")),
                    geometry_path(feature, where));
      return std::nullopt;
    }
    ++c;
  }
  if ((size > 3 || xyz[2] != 0) && !warned_extra_dimensions_) {
    warned_extra_dimensions_ = true;
    where.coordinate = 2;
    feature_issue(feature, false, "GEO009",
                  position_label(where) + " has " + std::to_string(size) +
                      " numbers; only x and y are used (footprints lie at z = 0; reported once)",
                  geometry_path(feature, where));
  }
  return kernel::Vec2{xyz[0], xyz[1]};
}

base::Result<FootprintSet> Reader::run() {
  if (prescan() && parse()) {
    try {
      if (sequence_) {
        read_features();
      } else {
        read_top_level(top_.root);
      }
    } catch (const SyntaxAbort&) {
      // No diagnostic but GEO001 has been emitted (ensure_valid()): forget what was read.
      features_.clear();
      properties_ = PropertyTable();
      states_.clear();
      declared_crs_.clear();
      crs_offset_ = kNone;
    }
  }
  // The parsers' memory goes before the finishing steps allocate theirs.
  top_ = ParsedPiece();
  chunks_.clear();
  chunks_.shrink_to_fit();
  feature_offsets_.clear();
  feature_offsets_.shrink_to_fit();
  feature_ends_.clear();
  feature_ends_.shrink_to_fit();
  finish_features(at(crs_offset_));
  return result();
}

}  // namespace

bool is_geojson_sequence_path(std::string_view path) {
  std::string lower(path.substr(path.size() - std::min<std::size_t>(path.size(), 12)));
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c + 32) : c; });
  const std::string_view name(lower);
  return std::any_of(kSequenceSuffixes.begin(), kSequenceSuffixes.end(),
                     [&](std::string_view suffix) { return name.ends_with(suffix); });
}

base::Result<FootprintSet> read_geojson(std::string_view text, const std::string& source_name,
                                        const GeoJsonOptions& options) {
  return Reader(text, source_name, options).run();
}

}  // namespace insula::io
