// The ray cast of seed 003, §4.5 (Fig. 8): nearest hits of rays on target meshes through a
// bounding volume hierarchy over all target faces.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "kernel/context_query.h"

namespace insula::kernel {

namespace {

// A target face ready for ray tests: its plane, and its loop projected onto the two world axes
// other than `drop` (the normal's largest), where the loop stays a simple polygon.
struct RayFace {
  std::uint32_t target = 0;
  int drop = 2;
  Vec3 normal;
  double offset = 0;  // plane: dot(normal, p) == offset
  std::uint32_t first = 0;
  std::uint32_t count = 0;  // the loop is projected[first .. first + count)
};

struct BvhNode {
  Bounds3 box;
  std::uint32_t first = 0;  // leaf: faces order_[first .. first + count); inner: left child
  std::uint32_t count = 0;  // 0 marks an inner node
  std::uint32_t right = 0;  // inner: right child
};

constexpr std::uint32_t kLeafSize = 4;

double axis_value(Vec3 v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

Vec2 project(Vec3 p, int drop) {
  return drop == 0 ? Vec2{p.y, p.z} : drop == 1 ? Vec2{p.z, p.x} : Vec2{p.x, p.y};
}

int largest_axis(Vec3 v) {
  const double x = std::abs(v.x), y = std::abs(v.y), z = std::abs(v.z);
  return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
}

class FaceIndex {
 public:
  explicit FaceIndex(std::span<const Mesh> targets);
  // The nearest hit within `limit` along the unit direction, or target -1.
  RayHit nearest(std::size_t ray, Vec3 origin, Vec3 direction, double limit,
                 const SkipPredicate& skip, std::size_t& tests) const;

 private:
  std::uint32_t build(std::uint32_t first, std::uint32_t count);
  bool hits_face(const RayFace& face, Vec3 origin, Vec3 direction, double& t) const;

  std::vector<RayFace> faces_;
  std::vector<Bounds3> face_boxes_;
  std::vector<Vec3> centres_;
  std::vector<Vec2> projected_;
  std::vector<std::uint32_t> order_;
  std::vector<BvhNode> nodes_;
};

FaceIndex::FaceIndex(std::span<const Mesh> targets) {
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const Mesh& mesh = targets[t];
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const Vec3 n = face_normal(mesh, f);
      if (length(n) == 0) continue;  // degenerate: no plane to hit
      RayFace face{static_cast<std::uint32_t>(t),
                   largest_axis(n),
                   n,
                   0,
                   static_cast<std::uint32_t>(projected_.size()),
                   0};
      Bounds3 box;
      Vec3 sum;
      for (const std::uint32_t v : mesh.face(f)) {
        const Vec3 p = mesh.position(v);
        projected_.push_back(project(p, face.drop));
        box.add(p);
        sum += p;
      }
      face.count = static_cast<std::uint32_t>(mesh.face(f).size());
      const Vec3 centre = sum / static_cast<double>(face.count);
      face.offset = dot(n, centre);
      faces_.push_back(face);
      face_boxes_.push_back(box);
      centres_.push_back(centre);
    }
  }
  order_.resize(faces_.size());
  std::iota(order_.begin(), order_.end(), 0u);
  if (!faces_.empty()) build(0, static_cast<std::uint32_t>(faces_.size()));
}

// Builds the subtree over order_[first .. first + count) and returns its node index.
std::uint32_t FaceIndex::build(std::uint32_t first, std::uint32_t count) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Bounds3 box, centres;
  for (std::uint32_t i = first; i < first + count; ++i) {
    box.add(face_boxes_[order_[i]].min);
    box.add(face_boxes_[order_[i]].max);
    centres.add(centres_[order_[i]]);
  }
  nodes_[index].box = box;
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  const int axis = largest_axis(centres.size());
  const std::uint32_t half = count / 2;
  const auto begin = order_.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t a, std::uint32_t b) {
    const double ka = axis_value(centres_[a], axis), kb = axis_value(centres_[b], axis);
    return ka < kb || (ka == kb && a < b);  // total order: the same tree on every library
  });
  const std::uint32_t left = build(first, half);
  const std::uint32_t right = build(first + half, count - half);
  nodes_[index].first = left;
  nodes_[index].right = right;
  return index;
}

// Entry distance of the ray into `box` when it meets it within [0, limit]; negative otherwise.
double enter(const Bounds3& box, Vec3 origin, Vec3 direction, double limit) {
  double t0 = 0, t1 = limit;
  for (int a = 0; a < 3; ++a) {
    const double o = axis_value(origin, a), d = axis_value(direction, a);
    const double lo = axis_value(box.min, a), hi = axis_value(box.max, a);
    if (d == 0) {
      if (o < lo || o > hi) return -1;
      continue;
    }
    double near = (lo - o) / d, far = (hi - o) / d;
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return -1;
  }
  return t0;
}

// Even-odd crossing test; a point on an edge may fall on either side of it.
bool inside(std::span<const Vec2> loop, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec2 a = loop[i], b = loop[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
      in = !in;
    }
  }
  return in;
}

bool FaceIndex::hits_face(const RayFace& face, Vec3 origin, Vec3 direction, double& t) const {
  const double along = dot(face.normal, direction);
  if (std::abs(along) < 1e-12) return false;  // edge-on
  t = (face.offset - dot(face.normal, origin)) / along;
  if (!(t >= 0)) return false;
  const Vec2 p = project(origin + direction * t, face.drop);
  return inside({projected_.data() + face.first, face.count}, p);
}

RayHit FaceIndex::nearest(std::size_t ray, Vec3 origin, Vec3 direction, double limit,
                          const SkipPredicate& skip, std::size_t& tests) const {
  RayHit best;
  double best_t = limit;
  if (nodes_.empty()) return best;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const BvhNode& node = nodes_[stack.back()];
    stack.pop_back();
    const double entry = enter(node.box, origin, direction, best_t);
    if (entry < 0) continue;
    if (node.count == 0) {
      const double left = enter(nodes_[node.first].box, origin, direction, best_t);
      const double right = enter(nodes_[node.right].box, origin, direction, best_t);
      // Push the farther child first so the nearer one is searched first and shrinks best_t.
      if (left <= right) {
        stack.push_back(node.right);
        stack.push_back(node.first);
      } else {
        stack.push_back(node.first);
        stack.push_back(node.right);
      }
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const RayFace& face = faces_[order_[i]];
      if (skip && skip(ray, face.target)) continue;
      ++tests;
      double t = 0;
      if (!hits_face(face, origin, direction, t) || t > best_t) continue;
      if (t == best_t && best.target >= 0 && face.target >= static_cast<std::uint32_t>(best.target))
        continue;
      best_t = t;
      best.target = static_cast<int>(face.target);
    }
  }
  if (best.target >= 0) {
    best.distance = best_t;
    best.position = origin + direction * best_t;
  }
  return best;
}

}  // namespace

RayCastResult ray_cast(std::span<const Ray> rays, std::span<const Mesh> targets,
                       const SkipPredicate& skip) {
  const FaceIndex index(targets);
  RayCastResult result;
  result.hits.resize(rays.size());
  result.target_hit.assign(targets.size(), false);
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const Vec3 direction = normalized(rays[r].direction);
    if (length(direction) == 0 || !(rays[r].max_distance >= 0)) continue;
    result.hits[r] =
        index.nearest(r, rays[r].origin, direction, rays[r].max_distance, skip, result.face_tests);
    if (result.hits[r].target >= 0) result.target_hit[result.hits[r].target] = true;
  }
  return result;
}

}  // namespace insula::kernel
