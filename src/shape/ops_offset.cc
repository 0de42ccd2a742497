// Offset and setback of flat shapes (CGA offset and setback), in the shape's plane with the
// kernel's Clipper-backed 2D booleans (boolean2d.h). Every resulting region becomes one flat child
// in the parent's frame, its scope fitted to the region.
#include <algorithm>
#include <cmath>
#include <optional>

#include "kernel/boolean2d.h"
#include "shape/ops.h"
#include "shape/ops_fast.h"

namespace insula::shape {

using kernel::Polygon;
using kernel::Vec2;

void add_flat_region(ShapeTree& tree, ShapeId id, const Polygon& region, std::uint32_t piece,
                     OpResult& result) {
  const Shape& s = tree[id];
  FlatRegion fitted = flat_region(region);
  auto outline = std::make_shared<Polygon>(std::move(fitted.outline));
  const Scope scope = s.scope.sub(fitted.offset, fitted.size);
  const kernel::FaceTag tag = s.mesh && !s.mesh->empty() ? s.mesh->tag(0) : kernel::FaceTag{};
  auto mesh = flat_mesh(*outline, tag);
  result.add(tree.add_child(id, scope, std::move(mesh), std::move(outline)), piece);
}

namespace {

std::string boolean_error(kernel::BooleanStatus status) {
  return "2D boolean failed: " + std::string(kernel::to_string(status));
}

double depth_of(const EdgeDepths& depths, Vec2 outward) {
  switch (edge_side(outward)) {
    case EdgeSelector::kFront:
      return depths.front;
    case EdgeSelector::kBack:
      return depths.back;
    case EdgeSelector::kLeft:
      return depths.left;
    default:
      return depths.right;
  }
}

// Calls visit(a, b, inward unit normal, edge index) for every edge of the outline, outer ring
// first. The region lies left of every edge (outer ring counter-clockwise, holes clockwise), so
// inward is the left normal. Degenerate edges keep their index but are not visited.
template <typename Visit>
void for_each_edge(const Polygon& outline, Visit&& visit) {
  std::size_t index = 0;
  const auto ring_edges = [&](const kernel::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i, ++index) {
      const Vec2 a = ring[i];
      const Vec2 b = ring[(i + 1) % ring.size()];
      const Vec2 d = kernel::normalized(b - a);
      if (kernel::length(d) == 0) continue;
      visit(a, b, kernel::perp(d), index);
    }
  };
  ring_edges(outline.outer);
  for (const auto& hole : outline.holes) ring_edges(hole);
}

// Quads reaching inward from every edge by its depth (none where it is 0).
template <typename DepthOf>
std::vector<Polygon> edge_strips(const Polygon& outline, DepthOf&& depth_of_edge) {
  std::vector<Polygon> strips;
  for_each_edge(outline, [&](Vec2 a, Vec2 b, Vec2 inward, std::size_t index) {
    const double depth = depth_of_edge(-inward, index);
    if (depth > 0) strips.push_back({{a, b, b + inward * depth, a + inward * depth}, {}});
  });
  return strips;
}

OpResult cut_strips(ShapeTree& tree, ShapeId id, const std::vector<Polygon>& strips,
                    SetbackPart part) {
  const std::vector<Polygon> original{*tree[id].outline};
  const kernel::BooleanResult band = kernel::intersect(original, strips);
  const kernel::BooleanResult rest = kernel::subtract(original, strips);
  if (!band.ok()) return OpResult::failure(boolean_error(band.status));
  if (!rest.ok()) return OpResult::failure(boolean_error(rest.status));
  OpResult result;
  if (part != SetbackPart::kRemainder) {
    for (const Polygon& p : band.polygons) add_flat_region(tree, id, p, 0, result);
  }
  if (part != SetbackPart::kShape) {
    for (const Polygon& p : rest.polygons) add_flat_region(tree, id, p, 1, result);
  }
  return finish(tree, id, std::move(result));
}

// A rectangle inset by `depth` (> 0, less than half its shorter side): the smaller rectangle and
// the frame around it (ops_fast.h), as the Clipper offset and subtraction would give them, without
// either: windows and façade tiles are most of a district's offsets (issue 17, CGA to 3D Tiles).
void inset_rectangle(ShapeTree& tree, ShapeId id, const kernel::Bounds2& box, double depth,
                     OffsetPart part, OpResult& result) {
  if (part != OffsetPart::kBorder) {
    add_flat_region(tree, id, rectangle_inset_piece(box, depth, 0), 0, result);
  }
  if (part != OffsetPart::kInside) {
    add_flat_region(tree, id, rectangle_inset_piece(box, depth, 1), 1, result);
  }
}

}  // namespace

