#include "shape/scene.h"

#include <string>

namespace insula::shape {

using kernel::SemanticClass;

Scene::Scene() {
  materials.push_back(Material{"default", {0.8F, 0.8F, 0.8F, 1.0F}});
}

void translate(Building& building, kernel::Vec3 offset) {
  for (Part& part : building.parts) {
    if (part.instance_of) {
      part.instance_transform.t += offset;
    } else {
      for (kernel::Vec3& p : part.mesh.positions()) p += offset;
    }
    if (part.uv) part.uv = part.uv->moved(kernel::translation(offset));
  }
  for (StoreyPlan& plan : building.plans) translate(plan, offset);
}

Material Scene::material_for(const kernel::FaceTag& tag) const {
  if (tag.material != 0 && tag.material < materials.size()) return materials[tag.material];
  return default_material(tag.semantic);
}

Material default_material(SemanticClass semantic) {
  const std::string name(kernel::semantic_name(semantic));
  switch (semantic) {
    case SemanticClass::kWallSurface:
    case SemanticClass::kJamb:
    case SemanticClass::kSill:
    case SemanticClass::kLintel:
      return {name, {0.86F, 0.82F, 0.74F, 1.0F}};
    case SemanticClass::kRoofSurface:
      return {name, {0.70F, 0.30F, 0.22F, 1.0F}};
    case SemanticClass::kGroundSurface:
      return {name, {0.35F, 0.35F, 0.35F, 1.0F}};
    case SemanticClass::kOuterCeilingSurface:
      return {name, {0.55F, 0.45F, 0.38F, 1.0F}};
    case SemanticClass::kWindow:
      return {name, {0.45F, 0.62F, 0.78F, 1.0F}};
    case SemanticClass::kDoor:
      return {name, {0.45F, 0.30F, 0.18F, 1.0F}};
    case SemanticClass::kFloorSurface:
      return {name, {0.66F, 0.55F, 0.42F, 1.0F}};
    case SemanticClass::kInteriorWallSurface:
      return {name, {0.93F, 0.92F, 0.88F, 1.0F}};
    case SemanticClass::kCeilingSurface:
      return {name, {0.97F, 0.97F, 0.95F, 1.0F}};
    default:
      return {name, {0.75F, 0.75F, 0.75F, 1.0F}};
  }
}

}  // namespace insula::shape
