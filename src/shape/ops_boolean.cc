// Union, intersection and subtraction of components (seed 001 §3.4.3 "Boolean operations"), 2D or
// 3D. Placement: union and intersection become roots, a subtraction's result becomes children of
// the component it cuts. Prisms standing on parallel y axes (the rooms, corridors and shafts of a
// building) are combined exactly in 2D (kernel/boolean2d.h) and re-extruded, which keeps n-gon
// faces and face ids; other solids go through CGAL corefinement (kernel/boolean3d.h).
#include <algorithm>
#include <cmath>

#include "kernel/boolean2d.h"
#include "kernel/boolean3d.h"
#include "kernel/extrude.h"
#include "shape/component_ops.h"

namespace insula::shape {

using kernel::FaceTag;
using kernel::Mesh;
using kernel::Polygon;
using kernel::Vec2;
using kernel::Vec3;

namespace {

constexpr double kPlanar = 1e-6;  // meters: points this close to a plane lie on it

enum class Op { kUnion, kIntersection, kDifference };

// --- flat components

// `id`'s outline in the 2D frame of `ref` (its scope's xy plane); false when not coplanar.
bool outline_in(const ShapeTree& tree, ShapeId id, const Scope& ref, Polygon& out) {
  const Shape& s = tree[id];
  const auto convert = [&](const kernel::Ring& ring, kernel::Ring& into) {
    for (Vec2 p : ring) {
      const Vec3 q = ref.to_local(s.scope.to_world(kernel::lift(p, 0)));
      if (std::fabs(q.z) > kPlanar) return false;
      into.push_back(kernel::drop(q));
    }
    return true;
  };
  out = {};
  if (!convert(s.outline->outer, out.outer)) return false;
  for (const auto& hole : s.outline->holes) {
    if (!convert(hole, out.holes.emplace_back())) return false;
  }
  return true;
}

FaceTag first_tag(const Shape& s) {
  return s.mesh && !s.mesh->empty() ? s.mesh->tag(0) : FaceTag{};
}

// A flat component per polygon, in `ref`'s plane and axes: children of `parent`, or roots.
OpResult add_flat(ShapeTree& tree, ShapeId parent, const Scope& ref, FaceTag tag,
                  const std::vector<Polygon>& polygons) {
  OpResult result;
  for (std::uint32_t i = 0; i < polygons.size(); ++i) {
    const kernel::Bounds2 b = kernel::bounds(polygons[i]);
    auto outline = std::make_shared<Polygon>(polygons[i]);
    const auto shift = [&](kernel::Ring& ring) {
      for (Vec2& p : ring) p -= b.min;
    };
    shift(outline->outer);
    for (auto& hole : outline->holes) shift(hole);
    Scope scope = ref;
    scope.origin = ref.to_world(kernel::lift(b.min, 0));
    scope.size = {b.max.x - b.min.x, b.max.y - b.min.y, 0};
    auto mesh = flat_mesh(*outline, tag);
    const ShapeId child = parent == kNoShape ? tree.add_root(scope, mesh, outline)
                                             : tree.add_child(parent, scope, mesh, outline);
    result.add(child, i);
  }
  return result;
}

OpResult flat_boolean(ShapeTree& tree, std::span<const ShapeId> ids, Op op) {
  const Scope ref = tree[ids[0]].scope;
  std::vector<Polygon> acc(1);
  if (!outline_in(tree, ids[0], ref, acc[0])) return OpResult::failure("bad outline");
  for (std::size_t i = 1; i < ids.size(); ++i) {
    std::vector<Polygon> other(1);
    if (!tree[ids[i]].is_flat() || !outline_in(tree, ids[i], ref, other[0])) {
      return OpResult::failure("component " + std::to_string(ids[i]) +
                               " is not flat and coplanar with component " +
                               std::to_string(ids[0]));
    }
    kernel::BooleanResult r = op == Op::kUnion          ? kernel::unite(acc, other)
                              : op == Op::kIntersection ? kernel::intersect(acc, other)
                                                        : kernel::subtract(acc, other);
    if (!r.ok()) return OpResult::failure(std::string(kernel::to_string(r.status)));
    acc = std::move(r.polygons);
  }
  const ShapeId parent = op == Op::kDifference ? ids[0] : kNoShape;
  OpResult result = add_flat(tree, parent, ref, first_tag(tree[ids[0]]), acc);
  if (result.children.empty()) result.warning = "the result is empty";
  return result;
}

// --- 3D prisms

// A prism along `ref`'s y axis: its cross-section in ref's (x, -z) plane (counter-clockwise seen
// from +y) and its y range in ref space.
struct Prism {
  std::vector<Polygon> section;
  double y0 = 0;
  double y1 = 0;
  Mesh mesh;  // in ref space, for carrying face tags
};

Vec2 plane_point(Vec3 p) {
  return {p.x, -p.z};
}

std::optional<Prism> as_prism(const ShapeTree& tree, ShapeId id, const Scope& ref) {
  const Shape& s = tree[id];
  if (!s.mesh || s.mesh->empty() || s.is_flat()) return {};
  if (std::fabs(dot(s.scope.y, ref.y)) < 1 - 1e-9) return {};
  const double h = s.scope.size.y;
  for (const Vec3& p : s.mesh->positions()) {
    if (std::fabs(p.y) > 1e-7 && std::fabs(p.y - h) > 1e-7) return {};
  }
  Prism prism;
  prism.mesh = kernel::transformed(*s.mesh, scope_transform(s.scope));
  kernel::Transform to_ref = *kernel::inverse(scope_transform(ref));
  kernel::transform_mesh(prism.mesh, to_ref);
  std::vector<Polygon> bottoms;
  for (std::size_t f = 0; f < s.mesh->face_count(); ++f) {
    const Vec3 n = kernel::face_normal(*s.mesh, f);
    if (std::fabs(n.y) < 1e-7) continue;  // a side
    if (std::fabs(std::fabs(n.y) - 1) > 1e-7) return {};
    if (n.y > 0) continue;
    Polygon& p = bottoms.emplace_back();
    for (std::uint32_t v : prism.mesh.face(f))
      p.outer.push_back(plane_point(prism.mesh.position(v)));
  }
  prism.section = kernel::union_all(bottoms);
  const double a = dot(s.scope.origin - ref.origin, ref.y);
  prism.y0 = dot(s.scope.y, ref.y) > 0 ? a : a - h;
  prism.y1 = prism.y0 + h;
  return prism;
}

// Whether the point (on face f's plane) lies in the face, boundary included: the loop projected
// along the normal's dominant axis.
bool face_contains(const Mesh& mesh, std::size_t f, Vec3 point, Vec3 normal) {
  const double ax = std::fabs(normal.x);
  const double ay = std::fabs(normal.y);
  const double az = std::fabs(normal.z);
  const auto flat = [&](Vec3 p) -> Vec2 {
    if (ax >= ay && ax >= az) return {p.y, p.z};
    if (ay >= az) return {p.x, p.z};
    return {p.x, p.y};
  };
  Polygon loop;
  for (std::uint32_t v : mesh.face(f)) loop.outer.push_back(flat(mesh.position(v)));
  return kernel::locate(loop, flat(point), kPlanar) != kernel::PointLocation::kOutside;
}

// The tag of the source face (ref space) holding `centre`, with a parallel normal.
FaceTag carried_tag(std::span<const Prism* const> sources, Vec3 centre, Vec3 normal,
                    FaceTag fallback) {
  for (const Prism* src : sources) {
    for (std::size_t f = 0; f < src->mesh.face_count(); ++f) {
      const Vec3 n = kernel::face_normal(src->mesh, f);
      if (std::fabs(std::fabs(dot(n, normal)) - 1) > 1e-6) continue;
      const Vec3 p = src->mesh.position(src->mesh.face(f)[0]);
      if (std::fabs(dot(n, centre - p)) > kPlanar) continue;
      if (face_contains(src->mesh, f, centre, n)) return src->mesh.tag(f);
    }
  }
  return fallback;
}

bool same_tag(const FaceTag& a, const FaceTag& b) {
  return a.face_id == b.face_id && a.semantic == b.semantic && a.material == b.material;
}

// §3.1.1: "the boolean union ... will only merge faces sharing the same ID". Clipper merges
// collinear edges of the result; this puts back, on each result edge, the source vertices where
// the carried face changes, so side faces from differently tagged sources stay apart.
void keep_face_ids(Polygon& polygon, double y_mid, std::span<const Prism* const> sources) {
  std::vector<Vec2> points;
  for (const Prism* src : sources) {
    for (const Polygon& p : src->section) {
      points.insert(points.end(), p.outer.begin(), p.outer.end());
      for (const auto& hole : p.holes) points.insert(points.end(), hole.begin(), hole.end());
    }
  }
  const auto tag_at = [&](Vec2 a, Vec2 b) {
    const Vec2 m = (a + b) * 0.5;
    const Vec2 d = b - a;
    return carried_tag(sources, {m.x, y_mid, -m.y}, normalized(Vec3{d.y, 0, d.x}), FaceTag{});
  };
  const auto refine = [&](kernel::Ring& ring) {
    kernel::Ring out;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i];
      const Vec2 b = ring[(i + 1) % ring.size()];
      const Vec2 d = b - a;
      const double len2 = dot(d, d);
      std::vector<double> ts;
      for (Vec2 p : points) {
        const double t = len2 > 0 ? dot(p - a, d) / len2 : 0;
        if (t > 1e-9 && t < 1 - 1e-9 && kernel::distance_to_segment(p, a, b) <= kPlanar) {
          ts.push_back(t);
        }
      }
      std::sort(ts.begin(), ts.end());
      ts.erase(std::unique(ts.begin(), ts.end(), [](double x, double y) { return y - x < 1e-9; }),
               ts.end());
      out.push_back(a);
      double from = 0;
      for (std::size_t k = 0; k < ts.size(); ++k) {
        const double to = k + 1 < ts.size() ? ts[k + 1] : 1.0;
        const Vec2 split = a + d * ts[k];
        if (!same_tag(tag_at(a + d * from, split), tag_at(split, a + d * to))) {
          out.push_back(split);
          from = ts[k];
        }
      }
    }
    ring = std::move(out);
  };
  refine(polygon.outer);
  for (auto& hole : polygon.holes) refine(hole);
}

