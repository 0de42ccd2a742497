#include "apps/cli/mass_report.h"

#include <nlohmann/json.hpp>

#include "apps/cli/mass_plan.h"

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

std::string building_entry(const shape::Building& building) {
  nlohmann::ordered_json entry;
  entry["id"] = building.id;
  const auto attribute = [&](const shape::AttributeMap& attributes, const char* key) {
    auto it = attributes.find(key);
    if (it == attributes.end()) return nlohmann::ordered_json();
    if (const double* d = std::get_if<double>(&it->second)) return nlohmann::ordered_json(*d);
    return nlohmann::ordered_json(shape::to_string(it->second));
  };
  const auto describe = [&](const shape::AttributeMap& attributes, nlohmann::ordered_json& out) {
    for (const char* key : kFormAttributes) {
      nlohmann::ordered_json value = attribute(attributes, key);
      if (!value.is_null()) out[std::string(key).substr(7)] = value;
    }
  };
  describe(building.attributes, entry);
  // Parts joined from building:part features carry their own sources.
  nlohmann::ordered_json joined = nlohmann::ordered_json::array();
  for (const shape::Part& part : building.parts) {
    if (part.attributes.count("insula:height") == 0) continue;
    nlohmann::ordered_json p;
    p["name"] = part.name;
    describe(part.attributes, p);
    joined.push_back(std::move(p));
  }
  if (!joined.empty()) entry["parts"] = std::move(joined);
  return entry.dump();
}

nlohmann::json MassReport::counts() const {
  return {buildings, watertight, parts, vertices, faces, triangles};
}

void MassReport::add_counts(const nlohmann::json& counts) {
  buildings += counts[0].get<std::size_t>();
  watertight += counts[1].get<std::size_t>();
  parts += counts[2].get<std::size_t>();
  vertices += counts[3].get<std::size_t>();
  faces += counts[4].get<std::size_t>();
  triangles += counts[5].get<std::size_t>();
}

void MassReport::describe_building(const shape::Building& building) {
  building_entries.push_back(building_entry(building));
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
  out["invalid"] = invalid;
  out["not_buildings"] = not_buildings;
  out["invalid_by_code"] = invalid_by_code;
  out["repairs"] = repairs;
  out["overlaps"] = overlaps;
  if (largest_overlap) {
    out["largest_overlap"] = {{"first", largest_overlap->first},
                              {"second", largest_overlap->second},
                              {"area", largest_overlap->area}};
  }
  out["crs"] = crs.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(crs);
  if (!source_crs.empty()) out["reprojected_from"] = source_crs;
  out["threads"] = threads;
  out["ranks"] = ranks;
  if (!tiles_by_rank.empty()) out["tiles_by_rank"] = tiles_by_rank;
  out["seconds"] = seconds;
  if (!building_entries.empty()) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const std::string& entry : building_entries) {
      list.push_back(nlohmann::ordered_json::parse(entry));
    }
    out["buildings_made"] = std::move(list);
  }
  return out.dump(2) + "\n";
}

}  // namespace insula::cli
