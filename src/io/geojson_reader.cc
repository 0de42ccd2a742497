// GeoJSON footprint reader (RFC 7946 structure, GeoJSON-2008 "crs" member). Stages: byte
// pre-scan (empty input, nesting depth) -> nlohmann::json DOM parse -> structure walk collecting
// world-coordinate rings per feature -> CRS choice and reprojection (io/crs.h) -> origin choice
// and shift -> kernel::repair() and the simplicity builders need -> id de-duplication.
// nlohmann::json keeps no positions, so diagnostics find theirs again with a small scanner over the
// (by then known valid) text: feature starts are listed once, deeper paths are scanned from the
// feature start only when a diagnostic needs them.
#include "io/geojson_reader.h"

#include "io/crs.h"
#include "kernel/skeleton.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

namespace insula::io {
namespace {

using base::Diagnostic;
using nlohmann::json;
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

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

std::string quote_text(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out = "\"";
  out.append(text.substr(0, kMax));
  if (text.size() > kMax) out += "...";
  return out + "\"";
}

std::string compact(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string number_text(double v) {
  if (std::abs(v) < 1e15 && v == std::floor(v)) return std::to_string(static_cast<long long>(v));
  return compact(json(v));
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

// Where two rings of a polygon meet, or one ring meets itself, other than at the shared vertex of
// consecutive edges. O(n^2), only run to explain a polygon kernel::is_simple_polygon rejected.
struct Touch {
  std::size_t ring_a = 0;  // 0: the outer ring, k: hole k
  std::size_t ring_b = 0;
  kernel::Vec2 point;
};

bool on_segment(kernel::Vec2 a, kernel::Vec2 b, kernel::Vec2 p) {
  return kernel::cross(b - a, p - a) == 0 && std::min(a.x, b.x) <= p.x &&
         p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

std::optional<Touch> find_touch(const kernel::Polygon& polygon) {
  std::vector<const kernel::Ring*> rings{&polygon.outer};
  for (const kernel::Ring& hole : polygon.holes) rings.push_back(&hole);
  for (std::size_t ra = 0; ra < rings.size(); ++ra) {
    const kernel::Ring& a = *rings[ra];
    for (std::size_t i = 0; i < a.size(); ++i) {
      const kernel::Vec2 p = a[i];
      const kernel::Vec2 q = a[(i + 1) % a.size()];
      for (std::size_t rb = ra; rb < rings.size(); ++rb) {
        const kernel::Ring& b = *rings[rb];
        for (std::size_t j = rb == ra ? i + 1 : 0; j < b.size(); ++j) {
          if (rb == ra && (j == i + 1 || (i == 0 && j + 1 == b.size()))) continue;
          const kernel::Vec2 u = b[j];
          const kernel::Vec2 v = b[(j + 1) % b.size()];
          for (const kernel::Vec2 point : {u, v}) {
            if (on_segment(p, q, point)) return Touch{ra, rb, point};
          }
          for (const kernel::Vec2 point : {p, q}) {
            if (on_segment(u, v, point)) return Touch{ra, rb, point};
          }
        }
      }
    }
  }
  return std::nullopt;
}

struct FeatureState {
  std::size_t index = 0;
  std::size_t offset = kNone;             // text offset of the feature (or bare geometry) value
  bool bare_geometry = false;             // paths start at the geometry itself
  std::string label;                      // "feature 3" or "feature 3 (id \"b12\")"
  std::string id;                         // empty: none in the file
  std::vector<PathStep> id_path;          // where the id came from
  std::vector<kernel::Polygon> polygons;  // world coordinates, closing vertex dropped
  std::vector<Where> polygon_where;
  shape::AttributeMap properties;
  bool failed = false;
};

// ---------------------------------------------------------------------------------------------

class Reader {
 public:
  Reader(std::string_view text, const std::string& name, const GeoJsonOptions& options)
      : text_(text), name_(name), options_(options), locator_(text) {}

  base::Result<FootprintSet> run();

 private:
  struct Pending {
    std::size_t offset;
    Diagnostic diagnostic;
  };

  // Diagnostics ----------------------------------------------------------------------------
  void report(base::Severity severity, const char* code, std::string message, std::size_t offset,
              std::vector<std::string> notes = {});
  void feature_issue(FeatureState& feature, bool is_error, const char* code,
                     const std::string& message, const std::vector<PathStep>& path,
                     std::vector<std::string> notes = {});
  std::vector<PathStep> geometry_path(const FeatureState& feature, const Where& where) const;
  base::Span span_at(std::size_t offset);

  // Stages ---------------------------------------------------------------------------------
  bool prescan();
  std::optional<json> parse();
  void read_top_level(const json& doc);
  void read_crs(const json& doc);
  void read_feature(const json& value, std::size_t index, std::size_t offset);
  void read_geometry(FeatureState& feature, const json& geometry);
  void read_properties(FeatureState& feature, const json& value);
  std::optional<kernel::Polygon> read_polygon(FeatureState& feature, const json& rings,
                                              Where where);
  std::optional<kernel::Ring> read_ring(FeatureState& feature, const json& ring,
                                        const Where& where);
  std::optional<kernel::Vec2> read_position(FeatureState& feature, const json& position,
                                            Where where);
  bool looks_like_degrees() const;
  kernel::Bounds2 valid_bounds() const;
  void resolve_crs();
  void to_geographic_range();
  void reproject_all(const std::string& from, const std::string& to);
  void reject_touching_rings(FeatureState& feature, std::size_t p, const kernel::Polygon& repaired);
  void choose_origin();
  void repair(FeatureState& feature, Footprint& footprint);
  void assign_ids();
  base::Result<FootprintSet> finish();
  std::vector<std::string> local_note() const;

  std::string_view text_;
  const std::string& name_;
  const GeoJsonOptions& options_;
  TextLocator locator_;
  std::optional<base::Source> source_;  // built on the first positioned diagnostic
  std::vector<Pending> pending_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::size_t suppressed_warnings_ = 0;
  bool stopped_ = false;
  bool warned_extra_dimensions_ = false;
  bool hinted_skip_ = false;
  std::string declared_crs_;  // from the "crs" member: "EPSG:N" or "OGC:CRS84"
  std::size_t crs_offset_ = kNone;
  std::size_t root_offset_ = 0;
  std::vector<FeatureState> features_;
  FootprintSet result_;
};

base::Span Reader::span_at(std::size_t offset) {
  if (offset == kNone) return base::Span::whole(name_);
  if (!source_) source_.emplace(name_, std::string(text_));
  const auto [line, column] = source_->locate(offset);
  return base::Span::at(name_, line, column);
}

void Reader::report(base::Severity severity, const char* code, std::string message,
                    std::size_t offset, std::vector<std::string> notes) {
  if (stopped_) return;
  if (severity == base::Severity::kWarning && warnings_ >= options_.max_warnings) {
    ++suppressed_warnings_;
    return;
  }
  Diagnostic d = severity == base::Severity::kError
                     ? Diagnostic::error(code, std::move(message), span_at(offset))
                     : Diagnostic::warning(code, std::move(message), span_at(offset));
  d.notes = std::move(notes);
  if (severity == base::Severity::kError && ++errors_ >= options_.max_errors) {
    d.notes.push_back("too many errors (GeoJsonOptions::max_errors = " +
                      std::to_string(options_.max_errors) + "); stopped reading");
    stopped_ = true;
  }
  if (severity == base::Severity::kWarning) ++warnings_;
  pending_.push_back({offset, std::move(d)});
}

void Reader::feature_issue(FeatureState& feature, bool is_error, const char* code,
                           const std::string& message, const std::vector<PathStep>& path,
                           std::vector<std::string> notes) {
  const std::size_t offset =
      feature.offset == kNone ? kNone : locator_.follow(feature.offset, path);
  const std::string flag = options_.skip_invalid_flag.empty() ? "GeoJsonOptions::skip_invalid"
                                                              : options_.skip_invalid_flag;
  if (is_error) {
    // Skipping: one warning per feature, its first error; the rest would repeat "skipped".
    if (options_.skip_invalid && feature.failed) return;
    if (options_.skip_invalid) {
      notes.push_back("feature skipped (" + flag + ")");
    } else if (!hinted_skip_ && !options_.skip_invalid_flag.empty()) {
      notes.push_back(flag + " skips invalid features, each with a warning");
      hinted_skip_ = true;
    }
    feature.failed = true;
  }
  const bool as_error = is_error && !options_.skip_invalid;
  report(as_error ? base::Severity::kError : base::Severity::kWarning, code,
         feature.label + ": " + message, offset, std::move(notes));
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
  if (const auto deep = find_too_deep(text_, options_.max_depth)) {
    report(base::Severity::kError, "GEO003",
           "arrays and objects nest deeper than " + std::to_string(options_.max_depth) +
               " levels (GeoJsonOptions::max_depth)",
           *deep);
    return false;
  }
  return true;
}

// Stage 2: JSON. The DOM parse runs without exceptions; only on failure a second, validating
// SAX pass finds the error's position and nlohmann's message.
std::optional<json> Reader::parse() {
  const char* begin = text_.data();
  json doc = json::parse(begin, begin + text_.size(), nullptr, false);
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
    const std::vector<std::size_t> offsets = locator_.elements(at);
    for (std::size_t i = 0; i < features->size() && !stopped_; ++i) {
      read_feature((*features)[i], i, i < offsets.size() ? offsets[i] : kNone);
    }
  } else if (name == "Feature") {
    read_feature(doc, 0, root_offset_);
  } else if (name == "Polygon" || name == "MultiPolygon") {
    FeatureState& feature = features_.emplace_back();
    feature.offset = root_offset_;
    feature.bare_geometry = true;
    feature.label = "feature 0";
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

void Reader::read_feature(const json& value, std::size_t index, std::size_t offset) {
  FeatureState& feature = features_.emplace_back();
  feature.index = index;
  feature.offset = offset;
  feature.label = "feature " + std::to_string(index);
  if (!value.is_object()) {
    feature_issue(feature, true, "GEO015", "is " + type_name(value) + "; expected an object", {});
    return;
  }
  const json* props = member(value, "properties");
  if (const json* id = member(value, "id"); id != nullptr && !id->is_null()) {
    if (auto text = id_text(*id)) {
      feature.id = *text;
      feature.id_path = {{"id", 0}};
    } else {
      feature_issue(feature, false, "GEO018",
                    "\"id\" is " + type_name(*id) + "; expected a string or a number; ignored",
                    {{"id", 0}});
    }
  }
  for (const char* key : {"id", "name"}) {
    const json* alt = props != nullptr ? member(*props, key) : nullptr;
    if (!feature.id.empty() || alt == nullptr) continue;
    if (auto text = id_text(*alt)) {
      feature.id = *text;
      feature.id_path = {{"properties", 0}, {key, 0}};
    }
  }
  if (!feature.id.empty()) feature.label += " (id " + quote_text(feature.id) + ")";
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
    feature.properties.insert_or_assign(key, std::move(converted));
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
      feature.polygons.push_back(std::move(*polygon));
      feature.polygon_where.push_back(Where{});
    }
    return;
  }
  for (std::size_t i = 0; i < coordinates->size() && !stopped_; ++i) {
    Where where;
    where.polygon = i;
    if (auto polygon = read_polygon(feature, (*coordinates)[i], where)) {
      feature.polygons.push_back(std::move(*polygon));
      feature.polygon_where.push_back(where);
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
    if (!std::isfinite(xyz[c]) || std::abs(xyz[c]) > options_.max_abs_coordinate) {
      feature_issue(feature, true, "GEO013",
                    label + " coordinate " +
                        (std::isfinite(xyz[c]) ? number_text(xyz[c]) + " is beyond +-" +
                                                     number_text(options_.max_abs_coordinate) +
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

// Stage 4: CRS (docs/geojson.md, "Coordinates, units and CRS"). Longitude/latitude without a
// "crs" member gives itself away by fitting in +-180 x +-90 while every footprint spans less than
// 0.05 units (5 cm if it were meters, a few kilometres in degrees): no real building is 5 cm wide,
// and a hand-made file in meters near (0, 0) stays in meters.
bool Reader::looks_like_degrees() const {
  bool any = false;
  for (const FeatureState& feature : features_) {
    if (feature.failed) continue;
    for (const kernel::Polygon& polygon : feature.polygons) {
      const kernel::Bounds2 box = kernel::bounds(polygon);
      const bool degrees = std::abs(box.min.x) <= 180 && std::abs(box.max.x) <= 180 &&
                           std::abs(box.min.y) <= 90 && std::abs(box.max.y) <= 90 &&
                           box.max.x - box.min.x < 0.05 && box.max.y - box.min.y < 0.05;
      if (!degrees) return false;
      any = true;
    }
  }
  return any;
}

void Reader::resolve_crs() {
  std::string error;
  if (!options_.crs.empty()) {
    if (const std::string why = buildable_crs(options_.crs); !why.empty()) {
      report(base::Severity::kError, "GEO007", "GeoJsonOptions::crs: " + why, kNone);
      return;
    }
  }
  std::string source = declared_crs_;
  if (source.empty()) {
    if (!looks_like_degrees()) {
      result_.crs = options_.crs;  // meters in no named CRS: in the caller's, if it names one
      return;
    }
    source = "OGC:CRS84";  // RFC 7946: GeoJSON without a "crs" member is WGS 84 lon/lat
  }
  const std::optional<CrsInfo> info = describe_crs(source, error);
  if (!info) {
    if (options_.crs.empty()) {
      report(base::Severity::kWarning, "GEO007",
             "crs " + source + ": " + error + "; coordinates taken as meters", crs_offset_);
      result_.crs = source;
    } else {
      report(base::Severity::kError, "GEO007",
             "crs " + source + ": " + error + "; cannot reproject to " + options_.crs, crs_offset_);
    }
    return;
  }
  if (info->geographic) to_geographic_range();
  if (errors_ > 0) return;
  std::string target = options_.crs;
  if (target.empty() && !info->geographic) {
    if (!info->metric) {
      report(base::Severity::kError, "GEO007",
             "crs " + info->name + " (" + info->title + ") measures in " + info->unit +
                 "; footprints are built in meters: name a projected CRS in meters to "
                 "reproject to (--crs EPSG:N)",
             crs_offset_);
      return;
    }
    result_.crs = info->name;
    return;
  }
  if (target.empty()) {
    const kernel::Bounds2 box = valid_bounds();
    if (box.empty()) return;
    target = utm_crs(0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y));
  }
  const std::optional<CrsInfo> to = describe_crs(target, error);
  if (to && to->name == info->name) {
    result_.crs = info->name;
    return;
  }
  reproject_all(info->name, to ? to->name : target);
}

// Degrees in a geographic CRS: a coordinate beyond +-180 x +-90 says the file's "crs" member is
// wrong (often meters under an EPSG:4326 label); guessing would misplace the building.
void Reader::to_geographic_range() {
  for (FeatureState& feature : features_) {
    if (feature.failed) continue;
    for (std::size_t p = 0; p < feature.polygons.size() && !feature.failed; ++p) {
      const kernel::Polygon& polygon = feature.polygons[p];
      for (std::size_t r = 0; r <= polygon.holes.size() && !feature.failed; ++r) {
        const kernel::Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (std::size_t i = 0; i < ring.size(); ++i) {
          if (std::abs(ring[i].x) <= 180 && std::abs(ring[i].y) <= 90) continue;
          Where where = feature.polygon_where[p];
          where.ring = r;
          where.position = i;
          feature_issue(feature, true, "GEO008",
                        ring_label(where) + " position " + std::to_string(i) + " (" +
                            number_text(ring[i].x) + ", " + number_text(ring[i].y) +
                            ") is not a longitude/latitude, but crs " + declared_crs_ +
                            " is geographic (degrees)",
                        geometry_path(feature, where));
          break;
        }
      }
    }
  }
}

void Reader::reproject_all(const std::string& from, const std::string& to) {
  std::vector<kernel::Vec2> points;
  for (const FeatureState& feature : features_) {
    if (feature.failed) continue;
    for (const kernel::Polygon& polygon : feature.polygons) {
      points.insert(points.end(), polygon.outer.begin(), polygon.outer.end());
      for (const kernel::Ring& hole : polygon.holes) {
        points.insert(points.end(), hole.begin(), hole.end());
      }
    }
  }
  if (const std::string error = io::reproject(from, to, points); !error.empty()) {
    report(base::Severity::kError, "GEO007", error, crs_offset_);
    return;
  }
  std::size_t next = 0;
  for (FeatureState& feature : features_) {
    if (feature.failed) continue;
    for (std::size_t p = 0; p < feature.polygons.size(); ++p) {
      kernel::Polygon& polygon = feature.polygons[p];
      for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
        kernel::Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const kernel::Vec2 q = points[next++];
          if (std::isfinite(q.x) && std::isfinite(q.y)) {
            ring[i] = q;
          } else if (!feature.failed) {
            Where where = feature.polygon_where[p];
            where.ring = r;
            where.position = i;
            feature_issue(feature, true, "GEO008",
                          ring_label(where) + " position " + std::to_string(i) +
                              " could not be reprojected from " + from + " to " + to,
                          geometry_path(feature, where));
          }
        }
      }
    }
  }
  result_.crs = to;
  result_.source_crs = from;
}

// The bounding box of the features still valid, in world coordinates.
kernel::Bounds2 Reader::valid_bounds() const {
  kernel::Bounds2 box;
  for (const FeatureState& feature : features_) {
    if (feature.failed) continue;
    for (const kernel::Polygon& polygon : feature.polygons) {
      const kernel::Bounds2 b = kernel::bounds(polygon);
      box.add(b.min);
      box.add(b.max);
    }
  }
  return box;
}

// Stage 5: origin. The bounding-box centre rounded down to whole meters: local coordinates stay
// within half the data's extent (which float32 outputs such as glTF need), and world - origin is
// exact whenever origin and world lie within a factor of 2 of each other (Sterbenz), which holds
// for any dataset smaller than its distance from (0, 0): UTM tiles, national grids.
void Reader::choose_origin() {
  const kernel::Bounds2 box = valid_bounds();
  if (options_.origin) {
    result_.origin = {options_.origin->x, options_.origin->y, 0};
  } else if (!box.empty() &&
             (std::max(std::abs(box.min.x), std::abs(box.max.x)) > options_.shift_threshold ||
              std::max(std::abs(box.min.y), std::abs(box.max.y)) > options_.shift_threshold)) {
    result_.origin = {std::floor(0.5 * box.min.x + 0.5 * box.max.x),
                      std::floor(0.5 * box.min.y + 0.5 * box.max.y), 0};
  }
}

bool has_three_distinct(const kernel::Ring& ring) {
  const auto second =
      std::find_if(ring.begin(), ring.end(), [&](kernel::Vec2 v) { return v != ring[0]; });
  return second != ring.end() && std::any_of(second, ring.end(), [&](kernel::Vec2 v) {
           return v != ring[0] && v != *second;
         });
}

const char* repair_code(kernel::PolygonIssueKind kind) {
  switch (kind) {
    case kernel::PolygonIssueKind::kTooFewVertices:
      return "GEO020";
    case kernel::PolygonIssueKind::kZeroArea:
      return "GEO021";
    case kernel::PolygonIssueKind::kSelfIntersection:
      return "GEO022";
    case kernel::PolygonIssueKind::kRingsIntersect:
      return "GEO023";
    case kernel::PolygonIssueKind::kHoleOutside:
      return "GEO024";
    case kernel::PolygonIssueKind::kDuplicateVertex:
      return "GEO025";
    case kernel::PolygonIssueKind::kCollinearVertex:
      return "GEO026";
    case kernel::PolygonIssueKind::kNonFinite:
    case kernel::PolygonIssueKind::kWrongOrientation:
      break;
  }
  return "GEO013";
}

// Stage 6: repair in local coordinates (small numbers keep the kernel's tolerance meaningful).
// Orientation fixes are silent: RFC 7946 asks readers to accept either winding. Repeated repairs
// of one kind in one polygon are reported once with a count.
void Reader::repair(FeatureState& feature, Footprint& footprint) {
  const kernel::Vec2 origin{result_.origin.x, result_.origin.y};
  for (std::size_t p = 0; p < feature.polygons.size(); ++p) {
    kernel::Polygon& polygon = feature.polygons[p];
    for (kernel::Vec2& v : polygon.outer) v -= origin;
    for (kernel::Ring& hole : polygon.holes) {
      for (kernel::Vec2& v : hole) v -= origin;
    }
    kernel::RepairResult repaired = kernel::repair(polygon, options_.repair_tolerance);
    std::map<kernel::PolygonIssueKind, std::size_t> repeats;
    for (const kernel::PolygonIssue& issue : repaired.issues) {
      if (issue.repaired) ++repeats[issue.kind];
    }
    for (const kernel::PolygonIssue& issue : repaired.issues) {
      // Orientation is free in GeoJSON; repairs of a rejected polygon are noise.
      if (issue.kind == kernel::PolygonIssueKind::kWrongOrientation) continue;
      if (issue.repaired && !repaired.ok) continue;
      const char* code = repair_code(issue.kind);
      std::string message =
          ring_label(Where{feature.polygon_where[p].polygon}) + ": " + issue.message;
      if (issue.kind == kernel::PolygonIssueKind::kTooFewVertices && !issue.repaired &&
          issue.ring == 0 && has_three_distinct(polygon.outer)) {
        // Collinear and spike removal left too little: the ring was a line all along.
        code = "GEO021";
        message = ring_label(Where{feature.polygon_where[p].polygon}) +
                  ": outer ring: zero area (its positions lie on one line)";
      }
      if (issue.repaired) {
        std::size_t& count = repeats[issue.kind];
        if (count == 0) continue;  // reported with the first of its kind
        if (count > 1) message += " (and " + std::to_string(count - 1) + " more like it)";
        count = 0;
      }
      Where where = feature.polygon_where[p];
      where.ring = issue.ring >= 0 ? static_cast<std::size_t>(issue.ring) : kNone;
      where.position = issue.vertex >= 0 ? static_cast<std::size_t>(issue.vertex) : kNone;
      feature_issue(feature, !issue.repaired, code, message, geometry_path(feature, where),
                    local_note());
    }
    if (!repaired.ok) continue;
    if (!kernel::is_simple_polygon(repaired.polygon)) {
      reject_touching_rings(feature, p, repaired.polygon);
      continue;
    }
    const kernel::Ring& written = polygon.outer;
    const auto second = std::find_if(written.begin(), written.end(),
                                     [&](kernel::Vec2 v) { return v != written[0]; });
    footprint.first_edges.push_back({written[0], second == written.end() ? written[0] : *second});
    footprint.outer_clockwise.push_back(kernel::signed_area(written) < 0);
    footprint.polygons.push_back(std::move(repaired.polygon));
  }
}

std::vector<std::string> Reader::local_note() const {
  if (result_.origin.x == 0 && result_.origin.y == 0) return {};
  return {"coordinates in this message are local: world = local + (" +
          number_text(result_.origin.x) + ", " + number_text(result_.origin.y) + ")"};
}

// kernel::repair() accepts rings that touch at one point (valid in OGC simple features), but walls
// and roofs cannot be built on them (kernel::is_simple_polygon): rejected here, so that `check`
// and every builder agree, with where they touch.
void Reader::reject_touching_rings(FeatureState& feature, std::size_t p,
                                   const kernel::Polygon& repaired) {
  const Where polygon_where = feature.polygon_where[p];
  std::string message = ring_label(Where{polygon_where.polygon}) + ": ";
  Where where = polygon_where;
  if (const std::optional<Touch> touch = find_touch(repaired)) {
    const auto name = [](std::size_t ring) {
      return ring == 0 ? std::string("the outer ring") : "hole " + std::to_string(ring);
    };
    message += touch->ring_a == touch->ring_b
                   ? name(touch->ring_a) + " touches itself"
                   : name(touch->ring_b) + " touches " + name(touch->ring_a);
    message += " at (" + number_text(touch->point.x) + ", " + number_text(touch->point.y) + ")";
    // The file position nearest the touching point, on the touching ring where there is a tie
    // (repair may have dropped or reordered positions).
    const kernel::Polygon& written = feature.polygons[p];
    double best = std::numeric_limits<double>::infinity();
    std::vector<std::size_t> order{touch->ring_b};
    for (std::size_t r = 0; r <= written.holes.size(); ++r) order.push_back(r);
    for (const std::size_t r : order) {
      if (r > written.holes.size()) continue;
      const kernel::Ring& ring = r == 0 ? written.outer : written.holes[r - 1];
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const kernel::Vec2 d = ring[i] - touch->point;
        if (kernel::dot(d, d) < best) {
          best = kernel::dot(d, d);
          where.ring = r;
          where.position = i;
        }
      }
    }
  } else {
    message += "rings touch or fold back on themselves";
  }
  message += "; footprint rings must not meet (walls and roofs need a simple outline)";
  feature_issue(feature, true, "GEO027", message, geometry_path(feature, where), local_note());
}

// Stage 7: ids. File order decides: the first feature keeps an id, later ones are renamed.
void Reader::assign_ids() {
  std::set<std::string, std::less<>> used;
  for (const FeatureState& feature : features_) {
    if (!feature.id.empty()) used.insert(feature.id);
  }
  std::set<std::string, std::less<>> taken;
  std::map<std::string, std::size_t, std::less<>> first_user;
  for (Footprint& footprint : result_.footprints) {
    FeatureState& feature = features_[footprint.feature_index];
    std::string id = feature.id.empty() ? "feature-" + std::to_string(feature.index) : feature.id;
    if (taken.count(id) != 0) {
      std::string renamed;
      for (std::size_t n = 2;
           renamed.empty() || taken.count(renamed) != 0 || used.count(renamed) != 0; ++n) {
        renamed = id + "-" + std::to_string(n);
      }
      feature_issue(feature, false, "GEO019",
                    "id " + quote_text(id) + " is already used by feature " +
                        std::to_string(first_user[id]) + "; renamed to " + quote_text(renamed),
                    feature.id_path);
      id = renamed;
    }
    first_user.emplace(id, feature.index);
    taken.insert(id);
    footprint.id = std::move(id);
  }
}

base::Result<FootprintSet> Reader::run() {
  std::optional<json> doc;
  if (prescan()) doc = parse();
  if (doc) read_top_level(*doc);
  if (errors_ == 0) resolve_crs();
  if (errors_ == 0) {
    choose_origin();
    for (FeatureState& feature : features_) {
      if (feature.failed || feature.polygons.empty() || stopped_) continue;
      Footprint footprint;
      footprint.feature_index = feature.index;
      repair(feature, footprint);
      if (feature.failed) continue;
      footprint.properties = std::move(feature.properties);
      result_.footprints.push_back(std::move(footprint));
    }
  }
  if (errors_ == 0 && result_.footprints.empty()) {
    report(base::Severity::kError, "GEO006", "no polygon features", kNone,
           {std::to_string(features_.size()) + " feature" + (features_.size() == 1 ? "" : "s") +
            " read; the warnings above say why each was skipped"});
  }
  if (errors_ == 0) assign_ids();
  result_.skipped_invalid = static_cast<std::size_t>(std::count_if(
      features_.begin(), features_.end(), [](const FeatureState& f) { return f.failed; }));
  return finish();
}

// Diagnostics in file order (those without a position last), then the count of unlisted warnings.
base::Result<FootprintSet> Reader::finish() {
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const Pending& a, const Pending& b) { return a.offset < b.offset; });
  std::vector<Diagnostic> diagnostics;
  diagnostics.reserve(pending_.size() + 1);
  for (Pending& p : pending_) diagnostics.push_back(std::move(p.diagnostic));
  if (suppressed_warnings_ > 0) {
    diagnostics.push_back(
        Diagnostic::warning("",
                            std::to_string(suppressed_warnings_) +
                                " more warnings not listed (GeoJsonOptions::max_warnings = " +
                                std::to_string(options_.max_warnings) + ")",
                            base::Span::whole(name_)));
  }
  if (errors_ > 0) return base::Result<FootprintSet>::failure(std::move(diagnostics));
  return base::Result<FootprintSet>(std::move(result_), std::move(diagnostics));
}

}  // namespace

base::Result<FootprintSet> read_geojson(std::string_view text, const std::string& source_name,
                                        const GeoJsonOptions& options) {
  return Reader(text, source_name, options).run();
}

}  // namespace insula::io
