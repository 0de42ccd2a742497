// The JSON report of `insula mass`: counts and timings per stage (issue 2, "The first job").
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

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
  std::size_t failed = 0;         // footprints left out with --keep-going: no closed building
  std::size_t invalid = 0;        // features left out with --keep-going: invalid geometry
  std::size_t not_buildings = 0;  // map areas left out (io/map_areas.h: landuse=...)
  std::map<std::string, std::size_t> invalid_by_code;  // why, by the reader's error code
  std::map<std::string, std::size_t> repairs;          // rings repaired, by kind (docs/geojson.md)
  std::size_t overlaps = 0;  // pairs of footprints drawn over each other (mass_plan.h)
  struct LargestOverlap {
    std::string first, second;  // building ids
    double area = 0;            // square meters
  };
  std::optional<LargestOverlap> largest_overlap;
  std::vector<std::string> building_entries;  // JSON objects, with --report-buildings
  std::string crs;         // the CRS of the outputs' world coordinates; empty: unknown
  std::string source_crs;  // the input's CRS when it was reprojected
  int threads = 1;
  int ranks = 1;                           // processes under mpirun (docs/cluster.md)
  std::vector<std::size_t> tiles_by_rank;  // 3D Tiles job: how many tiles each rank built
  double total_seconds = 0;
  std::vector<std::pair<std::string, double>> stages;  // in execution order

  void stage(std::string name, double seconds) { stages.emplace_back(std::move(name), seconds); }
  void count_building(const shape::Building& building, bool is_watertight);
  // The building, watertight, part, vertex, face and triangle counts, as a tile job's tally
  // (tile_job.h), and their sum back.
  nlohmann::json counts() const;
  void add_counts(const nlohmann::json& counts);
  // Adds the building's id, parts and insula:* attributes (mass_plan.h) as a report entry.
  void describe_building(const shape::Building& building);
  std::string json() const;
};

// A building's report entry (JSON): its id, parts and insula:* attributes (mass_plan.h).
std::string building_entry(const shape::Building& building);

}  // namespace insula::cli
