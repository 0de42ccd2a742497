// `insula random` (seed 000, §4.3 "a number of structures to be built can be provided to trigger
// the generation of stochastic-based virtual buildings"; "a building configuration (L-shaped,
// U-shaped, or fully convex) along with a rooms' list"). For building i of a batch:
// random_building(spec, batch_seed(seed, i)) -> print_building -> DIR/NAME.bldg, then the same
// pipeline as `insula build DIR/NAME.bldg -o DIR/NAME.glb --report DIR/NAME.json`, so the .glb is
// exactly what rebuilding the (editable) grammar gives. The per-building report leaves out the
// wall-clock `seconds`, so the same seed gives the same bytes in all three files; --report gives
// the batch's timings. All files of a batch are one output transaction.
#include "apps/cli/random_command.h"

#include <CLI/CLI.hpp>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/progress.h"
#include "apps/cli/stopwatch.h"
#include "apps/cli/warnings.h"
#include "io/output.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/printer.h"
#include "lang/bldg/restrictions.h"
#include "lang/bldg/stochastic.h"

namespace insula::cli {
namespace {

// "MIN-MAX" or "N", 1 <= MIN <= MAX <= 200.
bool parse_rooms(const std::string& text, int& lo, int& hi) {
  const auto number = [](const std::string& s, int& out) {
    if (s.empty() || s.size() > 4) return false;
    for (const char c : s) {
      if (c < '0' || c > '9') return false;
    }
    out = std::stoi(s);
    return true;
  };
  const std::size_t dash = text.find('-');
  if (dash == std::string::npos) {
    if (!number(text, lo)) return false;
    hi = lo;
  } else if (!number(text.substr(0, dash), lo) || !number(text.substr(dash + 1), hi)) {
    return false;
  }
  return lo >= 1 && lo <= hi && hi <= 200;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::string item;
  const auto flush = [&] {
    const std::size_t b = item.find_first_not_of(' ');
    const std::size_t e = item.find_last_not_of(' ');
    if (b != std::string::npos) out.push_back(item.substr(b, e - b + 1));
    item.clear();
  };
  for (const char c : text) {
    if (c == ',') {
      flush();
    } else {
      item += c;
    }
  }
  flush();
  return out;
}

std::string building_name(int index, int count) {
  std::string digits = std::to_string(index);
  const std::size_t width = std::max<std::size_t>(3, std::to_string(count - 1).size());
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  return "building_" + digits;
}

struct Batch {
  explicit Batch(const RandomOptions& given)
      : options(given),
        dir(given.output_dir),
        progress("buildings", static_cast<std::size_t>(given.count), given.quiet) {}

