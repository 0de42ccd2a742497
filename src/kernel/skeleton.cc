// CGAL translation unit #1 (design.md: CGAL stays in at most two translation units). Wraps
// create_interior_straight_skeleton_2 with Exact_predicates_inexact_constructions_kernel and
// copies its half-edge structure into the plain Skeleton of skeleton.h. Strictly convex polygons
// take a direct wavefront simulation instead (ConvexSkeleton below), and rectilinear ones the
// wavefront of skeleton_rectilinear.cc: both exact for their inputs and far cheaper than CGAL's
// general builder.
#include "kernel/skeleton.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Straight_skeleton_builder_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "kernel/skeleton_rectilinear.h"
#include "kernel/skeleton_wavefront.h"

namespace insula::kernel {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalSkeleton = CGAL::Straight_skeleton_2<K>;

constexpr std::uint32_t kUnset = 0xffffffffU;

// Exact bit pattern of a point: CGAL's inexact constructions copy input doubles unchanged, so a
// contour vertex is found again by its bits.
struct PointKey {
  std::uint64_t x = 0;
  std::uint64_t y = 0;
  friend bool operator==(PointKey, PointKey) = default;
};
struct PointKeyHash {
  std::size_t operator()(PointKey k) const {
    return k.x * 0x9E3779B97F4A7C15ULL ^ (k.y + 0x7F4A7C15);
  }
};
PointKey key_of(double x, double y) {
  PointKey k;
  x += 0.0;  // -0.0 and 0.0 compare equal; give them one key
  y += 0.0;
  std::memcpy(&k.x, &x, sizeof x);
  std::memcpy(&k.y, &y, sizeof y);
  return k;
}

// Proper or touching intersection of closed segments ab and cd.
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segments_cross_properly(a, b, c, d)) return true;
  const double d1 = cross(b - a, c - a);
  const double d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c);
  const double d4 = cross(d - c, b - c);
  auto on_segment = [](Vec2 p, Vec2 q, Vec2 r) {  // r collinear with pq: is it within pq?
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  return (d1 == 0 && on_segment(a, b, c)) || (d2 == 0 && on_segment(a, b, d)) ||
         (d3 == 0 && on_segment(c, d, a)) || (d4 == 0 && on_segment(c, d, b));
}

struct Segment {
  Vec2 a, b;
  std::uint32_t ring, index, ring_size;
};

bool rings_valid(const Polygon& polygon) {
  auto ring_ok = [](const Ring& ring) {
    if (ring.size() < 3) return false;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 p = ring[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
      if (p == ring[(i + 1) % ring.size()]) return false;
    }
    return true;
  };
  if (!ring_ok(polygon.outer) || signed_area(polygon.outer) <= 0) return false;
  for (const Ring& hole : polygon.holes) {
    if (!ring_ok(hole) || signed_area(hole) >= 0) return false;
  }
  return true;
}

bool boxes_apart(const Segment& s, const Segment& t) {
  return std::max(s.a.x, s.b.x) < std::min(t.a.x, t.b.x) ||
         std::max(t.a.x, t.b.x) < std::min(s.a.x, s.b.x) ||
         std::max(s.a.y, s.b.y) < std::min(t.a.y, t.b.y) ||
         std::max(t.a.y, t.b.y) < std::min(s.a.y, s.b.y);
}

// Two edges that must not touch except where consecutive edges share their vertex.
bool pair_valid(const Segment& s, const Segment& t) {
  if (boxes_apart(s, t)) return true;
  const bool t_after_s = s.ring == t.ring && t.index == (s.index + 1) % s.ring_size;
  const bool s_after_t = s.ring == t.ring && s.index == (t.index + 1) % s.ring_size;
  if (!t_after_s && !s_after_t) return !segments_meet(s.a, s.b, t.a, t.b);
  // Consecutive edges share one vertex; they must not fold back onto each other.
  const Vec2 shared = t_after_s ? s.b : s.a;
  const Vec2 u = (t_after_s ? s.a : s.b) - shared;
  const Vec2 v = (t_after_s ? t.b : t.a) - shared;
  return !(cross(u, v) == 0 && dot(u, v) > 0);
}

