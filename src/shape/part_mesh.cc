#include "shape/part_mesh.h"

#include <algorithm>

#include "kernel/transform.h"

namespace insula::shape {

kernel::Mesh part_world_mesh(const Part& part) {
  if (!part.instance_of) return part.mesh;
  return kernel::transformed(*part.instance_of, part.instance_transform);
}

bool has_instances(const Scene& scene) {
  return std::any_of(scene.buildings.begin(), scene.buildings.end(), [](const Building& b) {
    return std::any_of(b.parts.begin(), b.parts.end(),
                       [](const Part& p) { return p.instance_of != nullptr; });
  });
}

const Scene& expand_instances(const Scene& scene, Scene& storage) {
  if (!has_instances(scene)) return scene;
  storage = scene;
  for (Building& b : storage.buildings) {
    for (Part& p : b.parts) {
      if (!p.instance_of) continue;
      p.mesh = part_world_mesh(p);
      p.instance_of.reset();
      p.instance_transform = kernel::identity_transform();
    }
  }
  return storage;
}

}  // namespace insula::shape
