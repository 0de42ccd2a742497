// Command-line validators. CLI11's Range lets "nan" through (every comparison with NaN is false),
// so numeric options use finite_range instead.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <string>

namespace insula::cli {

// A finite number in [low, high].
inline CLI::Validator finite_range(double low, double high) {
  const std::string range =
      "[" + CLI::detail::to_string(low) + " - " + CLI::detail::to_string(high) + "]";
  return CLI::Validator(
      [low, high, range](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) {
          return "'" + text + "' is not a finite number";
        }
        if (value < low || value > high) return "value " + text + " not in range " + range;
        return {};
      },
      "FLOAT in " + range);
}

}  // namespace insula::cli