EdgeSelector edge_side(Vec2 outward) {
  if (std::fabs(outward.y) >= std::fabs(outward.x)) {
    return outward.y < 0 ? EdgeSelector::kFront : EdgeSelector::kBack;
  }
  return outward.x < 0 ? EdgeSelector::kLeft : EdgeSelector::kRight;
}

OpResult offset(ShapeTree& tree, ShapeId id, double distance, OffsetPart part) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (!std::isfinite(distance)) return OpResult::failure("distance must be finite");
  if (const std::optional<kernel::Bounds2> box = as_rectangle(*s.outline);
      box && is_rectangle_inset(*box, distance)) {
    OpResult result;
    inset_rectangle(tree, id, *box, -distance, part, result);
    return finish(tree, id, std::move(result));
  }
  const std::vector<Polygon> original{*s.outline};
  const kernel::BooleanResult inside = kernel::offset(original, distance);
  if (!inside.ok()) return OpResult::failure(boolean_error(inside.status));
  // The border lies between the outline and its offset, whichever way the offset went.
  const kernel::BooleanResult border = distance < 0 ? kernel::subtract(original, inside.polygons)
                                                    : kernel::subtract(inside.polygons, original);
  if (!border.ok()) return OpResult::failure(boolean_error(border.status));
  OpResult result;
  if (part != OffsetPart::kBorder) {
    for (const Polygon& p : inside.polygons) add_flat_region(tree, id, p, 0, result);
  }
  if (part != OffsetPart::kInside) {
    for (const Polygon& p : border.polygons) add_flat_region(tree, id, p, 1, result);
  }
  return finish(tree, id, std::move(result));
}

OpResult setback(ShapeTree& tree, ShapeId id, double distance, EdgeSelector edges) {
  if (!tree[id].is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (!(distance > 0) || !std::isfinite(distance)) {
    return OpResult::failure("distance must be > 0");
  }
  const bool all = edges == EdgeSelector::kAll;
  const bool side = all || edges == EdgeSelector::kSide;
  EdgeDepths depths;
  depths.front = all || edges == EdgeSelector::kFront ? distance : 0;
  depths.back = all || edges == EdgeSelector::kBack ? distance : 0;
  depths.left = side || edges == EdgeSelector::kLeft ? distance : 0;
  depths.right = side || edges == EdgeSelector::kRight ? distance : 0;
  return setback(tree, id, depths, SetbackPart::kAll);
}

OpResult setback(ShapeTree& tree, ShapeId id, const EdgeDepths& depths, SetbackPart part) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  for (double d : {depths.front, depths.back, depths.left, depths.right}) {
    if (!(d >= 0) || !std::isfinite(d)) return OpResult::failure("depths must be finite and >= 0");
  }
  const std::vector<Polygon> strips =
      edge_strips(*s.outline, [&](Vec2 outward, std::size_t) { return depth_of(depths, outward); });
  return cut_strips(tree, id, strips, part);
}

OpResult setback(ShapeTree& tree, ShapeId id, std::span<const double> edge_depths,
                 SetbackPart part) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  for (double d : edge_depths) {
    if (!(d >= 0) || !std::isfinite(d)) return OpResult::failure("depths must be finite and >= 0");
  }
  const std::vector<Polygon> strips = edge_strips(*s.outline, [&](Vec2, std::size_t index) {
    return index < edge_depths.size() ? edge_depths[index] : 0.0;
  });
  return cut_strips(tree, id, strips, part);
}

