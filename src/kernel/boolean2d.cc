// Clipper 1 wrapper (boolean2d.h). Clipper is confined to this file: it throws on coordinates
// outside its range, so every call is guarded by an explicit range check and a catch, and nothing
// crosses the module boundary but values.
#include "kernel/boolean2d.h"

#include <algorithm>
#include <cmath>
#include <polyclipping/clipper.hpp>
#include <tuple>
#include <utility>
#include <vector>

namespace insula::kernel {
namespace {

using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;
using ClipperLib::PolyNode;
using ClipperLib::PolyTree;

// The integer frame shared by all operands of one operation.
struct Frame {
  Vec2 origin;
  BooleanStatus status = BooleanStatus::kOk;
};

// `box`: a box the frame must hold besides the inputs (empty: the inputs' bounds alone).
Frame make_frame(const std::vector<const std::vector<Polygon>*>& inputs, double margin,
                 Bounds2 box = {}) {
  Frame frame;
  for (const std::vector<Polygon>* input : inputs) {
    for (const Polygon& p : *input) {
      const Bounds2 b = bounds(p);
      if (b.empty()) continue;
      box.add(b.min);
      box.add(b.max);
    }
  }
  if (!std::isfinite(margin)) frame.status = BooleanStatus::kNonFinite;
  if (box.empty()) return frame;
  if (!std::isfinite(box.min.x) || !std::isfinite(box.min.y) || !std::isfinite(box.max.x) ||
      !std::isfinite(box.max.y)) {
    frame.status = BooleanStatus::kNonFinite;
    return frame;
  }
  // NaN never wins a min/max comparison in Bounds2::add, so look for it explicitly.
  for (const std::vector<Polygon>* input : inputs)
    for (const Polygon& p : *input) {
      auto bad = [](const Ring& r) {
        return std::any_of(r.begin(), r.end(),
                           [](Vec2 v) { return !std::isfinite(v.x) || !std::isfinite(v.y); });
      };
      if (bad(p.outer) || std::any_of(p.holes.begin(), p.holes.end(), bad))
        frame.status = BooleanStatus::kNonFinite;
    }
  const double extent =
      std::max(box.max.x - box.min.x, box.max.y - box.min.y) + 2 * std::abs(margin);
  if (frame.status == BooleanStatus::kOk && !(extent <= kBooleanMaxExtent))
    frame.status = BooleanStatus::kRangeTooLarge;
  frame.origin = (box.min + box.max) * 0.5;
  return frame;
}

IntPoint to_int(Vec2 p, Vec2 origin) {
  return IntPoint(std::llround((p.x - origin.x) * kBooleanScale),
                  std::llround((p.y - origin.y) * kBooleanScale));
}

Vec2 from_int(const IntPoint& q, Vec2 origin) {
  return origin + Vec2{double(q.X) / kBooleanScale, double(q.Y) / kBooleanScale};
}

// Appends `ring` as normalize() would leave it (closing duplicates dropped, outer rings
// counter-clockwise, holes clockwise), without copying the polygon first.
void add_ring(const Ring& ring, bool hole, Vec2 origin, Paths& out) {
  std::size_t n = ring.size();
  while (n > 1 && ring.front() == ring[n - 1]) --n;
  if (n != ring.size()) {
    add_ring(Ring(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(n)), hole, origin, out);
    return;
  }
  const double twice = signed_area(ring);
  const bool reverse = hole ? twice > 0 : twice < 0;
  Path path;
  path.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const IntPoint q = to_int(ring[reverse ? n - 1 - k : k], origin);
    if (path.empty() || !(path.back() == q)) path.push_back(q);
  }
  while (path.size() > 1 && path.front() == path.back()) path.pop_back();
  if (path.size() >= 3) out.push_back(std::move(path));
}

// Normalised rings, so that under the non-zero rule holes cancel their outer ring.
Paths to_paths(const std::vector<Polygon>& polygons, Vec2 origin) {
  Paths paths;
  std::size_t rings = 0;
  for (const Polygon& p : polygons) rings += 1 + p.holes.size();
  paths.reserve(rings);
  for (const Polygon& p : polygons) {
    add_ring(p.outer, false, origin, paths);
    for (const Ring& hole : p.holes) add_ring(hole, true, origin, paths);
  }
  return paths;
}

// Is b within half a grid unit of the line through a and c? Clipper keeps such vertices where
// input edges met (the ends of a shared wall after a union); they carry no shape.
bool collinear(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
  const double ux = double(c.X - a.X), uy = double(c.Y - a.Y);
  const double vx = double(b.X - a.X), vy = double(b.Y - a.Y);
  const double base = std::hypot(ux, uy);
  if (base == 0) return true;
  return std::abs(ux * vy - uy * vx) <= 0.5 * base && ux * vx + uy * vy >= 0 &&
         vx * vx + vy * vy <= base * base;
}

Ring to_ring(const Path& path, Vec2 origin) {
  Path kept;
  for (const IntPoint& q : path) {
    while (kept.size() >= 2 && collinear(kept[kept.size() - 2], kept.back(), q)) kept.pop_back();
    kept.push_back(q);
  }
  // Close the loop: the last and first kept vertices may be straight too.
  std::size_t first = 0;
  bool changed = true;
  while (changed && kept.size() - first >= 3) {
    changed = false;
    if (collinear(kept[kept.size() - 2], kept.back(), kept[first])) {
      kept.pop_back();
      changed = true;
    } else if (collinear(kept.back(), kept[first], kept[first + 1])) {
      ++first;
      changed = true;
    }
  }
  Ring ring;
  ring.reserve(kept.size() - first);
  for (std::size_t i = first; i < kept.size(); ++i) ring.push_back(from_int(kept[i], origin));
  return ring;
}

// Outer nodes become polygons, their children holes, and the holes' children (islands inside
// holes) are outer nodes again.
void collect(const PolyNode& outer, Vec2 origin, std::vector<Polygon>& out) {
  Polygon polygon;
  polygon.outer = to_ring(outer.Contour, origin);
  for (const PolyNode* hole : outer.Childs) {
    polygon.holes.push_back(to_ring(hole->Contour, origin));
    for (const PolyNode* island : hole->Childs) collect(*island, origin, out);
  }
  normalize(polygon);
  out.push_back(std::move(polygon));
}

Vec2 lowest_vertex(const Polygon& p) {
  Vec2 best = p.outer.empty() ? Vec2{} : p.outer.front();
  for (const Vec2& v : p.outer)
    if (std::tie(v.y, v.x) < std::tie(best.y, best.x)) best = v;
  return best;
}

std::vector<Polygon> from_tree(const PolyTree& tree, Vec2 origin) {
  std::vector<Polygon> out;
  for (const PolyNode* node : tree.Childs) collect(*node, origin, out);
  std::vector<std::pair<double, Polygon>> keyed;
  for (Polygon& p : out) keyed.emplace_back(area(p), std::move(p));
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first > b.first;
    const Vec2 la = lowest_vertex(a.second), lb = lowest_vertex(b.second);
    return std::tie(la.y, la.x) < std::tie(lb.y, lb.x);
  });
  out.clear();
  for (auto& [a, p] : keyed) out.push_back(std::move(p));
  return out;
}

