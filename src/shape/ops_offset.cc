// Offset and setback of flat shapes (CGA offset and setback), in the shape's plane with the
// kernel's Clipper-backed 2D booleans (boolean2d.h). Every resulting region becomes one flat child
// in the parent's frame, its scope fitted to the region.
#include <cmath>

#include "kernel/boolean2d.h"
#include "shape/ops.h"

namespace insula::shape {

using kernel::Polygon;
using kernel::Vec2;

namespace {

void add_region(ShapeTree& tree, ShapeId id, const Polygon& region, std::uint32_t piece,
                OpResult& result) {
  const Shape& s = tree[id];
  const kernel::Bounds2 b = kernel::bounds(region);
  auto outline = std::make_shared<Polygon>(region);
  for (Vec2& p : outline->outer) p -= b.min;
  for (auto& hole : outline->holes) {
    for (Vec2& p : hole) p -= b.min;
  }
  const Scope scope = s.scope.sub({b.min.x, b.min.y, 0}, {b.max.x - b.min.x, b.max.y - b.min.y, 0});
  const kernel::FaceTag tag = s.mesh && !s.mesh->empty() ? s.mesh->tag(0) : kernel::FaceTag{};
  auto mesh = flat_mesh(*outline, tag);
  result.add(tree.add_child(id, scope, std::move(mesh), std::move(outline)), piece);
}

std::string boolean_error(kernel::BooleanStatus status) {
  return "2D boolean failed: " + std::string(kernel::to_string(status));
}

bool edge_selected(EdgeSelector selector, Vec2 outward) {
  if (selector == EdgeSelector::kAll) return true;
  const bool along_y = std::fabs(outward.y) >= std::fabs(outward.x);
  if (along_y) {
    return (selector == EdgeSelector::kFront && outward.y < 0) ||
           (selector == EdgeSelector::kBack && outward.y > 0);
  }
  return selector == EdgeSelector::kSide || (selector == EdgeSelector::kLeft && outward.x < 0) ||
         (selector == EdgeSelector::kRight && outward.x > 0);
}

// Quads reaching `distance` inward from every selected edge. The region lies left of every edge
// (outer ring counter-clockwise, holes clockwise), so inward is the left normal.
std::vector<Polygon> edge_strips(const Polygon& outline, double distance, EdgeSelector selector) {
  std::vector<Polygon> strips;
  const auto add_ring = [&](const kernel::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i];
      const Vec2 b = ring[(i + 1) % ring.size()];
      const Vec2 d = kernel::normalized(b - a);
      if (kernel::length(d) == 0) continue;
      const Vec2 inward = kernel::perp(d);
      if (!edge_selected(selector, -inward)) continue;
      strips.push_back({{a, b, b + inward * distance, a + inward * distance}, {}});
    }
  };
  add_ring(outline.outer);
  for (const auto& hole : outline.holes) add_ring(hole);
  return strips;
}

}  // namespace

OpResult offset(ShapeTree& tree, ShapeId id, double distance, OffsetPart part) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (!std::isfinite(distance)) return OpResult::failure("distance must be finite");
  const std::vector<Polygon> original{*s.outline};
  const kernel::BooleanResult inside = kernel::offset(original, distance);
  if (!inside.ok()) return OpResult::failure(boolean_error(inside.status));
  // The border lies between the outline and its offset, whichever way the offset went.
  const kernel::BooleanResult border = distance < 0 ? kernel::subtract(original, inside.polygons)
                                                    : kernel::subtract(inside.polygons, original);
  if (!border.ok()) return OpResult::failure(boolean_error(border.status));
  OpResult result;
  if (part != OffsetPart::kBorder) {
    for (const Polygon& p : inside.polygons) add_region(tree, id, p, 0, result);
  }
  if (part != OffsetPart::kInside) {
    for (const Polygon& p : border.polygons) add_region(tree, id, p, 1, result);
  }
  return finish(tree, id, std::move(result));
}

OpResult setback(ShapeTree& tree, ShapeId id, double distance, EdgeSelector edges) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (!(distance > 0) || !std::isfinite(distance)) {
    return OpResult::failure("distance must be > 0");
  }
  const std::vector<Polygon> original{*s.outline};
  const std::vector<Polygon> strips = edge_strips(*s.outline, distance, edges);
  const kernel::BooleanResult band = kernel::intersect(original, strips);
  const kernel::BooleanResult rest = kernel::subtract(original, strips);
  if (!band.ok()) return OpResult::failure(boolean_error(band.status));
  if (!rest.ok()) return OpResult::failure(boolean_error(rest.status));
  OpResult result;
  for (const Polygon& p : band.polygons) add_region(tree, id, p, 0, result);
  for (const Polygon& p : rest.polygons) add_region(tree, id, p, 1, result);
  return finish(tree, id, std::move(result));
}

std::vector<Operation> offset_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"offset",
       "Offsets a flat shape's outline (negative shrinks; CGA offset); children are the "
       "inside part (piece 0) and/or the border ring (piece 1).",
       {{"distance", ParamType::kNumber, "offset (meters; < 0 insets)", std::nullopt, {}, {}, {}},
        {"part",
         ParamType::kEnum,
         "which parts to keep",
         ArgValue{std::string("all")},
         {"inside", "border", "all"},
         {},
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         const std::string& p = a.string("part");
         const OffsetPart part = p == "inside"   ? OffsetPart::kInside
                                 : p == "border" ? OffsetPart::kBorder
                                                 : OffsetPart::kAll;
         return offset(t, id, a.number("distance"), part);
       }});
  ops.push_back(
      {"setback",
       "Cuts a strip of the given depth along the selected edges of a flat shape (CGA "
       "setback); children are the strip (piece 0) and the remainder (piece 1).",
       {{"distance", ParamType::kNumber, "strip depth (meters, > 0)", std::nullopt, {}, 0.0, {}},
        {"edges",
         ParamType::kEnum,
         "which edges (by outward direction in scope xy)",
         ArgValue{std::string("front")},
         {"front", "back", "left", "right", "side", "all"},
         {},
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         static constexpr std::array<std::pair<std::string_view, EdgeSelector>, 6> kEdges = {
             {{"front", EdgeSelector::kFront},
              {"back", EdgeSelector::kBack},
              {"left", EdgeSelector::kLeft},
              {"right", EdgeSelector::kRight},
              {"side", EdgeSelector::kSide},
              {"all", EdgeSelector::kAll}}};
         EdgeSelector edges = EdgeSelector::kAll;
         for (const auto& [name, value] : kEdges) {
           if (name == a.string("edges")) edges = value;
         }
         return setback(t, id, a.number("distance"), edges);
       }});
  return ops;
}

}  // namespace insula::shape
