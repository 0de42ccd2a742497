// Run-time values of expressions, parameters and attributes (graph-format.md §5): number
// (IEEE double), integer (64-bit), bool, string, vec3 and list. Lists are shared and immutable,
// so copying a value never copies a list.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "kernel/vec.h"
#include "lang/graph/json.h"
#include "lang/graph/types.h"

namespace insula::lang::graph {

struct Value;
using ValueList = std::vector<Value>;

struct Value {
  std::variant<double, std::int64_t, bool, std::string, kernel::Vec3,
               std::shared_ptr<const ValueList>>
      data = 0.0;

  Value() = default;
  Value(double v) : data(v) {}                    // NOLINT(google-explicit-constructor)
  Value(std::int64_t v) : data(v) {}              // NOLINT(google-explicit-constructor)
  Value(bool v) : data(v) {}                      // NOLINT(google-explicit-constructor)
  Value(std::string v) : data(std::move(v)) {}    // NOLINT(google-explicit-constructor)
  Value(const char* v) : data(std::string(v)) {}  // NOLINT(google-explicit-constructor)
  Value(kernel::Vec3 v) : data(v) {}              // NOLINT(google-explicit-constructor)
  Value(ValueList v)                              // NOLINT(google-explicit-constructor)
      : data(std::make_shared<const ValueList>(std::move(v))) {}

  ValueType type() const;  // kNumber, kInteger, kBool, kString, kVec3 or kList
  bool is_number() const { return type() == ValueType::kNumber || type() == ValueType::kInteger; }
  // Numbers and integers as double (0 for other types).
  double number() const;
  std::int64_t integer() const { return std::get<std::int64_t>(data); }
  bool boolean() const { return std::get<bool>(data); }
  const std::string& text() const { return std::get<std::string>(data); }
  kernel::Vec3 vec() const { return std::get<kernel::Vec3>(data); }
  const ValueList& list() const { return *std::get<std::shared_ptr<const ValueList>>(data); }

  // By value as §5's `==`: an integer equals the number of the same value (3 == 3.0), vec3s and
  // lists compare element by element; other values of different types are unequal.
  friend bool operator==(const Value& a, const Value& b);
};

// How a value is written in reports and messages: 3, 2.5, true, 'text' unquoted as text,
// [1, 2, 3] for vec3 and lists.
std::string to_string(const Value& value);

// A JSON literal as a value: numbers (integers stay integers), strings, booleans, arrays (three
// numbers are a vec3 when `want` is kVec3, else a list). Null and objects give nullopt.
std::optional<Value> value_from_json(const JsonValue& json, ValueType want = ValueType::kAny);

// `value` converted to `type` where §5 allows it (integer <-> number when integral, number list
// of three -> vec3, string -> enum); nullopt when it does not fit.
std::optional<Value> convert(const Value& value, ValueType type);

// `d` as an integer when it is whole and within int64 (casting anything else is undefined).
std::optional<std::int64_t> whole_integer(double d);

}  // namespace insula::lang::graph