// Does a ring of `node` (its contour or a hole's) run along an edge of another of its rings, here
// or in an island further in? A region's boundary never does: the two would bound a strip of no
// width.
bool shares_an_edge(const PolyNode& node) {
  if (node.Childs.empty()) return false;
  using Edge = std::pair<IntPoint, IntPoint>;
  std::vector<Edge> edges;
  const auto add = [&edges](const Path& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      IntPoint p = ring[i], q = ring[(i + 1) % ring.size()];
      if (std::tie(q.X, q.Y) < std::tie(p.X, p.Y)) std::swap(p, q);
      edges.emplace_back(p, q);
    }
  };
  add(node.Contour);
  for (const PolyNode* hole : node.Childs) add(hole->Contour);
  const auto key = [](const Edge& e) {
    return std::tie(e.first.X, e.first.Y, e.second.X, e.second.Y);
  };
  std::sort(edges.begin(), edges.end(),
            [&](const Edge& l, const Edge& r) { return key(l) < key(r); });
  if (std::adjacent_find(edges.begin(), edges.end(), [&](const Edge& l, const Edge& r) {
        return key(l) == key(r);
      }) != edges.end()) {
    return true;
  }
  for (const PolyNode* hole : node.Childs) {
    for (const PolyNode* island : hole->Childs) {
      if (shares_an_edge(*island)) return true;
    }
  }
  return false;
}

