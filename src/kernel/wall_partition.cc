// The front face of a wall cut into u-monotone hole-free pieces (wall_detail.h): the boundary
// rings, then MakeMonotone's sweep (de Berg et al., "Computational Geometry", 3rd ed., section
// 3.2) adds diagonals between existing vertices, then a walk over the half-edges lists the pieces.
// Every piece boundary uses only ring vertices, so the mesh has no T-junctions.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/wall_detail.h"

namespace insula::kernel::wall_detail {
namespace {

// ---------------------------------------------------------------------------------------------
// Boundary rings: every vertex starts one directed edge with the wall's material on its left.

EdgeKind rim_kind(Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  // The outward normal of a counter-clockwise edge is (d.y, -d.x) / |d|. Axis-parallel edges
  // (every edge of a rectangular wall) are settled without the root: |d| = |d.x| when d.y = 0.
  if (d.x == 0) return EdgeKind::kEnd;
  if (d.y != 0 && std::abs(d.x) <= 1e-9 * length(d)) return EdgeKind::kEnd;
  return d.x < 0 ? EdgeKind::kTop : EdgeKind::kBottom;
}

// Adds an opening's ring as edges: left jamb, lintel pieces, right jamb, then the sill (holes
// only).
void add_opening_edges(Boundary& out, const Accepted& c, bool notch) {
  const auto o = static_cast<std::int32_t>(c.index);
  const std::size_t m = c.ring.size();
  for (std::size_t i = 0; i < m; ++i) {
    EdgeKind k = EdgeKind::kLintel;
    if (i == 0 || i == m - 2) k = EdgeKind::kJamb;
    if (i == m - 1) {
      if (notch) break;  // the sill corner continues along the host edge
      k = EdgeKind::kSill;
    }
    out.add(c.ring[i], k, o);
  }
}

}  // namespace

void build_boundary(const Ring& outline, const std::vector<Accepted>& cut, Boundary& out,
                    std::vector<const Accepted*>& notches) {
  notches.clear();
  for (const Accepted& c : cut) {
    if (c.host >= 0) notches.push_back(&c);
  }
  std::sort(notches.begin(), notches.end(), [](const Accepted* a, const Accepted* b) {
    return a->host != b->host ? a->host < b->host : a->opening.u < b->opening.u;
  });
  std::size_t k = 0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const EdgeKind rim = rim_kind(outline[i], outline[(i + 1) % outline.size()]);
    out.add(outline[i], rim, -1);
    for (; k < notches.size() && notches[k]->host == static_cast<int>(i); ++k) {
      add_opening_edges(out, *notches[k], true);
      out.add(notches[k]->ring.back(), rim, -1);
    }
  }
  out.close();
  for (const Accepted& c : cut) {
    if (c.host >= 0) continue;
    add_opening_edges(out, c, false);
    out.close();
  }
}

namespace {

// ---------------------------------------------------------------------------------------------
// Monotone partition (de Berg section 3.2). The book sweeps top to bottom; we sweep along +u by
// working in the rotated frame x = v, y = -u (a rotation, so orientation and "interior on the
// left" are preserved). Ties are broken as in the book: equal y, smaller x comes first.

enum class VertexType : std::uint8_t { kStart, kSplit, kEnd, kMerge, kRegular };

class MonotonePartition {
 public:
  // Diagonals (vertex pairs) splitting the region of `b` into y-monotone pieces; false on a guard
  // failure. The sweep's arrays keep their storage from one call to the next (WallWorkspace).
  bool run(const Boundary& b, std::vector<std::array<std::uint32_t, 2>>& diagonals) {
    b_ = &b;
    const std::size_t n = b.points.size();
    q_.resize(n);
    for (std::size_t i = 0; i < n; ++i) q_[i] = {b.points[i].y, -b.points[i].x};
    type_.resize(n);
    bool split_or_merge = false;
    for (std::uint32_t i = 0; i < n; ++i) {
      type_[i] = classify(i);
      split_or_merge |= type_[i] == VertexType::kSplit || type_[i] == VertexType::kMerge;
    }
    // Without split or merge vertices the region is monotone already (de Berg, Lemma 3.4) and the
    // sweep would add no diagonal (it adds them only at split vertices and at merge helpers): a
    // plain wall skips the sort and the sweep. (A door notch can still make a merge vertex through
    // the equal-y tie-break, so walls with doors usually do sweep.)
    if (!split_or_merge) return true;
    status_.clear();
    // Vertices from the top down: sorted with their coordinates at hand (the comparison below(c, a)
    // on copies; the same comparisons on the same sequence, so the same order).
    order_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) order_[i] = {q_[i], i};
    std::sort(order_.begin(), order_.end(), [](const Ordered& a, const Ordered& c) {
      return c.q.y < a.q.y || (c.q.y == a.q.y && c.q.x > a.q.x);
    });
    helper_.assign(n, 0);
    for (const Ordered& o : order_) {
      if (!handle(o.vertex, diagonals)) return false;
    }
    return true;
  }

