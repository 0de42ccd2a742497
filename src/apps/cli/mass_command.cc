#include "apps/cli/mass_command.h"

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>

#include "apps/cli/build_command.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/mass_report.h"
#include "apps/cli/progress.h"
#include "apps/cli/stopwatch.h"
#include "apps/cli/validators.h"
#include "apps/cli/view_options.h"
#include "apps/cli/warnings.h"
#include "base/diagnostic.h"
#include "io/geojson_reader.h"
#include "io/output.h"
#include "kernel/mass.h"
#include "shape/scene.h"

namespace insula::cli {
namespace {

const std::vector<std::string> kRoofNames = {
    "flat",    "shed",        "gable",   "hip",   "pyramid", "mansard", "holed_mansard",
    "gambrel", "half_hipped", "saltbox", "round", "dome",    "onion"};

// What one footprint becomes, decided before the parallel build so warnings stay in input order.
struct BuildingPlan {
  kernel::MassSpec spec;
};

std::optional<double> number_property(const shape::AttributeMap& properties,
                                      const std::string& name) {
  auto it = properties.find(name);
  if (it == properties.end()) return std::nullopt;
  if (const double* d = std::get_if<double>(&it->second)) return *d;
  if (const std::string* s = std::get_if<std::string>(&it->second)) {
    char* end = nullptr;
    const double d = std::strtod(s->c_str(), &end);
    if (end != s->c_str() && *end == '\0') return d;
  }
  return std::nullopt;
}

// A warning of the mass stage: its code (docs/cli.md, "Warnings") and its text.
struct Warning {
  std::string code;
  std::string text;
};

std::string feature_name(const io::Footprint& footprint) {
  return "feature " + std::to_string(footprint.feature_index) + " (id \"" + footprint.id + "\")";
}

double plan_height(const MassOptions& options, const io::Footprint& footprint,
                   std::vector<Warning>& warnings) {
  if (options.height) return *options.height;
  const std::optional<double> h = number_property(footprint.properties, options.height_attr);
  if (h && std::isfinite(*h) && *h > 0 && *h < 1000) return *h;
  const bool present = footprint.properties.count(options.height_attr) > 0;
  warnings.push_back(
      {present ? "MAS002" : "MAS001",
       feature_name(footprint) + ": " +
           (present ? "property '" + options.height_attr + "' is not a height in (0, 1000) m"
                    : "no '" + options.height_attr + "' property") +
           "; using " + shape::to_string(options.default_height) + " m"});
  return options.default_height;
}

kernel::RoofType plan_roof(const MassOptions& options, const io::Footprint& footprint,
                           std::vector<Warning>& warnings) {
  if (!options.roof_given) {
    auto it = footprint.properties.find("roof");
    if (it != footprint.properties.end()) {
      const std::string name = shape::to_string(it->second);
      if (std::optional<kernel::RoofType> known = kernel::roof_type_from_name(name)) return *known;
      warnings.push_back({"MAS003", feature_name(footprint) + ": unknown roof '" + name +
                                        "'; using " + options.roof});
    }
  }
  return kernel::roof_type_from_name(options.roof).value_or(kernel::RoofType::kHip);
}

double plan_pitch(const MassOptions& options, const io::Footprint& footprint) {
  if (!options.pitch_given) {
    const std::optional<double> p = number_property(footprint.properties, "pitch");
    if (p && *p > 0 && *p < 89) return *p;
  }
  return options.pitch_deg;
}

std::vector<BuildingPlan> plan_buildings(const MassOptions& options, const io::FootprintSet& set,
                                         std::vector<Warning>& warnings) {
  std::vector<BuildingPlan> plans;
  plans.reserve(set.footprints.size());
  for (const io::Footprint& footprint : set.footprints) {
    BuildingPlan plan;
    plan.spec.wall_height = plan_height(options, footprint, warnings);
    plan.spec.roof = plan_roof(options, footprint, warnings);
    plan.spec.pitch_deg = plan_pitch(options, footprint);
    plan.spec.overhang = options.overhang;
    plans.push_back(plan);
  }
  return plans;
}

struct BuiltBuilding {
  shape::Building building;
  std::vector<std::string> messages;  // fallbacks and failures, reported in input order
  bool watertight = true;
};

BuiltBuilding build_one(const io::Footprint& footprint, const BuildingPlan& plan) {
  BuiltBuilding out;
  out.building.id = footprint.id;
  out.building.attributes = footprint.properties;
  for (std::size_t i = 0; i < footprint.polygons.size(); ++i) {
    kernel::MassResult mass = kernel::build_mass(footprint.polygons[i], plan.spec);
    if (!mass.message.empty()) out.messages.push_back(mass.message);
    shape::Part part;
    part.name =
        footprint.polygons.size() == 1 ? footprint.id : footprint.id + "-part-" + std::to_string(i);
    part.kind = shape::PartKind::kBuildingPart;
    part.mesh = std::move(mass.mesh);
    // build_mass promises shared vertices, so the topological check needs no welding.
    out.watertight = out.watertight && !part.mesh.empty() && kernel::check(part.mesh).closed &&
                     kernel::volume(part.mesh) > 0;
    out.building.parts.push_back(std::move(part));
  }
  return out;
}

// Builds every footprint in parallel; results land by index, so the output does not depend on the
// thread count. After an interruption the workers build nothing more (the caller checks).
std::vector<BuiltBuilding> build_all(const io::FootprintSet& set,
                                     const std::vector<BuildingPlan>& plans, bool quiet) {
  std::vector<BuiltBuilding> built(set.footprints.size());
  Progress progress("buildings", built.size(), quiet);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, built.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        if (interrupted()) return;
                        built[i] = build_one(set.footprints[i], plans[i]);
                      }
                      progress.advance(range.size());
                    });
  return built;
}

