// Operations on the cells of a complex (seed 002, §2): the Cartesian product `*`, JOIN (convex
// hull), SKELETON (k-faces), OFFSET (Minkowski sum with a box) and SPLITCELLS. Each flattens its
// operands and makes a new leaf; convex polytopes of any dimension come from kernel/hull_nd.
#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "kernel/hull_nd.h"
#include "lang/plasm/geometry.h"

namespace insula::lang::plasm {
namespace {

std::span<const double> cell_points(const FlatComplex& flat, const Cell& cell,
                                    std::vector<double>& buffer) {
  buffer.clear();
  for (std::uint32_t v : cell) buffer.insert(buffer.end(), flat.point(v), flat.point(v) + flat.dim);
  return buffer;
}

kernel::PolytopeNd cell_polytope(Context& c, const FlatComplex& flat, const Cell& cell,
                                 std::string_view who, Range at) {
  std::vector<double> buffer;
  return hull(c, cell_points(flat, cell, buffer), flat.dim, who, at);
}

// The polyhedra of a value: one, or a sequence of them.
std::vector<PolyPtr> polyhedra(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  if (v->is_polyhedron()) return {v->polyhedron()};
  std::vector<PolyPtr> out;
  for (const ValuePtr& e : c.seq(v, who, at)) out.push_back(polyhedron(c, e, who, at));
  if (out.empty()) c.fail("PSM407", text({"'", who, "' of an empty sequence"}), at);
  return out;
}

// JOIN: the convex hull of every point of the cells, one cell.
ValuePtr join_fn(Context& c, const Function&, Args a, Range at) {
  int dim = 0;
  std::vector<PolyPtr> parts = polyhedra(c, a[0], "JOIN", at);
  for (const PolyPtr& p : parts) dim = std::max(dim, p->dim);
  std::vector<double> points;
  for (const PolyPtr& p : parts) {
    const FlatComplex flat = flatten_cells(*p);
    const std::vector<double> own = used_points(flat);
    for (std::size_t i = 0; i < own.size(); i += static_cast<std::size_t>(flat.dim)) {
      points.insert(points.end(), own.begin() + std::ptrdiff_t(i),
                    own.begin() + std::ptrdiff_t(i) + flat.dim);
      points.insert(points.end(), static_cast<std::size_t>(dim - flat.dim), 0.0);
    }
  }
  if (points.empty()) return polyhedron_value(c, make_leaf(dim, {}, {}), at);
  c.charge(static_cast<double>(points.size()) / 4, at);
  const kernel::PolytopeNd joined = hull(c, points, dim, "JOIN", at);
  std::vector<double> kept;
  Cell cell;
  for (kernel::PointIndex v : joined.vertices()) {
    kept.insert(kept.end(), points.begin() + std::ptrdiff_t(v) * dim,
                points.begin() + std::ptrdiff_t(v + 1) * dim);
    cell.push_back(static_cast<std::uint32_t>(cell.size()));
  }
  return polyhedron_value(c, make_leaf(dim, std::move(kept), {std::move(cell)}), at);
}

// SKELETON:k:p: the k-faces of every cell, each once.
ValuePtr skeleton_fn(Context& c, const Function&, Args a, Range at) {
  const auto k = static_cast<int>(count_arg(c, a[0], kMaxDimension, "SKELETON", at));
  const PolyPtr& p = polyhedron(c, a[1], "SKELETON", at);
  FlatComplex flat = flatten_cells(*p);
  cells_only(c, flat, "SKELETON", at);
  std::map<std::vector<std::uint32_t>, bool> seen;
  std::vector<Cell> cells;
  for (const Cell& cell : flat.cells) {
    const kernel::PolytopeNd polytope = cell_polytope(c, flat, cell, "SKELETON", at);
    if (k >= static_cast<int>(polytope.faces.size())) continue;
    for (const kernel::IndexSet& face : polytope.faces[static_cast<std::size_t>(k)]) {
      Cell mapped;
      for (kernel::PointIndex v : face) mapped.push_back(cell[v]);
      std::vector<std::uint32_t> key = mapped;
      std::sort(key.begin(), key.end());
      if (seen.emplace(std::move(key), true).second) cells.push_back(std::move(mapped));
    }
    c.charge(static_cast<double>(cells.size()) / 64, at);
  }
  return polyhedron_value(c, make_leaf(flat.dim, std::move(flat.points), std::move(cells)), at);
}

// OFFSET:<d1, ..., dk>:p: every cell swept by the box [0, d1] x ... x [0, dk] (a Minkowski sum,
// a convex cell again), seed 002 Listing 7.
ValuePtr offset_fn(Context& c, const Function&, Args a, Range at) {
  const std::vector<double> sizes = numbers(c, a[0], "OFFSET", at);
  const PolyPtr& p = polyhedron(c, a[1], "OFFSET", at);
  const int dim = std::max(p->dim, static_cast<int>(sizes.size()));
  if (sizes.empty() || dim > kMaxDimension)
    c.fail("PSM402",
           text({"'OFFSET' needs one size per coordinate (at most ", std::to_string(kMaxDimension),
                 ")"}),
           at);
  const FlatComplex flat = flatten_cells(*p);
  cells_only(c, flat, "OFFSET", at);
  const std::size_t corners = std::size_t{1} << sizes.size();
  std::vector<double> points;
  std::vector<Cell> cells;
  std::vector<double> swept;
  for (const Cell& cell : flat.cells) {
    c.charge(static_cast<double>(cell.size() * corners) / 4, at);
    swept.clear();
    for (std::uint32_t v : cell) {
      for (std::size_t k = 0; k < corners; ++k) {
        for (int i = 0; i < dim; ++i) {
          double x = i < flat.dim ? flat.point(v)[i] : 0.0;
          if (static_cast<std::size_t>(i) < sizes.size() && (k >> i & 1U) != 0)
            x += sizes[static_cast<std::size_t>(i)];
          swept.push_back(x);
        }
      }
    }
    const kernel::PolytopeNd swept_hull = hull(c, swept, dim, "OFFSET", at);
    Cell out;
    for (kernel::PointIndex v : swept_hull.vertices()) {
      out.push_back(static_cast<std::uint32_t>(points.size() / static_cast<std::size_t>(dim)));
      points.insert(points.end(), swept.begin() + std::ptrdiff_t(v) * dim,
                    swept.begin() + std::ptrdiff_t(v + 1) * dim);
    }
    cells.push_back(std::move(out));
  }
  return polyhedron_value(c, make_leaf(dim, std::move(points), std::move(cells)), at);
}

// SPLITCELLS: one polyhedron per cell.
ValuePtr splitcells_fn(Context& c, const Function&, Args a, Range at) {
  const PolyPtr& p = polyhedron(c, a[0], "SPLITCELLS", at);
  const FlatComplex flat = flatten_cells(*p);
  c.charge(static_cast<double>(flat.cells.size()), at);
  Sequence out;
  for (const Cell& cell : flat.cells) {
    std::vector<double> points;
    Cell local;
    for (std::uint32_t v : cell) {
      local.push_back(static_cast<std::uint32_t>(local.size()));
      points.insert(points.end(), flat.point(v), flat.point(v) + flat.dim);
    }
    out.push_back(
        polyhedron_value(c, make_leaf(flat.dim, std::move(points), {std::move(local)}), at));
  }
  for (const kernel::Mesh& solid : flat.solids)
    out.push_back(polyhedron_value(c, make_solid(solid), at));
  return c.sequence(std::move(out), at);
}

const Native kComplex[] = {
    {"JOIN", 1, join_fn},
    {"OFFSET", 2, offset_fn},
    {"SKELETON", 2, skeleton_fn},
    {"SPLITCELLS", 1, splitcells_fn},
};

}  // namespace

// p * q: the Cartesian product, cell by cell (its dimension is the sum of theirs).
ValuePtr product(Context& c, const PolyPtr& p, const PolyPtr& q, Range at) {
  if (p->dim + q->dim > kMaxDimension)
    c.fail("PSM402",
           text({"a product of polyhedra would have more than ", std::to_string(kMaxDimension),
                 " coordinates"}),
           at);
  const FlatComplex a = flatten_cells(*p);
  const FlatComplex b = flatten_cells(*q);
  cells_only(c, a, "*", at);
  cells_only(c, b, "*", at);
  const int dim = a.dim + b.dim;
  const std::size_t na = a.point_count();
  const std::size_t nb = b.point_count();
  c.charge(static_cast<double>(na) * static_cast<double>(nb) * dim / 4 +
               static_cast<double>(a.cells.size()) * static_cast<double>(b.cells.size()),
           at);
  std::vector<double> points;
  points.reserve(na * nb * static_cast<std::size_t>(dim));
  for (std::size_t i = 0; i < na; ++i) {
    for (std::size_t j = 0; j < nb; ++j) {
      points.insert(points.end(), a.point(static_cast<std::uint32_t>(i)),
                    a.point(static_cast<std::uint32_t>(i)) + a.dim);
      points.insert(points.end(), b.point(static_cast<std::uint32_t>(j)),
                    b.point(static_cast<std::uint32_t>(j)) + b.dim);
    }
  }
  std::vector<Cell> cells;
  cells.reserve(a.cells.size() * b.cells.size());
  for (const Cell& ca : a.cells) {
    for (const Cell& cb : b.cells) {
      Cell cell;
      cell.reserve(ca.size() * cb.size());
      for (std::uint32_t i : ca)
        for (std::uint32_t j : cb) cell.push_back(static_cast<std::uint32_t>(i * nb + j));
      cells.push_back(std::move(cell));
    }
  }
  return polyhedron_value(c, make_leaf(dim, std::move(points), std::move(cells)), at);
}

std::span<const Native> complex_natives() {
  return kComplex;
}

}  // namespace insula::lang::plasm
