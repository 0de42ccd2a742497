// The shape tree: an arena of shapes with stable ids (the component tree of seed 001 §3 and the
// derivation tree of a CGA grammar, seed 004). Shapes are never removed: an operation adds children
// and marks the parent inactive, so every earlier shape stays queryable. Several roots may coexist.
// Labels and attribute names are interned in one symbol table per tree. Not thread-safe for writes;
// per-shape seeds make results independent of evaluation order (docs/shape-model.md).
#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "shape/shape.h"

namespace insula::shape {

// How a footprint root's scope x axis is chosen.
enum class RootAlignment {
  kFirstEdge,    // x along the outer ring's first edge (after normalisation): CGA's convention
  kLongestEdge,  // x along the longest outer edge
};

struct RootResult {
  ShapeId id = kNoShape;
  std::string error;  // empty on success
  bool ok() const { return id != kNoShape; }
};

// Approximate memory held by the tree (docs/shape-model.md, "Memory per shape").
struct MemoryStats {
  std::size_t shapes = 0;
  std::size_t shape_bytes = 0;     // sizeof(Shape) * count
  std::size_t heap_bytes = 0;      // vectors owned by shapes (labels, attributes, children, ...)
  std::size_t geometry_bytes = 0;  // distinct meshes and outlines (shared ones counted once)
};

class ShapeTree {
 public:
  explicit ShapeTree(std::uint64_t seed = 0) : seed_(seed) {}

  // A flat root shape from a footprint in world XY (meters, z = `elevation`): geometry is the
  // polygon as an upward face, scope z = world +Z, x along the first or longest outer edge, y = z
  // cross x (into the footprint), origin at the minimum corner. The polygon is normalised first;
  // fails on fewer than 3 vertices, non-finite coordinates or zero area.
  RootResult create_root(const kernel::Polygon& footprint, double elevation = 0,
                         RootAlignment alignment = RootAlignment::kFirstEdge);
  // A root with a given scope and optional geometry (scope space).
  ShapeId add_root(const Scope& scope, std::shared_ptr<const kernel::Mesh> mesh = nullptr,
                   std::shared_ptr<const kernel::Polygon> outline = nullptr);
  // A child of `parent` (its seed follows from the parent's seed and the child index). Does not
  // change the parent's active flag: operations call deactivate() when they replace a shape.
  ShapeId add_child(ShapeId parent, const Scope& scope,
                    std::shared_ptr<const kernel::Mesh> mesh = nullptr,
                    std::shared_ptr<const kernel::Polygon> outline = nullptr);
  void deactivate(ShapeId id) { shapes_[id].active = false; }
  // Removes every shape with id >= `size` (and its entries in parents' child lists), undoing a
  // failed operation. Shapes below `size` keep their ids and state, except active flags.
  void truncate(std::size_t size);

  std::size_t size() const { return shapes_.size(); }
  bool contains(ShapeId id) const { return id < shapes_.size(); }
  // References stay valid while shapes are added (the arena is a deque).
  const Shape& operator[](ShapeId id) const { return shapes_[id]; }
  Shape& operator[](ShapeId id) { return shapes_[id]; }

  const std::vector<ShapeId>& roots() const { return roots_; }
  ShapeId parent(ShapeId id) const { return shapes_[id].parent; }
  const std::vector<ShapeId>& children(ShapeId id) const { return shapes_[id].children; }
  ShapeId root_of(ShapeId id) const;
  // `id` and all its descendants, depth first, children in order.
  std::vector<ShapeId> subtree(ShapeId id) const;
  // Shapes without children, in id order (optionally only under `under`).
  std::vector<ShapeId> leaves(ShapeId under = kNoShape) const;
  // Active shapes (the current configuration of a grammar), in id order.
  std::vector<ShapeId> active() const;
  std::vector<ShapeId> all() const;

  // Interned strings.
  SymbolId intern(std::string_view text);
  // The symbol of `text` if it was ever interned.
  std::optional<SymbolId> find_symbol(std::string_view text) const;
  std::string_view symbol(SymbolId id) const { return symbols_[id]; }

  // Labels (not inherited).
  void add_label(ShapeId id, std::string_view label);
  bool has_label(ShapeId id, std::string_view label) const;
  bool has_label(ShapeId id, SymbolId label) const;
  std::vector<std::string_view> labels(ShapeId id) const;
  // The first label, or "" (the grammar symbol when a front-end sets it first).
  std::string_view first_label(ShapeId id) const;

  // Attributes: set on one shape, seen by its descendants unless they override them.
  void set_attribute(ShapeId id, std::string_view name, Value value);
  // The value seen by `id` (its own, or the nearest ancestor's), or null when none sets it.
  const Value* attribute(ShapeId id, std::string_view name) const;
  // Every attribute visible from `id`, nearest definition winning.
  AttributeMap resolved_attributes(ShapeId id) const;

  // Face identifiers (seed 001 §3.1.1) are interned names; 0 means "no id".
  std::uint32_t face_id(std::string_view name) { return intern(name) + 1; }
  std::string_view face_name(std::uint32_t face_id) const;

  // A fresh generator for the shape (same stream every call).
  Rng rng(ShapeId id) const { return Rng(shapes_[id].seed); }
  std::uint64_t seed() const { return seed_; }

  MemoryStats memory_stats() const;

 private:
  ShapeId push(Shape shape);

  std::uint64_t seed_;
  std::deque<Shape> shapes_;
  std::vector<ShapeId> roots_;
  std::deque<std::string> symbols_;  // a deque: views into it stay valid
  std::unordered_map<std::string_view, SymbolId> symbol_index_;  // views into symbols_' strings
};

// The shared flat geometry for a polygon in a scope's xy plane: one upward face per hole-free piece
// (a polygon with holes is triangulated), tagged `tag`.
std::shared_ptr<const kernel::Mesh> flat_mesh(const kernel::Polygon& outline, kernel::FaceTag tag);

}  // namespace insula::shape
