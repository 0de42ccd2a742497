// Walls of one storey (seed 000, §3.4: "inner and outer walls are raised until a certain height
// [...] Then, frames for doors and windows are created"; §4.1 "the walls are extruded considering
// the doors and windows previously flagged").
//
// Every boundary piece of the floor plan (floorplan.h, PlanWall) becomes one closed wall solid
// built by kernel/wall.h with its door and window openings cut through it:
//  - a piece between two rooms is an inner wall centred on the cell boundary;
//  - a piece on the exterior (or on a dead zone) is an outer wall standing inside the room's cell,
//    its outer face on the outline.
// Corners: an inner wall is lengthened by half its thickness at a free end (filling the corner of
// two inner walls, or reaching the middle of the wall it meets) and shortened by half the outer
// thickness where it meets the outline (its end stays buried in the outer wall, never flush with
// the facade). An outer wall is lengthened by its thickness at a reflex corner of the outline,
// where two walls standing inside would otherwise leave a square hole.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>

#include "kernel/opening_frame.h"
#include "kernel/planar.h"
#include "kernel/polygon.h"
#include "kernel/wall.h"
#include "lang/bldg/builder_detail.h"

namespace insula::lang::bldg::detail {
namespace {

constexpr double kTouch = 1e-6;       // m: endpoints closer than this are the same point
constexpr double kOpeningTop = 0.05;  // m: least wall above an opening, below the ceiling slab

bool outer_side(const PlanWall& wall) {
  return wall.right == kExteriorSide || wall.right == kDeadZoneSide;
}

// An outer piece with its bounding box grown by kTouch (a cheap test before the distance).
struct OuterWall {
  const PlanWall* wall;
  Vec2 lo;
  Vec2 hi;

  bool near(Vec2 p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
};

// The storey's outer pieces (exterior or dead-zone side), listed once per storey: the corner tests
// below look at them for every piece, and the inner pieces are most of the storey's walls.
// on_outline's question is asked for both ends of every inner piece, so the pieces are also listed
// per column: the x range of the outline is cut into as many columns as there are pieces, and a
// piece is listed in every column its box spans.
struct Outline {
  std::vector<OuterWall> pieces;  // in plan order (next_outer and previous_outer take the first)
  double x0 = 0;                  // left edge of column 0
  double column_width = 1;
  std::size_t columns = 0;
  std::vector<std::uint32_t> column_start;  // column c lists column_items[start[c], start[c + 1])
  std::vector<std::uint32_t> column_items;  // indices into pieces
  // The pieces' starts (by_start) or ends (by_end) with the piece's index, ordered by x, ties in
  // plan order: next_outer and previous_outer look only at the points whose x is close, read from
  // these arrays rather than through the pieces.
  struct End {
    Vec2 p;
    std::uint32_t piece;
  };
  std::vector<End> by_start;
  std::vector<End> by_end;

  // The column of x, clamped to the existing ones (monotone in x, so a box [lo, hi] is listed in
  // every column of a point inside it).
  std::size_t column(double x) const {
    const double c = std::floor((x - x0) / column_width);
    if (!(c > 0)) return 0;
    return static_cast<std::size_t>(std::min(c, static_cast<double>(columns - 1)));
  }

