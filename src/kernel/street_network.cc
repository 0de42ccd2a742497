// Street networks (street_network.h): merging into a planar graph, its faces, and road and block
// surfaces built with the 2D booleans of boolean2d.h.
#include "kernel/street_network.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "kernel/boolean2d.h"

namespace insula::kernel {
namespace {

using Edge = std::array<std::uint32_t, 2>;

bool finite(Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

bool valid_edge(const StreetNetwork& network, const Edge& edge) {
  const std::size_t n = network.vertices.size();
  return edge[0] < n && edge[1] < n && finite(network.vertices[edge[0]]) &&
         finite(network.vertices[edge[1]]);
}

double squared_xy_distance(Vec3 a, Vec3 b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

std::uint64_t undirected_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// Welds points within a distance: each new point joins the lowest-numbered kept vertex within
// `tolerance`, found through a hash of square cells at least that wide (so a 3x3 block of cells
// holds every candidate).
class Welder {
 public:
  Welder(double tolerance, std::vector<Vec3>& vertices)
      : tolerance2_(tolerance * tolerance), cell_(std::max(tolerance, 1e-6)), vertices_(vertices) {}

  std::uint32_t add(Vec3 p) {
    const auto [cx, cy] = cell_of(p);
    std::uint32_t best = std::numeric_limits<std::uint32_t>::max();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find(key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (const std::uint32_t id : it->second)
          if (id < best && squared_xy_distance(vertices_[id], p) <= tolerance2_) best = id;
      }
    if (best != std::numeric_limits<std::uint32_t>::max()) return best;
    const auto id = static_cast<std::uint32_t>(vertices_.size());
    vertices_.push_back(p);
    cells_[key(cx, cy)].push_back(id);
    return id;
  }

 private:
  std::pair<std::int64_t, std::int64_t> cell_of(Vec3 p) const {
    // Clamped so that the conversion stays defined; far-off points only share cells, which the
    // distance test then sorts out.
    auto index = [this](double v) {
      return static_cast<std::int64_t>(std::clamp(std::floor(v / cell_), -1e18, 1e18));
    };
    return {index(p.x), index(p.y)};
  }
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(y);
  }

  double tolerance2_;
  double cell_;
  std::vector<Vec3>& vertices_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

// A uniform grid over a box for finding edges and vertices near an edge: at most 512 x 512
// cells, about one edge long, so that a grid-like network puts a few items in each.
class CellGrid {
 public:
  CellGrid(const Bounds2& box, double cell) : box_(box) {
    const double w = box.max.x - box.min.x, h = box.max.y - box.min.y;
    cell_ = std::max({cell, w / 512, h / 512, 1e-9});
    // fmin also maps the NaN of an overflowed extent (coordinates near 1e308) to the cap.
    nx_ = static_cast<int>(std::fmin(w / cell_, 512)) + 1;
    ny_ = static_cast<int>(std::fmin(h / cell_, 512)) + 1;
    cells_.resize(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
  }

  void insert(const Bounds2& b, std::uint32_t id) {
    visit(b, [&](std::vector<std::uint32_t>& cell) { cell.push_back(id); });
  }
  // The ids in the cells `b` overlaps, sorted, each once.
  std::vector<std::uint32_t> near(const Bounds2& b) {
    std::vector<std::uint32_t> ids;
    visit(b, [&](std::vector<std::uint32_t>& cell) {
      ids.insert(ids.end(), cell.begin(), cell.end());
    });
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
  }

 private:
  template <typename F>
  void visit(const Bounds2& b, F f) {
    auto index = [this](double v, double lo, int n) {
      return static_cast<int>(std::fmax(0, std::fmin(std::floor((v - lo) / cell_), n - 1)));
    };
    const int x0 = index(b.min.x, box_.min.x, nx_), x1 = index(b.max.x, box_.min.x, nx_);
    const int y0 = index(b.min.y, box_.min.y, ny_), y1 = index(b.max.y, box_.min.y, ny_);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) f(cells_[static_cast<std::size_t>(y) * nx_ + x]);
  }

  Bounds2 box_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
};

Bounds2 segment_box(Vec3 a, Vec3 b, double margin) {
  return {{std::min(a.x, b.x) - margin, std::min(a.y, b.y) - margin},
          {std::max(a.x, b.x) + margin, std::max(a.y, b.y) + margin}};
}

// Parameter of the point of segment ab nearest to p, in [0, 1].
double project(Vec3 p, Vec3 a, Vec3 b) {
  const Vec2 ab = drop(b) - drop(a);
  const double len2 = dot(ab, ab);
  return len2 > 0 ? std::clamp(dot(drop(p) - drop(a), ab) / len2, 0.0, 1.0) : 0.0;
}

struct Split {
  double t;
  std::uint32_t vertex;
  friend bool operator<(const Split& a, const Split& b) {
    return std::tie(a.t, a.vertex) < std::tie(b.t, b.vertex);
  }
};

// One round of merge_networks: weld, find crossings and vertices on edges, split. `changed` tells
// whether the round did anything, so that the caller can stop at a fixed point. Used once: run()
// hands over the result.
class MergeRound {
 public:
  explicit MergeRound(double tolerance)
      : tolerance_(tolerance), welder_(tolerance, out_.vertices) {}

  StreetNetwork run(std::span<const StreetNetwork> networks, bool& changed) && {
    weld(networks);
    split();
    changed = changed_;
    return std::move(out_);
  }

 private:
  void weld(std::span<const StreetNetwork> networks) {
    for (const StreetNetwork& network : networks) {
      std::vector<std::uint32_t> map(network.vertices.size());
      for (std::size_t i = 0; i < network.vertices.size(); ++i) {
        const Vec3 p = network.vertices[i];
        if (!finite(p)) {
          changed_ = true;
          continue;
        }
        const std::size_t before = out_.vertices.size();
        map[i] = welder_.add(p);
        if (out_.vertices.size() == before) changed_ = true;
      }
      for (const Edge& e : network.edges) {
        if (!valid_edge(network, e) || map[e[0]] == map[e[1]]) {
          changed_ = true;
          continue;
        }
        edges_.push_back({map[e[0]], map[e[1]]});
      }
    }
  }

  Vec3 at(std::uint32_t v) const { return out_.vertices[v]; }

  void split() {
    if (edges_.empty()) return;
    Bounds2 box;
    double total = 0;
    for (const Vec3& p : out_.vertices) box.add(drop(p));
    for (const Edge& e : edges_) total += length(drop(at(e[1])) - drop(at(e[0])));
    const double cell = std::max(total / static_cast<double>(edges_.size()), 4 * tolerance_);
    CellGrid edge_grid(box, cell), vertex_grid(box, cell);
    for (std::uint32_t i = 0; i < edges_.size(); ++i)
      edge_grid.insert(segment_box(at(edges_[i][0]), at(edges_[i][1]), tolerance_), i);
    const auto kept = static_cast<std::uint32_t>(out_.vertices.size());
    for (std::uint32_t v = 0; v < kept; ++v) vertex_grid.insert(segment_box(at(v), at(v), 0), v);
    splits_.assign(edges_.size(), {});
    for (std::uint32_t i = 0; i < edges_.size(); ++i) {
      const Bounds2 b = segment_box(at(edges_[i][0]), at(edges_[i][1]), tolerance_);
      for (const std::uint32_t j : edge_grid.near(b))
        if (j > i) split_crossing(i, j);
      for (const std::uint32_t v : vertex_grid.near(b)) split_at_vertex(i, v);
    }
    rebuild();
  }

  void add_split(std::uint32_t e, std::uint32_t v) {
    const Edge& edge = edges_[e];
    if (v == edge[0] || v == edge[1]) return;
    const double t = project(at(v), at(edge[0]), at(edge[1]));
    if (t > 0 && t < 1) splits_[e].push_back({t, v});
  }

  void split_crossing(std::uint32_t i, std::uint32_t j) {
    const Edge ei = edges_[i], ej = edges_[j];
    if (ei[0] == ej[0] || ei[0] == ej[1] || ei[1] == ej[0] || ei[1] == ej[1]) return;
    const Vec3 a = at(ei[0]), b = at(ei[1]), c = at(ej[0]), d = at(ej[1]);
    if (!segments_cross_properly(drop(a), drop(b), drop(c), drop(d))) return;
    const Vec2 ab = drop(b) - drop(a), cd = drop(d) - drop(c), ac = drop(c) - drop(a);
    const double t = cross(ac, cd) / cross(ab, cd), u = cross(ac, ab) / cross(ab, cd);
    // The orientation tests can misjudge nearly collinear segments that do not meet.
    if (!(t > 0 && t < 1 && u > 0 && u < 1)) return;
    const std::uint32_t v = welder_.add(a + (b - a) * t);
    add_split(i, v);
    add_split(j, v);
  }

  void split_at_vertex(std::uint32_t e, std::uint32_t v) {
    const Edge& edge = edges_[e];
    if (v == edge[0] || v == edge[1]) return;
    if (squared_distance_to_segment(drop(at(v)), drop(at(edge[0])), drop(at(edge[1]))) <=
        tolerance_ * tolerance_)
      add_split(e, v);
  }

  // Each edge becomes its pieces in order; zero-length pieces and repeats are dropped.
  void rebuild() {
    std::unordered_set<std::uint64_t> seen;
    auto emit = [&](std::uint32_t a, std::uint32_t b) {
      if (a == b || !seen.insert(undirected_key(a, b)).second) {
        changed_ = true;
        return;
      }
      out_.edges.push_back({a, b});
    };
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      std::vector<Split>& cuts = splits_[e];
      std::sort(cuts.begin(), cuts.end());
      if (!cuts.empty()) changed_ = true;
      std::uint32_t from = edges_[e][0];
      for (const Split& cut : cuts) {
        if (cut.vertex == from) continue;
        emit(from, cut.vertex);
        from = cut.vertex;
      }
      emit(from, edges_[e][1]);
    }
  }

  double tolerance_;
  StreetNetwork out_;
  Welder welder_;
  std::vector<Edge> edges_;
  std::vector<std::vector<Split>> splits_;
  bool changed_ = false;
};

// Half-edge h runs along edge h / 2, forwards when h is even.
struct Embedding {
  // Per vertex, its outgoing half-edges counter-clockwise by angle (ties by half-edge number).
  std::vector<std::vector<std::pair<double, std::uint32_t>>> around;
  std::vector<std::uint32_t> slot;  // position of each half-edge in its origin's list

  explicit Embedding(const StreetNetwork& network) {
    around.resize(network.vertices.size());
    slot.resize(2 * network.edges.size());
    for (std::uint32_t h = 0; h < slot.size(); ++h) {
      const Vec2 d = direction(network, h);
      around[origin(network, h)].emplace_back(std::atan2(d.y, d.x), h);
    }
    for (auto& list : around) {
      std::sort(list.begin(), list.end());
      for (std::uint32_t k = 0; k < list.size(); ++k) slot[list[k].second] = k;
    }
  }

  static std::uint32_t origin(const StreetNetwork& network, std::uint32_t h) {
    return network.edges[h / 2][h % 2];
  }
  static Vec2 direction(const StreetNetwork& network, std::uint32_t h) {
    const Edge& e = network.edges[h / 2];
    const Vec2 d = drop(network.vertices[e[1]]) - drop(network.vertices[e[0]]);
    return normalized(h % 2 ? -d : d);
  }
  // The half-edge after h on the face to its left: the next one clockwise from h's twin at h's
  // head. At a dead end that is the twin itself, so the walk comes back along the spike.
  std::uint32_t next(const StreetNetwork& network, std::uint32_t h) const {
    const std::uint32_t twin = h ^ 1;
    const auto& list = around[origin(network, twin)];
    const std::uint32_t k = slot[twin];
    return list[(k + list.size() - 1) % list.size()].second;
  }
};

// The outer rings of the bounded faces (counter-clockwise, positive area). Rings of trees and
// the unbounded face of each component wind zero or clockwise and are left out; a face's ring
// may walk a dead end out and back (a zero-area spike the booleans ignore).
std::vector<Polygon> bounded_faces(const StreetNetwork& network, const Embedding& embedding) {
  std::vector<Polygon> faces;
  std::vector<bool> walked(embedding.slot.size(), false);
  for (std::uint32_t start = 0; start < walked.size(); ++start) {
    if (walked[start]) continue;
    Ring ring;
    for (std::uint32_t h = start; !walked[h]; h = embedding.next(network, h)) {
      walked[h] = true;
      ring.push_back(drop(network.vertices[Embedding::origin(network, h)]));
    }
    // Twice the area about the first vertex, against the size of the terms: a tree's walk sums
    // to zero up to rounding.
    double twice = 0, scale = 0;
    for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
      const double term = cross(ring[k] - ring[0], ring[k + 1] - ring[0]);
      twice += term;
      scale += std::abs(term);
    }
    if (twice > 1e-9 * scale && twice > 0) faces.push_back({std::move(ring), {}});
  }
  return faces;
}

// The part of a road's buffer in the angular gap from half-edge direction `a` counter-clockwise
// to `b` at vertex v (angle `gap`), where the edge rectangles leave a notch: gaps wider than a
// half turn, on the outside of a bend or at a dead end (gap = a full turn). `reach` (> 0) is how
// far the join may extend into both rectangles.
void add_join(Vec2 v, Vec2 a, Vec2 b, double gap, double half, double reach,
              std::vector<Polygon>& pieces) {
  if (gap <= std::numbers::pi * (1 + 1e-12)) return;
  const Vec2 p = v + perp(a) * half, q = v - perp(b) * half;
  // The join's inner corner lies inside both rectangles rather than at v, the middle of their end
  // edges: on the booleans' grid v rounds off that edge and would leave a sliver between join and
  // rectangle, which Clipper then returns as two polygons touching along the edge.
  const Vec2 inner = v + (a + b) * reach;
  const double s = std::sin(gap / 2);
  if (s * kStreetMiterLimit >= 1) {
    // The miter point, where the two offset lines meet behind v.
    const Vec2 miter = p - a * (half * std::tan((gap - std::numbers::pi) / 2));
    pieces.push_back({{inner, p, miter, q}, {}});
    return;
  }
  // Cut square at one half-width from v, across the bisector.
  const double back = half * (1 - s) / -std::cos(gap / 2);
  pieces.push_back({{inner, p, p - a * back, q - b * back, q}, {}});
}

// Edge rectangles plus the joins; their union is the road surface.
std::vector<Polygon> road_pieces(const StreetNetwork& network, const Embedding& embedding,
                                 double half) {
  std::vector<Polygon> pieces;
  std::vector<double> lengths;
  for (const Edge& e : network.edges) {
    const Vec2 a = drop(network.vertices[e[0]]), b = drop(network.vertices[e[1]]);
    const Vec2 n = perp(normalized(b - a)) * half;
    pieces.push_back({{a - n, b - n, b + n, a + n}, {}});
    lengths.push_back(length(b - a));
  }
  for (std::size_t v = 0; v < embedding.around.size(); ++v) {
    const auto& list = embedding.around[v];
    for (std::size_t k = 0; k < list.size(); ++k) {
      const auto& [angle, h] = list[k];
      const auto& [next_angle, next_h] = list[(k + 1) % list.size()];
      double gap = next_angle - angle;
      if (k + 1 == list.size()) gap += 2 * std::numbers::pi;
      if (list.size() == 1) gap = 2 * std::numbers::pi;
      // Half of what keeps v + (a + b) * reach within both rectangles.
      const double reach = 0.25 * std::min({half, lengths[h / 2], lengths[next_h / 2]});
      add_join(drop(network.vertices[v]), Embedding::direction(network, h),
               Embedding::direction(network, next_h), gap, half, reach, pieces);
    }
  }
  return pieces;
}

double lowest_used_z(const StreetNetwork& network) {
  double z = std::numeric_limits<double>::infinity();
  for (const Edge& e : network.edges)
    z = std::min({z, network.vertices[e[0]].z, network.vertices[e[1]].z});
  return network.edges.empty() ? 0 : z;
}

// Rotates the outer ring to start at its anchor (street_network.h) and returns the anchor.
Vec2 start_at_anchor(Polygon& block) {
  Ring& ring = block.outer;
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec2 p : ring) lowest = std::min(lowest, p.y);
  std::size_t anchor = 0;
  for (std::size_t k = 0; k < ring.size(); ++k)
    if (ring[k].y <= lowest + 1e-6 &&
        (ring[anchor].y > lowest + 1e-6 || ring[k].x < ring[anchor].x))
      anchor = k;
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(anchor), ring.end());
  return ring.empty() ? Vec2{} : ring.front();
}