FaceTag cap_tag(const Prism& p, bool top) {
  for (std::size_t f = 0; f < p.mesh.face_count(); ++f) {
    const double ny = kernel::face_normal(p.mesh, f).y;
    if (top ? ny > 0.5 : ny < -0.5) return p.mesh.tag(f);
  }
  return {};
}

// Extrudes each result polygon over [y0, y1] (ref space) and adds it as a component.
OpResult add_prisms(ShapeTree& tree, ShapeId parent, const Scope& ref,
                    const std::vector<Polygon>& polygons, double y0, double y1,
                    std::span<const Prism* const> sources) {
  OpResult result;
  const kernel::Transform plane{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}, {0, y0, 0}};
  for (std::uint32_t i = 0; i < polygons.size(); ++i) {
    kernel::ExtrudeOptions options;
    options.bottom = cap_tag(*sources[0], false);
    options.top = cap_tag(*sources[0], true);
    Polygon section = polygons[i];
    keep_face_ids(section, (y0 + y1) / 2, sources);
    kernel::ExtrudeResult prism = kernel::extrude_planar(section, plane, y1 - y0, options);
    if (!prism.ok())
      return OpResult::failure(std::string(kernel::extrude_status_message(prism.status)));
    Mesh& m = prism.mesh;
    for (std::size_t f = 0; f < m.face_count(); ++f) {
      const Vec3 n = kernel::face_normal(m, f);
      if (std::fabs(n.y) > 1e-7) continue;
      Vec3 c;
      for (std::uint32_t v : m.face(f)) c += m.position(v);
      c = c / static_cast<double>(m.face(f).size());
      m.tag(f) = carried_tag(sources, c, n, m.tag(f));
    }
    Refit fit = refit(ref, m, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    auto mesh = std::make_shared<Mesh>(std::move(fit.mesh));
    const ShapeId child = parent == kNoShape ? tree.add_root(fit.scope, mesh)
                                             : tree.add_child(parent, fit.scope, mesh);
    result.add(child, i);
  }
  return result;
}

