#include "lang/bldg/plan_openings.h"

#include <algorithm>
#include <cmath>

#include "kernel/planar.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;
using kernel::Vec2;

// Depth of the area in front of a door that must stay clear of stairs on both sides (m).
constexpr double kDoorApproach = 0.9;

struct Interval {
  double lo;
  double hi;
};

// Appends the interval (metres from p) of opening a..b to `out` when it lies on the line through p
// with unit direction u (both ends within 0.1 mm of it).
void add_if_on_line(Vec2 p, Vec2 u, Vec2 a, Vec2 b, std::vector<Interval>& out) {
  if (std::abs(kernel::cross(u, a - p)) > 1e-4 || std::abs(kernel::cross(u, b - p)) > 1e-4) return;
  const double sa = kernel::dot(a - p, u);
  const double sb = kernel::dot(b - p, u);
  out.push_back({std::min(sa, sb), std::max(sa, sb)});
}

// Intervals of the line through p with unit direction u (metres from p) occupied by openings of
// the storey on that line, into `out` (cleared first).
void occupied(const PlanStorey& storey, Vec2 p, Vec2 u, std::vector<Interval>& out) {
  out.clear();
  for (const PlanDoor& d : storey.doors) add_if_on_line(p, u, d.a, d.b, out);
  for (const PlanDoor& d : storey.entrances) add_if_on_line(p, u, d.a, d.b, out);
  for (const PlanWindow& w : storey.windows) add_if_on_line(p, u, w.a, w.b, out);
}

// The same intervals in the same order, the openings found through the index when the line is
// horizontal or vertical. On a horizontal line (u.y == 0, u.x == +-1) cross(u, a - p) is exactly
// +-(a.y - p.y), so an opening on the line has its first end's y within 1e-4 of p.y (0.2 mm taken,
// for rounding): those are the candidates, tested as the scan tests them, in the scan's order.
// Vertical lines likewise with x; oblique ones scan every opening.
void occupied(OpeningIndex& index, Vec2 p, Vec2 u, std::vector<Interval>& out) {
  if (u.x != 0 && u.y != 0) {
    occupied(index.storey(), p, u, out);
    return;
  }
  std::vector<std::uint32_t> near;
  const bool horizontal = u.y == 0;
  index.near(horizontal, horizontal ? p.y : p.x, 2e-4, near);
  out.clear();
  const PlanStorey& storey = index.storey();
  for (const std::uint32_t order : near) {
    const std::size_t i = OpeningIndex::index(order);
    switch (OpeningIndex::kind(order)) {
      case 0:
        add_if_on_line(p, u, storey.doors[i].a, storey.doors[i].b, out);
        break;
      case 1:
        add_if_on_line(p, u, storey.entrances[i].a, storey.entrances[i].b, out);
        break;
      default:
        add_if_on_line(p, u, storey.windows[i].a, storey.windows[i].b, out);
        break;
    }
  }
}

bool clear_of(const std::vector<Polygon>& keep_out, const Polygon& zone) {
  return std::none_of(keep_out.begin(), keep_out.end(),
                      [&](const Polygon& k) { return convex_overlap(k, zone); });
}

}  // namespace

StoreyCells::StoreyCells(const PlanStorey& storey) : storey_(&storey) {
  others_.reserve(storey.rooms.size() + storey.dead_zones.size());
  for (const PlanRoom& r : storey.rooms) others_.push_back(&r.cell);
  for (const PlanDeadZone& z : storey.dead_zones) others_.push_back(&z.cell);
  boxes_.reserve(others_.size());
  for (const Polygon* cell : others_) boxes_.push_back(kernel::bounds(*cell));
  near_ = touching_boxes(boxes_, kLineTolerance);
  pieces_.resize(others_.size());
  done_.assign(others_.size(), false);
}

const std::vector<EdgePiece>& StoreyCells::pieces(int index) const {
  const auto i = static_cast<std::size_t>(index);
  if (done_[i]) return pieces_[i];
  // The touching lists leave the cell itself out, as boundary_pieces does with a null entry.
  pieces_[i] = boundary_pieces(*others_[i], others_, boxes_, near_.of(i));
  done_[i] = true;
  return pieces_[i];
}