  const RandomOptions& options;
  lang::bldg::RandomSpec spec;
  std::filesystem::path dir;
  io::OutputTransaction transaction{interrupted};  // every file of the batch
  Progress progress;
  std::mutex mutex;  // stderr and the totals
  std::size_t vertices = 0;
  int failures = 0;
  double generate_seconds = 0;  // summed over the workers
  double build_seconds = 0;
};

void fit_windows(lang::bldg::Division& division, const std::map<std::string, int>& placed) {
  if (division.room) {
    const auto it = placed.find(division.symbol);
    division.room->windows = std::min(division.room->windows, it == placed.end() ? 0 : it->second);
  }
  for (lang::bldg::Division& child : division.children) fit_windows(child, placed);
}

void fit_windows(lang::bldg::PartNode& node, const std::map<std::string, int>& placed) {
  if (node.part) {
    for (lang::bldg::Floor& floor : node.part->floors) fit_windows(floor.layout, placed);
  }
  for (lang::bldg::PartNode& child : node.children) fit_windows(child, placed);
}

// The generator gives windows to rooms by its own room rectangles, but the floor planner (§3.4)
// lays the rooms out anew and can leave a room it saw on the outline without open-air wall (a
// middle room of glued parts): the grammar then asked for windows that cannot be placed, and
// building it warned (the documented village printed 12 such warnings). Each room asks for the
// windows the default plan places, so the written grammar builds without them.
void fit_windows_to_plan(lang::bldg::Building& building) {
  const base::Result<lang::bldg::FloorPlan> plan =
      lang::bldg::make_floor_plan(building, lang::bldg::Restrictions{});
  if (!plan.ok()) return;  // the build reports it
  std::map<std::string, int> placed;
  for (const lang::bldg::PlanStorey& storey : plan->storeys) {
    for (const lang::bldg::PlanWindow& w : storey.windows) {
      if (w.symbol.empty()) ++placed[storey.rooms[static_cast<std::size_t>(w.room)].symbol];
    }
  }
  fit_windows(building.layout, placed);
}

// The build's report without its timings (same seed, same bytes) and with the generation inputs.
void amend_report(nlohmann::json& report, const std::filesystem::path& grammar, std::uint64_t seed,
                  const Batch& batch) {
  report.erase("seconds");
  report["input"] = grammar.filename().string();  // not the folder: same seed, same bytes
  report["random"] = {{"seed", seed},
                      {"shape", lang::bldg::random_shape_name(batch.spec.shape)},
                      {"parts", batch.spec.parts},
                      {"rooms", {batch.spec.rooms_min, batch.spec.rooms_max}}};
}

void make_one(Batch& batch, int index) {
  const std::string name = building_name(index, batch.options.count);
  const Stopwatch generate_clock;
  lang::bldg::RandomSpec spec = batch.spec;
  spec.name = name;
  const std::uint64_t seed =
      lang::bldg::batch_seed(batch.options.seed, static_cast<std::uint64_t>(index));
  lang::bldg::Building building = lang::bldg::random_building(spec, seed);
  fit_windows_to_plan(building);
  const std::filesystem::path grammar = batch.dir / (name + ".bldg");
  std::string error =
      batch.transaction.write_text(grammar.string(), lang::bldg::print_building(building));
  const double generate_seconds = generate_clock.seconds();
  const Stopwatch build_clock;
  BuildOptions build;
  build.input = grammar.string();
  build.outputs = {(batch.dir / (name + ".glb")).string()};
  build.report = (batch.dir / (name + ".json")).string();
  build.quiet = true;
  build.transaction = &batch.transaction;
  std::size_t vertices = 0;
  build.amend_report = [&](nlohmann::json& report) {
    amend_report(report, grammar, seed, batch);
    vertices = report.value("vertices", std::size_t{0});
  };
  if (error.empty() && build_bldg(build) != kExitDone && !interrupted()) {
    error = grammar.string() + ": the generated building failed to build (grammar kept)";
  }
  batch.progress.advance();
  const std::lock_guard<std::mutex> lock(batch.mutex);
  batch.generate_seconds += generate_seconds;
  batch.build_seconds += build_clock.seconds();
  if (!error.empty() && !interrupted()) {
    clear_progress_line();
    std::fprintf(stderr, "insula: error: %s\n", error.c_str());
    ++batch.failures;
  }
  batch.vertices += vertices;
}

// --report: the batch's counts and timings (the per-building reports have none, so that the same
// seed gives the same bytes).
std::string batch_report(const Batch& batch, int threads, double total_seconds) {
  nlohmann::ordered_json report;
  report["count"] = batch.options.count;
  report["failed"] = batch.failures;
  report["seed"] = batch.options.seed;
  report["shape"] = lang::bldg::random_shape_name(batch.spec.shape);
  report["vertices"] = batch.vertices;
  report["threads"] = threads;
  report["warning_counts"] = warning_counts();
  report["seconds"] = {{"total", total_seconds},
                       {"generate", batch.generate_seconds},
                       {"build", batch.build_seconds}};
  return report.dump(2) + "\n";
}

// Every building by the workers, then the report, then the commit: an interruption at any moment
// leaves the folder as it was.
int run_batch(Batch& batch, int threads, const Stopwatch& total) {
  std::atomic<int> next{0};
  const auto work = [&] {
    for (int i = next++; i < batch.options.count && !interrupted(); i = next++) make_one(batch, i);
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  batch.progress.finish();
  if (const int code = stop_if_interrupted(); code != 0) return code;
  if (!batch.options.report.empty()) {
    const std::string error = batch.transaction.write_text(
        batch.options.report, batch_report(batch, threads, total.seconds()));
    if (!error.empty()) return write_failure(error);
  }
  if (const std::string error = batch.transaction.commit(); !error.empty()) {
    return write_failure(error);
  }
  return batch.failures == 0 ? kExitDone : kExitInput;
}

}  // namespace

void add_random_command(CLI::App& app, RandomOptions& options) {
  CLI::App* random = app.add_subcommand("random", "stochastic traversable buildings (seed 000)");
  random->add_option("--count", options.count, "how many buildings")->check(CLI::Range(1, 100000));
  random->add_option("--seed", options.seed, "random seed (same seed, same files)");
  random->add_option("--shape", options.shape, "L, U, T, H or convex")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            lang::bldg::RandomShape shape{};
            return lang::bldg::parse_random_shape(text, shape)
                       ? std::string()
                       : "unknown shape '" + text + "' (L, U, T, H or convex)";
          },
          "SHAPE"));
  random->add_option("--parts", options.parts, "building parts (0 = random)")
      ->check(CLI::Range(0, 24));
  auto* rooms =
      random->add_option("--rooms", options.rooms, "rooms per part, MIN-MAX (default 3-7)")
          ->check(CLI::Validator(
              [](std::string& text) -> std::string {
                int lo = 0, hi = 0;
                return parse_rooms(text, lo, hi) ? std::string()
                                                 : "expected MIN-MAX rooms with 1 <= MIN <= MAX <= "
                                                   "200, found '" +
                                                       text + "'";
              },
              "MIN-MAX"));
  // The list fixes the rooms (one per entry, repeated when a part needs more), so a range given
  // with it could only be ignored: the two exclude each other (docs/cli.md).
  random
      ->add_option(
          "--room-list", options.room_list,
          "the room program, comma-separated types (kitchen,bedroom,...); excludes --rooms")
      ->excludes(rooms);
  random->add_option("--report", options.report,
                     "write a JSON report of the batch (counts, timings)");
  random->add_option("-o,--output", options.output_dir, "output folder")->required();
  random->add_option("--threads", options.threads, "worker threads (0 = all cores)")
      ->check(CLI::Range(0, 256));
  random->add_flag("-q,--quiet", options.quiet, "no progress or summary line");
}

