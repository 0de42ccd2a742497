// Roofs over a flat shape (seed 001 §3.4.3 "Roofing"; seed 000 §4.6 straight-skeleton roofs; CGA
// roofGable/roofHip/...). The geometry comes from kernel roof.h, or kernel roof_solid.h for a
// closed solid (the .bldg builder's roofs); this file orients the result.
#include <cmath>

#include "kernel/roof_solid.h"
#include "shape/ops.h"

namespace insula::shape {

using kernel::Vec3;

namespace {

struct Built {
  kernel::Mesh mesh;
  kernel::RoofStatus status = kernel::RoofStatus::kFailed;
  std::string message;
};

Built build(const kernel::Polygon& outline, const kernel::RoofSpec& spec, const RoofForm& form) {
  const bool flat = spec.type == kernel::RoofType::kFlat;
  if (form.closed || (flat && form.thickness > 0)) {
    if (flat && !(form.thickness > 0)) return {{}, {}, "a closed flat roof needs a thickness > 0"};
    kernel::RoofSolidSpec solid;
    solid.roof = spec;
    solid.height = form.height;
    solid.flat_thickness = form.thickness;
    kernel::RoofSolid built = kernel::build_roof_solid(outline, solid, 0);
    return {std::move(built.mesh), built.status, std::move(built.message)};
  }
  kernel::RoofResult built = kernel::build_roof(outline, spec, 0);
  kernel::scale_roof_height(built.mesh, 0, form.height);
  return {std::move(built.mesh), built.status, std::move(built.message)};
}

}  // namespace

OpResult roof(ShapeTree& tree, ShapeId id, const kernel::RoofSpec& spec, const RoofForm& form) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  Built built = build(*s.outline, spec, form);
  if (built.status == kernel::RoofStatus::kFailed || built.mesh.empty()) {
    return OpResult::failure(built.message.empty() ? "no roof could be built" : built.message);
  }
  // Oriented like an extrusion: x as before, y along the face normal (up), z = x cross y.
  return replace_with(
      tree, id, built.mesh, {1, 0, 0}, {0, 0, 1}, {0, -1, 0},
      built.status == kernel::RoofStatus::kFallback ? std::move(built.message) : std::string());
}

// Every kernel roof type by name, in the kernel's order.
std::vector<std::string> roof_type_names() {
  std::vector<std::string> names;
  for (const kernel::RoofType type : kernel::kRoofTypes) {
    names.emplace_back(kernel::roof_type_name(type));
  }
  return names;
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
         roof_type_names(),
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
         {}},
        {"height",
         ParamType::kNumber,
         "top above the eave (meters; the heights are scaled to it); 0: as the pitch gives",
         ArgValue{0.0},
         {},
         0.0,
         {}},
        {"closed",
         ParamType::kBool,
         "a closed solid: gable ends and the bottom closed, a holed mansard's opening through it",
         ArgValue{false},
         {},
         {},
         {}},
        {"thickness",
         ParamType::kNumber,
         "flat roofs: a slab this thick over the outline grown by the overhang (meters); 0: the "
         "single roof face",
         ArgValue{0.0},
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
         return roof(t, id, spec, {a.number("height"), a.boolean("closed"), a.number("thickness")});
       }});
  return ops;
}

}  // namespace insula::shape
