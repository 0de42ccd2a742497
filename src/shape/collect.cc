#include "shape/collect.h"

#include <algorithm>
#include <map>
#include <optional>

namespace insula::shape {

namespace {

bool selected(const ShapeTree& tree, ShapeId id, const CollectOptions& options) {
  if (options.labels.empty()) return tree[id].children.empty();
  return std::any_of(options.labels.begin(), options.labels.end(),
                     [&](const std::string& l) { return tree.has_label(id, l); });
}

std::string building_id(const ShapeTree& tree, ShapeId root, std::size_t index,
                        const CollectOptions& options) {
  const Value* id = tree.attribute(root, "id");
  if (id != nullptr && !is_null(*id)) return to_string(*id);
  return options.id_prefix + std::to_string(index);
}

// How many collected shapes use each mesh (for CollectOptions::instances).
std::map<const kernel::Mesh*, int> mesh_uses(const ShapeTree& tree, const CollectOptions& options) {
  std::map<const kernel::Mesh*, int> uses;
  if (!options.instances) return uses;
  for (ShapeId id = 0; id < tree.size(); ++id) {
    if (tree[id].mesh && selected(tree, id, options)) ++uses[tree[id].mesh.get()];
  }
  return uses;
}

// The texturing operations' state (shape/uv_map.h) becomes the part's uv map and, for a colour
// map, a white material showing it on every face (CityEngine's default colour when textured).
// Returns the material, or nullopt without a colour map.
std::optional<kernel::MaterialId> texture_state(Part& part, Scene& scene) {
  if (auto it = part.attributes.find(uv_set_attribute(0)); it != part.attributes.end()) {
    part.uv = decode_uv_map(it->second);
  }
  std::erase_if(part.attributes, [](const auto& a) { return a.first.starts_with("#uv"); });
  const auto it = part.attributes.find(kColormapAttribute);
  const auto* texture =
      it != part.attributes.end() ? std::get_if<std::string>(&it->second) : nullptr;
  if (texture == nullptr || texture->empty()) return std::nullopt;
  std::size_t m = 0;
  while (m < scene.materials.size() && scene.materials[m].texture != *texture) ++m;
  if (m == scene.materials.size()) {
    Material material{*texture, {1, 1, 1, 1}};
    material.texture = *texture;
    scene.materials.push_back(std::move(material));
  }
  return static_cast<kernel::MaterialId>(m);
}

}  // namespace

Scene collect(const ShapeTree& tree, const CollectOptions& options) {
  const std::map<const kernel::Mesh*, int> uses = mesh_uses(tree, options);
  Scene scene;
  scene.origin = options.origin;
  scene.crs = options.crs;
  for (std::size_t r = 0; r < tree.roots().size(); ++r) {
    const ShapeId root = tree.roots()[r];
    Building building;
    building.id = building_id(tree, root, r, options);
    building.attributes = tree.resolved_attributes(root);
    std::vector<ShapeId> ids = tree.subtree(root);
    std::sort(ids.begin(), ids.end());  // parts in creation order: deterministic
    for (ShapeId id : ids) {
      const Shape& s = tree[id];
      if (!selected(tree, id, options) || !s.mesh || s.mesh->empty()) continue;
      Part part;
      const std::string_view label = tree.first_label(id);
      part.name = label.empty() ? "shape_" + std::to_string(id) : std::string(label);
      part.attributes = tree.resolved_attributes(id);
      if (tree.has_label(id, kFurnitureLabel)) part.kind = PartKind::kFurniture;
      if (tree.has_label(id, kInstallationLabel)) part.kind = PartKind::kInstallation;
      const std::optional<kernel::MaterialId> textured = texture_state(part, scene);
      if (auto it = uses.find(s.mesh.get()); it != uses.end() && it->second > 1 && !textured) {
        part.instance_of = s.mesh;
        part.instance_transform = scope_transform(s.scope);
      } else {
        part.mesh = mesh_to_world(*s.mesh, s.scope);
        for (std::size_t f = 0; textured && f < part.mesh.face_count(); ++f) {
          part.mesh.tag(f).material = *textured;
        }
      }
      building.parts.push_back(std::move(part));
    }
    if (!building.parts.empty()) scene.buildings.push_back(std::move(building));
  }
  return scene;
}

}  // namespace insula::shape