// --- general solids (CGAL)

OpResult general_boolean(ShapeTree& tree, std::span<const ShapeId> ids, Op op) {
  const Scope ref = tree[ids[0]].scope;
  const auto world = [&](ShapeId id) { return mesh_to_world(*tree[id].mesh, tree[id].scope); };
  Mesh acc = world(ids[0]);
  const auto kop = op == Op::kUnion          ? kernel::BooleanOp::kUnion
                   : op == Op::kIntersection ? kernel::BooleanOp::kIntersection
                                             : kernel::BooleanOp::kDifference;
  for (std::size_t i = 1; i < ids.size(); ++i) {
    if (!tree[ids[i]].mesh || tree[ids[i]].is_flat()) {
      return OpResult::failure("component " + std::to_string(ids[i]) + " is not a solid");
    }
    kernel::Boolean3dResult r = kernel::boolean3d(acc, world(ids[i]), kop);
    if (r.status != kernel::Boolean3dStatus::kOk) return OpResult::failure(r.message);
    acc = std::move(r.mesh);
  }
  OpResult result;
  if (acc.empty()) {
    result.warning = "the result is empty";
    return result;
  }
  Scope scope = fit_scope(acc, ref.x, ref.y, ref.z);
  auto mesh = std::make_shared<Mesh>(mesh_to_local(acc, scope));
  const ShapeId parent = op == Op::kDifference ? ids[0] : kNoShape;
  result.add(parent == kNoShape ? tree.add_root(scope, mesh) : tree.add_child(parent, scope, mesh),
             0);
  return result;
}

