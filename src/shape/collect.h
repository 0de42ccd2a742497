// From a shape tree to the export model (scene.h): one Building per root, one Part per collected
// shape with geometry, meshes transformed from scope space to world space.
#pragma once

#include <string>
#include <vector>

#include "shape/scene.h"
#include "shape/shape_tree.h"

namespace insula::shape {

struct CollectOptions {
  // Collect shapes carrying one of these labels; empty collects the leaves (terminal shapes).
  std::vector<std::string> labels;
  // Building ids are "<prefix><root index>" unless the root has a string attribute "id".
  std::string id_prefix = "building_";
  kernel::Vec3 origin;  // copied to Scene::origin (world = local + origin)
  std::string crs;
  // Shapes sharing one mesh (seed 001 §4.5: repeated decorations placed by connect/place) become
  // instance parts (Part::instance_of, instance_transform) when two or more are collected.
  bool instances = false;
};

// Part name = the shape's first label ("shape_<id>" without labels), attributes = its resolved
// (inherited) attributes, mesh in world space. Shapes without faces are skipped, and so are roots
// without any collected part. Buildings carry their root's resolved attributes.
Scene collect(const ShapeTree& tree, const CollectOptions& options = {});

}  // namespace insula::shape
