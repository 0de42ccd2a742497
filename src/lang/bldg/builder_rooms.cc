// Rooms, stairs and the building base (seed 000, §4.1: "Ground and ceilings are also placed in
// each room [...] producing entrance's stairs, rooms' footers"; §3.4 "building base and division
// footers"; §5 asks for several floors, which need stairs).
//
// A room's clear floor is its cell minus the wall footprints around it (kernel/boolean2d.h). It
// gets a floor slab (FloorSurface on top) at the storey's floor level and a ceiling slab
// (CeilingSurface below) under the next floor, both slab_thickness thick, with a stairwell cut
// where a flight arrives from below or leaves upwards; and footers (skirting) along its walls,
// footer_height tall and footer_depth deep, interrupted at door gaps and stairwells. Convex cells
// (the treemap's usual output) are cut by half-planes instead of booleans: the same polygon, about
// twenty times faster (docs/PERFORMANCE.md).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <unordered_set>
#include <utility>

#include "kernel/boolean2d.h"
#include "kernel/planar.h"
#include "lang/bldg/builder_detail.h"

namespace insula::lang::bldg::detail {
namespace {

// Boxes closer than this are taken to meet (m).
constexpr double kSlack = 1e-6;

bool boxes_overlap(const kernel::Bounds2& a, const kernel::Bounds2& b) {
  return kernel::touches(a, b, kSlack);
}

// Do the boxes share interior (not only a side or a corner)?
bool interiors_overlap(const kernel::Bounds2& a, const kernel::Bounds2& b) {
  return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

// The boxes of a storey's door gaps ordered by their left sides: a room finds the gaps whose
// boxes meet its own (boxes_overlap) among the few whose left sides lie within reach of its
// x-range, instead of testing every gap of the storey for every room.
class GapBoxes {
 public:
  explicit GapBoxes(const std::vector<kernel::Bounds2>& boxes) : boxes_(boxes) {
    order_.resize(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) order_[k] = static_cast<std::uint32_t>(k);
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
      return boxes[a].min.x < boxes[b].min.x || (boxes[a].min.x == boxes[b].min.x && a < b);
    });
    lefts_.reserve(boxes.size());
    for (std::uint32_t k : order_) {
      lefts_.push_back(boxes[k].min.x);
      widest_ = std::max(widest_, boxes[k].max.x - boxes[k].min.x);
    }
  }

  // The indices k (increasing) with boxes_overlap(box, boxes[k]), into `out` (cleared).
  void overlapping(const kernel::Bounds2& box, std::vector<std::uint32_t>& out) const {
    out.clear();
    // A gap meeting the box starts at most its width plus the slack (and a micrometre for the
    // rounding of these sums) left of the box, and no further right than boxes_overlap allows;
    // each gap in between still takes the exact test.
    const double from = box.min.x - (widest_ + kSlack + 1e-6);
    const auto first = std::lower_bound(lefts_.begin(), lefts_.end(), from);
    for (auto it = first; it != lefts_.end() && *it <= box.max.x + kSlack; ++it) {
      const std::uint32_t k = order_[static_cast<std::size_t>(it - lefts_.begin())];
      if (boxes_overlap(box, boxes_[k])) out.push_back(k);
    }
    std::sort(out.begin(), out.end());
  }