// Sweep and prune along x: only pairs whose x ranges overlap are tested, so footprints of many
// thousand vertices are checked in about n log n instead of n^2 (the same pairs as an all-pairs
// test with boxes_apart, since pairs apart in x are valid anyway).
bool segments_valid(const std::vector<Segment>& segments) {
  std::vector<std::uint32_t> order(segments.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  auto min_x = [&](std::uint32_t i) { return std::min(segments[i].a.x, segments[i].b.x); };
  auto max_x = [&](std::uint32_t i) { return std::max(segments[i].a.x, segments[i].b.x); };
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return min_x(a) < min_x(b); });
  for (std::size_t a = 0; a < order.size(); ++a) {
    const double reach = max_x(order[a]);
    for (std::size_t b = a + 1; b < order.size() && min_x(order[b]) <= reach; ++b) {
      if (!pair_valid(segments[order[a]], segments[order[b]])) return false;
    }
  }
  return true;
}

std::vector<K::Point_2> to_cgal(const Ring& ring) {
  std::vector<K::Point_2> out;
  out.reserve(ring.size());
  for (const Vec2& p : ring) out.emplace_back(p.x, p.y);
  return out;
}

void add_contour(const Polygon& polygon, Skeleton& out) {
  std::uint32_t index = 0;
  auto add_ring = [&](const Ring& ring) {
    out.ring_starts.push_back(index);
    for (const Vec2& p : ring) {
      out.vertices.push_back({p, 0.0});
      ++index;
    }
  };
  add_ring(polygon.outer);
  for (const Ring& hole : polygon.holes) add_ring(hole);
  out.ring_starts.push_back(index);
  out.contour_count = index;
}

// Removes repeated consecutive ids, including the last against the first: after near-coincident
// nodes are merged, a loop may step from a node to itself.
void drop_repeats(std::vector<std::uint32_t>& loop) {
  loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
  while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
}

// Fails when a loop has fewer than 3 distinct consecutive vertices: each face belongs to one
// contour edge, so a degenerate face cannot be dropped without breaking the face(e) invariant.
bool store_faces(const std::vector<std::vector<std::uint32_t>>& loops, Skeleton& out) {
  out.face_offsets.assign(1, 0);
  for (const auto& loop : loops) {
    if (loop.size() < 3) return false;
    out.face_indices.insert(out.face_indices.end(), loop.begin(), loop.end());
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_indices.size()));
  }
  return true;
}

