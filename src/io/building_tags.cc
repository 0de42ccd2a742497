// The form of a building from its footprint's properties: S3DB for OpenStreetMap features, named
// attributes for registers (docs/osm-buildings.md gives every rule in order).
#include "io/building_tags.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>

#include "kernel/roof.h"

namespace insula::io {
namespace {

// Walls this low are kept under a roof that takes (almost) the whole height: the kernel needs
// walls, and a 10 cm plinth is invisible at the scale of a building.
constexpr double kMinimumWall = 0.1;

// The property as text: a number as written by shape::to_string, a string as is; nullopt when
// missing or null.
std::optional<std::string> text_of(const PropertyRow& properties, std::string_view key) {
  const std::optional<shape::Value> value = properties.find(key);
  if (!value || std::holds_alternative<std::monostate>(*value)) return std::nullopt;
  return shape::to_string(*value);
}

// A length property in meters: a JSON number, or a text that is only a number, counts `unit`
// meters per unit; any other text goes through parse_length ("40 ft", "12'6\"").
std::optional<double> length_of(const shape::Value& value, double unit) {
  if (const double* d = std::get_if<double>(&value)) {
    return std::isfinite(*d) ? std::optional<double>(*d * unit) : std::nullopt;
  }
  if (const std::string* s = std::get_if<std::string>(&value)) {
    std::string_view rest = *s;
    const std::optional<double> number = base::take_number(rest);
    if (number && rest.empty() && std::isfinite(*number)) return *number * unit;
    return parse_length(*s);
  }
  return std::nullopt;
}

// Microsoft's building footprints write "height": -1 (and "confidence": -1) where the height is
// unknown: exactly -1, as a number or a text that is only that number, means no height given.
bool is_unknown_height(const shape::Value& value) {
  if (const double* d = std::get_if<double>(&value)) return *d == -1;
  if (const std::string* s = std::get_if<std::string>(&value)) {
    std::string_view rest = *s;
    while (rest.starts_with(' ')) rest.remove_prefix(1);
    if (!rest.starts_with('-')) return false;
    rest.remove_prefix(1);
    const std::optional<double> number = base::take_number(rest);
    return number && rest.empty() && *number == 1;
  }
  return false;
}

std::optional<double> levels_of(const shape::Value& value) {
  if (const double* d = std::get_if<double>(&value)) {
    return std::isfinite(*d) ? std::optional<double>(*d) : std::nullopt;
  }
  if (const std::string* s = std::get_if<std::string>(&value)) return parse_levels(*s);
  return std::nullopt;
}

std::string quoted(const shape::Value& value) {
  std::string text = "'";
  text += shape::to_string(value);
  text += "'";
  return text;
}

// Overture Maps' building schema spells the S3DB tags with underscores and means the same by
// them (`height` the top of the roof; docs/osm-buildings.md, "Overture Maps").
constexpr std::array<std::pair<std::string_view, std::string_view>, 10> kOvertureNames{{
    {"roof:shape", "roof_shape"},
    {"building:levels", "num_floors"},
    {"building:min_level", "min_floor"},
    {"roof:height", "roof_height"},
    {"roof:direction", "roof_direction"},
    {"roof:orientation", "roof_orientation"},
    {"building:colour", "facade_color"},
    {"roof:colour", "roof_color"},
    {"building:material", "facade_material"},
    {"roof:material", "roof_material"},
}};

// An Overture feature: its `names` object or `sources` array (nested values are JSON text,
// docs/geojson.md), or a property only Overture's schema names so.
bool is_overture(const PropertyRow& properties) {
  const auto starts = [&](std::string_view key, char c) {
    const std::optional<std::string> text = text_of(properties, key);
    return text && !text->empty() && text->front() == c;
  };
  return starts("names", '{') || starts("sources", '[') || text_of(properties, "roof_shape") ||
         text_of(properties, "num_floors") || text_of(properties, "facade_color");
}

// Names registers give their height column: any name holding one of kHeightWords, or one of
// kHeightNames (ASCII letters compared in lower case).
constexpr std::array<std::string_view, 6> kHeightWords{"height",      "hauteur", "hoehe",
                                                       "h\xC3\xB6he", "hoogte",  "hgt"};
constexpr std::array<std::string_view, 10> kHeightNames{
    "h", "h_dak", "h_max", "h_mean", "h_median", "ht", "bldg_ht", "altura", "altezza", "korkeus"};

// The properties of a feature without a height that may be its height column (MAS001 names
// them): not null, not the program's own insula:* attributes, at most 3.
std::vector<std::string> height_candidates(const PropertyRow& properties) {
  std::vector<std::string> out;
  for (const auto& [key, value] : properties.map()) {
    if (out.size() == 3) break;
    if (shape::is_null(value) || key.starts_with("insula:")) continue;
    std::string lower = key;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c + 32) : c; });
    const auto holds = [&](std::string_view word) { return lower.find(word) != std::string::npos; };
    if (std::any_of(kHeightWords.begin(), kHeightWords.end(), holds) ||
        std::find(kHeightNames.begin(), kHeightNames.end(), lower) != kHeightNames.end()) {
      out.push_back(key);
    }
  }
  return out;
}