bool ranges_overlap(const Prism& a, const Prism& b) {
  return b.y1 > a.y0 + kPlanar && b.y0 < a.y1 - kPlanar;
}

bool sections_overlap(const Prism& a, const Prism& b) {
  kernel::Bounds2 ba;
  kernel::Bounds2 bb;
  for (const Polygon& p : a.section) {
    for (Vec2 q : p.outer) ba.add(q);
  }
  for (const Polygon& p : b.section) {
    for (Vec2 q : p.outer) bb.add(q);
  }
  return !ba.empty() && !bb.empty() && ba.min.x < bb.max.x && bb.min.x < ba.max.x &&
         ba.min.y < bb.max.y && bb.min.y < ba.max.y;
}

OpResult solid_boolean(ShapeTree& tree, std::span<const ShapeId> ids, Op op) {
  const Scope ref = tree[ids[0]].scope;
  std::vector<Prism> prisms;
  for (ShapeId id : ids) {
    auto p = as_prism(tree, id, ref);
    if (!p) return general_boolean(tree, ids, op);
    prisms.push_back(std::move(*p));
  }
  std::vector<const Prism*> sources;
  for (const Prism& p : prisms) sources.push_back(&p);
  const Prism& a = prisms[0];
  std::vector<Polygon> acc = a.section;
  double y0 = a.y0;
  double y1 = a.y1;
  for (std::size_t i = 1; i < prisms.size(); ++i) {
    const Prism& b = prisms[i];
    kernel::BooleanResult r;
    if (op == Op::kDifference) {
      if (!ranges_overlap(a, b) || !sections_overlap(a, b)) continue;
      if (b.y0 > a.y0 + kPlanar || b.y1 < a.y1 - kPlanar) return general_boolean(tree, ids, op);
      r = kernel::subtract(acc, b.section);
    } else if (op == Op::kIntersection) {
      y0 = std::max(y0, b.y0);
      y1 = std::min(y1, b.y1);
      r = kernel::intersect(acc, b.section);
    } else {
      if (std::fabs(b.y0 - y0) > kPlanar || std::fabs(b.y1 - y1) > kPlanar) {
        return general_boolean(tree, ids, op);
      }
      r = kernel::unite(acc, b.section);
    }
    if (!r.ok()) return OpResult::failure(std::string(kernel::to_string(r.status)));
    acc = std::move(r.polygons);
  }
  OpResult result;
  if (y1 - y0 <= kPlanar) acc.clear();
  if (!acc.empty()) {
    const ShapeId parent = op == Op::kDifference ? ids[0] : kNoShape;
    result = add_prisms(tree, parent, ref, acc, y0, y1, sources);
  }
  if (result.ok() && result.children.empty()) result.warning = "the result is empty";
  return result;
}

OpResult run(ShapeTree& tree, std::span<const ShapeId> ids, Op op) {
  if (ids.empty()) return OpResult::failure("no components");
  for (ShapeId id : ids) {
    if (!tree.contains(id)) return OpResult::failure("no component " + std::to_string(id));
    if (!tree[id].mesh)
      return OpResult::failure("component " + std::to_string(id) + " has no boundary");
  }
  return tree[ids[0]].is_flat() ? flat_boolean(tree, ids, op) : solid_boolean(tree, ids, op);
}

}  // namespace

OpResult unite_components(ShapeTree& tree, std::span<const ShapeId> ids) {
  return run(tree, ids, Op::kUnion);
}

OpResult intersect_components(ShapeTree& tree, std::span<const ShapeId> ids) {
  return run(tree, ids, Op::kIntersection);
}

OpResult subtract_components(ShapeTree& tree, ShapeId id, std::span<const ShapeId> cutters) {
  std::vector<ShapeId> ids{id};
  for (ShapeId c : cutters) {
    if (c != id) ids.push_back(c);
  }
  return finish(tree, id, run(tree, ids, Op::kDifference));
}

}  // namespace insula::shape
