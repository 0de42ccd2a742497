#include "shape/value.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace insula::shape {

std::string to_string(const Value& value) {
  if (std::holds_alternative<bool>(value)) return std::get<bool>(value) ? "true" : "false";
  if (std::holds_alternative<std::string>(value)) return std::get<std::string>(value);
  if (std::holds_alternative<double>(value)) {
    const double d = std::get<double>(value);
    char buffer[32];
    if (std::isfinite(d) && d == std::round(d) && std::fabs(d) < 1e15) {
      std::snprintf(buffer, sizeof buffer, "%.0f", d);
      return buffer;
    }
    // The shortest text that reads back as the same double: 0.3, not 0.29999999999999999.
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, d).ptr;
    return std::string(buffer, end);
  }
  return "null";
}

bool is_null(const Value& value) {
  return std::holds_alternative<std::monostate>(value);
}

}  // namespace insula::shape
