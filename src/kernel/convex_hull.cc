#include "kernel/convex_hull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <vector>

#include "base/union_find.h"

namespace insula::kernel {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

bool finite(Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

std::uint64_t edge_key(std::uint32_t from, std::uint32_t to) {
  return (static_cast<std::uint64_t>(from) << 32) | to;
}

// A triangle of the hull under construction: edge i runs v[i] -> v[i + 1] and borders adj[i].
struct HullFace {
  std::array<std::uint32_t, 3> v{};
  std::array<std::uint32_t, 3> adj{kNone, kNone, kNone};
  Vec3 normal;  // unit, outward
  double offset = 0;
  std::vector<std::uint32_t> outside;  // pending points in front of this face
  bool alive = true;
};

class HullBuilder {
 public:
  HullBuilder(std::span<const Vec3> points, double tolerance) : p_(points), eps_(tolerance) {}

  HullStatus build();
  Mesh to_mesh(const HullOptions& options) const;

 private:
  double distance(const HullFace& f, std::uint32_t point) const {
    return dot(f.normal, p_[point]) - f.offset;
  }
  std::uint32_t add_face(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  HullStatus initial_simplex(std::array<std::uint32_t, 4>& simplex) const;
  void assign(const std::vector<std::uint32_t>& points, std::span<const std::uint32_t> faces);
  bool add_point(std::uint32_t face);
  std::vector<std::uint32_t> coplanar_groups() const;

  std::span<const Vec3> p_;
  double eps_;
  std::vector<HullFace> faces_;
};

std::uint32_t HullBuilder::add_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  HullFace f;
  f.v = {a, b, c};
  f.normal = normalized(cross(p_[b] - p_[a], p_[c] - p_[a]));
  f.offset = dot(f.normal, p_[a]);
  faces_.push_back(std::move(f));
  return static_cast<std::uint32_t>(faces_.size() - 1);
}

// Four points spanning a tetrahedron as large as cheaply found: the farthest pair of axis
// extremes, the point farthest from their line, the point farthest from that plane.
HullStatus HullBuilder::initial_simplex(std::array<std::uint32_t, 4>& s) const {
  std::array<std::uint32_t, 6> extreme{};
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      const auto coordinate = [axis](Vec3 p) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; };
      if (coordinate(p_[i]) < coordinate(p_[extreme[2 * axis]])) extreme[2 * axis] = i;
      if (coordinate(p_[i]) > coordinate(p_[extreme[2 * axis + 1]])) extreme[2 * axis + 1] = i;
    }
  }
  double best = -1;
  for (std::uint32_t a : extreme) {
    for (std::uint32_t b : extreme) {
      if (length(p_[a] - p_[b]) > best) {
        best = length(p_[a] - p_[b]);
        s[0] = a;
        s[1] = b;
      }
    }
  }
  if (best <= eps_) return HullStatus::kTooFewPoints;
  const Vec3 axis = normalized(p_[s[1]] - p_[s[0]]);
  best = -1;
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    const double d = length(cross(p_[i] - p_[s[0]], axis));
    if (d > best) {
      best = d;
      s[2] = i;
    }
  }
  if (best <= eps_) return HullStatus::kCollinear;
  const Vec3 n = normalized(cross(p_[s[1]] - p_[s[0]], p_[s[2]] - p_[s[0]]));
  best = -1;
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    const double d = std::abs(dot(p_[i] - p_[s[0]], n));
    if (d > best) {
      best = d;
      s[3] = i;
    }
  }
  return best <= eps_ ? HullStatus::kCoplanar : HullStatus::kOk;
}

// Gives each point to the face it lies farthest in front of; points behind all are inside.
void HullBuilder::assign(const std::vector<std::uint32_t>& points,
                         std::span<const std::uint32_t> faces) {
  for (std::uint32_t point : points) {
    std::uint32_t best = kNone;
    double best_distance = eps_;
    for (std::uint32_t f : faces) {
      const double d = distance(faces_[f], point);
      if (d > best_distance) {
        best_distance = d;
        best = f;
      }
    }
    if (best != kNone) faces_[best].outside.push_back(point);
  }
}

