// CityEngine's convexify (a flat shape cut into convex pieces, kernel/convex_partition.h) and
// trim, which Insula accepts and reports as doing nothing (no trim planes are made).
#include <cmath>

#include "kernel/convex_partition.h"
#include "shape/ops.h"

namespace insula::shape {

OpResult convexify(ShapeTree& tree, ShapeId id, double max_length) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (!(max_length >= 0) || !std::isfinite(max_length)) {
    return OpResult::failure("maxLength must be finite and >= 0");
  }
  const std::vector<kernel::Ring> rings = kernel::convex_partition(*s.outline, max_length);
  if (rings.empty()) return OpResult::failure("the outline cannot be triangulated");
  OpResult result;
  for (const kernel::Ring& ring : rings) add_flat_region(tree, id, {ring, {}}, 0, result);
  return finish(tree, id, std::move(result));
}

std::vector<Operation> convexify_operations() {
  std::vector<Operation> ops;
  ops.push_back({"convexify",
                 "Cuts a flat shape into convex pieces, one flat child each (CGA convexify); "
                 "with maxLength > 0 only cut lines shorter than it are kept, so a piece may stay "
                 "concave.",
                 {{"maxLength",
                   ParamType::kNumber,
                   "longest cut line kept (meters; 0: no limit)",
                   ArgValue{0.0},
                   {},
                   0.0,
                   {}}},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return convexify(t, id, a.number("maxLength"));
                 }});
  ops.push_back({"trim",
                 "Accepted for CityEngine's rules and reported: Insula makes no trim planes "
                 "(CityEngine cuts inserted assets by the planes comp(f) leaves), so the shape "
                 "goes on unchanged with a warning.",
                 {},
                 [](ShapeTree& t, ShapeId id, const Arguments&, const Context&) {
                   const Shape& s = t[id];
                   return relabelled_child(
                       t, id, s.scope, s.mesh, s.outline,
                       "trim planes are not made in Insula: trim() leaves the shape unchanged");
                 }});
  return ops;
}

}  // namespace insula::shape
