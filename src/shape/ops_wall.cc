// Walls with door and window openings (seed 000 §4.1 "the walls are extruded considering the doors
// and windows previously flagged"; seed 001 §4.4's hole in the wall) over a flat shape taken as the
// wall's face, from kernel/wall.h as the .bldg builder builds its walls (issue 11: one engine).
#include <cmath>
#include <cstdio>
#include <string>

#include "kernel/wall.h"
#include "shape/building_ops.h"
#include "shape/ops.h"

namespace insula::shape {

OpResult wall_solid(ShapeTree& tree, ShapeId id, double thickness,
                    std::span<const kernel::Opening> openings) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a face or a footprint)");
  if (!(thickness > 0) || !std::isfinite(thickness)) {
    return OpResult::failure("thickness must be > 0");
  }
  // A hole of the face is no opening of kernel::build_wall (it has no jambs or sill to tag).
  if (!s.outline->holes.empty()) return OpResult::failure("the shape has holes");
  kernel::WallSpec spec;
  spec.outline = s.outline->outer;
  spec.thickness = thickness;
  spec.openings.assign(openings.begin(), openings.end());
  // What the .bldg builder does with an opening that does not fit: the wall is built without it.
  spec.policy = kernel::OpeningPolicy::kSkip;
  // The wall lies behind the face, as frame's: its faces are w = 0 (scope z = -thickness) and
  // w = thickness (the face itself, WallSurface).
  kernel::WallFrame frame;
  frame.origin = {0, 0, -thickness};
  const kernel::WallResult built = kernel::build_wall(spec, frame);
  if (!built.ok()) return OpResult::failure(built.message);
  std::string warning;
  for (const kernel::OpeningIssue& issue : built.issues) {
    if (!warning.empty()) warning += "; ";
    warning += issue.message + " (left out)";
  }
  return replace_with(tree, id, built.mesh, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, std::move(warning));
}

namespace {

// The registry's size list as openings, four sizes each; relative sizes are fractions of the
// scope's width (u, width) or height (sill, height).
std::string to_openings(const std::vector<SizeSpec>& sizes, const Scope& scope,
                        std::vector<kernel::Opening>& out) {
  if (sizes.size() % 4 != 0) {
    return "openings take four sizes each (u, sill, width, height); got " +
           std::to_string(sizes.size());
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const SizeSpec& size = sizes[i];
    if (size.mode == SizeMode::kFloating) {
      return "opening sizes are meters or relative ('), not floating (~); got " + to_string(size);
    }
    const bool along = i % 4 == 0 || i % 4 == 2;
    values.push_back(size.mode == SizeMode::kRelative
                         ? size.value * (along ? scope.size.x : scope.size.y)
                         : size.value);
  }
  for (std::size_t i = 0; i < values.size(); i += 4) {
    out.push_back({values[i], values[i + 1], values[i + 2], values[i + 3], 0, 8});
  }
  return {};
}

}  // namespace

std::vector<Operation> wall_operations() {
  char margin[32];  // %g: the shortest text of the kernel's margin ("0.05"), not 17 digits
  std::snprintf(margin, sizeof margin, "%g", kernel::WallSpec{}.min_margin);
  std::vector<Operation> ops;
  ops.push_back(
      {"wall",
       "Builds a wall `thickness` thick behind a flat shape (its face: x along the wall, y up) "
       "with rectangular openings cut through it, one closed solid (the .bldg builder's walls, "
       "kernel::build_wall); an opening on the bottom edge is a notch (a door), one closer than " +
           std::string(margin) + " m to the edge or another opening is left out with a warning.",
       {{"thickness", ParamType::kNumber, "wall thickness (meters)", ArgValue{0.3}, {}, 0.001, {}},
        {"openings",
         ParamType::kSizeList,
         "four sizes per opening: u (left edge along x), sill (bottom along y), width, height; "
         "meters or relative (' of the shape's width for u and width, of its height for sill and "
         "height)",
         ArgValue{std::vector<SizeSpec>{}},
         {},
         0.0,
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         std::vector<kernel::Opening> openings;
         const std::string error = to_openings(a.sizes("openings"), t[id].scope, openings);
         if (!error.empty()) return OpResult::failure(error);
         return wall_solid(t, id, a.number("thickness"), openings);
       }});
  return ops;
}

}  // namespace insula::shape