// Tagged building or building:part (any value but no).
bool is_osm_building(const PropertyRow& properties) {
  const std::optional<std::string> building = text_of(properties, "building");
  const std::optional<std::string> part = text_of(properties, "building:part");
  return (building && *building != "no") || (part && *part != "no");
}

class FormReader {
 public:
  FormReader(const PropertyRow& properties, const BuildingTagOptions& options,
             std::vector<TagWarning>& warnings)
      : properties_(properties), options_(options), warnings_(warnings) {}

  BuildingForm read(const RoofRise& roof_rise) {
    classify();
    read_base();
    read_roof();
    read_heights();
    if (total_height_) split_total_height(roof_rise);
    limit_default_roof();
    read_colours();
    return form_;
  }

 private:
  // The message is given in pieces: gcc 12 sees false overlaps (-Wrestrict) in chains of
  // "literal" + std::string.
  void warn(const char* code, std::initializer_list<std::string_view> pieces) {
    const std::string_view c(code);
    if (c == "MAS002" || c == "MAS007") height_warning_ = warnings_.size();
    std::string text;
    for (const std::string_view piece : pieces) text += piece;
    warnings_.push_back({code, std::move(text)});
  }

  // The property that carries S3DB tag `key` in this feature's schema.
  std::string_view key_of(std::string_view key) const {
    if (!overture_) return key;
    for (const auto& [s3db, overture] : kOvertureNames) {
      if (s3db == key) return overture;
    }
    return key;
  }
  std::optional<shape::Value> tag(std::string_view key) const {
    return properties_.find(key_of(key));
  }
  std::optional<std::string> tag_text(std::string_view key) const {
    return text_of(properties_, key_of(key));
  }

  // A length tag: its value in meters, or nullopt (with a warning when present but unreadable
  // or outside (minimum, 1000) m).
  std::optional<double> length_tag(std::string_view key, double minimum, const char* code) {
    const std::optional<shape::Value> value = tag(key);
    if (!value || std::holds_alternative<std::monostate>(*value)) return std::nullopt;
    // S3DB's bare numbers are meters; a register's are in --height-unit.
    const std::optional<double> meters = length_of(*value, form_.osm ? 1.0 : options_.length_unit);
    if (meters && *meters > minimum && *meters < 1000) return meters;
    warn(code, {key_of(key), "=", quoted(*value), " is not a length in ", minimum < 0 ? "[0" : "(",
                minimum < 0 ? "" : shape::to_string(minimum), ", 1000) m; ignored"});
    return std::nullopt;
  }

  // A level count: nullopt (with a warning) when present but unreadable or not above `minimum`.
  std::optional<double> levels_tag(std::string_view key, double minimum, const char* code) {
    const std::optional<shape::Value> value = tag(key);
    if (!value || std::holds_alternative<std::monostate>(*value)) return std::nullopt;
    const std::optional<double> levels = levels_of(*value);
    if (levels && *levels > minimum && *levels < 300) return levels;
    warn(code,
         {key_of(key), "=", quoted(*value), " is not a level count", minimum < 0 ? "" : " above ",
          minimum < 0 ? "" : shape::to_string(minimum), "; ignored"});
    return std::nullopt;
  }

  void classify() {
    const std::optional<std::string> building = text_of(properties_, "building");
    const std::optional<std::string> part = text_of(properties_, "building:part");
    form_.osm = is_osm_building(properties_);
    form_.is_part = part && *part != "no";
    if (!form_.osm && is_overture(properties_)) {
      // Overture's building_part features name the building they belong to.
      overture_ = form_.osm = true;
      form_.is_part = text_of(properties_, "building_id").has_value();
    }
    form_.walls = !((building && *building == "roof") || (part && *part == "roof"));
  }

  void read_base() {
    if (!form_.osm) return;
    if (std::optional<double> min_height = length_tag("min_height", -1e-9, "MAS006")) {
      form_.base = *min_height;
    } else if (std::optional<double> min_level =
                   levels_tag("building:min_level", -1e-9, "MAS006")) {
      form_.base = *min_level * options_.storey_height;
    }
  }

