#include "lang/graph/value.h"

#include <array>
#include <charconv>
#include <cmath>

namespace insula::lang::graph {
namespace {

// 2^63: the first double past INT64_MAX (every double below it and >= -2^63 fits).
constexpr double kTwo63 = 9223372036854775808.0;

// Integer and number compare as numbers; long double holds every int64 exactly on the targets
// we build for (x86-64 extended, aarch64 quad), so 2^53 + 1 is not equal to 2^53.
bool same_number(std::int64_t i, double d) {
  return static_cast<long double>(i) == static_cast<long double>(d);
}

}  // namespace

ValueType Value::type() const {
  switch (data.index()) {
    case 0:
      return ValueType::kNumber;
    case 1:
      return ValueType::kInteger;
    case 2:
      return ValueType::kBool;
    case 3:
      return ValueType::kString;
    case 4:
      return ValueType::kVec3;
    default:
      return ValueType::kList;
  }
}

double Value::number() const {
  if (const double* d = std::get_if<double>(&data)) return *d;
  if (const std::int64_t* i = std::get_if<std::int64_t>(&data)) return static_cast<double>(*i);
  return 0;
}

bool operator==(const Value& a, const Value& b) {
  const ValueType ta = a.type();
  const ValueType tb = b.type();
  if (ta == ValueType::kInteger && tb == ValueType::kNumber) {
    return same_number(a.integer(), std::get<double>(b.data));
  }
  if (ta == ValueType::kNumber && tb == ValueType::kInteger) {
    return same_number(b.integer(), std::get<double>(a.data));
  }
  if (ta != tb) return false;
  switch (ta) {
    case ValueType::kNumber:
      return std::get<double>(a.data) == std::get<double>(b.data);
    case ValueType::kInteger:
      return a.integer() == b.integer();
    case ValueType::kBool:
      return a.boolean() == b.boolean();
    case ValueType::kString:
      return a.text() == b.text();
    case ValueType::kVec3:
      return a.vec() == b.vec();
    default:
      return a.list() == b.list();
  }
}

std::string to_string(const Value& value) {
  switch (value.type()) {
    case ValueType::kNumber: {
      const double d = std::get<double>(value.data);
      if (d == 0) return "0";  // also -0
      // The shortest text that reads back as the same double, in positional notation between
      // 1e-7 and 1e21 as JavaScript writes numbers (100000, not 1e+05), else in exponent form.
      std::array<char, 400> buffer{};
      const double magnitude = std::fabs(d);
      const auto result = magnitude >= 1e-7 && magnitude < 1e21
                              ? std::to_chars(buffer.data(), buffer.data() + buffer.size(), d,
                                              std::chars_format::fixed)
                              : std::to_chars(buffer.data(), buffer.data() + buffer.size(), d);
      return std::string(buffer.data(), result.ptr);
    }
    case ValueType::kInteger:
      return std::to_string(value.integer());
    case ValueType::kBool:
      return value.boolean() ? "true" : "false";
    case ValueType::kString:
      return value.text();
    case ValueType::kVec3: {
      const kernel::Vec3 v = value.vec();
      return to_string(Value(ValueList{v.x, v.y, v.z}));
    }
    default: {
      std::string out = "[";
      for (const Value& item : value.list()) {
        if (out.size() > 1) out += ", ";
        out += to_string(item);
      }
      return out + "]";
    }
  }
}

std::optional<Value> value_from_json(const JsonValue& json, ValueType want) {
  switch (json.kind) {
    case JsonValue::Kind::kNull:
    case JsonValue::Kind::kObject:
      return std::nullopt;
    case JsonValue::Kind::kBool:
      return Value(json.boolean);
    case JsonValue::Kind::kInteger:
      return Value(json.integer);
    case JsonValue::Kind::kNumber:
      return Value(json.number);
    case JsonValue::Kind::kString:
      return Value(json.text);
    case JsonValue::Kind::kArray:
      break;
  }
  if (want == ValueType::kVec3 && json.items.size() == 3 && json.items[0].is_number() &&
      json.items[1].is_number() && json.items[2].is_number()) {
    return Value(kernel::Vec3{json.items[0].number, json.items[1].number, json.items[2].number});
  }
  ValueList items;
  items.reserve(json.items.size());
  for (const JsonValue& item : json.items) {
    std::optional<Value> v = value_from_json(item);
    if (!v) return std::nullopt;
    items.push_back(std::move(*v));
  }
  return Value(std::move(items));
}

std::optional<std::int64_t> whole_integer(double d) {
  if (std::trunc(d) != d || d < -kTwo63 || d >= kTwo63) return std::nullopt;
  return static_cast<std::int64_t>(d);
}

std::optional<Value> convert(const Value& value, ValueType type) {
  const ValueType have = value.type();
  if (type == ValueType::kAny || type == have) return value;
  switch (type) {
    case ValueType::kNumber:
      if (have == ValueType::kInteger) return Value(value.number());
      return std::nullopt;
    case ValueType::kInteger: {
      if (have != ValueType::kNumber) return std::nullopt;
      const std::optional<std::int64_t> i = whole_integer(std::get<double>(value.data));
      if (!i) return std::nullopt;
      return Value(*i);
    }
    case ValueType::kVec3: {
      if (have != ValueType::kList) return std::nullopt;
      const ValueList& items = value.list();
      if (items.size() != 3 || !items[0].is_number() || !items[1].is_number() ||
          !items[2].is_number()) {
        return std::nullopt;
      }
      return Value(kernel::Vec3{items[0].number(), items[1].number(), items[2].number()});
    }
    case ValueType::kEnum:
      if (have == ValueType::kString) return value;
      return std::nullopt;
    default:
      return std::nullopt;
  }
}

}  // namespace insula::lang::graph