 private:
  const std::vector<kernel::Bounds2>& boxes_;
  std::vector<std::uint32_t> order_;  // gap indices by the left sides of their boxes
  std::vector<double> lefts_;         // those left sides, in that order
  double widest_ = 0;                 // the widest box along x
};

// The inner face of a wall piece seen from `room`: points p of the room with
// dot(p - origin, normal) >= d.
using Face = kernel::HalfPlane;

Face inner_face(const WallGeometry& g, bool room_on_left) {
  return room_on_left ? Face{g.start, g.left, g.offset1} : Face{g.start, -g.left, -g.offset0};
}

// Per-storey facts and per-room buffers of the room stage, kept across the rooms of a storey so
// that a room costs no temporary allocations of its own (rooms are the stage's inner loop).
struct RoomScratch {
  std::vector<const WallGeometry*> reaching;  // the walls lengthened at reflex corners
  std::vector<Face> faces;
  kernel::Ring ring;
  kernel::Ring cut;
  kernel::Ring probe;
  kernel::Ring probe_cut;
  std::vector<kernel::Polygon> near;
  std::vector<const kernel::Polygon*> gaps;
  std::vector<std::uint32_t> gap_indices;
  std::vector<std::pair<double, double>> blocked;
};

// Drops the vertices of a convex ring that lie on the line through their neighbours (within a
// nanometre), as the boolean path's output has none: a cell's T-junction vertex would otherwise
// split a slab side and a footer in two.
void drop_straight_vertices(kernel::Ring& ring) {
  constexpr double kTolerance = 1e-9;
  bool changed = true;
  while (changed && ring.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < ring.size() && ring.size() >= 3; ++i) {
      const Vec2 a = ring[(i + ring.size() - 1) % ring.size()];
      const Vec2 b = ring[i];
      const Vec2 c = ring[(i + 1) % ring.size()];
      if (std::abs(kernel::cross(b - a, c - a)) <= kTolerance * kernel::length(c - a)) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
}

// Does the convex polygon `wall` (a wall footprint) overlap the convex ring `floor` over more
// than a sliver? (`floor` clipped by the half-planes of `wall`'s edges keeps some area.)
bool reaches_into(const kernel::Ring& floor, const kernel::Ring& wall, RoomScratch& scratch) {
  if (wall.size() < 3) return false;
  kernel::Ring& part = scratch.probe;
  part.assign(floor.begin(), floor.end());
  const double orient = kernel::signed_area(wall) > 0 ? 1 : -1;
  const std::size_t m = wall.size();
  for (std::size_t e = 0; e < m && part.size() >= 3; ++e) {
    const Vec2 dir = (wall[(e + 1) % m] - wall[e]) * orient;
    kernel::clip(part, {wall[e], kernel::perp(dir)}, scratch.probe_cut);
    std::swap(part, scratch.probe_cut);
  }
  return part.size() >= 3 && std::abs(kernel::signed_area(part)) > 1e-10;
}

// The clear floor of a convex cell: the cell cut by the inner face of every wall bordering it
// (exactly the cell minus those walls, since the walls' footprints lie along the cell's edges).
// Not taken (false) when two collinear pieces of one edge stand out differently (a notch the
// half-planes cannot make) or an outer wall lengthened at a reflex corner reaches into the cell:
// then the boolean difference is used. On success `out` holds the clear floor (empty when the
// walls leave nothing).
bool convex_clear_floor(const kernel::Polygon& cell, const kernel::Bounds2& box, int room,
                        const StoreyWalls& walls, const PlanStorey& storey, RoomScratch& scratch,
                        std::vector<kernel::Polygon>& out) {
  if (!cell.holes.empty() || cell.outer.size() < 3 ||
      !kernel::is_convex(cell.outer, kernel::Winding::kCounterClockwise, 1e-12)) {
    return false;
  }
  std::vector<Face>& faces = scratch.faces;
  faces.clear();
  for (int i : walls.room_walls[static_cast<std::size_t>(room)]) {
    const WallGeometry& g = walls.walls[static_cast<std::size_t>(i)];
    if (g.footprint.outer.empty()) continue;
    faces.push_back(inner_face(g, storey.walls[static_cast<std::size_t>(i)].left == room));
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      const bool parallel = kernel::dot(faces[i].normal, faces[j].normal) > 1 - 1e-12;
      const double line_i = kernel::dot(faces[i].origin, faces[i].normal);
      const double line_j = kernel::dot(faces[j].origin, faces[j].normal);
      if (parallel && std::abs(line_i - line_j) < 1e-9 &&
          std::abs(faces[i].offset - faces[j].offset) > 1e-9) {
        return false;
      }
    }
  }
  kernel::Ring& clear = scratch.ring;
  clear.assign(cell.outer.begin(), cell.outer.end());
  for (const Face& f : faces) {
    kernel::clip(clear, f, scratch.cut);
    std::swap(clear, scratch.cut);
    if (clear.size() < 3) return true;
  }
  // A wall lengthened at a reflex corner may reach into what the half-planes left: then only the
  // boolean difference is exact.
  for (const WallGeometry* g : scratch.reaching) {
    if (!boxes_overlap(box, g->box)) continue;
    if (reaches_into(clear, g->footprint.outer, scratch)) return false;
  }
  drop_straight_vertices(clear);
  if (clear.size() < 3) return true;
  kernel::Polygon& floor = out.emplace_back();
  floor.outer = clear;
  if (kernel::area(floor) < 1e-9) out.pop_back();
  return true;
}

// The clear floor of a room: its cell minus the wall footprints around it, into `out` (empty on
// entry); boolean results come largest first.
void clear_floor(const kernel::Polygon& cell, const kernel::Bounds2& box, int room,
                 const StoreyWalls& walls, const PlanStorey& storey, RoomScratch& scratch,
                 std::vector<kernel::Polygon>& out) {
  if (convex_clear_floor(cell, box, room, walls, storey, scratch, out)) return;
  // The walls whose boxes meet the cell's. Those that only touch it cannot take any of its area
  // and stay out of the (costly) boolean; they still widen its integer frame, so the result has
  // the vertices it would have with them.
  std::vector<kernel::Polygon>& near = scratch.near;
  near.clear();
  kernel::Bounds2 frame = box;
  bool any = false;
  for (const WallGeometry& w : walls.walls) {
    if (w.footprint.outer.empty() || !boxes_overlap(box, w.box)) continue;
    any = true;
    frame.add(w.box.min);
    frame.add(w.box.max);
    if (interiors_overlap(box, w.box)) near.push_back(w.footprint);
  }
  if (!any) {
    out.push_back(cell);
    return;
  }
  kernel::BooleanResult r = kernel::subtract({cell}, near, frame);
  if (r.ok()) {
    out = std::move(r.polygons);
  } else {
    out.push_back(cell);
  }
}

// The stretch [u0, u1] along an edge (origin p, unit dir, inward normal n) that `blocker`
// covers within `depth` of the edge, or an empty interval. Most blockers (the door gaps and
// stairwells near a room) miss most of its edges: the extent across the edge is settled first,
// and the stretch along it only measured for those within reach.
std::pair<double, double> covered(const kernel::Polygon& blocker, Vec2 p, Vec2 dir, Vec2 n,
                                  double depth) {
  double a0 = 1e300;
  double a1 = -1e300;
  for (Vec2 v : blocker.outer) {
    a0 = std::min(a0, kernel::dot(v - p, n));
    a1 = std::max(a1, kernel::dot(v - p, n));
  }
  if (a1 < -1e-9 || a0 > depth + 1e-9) return {0, 0};
  double u0 = 1e300;
  double u1 = -1e300;
  for (Vec2 v : blocker.outer) {
    u0 = std::min(u0, kernel::dot(v - p, dir));
    u1 = std::max(u1, kernel::dot(v - p, dir));
  }
  return {u0, u1};
}

// Room footers (§3.4): a strip footer_depth deep and footer_height tall along every edge of the
// clear floor, one box per stretch between door gaps and stairwells.
void add_footers(const std::vector<kernel::Polygon>& clear,
                 const std::vector<const kernel::Polygon*>& gaps, double depth, double z,
                 double height, std::vector<std::pair<double, double>>& blocked,
                 kernel::Mesh& mesh) {
  const FaceTag tag{SemanticClass::kInteriorWallSurface, kFooterMaterial, 4};
  const auto edge_footers = [&](const kernel::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 p = ring[i];
      const double length = kernel::length(ring[(i + 1) % ring.size()] - p);
      if (length < 2 * depth) continue;
      const Vec2 dir = (ring[(i + 1) % ring.size()] - p) / length;
      const Vec2 n = kernel::perp(dir);  // the floor lies left of every ring edge
      blocked.clear();
      for (const kernel::Polygon* g : gaps) {
        const auto [u0, u1] = covered(*g, p, dir, n, depth);
        if (u1 > u0) blocked.emplace_back(u0, u1);
      }
      std::sort(blocked.begin(), blocked.end());
      double u = 0;
      const auto strip = [&](double from, double to) {
        if (to - from < depth) return;
        kernel::add_box(mesh, kernel::lift(p + dir * from, z), kernel::lift(dir * (to - from), 0),
                        kernel::lift(n * depth, 0), Vec3{0, 0, height}, tag);
      };
      for (const auto& [b0, b1] : blocked) {
        strip(u, std::min(b0, length));
        u = std::max(u, b1);
      }
      strip(u, length);
    }
  };
  for (const kernel::Polygon& p : clear) {
    edge_footers(p.outer);
    for (const kernel::Ring& hole : p.holes) edge_footers(hole);
  }
}

