// Floor plans per storey, carried by a Building for the SVG plan writer (seed 000: "look at its
// plan"): rooms with names and areas, walls, doors with their swing, windows and stairs, in the
// building's local coordinates (meters, the same frame as its meshes, seen from above).
#pragma once

#include <string>
#include <vector>

#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::shape {

struct PlanRoom {
  std::string name;         // e.g. "kitchen_1"
  std::string type;         // e.g. "kitchen"
  kernel::Polygon outline;  // the room's clear floor (inside its walls)
  double area = 0;          // m², of `outline`
};

struct PlanWall {
  kernel::Polygon outline;  // the wall's footprint (thickness included)
  bool exterior = false;
};

enum class PlanOpeningKind { kDoor, kEntrance, kWindow };

struct PlanOpening {
  PlanOpeningKind kind = PlanOpeningKind::kDoor;
  kernel::Vec2 a;  // the opening's two ends on the wall's centre line
  kernel::Vec2 b;
  // Doors: unit vector, perpendicular to a-b, pointing into the room the leaf swings into; the
  // hinge is at `a`.
  kernel::Vec2 swing;
};

struct PlanStair {
  kernel::Polygon outline;
  kernel::Vec2 up_from;  // the foot of the flight (the arrow starts here)
  kernel::Vec2 up_to;    // its head
};

struct StoreyPlan {
  std::string name;  // e.g. "storey 0"
  int level = 0;
  double elevation = 0;  // floor level, meters
  std::vector<PlanRoom> rooms;
  std::vector<PlanWall> walls;
  std::vector<PlanOpening> openings;
  std::vector<PlanStair> stairs;
};

// Moves the plan by `offset` (meters): every outline and point by its x and y, `elevation` by its
// z; directions (a door's swing) stay. Exact up to one rounding per coordinate.
void translate(StoreyPlan& plan, kernel::Vec3 offset);

}  // namespace insula::shape