// Maps each CGAL vertex to a Skeleton vertex id: contour vertices to their ring-order index,
// skeleton nodes to new ids in order of discovery.
class Converter {
 public:
  explicit Converter(Skeleton& out) : out_(out) {
    Vec2 lo = out_.vertices[0].position, hi = lo;
    for (std::uint32_t k = 0; k < out_.contour_count; ++k) {
      const Vec2 p = out_.vertices[k].position;
      by_position_.emplace(key_of(p.x, p.y), k);
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    // CGAL reports the nodes of one simultaneous event (e.g. the centre of a regular star) as
    // several vertices a few ulps apart; closer than this they are one node. Far below any
    // geometric feature the contour can carry, far above the rounding of its constructions.
    tolerance_ = kMergeTolerance * std::max(length(hi - lo), 1e-300);
    origin_ = lo;
  }

  bool convert(const CgalSkeleton& ss) {
    int max_id = 0;
    for (auto v = ss.vertices_begin(); v != ss.vertices_end(); ++v)
      max_id = std::max(max_id, v->id());
    ids_.assign(static_cast<std::size_t>(max_id) + 1, kUnset);
    std::vector<std::vector<std::uint32_t>> loops(out_.contour_count);
    std::size_t faces = 0;
    for (auto f = ss.faces_begin(); f != ss.faces_end(); ++f) {
      if (!convert_face(f->halfedge(), loops)) return false;
      ++faces;
    }
    return faces == out_.contour_count && store_faces(loops, out_);
  }

 private:
  // The contour edge index whose start is at s and end at t, or kUnset.
  std::uint32_t find_edge(K::Point_2 s, K::Point_2 t) const {
    const auto range = by_position_.equal_range(key_of(s.x(), s.y()));
    for (auto it = range.first; it != range.second; ++it) {
      const Vec2 next = out_.vertices[out_.next_contour(it->second)].position;
      if (next.x == t.x() && next.y == t.y()) return it->second;
    }
    return kUnset;
  }

  template <typename Halfedge>
  bool convert_face(Halfedge start, std::vector<std::vector<std::uint32_t>>& loops) {
    Halfedge contour = start;
    do {
      if (!contour->is_bisector()) break;
      contour = contour->next();
    } while (contour != start);
    if (contour->is_bisector()) return false;
    const std::uint32_t edge =
        find_edge(contour->opposite()->vertex()->point(), contour->vertex()->point());
    if (edge == kUnset || !loops[edge].empty()) return false;
    ids_[static_cast<std::size_t>(contour->opposite()->vertex()->id())] = edge;
    ids_[static_cast<std::size_t>(contour->vertex()->id())] = out_.next_contour(edge);
    Halfedge h = contour;
    std::size_t guard = 0;
    do {
      loops[edge].push_back(id_of(h->opposite()->vertex()));  // the source of h
      h = h->next();
      if (++guard > 1000000) return false;
    } while (h != contour);
    drop_repeats(loops[edge]);
    return true;
  }

  template <typename VertexHandle>
  std::uint32_t id_of(VertexHandle v) {
    std::uint32_t& id = ids_[static_cast<std::size_t>(v->id())];
    if (id != kUnset) return id;
    const double time = std::isfinite(v->time()) ? v->time() : -1.0;
    id = merged_node({v->point().x(), v->point().y()}, time);
    return id;
  }

  using Cell = std::pair<std::int64_t, std::int64_t>;
  struct CellHash {
    std::size_t operator()(Cell c) const {
      return static_cast<std::size_t>(c.first) * 0x9E3779B97F4A7C15ULL ^
             static_cast<std::size_t>(c.second);
    }
  };
  // Cells are counted from the contour's lower corner: nodes lie inside its bounding box, so the
  // indices stay below ~1e9 whatever the absolute coordinates.
  Cell cell_of(Vec2 p) const {
    const double size = 4 * tolerance_;  // one cell spans the tolerance, so 3x3 cells suffice
    const double limit = 4e18;
    return {
        static_cast<std::int64_t>(std::clamp(std::floor((p.x - origin_.x) / size), -limit, limit)),
        static_cast<std::int64_t>(std::clamp(std::floor((p.y - origin_.y) / size), -limit, limit))};
  }

  // The id of an existing skeleton node within tolerance_ of p in position and time, or a new
  // node. Nodes are hashed in a grid of cells 4 * tolerance_ wide; neighbours are in 3x3 cells.
  std::uint32_t merged_node(Vec2 p, double time) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {  // rejected later by times_valid
      out_.vertices.push_back({p, time});
      return static_cast<std::uint32_t>(out_.vertices.size() - 1);
    }
    const Cell c = cell_of(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto range = by_cell_.equal_range({c.first + dx, c.second + dy});
        for (auto it = range.first; it != range.second; ++it) {
          const SkeletonVertex& s = out_.vertices[it->second];
          if (std::abs(s.time - time) <= tolerance_ && length(s.position - p) <= tolerance_) {
            return it->second;
          }
        }
      }
    }
    const auto id = static_cast<std::uint32_t>(out_.vertices.size());
    out_.vertices.push_back({p, time});
    by_cell_.emplace(c, id);
    return id;
  }

  static constexpr double kMergeTolerance = 1e-9;  // relative to the contour's bounding diagonal

  Skeleton& out_;
  std::unordered_multimap<PointKey, std::uint32_t, PointKeyHash> by_position_;
  std::unordered_multimap<Cell, std::uint32_t, CellHash> by_cell_;
  std::vector<std::uint32_t> ids_;
  double tolerance_ = 0;
  Vec2 origin_;
};

// Straight skeleton of a strictly convex polygon by direct wavefront simulation: only edge events
// occur (Aichholzer et al. 1995), so each step collapses the edge that vanishes first. O(n^2); for
// the small convex footprints that dominate city data it avoids CGAL's exact fallbacks, which the
// simultaneous events of rectangles trigger.
//
// The wavefront is kept as lines, not as moving vertices: edge e at time t is the line
// dot(n_e, x) = c_e + t, and an edge vanishes where its line and its two neighbours' lines meet
// (three offset lines concurrent: a 3 x 3 system that stays well conditioned when the neighbours
// are antiparallel or nearly so). A vertex between nearly antiparallel edges, the end of a
// near-rectangle's ridge, races along the ridge at a speed of 2 / angle; extrapolating its
// position from a velocity, or treating the pair as parallel below a threshold, put the far end
// of the ridge micrometres off and left a sliver of the roof open (docs/kernel-roofs.md,
// "Near-rectangles").
class ConvexSkeleton {
 public:
  explicit ConvexSkeleton(Skeleton& out) : out_(out) {}

