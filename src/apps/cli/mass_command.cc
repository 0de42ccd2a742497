#include "apps/cli/mass_command.h"

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <thread>

#include "apps/cli/build_command.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/footprint_input.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/height_unit.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/mass_build.h"
#include "apps/cli/mass_outcome.h"
#include "apps/cli/mass_plan.h"
#include "apps/cli/mass_report.h"
#include "apps/cli/mass_tiles.h"
#include "apps/cli/memory.h"
#include "apps/cli/progress.h"
#include "apps/cli/ranks.h"
#include "apps/cli/stopwatch.h"
#include "apps/cli/tile_job.h"
#include "apps/cli/validators.h"
#include "apps/cli/view_options.h"
#include "apps/cli/warnings.h"
#include "base/diagnostic.h"
#include "io/geojson_reader.h"
#include "io/output.h"
#include "io/tileset_writer.h"
#include "kernel/mass.h"
#include "shape/scene.h"

namespace insula::cli {
namespace {

const std::vector<std::string> kRoofNames = {
    "flat",    "shed",        "gable",   "hip",   "pyramid", "mansard", "holed_mansard",
    "gambrel", "half_hipped", "saltbox", "round", "dome",    "onion"};

// Builds every unit in parallel; results land by index, so the output does not depend on the
// thread count. After an interruption the workers build nothing more (the caller checks).
std::vector<BuiltBuilding> build_all(const io::FootprintSet& set, const MassPlan& plan,
                                     const std::vector<MassUnit>& units, bool quiet) {
  std::vector<BuiltBuilding> built(units.size());
  Progress progress("buildings", built.size(), quiet);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, built.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        if (interrupted()) return;
                        built[i] = build_unit(set, plan, units[i]);
                      }
                      progress.advance(range.size());
                    });
  return built;
}

}  // namespace