void order_blocks(std::vector<Polygon>& blocks) {
  std::vector<std::pair<Vec2, Polygon>> keyed;
  keyed.reserve(blocks.size());
  for (Polygon& block : blocks) {
    const Vec2 anchor = start_at_anchor(block);
    keyed.emplace_back(anchor, std::move(block));
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.y, a.first.x) < std::tie(b.first.y, b.first.x);
  });
  blocks.clear();
  for (auto& [anchor, block] : keyed) blocks.push_back(std::move(block));
}

StreetSurfaces surfaces(const StreetNetwork& input, double width, bool with_blocks) {
  StreetSurfaces result;
  if (!std::isfinite(width) || !(width > 0)) {
    result.status = StreetStatus::kBadWidth;
    return result;
  }
  const StreetNetwork network = merge_networks({&input, 1}, kStreetSurfaceTolerance);
  result.z = lowest_used_z(network);
  if (network.edges.empty()) return result;  // Clipper fails on no input at all
  const Embedding embedding(network);
  BooleanResult roads = unite(road_pieces(network, embedding, width / 2), {});
  if (!roads.ok()) {
    result.status = StreetStatus::kBooleanFailed;
    return result;
  }
  if (with_blocks) {
    const std::vector<Polygon> faces = bounded_faces(network, embedding);
    if (!faces.empty()) {
      BooleanResult blocks = subtract(faces, roads.polygons);
      if (!blocks.ok()) {
        result.status = StreetStatus::kBooleanFailed;
        return result;
      }
      result.blocks = std::move(blocks.polygons);
      order_blocks(result.blocks);
    }
  }
  result.roads = std::move(roads.polygons);
  return result;
}

}  // namespace