  bool run() {
    const std::uint32_t n = out_.contour_count;
    // Lines relative to the first vertex, so their constants stay small for georeferenced input.
    origin_ = out_.vertices[0].position;
    for (std::uint32_t k = 0; k < n; ++k) {
      const Vec2 a = out_.vertices[k].position - origin_;
      const Vec2 b = out_.vertices[(k + 1) % n].position - origin_;
      const Vec2 normal = perp(normalized(b - a));
      lines_.push_back({normal, dot(normal, a), {}, {}});
      active_.push_back(k);
    }
    faces_.assign(n, {});
    while (active_.size() > 3) {
      std::uint32_t best = kUnset;
      Event best_event;
      for (std::uint32_t i = 0; i < active_.size(); ++i) {
        const Event event = collapse_of(i);
        if (!event.valid) return false;
        if (best == kUnset || event.time < best_event.time) best = i, best_event = event;
      }
      collapse(best, best_event);
    }
    // The last three edges meet in one node (the triangle's incentre).
    const Event last = collapse_of(0);
    if (!last.valid) return false;
    const std::uint32_t node = node_at(last.point, std::max(last.time, time_));
    for (std::uint32_t i = 0; i < 3; ++i) close_face(active_[i], node, node);
    return store_faces(faces_, out_);
  }

 private:
  struct Line {
    Vec2 normal;  // unit, pointing inward
    double offset = 0;
    std::vector<std::uint32_t> left_nodes, right_nodes;  // nodes its end points passed
  };
  struct Event {
    Vec2 point;  // relative to origin_
    double time = 0;
    bool valid = false;
  };

  // Where active edge i vanishes: its line and its neighbours' lines, each moved inward by t, meet.
  Event collapse_of(std::uint32_t i) const {
    const auto m = static_cast<std::uint32_t>(active_.size());
    const Line& l = lines_[active_[(i + m - 1) % m]];
    const Line& e = lines_[active_[i]];
    const Line& r = lines_[active_[(i + 1) % m]];
    // (n_l - n_e) . x = c_l - c_e and (n_r - n_e) . x = c_r - c_e; then t = n_e . x - c_e.
    const Vec2 u = l.normal - e.normal;
    const Vec2 v = r.normal - e.normal;
    const double det = cross(u, v);
    Event event;
    if (!(std::abs(det) > 1e-12)) return event;
    const double cu = l.offset - e.offset;
    const double cv = r.offset - e.offset;
    event.point = Vec2{cu * v.y - cv * u.y, cv * u.x - cu * v.x} / det;
    event.time = dot(e.normal, event.point) - e.offset;
    event.valid =
        std::isfinite(event.time) && std::isfinite(event.point.x) && std::isfinite(event.point.y);
    return event;
  }

  // A node at p (relative to origin_) and time, merged with an existing one at the same place
  // (simultaneous events, e.g. the centre of a square or a regular polygon).
  std::uint32_t node_at(Vec2 p, double time) {
    const Vec2 q = p + origin_;
    const double tolerance = 1e-9 * (1 + time);
    for (std::uint32_t v = out_.contour_count; v < out_.vertices.size(); ++v) {
      const SkeletonVertex& s = out_.vertices[v];
      if (std::abs(s.time - time) < tolerance && length(s.position - q) < tolerance) return v;
    }
    out_.vertices.push_back({q, time});
    return static_cast<std::uint32_t>(out_.vertices.size() - 1);
  }

  // Face of edge e: the contour edge, the nodes its right end passed, `last_right` and `last_left`
  // (where its ends stop), then the nodes its left end passed, backwards.
  void close_face(std::uint32_t e, std::uint32_t last_right, std::uint32_t last_left) {
    const std::uint32_t n = out_.contour_count;
    std::vector<std::uint32_t>& f = faces_[e];
    auto push = [&f](std::uint32_t v) {
      if (f.empty() || (f.back() != v && f.front() != v)) f.push_back(v);
    };
    push(e);
    push((e + 1) % n);
    for (std::uint32_t v : lines_[e].right_nodes) push(v);
    push(last_right);
    push(last_left);
    for (auto it = lines_[e].left_nodes.rbegin(); it != lines_[e].left_nodes.rend(); ++it)
      push(*it);
  }

