// Ear clipping with hole bridging (Eberly 2002; Held 2001), see triangulate.h.
//
// Invariants kept by the clipper:
// - every live ring is a circular doubly linked list of nodes whose interior lies to the left of
//   each directed edge (outer counter-clockwise, holes clockwise before bridging);
// - a node refers to one input vertex; bridges and diagonal splits copy nodes, never vertices, so
//   every emitted index is an input vertex;
// - an ear (a, b, c) is clipped only if b is strictly convex and no other live node lies in the
//   closed triangle, except nodes sitting exactly on a, b or c whose edges stay out of the
//   triangle's corner (bridge copies and rings touching at a vertex).
#include "kernel/triangulate.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace insula::kernel {
namespace {

constexpr std::uint32_t kNone = UINT32_MAX;

double orient(Vec2 a, Vec2 b, Vec2 c) {
  return cross(b - a, c - a);
}

// p strictly between a and b on the line through them.
bool on_open_segment(Vec2 p, Vec2 a, Vec2 b) {
  return orient(a, b, p) == 0 && dot(p - a, b - a) > 0 && dot(p - b, a - b) > 0;
}

// q strictly inside the cone at v swept counter-clockwise from direction v->x to direction v->y
// (the cone is less than a half-turn here: a triangle corner).
bool in_corner(Vec2 v, Vec2 x, Vec2 y, Vec2 q) {
  return orient(v, x, q) > 0 && orient(v, q, y) > 0;
}

// Does the edge c-d obstruct the open segment a-b (a candidate bridge or diagonal)? Edges that
// share an endpoint position with a-b only obstruct it when they overlap it.
bool obstructs(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (on_open_segment(c, a, b) || on_open_segment(d, a, b)) return true;
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  if (c == a || c == b || d == a || d == b) {
    if (o1 != 0 || o2 != 0) return false;
    return on_open_segment(a, c, d) || on_open_segment(b, c, d) || ((c == a) == (d == b));
  }
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

struct Node {
  Vec2 p;  // relative to the polygon's bounding-box minimum, for precision far from the origin
  std::uint32_t vertex = 0;
  std::uint32_t prev = kNone;
  std::uint32_t next = kNone;
  bool alive = true;
};

// Uniform grid over node positions (CSR), plus a short list of nodes created after it was built.
class PointGrid {
 public:
  void build(const std::vector<Node>& nodes, Vec2 size) {
    extra_.clear();
    // A few nodes are all looked at: an ear test's answer does not depend on which nodes outside
    // its box it visits, and building the grid cost more than the tests it saved.
    everything_ = nodes.size() <= kEverything ? std::uint32_t(nodes.size()) : 0;
    if (everything_ > 0) return;
    const double n = double(std::max<std::size_t>(nodes.size(), 1));
    const double w = std::max(size.x, 1e-300), h = std::max(size.y, 1e-300);
    cell_ = std::max({std::sqrt(w * h / n), w / 1024.0, h / 1024.0});
    nx_ = std::clamp(int(w / cell_) + 1, 1, 1025);
    ny_ = std::clamp(int(h / cell_) + 1, 1, 1025);
    start_.assign(std::size_t(nx_) * std::size_t(ny_) + 1, 0);
    for (const Node& node : nodes) ++start_[cell(node.p) + 1];
    for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
    items_.resize(nodes.size());
    fill_.assign(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < nodes.size(); ++i) items_[fill_[cell(nodes[i].p)]++] = i;
  }
  void add_late(std::uint32_t id) { extra_.push_back(id); }

  // Calls f(id) for every node in cells overlapping [lo, hi]; stops early when f returns false.
  template <typename F>
  bool visit(Vec2 lo, Vec2 hi, F&& f) const {
    for (std::uint32_t id = 0; id < everything_; ++id)
      if (!f(id)) return false;
    if (everything_ > 0) {
      for (std::uint32_t id : extra_)
        if (!f(id)) return false;
      return true;
    }
    const int x0 = cx(lo.x), x1 = cx(hi.x), y0 = cy(lo.y), y1 = cy(hi.y);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const std::size_t c = std::size_t(y) * std::size_t(nx_) + std::size_t(x);
        for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k)
          if (!f(items_[k])) return false;
      }
    }
    for (std::uint32_t id : extra_)
      if (!f(id)) return false;
    return true;
  }

 private:
  int cx(double x) const { return std::clamp(int(x / cell_), 0, nx_ - 1); }
  int cy(double y) const { return std::clamp(int(y / cell_), 0, ny_ - 1); }
  std::size_t cell(Vec2 p) const { return std::size_t(cy(p.y)) * std::size_t(nx_) + cx(p.x); }

  static constexpr std::size_t kEverything = 32;
  std::uint32_t everything_ = 0;  // when not 0: no grid, every node below it is visited
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> start_, items_, extra_, fill_;
};

