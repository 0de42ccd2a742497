// Openings of the floor plan: where a door, an entrance or a window goes on a wall (seed 000, §3.3
// "geometric tests ... to check if there is space to place a transition"), and the checks that
// keep placed openings valid while later stages (room shape adaptation, added doors) edit cells.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "kernel/polygon.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/plan_geometry.h"

namespace insula::lang::bldg::plan {

struct Slot {
  kernel::Vec2 a;
  kernel::Vec2 b;
  kernel::Vec2 center;
};

// The cells of a storey, rooms then dead zones, with their boxes (kernel::bounds), taken once for
// stages that list the boundary pieces of many rooms of the storey while the cells do not change:
// each listing would otherwise recompute the box of every cell. Each cell's pieces are computed on
// first request and kept (the windows and the walls stages ask for the same ones). Holds pointers
// into the storey: valid while its rooms and dead zones are neither moved nor edited.
class StoreyCells {
 public:
  explicit StoreyCells(const PlanStorey& storey);
  // boundary_pieces of cell `index` (a room, or rooms.size() + k for dead zone k) against all the
  // others.
  const std::vector<EdgePiece>& pieces(int index) const;
  int size() const { return static_cast<int>(others_.size()); }
  const PlanStorey* storey() const { return storey_; }

 private:
  const PlanStorey* storey_;
  std::vector<const kernel::Polygon*> others_;
  std::vector<kernel::Bounds2> boxes_;
  NearLists near_;
  mutable std::vector<std::vector<EdgePiece>> pieces_;
  mutable std::vector<bool> done_;
};

// The pieces of room `room`'s boundary with the storey's room index on the other side: -1 for the
// exterior, rooms.size() + k for dead zone k.
std::vector<EdgePiece> room_pieces(const PlanStorey& storey, int room);

// A slot of `width` on segment p->q: `clearance` free at both ends and from every opening of the
// storey on the same line, out of `keep_out` areas (stairs) on both sides of the wall, centred as
// close as possible to `prefer` metres from p (the segment's middle when negative).
std::optional<Slot> find_slot(const PlanStorey& storey, kernel::Vec2 p, kernel::Vec2 q,
                              double width, double clearance,
                              const std::vector<kernel::Polygon>& keep_out = {},
                              double prefer = -1);

// The openings of a storey (doors, entrances, windows) sorted by the y of their first end (those
// lying horizontally) and by its x (those lying vertically), so that find_slot on a horizontal or
// vertical wall visits only those near its line instead of every opening of the storey (the windows
// stage asks once per window). For a stage that only appends openings to the storey while it uses
// the index (each query takes the new ones in); a stage that moves or removes openings must build a
// new index.
class OpeningIndex {
 public:
  explicit OpeningIndex(const PlanStorey& storey) : storey_(&storey) {}
  const PlanStorey& storey() const { return *storey_; }
  // Listing position of the openings whose first end's coordinate (y when by_y, else x) lies
  // within `margin` of `at`, ascending: doors, then entrances, then windows, each in list order
  // (the order find_slot's scan visits them), into `out` (cleared first).
  void near(bool by_y, double at, double margin, std::vector<std::uint32_t>& out);
  // Decodes a listing position of near(): 0 door, 1 entrance, 2 window, and the index in its list.
  static int kind(std::uint32_t order) { return static_cast<int>(order >> 30); }
  static std::size_t index(std::uint32_t order) { return order & ((1u << 30) - 1); }

 private:
  struct Entry {
    double key;
    std::uint32_t order;
  };
  // An axis's entries: `sorted` by key, then the latest additions unsorted in `recent`, merged
  // into `sorted` once there are kMergeAt of them (an insertion per opening moved the whole list).
  struct Axis {
    std::vector<Entry> sorted;
    std::vector<Entry> recent;
  };
  static constexpr std::size_t kMergeAt = 16;
  void sync();
  static void merge(Axis& axis);
  const PlanStorey* storey_;
  Axis by_y_;              // keyed by the first end's y
  Axis by_x_;              // keyed by the first end's x
  std::size_t doors_ = 0;  // how many of each list the index holds
  std::size_t entrances_ = 0;
  std::size_t windows_ = 0;
};

// find_slot with the storey's openings found through `openings` (built on the same storey): the
// same slot.
std::optional<Slot> find_slot(OpeningIndex& openings, kernel::Vec2 p, kernel::Vec2 q, double width,
                              double clearance, const std::vector<kernel::Polygon>& keep_out = {},
                              double prefer = -1);

// True when a..b lies on one straight edge of `cell` with no vertex of the cell within
// `clearance` of it along that edge.
bool opening_on(const kernel::Polygon& cell, kernel::Vec2 a, kernel::Vec2 b, double clearance);

// True when every door and entrance touching one of `rooms` still sits on its wall.
bool openings_intact(const PlanStorey& storey, const std::vector<int>& rooms, double clearance);

// Places a door between rooms a and b of the storey on their longest shared segment where a slot
// fits; nullopt when none does.
std::optional<PlanDoor> door_between(const PlanStorey& storey, int a, int b, double width,
                                     double clearance,
                                     const std::vector<kernel::Polygon>& keep_out = {});
// door_between with the storey's openings found through `openings` (built on that storey): the
// same door.
std::optional<PlanDoor> door_between(OpeningIndex& openings, int a, int b, double width,
                                     double clearance,
                                     const std::vector<kernel::Polygon>& keep_out = {});

// Segments of room `room`'s boundary that face the open air: exterior pieces whose outside is not
// covered by `footprint` (on upper storeys a piece above a lower part's roof is not open air).
std::vector<EdgePiece> open_air_pieces(const PlanStorey& storey, int room,
                                       const std::vector<kernel::Polygon>& footprint);
// The same with the storey's cells taken once (`cells` built from `storey`, unchanged since).
std::vector<EdgePiece> open_air_pieces(const PlanStorey& storey, const StoreyCells& cells, int room,
                                       const std::vector<kernel::Polygon>& footprint);

// Stair footprints that constrain doors of `storey`: its own flights and the stairwells of the
// flights arriving from the storey below.
std::vector<kernel::Polygon> stair_keep_out(const FloorPlan& plan, int level);

}  // namespace insula::lang::bldg::plan