// `base`, or base#2, base#3, ... whichever is not `taken` yet; the name returned is added to it.
std::string unique_name(const std::string& base, std::unordered_set<std::string>& taken) {
  std::string name = base;
  for (int k = 2; taken.count(name) != 0; ++k) name = base + "#" + std::to_string(k);
  taken.insert(name);
  return name;
}

}  // namespace

void build_rooms(const Context& c, int s, const StoreyWalls& walls, std::vector<shape::Part>& parts,
                 shape::StoreyPlan& plan) {
  const PlanStorey& storey = c.plan.storeys[static_cast<std::size_t>(s)];
  const double z0 = c.floor_z(s);
  const double h = c.storey_height(s);
  const double slab_thickness = c.options.slab_thickness;
  // Stairwells: flights arriving from the storey below cut this floor; flights leaving upwards cut
  // this storey's ceilings.
  std::vector<kernel::Polygon> floor_holes;
  if (s > 0) {
    for (const PlanStair& st : c.plan.storeys[static_cast<std::size_t>(s - 1)].stairs) {
      floor_holes.push_back(st.footprint);
    }
  }
  std::vector<kernel::Polygon> ceiling_holes;
  for (const PlanStair& st : storey.stairs) ceiling_holes.push_back(st.footprint);
  const FaceTag closure{SemanticClass::kClosureSurface, 0, 0};
  const FaceTag inner{SemanticClass::kInteriorWallSurface, 0, 2};
  // Bounds of every hole list, computed once per storey rather than once per room and hole.
  const auto boxes_of = [](const std::vector<kernel::Polygon>& holes) {
    std::vector<kernel::Bounds2> out;
    out.reserve(holes.size());
    for (const kernel::Polygon& hole : holes) out.push_back(kernel::bounds(hole));
    return out;
  };
  const std::vector<kernel::Bounds2> floor_boxes = boxes_of(floor_holes);
  const std::vector<kernel::Bounds2> ceiling_boxes = boxes_of(ceiling_holes);
  const std::vector<kernel::Bounds2> gap_boxes = boxes_of(walls.door_gaps);
  const GapBoxes gap_finder(gap_boxes);
  RoomScratch scratch;
  for (const WallGeometry& g : walls.walls) {
    if (g.reaches_past) scratch.reaching.push_back(&g);
  }
  std::vector<kernel::Polygon> clear;
  std::unordered_set<std::string> taken;  // the names of `parts`, so far and as rooms are added
  taken.reserve(parts.size() + storey.rooms.size());
  for (const shape::Part& part : parts) taken.insert(part.name);
  for (const PlanRoom& room : storey.rooms) {
    const int index = static_cast<int>(&room - storey.rooms.data());
    const kernel::Bounds2 box = kernel::bounds(room.cell);
    clear.clear();
    clear_floor(room.cell, box, index, walls, storey, scratch, clear);
    shape::Part part;
    part.name = unique_name(room.symbol, taken);
    part.kind = shape::PartKind::kRoom;
    double area = 0;
    for (const kernel::Polygon& p : clear) area += kernel::area(p);
    // In key order, each placed at the end without a search.
    shape::AttributeMap& attributes = part.attributes;
    attributes.emplace_hint(attributes.end(), "area", std::round(area * 1000) / 1000);
    attributes.emplace_hint(attributes.end(), "building_part", room.part);
    attributes.emplace_hint(attributes.end(), "name", room.symbol);
    attributes.emplace_hint(attributes.end(), "storey", static_cast<double>(storey.level));
    attributes.emplace_hint(attributes.end(), "type", room.type);
    const auto near = [&](const std::vector<kernel::Polygon>& holes,
                          const std::vector<kernel::Bounds2>& boxes) {
      std::vector<kernel::Polygon> out;
      for (std::size_t k = 0; k < holes.size(); ++k) {
        if (boxes_overlap(box, boxes[k])) out.push_back(holes[k]);
      }
      return out;
    };
    // A slab over the clear floor minus `holes` (stairwells, a compluvium).
    const auto slab = [&](const std::vector<kernel::Polygon>& holes, double bottom, double top,
                          FaceTag below, FaceTag above) {
      kernel::add_slab(part.mesh, clear, holes, bottom, top, {below, above, inner});
    };
    const std::vector<kernel::Polygon> floor_cut = near(floor_holes, floor_boxes);
    const bool footers =
        c.options.footers && c.rules.footer_height > 0 && c.options.footer_depth > 0;
    std::vector<const kernel::Polygon*>& gaps = scratch.gaps;
    gaps.clear();
    if (footers) {
      gap_finder.overlapping(box, scratch.gap_indices);
      for (std::uint32_t k : scratch.gap_indices) gaps.push_back(&walls.door_gaps[k]);
      for (const kernel::Polygon& hole : floor_cut) gaps.push_back(&hole);
    }
    // Room for the floor and ceiling prisms (2n vertices, n + 2 faces and 6n indices each over n
    // outline vertices) and the footer boxes (8 vertices, 6 faces, 24 indices each): one per edge,
    // plus one more wherever a gap splits an edge (a gap meets at most two), so the mesh grows
    // once.
    std::size_t n = 0;
    for (const kernel::Polygon& p : clear) {
      n += p.outer.size();
      for (const kernel::Ring& hole : p.holes) n += hole.size();
    }
    const std::size_t boxes = footers ? n + 2 * gaps.size() : 0;
    part.mesh.reserve(4 * n + 8 * boxes, 2 * n + 4 + 6 * boxes, 12 * n + 24 * boxes);
    slab(floor_cut, z0, z0 + slab_thickness, closure,
         {SemanticClass::kFloorSurface, kFloorMaterial, 1});
    std::vector<kernel::Polygon> open_above = near(ceiling_holes, ceiling_boxes);
    // Under a compluvium (the part's top storey), the ceiling stays open to the sky.
    const auto compluvium = c.compluvia->find(room.part);
    if (compluvium != c.compluvia->end() && room.part_index >= 0 &&
        static_cast<std::size_t>(room.part_index) < c.plan.parts.size() &&
        c.plan.parts[static_cast<std::size_t>(room.part_index)].storeys == storey.level + 1) {
      for (const kernel::Polygon& hole : near(compluvium->second, boxes_of(compluvium->second)))
        open_above.push_back(hole);
    }
    slab(open_above, z0 + h - slab_thickness, z0 + h, {SemanticClass::kCeilingSurface, 0, 3},
         closure);
    if (footers) {
      add_footers(clear, gaps, c.options.footer_depth, z0 + slab_thickness, c.rules.footer_height,
                  scratch.blocked, part.mesh);
    }
    shape::PlanRoom drawn;
    drawn.name = room.symbol;
    drawn.type = room.type;
    drawn.area = area;
    // Boolean results come largest first. `clear` is refilled for the next room: its first
    // polygon moves into the plan rather than being copied.
    if (!clear.empty()) drawn.outline = std::move(clear.front());
    plan.rooms.push_back(std::move(drawn));
    parts.push_back(std::move(part));
    ++c.result.stats.rooms;
  }
}

