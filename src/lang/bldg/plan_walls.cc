// Walls of the final plan: every boundary piece of every cell once, with the rooms on both sides
// (floorplan.h, PlanWall), then the wall each opening sits on and the rooms' door neighbours.
#include <algorithm>
#include <optional>

#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/plan_openings.h"
#include "lang/bldg/plan_stages.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;

void storey_walls(const Restrictions& r, const StoreyCells& cells, PlanStorey& storey) {
  const int rooms = static_cast<int>(storey.rooms.size());
  // At most one wall per piece: the list is sized once rather than grown.
  std::size_t pieces_total = 0;
  for (int i = 0; i < cells.size(); ++i) pieces_total += cells.pieces(i).size();
  storey.walls.reserve(storey.walls.size() + pieces_total);
  for (int i = 0; i < cells.size(); ++i) {
    const bool dead = i >= rooms;
    const std::vector<EdgePiece>& pieces = cells.pieces(i);
    for (const EdgePiece& piece : pieces) {
      PlanWall wall;
      wall.a = piece.a;
      wall.b = piece.b;
      wall.left = dead ? kDeadZoneSide : i;
      if (piece.other < 0) {
        wall.right = kExteriorSide;
      } else if (piece.other >= rooms) {
        if (dead) continue;  // between two dead zones: no wall
        wall.right = kDeadZoneSide;
      } else {
        if (dead || piece.other < i) continue;  // listed from the other side
        wall.right = piece.other;
      }
      wall.thickness =
          wall.right == kExteriorSide ? r.outer_wall_thickness : r.inner_wall_thickness;
      storey.walls.push_back(wall);
    }
  }
}

// The walls of each room of a storey (as left or right side), in increasing wall index: room r's
// are index[start[r] .. start[r + 1]). Two lists for the storey (a counting pass, then a fill),
// not one per room.
struct WallsByRoom {
  std::vector<int> start;
  std::vector<int> index;
};

WallsByRoom walls_by_room(const PlanStorey& storey) {
  const int rooms = static_cast<int>(storey.rooms.size());
  auto for_each_side = [&](auto&& visit) {
    for (std::size_t w = 0; w < storey.walls.size(); ++w) {
      const PlanWall& wall = storey.walls[w];
      if (wall.left >= 0 && wall.left < rooms) visit(wall.left, static_cast<int>(w));
      if (wall.right >= 0 && wall.right < rooms && wall.right != wall.left)
        visit(wall.right, static_cast<int>(w));
    }
  };
  WallsByRoom out;
  out.start.assign(storey.rooms.size() + 1, 0);
  for_each_side([&](int room, int) { ++out.start[room + 1]; });
  for (int r = 0; r < rooms; ++r) out.start[r + 1] += out.start[r];
  out.index.resize(out.start[rooms]);
  std::vector<int> fill(out.start.begin(), out.start.end() - 1);
  for_each_side([&](int room, int wall) { out.index[fill[room]++] = wall; });
  return out;
}

// The first wall (lowest index) between room a (a room of the storey) and side b through
// `centre`; only room a's walls are scanned, which finds the same first wall as a scan of all.
int wall_of(const PlanStorey& storey, const WallsByRoom& by_room, int a, int b,
            kernel::Vec2 centre) {
  if (a < 0 || a + 1 >= static_cast<int>(by_room.start.size())) return -1;
  for (int k = by_room.start[a]; k < by_room.start[a + 1]; ++k) {
    const int w = by_room.index[k];
    const PlanWall& wall = storey.walls[w];
    const bool sides = (wall.left == a && wall.right == b) || (wall.left == b && wall.right == a);
    if (sides && kernel::distance_to_segment(centre, wall.a, wall.b) < 1e-5) return w;
  }
  return -1;
}

// Puts an opening's points exactly on its wall's line (welding may have moved the wall by a few
// micrometres since the opening was placed).
void onto_wall(const PlanWall& wall, kernel::Vec2& a, kernel::Vec2& b, kernel::Vec2& centre) {
  const kernel::Vec2 d = wall.b - wall.a;
  const double len2 = kernel::dot(d, d);
  if (len2 <= 0) return;
  for (kernel::Vec2* p : {&a, &b, &centre}) *p = wall.a + d * (kernel::dot(*p - wall.a, d) / len2);
}

}  // namespace

void build_walls(Work& work, FloorPlan& plan) {
  for (std::size_t s = 0; s < plan.storeys.size(); ++s) {
    PlanStorey& storey = plan.storeys[s];
    storey.walls.clear();
    // The pieces place_windows listed, when it ran on these storeys; else listed here.
    const bool cached = s < work.storey_cells.size() && work.storey_cells[s].storey() == &storey;
    std::optional<StoreyCells> fresh;
    if (!cached) fresh.emplace(storey);
    storey_walls(*work.restrictions, cached ? work.storey_cells[s] : *fresh, storey);
    const WallsByRoom by_room = walls_by_room(storey);
    for (PlanDoor& d : storey.doors) {
      d.wall = wall_of(storey, by_room, d.room_a, d.room_b, d.center);
      if (d.wall >= 0) onto_wall(storey.walls[d.wall], d.a, d.b, d.center);
    }
    for (PlanDoor& d : storey.entrances) {
      d.wall = wall_of(storey, by_room, d.room_a, kExteriorSide, d.center);
      if (d.wall >= 0) onto_wall(storey.walls[d.wall], d.a, d.b, d.center);
    }
    for (PlanWindow& w : storey.windows) {
      w.wall = wall_of(storey, by_room, w.room, kExteriorSide, w.center);
      if (w.wall >= 0) onto_wall(storey.walls[w.wall], w.a, w.b, w.center);
    }
    // Each room's neighbour list sized once (its doors), not grown door by door.
    std::vector<std::size_t> doors_of(storey.rooms.size(), 0);
    for (const PlanDoor& d : storey.doors) {
      ++doors_of[d.room_a];
      ++doors_of[d.room_b];
    }
    for (std::size_t r = 0; r < storey.rooms.size(); ++r) {
      PlanRoom& room = storey.rooms[r];
      room.area = kernel::area(room.cell);
      room.walls = wall_count(room.cell);
      room.neighbors.clear();
      room.neighbors.reserve(doors_of[r]);
    }
    for (const PlanDoor& d : storey.doors) {
      storey.rooms[d.room_a].neighbors.push_back(d.room_b);
      storey.rooms[d.room_b].neighbors.push_back(d.room_a);
    }
    for (PlanRoom& room : storey.rooms) {
      std::sort(room.neighbors.begin(), room.neighbors.end());
      room.neighbors.erase(std::unique(room.neighbors.begin(), room.neighbors.end()),
                           room.neighbors.end());
    }
  }
  work.storey_cells.clear();
}

}  // namespace insula::lang::bldg::plan
