// `insula mass FOOTPRINTS.geojson -o OUT...`: one closed LOD2 building per footprint.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "apps/cli/crs_flags.h"
#include "io/output.h"

namespace CLI {
class App;
}

namespace insula::cli {

struct MassOptions {
  std::string input;
  std::vector<std::string> outputs;
  std::string roof = "hip";
  double pitch_deg = 30;
  double overhang = 0;
  std::optional<double> height;
  std::string height_attr = "height";
  std::string height_unit = "m";  // --height-unit: m, ft or us-ft (registers' bare numbers)
  std::string levels_attr;        // --levels-attr: a register's storey count
  double storey_height = 3;       // --storey-height: meters per level (S3DB levels, --levels-attr)
  double default_height = 10;
  std::string report;
  bool report_buildings = false;  // --report-buildings: one report entry per building
  int threads = 0;
  bool quiet = false;
  bool keep_going = false;
  CrsFlags crs;              // --crs, --out-crs
  io::OutputOptions output;  // PNG view and SVG options
  // Set when the flag was given on the command line; a given flag wins over feature properties.
  bool roof_given = false;
  bool pitch_given = false;
};

void add_mass_command(CLI::App& app, MassOptions& options);
int run_mass(const MassOptions& options);

}  // namespace insula::cli