void build_stairs(const Context& c, int s, kernel::Mesh& mesh, shape::StoreyPlan& plan) {
  const PlanStorey& storey = c.plan.storeys[static_cast<std::size_t>(s)];
  const bool has_above = static_cast<std::size_t>(s + 1) < c.plan.storeys.size();
  const double rise = has_above ? c.floor_z(s + 1) - c.floor_z(s) : c.storey_height(s);
  for (const PlanStair& st : storey.stairs) {
    const double run = kernel::length(st.head - st.foot);
    if (!(run > 0) || !(rise > 0)) continue;
    const int risers = st.risers > 0 ? st.risers : kernel::stair_steps(rise, kernel::kMaxStepRise);
    // The last step's top is the upper floor's top: the flight starts on this floor's slab.
    kernel::add_staircase(
        mesh,
        {st.foot, (st.head - st.foot) / run, st.width, c.floor_z(s) + c.options.slab_thickness,
         risers, run / risers, rise / risers},
        {SemanticClass::kStair, kStairMaterial, 0});
    plan.stairs.push_back({st.footprint, st.foot, st.head});
    ++c.result.stats.stairs;
  }
  // The flights arriving from below show on this storey's plan too, over their stairwell.
  if (s > 0) {
    for (const PlanStair& st : c.plan.storeys[static_cast<std::size_t>(s - 1)].stairs) {
      plan.stairs.push_back({st.footprint, st.foot, st.head});
    }
  }
}