  void collapse(std::uint32_t i, const Event& event) {
    const auto m = static_cast<std::uint32_t>(active_.size());
    // Events come in time order; rounding may put one a hair before the previous one.
    time_ = std::max(time_, event.time);
    const std::uint32_t node = node_at(event.point, time_);
    const std::uint32_t e = active_[i];
    close_face(e, node, node);
    lines_[active_[(i + m - 1) % m]].right_nodes.push_back(node);
    lines_[active_[(i + 1) % m]].left_nodes.push_back(node);
    active_.erase(active_.begin() + i);
  }

  Skeleton& out_;
  Vec2 origin_;
  std::vector<Line> lines_;
  std::vector<std::uint32_t> active_;  // edges still on the wavefront, in ring order
  std::vector<std::vector<std::uint32_t>> faces_;
  double time_ = 0;
};

bool strictly_convex(const Polygon& polygon) {
  if (!polygon.holes.empty() || polygon.outer.size() > 8192) return false;
  const Ring& r = polygon.outer;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Vec2 u = r[(i + 1) % r.size()] - r[i];
    const Vec2 v = r[(i + 2) % r.size()] - r[(i + 1) % r.size()];
    if (!(cross(u, v) > 1e-9 * length(u) * length(v))) return false;
  }
  return true;
}

bool times_valid(const Skeleton& s) {
  for (std::size_t i = s.contour_count; i < s.vertices.size(); ++i) {
    const SkeletonVertex& v = s.vertices[i];
    if (!std::isfinite(v.time) || !std::isfinite(v.position.x) || !std::isfinite(v.position.y) ||
        v.time < 0) {
      return false;
    }
  }
  return true;
}

// CGAL 5.5's builder finishes by merging each pair of nodes a split event made at one point
// (FinishUp -> MergeSplitNodes): it moves the pair's four incoming bisectors to the left node and
// frees the right one. When several split events meet at one point at one time (an 8 x 8 grid of
// unit holes one unit apart, transposed: hole corners colliding diagonally with their
// neighbours'), another wavefront halfedge can still end at a freed node, and the next step
// (MergeCoincidentNodes) reads it: a heap-use-after-free, so a crash or a wrong roof depending on
// the heap. This visitor replays those merges on CGAL's finished wavefront just before CGAL does
// them (on_cleanup_started) and throws, so that CGAL returns no skeleton, when a face would keep a
// halfedge ending at a freed node.
class SplitMergeGuard : public CGAL::Dummy_straight_skeleton_builder_2_visitor<CgalSkeleton> {
 public:
  using HalfedgeHandle = CgalSkeleton::Halfedge_const_handle;
  using VertexHandle = CgalSkeleton::Vertex_const_handle;
  struct Unsafe : std::runtime_error {
    Unsafe() : std::runtime_error("split nodes would leave a dangling halfedge") {}
  };

  // The callbacks are const in CGAL's visitor concept; the guard's records are not.
  void on_contour_edge_entered(const HalfedgeHandle& border) const { borders_.push_back(border); }
  void on_split_event_processed(const VertexHandle&, const VertexHandle& left,
                                const VertexHandle& right) const {
    pairs_.emplace_back(left, right);
  }
  void on_pseudo_split_event_processed(const VertexHandle&, const VertexHandle&,
                                       const VertexHandle& left, const VertexHandle& right) const {
    pairs_.emplace_back(left, right);
  }
  void on_cleanup_started() const {
    if (!merges_safe()) throw Unsafe();
  }

 private:
  using Vertex = CgalSkeleton::Vertex;
  using Halfedge = CgalSkeleton::Halfedge;

  bool merges_safe() const {
    std::unordered_map<const Halfedge*, const Vertex*> moved;
    std::unordered_set<const Vertex*> freed;
    auto end_of = [&moved](HalfedgeHandle h) {
      const auto it = moved.find(&*h);
      return it == moved.end() ? &*h->vertex() : it->second;
    };
    for (const auto& [left, right] : pairs_) {
      if (freed.count(&*left) != 0 || freed.count(&*right) != 0) return false;
      const HalfedgeHandle l1 = left->primary_bisector()->opposite();
      const HalfedgeHandle r1 = right->primary_bisector()->opposite();
      for (const HalfedgeHandle h : {l1, r1, l1->next()->opposite(), r1->next()->opposite()}) {
        if (end_of(h) == &*right) moved[&*h] = &*left;
      }
      freed.insert(&*right);
    }
    if (freed.empty()) return true;
    // Every face is a loop from its contour edge; a loop that does not close is no skeleton either.
    const std::size_t limit = 64 * (borders_.size() + pairs_.size()) + 64;
    for (const HalfedgeHandle& border : borders_) {
      HalfedgeHandle h = border;
      std::size_t steps = 0;
      do {
        if (freed.count(end_of(h)) != 0 || ++steps > limit) return false;
        h = h->next();
      } while (h != border);
    }
    return true;
  }