// The triangulator's working memory, kept per thread from call to call: the writers triangulate
// every concave face of a city one at a time, and allocating it anew cost more than most of
// those faces' clipping.
struct Scratch {
  std::vector<Node> nodes;
  PointGrid grid;
  Ring shifted;
  std::vector<std::uint32_t> holes;
  std::vector<std::uint32_t> work;
};

class Triangulator {
 public:
  Triangulator(Triangulation& out, Scratch& scratch)
      : out_(out), nodes_(scratch.nodes), grid_(scratch.grid), scratch_(scratch) {
    nodes_.clear();
  }

  TriangulationStatus run(const Polygon& polygon);

 private:
  // --- list plumbing
  Node& at(std::uint32_t i) { return nodes_[i]; }
  Vec2 pos(std::uint32_t i) const { return nodes_[i].p; }
  std::uint32_t next(std::uint32_t i) const { return nodes_[i].next; }
  std::uint32_t prev(std::uint32_t i) const { return nodes_[i].prev; }
  std::optional<std::uint32_t> build_ring(const Ring& ring, std::uint32_t base, bool ccw);
  void remove(std::uint32_t i);
  std::uint32_t copy(std::uint32_t i);
  std::uint32_t split(std::uint32_t a, std::uint32_t b);
  std::size_t count(std::uint32_t start) const;

  // --- holes
  bool eliminate_holes(std::uint32_t outer, std::vector<std::uint32_t> holes);
  std::optional<std::uint32_t> find_bridge(std::uint32_t hole, std::uint32_t outer,
                                           const std::vector<std::uint32_t>& unmerged);
  bool locally_inside(std::uint32_t a, Vec2 b) const;
  bool list_obstructs(Vec2 a, Vec2 b, std::uint32_t start) const;

  // --- clipping
  bool clip_all(std::uint32_t start);
  bool is_ear(std::uint32_t ear) const;
  bool corner_blocked(std::uint32_t other, Vec2 v, Vec2 x, Vec2 y) const;
  std::uint32_t filter(std::uint32_t start);
  std::optional<std::pair<std::uint32_t, std::uint32_t>> split_at_pinch(std::uint32_t start);
  double list_area(std::uint32_t start) const;
  bool split_touched_edges(std::uint32_t start);
  std::optional<std::pair<std::uint32_t, std::uint32_t>> find_diagonal(std::uint32_t start);
  bool drop_straight_vertex(std::uint32_t& start);

  Triangulation& out_;
  std::vector<Node>& nodes_;
  PointGrid& grid_;
  Scratch& scratch_;
  Vec2 origin_;
  std::uint64_t budget_ = 0;  // elementary steps left before giving up on pathological input
};

std::optional<std::uint32_t> Triangulator::build_ring(const Ring& ring, std::uint32_t base,
                                                      bool ccw) {
  const std::size_t n = ring.size();
  const bool reverse = (signed_area(ring) > 0) != ccw;
  const std::size_t first = nodes_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = reverse ? n - 1 - k : k;
    const Vec2 p = ring[i] - origin_;
    if (nodes_.size() > first && nodes_.back().p == p) continue;
    nodes_.push_back(Node{p, base + std::uint32_t(i)});
  }
  while (nodes_.size() > first + 1 && nodes_.back().p == nodes_[first].p) nodes_.pop_back();
  const std::size_t m = nodes_.size() - first;
  Ring& shifted = scratch_.shifted;
  shifted.clear();
  for (std::size_t i = first; i < nodes_.size(); ++i) shifted.push_back(nodes_[i].p);
  if (m < 3 || signed_area(shifted) == 0) {
    nodes_.resize(first);
    return std::nullopt;
  }
  for (std::size_t i = 0; i < m; ++i) {
    nodes_[first + i].prev = std::uint32_t(first + (i + m - 1) % m);
    nodes_[first + i].next = std::uint32_t(first + (i + 1) % m);
  }
  return std::uint32_t(first);
}