void add_mass_command(CLI::App& app, MassOptions& options) {
  CLI::App* mass =
      app.add_subcommand("mass", "LOD2 mass models: one closed roofed building per footprint");
  mass->add_option("FOOTPRINTS", options.input, "GeoJSON file of Polygon/MultiPolygon footprints")
      ->required();
  mass->add_option("-o,--output", options.outputs,
                   "output file, format by extension (.obj .glb .gltf .city.json .city.jsonl .svg "
                   ".png); repeatable")
      ->required();
  auto* roof =
      mass->add_option("--roof", options.roof,
                       "roof type: flat, shed, gable, hip, pyramid, mansard, holed_mansard, "
                       "gambrel, half_hipped, saltbox, round, dome, onion (default: hip; "
                       "OpenStreetMap features: roof:shape, else flat; others: their 'roof')")
          ->check(CLI::IsMember(kRoofNames));
  auto* pitch = mass->add_option("--pitch", options.pitch_deg,
                                 "roof pitch in degrees (default 30; else the feature's 'pitch')")
                    ->check(finite_range(1.0, 75.0));
  mass->add_option("--overhang", options.overhang, "roof overhang in meters (default 0)")
      ->check(finite_range(0.0, 5.0));
  auto* height =
      mass->add_option("--height", options.height, "wall height in meters for every building")
          ->check(finite_range(0.5, 1000.0));
  mass->add_option("--height-attr", options.height_attr,
                   "property holding the wall height of features that are not OpenStreetMap "
                   "buildings (default 'height'; OSM features follow Simple 3D Buildings)")
      ->excludes(height);
  add_height_unit_option(*mass, options.height_unit,
                         "unit of bare numbers in the height properties of features that are not "
                         "OpenStreetMap buildings");
  mass->add_option("--levels-attr", options.levels_attr,
                   "property holding the number of storeys, times --storey-height, when no "
                   "height is given")
      ->excludes(height);
  mass->add_option("--storey-height", options.storey_height,
                   "meters per storey for building:levels, roof:levels and --levels-attr "
                   "(default 3)")
      ->check(finite_range(1.0, 20.0));
  mass->add_option("--default-height", options.default_height,
                   "wall height when a feature has no usable height (default 10)")
      ->check(finite_range(0.5, 1000.0));
  mass->add_option("--report", options.report, "write a JSON report (counts, timings)");
  mass->add_flag("--report-buildings", options.report_buildings,
                 "list every building in the report: its heights, roof and their sources");
  mass->add_option("--threads", options.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  mass->add_flag("-q,--quiet", options.quiet, "no progress or warnings on stderr");
  mass->add_flag(
      "--keep-going", options.keep_going,
      "leave out invalid footprints and footprints that give no closed building (each with a "
      "warning) instead of failing");
  add_crs_option(*mass, options.crs);
  add_view_options(*mass, options.output);
  mass->callback([&options, roof, pitch]() {
    options.roof_given = roof->count() > 0;
    options.pitch_given = pitch->count() > 0;
  });
}

namespace {

void add_overlaps(const io::FootprintSet& set, const MassPlan& plan, MassReport& report) {
  report.overlaps = plan.overlap_summary.pairs;
  if (plan.overlap_summary.pairs > 0) {
    report.largest_overlap = {set.footprints[plan.overlap_summary.largest_first].id,
                              set.footprints[plan.overlap_summary.largest_second].id,
                              plan.overlap_summary.largest_area};
  }
}

}  // namespace

int run_mass(const MassOptions& given) {
  // Under mpirun only 3D Tiles are shared among the ranks; anything else is the leader's alone.
  // The other ranks work silently: the leader reports for all.
  if (Ranks::shared() && !Ranks::leader() && !streamable(given.outputs)) return kExitDone;
  MassOptions options = given;
  if (!Ranks::leader()) options.quiet = true;
  Stopwatch total;
  MassReport report;
  if (const int code = check_outputs(options.outputs, options.report, options.output);
      code != kExitDone) {
    return code;
  }
  const int threads = options.threads > 0
                          ? options.threads
                          : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(threads));
  report.threads = threads;

  Stopwatch read_clock;
  std::optional<io::FootprintSet> set = read_footprints(
      options.input, building_options(geojson_options(options.crs, options.keep_going)),
      options.quiet);
  if (!set) return kExitInput;
  report.stage("read", read_clock.seconds());
  release_free_memory();
  report.not_buildings = note_non_buildings(set.value(), options.quiet);
  report.invalid = set->skipped_invalid;
  report.invalid_by_code = set->skipped_by_code;
  report.repairs = set->repairs;
  report.crs = set->crs;
  report.source_crs = set->source_crs;

  Stopwatch build_clock;
  std::vector<Warning> warnings;
  const MassPlan plan = plan_mass(options, set.value(), warnings);
  report.stage("plan", build_clock.seconds());
  build_clock = Stopwatch();
  const std::vector<MassUnit> units = mass_units(plan);
  add_overlaps(set.value(), plan, report);
  if (streamable(options.outputs)) {
    return run_mass_tiles(options, set.value(), plan, units, warnings, report, total);
  }
  std::vector<BuiltBuilding> built = build_all(set.value(), plan, units, options.quiet);
  if (const int code = stop_if_interrupted(); code != 0) return code;
  shape::Scene scene;
  scene.origin = set->origin;
  scene.crs = set->crs;
  scene.materials = plan.materials;
  scene.buildings.reserve(built.size());
  std::vector<BuildOutcome> outcomes;
  outcomes.reserve(built.size());
  for (BuiltBuilding& b : built) {
    BuildOutcome outcome{b.building.id, b.feature, b.watertight, std::move(b.messages), {}};
    if (b.watertight || !options.keep_going) {
      report.count_building(b.building, b.watertight);
      if (options.report_buildings) report.describe_building(b.building);
      scene.buildings.push_back(std::move(b.building));
    }
    outcomes.push_back(std::move(outcome));
  }
  const std::size_t failed = account(options, set.value(), outcomes, warnings);
  if (const int code = check_built(options, failed, scene.buildings.size(), built.size());
      code != 0) {
    return code;
  }
  report.failed = failed;
  report.stage("build", build_clock.seconds());
  emit_mass_warnings(options, warnings, report);

  io::OutputTransaction transaction(interrupted);
  for (const std::string& out : options.outputs) {
    const Stopwatch write_clock;
    if (const std::string error = transaction.write_scene(scene, out, options.output);
        !error.empty()) {
      return write_failure(error);
    }
    report.stage("write " + io::output_format_name(out), write_clock.seconds());
  }
  return finish_mass(options, report, total, transaction);
}

}  // namespace insula::cli
