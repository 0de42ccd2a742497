// Building elements as shape operations (issue 11: one engine): stairs, door and window frames,
// floor or ceiling slabs and walls with openings, built by the kernel solids the .bldg builder uses
// (kernel/solids.h, kernel/opening_frame.h, kernel/wall.h), so a grammar, a Lua program and a .bldg
// file get the same meshes. Parameters in docs/operations.md; conventions in docs/shape-model.md.
#pragma once

#include <span>
#include <vector>

#include "kernel/opening_frame.h"
#include "kernel/wall.h"
#include "shape/operation.h"
#include "shape/shape_tree.h"

namespace insula::shape {

std::vector<Operation> stair_operations();
std::vector<Operation> frame_operations();
std::vector<Operation> slab_operations();
std::vector<Operation> wall_operations();

// --- stair (ops_stair.cc)
// A straight massive flight over a flat shape: it is the shape's scope rectangle wide (x) and
// deep (y), climbs from the y = 0 edge to `height` meters (> 0) at the far edge in `steps` steps
// (>= 1), along the shape's normal. The child's scope is oriented as extrude's (y up).
OpResult stair(ShapeTree& tree, ShapeId id, double height, int steps);

// --- frame (ops_frame.cc)
// The frame of an opening that fills a flat shape's scope rectangle (x the width, y the height,
// the sill at y = 0), in a wall `thickness` meters thick lying behind the face (scope z from
// -thickness to 0): kernel::add_opening_frame. The child's scope keeps the shape's axes.
OpResult frame(ShapeTree& tree, ShapeId id, kernel::FrameKind kind, double thickness,
               const kernel::FrameProfile& profile);

// --- slab (ops_slab.cc)
enum class SlabKind : std::uint8_t { kFloor, kCeiling };
// A floor slab (FloorSurface on top, standing on the shape) or a ceiling slab (CeilingSurface
// below, hanging under the shape) over a flat shape's outline, `thickness` meters (> 0); the
// other faces ClosureSurface and InteriorWallSurface. Oriented as extrude's child (y up).
OpResult slab(ShapeTree& tree, ShapeId id, SlabKind kind, double thickness);

// --- wall (ops_wall.cc)
// A wall `thickness` meters (> 0) thick behind a flat shape without holes (scope z from -thickness
// to 0; the shape's outline is the wall's outline, x along the wall, y up) with `openings` (in the
// shape's scope xy) cut through it: kernel::build_wall with the .bldg builder's margin and policy
// (an opening that does not fit is left out and named in the result's warning). Faces: the shape's
// side WallSurface, the back InteriorWallSurface, reveals Jamb, Sill and Lintel, the rim
// ClosureSurface. The child's scope keeps the shape's axes.
OpResult wall_solid(ShapeTree& tree, ShapeId id, double thickness,
                    std::span<const kernel::Opening> openings);

}  // namespace insula::shape