  mutable std::vector<HalfedgeHandle> borders_;
  mutable std::vector<std::pair<VertexHandle, VertexHandle>> pairs_;
};

std::optional<Skeleton> cgal_skeleton(const Polygon& polygon) {
  using Builder = CGAL::Straight_skeleton_builder_2<CGAL::Straight_skeleton_builder_traits_2<K>,
                                                    CgalSkeleton, SplitMergeGuard>;
  const SplitMergeGuard guard;  // the builder keeps a reference
  Builder builder(boost::none, Builder::Traits(), guard);
  for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
    const std::vector<K::Point_2> ring = to_cgal(r == 0 ? polygon.outer : polygon.holes[r - 1]);
    builder.enter_contour(ring.begin(), ring.end());
  }
  const auto ss = builder.construct_skeleton();
  if (!ss) return std::nullopt;
  Skeleton out;
  add_contour(polygon, out);
  if (!Converter(out).convert(*ss) || !times_valid(out)) return std::nullopt;
  return out;
}

}  // namespace

std::uint32_t Skeleton::next_contour(std::uint32_t vertex) const {
  const auto it = std::upper_bound(ring_starts.begin(), ring_starts.end(), vertex);
  return vertex + 1 == *it ? *(it - 1) : vertex + 1;
}

std::uint32_t Skeleton::previous_contour(std::uint32_t vertex) const {
  const auto it = std::upper_bound(ring_starts.begin(), ring_starts.end(), vertex);
  return vertex == *(it - 1) ? *it - 1 : vertex - 1;
}

double Skeleton::max_time() const {
  double t = 0;
  for (const SkeletonVertex& v : vertices) t = std::max(t, v.time);
  return t;
}

bool is_simple_polygon(const Polygon& polygon) {
  if (!rings_valid(polygon)) return false;
  std::vector<Segment> segments;
  auto add = [&](const Ring& ring, std::uint32_t r) {
    const auto n = static_cast<std::uint32_t>(ring.size());
    for (std::uint32_t i = 0; i < n; ++i) segments.push_back({ring[i], ring[(i + 1) % n], r, i, n});
  };
  add(polygon.outer, 0);
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    add(polygon.holes[h], static_cast<std::uint32_t>(h + 1));
  }
  if (!segments_valid(segments)) return false;
  // No crossings: one vertex of each hole decides whether it lies inside the outer ring.
  for (const Ring& hole : polygon.holes) {
    if (locate(Polygon{polygon.outer, {}}, hole[0], 0) != PointLocation::kInside) return false;
  }
  return true;
}

namespace {
// CGAL's predicates square coordinates: from about 1e154 on they overflow to infinity and GMP
// traps (SIGFPE) converting it. Far beyond any real footprint, so such outlines get no skeleton.
bool coordinates_in_range(const Polygon& polygon) {
  constexpr double kLimit = 1e100;
  auto ring_ok = [](const Ring& ring) {
    return std::all_of(ring.begin(), ring.end(),
                       [](Vec2 p) { return std::abs(p.x) <= kLimit && std::abs(p.y) <= kLimit; });
  };
  return ring_ok(polygon.outer) && std::all_of(polygon.holes.begin(), polygon.holes.end(), ring_ok);
}
}  // namespace

std::optional<Skeleton> interior_straight_skeleton(const Polygon& polygon) {
  try {
    if (!coordinates_in_range(polygon) || !is_simple_polygon(polygon)) return std::nullopt;
    if (strictly_convex(polygon)) {
      Skeleton out;
      add_contour(polygon, out);
      if (ConvexSkeleton(out).run() && times_valid(out)) return out;
    }
    if (auto rectilinear = rectilinear_straight_skeleton(polygon)) return rectilinear;
    if (auto wavefront = wavefront_straight_skeleton(polygon)) return wavefront;
    return cgal_skeleton(polygon);
  } catch (...) {
    return std::nullopt;
  }
}

std::optional<Skeleton> general_straight_skeleton(const Polygon& polygon) {
  try {
    if (!coordinates_in_range(polygon) || !is_simple_polygon(polygon)) return std::nullopt;
    return cgal_skeleton(polygon);
  } catch (...) {
    return std::nullopt;
  }
}

}  // namespace insula::kernel