std::vector<EdgePiece> room_pieces(const PlanStorey& storey, int room) {
  // One room's pieces: the cells whose boxes touch its box found by a scan of every box (the list
  // StoreyCells' touching lists hold for it, in the same increasing order), without their
  // storey-wide sweep. The room itself is left out as a null entry.
  std::vector<const Polygon*> others;
  std::vector<kernel::Bounds2> boxes;
  for (const PlanRoom& r : storey.rooms) others.push_back(&r.cell);
  for (const PlanDeadZone& z : storey.dead_zones) others.push_back(&z.cell);
  for (const Polygon* cell : others) boxes.push_back(kernel::bounds(*cell));
  const auto i = static_cast<std::size_t>(room);
  others[i] = nullptr;
  return boundary_pieces(storey.rooms[i].cell, boxes[i], others, boxes);
}

namespace {

// find_slot with the openings listed by `list_occupied(p, u, out)` (one of the occupied above).
template <typename Occupied>
std::optional<Slot> find_slot_with(const Occupied& list_occupied, Vec2 p, Vec2 q, double width,
                                   double clearance, const std::vector<Polygon>& keep_out,
                                   double prefer) {
  const double len = edge_length(q - p);
  const double target = prefer >= 0 ? prefer : len / 2;
  if (len < width + 2 * clearance) return std::nullopt;
  const Vec2 u = (q - p) / len;
  std::vector<Interval> busy;
  list_occupied(p, u, busy);
  std::vector<Interval> free{{clearance, len - clearance}};
  std::vector<Interval> next;
  for (const Interval& o : busy) {
    next.clear();
    for (const Interval& f : free) {
      const double lo = o.lo - clearance;
      const double hi = o.hi + clearance;
      if (hi <= f.lo || lo >= f.hi) {
        next.push_back(f);
        continue;
      }
      if (lo > f.lo) next.push_back({f.lo, lo});
      if (hi < f.hi) next.push_back({hi, f.hi});
    }
    std::swap(free, next);
  }
  // Candidates: the position nearest the middle in each free interval, then positions sliding
  // away from it, so a stair beside the middle does not rule the wall out.
  std::vector<double> centres;
  // Without keep-out areas the first candidate is taken: the earliest listed of those nearest the
  // target, which is what the stable sort below puts first, found without listing or sorting.
  const bool first_wins = keep_out.empty();
  double best = 0;
  bool have_best = false;
  auto consider = [&](double c) {
    if (!first_wins) {
      centres.push_back(c);
    } else if (!have_best || std::abs(c - target) < std::abs(best - target)) {
      best = c;
      have_best = true;
    }
  };
  for (const Interval& f : free) {
    if (f.hi - f.lo < width - 1e-9) continue;
    const double lo = f.lo + width / 2;
    const double hi = f.hi - width / 2;
    consider(std::clamp(target, lo, hi));
    // The sliding positions lie in [lo, hi], none strictly nearer the target than the clamped
    // one listed before them: only a keep-out area can make them matter.
    if (first_wins) continue;
    for (double s = lo; s <= hi + 1e-9; s += 0.25) consider(std::min(s, hi));
  }
  if (first_wins) {
    if (!have_best) return std::nullopt;
    return Slot{p + u * (best - width / 2), p + u * (best + width / 2), p + u * best};
  }
  std::stable_sort(centres.begin(), centres.end(),
                   [&](double x, double y) { return std::abs(x - target) < std::abs(y - target); });
  const Vec2 n = kernel::perp(u);
  for (double c : centres) {
    const Vec2 a = p + u * (c - width / 2);
    if (!keep_out.empty()) {
      const Polygon zone =
          oriented_rectangle(a - n * kDoorApproach, u, n, width, 2 * kDoorApproach);
      if (!clear_of(keep_out, zone)) continue;
    }
    return Slot{a, p + u * (c + width / 2), p + u * c};
  }
  return std::nullopt;
}

}  // namespace

void OpeningIndex::merge(Axis& axis) {
  // The recent entries (a few) sorted by insertion, then merged from the back into the grown list.
  std::vector<Entry>& r = axis.recent;
  for (std::size_t a = 1; a < r.size(); ++a)
    for (std::size_t b = a; b > 0 && r[b - 1].key > r[b].key; --b) std::swap(r[b - 1], r[b]);
  std::vector<Entry>& s = axis.sorted;
  std::size_t i = s.size();
  std::size_t j = r.size();
  s.resize(s.size() + r.size());
  for (std::size_t k = s.size(); j > 0;)
    s[--k] = (i > 0 && s[i - 1].key > r[j - 1].key) ? s[--i] : r[--j];
  r.clear();
}

