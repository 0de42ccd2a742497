// Frames of doors and windows (seed 000 §4.1 "frame portals for doors and windows"; seed 001 §4.4
// "adding the frame, then [...] the door or window pane"): posts, a head and, for windows, a sill
// piece on both faces of a wall, plus a pane (glass) or a leaf through the wall's middle. The
// .bldg builder, the shape operation `frame` and through it CGA and Lua build frames here.
#pragma once

#include "kernel/mesh.h"
#include "kernel/wall.h"

namespace insula::kernel {

enum class FrameKind { kDoor, kWindow };

// The frame's cross-section, meters.
struct FrameProfile {
  double width = 0.06;  // of the posts, the head and the sill, in the wall's plane (> 0)
  double depth = 0.04;  // how far each piece stands out of its wall face (> 0)
  // Thickness of a window's pane, at most a quarter of the wall; 0: no pane.
  double pane = 0.02;
  // Thickness of a door's leaf, closed in the wall's middle, at most a quarter of the wall; 0: an
  // open doorway (the .bldg builder's doors).
  double leaf = 0;
};

struct FrameTags {
  FaceTag frame{SemanticClass::kWindow};
  FaceTag pane{SemanticClass::kWindow};  // the pane's or the leaf's faces
};

// Appends the frame of `opening` (u, sill, width, height; arches are framed as their bounding
// rectangle) in a wall `thickness` thick whose faces are w = 0 and w = thickness of `frame`: four
// (door) or eight (window) boxes around the opening, the posts and head outside it, the sill
// piece below it, then the pane or leaf box, each of 8 vertices and 6 faces. Nothing is added for
// a size that is not positive.
void add_opening_frame(Mesh& mesh, const WallFrame& frame, double thickness, const Opening& opening,
                       FrameKind kind, const FrameProfile& profile, const FrameTags& tags);

}  // namespace insula::kernel
