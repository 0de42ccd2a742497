#include "io/gltf_metadata.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <variant>

namespace insula::io::gltf {
namespace {

// A property id (3D Metadata: [a-zA-Z_][a-zA-Z0-9_]*) for `name`, not yet in `taken`.
std::string property_id(std::string_view name, std::set<std::string>& taken) {
  std::string id;
  for (char c : name) {
    id += std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
  }
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0])) != 0) id = "_" + id;
  std::string unique = id;
  for (int n = 2; taken.contains(unique); ++n) unique = id + "_" + std::to_string(n);
  taken.insert(unique);
  return unique;
}

// A number none of `values` is, for noData: the lowest double, or the next one up past the
// (unlikely) values that take it.
double unused_number(const std::vector<double>& values) {
  double candidate = std::numeric_limits<double>::lowest();
  while (std::find(values.begin(), values.end(), candidate) != values.end()) {
    candidate = std::nextafter(candidate, 0.0);
  }
  return candidate;
}

}  // namespace

std::shared_ptr<const shape::AttributeMap> building_feature_attributes(
    const shape::Building& building) {
  auto attributes = std::make_shared<shape::AttributeMap>(building.attributes);
  (*attributes)[std::string(kBuildingIdProperty)] = building.id;
  return attributes;
}

void make_feature(shape::Part& part, std::shared_ptr<const shape::AttributeMap> building) {
  part.attributes.erase(std::string(kBuildingIdProperty));
  part.inherited = std::move(building);
}

std::string_view kind_name(shape::PartKind kind) {
  switch (kind) {
    case shape::PartKind::kBuildingPart:
      return "BuildingPart";
    case shape::PartKind::kStorey:
      return "Storey";
    case shape::PartKind::kRoom:
      return "Room";
    case shape::PartKind::kInstallation:
      return "Installation";
    case shape::PartKind::kFurniture:
      return "Furniture";
    case shape::PartKind::kOther:
      break;
  }
  return "Other";
}

namespace {

// Calls `own(key, value)` for each attribute `part` has of its own and `inherited(i, value)` for
// the `i`th entry of its inherited map where it has none of its own, skipping nulls; both maps are
// sorted by key, so one merge walks them.
template <typename Own, typename Inherited>
void for_each_attribute(const shape::Part& part, Own&& own, Inherited&& inherited) {
  static const shape::AttributeMap kNone;
  const shape::AttributeMap& mine = part.attributes;
  const shape::AttributeMap& theirs = part.inherited ? *part.inherited : kNone;
  auto a = mine.begin();
  auto b = theirs.begin();
  std::size_t i = 0;  // b's position
  while (a != mine.end() || b != theirs.end()) {
    const bool same = a != mine.end() && b != theirs.end() && a->first == b->first;
    if (b == theirs.end() || (a != mine.end() && a->first < b->first) ||
        (same && !shape::is_null(a->second))) {
      if (!shape::is_null(a->second)) own(a->first, a->second);
      if (same) ++b, ++i;
      ++a;
      continue;
    }
    if (same) ++a;  // a null of its own: the inherited value shows through
    if (!shape::is_null(b->second)) inherited(i, b->second);
    ++b, ++i;
  }
}

}  // namespace

PartTable::PartTable(const shape::Scene& scene, const std::vector<bool>& has_row) {
  find_columns(scene, has_row);
  std::size_t k = 0;  // the part's position in scene order
  for (const shape::Building& building : scene.buildings) {
    for (std::size_t p = 0; p < building.parts.size(); ++p, ++k) {
      if (has_row.empty() || has_row[k]) add_row(building.parts[p], p);
    }
  }
  for (Column& column : columns_) {
    column.index_of = {};
    if (column.type == Type::kString) make_dictionary(column);
  }
}