void Triangulator::remove(std::uint32_t i) {
  at(prev(i)).next = next(i);
  at(next(i)).prev = prev(i);
  at(i).alive = false;
}

std::uint32_t Triangulator::copy(std::uint32_t i) {
  nodes_.push_back(Node{nodes_[i].p, nodes_[i].vertex});
  const auto id = std::uint32_t(nodes_.size() - 1);
  grid_.add_late(id);  // before the grid is built this is discarded by build()
  return id;
}

// Joins a and b by a pair of opposite edges. If a and b are on one list it splits into two lists,
// (a, b, ...) and (b', a', ...); if on two lists (a bridge to a hole) they merge into one. Returns
// b's copy, which lies on the second list in the first case.
std::uint32_t Triangulator::split(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t a2 = copy(a), b2 = copy(b);
  const std::uint32_t an = next(a), bp = prev(b);
  at(a).next = b;
  at(b).prev = a;
  at(a2).next = an;
  at(an).prev = a2;
  at(b2).next = a2;
  at(a2).prev = b2;
  at(bp).next = b2;
  at(b2).prev = bp;
  return b2;
}

std::size_t Triangulator::count(std::uint32_t start) const {
  std::size_t n = 0;
  std::uint32_t i = start;
  do {
    ++n;
    i = next(i);
  } while (i != start);
  return n;
}

// ---- holes ------------------------------------------------------------------------------------

// Is direction a->b strictly inside the interior angle at node a (interior on the left)?
bool Triangulator::locally_inside(std::uint32_t a, Vec2 b) const {
  const Vec2 v = pos(a), p = pos(prev(a)), n = pos(next(a));
  if (orient(p, v, n) > 0) return orient(v, n, b) > 0 && orient(v, b, p) > 0;
  return orient(v, p, b) < 0 || orient(v, b, n) < 0;
}

bool Triangulator::list_obstructs(Vec2 a, Vec2 b, std::uint32_t start) const {
  std::uint32_t e = start;
  do {
    if (obstructs(a, b, pos(e), pos(next(e)))) return true;
    e = next(e);
  } while (e != start);
  return false;
}

// The nearest vertex of the merged outer list that sees the hole's leftmost vertex. Holes are
// merged in order of their leftmost x, so the leftward ray from it first meets the merged list and
// such a vertex exists (Eberly 2002, section 3); the nearest one gives the shortest bridge.
std::optional<std::uint32_t> Triangulator::find_bridge(std::uint32_t hole, std::uint32_t outer,
                                                       const std::vector<std::uint32_t>& unmerged) {
  const Vec2 m = pos(hole);
  std::vector<std::pair<double, std::uint32_t>> candidates;
  std::uint32_t i = outer;
  do {
    const Vec2 d = pos(i) - m;
    candidates.emplace_back(dot(d, d), i);
    i = next(i);
  } while (i != outer);
  std::sort(candidates.begin(), candidates.end());
  for (const auto& candidate : candidates) {
    const double distance2 = candidate.first;
    const std::uint32_t v = candidate.second;
    if (budget_ < candidates.size()) return std::nullopt;
    budget_ -= candidates.size();
    if (distance2 == 0) {
      // The hole touches the outer list here: a zero-length bridge, valid if the hole's edges
      // leave into this copy's interior angle.
      if (locally_inside(v, pos(next(hole))) && locally_inside(v, pos(prev(hole)))) return v;
      continue;
    }
    if (!locally_inside(v, m) || !locally_inside(hole, pos(v))) continue;
    if (list_obstructs(m, pos(v), outer)) continue;
    const bool blocked = std::any_of(unmerged.begin(), unmerged.end(),
                                     [&](std::uint32_t h) { return list_obstructs(m, pos(v), h); });
    if (!blocked) return v;
  }
  return std::nullopt;
}

