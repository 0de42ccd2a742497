// The stages of the floor-plan engine after the subdivision, in the order floorplan.cc runs them.
// Each edits the FloorPlan being assembled; warnings go to Work::warnings.
#pragma once

#include <vector>

#include "lang/bldg/floorplan.h"
#include "lang/bldg/plan_state.h"
#include "lang/bldg/plan_transitions.h"

namespace insula::lang::bldg::plan {

// The frame a lot is planned in (plan_frame.cc): turned by `angle` (radians, within +-45 degrees)
// about `pivot` from the lot's, so the direction most of its walls run along is the x axis.
struct PlanFrame {
  double angle = 0;
  kernel::Vec2 pivot;
  bool rotated() const { return angle != 0; }
};
// The frame of `outline`'s dominant wall direction; not rotated for an axis-aligned outline.
PlanFrame lot_frame(const kernel::Polygon& outline);
// Turns a lot outline into the frame, and every coordinate of a plan made there back out of it.
void into_frame(kernel::Polygon& outline, const PlanFrame& frame);
void out_of_frame(FloorPlan& plan, const PlanFrame& frame);

// Doors between rooms, on their longest shared segment (§3.3); requests that lost their fit are
// dropped with a warning.
void place_doors(Work& work, FloorPlan& plan, const std::vector<DoorRequest>& doors);
// Entrance doors of rooms flagged `entrance` and of entrance transitions, on the ground storey's
// open-air walls; when the building has none, one on the room with the longest open-air wall.
void place_entrances(Work& work, FloorPlan& plan);
// §3.4: add or remove room outline vertices toward the requested number of walls (plan_shape.cc).
void adapt_room_shapes(Work& work, FloorPlan& plan);
// Stair transitions: a straight flight inside both rooms (plan_stairs.cc).
void place_stairs(Work& work, FloorPlan& plan);
// Adds a stair between reachable room `lower` (storey level) and room `upper` (level + 1) when
// one fits; returns whether it did.
bool add_stair(Work& work, FloorPlan& plan, int level, int lower, int upper,
               const std::string& symbol, Location where, bool added);
// Every room reachable from an entrance through doors and stairs, doors and stairs added where
// they fit (when `repair`); the rest listed in FloorPlan::unreachable_rooms with the reason
// (plan_reach.cc).
void guarantee_reachability(Work& work, FloorPlan& plan, bool repair);
// An entrance door on the longest open-air wall of ground-storey room `room` that fits one (a
// piece of the footprint no door reaches, after fake-concave split it); false when none fits.
bool add_entrance(Work& work, FloorPlan& plan, int room);
// Windows on open-air walls, as many as asked where they fit.
void place_windows(Work& work, FloorPlan& plan);
// Rooms that fit the lot (plan_fit.cc): true when no disc of diameter `width` fits in `cell`.
bool narrower_than(const kernel::Polygon& cell, double width);
// Merges room `x` of storey `level` into the neighbour (among `allowed`, all when empty) it
// shares the longest wall with, same part first; its doors, entrance and stairs go with it, a
// door between the two is removed, rooms are renumbered. False when no neighbour unites with it.
bool merge_room(Work& work, FloorPlan& plan, int level, int x, const std::vector<bool>& allowed,
                const std::string& why);
// Turns room `x` into a dead zone, with its openings and stairs removed.
void drop_room(Work& work, FloorPlan& plan, int level, int x, const std::string& why);
// Every room below Restrictions::min_room_area or min_room_width merged into a neighbour, or
// dropped when it touches none (smallest first).
void fit_rooms(Work& work, FloorPlan& plan);
// Walls from the final cells, wall indices of every opening, rooms' neighbours (plan_walls.cc).
void build_walls(Work& work, FloorPlan& plan);

}  // namespace insula::lang::bldg::plan