 private:
  bool below(std::uint32_t a, std::uint32_t c) const {
    return q_[a].y < q_[c].y || (q_[a].y == q_[c].y && q_[a].x > q_[c].x);
  }

  VertexType classify(std::uint32_t v) const {
    const std::uint32_t p = b_->prev[v], n = b_->next[v];
    const bool convex = cross(q_[v] - q_[p], q_[n] - q_[v]) > 0;
    const bool p_below = below(p, v), n_below = below(n, v);
    if (p_below && n_below) return convex ? VertexType::kStart : VertexType::kSplit;
    if (!p_below && !n_below) return convex ? VertexType::kEnd : VertexType::kMerge;
    return VertexType::kRegular;
  }

  // x of edge e (from e to next(e), going down) at height y.
  double x_at(std::uint32_t e, double y) const {
    const Vec2 a = q_[e], c = q_[b_->next[e]];
    if (a.y == c.y) return std::max(a.x, c.x);
    return a.x + (c.x - a.x) * (y - a.y) / (c.y - a.y);
  }

  // The status edge directly left of v, or -1.
  std::int64_t left_of(std::uint32_t v) const {
    std::int64_t best = -1;
    double best_x = -1e300;
    for (std::uint32_t e : status_) {
      const double x = x_at(e, q_[v].y);
      if (x < q_[v].x && x > best_x) best = e, best_x = x;
    }
    return best;
  }

  void erase(std::uint32_t e) {
    auto it = std::find(status_.begin(), status_.end(), e);
    if (it != status_.end()) {
      *it = status_.back();
      status_.pop_back();
    }
  }

  // Connects v to the helper of e if that helper is a merge vertex.
  void fix_up(std::uint32_t v, std::uint32_t e, std::vector<std::array<std::uint32_t, 2>>& d) {
    if (type_[helper_[e]] == VertexType::kMerge) d.push_back({v, helper_[e]});
  }

  bool handle(std::uint32_t v, std::vector<std::array<std::uint32_t, 2>>& d) {
    const std::uint32_t in = b_->prev[v];  // e_{i-1}
    switch (type_[v]) {
      case VertexType::kStart:
        status_.push_back(v);
        helper_[v] = v;
        return true;
      case VertexType::kEnd:
        fix_up(v, in, d);
        erase(in);
        return true;
      case VertexType::kSplit: {
        const std::int64_t e = left_of(v);
        if (e < 0) return false;
        d.push_back({v, helper_[static_cast<std::uint32_t>(e)]});
        helper_[static_cast<std::uint32_t>(e)] = v;
        status_.push_back(v);
        helper_[v] = v;
        return true;
      }
      case VertexType::kMerge: {
        fix_up(v, in, d);
        erase(in);
        return connect_left(v, d);
      }
      case VertexType::kRegular:
        if (below(v, in)) {  // interior to the right: the chain runs downward
          fix_up(v, in, d);
          erase(in);
          status_.push_back(v);
          helper_[v] = v;
          return true;
        }
        return connect_left(v, d);
    }
    return false;
  }

  bool connect_left(std::uint32_t v, std::vector<std::array<std::uint32_t, 2>>& d) {
    const std::int64_t e = left_of(v);
    if (e < 0) return false;
    fix_up(v, static_cast<std::uint32_t>(e), d);
    helper_[static_cast<std::uint32_t>(e)] = v;
    return true;
  }

  struct Ordered {
    Vec2 q;  // q_[vertex]
    std::uint32_t vertex;
  };

  const Boundary* b_ = nullptr;
  std::vector<Vec2> q_;
  std::vector<Ordered> order_;
  std::vector<VertexType> type_;
  std::vector<std::uint32_t> helper_;
  std::vector<std::uint32_t> status_;
};

// ---------------------------------------------------------------------------------------------
// Faces of the subdivision: walk half-edges keeping the face on the left. At a vertex with
// diagonals the next half-edge is the first one clockwise from the way back.

