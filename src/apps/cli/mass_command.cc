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
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/mass_build.h"
#include "apps/cli/mass_plan.h"
#include "apps/cli/mass_report.h"
#include "apps/cli/memory.h"
#include "apps/cli/progress.h"
#include "apps/cli/stopwatch.h"
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

// A footprint that gave no closed shell: an error, or a warning with --keep-going.
void report_failed_building(const MassOptions& options, const io::Footprint& footprint,
                            const BuildOutcome& built) {
  std::string message = feature_name(footprint) + ": no closed building could be made";
  if (!built.messages.empty()) message += ": " + built.messages.front();
  if (options.keep_going) {
    emit_warning("MAS005", options.input + ": warning[MAS005]: " + message, options.quiet);
  } else {
    std::fprintf(stderr, "%s: error: %s\n", options.input.c_str(), message.c_str());
  }
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

// Warnings and failures of the built buildings, in input order. Returns how many gave no closed
// building.
std::size_t account(const MassOptions& options, const io::FootprintSet& set,
                    const std::vector<BuildOutcome>& built, std::vector<Warning>& warnings) {
  std::size_t failed = 0;
  for (const BuildOutcome& b : built) {
    for (const std::string& m : b.messages)
      warnings.push_back({"MAS004", "building \"" + b.id + "\": " + m});
    if (!b.watertight) {
      ++failed;
      report_failed_building(options, set.footprints[b.feature], b);
    }
  }
  return failed;
}

void add_overlaps(const io::FootprintSet& set, const MassPlan& plan, MassReport& report) {
  report.overlaps = plan.overlap_summary.pairs;
  if (plan.overlap_summary.pairs > 0) {
    report.largest_overlap = {set.footprints[plan.overlap_summary.largest_first].id,
                              set.footprints[plan.overlap_summary.largest_second].id,
                              plan.overlap_summary.largest_area};
  }
}

// Fails the run when buildings failed without --keep-going or none was made; else 0.
int check_built(const MassOptions& options, std::size_t failed, std::size_t made,
                std::size_t total) {
  if (failed > 0 && !options.keep_going) {
    std::fprintf(
        stderr,
        "insula: %zu of %zu buildings failed; nothing written (--keep-going leaves them out)\n",
        failed, total);
    return kExitInput;
  }
  if (made == 0) {
    std::fprintf(stderr, "insula: error: no building could be made; nothing written\n");
    return kExitInput;
  }
  return 0;
}

void emit_mass_warnings(const MassOptions& options, const std::vector<Warning>& warnings,
                        MassReport& report) {
  for (const Warning& w : warnings) {
    emit_warning(w.code, options.input + ": warning[" + w.code + "]: " + w.text, options.quiet);
  }
  report.warnings = warning_total();
  report.warning_counts = warning_counts();
}

// The report, the commit point, and what a finished run prints.
int finish_mass(const MassOptions& options, MassReport& report, const Stopwatch& total,
                io::OutputTransaction& transaction) {
  report.total_seconds = total.seconds();
  if (!options.report.empty()) {
    if (const std::string error = transaction.write_text(options.report, report.json());
        !error.empty()) {
      return write_failure(error);
    }
  }
  if (const std::string error = transaction.commit(); !error.empty()) return write_failure(error);
  finish_warnings(options.quiet);
  if (!options.quiet) {
    std::fprintf(stderr, "insula: %zu buildings in %.2f s\n", report.buildings,
                 report.total_seconds);
  }
  for (const std::string& out : options.outputs) std::printf("%s\n", out.c_str());
  return kExitDone;
}

// Every output a 3D Tiles tileset: the city is built tile by tile and never held whole.
bool tiles_only(const std::vector<std::string>& outputs) {
  return std::all_of(outputs.begin(), outputs.end(), [](const std::string& out) {
    return io::output_format_name(out) == "3dtiles";
  });
}

// The 3D Tiles job (issue 17): the units are grouped into tiles by where they stand, and each tile
// is built (its units in parallel) and written before the next, so memory holds the footprints
// and the tiles in flight, never the city.
int run_mass_tiles(const MassOptions& options, const io::FootprintSet& set, const MassPlan& plan,
                   const std::vector<MassUnit>& units, std::vector<Warning>& warnings,
                   MassReport& report, const Stopwatch& total) {
  const Stopwatch build_clock;
  std::vector<io::TileItem> items;
  items.reserve(units.size());
  for (const MassUnit& unit : units) items.push_back(unit_tile_item(set, unit, options.overhang));
  io::OutputTransaction transaction(interrupted);
  std::vector<std::unique_ptr<io::TilesetWriter>> writers;
  for (const std::string& out : options.outputs) {
    if (const std::string error = transaction.claim_output(out); !error.empty()) {
      return write_failure(error);
    }
    writers.push_back(std::make_unique<io::TilesetWriter>(
        out, set.crs, set.origin, plan.materials, options.output.gltf, options.output.tiles));
    if (const std::string error = writers.back()->plan(items); !error.empty()) {
      return write_failure(error);
    }
  }
  const io::TilesetWriter& layout = *writers.front();
  std::vector<BuildOutcome> outcomes(units.size());
  std::vector<MassReport> tallies(layout.leaf_count());  // vertices, faces, triangles per tile
  std::vector<std::string> errors(layout.leaf_count());
  Progress progress("buildings", units.size(), options.quiet);
  tbb::parallel_for(std::size_t{0}, layout.leaf_count(), [&](std::size_t leaf) {
    if (interrupted()) return;
    const std::vector<std::size_t>& members = layout.leaf_items(leaf);
    std::vector<BuiltBuilding> built(members.size());
    tbb::parallel_for(std::size_t{0}, members.size(),
                      [&](std::size_t k) { built[k] = build_unit(set, plan, units[members[k]]); });
    std::vector<const shape::Building*> kept;
    for (BuiltBuilding& b : built) {
      if (!b.watertight && options.keep_going) continue;
      kept.push_back(&b.building);
      tallies[leaf].count_building(b.building, b.watertight);
    }
    for (const auto& writer : writers) {
      if (errors[leaf].empty()) errors[leaf] = writer->write_tile(leaf, kept);
    }
    for (std::size_t k = 0; k < members.size(); ++k) {
      std::string entry;
      if (options.report_buildings && (built[k].watertight || !options.keep_going)) {
        entry = building_entry(built[k].building);
      }
      outcomes[members[k]] = outcome_of(std::move(built[k]));
      outcomes[members[k]].entry = std::move(entry);
    }
    progress.advance(members.size());
  });
  if (const int code = stop_if_interrupted(); code != 0) return code;
  for (const std::string& error : errors) {
    if (!error.empty()) return write_failure(error);
  }
  const std::size_t failed = account(options, set, outcomes, warnings);
  for (const MassReport& tally : tallies) {
    report.buildings += tally.buildings;
    report.watertight += tally.watertight;
    report.parts += tally.parts;
    report.vertices += tally.vertices;
    report.faces += tally.faces;
    report.triangles += tally.triangles;
  }
  for (BuildOutcome& outcome : outcomes) {
    if (!outcome.entry.empty()) report.building_entries.push_back(std::move(outcome.entry));
  }
  if (const int code = check_built(options, failed, report.buildings, outcomes.size()); code != 0) {
    return code;
  }
  report.failed = failed;
  report.stage("build and write 3dtiles", build_clock.seconds());
  emit_mass_warnings(options, warnings, report);
  for (const auto& writer : writers) {
    if (const std::string error = writer->finish(); !error.empty()) return write_failure(error);
  }
  return finish_mass(options, report, total, transaction);
}

}  // namespace

int run_mass(const MassOptions& options) {
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
      options.input, geojson_options(options.crs, options.keep_going), options.quiet);
  if (!set) return kExitInput;
  report.stage("read", read_clock.seconds());
  release_free_memory();
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
  if (tiles_only(options.outputs)) {
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