bool Triangulator::eliminate_holes(std::uint32_t outer, std::vector<std::uint32_t> holes) {
  // Each hole is represented by its leftmost (then lowest) node.
  for (std::uint32_t& h : holes) {
    std::uint32_t best = h, i = h;
    do {
      if (pos(i).x < pos(best).x || (pos(i).x == pos(best).x && pos(i).y < pos(best).y)) best = i;
      i = next(i);
    } while (i != h);
    h = best;
  }
  std::sort(holes.begin(), holes.end(), [&](std::uint32_t a, std::uint32_t b) {
    return pos(a).x < pos(b).x || (pos(a).x == pos(b).x && pos(a).y < pos(b).y);
  });
  for (std::size_t k = 0; k < holes.size(); ++k) {
    const std::vector<std::uint32_t> unmerged(holes.begin() + std::ptrdiff_t(k), holes.end());
    // The leftmost vertex nearly always sees the merged list. It may not when it lies inside an
    // outer edge (a T-touch): then any other vertex of the hole that does is fine.
    std::uint32_t from = holes[k];
    std::optional<std::uint32_t> bridge = find_bridge(from, outer, unmerged);
    while (!bridge && next(from) != holes[k]) {
      from = next(from);
      bridge = find_bridge(from, outer, unmerged);
    }
    if (!bridge) return false;
    split(*bridge, from);
  }
  return true;
}

// ---- clipping ---------------------------------------------------------------------------------

// A node `other` sits exactly on corner v of the candidate ear, whose corner spans from v->x
// counter-clockwise to v->y. The ear is blocked if one of `other`'s edges enters that corner, or if
// `other`'s own interior angle covers it (two sheets of the list overlapping there, as in what is
// left of a bridge after clipping around it): the triangle's centroid lies inside every corner.
bool Triangulator::corner_blocked(std::uint32_t other, Vec2 v, Vec2 x, Vec2 y) const {
  if (in_corner(v, x, y, pos(prev(other))) || in_corner(v, x, y, pos(next(other)))) return true;
  return locally_inside(other, (v + x + y) / 3.0);
}

bool Triangulator::is_ear(std::uint32_t ear) const {
  const std::uint32_t ia = prev(ear), ic = next(ear);
  const Vec2 a = pos(ia), b = pos(ear), c = pos(ic);
  if (orient(a, b, c) <= 0) return false;
  const Vec2 lo{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y})};
  const Vec2 hi{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y})};
  return grid_.visit(lo, hi, [&](std::uint32_t id) {
    if (id == ia || id == ear || id == ic || !nodes_[id].alive) return true;
    const Vec2 p = pos(id);
    if (p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y) return true;
    if (p == a) return !corner_blocked(id, a, b, c);
    if (p == b) return !corner_blocked(id, b, c, a);
    if (p == c) return !corner_blocked(id, c, a, b);
    return !(orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0);
  });
}

// Removes nodes repeating their successor's position and zero-width spikes; returns a live node.
std::uint32_t Triangulator::filter(std::uint32_t start) {
  std::uint32_t p = start, end = start;
  for (;;) {
    if (next(p) == p || next(next(p)) == p) return p;
    const Vec2 q = pos(prev(p)), v = pos(p), n = pos(next(p));
    const bool spike = orient(q, v, n) == 0 && dot(q - v, n - v) > 0;
    if (v == n || spike) {
      const std::uint32_t back = prev(p);
      remove(p);
      p = end = back;
      continue;
    }
    p = next(p);
    if (p == end) return p;
  }
}

double Triangulator::list_area(std::uint32_t start) const {
  double twice = 0;
  std::uint32_t i = start;
  do {
    twice += cross(pos(i), pos(next(i)));
    i = next(i);
  } while (i != start);
  return 0.5 * twice;
}

