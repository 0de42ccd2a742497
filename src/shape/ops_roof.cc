// Roofs over a flat shape (seed 001 §3.4.3 "Roofing"; seed 000 §4.6 straight-skeleton roofs; CGA
// roofGable/roofHip/...). The geometry comes from kernel roof.h; this file orients the result.
#include <cmath>

#include "shape/ops.h"

namespace insula::shape {

using kernel::Vec3;

OpResult roof(ShapeTree& tree, ShapeId id, const kernel::RoofSpec& spec) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  kernel::RoofResult built = kernel::build_roof(*s.outline, spec, 0);
  if (built.status == kernel::RoofStatus::kFailed || built.mesh.empty()) {
    return OpResult::failure(built.message.empty() ? "no roof could be built" : built.message);
  }
  // Oriented like an extrusion: x as before, y along the face normal (up), z = x cross y.
  Refit child = refit(s.scope, built.mesh, {1, 0, 0}, {0, 0, 1}, {0, -1, 0});
  OpResult result;
  result.add(tree.add_child(id, child.scope, std::make_shared<kernel::Mesh>(std::move(child.mesh))),
             0);
  if (built.status == kernel::RoofStatus::kFallback) result.warning = built.message;
  return finish(tree, id, std::move(result));
}

std::vector<Operation> roof_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"roof",
       "Builds a roof over a flat shape's outline with its eave in the shape's plane (kernel "
       "roofs: skeleton-based hip, gable and mansard); falls back with a warning when needed.",
       {{"type",
         ParamType::kEnum,
         "roof type",
         ArgValue{std::string("hip")},
         {"flat", "shed", "gable", "hip", "pyramid", "mansard", "holed_mansard"},
         {},
         {}},
        {"pitch", ParamType::kNumber, "slope (degrees)", ArgValue{30.0}, {}, 0.0, 89.0},
        {"overhang", ParamType::kNumber, "eave overhang (meters)", ArgValue{0.0}, {}, 0.0, {}},
        {"mansard_pitch",
         ParamType::kNumber,
         "slope of a mansard's lower part (degrees)",
         ArgValue{70.0},
         {},
         0.0,
         89.0},
        {"break_height",
         ParamType::kNumber,
         "height of a mansard's break line (meters)",
         ArgValue{2.5},
         {},
         0.0,
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         kernel::RoofSpec spec;
         spec.type = kernel::roof_type_from_name(a.string("type")).value_or(kernel::RoofType::kHip);
         spec.pitch_deg = a.number("pitch");
         spec.overhang = a.number("overhang");
         spec.mansard_pitch_deg = a.number("mansard_pitch");
         spec.mansard_break_height = a.number("break_height");
         return roof(t, id, spec);
       }});
  return ops;
}

}  // namespace insula::shape