// A footprint that gave no closed shell: an error, or a warning with --keep-going.
void report_failed_building(const MassOptions& options, const io::Footprint& footprint,
                            const BuiltBuilding& built) {
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
  mass->add_option(
          "-o,--output", options.outputs,
          "output file, format by extension (.obj .glb .gltf .city.json .svg .png); repeatable")
      ->required();
  auto* roof =
      mass->add_option("--roof", options.roof,
                       "roof type: flat, shed, gable, hip, pyramid, mansard, holed_mansard "
                       "(default hip; else the feature's 'roof' property)")
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
                   "feature property holding the wall height (default 'height')")
      ->excludes(height);
  mass->add_option("--default-height", options.default_height,
                   "wall height when a feature has no usable height (default 10)")
      ->check(finite_range(0.5, 1000.0));
  mass->add_option("--report", options.report, "write a JSON report (counts, timings)");
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
  const std::optional<std::string> text = read_input_or_report(options.input);
  if (!text) return kExitInput;
  const base::Source source(options.input, *text);
  base::Result<io::FootprintSet> set = io::read_geojson(
      source.text(), options.input, geojson_options(options.crs, options.keep_going));
  print_diagnostics(set.diagnostics(), source, options.quiet);
  if (!set.ok()) return kExitInput;
  report.stage("read", read_clock.seconds());
  report.invalid = set->skipped_invalid;
  report.crs = set->crs;
  report.source_crs = set->source_crs;

  Stopwatch build_clock;
  std::vector<Warning> warnings;
  const std::vector<BuildingPlan> plans = plan_buildings(options, set.value(), warnings);
  std::vector<BuiltBuilding> built = build_all(set.value(), plans, options.quiet);
  if (const int code = stop_if_interrupted(); code != 0) return code;
  shape::Scene scene;
  scene.origin = set->origin;
  scene.crs = set->crs;
  scene.buildings.reserve(built.size());
  std::size_t failed = 0;
  for (std::size_t i = 0; i < built.size(); ++i) {
    BuiltBuilding& b = built[i];
    for (std::string& m : b.messages)
      warnings.push_back({"MAS004", "building \"" + b.building.id + "\": " + m});
    if (!b.watertight) {
      ++failed;
      report_failed_building(options, set->footprints[i], b);
      if (options.keep_going) continue;
    }
    report.count_building(b.building, b.watertight);
    scene.buildings.push_back(std::move(b.building));
  }
  if (failed > 0 && !options.keep_going) {
    std::fprintf(
        stderr,
        "insula: %zu of %zu buildings failed; nothing written (--keep-going leaves them out)\n",
        failed, built.size());
    return kExitInput;
  }
  if (scene.buildings.empty()) {
    std::fprintf(stderr, "insula: error: no building could be made; nothing written\n");
    return kExitInput;
  }
  report.failed = failed;
  report.stage("build", build_clock.seconds());
  for (const Warning& w : warnings) {
    emit_warning(w.code, options.input + ": warning[" + w.code + "]: " + w.text, options.quiet);
  }
  report.warnings = warning_total();
  report.warning_counts = warning_counts();

  io::OutputTransaction transaction(interrupted);
  for (const std::string& out : options.outputs) {
    const Stopwatch write_clock;
    if (const std::string error = transaction.write_scene(scene, out, options.output);
        !error.empty()) {
      return write_failure(error);
    }
    report.stage("write " + io::output_format_name(out), write_clock.seconds());
  }
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
    std::fprintf(stderr, "insula: %zu buildings in %.2f s\n", scene.buildings.size(),
                 report.total_seconds);
  }
  for (const std::string& out : options.outputs) std::printf("%s\n", out.c_str());
  return kExitDone;
}

}  // namespace insula::cli
