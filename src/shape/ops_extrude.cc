// Extrusion of a flat shape (a footprint or a face from comp) along its normal into a closed prism
// (seed 001 §3.4.3 "Extruding"; CGA extrude). The geometry comes from kernel extrude.h.
#include <cmath>

#include "kernel/extrude.h"
#include "shape/ops.h"

namespace insula::shape {

using kernel::Vec3;

namespace {

// A flat shape's normal (scope z) becomes the child's y axis, so a mass stands with y up and its
// front face (the footprint's first edge, at local y = 0) on the child's +z side.
constexpr Vec3 kUpX{1, 0, 0};
constexpr Vec3 kUpY{0, 0, 1};
constexpr Vec3 kUpZ{0, -1, 0};

}  // namespace

OpResult extrude(ShapeTree& tree, ShapeId id, double height) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (!(height > 0) || !std::isfinite(height)) return OpResult::failure("height must be > 0");
  kernel::ExtrudeResult prism = kernel::extrude(*s.outline, 0, height);
  if (!prism.ok()) {
    return OpResult::failure(std::string(kernel::extrude_status_message(prism.status)));
  }
  Refit child = refit(s.scope, prism.mesh, kUpX, kUpY, kUpZ);
  OpResult result;
  result.add(tree.add_child(id, child.scope, std::make_shared<kernel::Mesh>(std::move(child.mesh))),
             0);
  return finish(tree, id, std::move(result));
}

std::vector<Operation> extrude_operations() {
  std::vector<Operation> ops;
  ops.push_back({"extrude",
                 "Extrudes a flat shape (footprint or face) along its normal into a closed prism; "
                 "the child's scope has y along the old normal.",
                 {{"height",
                   ParamType::kNumber,
                   "extrusion distance (meters, > 0)",
                   std::nullopt,
                   {},
                   0.0,
                   {}}},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return extrude(t, id, a.number("height"));
                 }});
  return ops;
}

}  // namespace insula::shape