  void read_roof() {
    if (options_.roof) {
      form_.roof = *options_.roof;
      form_.roof_source = ValueSource::kOption;
    } else if (const std::optional<shape::Value> shape = tag("roof:shape")) {
      if (std::optional<std::string> name = s3db_roof_name(shape::to_string(*shape))) {
        form_.roof = *name;
        form_.roof_source = ValueSource::kTag;
      } else {
        form_.roof = form_.osm ? "flat" : options_.default_roof;
        warn("MAS003",
             {"unknown ", key_of("roof:shape"), "=", quoted(*shape), "; using ", form_.roof});
      }
    } else if (const std::optional<shape::Value> roof = properties_.find("roof");
               roof && !form_.osm) {
      const std::string name = shape::to_string(*roof);
      if (kernel::roof_type_from_name(name)) {
        form_.roof = name;
        form_.roof_source = ValueSource::kAttribute;
      } else {
        form_.roof = options_.default_roof;
        warn("MAS003", {"unknown roof ", quoted(*roof), "; using ", form_.roof});
      }
    } else {
      // S3DB: an OpenStreetMap building without roof:shape has a flat roof.
      form_.roof = form_.osm ? "flat" : options_.default_roof;
    }
    read_pitch();
    read_roof_height();
    read_direction();
  }

  void read_pitch() {
    form_.pitch_deg = options_.pitch_deg;
    if (options_.pitch_given) return;
    const char* key = form_.osm ? "roof:angle" : "pitch";
    const std::optional<shape::Value> value = properties_.find(key);
    if (!value) return;
    const std::optional<double> degrees = levels_of(*value);
    if (degrees && *degrees > 0 && *degrees < 89) {
      form_.pitch_deg = *degrees;
      pitch_from_data_ = true;
    } else {
      warn("MAS006", {key, "=", quoted(*value), " is not an angle in (0, 89) degrees; ignored"});
    }
  }

  void read_roof_height() {
    if (form_.roof == "flat") return;
    if (std::optional<double> height = length_tag("roof:height", 0, "MAS006")) {
      form_.roof_height = *height;
    } else if (std::optional<double> levels = levels_tag("roof:levels", 0, "MAS006")) {
      form_.roof_height = *levels * options_.storey_height;
    }
    roof_height_given_ = form_.roof_height.has_value();
  }

  void read_direction() {
    if (const std::optional<shape::Value> value = tag("roof:direction")) {
      form_.direction_deg = parse_direction(shape::to_string(*value));
      if (!form_.direction_deg) {
        warn("MAS006", {key_of("roof:direction"), "=", quoted(*value),
                        " is not a compass direction; ignored"});
      }
    }
    if (const std::optional<std::string> value = tag_text("roof:orientation")) {
      if (*value == "along") {
        form_.orientation = RoofOrientation::kAlong;
      } else if (*value == "across") {
        form_.orientation = RoofOrientation::kAcross;
      } else {
        warn("MAS006",
             {key_of("roof:orientation"), "='", *value, "' is neither along nor across; ignored"});
      }
    }
  }

  // The height tag or attribute `key`, in meters; -1 (unknown) is no height, remembered for
  // MAS001.
  std::optional<double> height_tag(std::string_view key) {
    const std::optional<shape::Value> value = tag(key);
    if (value && is_unknown_height(*value)) {
      unknown_height_ = key_of(key);
      return std::nullopt;
    }
    return length_tag(key, 0, "MAS002");
  }

  void read_heights() {
    if (options_.height) {
      set_eave(form_.base + *options_.height, ValueSource::kOption);
      return;
    }
    if (form_.osm) {
      total_height_ = height_tag("height");
      if (total_height_ && *total_height_ <= form_.base) {
        warn("MAS002", {"height ", shape::to_string(*total_height_), " m is not above min_height ",
                        shape::to_string(form_.base), " m; ignored"});
        total_height_.reset();
      }
      if (total_height_) {
        form_.height_source = ValueSource::kTag;
        return;
      }
      if (levels_height("building:levels")) return;
    } else {
      if (std::optional<double> height = height_tag(options_.height_attr)) {
        set_eave(form_.base + *height, ValueSource::kAttribute);
        return;
      }
    }
    if (!options_.levels_attr.empty() && levels_height(options_.levels_attr)) return;
    set_eave(form_.base + options_.default_height, ValueSource::kDefault);
    std::string fallback = "using ";
    fallback += shape::to_string(options_.default_height);
    fallback += " m";
    if (height_warning_) {
      // The height that could not be read already has its warning: say what replaced it.
      std::string& text = warnings_[*height_warning_].text;
      text.replace(text.rfind("ignored"), std::string::npos, fallback);
      return;
    }
    if (!unknown_height_.empty()) {
      warn("MAS001",
           {"'", unknown_height_, "' is -1 (unknown)", form_.osm ? " and no " : "",
            form_.osm ? key_of("building:levels") : "", form_.osm ? " tag" : "", "; ", fallback});
    } else if (form_.osm) {
      warn("MAS001", {"no height or ", key_of("building:levels"), " tag; ", fallback});
    } else {
      warn("MAS001", {"no '", options_.height_attr, "' property; ", candidates_hint(), fallback});
    }
  }