int run_random(const RandomOptions& options) {
  const Stopwatch total;
  if (!options.report.empty()) {
    if (const int code = check_outputs({}, options.report, {}); code != kExitDone) return code;
  }
  Batch batch(options);
  lang::bldg::parse_random_shape(options.shape, batch.spec.shape);
  batch.spec.parts = options.parts;
  if (!options.rooms.empty())
    parse_rooms(options.rooms, batch.spec.rooms_min, batch.spec.rooms_max);
  batch.spec.room_types = split_list(options.room_list);
  std::error_code ec;
  std::filesystem::create_directories(batch.dir, ec);
  if (!std::filesystem::is_directory(batch.dir)) {
    std::fprintf(stderr, "insula: error: %s: cannot create the output folder\n",
                 options.output_dir.c_str());
    return kExitInput;
  }
  const unsigned cores = std::max(1U, std::thread::hardware_concurrency());
  const int threads =
      std::min(options.count, options.threads > 0 ? options.threads : static_cast<int>(cores));
  const int code = run_batch(batch, threads, total);
  if (code != kExitDone && code != kExitInput) return code;
  if (!options.quiet) {
    const double seconds = total.seconds();
    std::printf("%s: %d buildings (%d failed), %zu vertices, %.3f s (%.1f ms per building)\n",
                options.output_dir.c_str(), options.count, batch.failures, batch.vertices, seconds,
                1000 * seconds / options.count);
  }
  return code;
}

}  // namespace insula::cli
