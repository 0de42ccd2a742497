// Convex polytopes in any dimension, given by points (V-representation): their affine hull, their
// faces of every dimension and a simplicial decomposition. PLaSM's cells (seed 002) are convex
// hulls of points in R^n with n up to 6 and more; JOIN, SKELETON, MAP and every export need these.
// Full-dimensional hulls come from Qhull (Barber, Dobkin, Huhdanpaa, "The Quickhull algorithm for
// convex hulls", ACM TOMS 22, 1996; the reentrant libqhull_r); a polytope of lower dimension than
// its space is first expressed in an orthonormal frame of its affine hull.
//
// Points are flat arrays of doubles, `n` per point; every result names points by their index in
// the input. Degenerate input (no points, non-finite coordinates) gives an empty result with a
// status, never a crash or an exception.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace insula::kernel {

using PointIndex = std::uint32_t;
using IndexSet = std::vector<PointIndex>;  // sorted ascending, no repeats

enum class HullNdStatus { kOk, kEmpty, kNonFinite, kFailed };

std::string_view hull_nd_status_message(HullNdStatus status);

// The smallest affine subspace holding the points: origin + span of `basis` (dim orthonormal
// vectors of n coordinates each, flattened). Points farther than `tolerance` from the subspace
// spanned so far raise its dimension; 0 picks 1e-9 times the points' extent.
struct AffineFrame {
  int space_dim = 0;           // n
  int dim = -1;                // -1 for no points, 0 for one point, ...
  std::vector<double> origin;  // n coordinates
  std::vector<double> basis;   // dim * n coordinates
  // The coordinates of a point of R^n in this frame (dim numbers).
  std::vector<double> local(std::span<const double> point) const;
};
AffineFrame affine_frame(std::span<const double> points, int n, double tolerance = 0);

// The face lattice of the convex hull of the points, from vertices up to the polytope itself.
struct PolytopeNd {
  HullNdStatus status = HullNdStatus::kOk;
  int dim = -1;  // the dimension of the polytope (of its affine hull)
  // faces[k] holds the k-faces, each as the set of input points that are its vertices
  // (k = 0 ... dim; faces[dim] holds the polytope itself, faces[0] one set per vertex). A point
  // that is not a vertex (inside, or on a face but not at a corner) is in no set.
  std::vector<std::vector<IndexSet>> faces;
  bool ok() const { return status == HullNdStatus::kOk; }
  const IndexSet& vertices() const { return faces.back().front(); }  // all vertices
};
PolytopeNd polytope_nd(std::span<const double> points, int n, double tolerance = 0);

// A simplicial decomposition of the polytope: each simplex lists dim + 1 vertex indices. It is the
// pulling triangulation by `order`: the polytope's least vertex (by order[index], ties by index)
// is joined to a decomposition of every facet that does not contain it, recursively. Two
// polytopes that share a face and are decomposed with the same order decompose that face
// identically, so a complex of cells becomes a conforming simplicial complex. An empty `order`
// means the point index itself.
std::vector<IndexSet> simplices_nd(const PolytopeNd& polytope,
                                   std::span<const std::uint64_t> order = {});

}  // namespace insula::kernel
