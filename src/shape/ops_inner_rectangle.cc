// CityEngine's innerRectangle: the largest rectangle inside a flat shape, and the rest.
#include <cmath>

#include "kernel/boolean2d.h"
#include "kernel/inner_rectangle.h"
#include "shape/ops.h"

namespace insula::shape {

using kernel::Polygon;
using kernel::Vec2;

namespace {

// `p` turned by the angle whose cosine and sine are c and s.
Vec2 turn(Vec2 p, double c, double s) {
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

Polygon turned(const Polygon& polygon, double c, double s) {
  Polygon out = polygon;
  for (Vec2& p : out.outer) p = turn(p, c, s);
  for (auto& hole : out.holes) {
    for (Vec2& p : hole) p = turn(p, c, s);
  }
  return out;
}

// Unit direction of the outline's longest outer edge ((1, 0) for none).
Vec2 longest_edge(const Polygon& outline) {
  Vec2 best{1, 0};
  double best_length = 0;
  const kernel::Ring& ring = outline.outer;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 d = ring[(i + 1) % ring.size()] - ring[i];
    if (kernel::length(d) > best_length + 1e-9) {
      best_length = kernel::length(d);
      best = kernel::normalized(d);
    }
  }
  return best;
}

}  // namespace

OpResult inner_rectangle(ShapeTree& tree, ShapeId id, bool along_edge, SetbackPart part) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  // Work in a frame whose x runs along the chosen direction (the scope's x, or the edge).
  const Vec2 dir = along_edge ? longest_edge(*s.outline) : Vec2{1, 0};
  const Polygon local = turned(*s.outline, dir.x, -dir.y);
  const std::optional<kernel::Rect2> rect = kernel::largest_inner_rectangle(local);
  if (!rect) return OpResult::failure("the shape has no area");
  const double w = rect->max.x - rect->min.x;
  const double h = rect->max.y - rect->min.y;
  Polygon in_scope;  // the rectangle in the shape's scope xy
  for (Vec2 p :
       {rect->min, Vec2{rect->max.x, rect->min.y}, rect->max, Vec2{rect->min.x, rect->max.y}}) {
    in_scope.outer.push_back(turn(p, dir.x, dir.y));
  }
  OpResult result;
  if (part != SetbackPart::kRemainder) {
    Scope scope = s.scope;
    scope.origin = s.scope.to_world(kernel::lift(in_scope.outer[0], 0));
    scope.x = s.scope.direction_to_world({dir.x, dir.y, 0});
    scope.y = s.scope.direction_to_world({-dir.y, dir.x, 0});
    scope.size = {w, h, 0};
    auto outline = std::make_shared<Polygon>();
    outline->outer = {{0, 0}, {w, 0}, {w, h}, {0, h}};
    const kernel::FaceTag tag = s.mesh && !s.mesh->empty() ? s.mesh->tag(0) : kernel::FaceTag{};
    auto mesh = flat_mesh(*outline, tag);
    result.add(tree.add_child(id, scope, std::move(mesh), std::move(outline)), 0);
  }
  if (part != SetbackPart::kShape) {
    const kernel::BooleanResult rest = kernel::subtract({*s.outline}, {in_scope});
    if (!rest.ok()) {
      return OpResult::failure("2D boolean failed: " + std::string(kernel::to_string(rest.status)));
    }
    for (const Polygon& p : rest.polygons) {
      if (kernel::area(p) > 1e-9 * (w * h + 1)) add_flat_region(tree, id, p, 1, result);
    }
  }
  return finish(tree, id, std::move(result));
}

std::vector<Operation> inner_rectangle_operations() {
  std::vector<Operation> ops;
  ops.push_back({"innerRectangle",
                 "The largest rectangle inside a flat shape, its sides parallel to the scope's x "
                 "and y or to the outline's longest edge (CGA innerRectangle); children the "
                 "rectangle (piece 0, scope x along its side) and the rest (piece 1).",
                 {{"align",
                   ParamType::kEnum,
                   "scope: sides parallel to scope x and y; edge: to the longest outer edge",
                   ArgValue{std::string("scope")},
                   {"scope", "edge"},
                   {},
                   {}},
                  part_param()},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return inner_rectangle(t, id, a.string("align") == "edge",
                                          part_from(a.string("part")));
                 }});
  return ops;
}

}  // namespace insula::shape
