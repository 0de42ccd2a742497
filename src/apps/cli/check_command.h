// `insula check INPUT`: parse and check only, no geometry (design.md, "Command line"). The
// front-end is chosen by INPUT's extension.
#pragma once

#include <string>

namespace CLI {
class App;
}

#include "apps/cli/crs_flags.h"

namespace insula::cli {

struct CheckOptions {
  std::string input;
  bool quiet = false;
  std::string start;        // --start SYMBOL: the CGA start symbol (other front-ends ignore it)
  CrsFlags crs;             // --crs, --out-crs (GeoJSON, OSM)
  bool keep_going = false;  // --keep-going: skip invalid features, as mass and build do (GeoJSON)
  std::string workspace;    // --workspace DIR: where CGA's "/Project/..." names start (assets.md)
};

void add_check_command(CLI::App& app, CheckOptions& options);
int run_check(const CheckOptions& options);

}  // namespace insula::cli