OffsetPart offset_part(std::string_view name) {
  if (name == "inside") return OffsetPart::kInside;
  if (name == "border") return OffsetPart::kBorder;
  return OffsetPart::kAll;
}

std::optional<OffsetRequest> offset_request(const std::vector<ArgInput>& args) {
  std::optional<double> distance;
  OffsetPart part = OffsetPart::kAll;
  for (const ArgInput& a : args) {
    const double* number = std::get_if<double>(&a.value);
    const std::string* name = std::get_if<std::string>(&a.value);
    if (a.name == "distance" && number != nullptr) {
      distance = *number;
    } else if (a.name == "part" && name != nullptr &&
               (*name == "inside" || *name == "border" || *name == "all")) {
      part = offset_part(*name);
    } else {
      return std::nullopt;
    }
  }
  if (!distance) return std::nullopt;
  return OffsetRequest{*distance, part};
}

ParamDecl part_param() {
  return {"part",
          ParamType::kEnum,
          "which parts to keep",
          ArgValue{std::string("all")},
          {"shape", "remainder", "all"},
          {},
          {}};
}

SetbackPart part_from(std::string_view name) {
  if (name == "shape") return SetbackPart::kShape;
  if (name == "remainder") return SetbackPart::kRemainder;
  return SetbackPart::kAll;
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
         return offset(t, id, a.number("distance"), offset_part(a.string("part")));
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
  ops.push_back(
      {"setbackEdges",
       "Cuts a strip along each edge of a flat shape as deep as that edge's entry of the depths "
       "(outer ring from its first vertex, then the holes; CGA setback(float[])); children the "
       "strips' union (piece 0) and the remainder (piece 1), as `part` keeps.",
       {{"depths",
         ParamType::kSizeList,
         "strip depth per edge (meters, 0: none; missing entries: none)",
         std::nullopt,
         {},
         0.0,
         {}},
        part_param()},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         std::vector<double> depths;
         for (const SizeSpec& d : a.sizes("depths")) {
           if (d.mode != SizeMode::kAbsolute) {
             return OpResult::failure("depths must be meters, not relative or floating sizes");
           }
           depths.push_back(d.value);
         }
         return setback(t, id, depths, part_from(a.string("part")));
       }});
  // CityEngine's L, U and O shapes: setbacks of the front and the named sides, in its order.
  struct Band {
    const char* name;
    const char* doc;
    std::vector<std::string> sides;
  };
  const Band bands[] = {
      {"shapeL",
       "An L along the front and left edges of a flat shape (CGA shapeL)",
       {"front", "left"}},
      {"shapeU",
       "A U along the front, right and left edges of a flat shape (CGA shapeU)",
       {"front", "right", "left"}},
      {"shapeO",
       "An O along every edge of a flat shape, front, right, back, left (CGA shapeO)",
       {"front", "right", "back", "left"}}};
  for (const Band& band : bands) {
    Operation op{band.name,
                 std::string(band.doc) +
                     ": strips as deep as given along the edges facing each side (as setback "
                     "classifies them), clipped to the shape; children the band (piece 0) and "
                     "the remainder (piece 1).",
                 {},
                 {}};
    for (const std::string& side : band.sides) {
      op.params.push_back({side + "Width",
                           ParamType::kNumber,
                           "strip depth along the " + side + " edges (meters, 0: none)",
                           std::nullopt,
                           {},
                           0.0,
                           {}});
    }
    op.params.push_back(part_param());
    op.execute = [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
      const auto width = [&](const char* name) { return a.has(name) ? a.number(name) : 0.0; };
      EdgeDepths depths{width("frontWidth"), width("backWidth"), width("leftWidth"),
                        width("rightWidth")};
      return setback(t, id, depths, part_from(a.string("part")));
    };
    ops.push_back(std::move(op));
  }
  return ops;
}

}  // namespace insula::shape