  void index_columns() {
    if (pieces.empty()) return;
    double x1 = pieces.front().hi.x;
    x0 = pieces.front().lo.x;
    for (const OuterWall& w : pieces) x0 = std::min(x0, w.lo.x), x1 = std::max(x1, w.hi.x);
    columns = pieces.size();
    column_width = std::max((x1 - x0) / static_cast<double>(columns), 1e-3);
    column_start.assign(columns + 2, 0);
    for (const OuterWall& w : pieces) {  // count, then place (a counting sort)
      for (std::size_t c = column(w.lo.x); c <= column(w.hi.x); ++c) ++column_start[c + 2];
    }
    for (std::size_t c = 2; c < column_start.size(); ++c) column_start[c] += column_start[c - 1];
    column_items.resize(column_start.back());
    for (std::uint32_t i = 0; i < pieces.size(); ++i) {
      for (std::size_t c = column(pieces[i].lo.x); c <= column(pieces[i].hi.x); ++c) {
        column_items[column_start[c + 1]++] = i;
      }
    }
  }
};

Outline outer_walls(const PlanStorey& storey) {
  Outline out;
  for (const PlanWall& w : storey.walls) {
    if (!outer_side(w)) continue;
    out.pieces.push_back({&w,
                          {std::min(w.a.x, w.b.x) - kTouch, std::min(w.a.y, w.b.y) - kTouch},
                          {std::max(w.a.x, w.b.x) + kTouch, std::max(w.a.y, w.b.y) + kTouch}});
  }
  out.index_columns();
  for (auto [order, end] : {std::pair{&out.by_start, false}, std::pair{&out.by_end, true}}) {
    order->resize(out.pieces.size());
    for (std::uint32_t i = 0; i < order->size(); ++i) {
      const PlanWall& w = *out.pieces[i].wall;
      (*order)[i] = {end ? w.b : w.a, i};
    }
    std::sort(order->begin(), order->end(), [](const Outline::End& e, const Outline::End& f) {
      return e.p.x < f.p.x || (e.p.x == f.p.x && e.piece < f.piece);
    });
  }
  return out;
}

// A point of the storey's outline (an outer wall's reference line). Only the pieces listed in p's
// column can have p in their box.
bool on_outline(const Outline& outline, Vec2 p) {
  if (outline.pieces.empty()) return false;
  const std::size_t c = outline.column(p.x);
  for (std::uint32_t k = outline.column_start[c]; k < outline.column_start[c + 1]; ++k) {
    const OuterWall& w = outline.pieces[outline.column_items[k]];
    if (w.near(p) &&
        kernel::squared_distance_to_segment(p, w.wall->a, w.wall->b) < kTouch * kTouch) {
      return true;
    }
  }
  return false;
}

// The first outer piece in plan order, other than `wall`, whose start (or end, with `end`) lies
// within kTouch of p along both axes; null if none. Only the pieces whose x lies within 4 kTouch
// kTouch of p.x are looked at (a superset of those passing the exact test, which is applied as it
// stands to each of them).
const PlanWall* outer_piece_at(const Outline& outline, const PlanWall& wall, Vec2 p, bool end) {
  const std::vector<Outline::End>& order = end ? outline.by_end : outline.by_start;
  auto it = std::lower_bound(order.begin(), order.end(), p.x - 4 * kTouch,
                             [](const Outline::End& e, double x) { return e.p.x < x; });
  std::uint32_t best = static_cast<std::uint32_t>(outline.pieces.size());
  for (; it != order.end() && it->p.x <= p.x + 4 * kTouch; ++it) {
    const Vec2 q = it->p;
    if (it->piece < best && outline.pieces[it->piece].wall != &wall &&
        std::abs(q.x - p.x) < kTouch && std::abs(q.y - p.y) < kTouch) {
      best = it->piece;
    }
  }
  return best < outline.pieces.size() ? outline.pieces[best].wall : nullptr;
}

// The outer piece that starts where `wall` ends (its successor along the outline), or null.
const PlanWall* next_outer(const Outline& outline, const PlanWall& wall) {
  return outer_piece_at(outline, wall, wall.b, false);
}
const PlanWall* previous_outer(const Outline& outline, const PlanWall& wall) {
  return outer_piece_at(outline, wall, wall.a, true);
}

bool reflex(Vec2 incoming, Vec2 outgoing) {
  return kernel::cross(incoming, outgoing) < -1e-9;
}

WallGeometry place(const Outline& outer, const PlanWall& wall, double outer_thickness) {
  WallGeometry g;
  const double length = kernel::length(wall.b - wall.a);
  g.dir = (wall.b - wall.a) / length;
  g.left = kernel::perp(g.dir);
  g.thickness = wall.thickness;
  g.exterior = outer_side(wall);
  double extend_start = 0;
  double extend_end = 0;
  if (g.exterior) {
    g.offset0 = 0;
    g.offset1 = g.thickness;
    const PlanWall* next = next_outer(outer, wall);
    const PlanWall* previous = previous_outer(outer, wall);
    if (next != nullptr && reflex(g.dir, kernel::normalized(next->b - next->a))) {
      extend_end = g.thickness;
    }
    if (previous != nullptr && reflex(kernel::normalized(previous->b - previous->a), g.dir)) {
      extend_start = g.thickness;
    }
  } else {
    g.offset0 = -g.thickness / 2;
    g.offset1 = g.thickness / 2;
    extend_start = on_outline(outer, wall.a) ? -outer_thickness / 2 : g.thickness / 2;
    extend_end = on_outline(outer, wall.b) ? -outer_thickness / 2 : g.thickness / 2;
  }
  g.reaches_past = g.exterior && (extend_start > 0 || extend_end > 0);
  g.start = wall.a - g.dir * extend_start;
  g.length = length + extend_start + extend_end;
  g.footprint = g.rect(0, g.length, g.offset0, g.offset1);
  g.box = kernel::bounds(g.footprint.outer);
  return g;
}

// One opening asked of a wall piece.
struct Asked {
  kernel::Opening opening;  // u and width set once the wall is placed, from a and b
  bool door = false;
  bool entrance = false;
  const PlanDoor* plan_door = nullptr;  // doors and entrances
  Vec2 a;                               // the opening's ends on the cell boundary
  Vec2 b;
};

kernel::WallFaceTags wall_tags(bool exterior, std::uint32_t& face_id) {
  kernel::WallFaceTags tags;
  tags.front.semantic =
      exterior ? SemanticClass::kWallSurface : SemanticClass::kInteriorWallSurface;
  for (FaceTag* tag : {&tags.front, &tags.back, &tags.jamb, &tags.sill, &tags.lintel, &tags.top,
                       &tags.bottom, &tags.end}) {
    tag->face_id = face_id++;
  }
  return tags;
}

// The wall's footprint in the plan, with gaps where doors go through it.
void plan_wall(const WallGeometry& g, std::vector<std::pair<double, double>>& gaps,
               shape::StoreyPlan& plan) {
  std::sort(gaps.begin(), gaps.end());
  double u = 0;
  for (const auto& [g0, g1] : gaps) {
    if (g0 > u + kTouch) plan.walls.push_back({g.rect(u, g0, g.offset0, g.offset1), g.exterior});
    u = std::max(u, g1);
  }
  if (g.length > u + kTouch) {
    plan.walls.push_back({g.rect(u, g.length, g.offset0, g.offset1), g.exterior});
  }
}

void plan_door(const WallGeometry& g, const PlanWall& wall, const Asked& asked,
               shape::StoreyPlan& plan) {
  // The leaf swings into room_a, hinged on the face of the wall on that side.
  const bool into_left = wall.left == asked.plan_door->room_a;
  const double across = into_left ? g.offset1 : g.offset0;
  shape::PlanOpening o;
  o.kind = asked.entrance ? shape::PlanOpeningKind::kEntrance : shape::PlanOpeningKind::kDoor;
  o.a = g.at(asked.opening.u, across);
  o.b = g.at(asked.opening.u + asked.opening.width, across);
  o.swing = into_left ? g.left : -g.left;
  plan.openings.push_back(o);
}

}  // namespace

StoreyWalls build_walls(const Context& c, int s, kernel::Mesh& mesh, shape::StoreyPlan& plan) {
  const PlanStorey& storey = c.plan.storeys[static_cast<std::size_t>(s)];
  const double z0 = c.floor_z(s);
  const double h = c.storey_height(s);
  const double slab = c.options.slab_thickness;
  StoreyWalls out;
  out.room_walls.resize(storey.rooms.size());
  for (std::size_t i = 0; i < storey.walls.size(); ++i) {
    for (const int room : {storey.walls[i].left, storey.walls[i].right}) {
      if (room >= 0 && static_cast<std::size_t>(room) < storey.rooms.size()) {
        out.room_walls[static_cast<std::size_t>(room)].push_back(static_cast<int>(i));
      }
    }
  }
  // The openings asked of each wall, in one array grouped by wall (a counting sort that keeps
  // doors, entrances, then windows in their plan order within a wall): no vector per wall.
  const std::size_t wall_count = storey.walls.size();
  const auto wall_of = [&](int wall) {
    return wall >= 0 && static_cast<std::size_t>(wall) < wall_count ? static_cast<std::size_t>(wall)
                                                                    : wall_count;
  };
  std::vector<std::uint32_t> asked_start(wall_count + 2, 0);
  for (const PlanDoor& d : storey.doors) ++asked_start[wall_of(d.wall) + 1];
  for (const PlanDoor& d : storey.entrances) ++asked_start[wall_of(d.wall) + 1];
  for (const PlanWindow& w : storey.windows) ++asked_start[wall_of(w.wall) + 1];
  for (std::size_t i = 0; i + 1 < asked_start.size(); ++i) asked_start[i + 1] += asked_start[i];
  std::vector<Asked> asked(asked_start[wall_count]);
  std::vector<std::uint32_t> asked_fill(asked_start.begin(), asked_start.end() - 2);
  const auto add_door = [&](const PlanDoor& d, bool entrance) {
    const std::size_t wall = wall_of(d.wall);
    if (wall == wall_count) return;
    const double height =
        std::min(d.height > 0 ? d.height : c.rules.door_height, h - 2 * slab - kOpeningTop);
    asked[asked_fill[wall]++] = {{0, slab, 0, height, 0, 8}, true, entrance, &d, d.a, d.b};
  };
  for (const PlanDoor& d : storey.doors) add_door(d, false);
  for (const PlanDoor& d : storey.entrances) add_door(d, true);
  for (const PlanWindow& w : storey.windows) {
    const std::size_t wall = wall_of(w.wall);
    if (wall == wall_count) continue;
    const double sill = slab + w.sill;
    const double height = std::min(w.height, h - slab - kOpeningTop - sill);
    asked[asked_fill[wall]++] = {{0, sill, 0, height, 0, 8}, false, false, nullptr, w.a, w.b};
  }
  std::vector<std::pair<double, double>> gaps;  // per wall, reused
  std::uint32_t face_id = 0;
  const Outline outer = outer_walls(storey);
  out.walls.reserve(storey.walls.size());
  // Room for the whole storey at once (the mesh would otherwise regrow a dozen times): a plain wall
  // is 8 vertices and 6 faces, an opening adds 8 vertices and 4 faces, and its frames 6 (door) or
  // 9 (window) boxes of 8 vertices and 6 faces.
  const std::size_t doors = storey.doors.size() + storey.entrances.size();
  const std::size_t windows = storey.windows.size();
  const std::size_t boxes = c.options.frames ? 6 * doors + 9 * windows : 0;
  const std::size_t faces = 8 * storey.walls.size() + 6 * (doors + windows) + 6 * boxes;
  mesh.reserve(mesh.vertex_count() + 8 * (storey.walls.size() + doors + windows + boxes),
               mesh.face_count() + faces, 4 * (mesh.face_count() + faces));
  // Frame portals (§4.1) on both faces of the wall; a window also gets a glass pane, a door none.
  kernel::FrameProfile profile;
  profile.width = c.options.frame_width;
  profile.depth = c.options.frame_depth;
  profile.pane = 0.02;
  profile.leaf = 0;
  const kernel::FrameTags door_tags{{SemanticClass::kDoor, kFrameMaterial, 0}, {}};
  const kernel::FrameTags window_tags{{SemanticClass::kWindow, kFrameMaterial, 0},
                                      {SemanticClass::kWindow, kGlassMaterial, 0}};
  kernel::WallSpec spec;            // reused: its vectors keep their storage from wall to wall
  kernel::WallWorkspace workspace;  // likewise the wall kernel's intermediate arrays
  spec.policy = kernel::OpeningPolicy::kSkip;
  for (std::size_t i = 0; i < storey.walls.size(); ++i) {
    const PlanWall& wall = storey.walls[i];
    out.walls.push_back(place(outer, wall, c.rules.outer_wall_thickness));
    const WallGeometry& g = out.walls.back();  // out.walls is reserved: stays in place
    if (!(g.length > kTouch) || !(g.thickness > 0)) continue;
    spec.openings.clear();
    spec.thickness = g.thickness;
    spec.tags = wall_tags(wall.exterior(), face_id);
    spec.outline = {{0, 0}, {g.length, 0}, {g.length, h}, {0, h}};
    const std::span<Asked> wall_asked(asked.data() + asked_start[i],
                                      asked_start[i + 1] - asked_start[i]);
    for (Asked& a : wall_asked) {
      const double u0 = g.u_of(a.a);
      const double u1 = g.u_of(a.b);
      a.opening.u = std::min(u0, u1);
      a.opening.width = std::abs(u1 - u0);
      spec.openings.push_back(a.opening);
    }
    const auto frame = kernel::place_wall_frame(
        kernel::lift(g.start, z0), kernel::lift(g.start + g.dir * g.length, z0), h, g.thickness,
        g.exterior ? kernel::WallAlignment::kInside : kernel::WallAlignment::kCenter);
    if (!frame) continue;
    // Appended straight into the storey's mesh: no mesh allocated and copied per wall.
    const kernel::WallResult& built = kernel::build_wall(spec, *frame, mesh, workspace);
    if (!built.ok()) {
      c.warn("storey " + std::to_string(storey.level) + ": wall " + std::to_string(i) +
             " of room '" + storey.rooms[static_cast<std::size_t>(wall.left)].symbol +
             "' could not be built: " + built.message);
      continue;
    }
    for (const kernel::OpeningIssue& issue : built.issues) {
      const Asked& a = wall_asked[issue.opening];
      c.warn("storey " + std::to_string(storey.level) + ": " +
             (a.door ? (a.entrance ? "entrance" : "door") : "window") + " in the wall of room '" +
             storey.rooms[static_cast<std::size_t>(wall.left)].symbol +
             "' left out: " + issue.message);
    }
    ++c.result.stats.walls;
    gaps.clear();
    for (std::size_t k : built.cut) {
      const Asked& a = wall_asked[k];
      if (c.options.frames) {
        kernel::add_opening_frame(mesh, *frame, g.thickness, a.opening,
                                  a.door ? kernel::FrameKind::kDoor : kernel::FrameKind::kWindow,
                                  profile, a.door ? door_tags : window_tags);
      }
      if (a.door) {
        gaps.emplace_back(a.opening.u, a.opening.u + a.opening.width);
        plan_door(g, wall, a, plan);
        ++(a.entrance ? c.result.stats.entrances : c.result.stats.doors);
        const double reach = c.options.frame_depth + c.options.footer_depth + 0.05;
        out.door_gaps.push_back(g.rect(a.opening.u, a.opening.u + a.opening.width,
                                       g.offset0 - reach, g.offset1 + reach));
      } else {
        const double mid = (g.offset0 + g.offset1) / 2;
        shape::PlanOpening o;
        o.kind = shape::PlanOpeningKind::kWindow;
        o.a = g.at(a.opening.u, mid);
        o.b = g.at(a.opening.u + a.opening.width, mid);
        o.swing = g.left;
        plan.openings.push_back(o);
        ++c.result.stats.windows;
      }
    }
    plan_wall(g, gaps, plan);
  }
  return out;
}

}  // namespace insula::lang::bldg::detail