void OpeningIndex::sync() {
  const PlanStorey& s = *storey_;
  if (s.doors.size() < doors_ || s.entrances.size() < entrances_ ||
      s.windows.size() < windows_) {  // not only appended: listed again
    by_y_ = {};
    by_x_ = {};
    doors_ = entrances_ = windows_ = 0;
  }
  // An opening can lie on a horizontal line (both ends within 1e-4 of it) only when its ends' y
  // differ by 2e-4 at most, on a vertical one likewise with x: each is listed under the axes it
  // can be found on (3e-4 taken, for rounding).
  auto add = [&](Vec2 a, Vec2 b, std::uint32_t order) {
    if (std::abs(a.y - b.y) <= 3e-4) by_y_.recent.push_back({a.y, order});
    if (std::abs(a.x - b.x) <= 3e-4) by_x_.recent.push_back({a.x, order});
  };
  for (; doors_ < s.doors.size(); ++doors_)
    add(s.doors[doors_].a, s.doors[doors_].b, static_cast<std::uint32_t>(doors_));
  for (; entrances_ < s.entrances.size(); ++entrances_)
    add(s.entrances[entrances_].a, s.entrances[entrances_].b,
        (1u << 30) | static_cast<std::uint32_t>(entrances_));
  for (; windows_ < s.windows.size(); ++windows_)
    add(s.windows[windows_].a, s.windows[windows_].b,
        (2u << 30) | static_cast<std::uint32_t>(windows_));
  if (by_y_.recent.size() >= kMergeAt) merge(by_y_);
  if (by_x_.recent.size() >= kMergeAt) merge(by_x_);
}

void OpeningIndex::near(bool by_y, double at, double margin, std::vector<std::uint32_t>& out) {
  sync();
  out.clear();
  const Axis& axis = by_y ? by_y_ : by_x_;
  const double lo = at - margin;
  const double hi = at + margin;
  auto it = std::lower_bound(axis.sorted.begin(), axis.sorted.end(), lo,
                             [](const Entry& e, double k) { return e.key < k; });
  for (; it != axis.sorted.end() && it->key <= hi; ++it) out.push_back(it->order);
  for (const Entry& e : axis.recent)
    if (e.key >= lo && e.key <= hi) out.push_back(e.order);
  // Few candidates (the openings of one wall line): insertion sort into listing order.
  for (std::size_t a = 1; a < out.size(); ++a)
    for (std::size_t b = a; b > 0 && out[b - 1] > out[b]; --b) std::swap(out[b - 1], out[b]);
}

std::optional<Slot> find_slot(const PlanStorey& storey, Vec2 p, Vec2 q, double width,
                              double clearance, const std::vector<Polygon>& keep_out,
                              double prefer) {
  return find_slot_with(
      [&](Vec2 from, Vec2 u, std::vector<Interval>& out) { occupied(storey, from, u, out); }, p, q,
      width, clearance, keep_out, prefer);
}

std::optional<Slot> find_slot(OpeningIndex& openings, Vec2 p, Vec2 q, double width,
                              double clearance, const std::vector<Polygon>& keep_out,
                              double prefer) {
  return find_slot_with(
      [&](Vec2 from, Vec2 u, std::vector<Interval>& out) { occupied(openings, from, u, out); }, p,
      q, width, clearance, keep_out, prefer);
}

bool opening_on(const Polygon& cell, Vec2 a, Vec2 b, double clearance) {
  constexpr double kTol = 1e-5;
  auto check_ring = [&](const kernel::Ring& ring) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 p = ring[i];
      const Vec2 q = ring[(i + 1) % n];
      if (kernel::distance_to_segment(a, p, q) > kTol ||
          kernel::distance_to_segment(b, p, q) > kTol)
        continue;
      // On this edge: the opening keeps `clearance` from both ends of the edge.
      const Vec2 u = kernel::normalized(q - p);
      const double sa = kernel::dot(a - p, u);
      const double sb = kernel::dot(b - p, u);
      const double len = kernel::length(q - p);
      return std::min(sa, sb) >= clearance - kTol && std::max(sa, sb) <= len - clearance + kTol;
    }
    return false;
  };
  if (check_ring(cell.outer)) return true;
  return std::any_of(cell.holes.begin(), cell.holes.end(), check_ring);
}