// The attribute columns and the type each can have.
void PartTable::find_columns(const shape::Scene& scene, const std::vector<bool>& has_row) {
  struct Seen {
    std::size_t count = 0;
    bool numbers = true;
    bool booleans = true;
  };
  std::map<std::string, Seen, std::less<>> seen;
  const auto note = [](Seen& s, const shape::Value& value) {
    ++s.count;
    s.numbers = s.numbers && std::holds_alternative<double>(value);
    s.booleans = s.booleans && std::holds_alternative<bool>(value);
  };
  // Each inherited map's entries as Seen records, looked up once for the run of parts sharing it
  // (a building's parts come together; a map met again later is looked up again, which costs
  // less than a table of every map seen, one entry a building).
  std::vector<Seen*> entries;
  const shape::AttributeMap* last = nullptr;
  std::size_t first = 0;
  std::size_t k = 0;  // the part's position in scene order
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      const bool row = has_row.empty() || has_row[k];
      ++k;
      if (!row) continue;
      ++rows_;
      if (part.inherited && part.inherited.get() != last) {
        last = part.inherited.get();
        first = entries.size();
        // A null makes no column (as a copied null did not): no entry for it.
        for (const auto& [key, value] : *last) {
          entries.push_back(shape::is_null(value) ? nullptr : &seen.try_emplace(key).first->second);
        }
      }
      for_each_attribute(
          part,
          [&](const std::string& key, const shape::Value& value) {
            note(seen.try_emplace(key).first->second, value);
          },
          [&](std::size_t i, const shape::Value& value) { note(*entries[first + i], value); });
    }
  }
  // The part's own name is `part_name`: a building's `name` (an OpenStreetMap tag, a register's
  // street name) keeps its own, and CesiumJS shows properties by id.
  std::set<std::string> taken{"kind", "part_name"};
  columns_.push_back({"part_name", "", Type::kString});
  columns_.push_back({"kind", "", Type::kString});
  // A column of numbers stays numeric where some parts lack it (a register's height column with
  // empty records): those rows get the column's noData. It was text, so a tile with one gap had
  // STRING heights and its neighbours SCALAR ones, and styling by number broke. Booleans have no
  // noData in 3D Metadata: one missing makes the column text.
  for (const auto& [key, s] : seen) {
    Type type = Type::kString;
    if (s.count > 0 && s.numbers) type = Type::kNumber;
    if (s.count == rows_ && s.booleans) type = Type::kBoolean;
    columns_.push_back({property_id(key, taken), key, type, s.count < rows_});
  }
}

// The column's code for `text`, a new one (in order of first use) for a text not met before. An
// open-addressing table of codes, looked up by view: a map of strings allocated a node and a
// copy of every distinct text (most of a tile's names and ids are distinct).
std::uint32_t PartTable::intern(Column& column, std::string_view text) {
  std::vector<std::uint32_t>& slots = column.index_of;
  if (2 * (column.values.size() + 1) > slots.size()) grow_index(column);
  const std::size_t mask = slots.size() - 1;
  const std::size_t hash = std::hash<std::string_view>{}(text);
  for (std::size_t slot = hash & mask;; slot = (slot + 1) & mask) {
    const std::uint32_t code = slots[slot];
    if (code == kAbsent) {
      slots[slot] = static_cast<std::uint32_t>(column.values.size());
      column.values.emplace_back(text);
      return slots[slot];
    }
    if (column.values[code] == text) return code;
  }
}

// The code of a value's text: a text value looked up as it is, without a copy.
std::uint32_t PartTable::intern_value(Column& column, const shape::Value& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return intern(column, *text);
  return intern(column, shape::to_string(value));
}

// Doubles the column's table of codes (16 slots at first) and enters every text again.
void PartTable::grow_index(Column& column) {
  std::vector<std::uint32_t>& slots = column.index_of;
  slots.assign(std::max<std::size_t>(16, 2 * slots.size()), kAbsent);
  const std::size_t mask = slots.size() - 1;
  for (std::uint32_t code = 0; code < column.values.size(); ++code) {
    std::size_t slot = std::hash<std::string_view>{}(column.values[code]) & mask;
    while (slots[slot] != kAbsent) slot = (slot + 1) & mask;
    slots[slot] = code;
  }
}

// The first of `map`'s entries in inherited_values_ and inherited_codes_ (one per attribute
// column), found once for the run of parts sharing the map (a tile's building's parts come
// together).
std::size_t PartTable::inherited_row(const shape::AttributeMap& map) {
  if (&map == last_inherited_) return last_inherited_row_;
  const std::size_t first = inherited_values_.size();
  last_inherited_ = &map;
  last_inherited_row_ = first;
  for (std::size_t c = 2; c < columns_.size(); ++c) {
    Column& column = columns_[c];
    const auto found = map.find(column.name);
    const bool present = found != map.end() && !shape::is_null(found->second);
    inherited_values_.push_back(present ? &found->second : nullptr);
    inherited_codes_.push_back(
        present && column.type == Type::kString ? intern_value(column, found->second) : kAbsent);
  }
  return first;
}