// Adds the farthest outside point of `face`: removes every face it sees (found by flooding from
// `face`, so the visible region is connected) and cones the horizon edges to it.
bool HullBuilder::add_point(std::uint32_t face) {
  const std::vector<std::uint32_t>& candidates = faces_[face].outside;
  const std::uint32_t eye = *std::max_element(
      candidates.begin(), candidates.end(), [&](std::uint32_t a, std::uint32_t b) {
        return distance(faces_[face], a) < distance(faces_[face], b);
      });
  std::vector<std::uint32_t> visible{face};
  std::vector<char> seen(faces_.size(), 0);
  seen[face] = 1;
  for (std::size_t k = 0; k < visible.size(); ++k) {
    for (std::uint32_t g : faces_[visible[k]].adj) {
      if (seen[g] || distance(faces_[g], eye) <= eps_) continue;
      seen[g] = 1;
      visible.push_back(g);
    }
  }
  std::vector<std::uint32_t> orphans;
  std::vector<std::uint32_t> cone;
  std::unordered_map<std::uint32_t, std::uint32_t> starting_at;
  std::unordered_map<std::uint32_t, std::uint32_t> ending_at;
  for (std::uint32_t f : visible) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t g = faces_[f].adj[i];
      if (seen[g]) continue;
      const std::uint32_t a = faces_[f].v[i];
      const std::uint32_t b = faces_[f].v[(i + 1) % 3];
      const std::uint32_t fresh = add_face(a, b, eye);
      faces_[fresh].adj[0] = g;
      for (int j = 0; j < 3; ++j) {
        if (faces_[g].v[j] == b && faces_[g].v[(j + 1) % 3] == a) faces_[g].adj[j] = fresh;
      }
      // A horizon that visits a vertex twice is not a simple loop: the cone would not be a disc.
      if (!starting_at.emplace(a, fresh).second || !ending_at.emplace(b, fresh).second) {
        return false;
      }
      cone.push_back(fresh);
    }
  }
  for (std::uint32_t f : cone) {
    // Edge 1 (b -> eye) meets the cone face starting at b; edge 2 (eye -> a) the one ending at a.
    const auto next = starting_at.find(faces_[f].v[1]);
    const auto previous = ending_at.find(faces_[f].v[0]);
    if (next == starting_at.end() || previous == ending_at.end()) return false;
    faces_[f].adj[1] = next->second;
    faces_[f].adj[2] = previous->second;
  }
  for (std::uint32_t f : visible) {
    faces_[f].alive = false;
    for (std::uint32_t point : faces_[f].outside) {
      if (point != eye) orphans.push_back(point);
    }
    faces_[f].outside.clear();
  }
  assign(orphans, cone);
  return true;
}

HullStatus HullBuilder::build() {
  std::array<std::uint32_t, 4> s{};
  const HullStatus status = initial_simplex(s);
  if (status != HullStatus::kOk) return status;
  // Orient the base so the apex lies behind it, then add the three sides.
  const Vec3 n = cross(p_[s[1]] - p_[s[0]], p_[s[2]] - p_[s[0]]);
  if (dot(p_[s[3]] - p_[s[0]], n) > 0) std::swap(s[1], s[2]);
  const std::array<std::array<std::uint32_t, 3>, 4> tetra{
      {{s[0], s[1], s[2]}, {s[0], s[3], s[1]}, {s[1], s[3], s[2]}, {s[2], s[3], s[0]}}};
  std::unordered_map<std::uint64_t, std::pair<std::uint32_t, int>> edges;
  for (const auto& t : tetra) {
    const std::uint32_t f = add_face(t[0], t[1], t[2]);
    for (int i = 0; i < 3; ++i) edges[edge_key(t[i], t[(i + 1) % 3])] = {f, i};
  }
  for (auto& [key, where] : edges) {
    const auto twin = edges.at(edge_key(static_cast<std::uint32_t>(key & 0xffffffffU),
                                        static_cast<std::uint32_t>(key >> 32)));
    faces_[where.first].adj[where.second] = twin.first;
  }
  std::vector<std::uint32_t> rest;
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    if (i != s[0] && i != s[1] && i != s[2] && i != s[3]) rest.push_back(i);
  }
  const std::array<std::uint32_t, 4> initial{0, 1, 2, 3};
  assign(rest, initial);
  // Each step removes its eye point from the pending sets, so this ends.
  for (std::uint32_t f = 0; f < faces_.size(); ++f) {
    while (faces_[f].alive && !faces_[f].outside.empty()) {
      if (!add_point(f)) return HullStatus::kNumericalFailure;
    }
  }
  return HullStatus::kOk;
}

// Union of neighbouring faces whose planes agree within the tolerance; returns each face's root.
std::vector<std::uint32_t> HullBuilder::coplanar_groups() const {
  base::UnionFind groups(faces_.size());
  for (std::uint32_t f = 0; f < faces_.size(); ++f) {
    if (!faces_[f].alive) continue;
    for (int i = 0; i < 3; ++i) {
      const HullFace& g = faces_[faces_[f].adj[i]];
      const std::uint32_t apex = faces_[f].v[(i + 2) % 3];
      if (dot(g.normal, faces_[f].normal) > 0 && std::abs(distance(g, apex)) <= eps_) {
        groups.unite(f, faces_[f].adj[i]);
      }
    }
  }
  std::vector<std::uint32_t> root(faces_.size());
  for (std::uint32_t f = 0; f < faces_.size(); ++f) root[f] = groups.find(f);
  return root;
}

