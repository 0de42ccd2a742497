#include "shape/plan.h"

namespace insula::shape {

using kernel::translate;

void translate(StoreyPlan& plan, kernel::Vec3 offset) {
  const kernel::Vec2 by{offset.x, offset.y};
  plan.elevation += offset.z;
  for (PlanRoom& room : plan.rooms) translate(room.outline, by);
  for (PlanWall& wall : plan.walls) translate(wall.outline, by);
  for (PlanOpening& opening : plan.openings) {
    opening.a += by;
    opening.b += by;
  }
  for (PlanStair& stair : plan.stairs) {
    translate(stair.outline, by);
    stair.up_from += by;
    stair.up_to += by;
  }
}

}  // namespace insula::shape
