// A shape (a CGA shape, seed 004; a component, seed 001 §3.1): labels, inherited attributes, a
// scope, geometry in scope space, children, regions and a random seed. Shapes live in a ShapeTree
// arena and refer to each other by ShapeId; strings (labels, attribute names) are interned in the
// tree so a shape stays small (docs/shape-model.md, "Memory per shape").
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "shape/rng.h"
#include "shape/scope.h"
#include "shape/value.h"

namespace insula::shape {

using ShapeId = std::uint32_t;
inline constexpr ShapeId kNoShape = 0xffffffffU;
// Index of an interned string in the tree's symbol table.
using SymbolId = std::uint32_t;

// A named sub-area of a shape where other components may be connected (seed 001 §3.1.2): a range of
// valid connector positions (an axis-aligned box in the shape's scope space; flat when the region
// lies on a face) and a range of valid orientations (degrees about the scope's x, y and z axes).
struct Region {
  std::string name;
  std::uint32_t face_id = 0;  // the face the region lies on; 0 = not tied to a face
  kernel::Vec3 min;           // scope space, meters
  kernel::Vec3 max;
  kernel::Vec3 min_degrees;  // orientation range about scope x, y, z
  kernel::Vec3 max_degrees;

  // True when the scope-space point lies in the position range (within `tolerance` meters).
  bool contains(kernel::Vec3 local, double tolerance = 1e-9) const;
};

// A connector placement drawn from a region: a position (scope space) and angles (degrees).
struct RegionPlacement {
  kernel::Vec3 position;
  kernel::Vec3 degrees;
};
// Uniform position and orientation inside the region's ranges (seed 001 §3.4.2: "a random one is
// generated within the range specified by the region").
RegionPlacement sample(const Region& region, Rng& rng);

struct Shape {
  ShapeId id = kNoShape;
  ShapeId parent = kNoShape;
  std::uint32_t child_index = 0;  // position among the parent's children (seeds the rng)
  // False once an operation has replaced the shape by its children (CGA: no longer in the active
  // configuration); the shape itself stays in the tree and queryable (seed 001 §3).
  bool active = true;
  std::uint64_t seed = 0;
  std::vector<SymbolId> labels;  // not inherited (seed 001 §3.1)
  // Values set on this shape; children see them unless they set their own (seed 001 §3.1).
  std::vector<std::pair<SymbolId, Value>> attributes;
  std::vector<ShapeId> children;
  Scope scope;
  // Geometry in scope space, shared between shapes until an operation changes it. Null for
  // degenerate shapes (edges and vertices from comp) and for pure scopes.
  std::shared_ptr<const kernel::Mesh> mesh;
  // For flat shapes (scope size z == 0): the outline (with holes) in the scope's xy plane. The mesh
  // holds the same region as faces; the outline keeps the holes for 2D operations.
  std::shared_ptr<const kernel::Polygon> outline;
  std::vector<Region> regions;

  bool is_flat() const { return outline != nullptr; }
};

}  // namespace insula::shape
