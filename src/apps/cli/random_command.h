// `insula random --count N --seed S [--shape L|U|T|H|convex] [--parts P] [--rooms MIN-MAX]
// [--room-list kitchen,bedroom,...] -o DIR` (seed 000, §4.3): stochastic buildings, each written
// as DIR/NAME.bldg (editable grammar), DIR/NAME.glb and DIR/NAME.json.
#pragma once

#include <cstdint>
#include <string>

namespace CLI {
class App;
}

namespace insula::cli {

struct RandomOptions {
  int count = 1;
  std::uint64_t seed = 0;
  std::string shape = "convex";  // L, U, T, H, convex
  int parts = 0;                 // 0 = random
  std::string rooms;             // "MIN-MAX" rooms per part
  std::string room_list;         // comma-separated room types
  std::string output_dir;
  std::string report;  // --report R.json: the batch's counts and timings
  int threads = 0;
  bool quiet = false;
};

void add_random_command(CLI::App& app, RandomOptions& options);
int run_random(const RandomOptions& options);

}  // namespace insula::cli