// Runs one Clipper boolean; the PolyTree keeps holes with their outer ring.
bool execute(ClipperLib::ClipType type, const Paths& a, const Paths& b, PolyTree& tree) {
  ClipperLib::Clipper clipper;
  clipper.StrictlySimple(true);
  // AddPaths says whether any ring had an area. Clipper reports a run without one as a failure;
  // here it is an empty result (a window a split left one grid unit wide rounds to a line).
  const bool subject = clipper.AddPaths(a, ClipperLib::ptSubject, true);
  const bool clip = clipper.AddPaths(b, ClipperLib::ptClip, true);
  if (!subject && !clip) {
    tree.Clear();
    return true;
  }
  if (!clipper.Execute(type, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero)) return false;
  if (std::none_of(tree.Childs.begin(), tree.Childs.end(),
                   [](const PolyNode* outer) { return shares_an_edge(*outer); })) {
    return true;
  }
  // Clipper 1's strictly simple pass can give a region with a hole along its own outline: a
  // setback's remainder came back as the whole lot with each strip along a bend of the outline a
  // hole sharing its edge (the area is right, the region invalid: on a curved OpenStreetMap
  // footprint no triangulation took it, so district.cga's parcel and yard had no mesh). The plain
  // pass gets such regions right; a strictly simple union of its rings then splits the rings that
  // touch themselves.
  ClipperLib::Clipper plain;
  plain.AddPaths(a, ClipperLib::ptSubject, true);
  plain.AddPaths(b, ClipperLib::ptClip, true);
  Paths rings;
  if (!plain.Execute(type, rings, ClipperLib::pftNonZero, ClipperLib::pftNonZero)) return false;
  ClipperLib::Clipper simple;
  simple.StrictlySimple(true);
  if (!simple.AddPaths(rings, ClipperLib::ptSubject, true)) {
    tree.Clear();
    return true;
  }
  return simple.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
}

BooleanResult run(ClipperLib::ClipType type, const std::vector<Polygon>& a,
                  const std::vector<Polygon>& b, const Bounds2& box = {}) {
  BooleanResult result;
  const Frame frame = make_frame({&a, &b}, 0, box);
  result.status = frame.status;
  if (!result.ok()) return result;
  try {
    PolyTree tree;
    if (!execute(type, to_paths(a, frame.origin), to_paths(b, frame.origin), tree)) {
      result.status = BooleanStatus::kClipperFailed;
      return result;
    }
    result.polygons = from_tree(tree, frame.origin);
  } catch (...) {  // ClipperLib::clipperException or std::bad_alloc: reported, never propagated
    result.polygons.clear();
    result.status = BooleanStatus::kClipperFailed;
  }
  return result;
}

ClipperLib::JoinType clipper_join(JoinType join) {
  switch (join) {
    case JoinType::kRound:
      return ClipperLib::jtRound;
    case JoinType::kSquare:
      return ClipperLib::jtSquare;
    case JoinType::kMiter:
      break;
  }
  return ClipperLib::jtMiter;
}

}  // namespace

std::string_view to_string(BooleanStatus status) {
  switch (status) {
    case BooleanStatus::kOk:
      return "ok";
    case BooleanStatus::kNonFinite:
      return "a coordinate or parameter is NaN or infinite";
    case BooleanStatus::kRangeTooLarge:
      return "the input spans more than 1e12 m; it cannot be represented at 1e-6 m resolution";
    case BooleanStatus::kClipperFailed:
      return "the polygon clipper failed";
  }
  return "unknown";
}

BooleanResult unite(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  return run(ClipperLib::ctUnion, a, b);
}

BooleanResult intersect(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  return run(ClipperLib::ctIntersection, a, b);
}

BooleanResult subtract(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  return run(ClipperLib::ctDifference, a, b);
}

BooleanResult subtract(const std::vector<Polygon>& a, const std::vector<Polygon>& b,
                       const Bounds2& frame) {
  return run(ClipperLib::ctDifference, a, b, frame);
}

BooleanResult exclusive_or(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  return run(ClipperLib::ctXor, a, b);
}

std::vector<Polygon> union_all(const std::vector<Polygon>& polygons) {
  return run(ClipperLib::ctUnion, polygons, {}).polygons;
}

BooleanResult offset(const std::vector<Polygon>& polygons, double delta, JoinType join,
                     double miter_limit, double arc_tolerance) {
  BooleanResult result;
  const Frame frame = make_frame({&polygons}, delta);
  result.status = frame.status;
  if (!std::isfinite(miter_limit) || !std::isfinite(arc_tolerance))
    result.status = BooleanStatus::kNonFinite;
  if (!result.ok()) return result;
  try {
    // Unite first: offsetting overlapping polygons one by one would shrink each on its own.
    PolyTree united;
    if (!execute(ClipperLib::ctUnion, to_paths(polygons, frame.origin), {}, united)) {
      result.status = BooleanStatus::kClipperFailed;
      return result;
    }
    Paths paths;
    ClipperLib::PolyTreeToPaths(united, paths);
    ClipperLib::ClipperOffset offsetter(std::max(miter_limit, 1.0),
                                        std::max(arc_tolerance, 1e-6) * kBooleanScale);
    offsetter.AddPaths(paths, clipper_join(join), ClipperLib::etClosedPolygon);
    PolyTree tree;
    offsetter.Execute(tree, delta * kBooleanScale);
    result.polygons = from_tree(tree, frame.origin);
  } catch (...) {
    result.polygons.clear();
    result.status = BooleanStatus::kClipperFailed;
  }
  return result;
}

}  // namespace insula::kernel
