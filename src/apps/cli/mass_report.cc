#include "apps/cli/mass_report.h"

#include <nlohmann/json.hpp>

namespace insula::cli {

void MassReport::count_building(const shape::Building& building, bool is_watertight) {
  ++buildings;
  watertight += is_watertight ? 1 : 0;
  for (const shape::Part& part : building.parts) {
    ++parts;
    vertices += part.mesh.vertex_count();
    faces += part.mesh.face_count();
    triangles += part.mesh.triangle_count();
  }
}

std::string MassReport::json() const {
  nlohmann::ordered_json seconds;
  seconds["total"] = total_seconds;
  for (const auto& [name, value] : stages) seconds[name] = value;
  nlohmann::ordered_json out;
  out["buildings"] = buildings;
  out["parts"] = parts;
  out["vertices"] = vertices;
  out["faces"] = faces;
  out["triangles"] = triangles;
  out["watertight"] = watertight;
  out["warnings"] = warnings;
  out["warning_counts"] = warning_counts;
  out["failed"] = failed;
  out["threads"] = threads;
  out["seconds"] = seconds;
  return out.dump(2) + "\n";
}

}  // namespace insula::cli