// Two nodes of one list at the same position (rings touching at a vertex, or what is left of a
// bridge) can make the list a figure eight whose lobes have no ear that the other lobe's sheet
// does not block. Exchanging the successors of the two nodes cuts the list into its two lobes;
// the cut is kept only if both lobes have positive area, so bridges to holes are never undone.
// Returns one node of each lobe.
std::optional<std::pair<std::uint32_t, std::uint32_t>> Triangulator::split_at_pinch(
    std::uint32_t start) {
  std::vector<std::uint32_t> order;
  std::uint32_t i = start;
  do {
    order.push_back(i);
    i = next(i);
  } while (i != start);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return pos(a).x < pos(b).x || (pos(a).x == pos(b).x && pos(a).y < pos(b).y);
  });
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    const std::uint32_t u = order[k], w = order[k + 1];
    if (pos(u) != pos(w)) continue;
    if (budget_ < order.size()) return std::nullopt;
    budget_ -= order.size();
    const std::uint32_t u1 = next(u), w1 = next(w);
    auto relink = [&](std::uint32_t a, std::uint32_t a1, std::uint32_t b, std::uint32_t b1) {
      at(a).next = b1;
      at(b1).prev = a;
      at(b).next = a1;
      at(a1).prev = b;
    };
    relink(u, u1, w, w1);
    if (list_area(u) > 0 && list_area(w) > 0) return std::pair{u, w};
    relink(u, w1, w, u1);  // undo
  }
  return std::nullopt;
}

// A vertex lying inside another edge of the same list (rings touching at a T, or a hole vertex
// on the outer ring) hides every ear along that edge; splitting the edge at a copy of the vertex
// turns the T into an ordinary touching vertex. O(n^2), only when stuck.
bool Triangulator::split_touched_edges(std::uint32_t start) {
  bool changed = false;
  std::uint32_t p = start;
  do {
    std::uint32_t e = start;
    do {
      const std::uint32_t f = next(e);
      if (budget_ > 0) --budget_;
      if (e != p && f != p && on_open_segment(pos(p), pos(e), pos(f))) {
        const std::uint32_t t = copy(p);
        at(t).prev = e;
        at(t).next = f;
        at(e).next = t;
        at(f).prev = t;
        changed = true;
      }
      e = next(e);
    } while (e != start && budget_ > 0);
    p = next(p);
  } while (p != start && budget_ > 0);
  return changed;
}

std::optional<std::pair<std::uint32_t, std::uint32_t>> Triangulator::find_diagonal(
    std::uint32_t start) {
  const std::size_t n = count(start);
  std::uint32_t a = start;
  do {
    for (std::uint32_t b = next(next(a)); b != prev(a); b = next(b)) {
      if (budget_ < n) return std::nullopt;
      budget_ -= n;
      if (pos(a) == pos(b) || !locally_inside(a, pos(b)) || !locally_inside(b, pos(a))) continue;
      if (!list_obstructs(pos(a), pos(b), start)) return std::pair{a, b};
    }
    a = next(a);
  } while (a != start);
  return std::nullopt;
}

// Last resort: drops one straight-angle vertex (between its neighbours). The area is unchanged;
// the vertex is then missing from the triangulation.
bool Triangulator::drop_straight_vertex(std::uint32_t& start) {
  std::uint32_t p = start;
  do {
    if (orient(pos(prev(p)), pos(p), pos(next(p))) == 0) {
      start = prev(p);
      remove(p);
      return true;
    }
    p = next(p);
  } while (p != start);
  return false;
}

bool Triangulator::clip_all(std::uint32_t start) {
  std::vector<std::uint32_t>& work = scratch_.work;
  work.assign(1, filter(start));
  while (!work.empty()) {
    std::uint32_t ear = work.back(), stop = ear;
    work.pop_back();
    int stage = 0;
    while (prev(ear) != next(ear)) {
      if (budget_ == 0) return false;
      --budget_;
      const std::uint32_t a = prev(ear), c = next(ear);
      if (is_ear(ear)) {
        out_.triangles.push_back({nodes_[a].vertex, nodes_[ear].vertex, nodes_[c].vertex});
        remove(ear);
        // Continuing two steps on avoids fans of slivers around one vertex.
        ear = stop = next(c);
        stage = 0;
        continue;
      }
      ear = c;
      if (ear != stop) continue;
      // A full turn without an ear: escalate.
      if (stage == 0) {
        ear = stop = filter(ear);
      } else if (stage == 1) {
        if (const auto lobes = split_at_pinch(ear)) {
          work.push_back(filter(lobes->first));
          work.push_back(filter(lobes->second));
          break;
        }
      } else if (stage == 2) {
        split_touched_edges(ear);
      } else if (stage == 3) {
        if (const auto d = find_diagonal(ear)) {
          const std::uint32_t b2 = split(d->first, d->second);
          work.push_back(filter(d->first));
          work.push_back(filter(b2));
          break;
        }
      } else if (!drop_straight_vertex(ear)) {
        return false;
      } else {
        stop = ear;
        stage = -1;
      }
      ++stage;
    }
    // A finished list leaves one or two nodes behind; they must not block ears of other lists.
    if (prev(ear) == next(ear)) {
      at(next(ear)).alive = false;
      at(ear).alive = false;
    }
  }
  return true;
}

