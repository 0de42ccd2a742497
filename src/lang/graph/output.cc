#include "lang/graph/output.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "kernel/heightfield.h"
#include "lang/graph/properties.h"
#include "shape/alike_parts.h"
#include "shape/scope.h"

namespace insula::lang::graph {
namespace {

shape::Value export_value(const Value& v) {
  switch (v.type()) {
    case ValueType::kBool:
      return v.boolean();
    case ValueType::kString:
      return v.text();
    case ValueType::kNumber:
    case ValueType::kInteger:
      return v.number();
    default:
      return to_string(v);
  }
}

nlohmann::ordered_json json_value(const Value& v) {
  switch (v.type()) {
    case ValueType::kBool:
      return v.boolean();
    case ValueType::kString:
      return v.text();
    case ValueType::kInteger:
      return v.integer();
    case ValueType::kNumber:
      return v.number();
    case ValueType::kVec3:
      return {v.vec().x, v.vec().y, v.vec().z};
    default: {
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const Value& item : v.list()) list.push_back(json_value(item));
      return list;
    }
  }
}

nlohmann::ordered_json vec(kernel::Vec3 v) {
  return {v.x, v.y, v.z};
}

// The top-level graph's attributes visible from the entity, in declaration order.
std::vector<std::pair<std::string, const Value*>> top_attributes(const RunResult& run,
                                                                 EntityId id) {
  std::vector<std::pair<std::string, const Value*>> out;
  for (const auto& [key, name] : run.attribute_names) {
    if (const Value* v = run.entities.attribute(id, key)) out.emplace_back(name, v);
  }
  return out;
}

// A part's mesh: the shape's geometry in world space, its faces showing the entity's material.
kernel::Mesh part_mesh(const RunResult& run, const Entity& e) {
  const shape::Shape& s = run.tree[e.shape];
  if (s.mesh == nullptr) return {};
  kernel::Mesh mesh = shape::mesh_to_world(*s.mesh, s.scope);
  if (e.material != 0) {
    kernel::Mesh tagged;
    for (const kernel::Vec3& p : mesh.positions()) tagged.add_vertex(p);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      kernel::FaceTag tag = mesh.tag(f);
      tag.material = e.material;
      tagged.add_face(mesh.face(f), tag);
    }
    return tagged;
  }
  return mesh;
}

nlohmann::ordered_json entity_record(const RunResult& run, EntityId id, const std::string& port);

using MaterialKey = std::tuple<std::string, std::array<float, 4>, const shape::Image*>;

// The scene's index of a material equal to `m` (name, colour, image), appended when new.
kernel::MaterialId material_index(shape::Scene& scene,
                                  std::map<MaterialKey, kernel::MaterialId>& known,
                                  const shape::Material& m) {
  const MaterialKey key{m.name, m.rgba, m.image.get()};
  const auto [it, added] =
      known.try_emplace(key, static_cast<kernel::MaterialId>(scene.materials.size()));
  if (added) scene.materials.push_back(m);
  return it->second;
}

// A terrain is a building of its own with one part, `terrain`: its surface in a grass colour,
// the cells of levelled roads in asphalt.
shape::Building terrain_building(const RunResult& run, EntityId id, shape::Scene& scene,
                                 std::map<MaterialKey, kernel::MaterialId>& known) {
  shape::Building b;
  b.id = "terrain_" + std::to_string(id);
  shape::Part part;
  part.name = "terrain";
  part.kind = shape::PartKind::kOther;
  for (const auto& [name, value] : top_attributes(run, id)) {
    b.attributes[name] = export_value(*value);
    part.attributes[name] = export_value(*value);
  }
  const kernel::Heightfield& field = *run.entities[id].terrain;
  const kernel::MaterialId grass =
      material_index(scene, known, {"terrain", {0.42F, 0.55F, 0.30F, 1.0F}});
  const kernel::MaterialId road =
      field.road.empty() ? grass
                         : material_index(scene, known, {"road", {0.32F, 0.33F, 0.35F, 1.0F}});
  part.mesh = kernel::heightfield_mesh(field, grass, road);
  b.parts.push_back(std::move(part));
  return b;
}

// Building ids: a building made from a lot (its oldest ancestor, or a copy of it, was made by
// create.lots) is named after the lot, the lot's second and later buildings `<lot>/2`, `<lot>/3`;
// so a lot's buildings have the same ids whichever other lots run beside it (a city built tile
// by tile, apps/cli/graph_tiles.h). Any other building is `entity_<id>`.
class LotNames {
 public:
  // `lot_ids`: every lot's id in the whole input (a run of a few lots knows only its own); a
  // later building's name skips them, so `C/2` never repeats a lot named `C/2`.
  LotNames(const RunResult& run, const std::set<std::string>* lot_ids) : run_(run) {
    for (const auto& [entity, id] : run.lots) {
      by_lineage_.emplace(run.entities[entity].lineage, id);
      taken_.insert(id);
    }
    if (lot_ids != nullptr) taken_.insert(lot_ids->begin(), lot_ids->end());
  }

