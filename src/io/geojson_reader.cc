// GeoJSON footprint reader (RFC 7946 structure, GeoJSON-2008 "crs" member). Stages: byte
// pre-scan (empty input, nesting depth) -> nlohmann::json DOM parse -> structure walk collecting
// world-coordinate rings per feature -> the finishing steps shared with the OSM reader
// (io/footprint_finish.h: CRS and reprojection, origin shift, repair, id de-duplication).
// nlohmann::json keeps no positions, so diagnostics find theirs again with a small scanner over the
// (by then known valid) text: feature starts are listed once, deeper paths are scanned from the
// feature start only when a diagnostic needs them.
#include "io/geojson_reader.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <utility>

namespace insula::io {
namespace {

using base::Diagnostic;
using nlohmann::json;
constexpr std::size_t kNone = kNoIndex;

// ---------------------------------------------------------------------------------------------
// Byte-level scanning. Works on any bytes (the depth scan runs before parsing); never reads past
// the end.

// Offset just past the string whose opening quote is at `pos`; text.size() when unterminated.
std::size_t skip_string(std::string_view text, std::size_t pos) {
  for (++pos; pos < text.size(); ++pos) {
    if (text[pos] == '\\') {
      ++pos;
    } else if (text[pos] == '"') {
      return pos + 1;
    }
  }
  return text.size();
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Offset of the first bracket that nests deeper than `max_depth`, outside strings.
std::optional<std::size_t> find_too_deep(std::string_view text, std::size_t max_depth) {
  std::size_t depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      i = skip_string(text, i) - 1;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

// One step of a path into a JSON value: an object member (key) or an array element (index).
struct PathStep {
  std::string_view key;
  std::size_t index = 0;
};

// Finds values again in text that nlohmann::json accepted. Offsets are byte offsets of the
// first character of a value; kNone propagates.
class TextLocator {
 public:
  explicit TextLocator(std::string_view text) : text_(text) {}

  std::size_t skip_space(std::size_t pos) const {
    if (pos == 0 && text_.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;
    while (pos < text_.size() && is_space(text_[pos])) ++pos;
    return pos;
  }

  // Offset just past the value starting at `pos`.
  std::size_t skip_value(std::size_t pos) const {
    if (pos >= text_.size()) return text_.size();
    if (text_[pos] == '"') return skip_string(text_, pos);
    if (text_[pos] != '[' && text_[pos] != '{') {
      while (pos < text_.size() && !is_space(text_[pos]) && text_[pos] != ',' &&
             text_[pos] != ']' && text_[pos] != '}') {
        ++pos;
      }
      return pos;
    }
    std::size_t depth = 0;
    for (; pos < text_.size(); ++pos) {
      const char c = text_[pos];
      if (c == '"') {
        pos = skip_string(text_, pos) - 1;
      } else if (c == '[' || c == '{') {
        ++depth;
      } else if ((c == ']' || c == '}') && --depth == 0) {
        return pos + 1;
      }
    }
    return text_.size();
  }

  // Offsets of the elements of the array at `pos`.
  std::vector<std::size_t> elements(std::size_t pos) const {
    std::vector<std::size_t> out;
    if (pos >= text_.size() || text_[pos] != '[') return out;
    pos = skip_space(pos + 1);
    while (pos < text_.size() && text_[pos] != ']') {
      out.push_back(pos);
      pos = skip_space(skip_value(pos));
      if (pos >= text_.size() || text_[pos] != ',') break;
      pos = skip_space(pos + 1);
    }
    return out;
  }

  // Offset of the value of member `key` (the last one, as nlohmann keeps the last duplicate).
  std::size_t member(std::size_t pos, std::string_view key) const {
    if (pos >= text_.size() || text_[pos] != '{') return kNone;
    std::size_t found = kNone;
    pos = skip_space(pos + 1);
    while (pos < text_.size() && text_[pos] == '"') {
      const std::size_t key_end = skip_string(text_, pos);
      const std::string_view name = text_.substr(pos + 1, key_end - pos - 2);
      pos = skip_space(key_end);
      if (pos >= text_.size() || text_[pos] != ':') break;
      pos = skip_space(pos + 1);
      if (name == key) found = pos;
      pos = skip_space(skip_value(pos));
      if (pos >= text_.size() || text_[pos] != ',') break;
      pos = skip_space(pos + 1);
    }
    return found;
  }

  std::size_t element(std::size_t pos, std::size_t index) const {
    if (pos >= text_.size() || text_[pos] != '[') return kNone;
    pos = skip_space(pos + 1);
    for (std::size_t i = 0; pos < text_.size() && text_[pos] != ']'; ++i) {
      if (i == index) return pos;
      pos = skip_space(skip_value(pos));
      if (pos >= text_.size() || text_[pos] != ',') break;
      pos = skip_space(pos + 1);
    }
    return kNone;
  }

  // The deepest offset reachable along `path` from `pos` (best effort: stops where a step fails).
  std::size_t follow(std::size_t pos, const std::vector<PathStep>& path) const {
    for (const PathStep& step : path) {
      const std::size_t next = step.key.empty() ? element(pos, step.index) : member(pos, step.key);
      if (next == kNone) break;
      pos = next;
    }
    return pos;
  }

 private:
  std::string_view text_;
};

// ---------------------------------------------------------------------------------------------
// JSON parse errors.

// Offset and message of the first syntax error, found by a validating SAX pass (no exceptions).
class ErrorCatcher : public nlohmann::json_sax<json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& e) override {
    // `position` counts the bytes read: the last one read is where the error shows. A number
    // overflow is reported after the whole token, so point at its start instead.
    offset = position > 0 ? position - 1 : 0;
    if (e.id == 406 && position >= last_token.size()) offset = position - last_token.size();
    // Escape bytes outside printable ASCII: the message may quote the invalid UTF-8 it rejects.
    for (const char c : std::string_view(e.what())) {
      const auto byte = static_cast<unsigned char>(c);
      if (byte >= 0x20 && byte < 0x7F) {
        message += c;
      } else {
        constexpr char kHex[] = "0123456789abcdef";
        message += "\\x";
        message += kHex[byte >> 4];
        message += kHex[byte & 15];
      }
    }
    if (message.rfind("[json.exception.", 0) == 0) message.erase(0, message.find("] ") + 2);
    if (message.rfind("parse error at line", 0) == 0) message.erase(0, message.find(": ") + 2);
    return false;
  }

  std::size_t offset = 0;
  std::string message;
};

// ---------------------------------------------------------------------------------------------
// Small helpers.

std::string type_name(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array";
    case json::value_t::string:
      return "a string";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return "a number";
    default:
      return "an unsupported value";
  }
}

std::string compact(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

// A numeric or non-empty string id, as text.
std::optional<std::string> id_text(const json& value) {
  if (value.is_string() && !value.get_ref<const std::string&>().empty()) {
    return value.get<std::string>();
  }
  if (value.is_number()) return number_text(value.get<double>());
  return std::nullopt;
}

const json* member(const json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
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

class Reader : public FootprintBuilder {
 public:
  Reader(std::string_view text, const std::string& name, const GeoJsonOptions& options)
      : FootprintBuilder(name, options, "GeoJsonOptions"),
        text_(text),
        geo_options_(options),
        locator_(text) {}

  base::Result<FootprintSet> run();

 private:
  // Diagnostics ----------------------------------------------------------------------------
  Location at(std::size_t offset);
  Location locate(std::size_t feature, const FootprintPlace& place) override;
  void report(base::Severity severity, const char* code, std::string message, std::size_t offset,
              std::vector<std::string> notes = {}) {
    FootprintBuilder::report(severity, code, std::move(message), at(offset), std::move(notes));
  }
  void feature_issue(FeatureState& feature, bool is_error, const char* code,
                     const std::string& message, const std::vector<PathStep>& path,
                     std::vector<std::string> notes = {});
  std::vector<PathStep> geometry_path(const FeatureState& feature, const Where& where) const;

  // Stages ---------------------------------------------------------------------------------
  bool prescan();
  std::optional<json> parse();
  void read_top_level(const json& doc);
  void read_crs(const json& doc);
  FeatureState& add_feature(std::size_t offset);
  void read_features(const std::vector<std::size_t>& offsets);
  void read_feature(const json& value, std::size_t index, std::size_t offset);
  void read_geometry(FeatureState& feature, const json& geometry);
  void read_properties(FeatureState& feature, const json& value);
  std::optional<kernel::Polygon> read_polygon(FeatureState& feature, const json& rings,
                                              Where where);
  std::optional<kernel::Ring> read_ring(FeatureState& feature, const json& ring,
                                        const Where& where);
  std::optional<kernel::Vec2> read_position(FeatureState& feature, const json& position,
                                            Where where);

  std::string_view text_;
  const GeoJsonOptions& geo_options_;
  TextLocator locator_;
  std::optional<base::Source> source_;  // built on the first positioned diagnostic
  bool warned_extra_dimensions_ = false;
  std::size_t crs_offset_ = kNone;
  std::size_t root_offset_ = 0;
  std::vector<FeatureState> states_;  // parallel to features_
};

FootprintBuilder::Location Reader::at(std::size_t offset) {
  if (offset == kNone) return whole_input();
  if (!source_) source_.emplace(name_, std::string(text_));
  const auto [line, column] = source_->locate(offset);
  return {offset, base::Span::at(name_, line, column)};
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
  const std::size_t offset =
      feature.offset == kNone ? kNone : locator_.follow(feature.offset, path);
  FootprintBuilder::feature_issue(feature.index, is_error, code, message, at(offset),
                                  std::move(notes));
}

std::vector<PathStep> Reader::geometry_path(const FeatureState& feature, const Where& where) const {
  std::vector<PathStep> path;
  if (!feature.bare_geometry) path.push_back({"geometry", 0});
  path.push_back({"coordinates", 0});
  for (std::size_t index : {where.polygon, where.ring, where.position, where.coordinate}) {
    if (index != kNone) path.push_back({{}, index});
  }
  return path;
}

// Stage 1: bytes. Empty input and hostile nesting are rejected before nlohmann's parser runs.
bool Reader::prescan() {
  root_offset_ = locator_.skip_space(0);
  if (root_offset_ >= text_.size()) {
    report(base::Severity::kError, "GEO002", "file is empty; expected a GeoJSON object", kNone);
    return false;
  }
  if (const auto deep = find_too_deep(text_, geo_options_.max_depth)) {
    report(base::Severity::kError, "GEO003",
           "arrays and objects nest deeper than " + std::to_string(geo_options_.max_depth) +
               " levels (GeoJsonOptions::max_depth)",
           *deep);
    return false;
  }
  return true;
}

// Stage 2: JSON. The DOM parse runs without exceptions; only on failure a second, validating
// SAX pass finds the error's position and nlohmann's message. The elements of the root's
// "features" array are checked but not kept: read_features() parses them one batch at a time, so
// a city's features are never all in memory as JSON.
std::optional<json> Reader::parse() {
  const char* begin = text_.data();
  bool in_features = false;
  bool features_key = false;
  const json::parser_callback_t drop_features = [&](int depth, json::parse_event_t event,
                                                    json& parsed) {
    using Event = json::parse_event_t;
    if (depth == 1 && event == Event::key) {
      features_key = parsed == "features";
    } else if (depth == 1 && event == Event::array_start) {
      in_features = features_key;
    } else if (depth == 1 && event == Event::array_end) {
      in_features = false;
    } else if (depth == 2 && in_features &&
               (event == Event::object_end || event == Event::array_end || event == Event::value)) {
      return false;
    }
    return true;
  };
  json doc = json::parse(begin, begin + text_.size(), drop_features, false);
  if (!doc.is_discarded()) return doc;
  ErrorCatcher catcher;
  json::sax_parse(begin, begin + text_.size(), &catcher);
  std::string message = catcher.message;
  std::vector<std::string> notes;
  const std::string_view at = text_.substr(std::min(catcher.offset, text_.size()));
  const std::size_t before =
      text_.find_last_not_of(" \t\r\n", catcher.offset - (catcher.offset > 0));
  if (at.rfind("NaN", 0) == 0 || at.rfind("Infinity", 0) == 0 || at.rfind("nan", 0) == 0 ||
      at.rfind("inf", 0) == 0) {
    notes.push_back(message);
    message = "NaN and Infinity are not valid JSON numbers";
  } else if (!at.empty() && (at[0] == ']' || at[0] == '}') && catcher.offset > 0 &&
             before != std::string_view::npos && text_[before] == ',') {
    notes.push_back(message);
    message = std::string("trailing comma before '") + at[0] + "' is not allowed in JSON";
  } else if (catcher.offset >= text_.size()) {
    notes.push_back("the file ends in the middle of a value: is it truncated?");
  }
  report(base::Severity::kError, "GEO001", message, catcher.offset, std::move(notes));
  return std::nullopt;
}

// Stage 3: structure.
void Reader::read_top_level(const json& doc) {
  const char* expected = "expected a FeatureCollection, a Feature, a Polygon or a MultiPolygon";
  if (!doc.is_object()) {
    report(base::Severity::kError, "GEO004",
           "the top-level value is " + type_name(doc) + "; " + expected, root_offset_);
    return;
  }
  const json* type = member(doc, "type");
  if (type == nullptr || !type->is_string()) {
    report(base::Severity::kError, "GEO004",
           "the top-level object has no \"type\" string; " + std::string(expected),
           type == nullptr ? root_offset_ : locator_.member(root_offset_, "type"));
    return;
  }
  read_crs(doc);
  const std::string& name = type->get_ref<const std::string&>();
  if (name == "FeatureCollection") {
    const json* features = member(doc, "features");
    const std::size_t at = locator_.member(root_offset_, "features");
    if (features == nullptr || !features->is_array()) {
      report(base::Severity::kError, "GEO005",
             features == nullptr
                 ? "the FeatureCollection has no \"features\" member"
                 : "\"features\" is " + type_name(*features) + "; expected an array",
             at == kNone ? root_offset_ : at);
      return;
    }
    read_features(locator_.elements(at));
  } else if (name == "Feature") {
    read_feature(doc, 0, root_offset_);
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
void Reader::read_crs(const json& doc) {
  const json* crs = member(doc, "crs");
  if (crs == nullptr || crs->is_null()) return;
  const std::size_t at = locator_.member(root_offset_, "crs");
  const json* props = member(*crs, "properties");
  const json* name = props != nullptr ? member(*props, "name") : nullptr;
  const json* code = props != nullptr ? member(*props, "code") : nullptr;
  int epsg = 0;
  std::string text = compact(*crs);
  if (name != nullptr && name->is_string()) {
    text = name->get<std::string>();
    epsg = epsg_code(text);
  } else if (code != nullptr && code->is_number_integer()) {
    epsg = code->get<int>();
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
  RawFootprint& raw = features_.emplace_back();
  raw.name = raw.label = "feature " + std::to_string(index);
  raw.fallback_id = "feature-" + std::to_string(index);
  FeatureState& feature = states_.emplace_back();
  feature.index = index;
  feature.offset = offset;
  return feature;
}

// The FeatureCollection's features at `offsets`, parsed in parallel a batch at a time (the whole
// text passed the parser already) and read in order.
void Reader::read_features(const std::vector<std::size_t>& offsets) {
  constexpr std::size_t kBatch = 8192;
  std::vector<json> batch;
  for (std::size_t first = 0; first < offsets.size() && !stopped_; first += kBatch) {
    const std::size_t count = std::min(kBatch, offsets.size() - first);
    batch.assign(count, json());
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t k) {
      const std::size_t start = offsets[first + k];
      const char* at = text_.data() + start;
      batch[k] = json::parse(at, text_.data() + locator_.skip_value(start), nullptr, false);
    });
    for (std::size_t k = 0; k < count && !stopped_; ++k) {
      read_feature(batch[k], first + k, offsets[first + k]);
    }
  }
}

void Reader::read_feature(const json& value, std::size_t /*index*/, std::size_t offset) {
  FeatureState& feature = add_feature(offset);
  RawFootprint& raw = features_[feature.index];
  if (!value.is_object()) {
    feature_issue(feature, true, "GEO015", "is " + type_name(value) + "; expected an object", {});
    return;
  }
  const json* props = member(value, "properties");
  if (const json* id = member(value, "id"); id != nullptr && !id->is_null()) {
    if (auto text = id_text(*id)) {
      raw.id = *text;
      feature.id_path = {{"id", 0}};
    } else {
      feature_issue(feature, false, "GEO018",
                    "\"id\" is " + type_name(*id) + "; expected a string or a number; ignored",
                    {{"id", 0}});
    }
  }
  for (const char* key : {"id", "name"}) {
    const json* alt = props != nullptr ? member(*props, key) : nullptr;
    if (!raw.id.empty() || alt == nullptr) continue;
    if (auto text = id_text(*alt)) {
      raw.id = *text;
      feature.id_path = {{"properties", 0}, {key, 0}};
    }
  }
  if (!raw.id.empty()) raw.label += " (id " + quote_text(raw.id) + ")";
  const json* type = member(value, "type");
  if (type == nullptr || !type->is_string() || type->get_ref<const std::string&>() != "Feature") {
    feature_issue(feature, true, "GEO015",
                  type == nullptr ? std::string("has no \"type\"; expected \"Feature\"")
                                  : "\"type\" is " + compact(*type) + "; expected \"Feature\"",
                  {{"type", 0}});
    return;
  }
  if (props != nullptr) read_properties(feature, *props);
  const json* geometry = member(value, "geometry");
  if (geometry == nullptr || geometry->is_null()) {
    feature_issue(feature, false, "GEO017",
                  geometry == nullptr ? "has no geometry; skipped" : "geometry is null; skipped",
                  {{"geometry", 0}});
    return;
  }
  read_geometry(feature, *geometry);
}

void Reader::read_properties(FeatureState& feature, const json& value) {
  if (value.is_null()) return;
  if (!value.is_object()) {
    feature_issue(feature, false, "GEO018",
                  "\"properties\" is " + type_name(value) + "; expected an object; ignored",
                  {{"properties", 0}});
    return;
  }
  for (const auto& [key, item] : value.items()) {
    shape::Value converted;
    if (item.is_boolean()) {
      converted = item.get<bool>();
    } else if (item.is_number()) {
      converted = item.get<double>();
    } else if (item.is_string()) {
      converted = item.get<std::string>();
    } else if (!item.is_null()) {
      converted = compact(item);
    }
    features_[feature.index].properties.insert_or_assign(key, std::move(converted));
  }
}

void Reader::read_geometry(FeatureState& feature, const json& geometry) {
  const std::vector<PathStep> here =
      feature.bare_geometry ? std::vector<PathStep>{} : std::vector<PathStep>{{"geometry", 0}};
  if (!geometry.is_object()) {
    feature_issue(feature, true, "GEO016",
                  "geometry is " + type_name(geometry) + "; expected an object", here);
    return;
  }
  const json* type = member(geometry, "type");
  std::vector<PathStep> type_path = here;
  type_path.push_back({"type", 0});
  if (type == nullptr || !type->is_string()) {
    feature_issue(feature, true, "GEO016", "geometry has no \"type\" string", type_path);
    return;
  }
  const std::string& name = type->get_ref<const std::string&>();
  if (!is_geojson_geometry(name)) {
    feature_issue(feature, true, "GEO016",
                  "geometry type " + quote_text(name) + " is not a GeoJSON geometry type",
                  type_path);
    return;
  }
  if (name != "Polygon" && name != "MultiPolygon") {
    feature_issue(feature, false, "GEO017", "geometry type " + name + " is not a polygon; skipped",
                  type_path);
    return;
  }
  const json* coordinates = member(geometry, "coordinates");
  std::vector<PathStep> coordinates_path = here;
  coordinates_path.push_back({"coordinates", 0});
  if (coordinates == nullptr || !coordinates->is_array()) {
    feature_issue(feature, true, "GEO014",
                  coordinates == nullptr ? name + " has no \"coordinates\""
                                         : name + " \"coordinates\" is " + type_name(*coordinates) +
                                               "; expected an array",
                  coordinates == nullptr ? here : coordinates_path);
    return;
  }
  if (coordinates->empty()) {
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
  for (std::size_t i = 0; i < coordinates->size() && !stopped_; ++i) {
    Where where;
    where.polygon = i;
    if (auto polygon = read_polygon(feature, (*coordinates)[i], where)) {
      features_[feature.index].polygons.push_back(std::move(*polygon));
    }
  }
}

std::optional<kernel::Polygon> Reader::read_polygon(FeatureState& feature, const json& rings,
                                                    Where where) {
  if (!rings.is_array() || rings.empty()) {
    feature_issue(feature, true, "GEO014",
                  ring_label(where) + " is " + (rings.is_array() ? "empty" : type_name(rings)) +
                      "; expected an array of rings",
                  geometry_path(feature, where));
    return std::nullopt;
  }
  kernel::Polygon polygon;
  bool ok = true;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    where.ring = r;
    auto ring = read_ring(feature, rings[r], where);
    if (!ring) {
      ok = false;
    } else if (r == 0) {
      polygon.outer = std::move(*ring);
    } else {
      polygon.holes.push_back(std::move(*ring));
    }
  }
  if (!ok) return std::nullopt;
  return polygon;
}

// A ring must be closed (RFC 7946 3.1.6); an open one is closed with a warning, since adding the
// closing position cannot change the intended shape.
std::optional<kernel::Ring> Reader::read_ring(FeatureState& feature, const json& ring,
                                              const Where& where) {
  if (!ring.is_array()) {
    feature_issue(feature, true, "GEO014",
                  ring_label(where) + " is " + type_name(ring) + "; expected an array of positions",
                  geometry_path(feature, where));
    return std::nullopt;
  }
  kernel::Ring out;
  out.reserve(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) {
    Where at = where;
    at.position = i;
    auto p = read_position(feature, ring[i], at);
    if (!p) return std::nullopt;
    out.push_back(*p);
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

std::optional<kernel::Vec2> Reader::read_position(FeatureState& feature, const json& position,
                                                  Where where) {
  const std::string label = ring_label(where) + " position " + std::to_string(where.position);
  if (!position.is_array() || position.size() < 2) {
    feature_issue(feature, true, "GEO014",
                  label + " is " +
                      (position.is_array() ? "an array of " + std::to_string(position.size())
                                           : type_name(position)) +
                      "; expected [x, y] or [x, y, z]",
                  geometry_path(feature, where));
    return std::nullopt;
  }
  double xyz[3] = {0, 0, 0};
  const std::size_t used = std::min<std::size_t>(position.size(), 3);
  for (std::size_t c = 0; c < used; ++c) {
    where.coordinate = c;
    const json& v = position[c];
    if (!v.is_number()) {
      feature_issue(
          feature, true, "GEO012",
          label + " coordinate " + std::to_string(c) + " is " + type_name(v) +
              (v.is_string() ? " (" + quote_text(v.get_ref<const std::string&>()) + ")" : "") +
              "; expected a number",
          geometry_path(feature, where));
      return std::nullopt;
    }
    xyz[c] = v.get<double>();
    if (!std::isfinite(xyz[c]) || std::abs(xyz[c]) > geo_options_.max_abs_coordinate) {
      feature_issue(feature, true, "GEO013",
                    label + " coordinate " +
                        (std::isfinite(xyz[c]) ? number_text(xyz[c]) + " is beyond +-" +
                                                     number_text(geo_options_.max_abs_coordinate) +
                                                     " m (GeoJsonOptions::max_abs_coordinate)"
                                               : std::string("is not finite")),
                    geometry_path(feature, where));
      return std::nullopt;
    }
  }
  if ((position.size() > 3 || xyz[2] != 0) && !warned_extra_dimensions_) {
    warned_extra_dimensions_ = true;
    where.coordinate = 2;
    feature_issue(feature, false, "GEO009",
                  label + " has " + std::to_string(position.size()) +
                      " numbers; only x and y are used (footprints lie at z = 0; reported once)",
                  geometry_path(feature, where));
  }
  return kernel::Vec2{xyz[0], xyz[1]};
}

base::Result<FootprintSet> Reader::run() {
  std::optional<json> doc;
  if (prescan()) doc = parse();
  if (doc) read_top_level(*doc);
  finish_features(at(crs_offset_));
  return result();
}

}  // namespace

base::Result<FootprintSet> read_geojson(std::string_view text, const std::string& source_name,
                                        const GeoJsonOptions& options) {
  return Reader(text, source_name, options).run();
}

}  // namespace insula::io
