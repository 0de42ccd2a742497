// Floor and ceiling slabs (seed 000 §4.1 "Ground and ceilings are also placed in each room") over
// a flat shape, from kernel/solids.h as the .bldg builder lays its rooms' slabs.
#include <cmath>

#include "kernel/solids.h"
#include "shape/building_ops.h"
#include "shape/ops.h"

namespace insula::shape {

using kernel::FaceTag;
using kernel::SemanticClass;

OpResult slab(ShapeTree& tree, ShapeId id, SlabKind kind, double thickness) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (!(thickness > 0) || !std::isfinite(thickness)) {
    return OpResult::failure("thickness must be > 0");
  }
  const bool floor = kind == SlabKind::kFloor;
  const FaceTag closure{SemanticClass::kClosureSurface, 0, 0};
  const kernel::PrismTags tags{floor ? closure : FaceTag{SemanticClass::kCeilingSurface, 0, 3},
                               floor ? FaceTag{SemanticClass::kFloorSurface, 0, 1} : closure,
                               {SemanticClass::kInteriorWallSurface, 0, 2}};
  kernel::Mesh mesh;
  const double z0 = floor ? 0 : -thickness;
  if (!kernel::add_prism(mesh, *s.outline, z0, z0 + thickness, tags)) {
    return OpResult::failure("the outline is degenerate");
  }
  return replace_with(tree, id, mesh, {1, 0, 0}, {0, 0, 1}, {0, -1, 0});
}

std::vector<Operation> slab_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"slab",
       "Lays a floor slab on a flat shape (FloorSurface on top) or hangs a ceiling slab under it "
       "(CeilingSurface below), `thickness` thick (the .bldg builder's room slabs).",
       {{"kind",
         ParamType::kEnum,
         "floor (above the shape) or ceiling (below it)",
         ArgValue{std::string("floor")},
         {"floor", "ceiling"},
         {},
         {}},
        {"thickness", ParamType::kNumber, "slab thickness (meters)", ArgValue{0.1}, {}, 0.001, {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return slab(t, id, a.string("kind") == "ceiling" ? SlabKind::kCeiling : SlabKind::kFloor,
                     a.number("thickness"));
       }});
  return ops;
}

}  // namespace insula::shape
