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
#include "apps/cli/footprint_input.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/mass_plan.h"
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

struct BuiltBuilding {
  shape::Building building;
  std::vector<std::string> messages;  // fallbacks and failures, reported in input order
  bool watertight = true;
  double top = 0;  // highest point built
};

void paint(const FootprintPlan& plan, kernel::Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    kernel::FaceTag& tag = mesh.tag(f);
    if (tag.semantic == kernel::SemanticClass::kWallSurface) {
      tag.material = plan.wall_material;
    } else if (tag.semantic == kernel::SemanticClass::kRoofSurface ||
               tag.semantic == kernel::SemanticClass::kOuterCeilingSurface) {
      tag.material = plan.roof_material;
    }
  }
}

BuiltBuilding build_one(const io::Footprint& footprint, const FootprintPlan& plan) {
  BuiltBuilding out;
  out.building.id = footprint.id;
  out.building.attributes = footprint.properties;
  kernel::RoofType built_roof = plan.spec.roof;
  for (std::size_t i = 0; i < footprint.polygons.size(); ++i) {
    kernel::MassResult mass = kernel::build_mass(footprint.polygons[i], plan.spec);
    if (!mass.message.empty()) out.messages.push_back(mass.message);
    built_roof = mass.roof;
    shape::Part part;
    part.name =
        footprint.polygons.size() == 1 ? footprint.id : footprint.id + "-part-" + std::to_string(i);
    part.kind = shape::PartKind::kBuildingPart;
    part.mesh = std::move(mass.mesh);
    paint(plan, part.mesh);
    // build_mass promises shared vertices, so the topological check needs no welding.
    out.watertight = out.watertight && !part.mesh.empty() && kernel::check(part.mesh).closed &&
                     kernel::volume(part.mesh) > 0;
    if (!part.mesh.empty()) out.top = std::max(out.top, part.mesh.bounds().max.z);
    out.building.parts.push_back(std::move(part));
  }
  add_form_attributes(plan.form, built_roof, out.top, out.building.attributes);
  return out;
}

// Builds every footprint in parallel; results land by index, so the output does not depend on the
// thread count. After an interruption the workers build nothing more (the caller checks).
std::vector<BuiltBuilding> build_all(const io::FootprintSet& set, const MassPlan& plan,
                                     bool quiet) {
  std::vector<BuiltBuilding> built(set.footprints.size());
  Progress progress("buildings", built.size(), quiet);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, built.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        if (interrupted()) return;
                        // An outline replaced by its building:part features is not built.
                        if (plan.footprints[i].replaced) continue;
                        built[i] = build_one(set.footprints[i], plan.footprints[i]);
                      }
                      progress.advance(range.size());
                    });
  return built;
}

// A building of the scene and the feature it came from (an outline, for joined parts).
struct Assembled {
  BuiltBuilding built;
  std::size_t feature = 0;
};

// S3DB: the building:part features of a replaced outline become the parts of one building named
// after the outline, with its properties; every other footprint is a building of its own.
std::vector<Assembled> assemble(const io::FootprintSet& set, const MassPlan& plan,
                                std::vector<BuiltBuilding>& built) {
  std::vector<std::vector<std::size_t>> parts_of(built.size());
  for (std::size_t i = 0; i < built.size(); ++i) {
    if (plan.footprints[i].outline) parts_of[*plan.footprints[i].outline].push_back(i);
  }
  std::vector<Assembled> out;
  for (std::size_t i = 0; i < built.size(); ++i) {
    if (plan.footprints[i].outline) continue;
    if (!plan.footprints[i].replaced) {
      out.push_back({std::move(built[i]), i});
      continue;
    }
    Assembled joined;
    joined.feature = i;
    joined.built.building.id = set.footprints[i].id;
    joined.built.building.attributes = set.footprints[i].properties;
    for (const std::size_t p : parts_of[i]) {
      BuiltBuilding& part = built[p];
      joined.built.watertight = joined.built.watertight && part.watertight;
      joined.built.top = std::max(joined.built.top, part.top);
      for (std::string& m : part.messages) {
        joined.built.messages.push_back("part \"" + part.building.id + "\": " + m);
      }
      for (shape::Part& mesh_part : part.building.parts) {
        mesh_part.attributes = part.building.attributes;
        joined.built.building.parts.push_back(std::move(mesh_part));
      }
    }
    joined.built.building.attributes["insula:height"] = joined.built.top;
    out.push_back(std::move(joined));
  }
  return out;
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
  std::vector<BuiltBuilding> built = build_all(set.value(), plan, options.quiet);
  if (const int code = stop_if_interrupted(); code != 0) return code;
  shape::Scene scene;
  scene.origin = set->origin;
  scene.crs = set->crs;
  scene.materials = plan.materials;
  std::vector<Assembled> buildings = assemble(set.value(), plan, built);
  scene.buildings.reserve(buildings.size());
  std::size_t failed = 0;
  for (Assembled& a : buildings) {
    BuiltBuilding& b = a.built;
    for (std::string& m : b.messages)
      warnings.push_back({"MAS004", "building \"" + b.building.id + "\": " + m});
    if (!b.watertight) {
      ++failed;
      report_failed_building(options, set->footprints[a.feature], b);
      if (options.keep_going) continue;
    }
    report.count_building(b.building, b.watertight);
    if (options.report_buildings) report.describe_building(b.building);
    scene.buildings.push_back(std::move(b.building));
  }
  report.overlaps = plan.overlap_summary.pairs;
  if (plan.overlap_summary.pairs > 0) {
    report.largest_overlap = {set->footprints[plan.overlap_summary.largest_first].id,
                              set->footprints[plan.overlap_summary.largest_second].id,
                              plan.overlap_summary.largest_area};
  }
  if (failed > 0 && !options.keep_going) {
    std::fprintf(
        stderr,
        "insula: %zu of %zu buildings failed; nothing written (--keep-going leaves them out)\n",
        failed, buildings.size());
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
