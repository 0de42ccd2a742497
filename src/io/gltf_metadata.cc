#include "io/gltf_metadata.h"

#include <algorithm>
#include <cctype>
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

}  // namespace

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
    case shape::PartKind::kOther:
      break;
  }
  return "Other";
}

PartTable::PartTable(const shape::Scene& scene) {
  // The attribute columns and the type each can have.
  struct Seen {
    std::size_t count = 0;
    bool numbers = true;
    bool booleans = true;
  };
  std::map<std::string, Seen, std::less<>> seen;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      ++rows_;
      for (const auto& [key, value] : part.attributes) {
        if (shape::is_null(value)) continue;
        Seen& s = seen[key];
        ++s.count;
        s.numbers = s.numbers && std::holds_alternative<double>(value);
        s.booleans = s.booleans && std::holds_alternative<bool>(value);
      }
    }
  }
  std::set<std::string> taken{"kind", "name"};
  columns_.push_back({"name", "", Type::kString});
  columns_.push_back({"kind", "", Type::kString});
  for (const auto& [key, s] : seen) {
    Type type = Type::kString;
    if (s.count == rows_ && s.numbers) type = Type::kNumber;
    if (s.count == rows_ && s.booleans) type = Type::kBoolean;
    columns_.push_back({property_id(key, taken), key, type, s.count < rows_});
  }
  for (const shape::Building& building : scene.buildings) {
    for (std::size_t p = 0; p < building.parts.size(); ++p) {
      const shape::Part& part = building.parts[p];
      columns_[0].strings.push_back(part.name.empty() ? "part" + std::to_string(p) : part.name);
      columns_[0].present.push_back(true);
      columns_[1].strings.emplace_back(kind_name(part.kind));
      columns_[1].present.push_back(true);
      for (std::size_t c = 2; c < columns_.size(); ++c) {
        Column& column = columns_[c];
        const auto it = part.attributes.find(column.name);
        const bool present = it != part.attributes.end() && !shape::is_null(it->second);
        switch (column.type) {
          case Type::kNumber:
            column.numbers.push_back(std::get<double>(it->second));
            break;
          case Type::kBoolean:
            column.booleans.push_back(std::get<bool>(it->second));
            break;
          case Type::kString:
            column.strings.push_back(present ? shape::to_string(it->second) : std::string{});
            column.present.push_back(present);
            break;
        }
      }
    }
  }
  for (Column& column : columns_) {
    if (column.type == Type::kString) make_dictionary(column);
  }
}

// The column's distinct values, sorted, when they fit 16-bit codes, none is empty (an enum value
// needs a name) and coding them makes the column smaller; `no_data` a name none of them has.
void PartTable::make_dictionary(Column& column) {
  // A sorted vector, not a set: a column is as long as the scene has parts.
  std::vector<std::string_view> distinct;
  for (std::size_t i = 0; i < column.strings.size(); ++i) {
    if (column.present[i]) distinct.push_back(column.strings[i]);
  }
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  const auto contains = [&distinct](std::string_view value) {
    return std::binary_search(distinct.begin(), distinct.end(), value);
  };
  if (contains("") || distinct.size() + (column.optional ? 1 : 0) > 65536) return;
  // Only where it pays: each enum value costs its name and about 30 bytes of JSON, each row a
  // code of 1 or 2 bytes; a STRING column costs each row's text and a 4-byte offset.
  std::size_t as_enum = 0;
  std::size_t as_string = 4;
  for (std::string_view value : distinct) as_enum += value.size() + 30;
  as_enum += column.strings.size() * (distinct.size() < 256 ? 1 : 2);
  for (const std::string& value : column.strings) as_string += value.size() + 4;
  if (as_enum >= as_string) return;
  column.dictionary.assign(distinct.begin(), distinct.end());
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
    std::string& values = buffers.data(column.values_view);
    switch (column.type) {
      case Type::kNumber:
        for (double v : column.numbers) append_value(values, v);
        break;
      case Type::kBoolean: {
        // A bitstream, least significant bit first (3D Metadata, "Booleans").
        values.assign((column.booleans.size() + 7) / 8, '\0');
        for (std::size_t i = 0; i < column.booleans.size(); ++i) {
          if (column.booleans[i]) values[i / 8] = static_cast<char>(values[i / 8] | (1 << (i % 8)));
        }
        break;
      }
      case Type::kString: {
        if (!column.dictionary.empty()) {
          const bool wide = column.dictionary.size() + (column.optional ? 1 : 0) > 256;
          for (std::size_t i = 0; i < column.strings.size(); ++i) {
            const auto code = static_cast<std::uint16_t>(
                column.present[i] ? std::lower_bound(column.dictionary.begin(),
                                                     column.dictionary.end(), column.strings[i]) -
                                        column.dictionary.begin()
                                  : column.dictionary.size());
            if (wide) {
              append_value(values, code);
            } else {
              append_value(values, static_cast<std::uint8_t>(code));
            }
          }
          break;
        }
        column.offsets_view = buffers.add_view(ViewKind::kColumn, 0);
        std::string& offsets = buffers.data(column.offsets_view);
        std::uint32_t offset = 0;
        for (const std::string& s : column.strings) {
          append_value(offsets, offset);
          values += s;
          offset += static_cast<std::uint32_t>(s.size());
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