// Appends `part` (the `index`th of its building) as a row: each attribute column takes the part's
// own value, else the inherited one (both maps and the columns are sorted by name, so one walk).
void PartTable::add_row(const shape::Part& part, std::size_t index) {
  Column& names = columns_[0];
  names.codes.push_back(part.name.empty() ? intern(names, "part" + std::to_string(index))
                                          : intern(names, part.name));
  // A handful of kinds: each one's code is kept rather than looked up row by row.
  const auto kind = static_cast<std::size_t>(part.kind);
  if (kind >= kind_codes_.size()) kind_codes_.resize(kind + 1, kAbsent);
  if (kind_codes_[kind] == kAbsent) kind_codes_[kind] = intern(columns_[1], kind_name(part.kind));
  columns_[1].codes.push_back(kind_codes_[kind]);
  constexpr std::size_t kNone = SIZE_MAX;
  const std::size_t inherited = part.inherited ? inherited_row(*part.inherited) : kNone;
  auto own = part.attributes.begin();
  for (std::size_t c = 2; c < columns_.size(); ++c) {
    Column& column = columns_[c];
    while (own != part.attributes.end() && own->first < column.name) ++own;
    const shape::Value* value = nullptr;
    std::uint32_t code = kAbsent;
    if (own != part.attributes.end() && own->first == column.name && !shape::is_null(own->second)) {
      value = &own->second;
      if (column.type == Type::kString) code = intern_value(column, *value);
    } else if (inherited != kNone) {
      value = inherited_values_[inherited + c - 2];
      code = inherited_codes_[inherited + c - 2];
    }
    switch (column.type) {
      case Type::kNumber:
        column.numbers.push_back(value != nullptr ? std::get<double>(*value)
                                                  : std::numeric_limits<double>::quiet_NaN());
        break;
      case Type::kBoolean:
        column.booleans.push_back(std::get<bool>(*value));
        break;
      case Type::kString:
        column.codes.push_back(code);
        break;
    }
  }
}

// The column's distinct values, sorted, when they fit 16-bit codes, none is empty (an enum value
// needs a name) and coding them makes the column smaller; `no_data` a name none of them has.
void PartTable::make_dictionary(Column& column) {
  // `values` are distinct already: the checks come before the sort, which most columns of mostly
  // distinct texts (names, ids) never need.
  const std::vector<std::string>& values = column.values;
  if (values.size() + (column.optional ? 1 : 0) > 65536) return;
  if (std::any_of(values.begin(), values.end(), [](const auto& v) { return v.empty(); })) return;
  // Only where it pays: each enum value costs its name and about 30 bytes of JSON, each row a
  // code of 1 or 2 bytes; a STRING column costs each row's text and a 4-byte offset.
  std::size_t as_enum = 0;
  std::size_t as_string = 4;
  for (const std::string& value : values) as_enum += value.size() + 30;
  as_enum += column.codes.size() * (values.size() < 256 ? 1 : 2);
  for (std::uint32_t code : column.codes) {
    as_string += (code == kAbsent ? 0 : values[code].size()) + 4;
  }
  if (as_enum >= as_string) return;
  std::vector<std::string_view> distinct(values.begin(), values.end());
  std::sort(distinct.begin(), distinct.end());
  const auto contains = [&distinct](std::string_view value) {
    return std::binary_search(distinct.begin(), distinct.end(), value);
  };
  column.dictionary.assign(distinct.begin(), distinct.end());
  column.enum_code.resize(column.values.size());
  for (std::size_t v = 0; v < column.values.size(); ++v) {
    column.enum_code[v] = static_cast<std::uint32_t>(
        std::lower_bound(distinct.begin(), distinct.end(), column.values[v]) - distinct.begin());
  }
  std::string dashes;
  column.no_data = "(none)";
  while (contains(column.no_data)) {
    dashes += '-';
    column.no_data = "(" + dashes + "none)";
  }
}

