// Door and window frames (seed 001 §4.4 "adding the frame, then [...] the door or window pane";
// seed 000 §4.1 "frame portals for doors and windows") over a flat shape taken as the opening,
// from kernel/opening_frame.h as the .bldg builder frames its openings.
#include <cmath>

#include "shape/building_ops.h"
#include "shape/ops.h"

namespace insula::shape {

OpResult frame(ShapeTree& tree, ShapeId id, kernel::FrameKind kind, double thickness,
               const kernel::FrameProfile& profile) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a face or a footprint)");
  if (!(thickness > 0) || !std::isfinite(thickness)) {
    return OpResult::failure("thickness must be > 0");
  }
  if (!(s.scope.size.x > 0) || !(s.scope.size.y > 0)) {
    return OpResult::failure("the shape has no area");
  }
  // The wall lies behind the face: its faces are w = 0 (scope z = -thickness) and w = thickness
  // (the face itself).
  kernel::WallFrame wall;
  wall.origin = {0, 0, -thickness};
  const kernel::Opening opening{0, 0, s.scope.size.x, s.scope.size.y, 0, 8};
  const bool door = kind == kernel::FrameKind::kDoor;
  const kernel::FaceTag tag{door ? kernel::SemanticClass::kDoor : kernel::SemanticClass::kWindow};
  kernel::Mesh mesh;
  kernel::add_opening_frame(mesh, wall, thickness, opening, kind, profile, {tag, tag});
  if (mesh.empty()) return OpResult::failure("no frame could be built");
  return replace_with(tree, id, mesh, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
}

std::vector<Operation> frame_operations() {
  const kernel::FrameProfile defaults;
  std::vector<Operation> ops;
  ops.push_back(
      {"frame",
       "Frames an opening that fills a flat shape (x the width, y the height) in a wall "
       "`thickness` "
       "thick behind the face: posts, head and (windows) sill on both wall faces, and a pane or "
       "leaf in the wall's middle (the .bldg builder's frames).",
       {{"kind",
         ParamType::kEnum,
         "door or window (a window has a sill piece and a pane)",
         ArgValue{std::string("window")},
         {"door", "window"},
         {},
         {}},
        {"thickness", ParamType::kNumber, "wall thickness (meters)", ArgValue{0.3}, {}, 0.001, {}},
        {"width",
         ParamType::kNumber,
         "frame profile width in the wall's plane (meters)",
         ArgValue{defaults.width},
         {},
         0.001,
         {}},
        {"depth",
         ParamType::kNumber,
         "how far the frame stands out of each wall face (meters)",
         ArgValue{defaults.depth},
         {},
         0.001,
         {}},
        {"pane",
         ParamType::kNumber,
         "window pane thickness, at most a quarter of the wall (meters; 0: none)",
         ArgValue{defaults.pane},
         {},
         0.0,
         {}},
        {"leaf",
         ParamType::kNumber,
         "door leaf thickness, at most a quarter of the wall (meters; 0: an open doorway)",
         ArgValue{defaults.leaf},
         {},
         0.0,
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         kernel::FrameProfile profile;
         profile.width = a.number("width");
         profile.depth = a.number("depth");
         profile.pane = a.number("pane");
         profile.leaf = a.number("leaf");
         const auto kind =
             a.string("kind") == "door" ? kernel::FrameKind::kDoor : kernel::FrameKind::kWindow;
         return frame(t, id, kind, a.number("thickness"), profile);
       }});
  return ops;
}

}  // namespace insula::shape