Mesh HullBuilder::to_mesh(const HullOptions& options) const {
  std::vector<std::uint32_t> remap(p_.size(), kNone);
  for (const HullFace& f : faces_) {
    if (!f.alive) continue;
    for (std::uint32_t v : f.v) remap[v] = 0;
  }
  Mesh mesh;
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    if (remap[i] == 0) remap[i] = mesh.add_vertex(p_[i]);
  }
  std::vector<std::uint32_t> group(faces_.size());
  if (options.merge_coplanar) {
    group = coplanar_groups();
  } else {
    std::iota(group.begin(), group.end(), 0U);
  }
  // Each group's boundary (edges whose neighbour is in another group) is one convex loop.
  std::vector<std::vector<std::uint32_t>> members(faces_.size());
  for (std::uint32_t f = 0; f < faces_.size(); ++f) {
    if (faces_[f].alive) members[group[f]].push_back(f);
  }
  std::vector<char> emitted(faces_.size(), 0);
  std::unordered_map<std::uint32_t, std::uint32_t> next;
  std::vector<std::uint32_t> loop;
  for (std::uint32_t f = 0; f < faces_.size(); ++f) {
    if (!faces_[f].alive || emitted[group[f]]) continue;
    emitted[group[f]] = 1;
    next.clear();
    std::uint32_t start = kNone;
    for (std::uint32_t g : members[group[f]]) {
      for (int i = 0; i < 3; ++i) {
        if (group[faces_[g].adj[i]] == group[f]) continue;
        next[faces_[g].v[i]] = faces_[g].v[(i + 1) % 3];
        start = faces_[g].v[i];
      }
    }
    loop.clear();
    for (std::uint32_t v = start; loop.size() <= next.size(); v = next[v]) {
      loop.push_back(remap[v]);
      if (next[v] == start) break;
    }
    FaceTag tag = options.tag;
    tag.face_id = options.tag.face_id + static_cast<std::uint32_t>(mesh.face_count());
    mesh.add_face(loop, tag);
  }
  return mesh;
}

}  // namespace

std::string_view hull_status_message(HullStatus status) {
  switch (status) {
    case HullStatus::kOk:
      return "ok";
    case HullStatus::kTooFewPoints:
      return "too few distinct points for a hull";
    case HullStatus::kCollinear:
      return "all points lie on one line";
    case HullStatus::kCoplanar:
      return "all points lie in one plane";
    case HullStatus::kNonFinite:
      return "a coordinate is not finite";
    case HullStatus::kNumericalFailure:
      return "the hull could not be built robustly (numerical failure)";
  }
  return "unknown hull status";
}

Hull2Result convex_hull_2d(std::span<const Vec2> points) {
  Hull2Result result;
  std::vector<Vec2> sorted(points.begin(), points.end());
  for (Vec2 p : sorted) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      result.status = HullStatus::kNonFinite;
      return result;
    }
  }
  std::sort(sorted.begin(), sorted.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.size() < 3) {
    result.status = HullStatus::kTooFewPoints;
    return result;
  }
  // Lower chain left to right, then upper chain right to left; a point that does not turn left
  // (cross <= 0) is popped, which also drops collinear points.
  Ring& hull = result.ring;
  hull.resize(2 * sorted.size());
  std::size_t k = 0;
  const auto push = [&](Vec2 p, std::size_t floor) {
    while (k >= floor && cross(hull[k - 1] - hull[k - 2], p - hull[k - 2]) <= 0) --k;
    hull[k++] = p;
  };
  for (Vec2 p : sorted) push(p, 2);
  const std::size_t lower = k + 1;
  for (std::size_t i = sorted.size() - 1; i-- > 0;) push(sorted[i], lower);
  hull.resize(k - 1);  // the last point repeats the first
  if (hull.size() < 3) {
    result.status = HullStatus::kCollinear;
    hull.clear();
  }
  return result;
}

Hull3Result convex_hull_3d(std::span<const Vec3> points, const HullOptions& options) {
  Hull3Result result;
  Bounds3 box;
  double largest = 0;
  for (Vec3 p : points) {
    if (!finite(p)) {
      result.status = HullStatus::kNonFinite;
      return result;
    }
    box.add(p);
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  if (points.size() < 4) {
    result.status = HullStatus::kTooFewPoints;
    return result;
  }
  const double automatic = 1e-10 * (length(box.size()) + largest);
  const double tolerance = options.tolerance > 0 ? options.tolerance : automatic;
  HullBuilder builder(points, tolerance);
  result.status = builder.build();
  if (result.ok()) result.mesh = builder.to_mesh(options);
  return result;
}

std::optional<Vec2> min_area_rectangle_direction(std::span<const Vec2> points) {
  const Hull2Result hull = convex_hull_2d(points);
  if (!hull.ok() || hull.ring.size() < 2) return std::nullopt;
  const Ring& ring = hull.ring;
  double best = 1e300;
  std::optional<Vec2> longer;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 d = normalized(ring[(i + 1) % ring.size()] - ring[i]);
    const Vec2 n{-d.y, d.x};
    double lo_d = 1e300, hi_d = -1e300, lo_n = 1e300, hi_n = -1e300;
    for (const Vec2& p : ring) {
      lo_d = std::min(lo_d, dot(p, d)), hi_d = std::max(hi_d, dot(p, d));
      lo_n = std::min(lo_n, dot(p, n)), hi_n = std::max(hi_n, dot(p, n));
    }
    const double along = hi_d - lo_d, across = hi_n - lo_n;
    if (along * across < best - 1e-12) {
      best = along * across;
      longer = along >= across ? d : n;
    }
  }
  return longer;
}

}  // namespace insula::kernel
