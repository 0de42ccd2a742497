// `insula random` (seed 000, §4.3 "a number of structures to be built can be provided to trigger
// the generation of stochastic-based virtual buildings"; "a building configuration (L-shaped,
// U-shaped, or fully convex) along with a rooms' list"). For building i of a batch:
// random_building(spec, batch_seed(seed, i)) -> print_building -> DIR/NAME.bldg, then the same
// pipeline as `insula build DIR/NAME.bldg -o DIR/NAME.glb --report DIR/NAME.json`, so the .glb is
// exactly what rebuilding the (editable) grammar gives. The per-building report leaves out the
// wall-clock `seconds`, so the same seed gives the same bytes in all three files.
#include "apps/cli/random_command.h"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/input_file.h"
#include "apps/cli/stopwatch.h"
#include "io/atomic_file.h"
#include "lang/bldg/printer.h"
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
  const RandomOptions& options;
  lang::bldg::RandomSpec spec;
  std::filesystem::path dir;
  std::mutex mutex;  // stderr and the totals
  std::size_t vertices = 0;
  int failures = 0;
};

// Removes the timings from the report written by the build and records the generation inputs.
bool finish_report(const std::filesystem::path& path, std::uint64_t seed, const Batch& batch,
                   std::size_t& vertices, std::string& error) {
  const auto text = read_input_file(path.string());
  if (!text) {
    error = path.string() + ": cannot read the report";
    return false;
  }
  nlohmann::json report = nlohmann::json::parse(*text, nullptr, false);
  if (report.is_discarded()) {
    error = path.string() + ": the report is not JSON";
    return false;
  }
  report.erase("seconds");
  report["input"] = path.stem().string() + ".bldg";  // not the folder: same seed, same bytes
  report["random"] = {{"seed", seed},
                      {"shape", lang::bldg::random_shape_name(batch.spec.shape)},
                      {"parts", batch.spec.parts},
                      {"rooms", {batch.spec.rooms_min, batch.spec.rooms_max}}};
  vertices = report.value("vertices", std::size_t{0});
  error = io::write_file_atomically(path, report.dump(2) + "\n");
  return error.empty();
}

void make_one(Batch& batch, int index) {
  const std::string name = building_name(index, batch.options.count);
  lang::bldg::RandomSpec spec = batch.spec;
  spec.name = name;
  const std::uint64_t seed =
      lang::bldg::batch_seed(batch.options.seed, static_cast<std::uint64_t>(index));
  const lang::bldg::Building building = lang::bldg::random_building(spec, seed);
  const std::filesystem::path grammar = batch.dir / (name + ".bldg");
  std::string error = io::write_file_atomically(grammar, lang::bldg::print_building(building));
  BuildOptions build;
  build.input = grammar.string();
  build.outputs = {(batch.dir / (name + ".glb")).string()};
  build.report = (batch.dir / (name + ".json")).string();
  build.quiet = true;
  std::size_t vertices = 0;
  if (error.empty() && build_bldg(build) != kExitDone) {
    error = grammar.string() + ": the generated building failed to build (grammar kept)";
  }
  if (error.empty()) finish_report(build.report, seed, batch, vertices, error);
  const std::lock_guard<std::mutex> lock(batch.mutex);
  if (!error.empty()) {
    std::fprintf(stderr, "insula: error: %s\n", error.c_str());
    ++batch.failures;
  }
  batch.vertices += vertices;
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
  random->add_option("--room-list", options.room_list,
                     "the room program, comma-separated types (kitchen,bedroom,...)");
  random->add_option("-o,--output", options.output_dir, "output folder")->required();
  random->add_option("--threads", options.threads, "worker threads (0 = all cores)")
      ->check(CLI::Range(0, 256));
  random->add_flag("-q,--quiet", options.quiet, "no summary line");
}

int run_random(const RandomOptions& options) {
  const Stopwatch total;
  Batch batch{options, {}, options.output_dir, {}, 0, 0};
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
  std::atomic<int> next{0};
  const auto work = [&] {
    for (int i = next++; i < options.count; i = next++) make_one(batch, i);
  };
  // Each build lists the files it wrote on stdout (finish_build, as `insula build` does); the
  // batch prints its own summary instead, so stdout is parked on /dev/null meanwhile.
  std::fflush(stdout);
  const int saved_stdout = dup(STDOUT_FILENO);
  const int null_fd = open("/dev/null", O_WRONLY);
  if (saved_stdout >= 0 && null_fd >= 0) dup2(null_fd, STDOUT_FILENO);
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  std::fflush(stdout);
  if (saved_stdout >= 0 && null_fd >= 0) dup2(saved_stdout, STDOUT_FILENO);
  if (saved_stdout >= 0) close(saved_stdout);
  if (null_fd >= 0) close(null_fd);
  if (!options.quiet) {
    const double seconds = total.seconds();
    std::printf("%s: %d buildings (%d failed), %zu vertices, %.3f s (%.1f ms per building)\n",
                options.output_dir.c_str(), options.count, batch.failures, batch.vertices, seconds,
                1000 * seconds / options.count);
  }
  return batch.failures == 0 ? kExitDone : kExitInput;
}

}  // namespace insula::cli