std::string_view to_string(StreetStatus status) {
  switch (status) {
    case StreetStatus::kOk:
      return "ok";
    case StreetStatus::kBadWidth:
      return "the street width must be a finite number greater than 0";
    case StreetStatus::kBooleanFailed:
      return "the street network spans more than 1e12 m; its surfaces cannot be represented";
  }
  return "unknown";
}

StreetNetwork merge_networks(std::span<const StreetNetwork> networks, double tolerance) {
  const double tol = std::isfinite(tolerance) && tolerance > 0 ? tolerance : 0;
  bool changed = false;
  StreetNetwork merged = MergeRound(tol).run(networks, changed);
  for (int round = 1; round < 8 && changed; ++round)
    merged = MergeRound(tol).run({&merged, 1}, changed);
  return merged;
}

StreetSurfaces street_surfaces(const StreetNetwork& network, double width) {
  return surfaces(network, width, true);
}

StreetSurfaces road_buffer(const StreetNetwork& network, double width) {
  return surfaces(network, width, false);
}

StreetParts decompose(const StreetNetwork& network) {
  StreetParts parts;
  for (const Edge& e : network.edges)
    if (valid_edge(network, e))
      parts.edges.push_back({{network.vertices[e[0]], network.vertices[e[1]]}, {{0, 1}}});
  for (const Vec3& p : network.vertices)
    if (finite(p)) parts.vertices.push_back(p);
  return parts;
}

StreetNetwork grid_network(int columns, int rows, double spacing_x, double spacing_y, Vec3 origin) {
  StreetNetwork network;
  if (columns < 1 || rows < 1) return network;
  const auto cols = static_cast<std::uint32_t>(columns);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c)
      network.vertices.push_back(origin + Vec3{c * spacing_x, r * spacing_y, 0});
  for (std::uint32_t v = 0; v < network.vertices.size(); ++v) {
    if ((v % cols) + 1 < cols) network.edges.push_back({v, v + 1});
    if (v / cols + 1 < static_cast<std::uint32_t>(rows)) network.edges.push_back({v, v + cols});
  }
  return network;
}

}  // namespace insula::kernel