void build_base(const Context& c, const std::vector<StoreyWalls>& walls, kernel::Mesh& mesh) {
  const double base = c.rules.base_height;
  if (base > 0) {
    const kernel::PrismTags tags{{SemanticClass::kGroundSurface, kPlinthMaterial, 0},
                                 {SemanticClass::kClosureSurface, kPlinthMaterial, 1},
                                 {SemanticClass::kWallSurface, kPlinthMaterial, 2}};
    for (const kernel::Polygon& footprint : c.plan.footprint) {
      if (kernel::add_prism(mesh, footprint, 0, base, tags)) continue;
      // A lot whose courtyard touches its outline (a real OpenStreetMap multipolygon) lost its
      // plinth without a word.
      std::size_t built = 0, pieces = 0;
      for (const kernel::Polygon& piece : simple_pieces(footprint)) {
        ++pieces;
        built += kernel::add_prism(mesh, piece, 0, base, tags) ? 1 : 0;
      }
      if (pieces == 0 || built < pieces) {
        c.warn("base: the plinth could not be built on " +
               std::string(built == 0 ? "the" : "part of the") +
               " footprint (not a simple polygon)");
      }
    }
  }
  if (c.plan.storeys.empty() || walls.empty()) return;
  // Entrance steps (§4.1) outside every entrance door, from the ground up to its threshold.
  const PlanStorey& ground = c.plan.storeys.front();
  const double rise = base + c.options.slab_thickness;
  const int steps = static_cast<int>(std::ceil(rise / c.options.step_rise - 1e-9));
  for (const PlanDoor& e : ground.entrances) {
    if (e.wall < 0 || static_cast<std::size_t>(e.wall) >= walls.front().walls.size()) continue;
    const WallGeometry& g = walls.front().walls[static_cast<std::size_t>(e.wall)];
    const Vec2 outward = -g.left;
    const double depth = steps * c.options.step_run;
    kernel::add_staircase(mesh,
                          {e.center + outward * depth, -outward, e.width + 0.4, 0, steps,
                           c.options.step_run, rise / steps},
                          {SemanticClass::kStair, kStairMaterial, 3});
  }
}

}  // namespace insula::lang::bldg::detail