  // The lineage of the lot of create.lots `entity` descends from, if any.
  std::optional<std::uint32_t> lot(EntityId entity) const {
    const auto found = lot_of(entity);
    if (found == by_lineage_.end()) return std::nullopt;
    return found->first;
  }

  std::string next(EntityId entity) {
    const auto lot = lot_of(entity);
    if (lot == by_lineage_.end()) return "entity_" + std::to_string(entity);
    std::size_t& count = made_[lot->second];
    if (++count == 1) return lot->second;
    std::string name = lot->second + "/" + std::to_string(count);
    while (taken_.contains(name)) name = lot->second + "/" + std::to_string(++count);
    return name;
  }

 private:
  std::map<std::uint32_t, std::string>::const_iterator lot_of(EntityId entity) const {
    EntityId root = entity;
    while (run_.entities[root].parent != kNoEntity) root = run_.entities[root].parent;
    return by_lineage_.find(run_.entities[root].lineage);
  }

  const RunResult& run_;
  std::map<std::uint32_t, std::string> by_lineage_;
  std::map<std::string, std::size_t> made_;
  std::set<std::string> taken_;
};

// What makes result shapes one building: the lot they descend from, and within it (or where
// there is none) their value of the top-level attribute `building`. So a lot's shapes are one
// building unless the graph numbers them apart, and a `building` the lot brings (OpenStreetMap's
// `building=yes`) cannot join two lots.
struct BuildingGroup {
  std::optional<std::uint32_t> lot;  // lineage of the lot
  std::string value;                 // of `building`, "" when it has none

  auto operator<=>(const BuildingGroup&) const = default;
};

}  // namespace

shape::Scene to_scene(const RunResult& run, const std::set<std::string>* lot_ids) {
  shape::Scene scene;
  scene.materials = run.materials;
  for (const auto& [material, texture] : run.textures) {
    auto image = std::make_shared<shape::Image>();
    image->name = texture->name;
    image->width = texture->width;
    image->height = texture->height;
    image->rgba = texture->rgba;
    scene.materials[material].image = image;
  }
  std::optional<AttributeKey> building_key;
  for (const auto& [key, name] : run.attribute_names) {
    if (name == "building") building_key = key;
  }
  std::map<BuildingGroup, std::size_t> by_group;
  LotNames lot_names(run, lot_ids);
  std::map<MaterialKey, kernel::MaterialId> known;  // rule nodes' materials, each once
  std::vector<shape::AlikeParts> part_index;        // per building
  for (const ResultEntity& r : run.results) {
    const Entity& e = run.entities[r.entity];
    if (e.type == EntityType::kLight || e.type == EntityType::kPoint) {
      if (e.type == EntityType::kLight) {
        shape::Light light;
        light.name = r.port + "#" + std::to_string(scene.lights.size());
        light.kind = e.light->kind;
        light.position = e.position;
        light.color = {static_cast<float>(e.light->color.x), static_cast<float>(e.light->color.y),
                       static_cast<float>(e.light->color.z)};
        light.intensity = e.light->intensity;
        light.range = e.light->range;
        scene.lights.push_back(std::move(light));
      }
      continue;
    }
    if (e.type == EntityType::kTerrain) {
      scene.buildings.push_back(terrain_building(run, r.entity, scene, known));
      part_index.emplace_back();
      continue;
    }
    if (e.type != EntityType::kShape) continue;
    const Value* group = building_key ? run.entities.attribute(r.entity, *building_key) : nullptr;
    const std::optional<std::uint32_t> lot = lot_names.lot(r.entity);
    std::size_t index = scene.buildings.size();
    if (lot || group != nullptr) {
      index =
          by_group.emplace(BuildingGroup{lot, group ? to_string(*group) : ""}, index).first->second;
    }
    if (index == scene.buildings.size()) {
      shape::Building b;
      // A building on a lot is named after the lot (its input id) even when its shapes are
      // grouped by `building`: the lot is what a user finds it by.
      b.id = group != nullptr && !lot ? "building_" + to_string(*group) : lot_names.next(r.entity);
      for (const auto& [name, value] : top_attributes(run, r.entity)) {
        b.attributes[name] = export_value(*value);
      }
      scene.buildings.push_back(std::move(b));
      part_index.emplace_back();
    }
    shape::Building& building = scene.buildings[index];
    if (e.model != nullptr) {
      // A rule node's parts: their materials appended to the scene's table.
      std::vector<kernel::MaterialId> remap(e.model->materials.size(), 0);
      for (std::size_t m = 1; m < e.model->materials.size(); ++m) {
        remap[m] = material_index(scene, known, e.model->materials[m]);
      }
      for (const shape::Part& part : e.model->parts) {
        shape::Part copy = part;
        kernel::Mesh mesh;
        for (const kernel::Vec3& p : part.mesh.positions()) mesh.add_vertex(p);
        for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
          kernel::FaceTag tag = part.mesh.tag(f);
          if (tag.material < remap.size()) tag.material = remap[tag.material];
          mesh.add_face(part.mesh.face(f), tag);
        }
        copy.mesh = std::move(mesh);
        part_index[index].add(building.parts, std::move(copy));
      }
      continue;
    }
    shape::Part part;
    part.name = r.port;
    for (const auto& [name, value] : top_attributes(run, r.entity)) {
      part.attributes[name] = export_value(*value);
    }
    part.mesh = part_mesh(run, e);
    if (!part.mesh.empty()) part_index[index].add(building.parts, std::move(part));
  }
  std::erase_if(scene.buildings, [](const shape::Building& b) { return b.parts.empty(); });
  return scene;
}

