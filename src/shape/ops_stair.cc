// Stairs (seed 000 §4.1 "producing entrance's stairs"; §5's several floors need stairs): a
// straight massive flight over a flat shape, from kernel/solids.h as the .bldg builder builds its
// stairs.
#include <cmath>

#include "kernel/solids.h"
#include "shape/building_ops.h"
#include "shape/ops.h"

namespace insula::shape {

OpResult stair(ShapeTree& tree, ShapeId id, double height, int steps) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (!(height > 0) || !std::isfinite(height)) return OpResult::failure("height must be > 0");
  if (steps < 1) return OpResult::failure("steps must be >= 1");
  const double width = s.scope.size.x;
  const double depth = s.scope.size.y;
  if (!(width > 0) || !(depth > 0)) return OpResult::failure("the shape has no area");
  kernel::StairSpec spec;
  spec.foot = {width / 2, 0};
  spec.dir = {0, 1};
  spec.width = width;
  spec.steps = steps;
  spec.run = depth / steps;
  spec.rise = height / steps;
  kernel::Mesh mesh;
  if (!kernel::add_staircase(mesh, spec, {kernel::SemanticClass::kStair, 0, 0})) {
    return OpResult::failure("no stair could be built");
  }
  // Oriented like an extrusion: y along the old normal (up).
  return replace_with(tree, id, mesh, {1, 0, 0}, {0, 0, 1}, {0, -1, 0});
}

std::vector<Operation> stair_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"stair",
       "Builds a straight massive flight of stairs over a flat shape, climbing along its y axis "
       "from the y = 0 edge to `height` at the far edge (the .bldg builder's stairs).",
       {{"height", ParamType::kNumber, "total rise (meters, > 0)", std::nullopt, {}, 0.0, {}},
        {"steps",
         ParamType::kInteger,
         "number of steps; 0: as few as keep each step at most max_rise high",
         ArgValue{std::int64_t{0}},
         {},
         0.0,
         1000.0},
        {"max_rise",
         ParamType::kNumber,
         "highest step when steps is 0 (meters)",
         ArgValue{kernel::kMaxStepRise},
         {},
         0.01,
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         const double height = a.number("height");
         const auto steps = static_cast<int>(a.integer("steps"));
         return stair(t, id, height,
                      steps > 0 ? steps : kernel::stair_steps(height, a.number("max_rise")));
       }});
  return ops;
}

}  // namespace insula::shape
