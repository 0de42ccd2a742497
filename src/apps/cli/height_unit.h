// --height-unit m|ft|us-ft, shared by `mass` and `build --lot`: the unit of bare numbers in the
// height properties of features that are not OpenStreetMap or Overture buildings (registers in
// feet: NYC's heightroof, Philadelphia's approx_hgt; docs/osm-buildings.md, "Heights").
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace insula::cli {

// The option on `command`, into `unit`; `help` says which properties it applies to.
inline CLI::Option* add_height_unit_option(CLI::App& command, std::string& unit,
                                           const std::string& help) {
  return command.add_option("--height-unit", unit, help + ": m (default), ft or us-ft")
      ->check(CLI::IsMember({"m", "ft", "us-ft"}));
}

// Meters per unit: the international foot, or the US survey foot of EPSG:2263 and other state
// plane CRSs.
inline double meters_per_height_unit(const std::string& unit) {
  return unit == "ft" ? 0.3048 : unit == "us-ft" ? 1200.0 / 3937.0 : 1.0;
}

}  // namespace insula::cli
