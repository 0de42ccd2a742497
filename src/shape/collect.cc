#include "shape/collect.h"

#include <algorithm>
#include <map>

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
      if (auto it = uses.find(s.mesh.get()); it != uses.end() && it->second > 1) {
        part.instance_of = s.mesh;
        part.instance_transform = scope_transform(s.scope);
      } else {
        part.mesh = mesh_to_world(*s.mesh, s.scope);
      }
      building.parts.push_back(std::move(part));
    }
    if (!building.parts.empty()) scene.buildings.push_back(std::move(building));
  }
  return scene;
}

}  // namespace insula::shape