bool openings_intact(const PlanStorey& storey, const std::vector<int>& rooms, double clearance) {
  auto touches = [&](int r) { return std::find(rooms.begin(), rooms.end(), r) != rooms.end(); };
  auto door_ok = [&](const PlanDoor& d) {
    if (!touches(d.room_a) && !(d.room_b >= 0 && touches(d.room_b))) return true;
    if (!opening_on(storey.rooms[d.room_a].cell, d.a, d.b, clearance)) return false;
    return d.room_b < 0 || opening_on(storey.rooms[d.room_b].cell, d.a, d.b, clearance);
  };
  return std::all_of(storey.doors.begin(), storey.doors.end(), door_ok) &&
         std::all_of(storey.entrances.begin(), storey.entrances.end(), door_ok) &&
         std::all_of(storey.windows.begin(), storey.windows.end(), [&](const PlanWindow& w) {
           return !touches(w.room) || opening_on(storey.rooms[w.room].cell, w.a, w.b, clearance);
         });
}

namespace {

// door_between with the slots found by `slot_on(piece)` (one of the find_slot above).
template <typename SlotOn>
std::optional<PlanDoor> door_with(const PlanStorey& storey, int a, int b, double width,
                                  const SlotOn& slot_on) {
  std::vector<EdgePiece> shared = shared_segments(storey.rooms[a].cell, storey.rooms[b].cell);
  // Longest first, ties in boundary order.
  std::stable_sort(shared.begin(), shared.end(),
                   [](const EdgePiece& x, const EdgePiece& y) { return x.length() > y.length(); });
  for (const EdgePiece& piece : shared) {
    const std::optional<Slot> slot = slot_on(piece);
    if (!slot) continue;
    PlanDoor door;
    door.room_a = a;
    door.room_b = b;
    door.a = slot->a;
    door.b = slot->b;
    door.center = slot->center;
    door.width = width;
    return door;
  }
  return std::nullopt;
}

}  // namespace

std::optional<PlanDoor> door_between(const PlanStorey& storey, int a, int b, double width,
                                     double clearance, const std::vector<Polygon>& keep_out) {
  return door_with(storey, a, b, width, [&](const EdgePiece& piece) {
    return find_slot(storey, piece.a, piece.b, width, clearance, keep_out);
  });
}

std::optional<PlanDoor> door_between(OpeningIndex& openings, int a, int b, double width,
                                     double clearance, const std::vector<Polygon>& keep_out) {
  return door_with(openings.storey(), a, b, width, [&](const EdgePiece& piece) {
    return find_slot(openings, piece.a, piece.b, width, clearance, keep_out);
  });
}

namespace {

// The exterior pieces of `pieces` (a room's boundary pieces) that face the open air.
std::vector<EdgePiece> open_air_of(const PlanStorey& storey, const std::vector<EdgePiece>& pieces,
                                   const std::vector<Polygon>& footprint) {
  std::vector<EdgePiece> out;
  for (const EdgePiece& piece : pieces) {
    if (piece.other >= 0) continue;
    const Vec2 u = kernel::normalized(piece.b - piece.a);
    const Vec2 outside = (piece.a + piece.b) * 0.5 - kernel::perp(u) * 0.01;
    // A point outside a polygon's box (by more than the tolerance) is not inside it: the box test
    // spares most point-in-polygon tests.
    auto inside = [&](const Polygon& polygon) {
      kernel::Bounds2 point;
      point.min = outside;
      point.max = outside;
      return kernel::touches(point, kernel::bounds(polygon), 1e-6) &&
             kernel::locate(polygon, outside, 1e-7) == kernel::PointLocation::kInside;
    };
    bool covered = false;
    for (const Polygon& f : footprint) covered = covered || inside(f);
    bool dead = false;
    for (const PlanDeadZone& z : storey.dead_zones) dead = dead || inside(z.cell);
    if (!covered && !dead) out.push_back(piece);
  }
  return out;
}

}  // namespace

std::vector<EdgePiece> open_air_pieces(const PlanStorey& storey, int room,
                                       const std::vector<Polygon>& footprint) {
  return open_air_of(storey, room_pieces(storey, room), footprint);
}

std::vector<EdgePiece> open_air_pieces(const PlanStorey& storey, const StoreyCells& cells, int room,
                                       const std::vector<Polygon>& footprint) {
  return open_air_of(storey, cells.pieces(room), footprint);
}

std::vector<Polygon> stair_keep_out(const FloorPlan& plan, int level) {
  std::vector<Polygon> out;
  if (level >= 0 && level < static_cast<int>(plan.storeys.size()))
    for (const PlanStair& s : plan.storeys[level].stairs) out.push_back(s.footprint);
  if (level >= 1)
    for (const PlanStair& s : plan.storeys[level - 1].stairs) out.push_back(s.footprint);
  return out;
}

}  // namespace insula::lang::bldg::plan