class PieceWalker {
 public:
  // Appends each piece of `b` cut by `diagonals` as a vertex loop (offsets into `loops`); false if
  // a walk does not close into a simple loop. The arrays keep their storage between calls.
  bool run(const Boundary& b, const std::vector<std::array<std::uint32_t, 2>>& diagonals,
           std::vector<std::uint32_t>& loops, std::vector<std::uint32_t>& offsets) {
    b_ = &b;
    if (diagonals.empty()) {
      rings_as_pieces(loops, offsets);
      return true;
    }
    link(diagonals);
    std::vector<std::uint32_t>& stamp = fill_;  // free once the half-edges are linked
    stamp.assign(b.points.size(), 0);
    std::uint32_t piece = 0;
    const std::size_t half_edges = to_.size();  // read once: the loop's stores may alias it
    for (std::uint32_t h = 0; h < half_edges; ++h) {
      if (used_[h]) continue;
      ++piece;
      std::uint32_t cur = h;
      std::uint32_t from = from_of(h);
      for (std::size_t steps = 0;; ++steps) {
        if (steps > half_edges || stamp[from] == piece) return false;
        stamp[from] = piece;
        used_[cur] = 1;
        loops.push_back(from);
        const std::uint32_t at = to_[cur];
        cur = next_half_edge(from, at);
        from = at;
        if (cur == h) break;
        if (used_[cur]) return false;
      }
      offsets.push_back(static_cast<std::uint32_t>(loops.size()));
    }
    return true;
  }

 private:
  // Without diagonals every ring is a piece, listed from its first vertex along `next`: what the
  // walk below yields then, without linking half-edges.
  void rings_as_pieces(std::vector<std::uint32_t>& loops, std::vector<std::uint32_t>& offsets) {
    const auto n = static_cast<std::uint32_t>(b_->points.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      loops.push_back(i);
      if (b_->next[i] != i + 1) offsets.push_back(static_cast<std::uint32_t>(loops.size()));
    }
  }

  // Outgoing half-edges per vertex: its boundary edge, then its diagonals.
  void link(const std::vector<std::array<std::uint32_t, 2>>& diagonals) {
    const std::size_t n = b_->points.size();
    start_.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) start_[i + 1] = 1;
    for (const auto& d : diagonals) ++start_[d[0] + 1], ++start_[d[1] + 1];
    for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
    to_.resize(start_[n]);
    used_.assign(start_[n], 0);
    fill_.assign(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i) to_[fill_[i]++] = b_->next[i];
    for (const auto& d : diagonals) to_[fill_[d[0]]++] = d[1], to_[fill_[d[1]]++] = d[0];
  }

  std::uint32_t from_of(std::uint32_t h) const {
    return static_cast<std::uint32_t>(std::upper_bound(start_.begin(), start_.end(), h) -
                                      start_.begin() - 1);
  }

  std::uint32_t next_half_edge(std::uint32_t from, std::uint32_t at) const {
    const std::uint32_t first = start_[at], last = start_[at + 1];
    if (last - first == 1) return first;
    const Vec2 back = b_->points[from] - b_->points[at];
    // The least clockwise angle from `back` in (0, 2 pi], compared without computing angles: first
    // by half-turn (0 for (0, pi], 1 for (pi, 2 pi]), then within a half-turn by orientation.
    const auto half_turn = [back](Vec2 d) {
      const double c = cross(d, back);
      return c > 0 || (c == 0 && dot(d, back) < 0) ? 0 : 1;
    };
    std::uint32_t best = first;
    Vec2 best_d = b_->points[to_[first]] - b_->points[at];
    int best_half = half_turn(best_d);
    for (std::uint32_t h = first + 1; h < last; ++h) {
      const Vec2 d = b_->points[to_[h]] - b_->points[at];
      const int half = half_turn(d);
      if (half < best_half || (half == best_half && cross(d, best_d) < 0)) {
        best = h, best_d = d, best_half = half;
      }
    }
    return best;
  }

  const Boundary* b_ = nullptr;
  std::vector<std::uint32_t> start_;  // outgoing half-edges of vertex v: [start_[v], start_[v+1])
  std::vector<std::uint32_t> to_;
  std::vector<std::uint8_t> used_;
  std::vector<std::uint32_t> fill_;  // next free slot per vertex while linking; then walk stamps
};

}  // namespace

struct PartitionScratch {
  MonotonePartition sweep;
  PieceWalker walker;
  std::vector<std::array<std::uint32_t, 2>> diagonals;
};

void PartitionScratchDeleter::operator()(PartitionScratch* scratch) const {
  delete scratch;
}

PartitionScratchPtr make_partition_scratch() {
  return PartitionScratchPtr(new PartitionScratch);
}

bool partition(const Boundary& b, PartitionScratch& scratch, std::vector<std::uint32_t>& loops,
               std::vector<std::uint32_t>& offsets) {
  scratch.diagonals.clear();
  return scratch.sweep.run(b, scratch.diagonals) &&
         scratch.walker.run(b, scratch.diagonals, loops, offsets);
}

}  // namespace insula::kernel::wall_detail
