// The properties of many footprints in one compact table (issue 17: a city of a million footprints
// held its properties as a std::map per footprint, about 110 bytes per property). Keys are stored
// once and numbered; each property is a 16-byte entry (key number, kind, value); texts lie back to
// back in one buffer. A footprint holds a PropertyRow, and a builder asks for a shape::AttributeMap
// only for the building it is making (docs/geojson.md, "Properties").
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shape/value.h"

namespace insula::io {

class PropertyTable {
 public:
  // Starts the next row (rows are numbered from 0 in the order they are added) and returns its
  // number. Only the last row can be written.
  std::size_t add_row();
  // Sets `key` in `row`, which must be the last row. A key set twice in a row keeps the later
  // value, as a repeated member of a JSON object does.
  void set(std::size_t row, std::string_view key, const shape::Value& value);
  // The same for a text value, without making a std::string of it first.
  void set_text(std::size_t row, std::string_view key, std::string_view text);

  std::size_t rows() const { return row_starts_.size(); }
  std::size_t size(std::size_t row) const { return row_end(row) - row_starts_[row]; }
  // The value of `key` in `row`, or nullopt when the row has no such key.
  std::optional<shape::Value> find(std::size_t row, std::string_view key) const;
  // Every property of `row`, ordered by key.
  shape::AttributeMap map(std::size_t row) const;

 private:
  enum class Kind : std::uint8_t { kNull, kBool, kNumber, kText };
  struct Entry {
    std::uint32_t key : 30;  // index in keys_
    std::uint32_t kind : 2;  // a Kind
    std::uint32_t size;      // a text's length in bytes
    std::uint64_t bits;      // a bool (0, 1), a number's bits, or a text's offset in texts_
  };
  static_assert(sizeof(Entry) == 16);

  std::size_t row_end(std::size_t row) const {
    return row + 1 < row_starts_.size() ? row_starts_[row + 1] : entries_.size();
  }
  Entry& entry_for(std::size_t row, std::string_view key);
  shape::Value value_of(const Entry& entry) const;

  std::vector<std::string> keys_;
  std::map<std::string, std::uint32_t, std::less<>> key_numbers_;
  std::vector<std::size_t> row_starts_;  // row r: entries_[row_starts_[r], row_end(r))
  std::vector<Entry> entries_;
  std::string texts_;  // every text value, back to back
};

// One footprint's properties: a row of a table shared by the footprints read with it. A
// default-constructed row has no properties.
class PropertyRow {
 public:
  PropertyRow() = default;
  PropertyRow(std::shared_ptr<const PropertyTable> table, std::size_t row)
      : table_(std::move(table)), row_(row) {}
  // A row of its own holding `properties` (tests, and callers with a single map).
  static PropertyRow of(const shape::AttributeMap& properties);

  bool empty() const { return size() == 0; }
  std::size_t size() const { return table_ ? table_->size(row_) : 0; }
  std::optional<shape::Value> find(std::string_view key) const {
    return table_ ? table_->find(row_, key) : std::nullopt;
  }
  shape::AttributeMap map() const { return table_ ? table_->map(row_) : shape::AttributeMap(); }

 private:
  std::shared_ptr<const PropertyTable> table_;
  std::size_t row_ = 0;
};

}  // namespace insula::io