namespace {

nlohmann::ordered_json entity_record(const RunResult& run, EntityId id, const std::string& port) {
  const Entity& e = run.entities[id];
  nlohmann::ordered_json r;
  r["id"] = id;
  r["type"] = std::string(entity_type_name(e.type));
  if (!port.empty()) r["port"] = port;
  nlohmann::ordered_json attributes = nlohmann::ordered_json::object();
  for (const auto& [name, value] : top_attributes(run, id)) attributes[name] = json_value(*value);
  r["attributes"] = attributes;
  switch (e.type) {
    case EntityType::kShape: {
      const Measures m = measure(run.entities, run.tree, id);
      r["area"] = m.area;
      r["volume"] = m.volume;
      r["faces"] = m.faces;
      r["material"] = e.material != 0 ? run.materials[e.material].name : "";
      if (e.model != nullptr) r["parts"] = e.model->parts.size();
      const shape::Scope& s = run.tree[e.shape].scope;
      r["scope"] = {
          {"origin", vec(s.origin)}, {"x", vec(s.x)}, {"y", vec(s.y)}, {"size", vec(s.size)}};
      break;
    }
    case EntityType::kPath: {
      nlohmann::ordered_json vertices = nlohmann::ordered_json::array();
      for (const kernel::Vec3& v : e.path->vertices) vertices.push_back(vec(v));
      nlohmann::ordered_json edges = nlohmann::ordered_json::array();
      double length = 0;
      for (const auto& [a, b] : e.path->edges) {
        edges.push_back({a, b});
        length += kernel::length(e.path->vertices[b] - e.path->vertices[a]);
      }
      r["vertices"] = vertices;
      r["edges"] = edges;
      r["length"] = length;
      break;
    }
    case EntityType::kPoint:
      r["position"] = vec(e.position);
      break;
    case EntityType::kLight:
      r["position"] = vec(e.position);
      r["kind"] = e.light->kind;
      r["intensity"] = e.light->intensity;
      break;
    case EntityType::kTexture:
      r["name"] = e.texture->name;
      r["text"] = e.texture->text;
      r["width"] = e.texture->width;
      r["height"] = e.texture->height;
      break;
    case EntityType::kTerrain: {
      const kernel::Heightfield& f = *e.terrain;
      const auto [lo, hi] = std::minmax_element(f.z.begin(), f.z.end());
      r["cells"] = f.cells();
      r["size"] = {f.width(), f.depth()};
      r["min_height"] = *lo;
      r["max_height"] = *hi;
      break;
    }
    case EntityType::kGroup: {
      nlohmann::ordered_json members = nlohmann::ordered_json::array();
      for (EntityId m : e.members) members.push_back(entity_record(run, m, ""));
      r["members"] = members;
      break;
    }
    default:
      break;
  }
  return r;
}

nlohmann::ordered_json counts(const std::map<std::string, std::uint64_t>& map) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [k, v] : map) out[k] = v;
  return out;
}

}  // namespace

nlohmann::ordered_json graph_report(const RunResult& run, std::size_t listed) {
  nlohmann::ordered_json g;
  g["cyclic_edges"] = run.cyclic_edges;
  nlohmann::ordered_json runs = nlohmann::ordered_json::object();
  for (const auto& [id, n] : run.node_runs) {
    runs[id] = {{"executions", n.executions}, {"rounds", n.rounds}, {"seconds", n.seconds}};
  }
  g["node_runs"] = runs;
  nlohmann::ordered_json leaves = nlohmann::ordered_json::object();
  for (const auto& [port, count] : run.leaves) {
    nlohmann::ordered_json types = nlohmann::ordered_json::object();
    for (const auto& [type, n] : count.types) types[type] = n;
    leaves[port] = {{"count", count.count}, {"types", types}};
  }
  g["leaves"] = leaves;
  g["ports"] = counts(run.ports);
  g["blocked"] = counts(run.blocked);
  g["unprocessed"] = counts(run.unprocessed);
  g["failed"] = counts(run.failed);
  nlohmann::ordered_json entities = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < run.results.size() && i < listed; ++i) {
    entities.push_back(entity_record(run, run.results[i].entity, run.results[i].port));
  }
  g["entities"] = entities;
  if (run.results.size() > listed) g["entities_listed"] = listed;
  return g;
}

}  // namespace insula::lang::graph