  // "this feature has 'hauteur' (use --height-attr hauteur); ", or nothing.
  std::string candidates_hint() const {
    const std::vector<std::string> names = height_candidates(properties_);
    if (names.empty()) return {};
    std::string text = "this feature has ";
    for (std::size_t i = 0; i < names.size(); ++i) {
      text += i == 0 ? "'" : i + 1 == names.size() ? " and '" : ", '";
      text += names[i];
      text += "'";
    }
    text += names.size() == 1 ? " (use --height-attr " + names[0] + "); "
                              : " (name one with --height-attr); ";
    return text;
  }

  // Levels x storey height from the ground (S3DB counts building:levels from the ground;
  // building:min_level levels are left out below the part).
  bool levels_height(const std::string& key) {
    const std::optional<double> levels = levels_tag(key, 0, "MAS007");
    if (!levels) return false;
    const double eave = *levels * options_.storey_height;
    if (eave <= form_.base) {
      warn("MAS007", {key, "=", shape::to_string(*levels), " ends below min_height ",
                      shape::to_string(form_.base), " m; ignored"});
      return false;
    }
    set_eave(eave, ValueSource::kLevels);
    return true;
  }

  void limit_default_roof() {
    if (form_.roof == "flat" || form_.roof_height || options_.pitch_given || pitch_from_data_)
      return;
    form_.roof_height_limit = form_.eave - form_.base;
  }

  void set_eave(double eave, ValueSource source) {
    form_.eave = eave;
    form_.height_source = source;
  }

  // S3DB's height is the top of the roof: the walls get what the roof leaves.
  void split_total_height(const RoofRise& roof_rise) {
    const double span = *total_height_ - form_.base;
    double rise = 0;
    if (form_.roof != "flat") {
      if (roof_height_given_) {
        rise = *form_.roof_height;
        if (rise > span) {
          warn("MAS008", {"roof:height ", shape::to_string(rise), " m is more than the ",
                          shape::to_string(span), " m of the building; the roof is made ",
                          shape::to_string(std::max(span - kMinimumWall, span / 2)), " m"});
        }
      } else {
        // A roof of the default pitch takes at most half a building given by its total height.
        rise = std::min(roof_rise(form_.roof, form_.pitch_deg), span / 2);
      }
      rise = std::min(rise, std::max(span - kMinimumWall, span / 2));
      form_.roof_height = rise;
    }
    form_.eave = *total_height_ - rise;
  }

  void read_colours() {
    read_colour("building:colour", "building:material", form_.wall_colour, form_.wall_colour_name);
    read_colour("roof:colour", "roof:material", form_.roof_colour, form_.roof_colour_name);
  }

  void read_colour(const char* colour_key, const char* material_key,
                   std::optional<std::array<float, 3>>& colour, std::string& name) {
    if (const std::optional<std::string> value = tag_text(colour_key)) {
      colour = parse_colour(*value);
      if (colour) {
        name = *value;
        return;
      }
      warn("MAS006", {key_of(colour_key), "='", *value, "' is not a colour; ignored"});
    }
    if (const std::optional<std::string> value = tag_text(material_key)) {
      colour = material_colour(*value);
      if (colour) name = *value;
    }
  }

  const PropertyRow& properties_;
  const BuildingTagOptions& options_;
  std::vector<TagWarning>& warnings_;
  BuildingForm form_;
  std::optional<double> total_height_;
  bool overture_ = false;  // Overture's names for the S3DB tags (kOvertureNames)
  bool roof_height_given_ = false;
  bool pitch_from_data_ = false;
  std::optional<std::size_t> height_warning_;  // the last MAS002/MAS007 of this feature
  std::string unknown_height_;                 // the height property that is -1 (unknown)
};

}  // namespace

std::string_view source_name(ValueSource source) {
  switch (source) {
    case ValueSource::kOption:
      return "option";
    case ValueSource::kTag:
      return "tag";
    case ValueSource::kAttribute:
      return "attribute";
    case ValueSource::kLevels:
      return "levels";
    case ValueSource::kDefault:
      return "default";
  }
  return "default";
}

bool follows_s3db(const PropertyRow& properties) {
  return is_osm_building(properties) || is_overture(properties);
}

BuildingForm read_building_form(const PropertyRow& properties, const BuildingTagOptions& options,
                                const RoofRise& roof_rise, std::vector<TagWarning>& warnings) {
  return FormReader(properties, options, warnings).read(roof_rise);
}

}  // namespace insula::io