TriangulationStatus Triangulator::run(const Polygon& polygon) {
  out_.vertices = polygon.outer;
  for (const Ring& hole : polygon.holes)
    out_.vertices.insert(out_.vertices.end(), hole.begin(), hole.end());
  for (const Vec2& v : out_.vertices)
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) return TriangulationStatus::kNonFinite;
  if (out_.vertices.size() >= UINT32_MAX / 4) return TriangulationStatus::kFailed;
  const Bounds2 box = bounds(polygon);
  origin_ = box.min;

  const std::optional<std::uint32_t> outer = build_ring(polygon.outer, 0, true);
  if (!outer) {
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < polygon.outer.size(); ++i)
      distinct += polygon.outer[i] != polygon.outer[(i + 1) % polygon.outer.size()];
    return distinct < 3 ? TriangulationStatus::kTooFewVertices : TriangulationStatus::kZeroArea;
  }
  double expected = std::abs(signed_area(polygon.outer)), magnitude = expected;
  std::vector<std::uint32_t>& holes = scratch_.holes;
  holes.clear();
  std::uint32_t base = std::uint32_t(polygon.outer.size());
  for (const Ring& hole : polygon.holes) {
    if (const auto h = build_ring(hole, base, false)) {
      holes.push_back(*h);
      expected -= std::abs(signed_area(hole));
      magnitude += std::abs(signed_area(hole));
    }
    base += std::uint32_t(hole.size());
  }
  const double n = double(nodes_.size());
  budget_ = std::uint64_t(64 * n * n + 4 * n * 1e4 + 1e6);
  if (!eliminate_holes(*outer, holes)) return TriangulationStatus::kFailed;
  grid_.build(nodes_, box.max - box.min);
  if (!clip_all(*outer)) return TriangulationStatus::kFailed;

  double total = 0;
  for (const auto& t : out_.triangles) {
    total += 0.5 * orient(out_.vertices[t[0]] - origin_, out_.vertices[t[1]] - origin_,
                          out_.vertices[t[2]] - origin_);
  }
  if (std::abs(total - expected) > 1e-9 * magnitude) return TriangulationStatus::kFailed;
  return TriangulationStatus::kOk;
}

}  // namespace

std::string_view to_string(TriangulationStatus status) {
  switch (status) {
    case TriangulationStatus::kOk:
      return "ok";
    case TriangulationStatus::kTooFewVertices:
      return "the outer ring has fewer than 3 distinct vertices";
    case TriangulationStatus::kNonFinite:
      return "a coordinate is NaN or infinite";
    case TriangulationStatus::kZeroArea:
      return "the outer ring encloses no area";
    case TriangulationStatus::kFailed:
      return "no valid triangulation (crossing or misplaced rings?)";
  }
  return "unknown";
}

bool triangulate(const Polygon& polygon, Triangulation& out) {
  out.vertices.clear();
  out.triangles.clear();
  out.status = TriangulationStatus::kOk;
  // An ear per vertex but two, and two more per bridged hole: grown once.
  std::size_t vertices = polygon.outer.size();
  for (const Ring& hole : polygon.holes) vertices += hole.size() + 2;
  out.triangles.reserve(vertices);
  thread_local Scratch scratch;
  Triangulator triangulator(out, scratch);
  out.status = triangulator.run(polygon);
  // What a huge polygon needed is not kept for the thread's lifetime.
  constexpr std::size_t kKeptNodes = std::size_t{1} << 16;
  if (scratch.nodes.capacity() > kKeptNodes) scratch = Scratch{};
  if (out.status != TriangulationStatus::kOk) out.triangles.clear();
  return out.status == TriangulationStatus::kOk;
}

}  // namespace insula::kernel
