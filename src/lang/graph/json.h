// Order-preserving JSON with the byte offset of every value and object key, so graph diagnostics
// point into the file and into expression strings (docs/graph-executor.md, "Reading").
// nlohmann_json's SAX parser reads the text through an iterator that counts the bytes consumed;
// each SAX event turns that count into the start of its token.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"

namespace insula::lang::graph {

struct JsonMember;

struct JsonValue {
  enum class Kind : std::uint8_t { kNull, kBool, kInteger, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;
  std::size_t offset = 0;  // first byte of the value (a string's opening quote)
  bool boolean = false;
  std::int64_t integer = 0;
  double number = 0;                // also set for integers
  std::string text;                 // a string's decoded bytes
  std::vector<JsonValue> items;     // arrays
  std::vector<JsonMember> members;  // objects, in file order

  bool is_number() const { return kind == Kind::kInteger || kind == Kind::kNumber; }
  // The member named `key`, or null.
  const JsonValue* find(std::string_view key) const;
};

struct JsonMember {
  std::string key;
  std::size_t key_offset = 0;  // the key's opening quote
  JsonValue value;
};

// "an object", "a string", ... for messages.
std::string_view kind_name(JsonValue::Kind kind);

// Objects and arrays nest at most this deep (deeper input is G001).
constexpr int kMaxJsonDepth = 200;

// Parses `source` whole; G001 `invalid JSON: <reason>` at the offending byte.
base::Result<JsonValue> parse_json(const base::Source& source);

// The byte offset in the file of byte `index` of the decoded string `value` (escapes counted as
// written), so an expression error points at its character in the file.
std::size_t string_byte_offset(const base::Source& source, const JsonValue& value,
                               std::size_t index);

}  // namespace insula::lang::graph