void PartTable::write_data(Buffers& buffers) {
  for (Column& column : columns_) {
    column.values_view = buffers.add_view(ViewKind::kColumn, 0);
    Bytes& values = buffers.data(column.values_view);
    switch (column.type) {
      case Type::kNumber:
        if (column.optional) column.no_data_number = unused_number(column.numbers);
        for (double v : column.numbers)
          append_value(values, std::isnan(v) ? column.no_data_number : v);
        break;
      case Type::kBoolean: {
        // A bitstream, least significant bit first (3D Metadata, "Booleans").
        values.append((column.booleans.size() + 7) / 8, '\0');  // a new view: empty
        for (std::size_t i = 0; i < column.booleans.size(); ++i) {
          if (column.booleans[i]) values[i / 8] = static_cast<char>(values[i / 8] | (1 << (i % 8)));
        }
        break;
      }
      case Type::kString: {
        if (!column.dictionary.empty()) {
          const bool wide = column.dictionary.size() + (column.optional ? 1 : 0) > 256;
          for (const std::uint32_t value : column.codes) {
            const auto code = static_cast<std::uint16_t>(
                value == kAbsent ? column.dictionary.size() : column.enum_code[value]);
            if (wide) {
              append_value(values, code);
            } else {
              append_value(values, static_cast<std::uint8_t>(code));
            }
          }
          break;
        }
        column.offsets_view = buffers.add_view(ViewKind::kColumn, 0);
        Bytes& offsets = buffers.data(column.offsets_view);
        std::uint32_t offset = 0;
        for (const std::uint32_t code : column.codes) {
          append_value(offsets, offset);
          if (code == kAbsent) continue;
          values += column.values[code];
          offset += static_cast<std::uint32_t>(column.values[code].size());
        }
        append_value(offsets, offset);
        // A table whose strings are all empty still needs a (non-empty) values view.
        if (values.empty()) values.push_back('\0');
        break;
      }
    }
  }
}

// The property's definition in the class; keys in sorted order.
void PartTable::write_class_property(JsonStream& json, const Column& column) const {
  const bool text = column.type == Type::kString;
  const bool coded = text && !column.dictionary.empty();
  json.key(column.id).begin_object();
  if (column.type == Type::kNumber) json.key("componentType").string("FLOAT64");
  if (coded) json.key("enumType").string(column.id);
  if (!column.name.empty()) json.key("name").string(column.name);
  if (text && column.optional) {
    json.key("noData").string(coded ? std::string_view(column.no_data) : std::string_view());
  } else if (column.type == Type::kNumber && column.optional) {
    json.key("noData").number(column.no_data_number);
  } else {
    json.key("required").boolean(true);
  }
  json.key("type").string(coded                           ? "ENUM"
                          : text                          ? "STRING"
                          : column.type == Type::kBoolean ? "BOOLEAN"
                                                          : "SCALAR");
  json.end_object();
}

void PartTable::write_json(JsonStream& json, const Buffers& buffers) const {
  std::vector<const Column*> sorted;
  for (const Column& column : columns_) sorted.push_back(&column);
  std::sort(sorted.begin(), sorted.end(),
            [](const Column* a, const Column* b) { return a->id < b->id; });
  json.key(kMetadataExtension).begin_object();
  json.key("propertyTables").begin_array().begin_object();
  json.key("class").string("part").key("count").integer(rows_).key("name").string("parts");
  json.key("properties").begin_object();
  for (const Column* column : sorted) {
    json.key(column->id).begin_object();
    if (column->type == Type::kString && column->dictionary.empty()) {
      json.key("stringOffsets").integer(buffers.view_index(column->offsets_view));
    }
    json.key("values").integer(buffers.view_index(column->values_view)).end_object();
  }
  json.end_object().end_object().end_array();
  json.key("schema").begin_object().key("classes").begin_object();
  json.key("part").begin_object().key("name").string("Part").key("properties").begin_object();
  for (const Column* column : sorted) write_class_property(json, *column);
  json.end_object().end_object().end_object();
  bool any_enum = false;
  for (const Column* column : sorted) any_enum = any_enum || !column->dictionary.empty();
  if (any_enum) {
    json.key("enums").begin_object();
    for (const Column* column : sorted) {
      if (column->dictionary.empty()) continue;
      const std::size_t codes = column->dictionary.size() + (column->optional ? 1 : 0);
      json.key(column->id).begin_object();
      json.key("valueType").string(codes > 256 ? "UINT16" : "UINT8").key("values").begin_array();
      for (std::size_t i = 0; i < column->dictionary.size(); ++i) {
        json.begin_object().key("name").string(column->dictionary[i]);
        json.key("value").integer(i).end_object();
      }
      if (column->optional) {
        json.begin_object().key("name").string(column->no_data);
        json.key("value").integer(column->dictionary.size()).end_object();
      }
      json.end_array().end_object();
    }
    json.end_object();
  }
  json.key("id").string("insula").end_object();
  json.end_object();
}

}  // namespace insula::io::gltf
