// Typed attribute values shared by shapes, footprints and exporters.
#pragma once

#include <map>
#include <string>
#include <variant>

namespace insula::shape {

// null, boolean, number (double), string.
using Value = std::variant<std::monostate, bool, double, std::string>;
// Ordered by name so every export is deterministic.
using AttributeMap = std::map<std::string, Value, std::less<>>;

std::string to_string(const Value& value);
bool is_null(const Value& value);

}  // namespace insula::shape
