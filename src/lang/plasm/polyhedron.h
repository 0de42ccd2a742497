// PLaSM's hierarchical polyhedral complexes (seed 002, §2; docs/plasm-language.md, "Geometry").
// A polyhedron is a tree: a node holds convex cells of its own (each the convex hull of some of
// its points) and placed children (another polyhedron under an affine map). Transformations and
// STRUCT only add nodes, so a part used a hundred times is stored once; operations that look at
// cells (JOIN, products, MAP, booleans, export) work on the flattened complex. Points have `dim`
// coordinates (any number, double precision); a child of lower dimension is embedded by zero
// coordinates.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "kernel/mesh.h"

namespace insula::lang::plasm {

// The vertices of a convex cell, as indices into its node's points. The order is kept: a
// simplex that MAP makes lists its vertices positively oriented in the domain, which gives a
// mapped surface its side.
using Cell = std::vector<std::uint32_t>;

// Coordinates a point may have, and levels of STRUCT a polyhedron may nest (both bound the work
// of a single builtin: a CUBOID has 2^d corners and 3^d faces, flattening walks the levels
// recursively).
inline constexpr int kMaxDimension = 7;
// Points one convex hull may have in 5 and more dimensions, where the number of facets grows like
// n^(d/2): twice a d-cube's corners, so boxes, their products and offsets always fit.
inline constexpr std::size_t kMaxHighHullPoints = std::size_t{2} << kMaxDimension;
inline constexpr int kMaxPolyhedronDepth = 2000;

// An affine map of R^n, as an (n+1) x (n+1) homogeneous matrix acting on columns (row-major).
struct Affine {
  int n = 0;
  std::vector<double> m;

  static Affine identity(int n);
  static Affine translation(int n, const std::vector<int>& axes, const std::vector<double>& by);
  static Affine scaling(int n, const std::vector<int>& axes, const std::vector<double>& by);
  // The rotation by `angle` in the plane of axes i and j (0-based), from i towards j.
  static Affine rotation(int n, int i, int j, double angle);

  double at(int row, int col) const { return m[static_cast<std::size_t>(row * (n + 1) + col)]; }
  // The same map in R^k (k >= n), acting as the identity on the extra coordinates.
  Affine widened(int k) const;
  // `after` applied after this map (dimensions are widened to the larger one).
  Affine then(const Affine& after) const;
  // Maps a point of `in_dim` coordinates (missing ones zero) to max(n, in_dim) coordinates in
  // `out`; coordinates past n pass unchanged (T:1:2 moves a 3D point along x only).
  void apply(const double* in, int in_dim, double* out) const;
  // The sign of the determinant of the linear part (-1, 0 or 1): negative for mirrors.
  int orientation() const;
  bool reverses_orientation() const { return orientation() < 0; }
};

struct Polyhedron;
using PolyPtr = std::shared_ptr<const Polyhedron>;

struct Polyhedron {
  struct Child {
    Affine transform;  // n == 0 and empty m: the identity
    PolyPtr part;
  };

  int dim = 0;                 // coordinates per point
  std::vector<double> points;  // dim numbers per point
  std::vector<Cell> cells;
  // A boolean's result (boolean.cc): a closed, outward 2-manifold bounding a region of R^3 that
  // need not be convex, kept as a mesh rather than split into convex cells (dim is 3).
  std::shared_ptr<const kernel::Mesh> solid;
  std::vector<Child> children;
  // The DEF or WHERE local whose value this is (empty when none); `part` marks top-level DEFs,
  // whose innermost one names the exported part (docs/plasm-language.md, "Output").
  std::string label;
  bool part = false;
  // Kept by the make_ functions: cells of every instance below, and the levels of nodes below
  // (the evaluator bounds it, so walking and destroying a tree never recurse without limit).
  std::uint64_t total_cells = 0;
  int depth = 0;

  std::size_t point_count() const { return dim == 0 ? 0 : points.size() / dim; }
};

// A labelled instance met while flattening: every cell belongs to the innermost one above it.
struct CellGroup {
  std::string part;  // the innermost top-level DEF name, or empty
  std::string path;  // all labels from the root down, joined by '/'
};

// A complex with its hierarchy resolved: every cell's points transformed into one frame.
struct FlatComplex {
  int dim = 0;
  std::vector<double> points;
  std::vector<Cell> cells;
  std::vector<std::uint32_t> group;  // per cell, an index into groups
  std::vector<CellGroup> groups;
  // flatten() only: per cell, which stored cell it is an instance of (numbered over the distinct
  // nodes, in the order first met), with kMirrored set when its placement reverses orientation,
  // or kNoOrigin under a singular placement. An invertible affine placement keeps a convex cell's
  // faces, so the export hulls each stored cell once.
  static constexpr std::uint32_t kMirrored = 0x80000000U;
  static constexpr std::uint32_t kNoOrigin = 0xFFFFFFFFU;
  std::vector<std::uint32_t> origin;
  std::uint32_t origins = 0;  // distinct stored cells
  // Boolean results, placed (outward still when the placement mirrors), and their groups.
  std::vector<kernel::Mesh> solids;
  std::vector<std::uint32_t> solid_group;

  std::size_t point_count() const { return dim == 0 ? 0 : points.size() / dim; }
  const double* point(std::uint32_t i) const { return points.data() + std::size_t(i) * dim; }
};

FlatComplex flatten(const Polyhedron& polyhedron);
// Flattened cells and their points only (no groups), for operations that make a new leaf.
FlatComplex flatten_cells(const Polyhedron& polyhedron);

// How many cells the flattened complex has, counting every instance (without flattening).
inline std::uint64_t cell_count(const Polyhedron& polyhedron) {
  return polyhedron.total_cells;
}

// A leaf node over `flat`'s points and cells (labels dropped).
PolyPtr make_leaf(int dim, std::vector<double> points, std::vector<Cell> cells);
// A leaf holding a closed 3D mesh (a boolean's result).
PolyPtr make_solid(kernel::Mesh mesh);
// A node placing `part` under `transform`.
PolyPtr make_placed(const PolyPtr& part, Affine transform);
// A node holding the parts side by side (STRUCT), in the largest of their dimensions.
PolyPtr make_group(std::vector<Polyhedron::Child> children);
// `polyhedron` carrying a label (a new node over it; the polyhedron itself is shared).
PolyPtr make_labelled(const PolyPtr& polyhedron, std::string label, bool part);

// The points of the cells and solids of a flattened complex, each once, for measures and hulls.
std::vector<double> used_points(const FlatComplex& flat);

}  // namespace insula::lang::plasm
