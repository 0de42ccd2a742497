#include "io/property_table.h"

#include <bit>
#include <limits>
#include <stdexcept>
#include <variant>

namespace insula::io {

std::size_t PropertyTable::add_row() {
  row_starts_.push_back(entries_.size());
  return row_starts_.size() - 1;
}

// The entry of `key` in the last row: the one already there (its value is replaced), else a new
// one at the end.
PropertyTable::Entry& PropertyTable::entry_for(std::size_t row, std::string_view key) {
  if (row + 1 != row_starts_.size()) throw std::logic_error("PropertyTable: not the last row");
  auto found = key_numbers_.find(key);
  if (found == key_numbers_.end()) {
    if (keys_.size() >= (std::size_t{1} << 30)) throw std::length_error("PropertyTable: keys");
    found = key_numbers_.emplace(std::string(key), static_cast<std::uint32_t>(keys_.size())).first;
    keys_.emplace_back(key);
  }
  const std::uint32_t number = found->second;
  for (std::size_t e = row_starts_[row]; e < entries_.size(); ++e) {
    if (entries_[e].key == number) return entries_[e];
  }
  Entry& entry = entries_.emplace_back();
  entry.key = number;
  return entry;
}

void PropertyTable::set(std::size_t row, std::string_view key, const shape::Value& value) {
  if (const std::string* text = std::get_if<std::string>(&value)) {
    set_text(row, key, *text);
    return;
  }
  Entry& entry = entry_for(row, key);
  entry.size = 0;
  if (const bool* b = std::get_if<bool>(&value)) {
    entry.kind = static_cast<std::uint32_t>(Kind::kBool);
    entry.bits = *b ? 1 : 0;
  } else if (const double* d = std::get_if<double>(&value)) {
    entry.kind = static_cast<std::uint32_t>(Kind::kNumber);
    entry.bits = std::bit_cast<std::uint64_t>(*d);
  } else {
    entry.kind = static_cast<std::uint32_t>(Kind::kNull);
    entry.bits = 0;
  }
}

void PropertyTable::set_text(std::size_t row, std::string_view key, std::string_view text) {
  if (text.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::length_error("PropertyTable: a text of 4 GiB or more");
  }
  Entry& entry = entry_for(row, key);
  entry.kind = static_cast<std::uint32_t>(Kind::kText);
  entry.size = static_cast<std::uint32_t>(text.size());
  entry.bits = texts_.size();
  texts_.append(text);
}

shape::Value PropertyTable::value_of(const Entry& entry) const {
  switch (static_cast<Kind>(entry.kind)) {
    case Kind::kBool:
      return entry.bits != 0;
    case Kind::kNumber:
      return std::bit_cast<double>(entry.bits);
    case Kind::kText:
      return std::string(texts_, entry.bits, entry.size);
    case Kind::kNull:
      break;
  }
  return std::monostate{};
}

std::optional<shape::Value> PropertyTable::find(std::size_t row, std::string_view key) const {
  const auto found = key_numbers_.find(key);
  if (found == key_numbers_.end()) return std::nullopt;
  for (std::size_t e = row_starts_[row]; e < row_end(row); ++e) {
    if (entries_[e].key == found->second) return value_of(entries_[e]);
  }
  return std::nullopt;
}

shape::AttributeMap PropertyTable::map(std::size_t row) const {
  shape::AttributeMap out;
  for (std::size_t e = row_starts_[row]; e < row_end(row); ++e) {
    out.emplace(keys_[entries_[e].key], value_of(entries_[e]));
  }
  return out;
}

PropertyRow PropertyRow::of(const shape::AttributeMap& properties) {
  auto table = std::make_shared<PropertyTable>();
  const std::size_t row = table->add_row();
  for (const auto& [key, value] : properties) table->set(row, key, value);
  return {std::move(table), row};
}

}  // namespace insula::io
