#include "shape/value.h"

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
    } else {
      std::snprintf(buffer, sizeof buffer, "%.17g", d);
    }
    return buffer;
  }
  return "null";
}

bool is_null(const Value& value) {
  return std::holds_alternative<std::monostate>(value);
}

}  // namespace insula::shape
