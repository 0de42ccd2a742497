// The JSON report of `insula mass`: counts and timings per stage (issue 2, "The first job").
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "shape/scene.h"

namespace insula::cli {

struct MassReport {
  std::size_t buildings = 0;
  std::size_t parts = 0;
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t triangles = 0;
  std::size_t watertight = 0;  // buildings whose every part is a closed, outward shell
  std::size_t warnings = 0;
  std::map<std::string, std::size_t> warning_counts;  // by code: the full count, printed or not
  std::size_t failed = 0;                             // footprints left out with --keep-going
  int threads = 1;
  double total_seconds = 0;
  std::vector<std::pair<std::string, double>> stages;  // in execution order

  void stage(std::string name, double seconds) { stages.emplace_back(std::move(name), seconds); }
  void count_building(const shape::Building& building, bool is_watertight);
  std::string json() const;
};

}  // namespace insula::cli
