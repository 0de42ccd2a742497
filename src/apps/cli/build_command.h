// `insula build INPUT [-o OUT]... [--lot LOTS.geojson] [--seed N] [--set name=value]...
// [--report R.json]` (design.md, "Command line"): the front-end is chosen by INPUT's extension
// (.cga, .bldg, .lua), each output format by OUT's extension. The options are shared; a front-end
// ignores those that do not apply to it and says so in its docs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/cli/crs_flags.h"
#include "apps/cli/stopwatch.h"
#include "io/output.h"
#include "shape/scene.h"
#include "shape/value.h"

namespace CLI {
class App;
}

namespace insula::cli {

class TileJob;
struct TileJobResult;
struct TileJobOptions;

struct BuildOptions {
  std::string input;
  std::vector<std::string> outputs;  // may be empty: derive and report only
  std::string lot;                   // --lot LOTS.geojson: lots / outline footprints
  std::uint64_t seed = 0;
  bool seed_given = false;  // --seed was on the command line (graphs have a seed of their own)
  int threads = 0;          // 0 = all cores
  std::vector<std::string> sets;    // --set name=value, as given
  std::string start;                // --start SYMBOL (CGA)
  std::string rules;                // --rules FILE: restriction rules (.bldg)
  std::vector<std::string> assets;  // --assets DIR: asset folders a program may read (.lua)
  std::string workspace;  // --workspace DIR: where CGA's "/Project/..." names start (assets.md)
  std::string report;     // --report R.json
  std::string probe;      // --probe NODE (graphs): that node's output entities, not the results
  std::size_t report_entities = std::numeric_limits<std::size_t>::max();  // --report-entities N
  CrsFlags crs;                   // --crs, --out-crs (geojson_options.h)
  std::string height_unit = "m";  // --height-unit: the lots' bare height numbers (height_unit.h)
  bool keep_going = false;        // --keep-going: skip invalid lot features with a warning
  bool quiet = false;
  io::OutputOptions output;  // PNG view and SVG options
  // Set by a batch (`insula random`): the outputs and the report go into its transaction, which
  // the batch commits, and nothing is listed on stdout.
  io::OutputTransaction* transaction = nullptr;
  // Called on the report just before it is written.
  std::function<void(nlohmann::json&)> amend_report;
};

void add_build_command(CLI::App& app, BuildOptions& options);
// Dispatches on the input's extension.
int run_build(const BuildOptions& options);

// True when the lots are built and written tile by tile (tile_job.h): --lot is given, every output
// is a 3D Tiles tileset or a CityJSONSeq and the build is not part of a batch.
bool city_by_tiles(const BuildOptions& options);

// Checks before any work: every output has a known format, picture options are valid and every
// output's directory (and the report's, when given) exists. Returns kExitDone or the exit code to
// return (the reason already printed). Shared by every verb that writes scenes.
int check_outputs(const std::vector<std::string>& outputs, const std::string& report,
                  const io::OutputOptions& output);
inline int check_build_outputs(const BuildOptions& options) {
  return check_outputs(options.outputs, options.report, options.output);
}

// The --set values, parsed: "name=value" with value a number, true/false or else a string.
// On a malformed entry returns false and sets `error` (e.g. "--set 'x': expected name=value").
bool parse_sets(const std::vector<std::string>& sets,
                std::vector<std::pair<std::string, shape::Value>>& out, std::string& error);

// Writes the scene to every output (adding report["seconds"]["write_<format>"]), then sets
// report["seconds"]["total"] from `total`, adds "warning_counts" and writes the report when asked,
// all in one io::OutputTransaction. Returns the exit code; on failure or interruption nothing is
// left behind and the user's earlier files are back.
int finish_build(const BuildOptions& options, const shape::Scene& scene, nlohmann::json& report,
                 const Stopwatch& total);
// finish_build's last steps, once the outputs are in `transaction`: the total time, the warning
// counts, the report, the commit point and the list of outputs on stdout.
int commit_build(const BuildOptions& options, nlohmann::json& report, const Stopwatch& total,
                 io::OutputTransaction& transaction);
// The tile job of `insula build --lot` (tile_job.h): the build's outputs, CRS, origin, glTF and
// tile options and threads; quiet on the other ranks; `counted` items named by `id_of`.
TileJobOptions build_tile_job_options(const BuildOptions& options, std::string crs,
                                      kernel::Vec3 origin, std::string counted,
                                      std::function<std::string(std::size_t)> id_of);
// The same for a tile job's tilesets (tile_job.h), on the leader: the report's tiles, ranks and
// stage time, the staged tiles moved into place, tileset.json, the commit point.
int commit_build_tiles(const BuildOptions& options, TileJob& job, const TileJobResult& built,
                       nlohmann::json& report, const Stopwatch& total,
                       const Stopwatch& build_clock);

}  // namespace insula::cli
