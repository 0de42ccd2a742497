// The plain-wall shortcut (wall_detail.h): a common wall's boundary and pieces written directly.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/wall_detail.h"

namespace insula::kernel::wall_detail {

// The plain-wall shortcut of build_wall. A plain wall is an outline (x0, y0), (x1, y0), (x1, y1),
// (x0, y1) (counter-clockwise from the lower-left corner, as place_wall and the bldg builder make
// it) with rectangular openings that stand clear of the outline and whose u-ranges lie side by
// side, each beyond the margin of the next. Most walls of a building are such. For them the general
// stages have a known outcome, produced here directly (the same boundary, the same loops in the
// same order):
//  - validation accepts every opening (a gap beyond the margin, with slack for the rounding of the
//    general path's distances; boxes apart along u fail touches exactly as there), so
//    `cut` is every opening in input order and opening i is boundary ring i + 1 (vertices 4 + 4i
//    ..);
//  - the sweep (de Berg section 3.2, along +u) meets vertices 0 (start) and 3, then opening after
//    opening by u, each with its lower-left corner a as a split vertex (diagonal to the helper of
//    the bottom edge: vertex 3 for the first opening, the previous opening's upper-right corner c
//    after that) and c as a merge vertex, then vertex 1 (diagonal to the last c);
//  - the walk from half-edge 0 then closes piece 1 = 0, 1, then c, d, a of each opening from the
//    last to the first, then 3, and piece 2 = 1, 2, 3, then a, b, c of each opening from the first.
// A wall that differs in any way takes the general path; tests/kernel/wall_plain_test.cc builds
// random walls both ways and compares them. Kept because it is the common wall and skips most of
// the work (docs/PERFORMANCE.md, "Kernel primitives once").

bool plain_wall(const Ring& ccw, const WallSpec& spec, std::vector<PlainOpening>& sorted) {
  sorted.clear();
  if (ccw.size() != 4) return false;
  const double x0 = ccw[0].x, y0 = ccw[0].y, x1 = ccw[2].x, y1 = ccw[2].y;
  if (!(ccw[1].x == x1 && ccw[1].y == y0 && ccw[3].x == x0 && ccw[3].y == y1 && x0 < x1 &&
        y0 < y1)) {
    return false;
  }
  // The general path's distances err by a few units in the last place of the coordinates; a gap
  // this much beyond `reach` is beyond the margin (and kEps) there too.
  const double reach = std::max(spec.min_margin, kEps);
  const double scale = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
  const double clear = reach + 1e-9 * (reach + scale);
  for (std::size_t i = 0; i < spec.openings.size(); ++i) {
    const Opening& o = spec.openings[i];
    if (o.arch_rise != 0 || !parameter_problem(o).empty()) return false;
    const double u1 = o.u + o.width;
    const double top = o.sill + o.height;  // fill_ring's top without an arch
    if (!(o.u - x0 > clear && x1 - u1 > clear && o.sill - y0 > clear && y1 - top > clear)) {
      return false;
    }
    sorted.push_back({o.u, u1, static_cast<std::uint32_t>(i)});
  }
  std::sort(sorted.begin(), sorted.end(),
            [](const PlainOpening& a, const PlainOpening& b) { return a.u0 < b.u0; });
  // Neighbours farther apart along u than against_opening's pad are never compared there.
  const double pad = spec.min_margin + kEps;
  for (std::size_t j = 1; j < sorted.size(); ++j) {
    if (!(sorted[j].u0 > sorted[j - 1].u1 + pad)) return false;
  }
  return true;
}

// build_boundary's rings for a plain wall: the outline's edges are bottom, end, top, end
// (rim_kind), each opening's left jamb, lintel, right jamb and sill (add_opening_edges). Written in
// place, every ring a run of four vertices; `prev` stays empty (only the sweep reads it).
void plain_boundary(const Ring& ccw, const WallSpec& spec, Boundary& b) {
  const std::size_t n = 4 + 4 * spec.openings.size();
  b.prev.clear();  // resized, not cleared: the arrays' old entries are overwritten, not zeroed
  b.points.resize(n);
  b.next.resize(n);
  b.kind.resize(n);
  b.opening.resize(n);
  b.ring_start = static_cast<std::uint32_t>(n);
  const auto ring = [&b](std::uint32_t first, std::array<Vec2, 4> corners,
                         std::array<EdgeKind, 4> kinds, std::int32_t opening) {
    for (std::uint32_t k = 0; k < 4; ++k) {
      b.points[first + k] = corners[k];
      b.next[first + k] = first + (k + 1) % 4;
      b.kind[first + k] = kinds[k];
      b.opening[first + k] = opening;
    }
  };
  ring(0, {ccw[0], ccw[1], ccw[2], ccw[3]},
       {EdgeKind::kBottom, EdgeKind::kEnd, EdgeKind::kTop, EdgeKind::kEnd}, -1);
  for (std::size_t i = 0; i < spec.openings.size(); ++i) {
    const Opening& o = spec.openings[i];
    const double u1 = o.u + o.width;
    const double top = o.sill + o.height;
    ring(static_cast<std::uint32_t>(4 + 4 * i),
         {Vec2{o.u, o.sill}, {o.u, top}, {u1, top}, {u1, o.sill}},
         {EdgeKind::kJamb, EdgeKind::kLintel, EdgeKind::kJamb, EdgeKind::kSill},
         static_cast<std::int32_t>(i));
  }
}

// The pieces' loops of a plain wall (see above), written in place: without openings one piece,
// the outline; else two pieces of 3 + 3k vertices for k openings.
void plain_loops(const std::vector<PlainOpening>& sorted, std::vector<std::uint32_t>& loops,
                 std::vector<std::uint32_t>& offsets) {
  if (sorted.empty()) {
    loops.assign({0, 1, 2, 3});
    offsets.assign({0, 4});
    return;
  }
  const auto piece = static_cast<std::uint32_t>(3 + 3 * sorted.size());
  loops.resize(2 * piece);
  offsets.assign({0, piece, 2 * piece});
  std::uint32_t* lower = loops.data();
  std::uint32_t* upper = lower + piece;
  *lower++ = 0, *lower++ = 1;
  *upper++ = 1, *upper++ = 2, *upper++ = 3;
  for (std::size_t j = 0; j < sorted.size(); ++j) {
    const std::uint32_t below = 4 + 4 * sorted[sorted.size() - 1 - j].index;  // right to left
    *lower++ = below + 2, *lower++ = below + 3, *lower++ = below;
    const std::uint32_t above = 4 + 4 * sorted[j].index;  // left to right
    *upper++ = above, *upper++ = above + 1, *upper++ = above + 2;
  }
  *lower = 3;
}

}  // namespace insula::kernel::wall_detail
