// Curved geometry (seed 002, §3): MAP sends the vertices of a simplicial decomposition of a
// domain complex through coordinate functions; BEZIER makes the coordinate functions of a Bezier
// map whose control points may themselves be functions (transfinite blending, Listings 3-6, 9);
// CIRCLE, SPHERE, TORUS, TRUNCONE and CYLINDER are maps of interval grids, as in the PLaSM library.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include "kernel/hull_nd.h"
#include "lang/plasm/geometry.h"

namespace insula::lang::plasm {
namespace {

// The k-volume of the parallelotope on the edge vectors of the simplex spanned by `corners` (k + 1
// points of `dim` coordinates; k! times the simplex's), as the product of the edges' lengths
// after modified Gram-Schmidt; also returns the longest edge. Its error is rounding times the
// edges' lengths, where the Gram determinant's square root loses half the digits: a simplex
// collapsed up to rounding (the pole of a sphere, where cos(PI/2) is 6e-17) measured 1e-8 of
// its size and passed for a cell.
double simplex_volume(const std::vector<const double*>& corners, int dim, double& longest) {
  const std::size_t k = corners.size() - 1;
  const auto d = static_cast<std::size_t>(dim);
  std::vector<double> edges(k * d);
  longest = 0;
  for (std::size_t e = 0; e < k; ++e) {
    double length = 0;
    for (std::size_t i = 0; i < d; ++i) {
      const double x = corners[e + 1][i] - corners[0][i];
      edges[e * d + i] = x;
      length += x * x;
    }
    longest = std::max(longest, std::sqrt(length));
  }
  double volume = 1;
  for (std::size_t e = 0; e < k; ++e) {
    double* v = edges.data() + e * d;
    for (std::size_t b = 0; b < e; ++b) {
      const double* u = edges.data() + b * d;  // unit length
      double along = 0;
      for (std::size_t i = 0; i < d; ++i) along += v[i] * u[i];
      for (std::size_t i = 0; i < d; ++i) v[i] -= along * u[i];
    }
    double norm = 0;
    for (std::size_t i = 0; i < d; ++i) norm += v[i] * v[i];
    norm = std::sqrt(norm);
    volume *= norm;
    if (norm == 0) return 0;
    for (std::size_t i = 0; i < d; ++i) v[i] /= norm;
  }
  return volume;
}

// The sign of det(v1 - v0, ..., vd - v0) for d + 1 points of d coordinates.
double orientation(const std::vector<const double*>& corners, int dim) {
  std::vector<double> a(static_cast<std::size_t>(dim * dim));
  for (int r = 0; r < dim; ++r)
    for (int col = 0; col < dim; ++col)
      a[static_cast<std::size_t>(r * dim + col)] =
          corners[static_cast<std::size_t>(col) + 1][r] - corners[0][r];
  double det = 1;
  for (int col = 0; col < dim; ++col) {
    int pivot = col;
    for (int r = col + 1; r < dim; ++r)
      if (std::abs(a[static_cast<std::size_t>(r * dim + col)]) >
          std::abs(a[static_cast<std::size_t>(pivot * dim + col)]))
        pivot = r;
    if (pivot != col) {
      for (int t = 0; t < dim; ++t)
        std::swap(a[static_cast<std::size_t>(pivot * dim + t)],
                  a[static_cast<std::size_t>(col * dim + t)]);
      det = -det;
    }
    const double p = a[static_cast<std::size_t>(col * dim + col)];
    if (p == 0) return 0;
    det *= p;
    for (int r = col + 1; r < dim; ++r) {
      const double f = a[static_cast<std::size_t>(r * dim + col)] / p;
      for (int t = col; t < dim; ++t)
        a[static_cast<std::size_t>(r * dim + t)] -= f * a[static_cast<std::size_t>(col * dim + t)];
    }
  }
  return det;
}

// The domain's cells as a conforming simplicial complex over welded points: every cell is
// decomposed by the pulling triangulation in one global vertex order (lexicographic), so cells
// that share a face split it alike; full-dimensional simplices list their vertices positively.
struct Simplicial {
  int dim = 0;
  std::vector<double> points;
  std::vector<Cell> simplices;
};

Simplicial simplicial(Context& c, const FlatComplex& domain, std::string_view who, Range at) {
  Simplicial out;
  out.dim = domain.dim;
  const auto d = static_cast<std::size_t>(domain.dim);
  std::map<std::vector<double>, std::uint32_t> welded;
  std::vector<std::uint32_t> index(domain.point_count(), 0);
  for (std::uint32_t v = 0; v < domain.point_count(); ++v) {
    std::vector<double> key(domain.point(v), domain.point(v) + d);
    for (double& x : key) x = x == 0.0 ? 0.0 : x;  // -0 and 0 are one point
    index[v] =
        welded.emplace(std::move(key), static_cast<std::uint32_t>(welded.size())).first->second;
  }
  out.points.resize(welded.size() * d);
  std::vector<std::uint64_t> rank(welded.size());
  std::uint64_t r = 0;
  for (const auto& [key, i] : welded) {  // std::map iterates in lexicographic order
    std::copy(key.begin(), key.end(), out.points.begin() + std::ptrdiff_t(i * d));
    rank[i] = r++;
  }
  std::vector<double> buffer;
  std::vector<std::uint64_t> order;
  // Decompositions by shape: a cell that is another one moved and stretched along the axes, with
  // its vertices in the same order, decomposes alike (the pulling triangulation depends on the
  // face lattice and the order only, and both survive such a map). The key is the vertex count,
  // the vertices' order and their coordinates rescaled to the cell's bounding box; the cells of a
  // product of intervals all share one key, so one hull serves the whole domain.
  std::map<std::vector<double>, std::vector<kernel::IndexSet>> shapes;
  std::vector<double> key;
  std::vector<double> lo(d);
  std::vector<double> hi(d);
  for (const Cell& cell : domain.cells) {
    Cell ids;
    for (std::uint32_t v : cell) ids.push_back(index[v]);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    buffer.clear();
    order.clear();
    for (std::uint32_t v : ids) {
      buffer.insert(buffer.end(), out.points.begin() + std::ptrdiff_t(v * d),
                    out.points.begin() + std::ptrdiff_t((v + 1) * d));
      order.push_back(rank[v]);
    }
    std::fill(lo.begin(), lo.end(), 0.0);
    std::fill(hi.begin(), hi.end(), 0.0);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      for (std::size_t a = 0; a < d; ++a) {
        const double x = buffer[i * d + a];
        lo[a] = i == 0 ? x : std::min(lo[a], x);
        hi[a] = i == 0 ? x : std::max(hi[a], x);
      }
    }
    key.assign(1, static_cast<double>(ids.size()));
    for (std::size_t i = 0; i < ids.size(); ++i) {
      std::size_t before = 0;  // the vertex's place in the order, within the cell
      for (std::uint64_t o : order) before += o < order[i] ? 1 : 0;
      key.push_back(static_cast<double>(before));
      for (std::size_t a = 0; a < d; ++a)
        key.push_back(hi[a] > lo[a] ? (buffer[i * d + a] - lo[a]) / (hi[a] - lo[a]) : 0.0);
    }
    auto known = shapes.find(key);
    if (known == shapes.end()) {
      const kernel::PolytopeNd polytope = hull(c, buffer, domain.dim, who, at);
      known = shapes.emplace(key, kernel::simplices_nd(polytope, order)).first;
    }
    for (const kernel::IndexSet& s : known->second) {
      Cell simplex;
      for (kernel::PointIndex v : s) simplex.push_back(ids[v]);
      if (static_cast<int>(simplex.size()) == domain.dim + 1) {
        std::vector<const double*> corners;
        for (std::uint32_t v : simplex) corners.push_back(out.points.data() + std::size_t(v) * d);
        if (orientation(corners, domain.dim) < 0) std::swap(simplex[0], simplex[1]);
      }
      out.simplices.push_back(std::move(simplex));
    }
    c.charge(static_cast<double>(out.simplices.size()) / 64, at);
  }
  return out;
}

}  // namespace

// The simplices of `domain` through `f` (out_dim coordinates), without the ones the map
// collapses (a k-simplex whose k-volume is below 1e-9 of its longest edge to the k: the pole of
// a sphere, the centre of a circle, slivers).
PolyPtr map_complex(Context& c, const FlatComplex& domain, int out_dim, const PointMap& f,
                    std::string_view who, Range at) {
  const Simplicial s = simplicial(c, domain, who, at);
  const auto d = static_cast<std::size_t>(s.dim);
  const std::size_t count = s.points.size() / std::max<std::size_t>(d, 1);
  std::vector<bool> used(count, false);
  for (const Cell& simplex : s.simplices)
    for (std::uint32_t v : simplex) used[v] = true;
  std::vector<double> mapped(count * static_cast<std::size_t>(out_dim), 0.0);
  for (std::size_t v = 0; v < count; ++v)
    if (used[v]) f(s.points.data() + v * d, mapped.data() + v * static_cast<std::size_t>(out_dim));
  std::vector<Cell> cells;
  std::vector<const double*> corners;
  for (const Cell& simplex : s.simplices) {
    corners.clear();
    for (std::uint32_t v : simplex)
      corners.push_back(mapped.data() + std::size_t(v) * static_cast<std::size_t>(out_dim));
    double longest = 0;
    const double volume = corners.size() == 1 ? 1.0 : simplex_volume(corners, out_dim, longest);
    const auto k = static_cast<double>(simplex.size() - 1);
    if (corners.size() > 1 && (longest == 0 || volume <= 1e-9 * std::pow(longest, k))) continue;
    cells.push_back(simplex);
  }
  return make_leaf(out_dim, std::move(mapped), std::move(cells));
}

namespace {

// The point as a PLaSM sequence of numbers.
ValuePtr point_value(Context& c, const double* x, int dim, Range at) {
  Sequence coords;
  coords.reserve(static_cast<std::size_t>(dim));
  for (int i = 0; i < dim; ++i) coords.push_back(make_number(x[i]));
  return c.sequence(std::move(coords), at);
}

double number_result(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  if (!v->is_number())
    c.fail("PSM402",
           text({"'", who, "': a coordinate function gave ", kind_name(v->kind()), " ", summary(*v),
                 ", not a number"}),
           at);
  if (!std::isfinite(v->number()))
    c.fail("PSM406", text({"'", who, "': a coordinate function gave no finite number"}), at);
  return v->number();
}

// MAP:f:domain, f a sequence of coordinate functions or one function giving a sequence.
ValuePtr map_values(Context& c, Args a, Range at) {
  const ValuePtr& f = a[0];
  const PolyPtr& p = polyhedron(c, a[1], "MAP", at);
  const FlatComplex domain = flatten_cells(*p);
  cells_only(c, domain, "MAP", at);
  int out_dim = 0;
  ValuePtr probe;
  if (f->is_sequence()) {
    out_dim = static_cast<int>(f->sequence().size());
    for (const ValuePtr& fi : f->sequence())
      if (!fi->is_function())
        c.fail("PSM402",
               text({"'MAP' needs coordinate functions, found ", kind_name(fi->kind()), " ",
                     summary(*fi)}),
               at);
  } else if (!f->is_function()) {
    c.fail("PSM402",
           text({"'MAP' needs a function or a sequence of functions, found ", kind_name(f->kind()),
                 " ", summary(*f)}),
           at);
  }
  if (domain.cells.empty()) return polyhedron_value(c, make_leaf(std::max(out_dim, 1), {}, {}), at);
  if (!f->is_sequence()) {
    // The dimension of the image: the length of the sequence f gives at a domain point.
    const ValuePtr sample =
        c.apply(f, point_value(c, domain.point(domain.cells[0][0]), domain.dim, at), at);
    out_dim = static_cast<int>(c.seq(sample, "MAP", at).size());
  }
  if (out_dim == 0 || out_dim > kMaxDimension)
    c.fail("PSM402",
           text({"'MAP' needs 1 to ", std::to_string(kMaxDimension),
                 " coordinate functions, found ", std::to_string(out_dim)}),
           at);
  const PointMap eval = [&](const double* in, double* out) {
    const ValuePtr x = point_value(c, in, domain.dim, at);
    if (f->is_sequence()) {
      for (int i = 0; i < out_dim; ++i)
        out[i] =
            number_result(c, c.apply(f->sequence()[static_cast<std::size_t>(i)], x, at), "MAP", at);
      return;
    }
    const ValuePtr image = c.apply(f, x, at);
    const Sequence& coords = c.seq(image, "MAP", at);
    if (static_cast<int>(coords.size()) != out_dim)
      c.fail("PSM402",
             text({"'MAP': the map gave ", std::to_string(coords.size()),
                   " coordinates at one point and ", std::to_string(out_dim), " at another"}),
             at);
    for (int i = 0; i < out_dim; ++i)
      out[i] = number_result(c, coords[static_cast<std::size_t>(i)], "MAP", at);
  };
  return polyhedron_value(c, map_complex(c, domain, out_dim, eval, "MAP", at), at);
}

ValuePtr map_fn(Context& c, const Function&, Args a, Range at) {
  if (const ValuePtr* known = c.memo(map_fn, a[0], a[1])) return *known;
  return c.remember(map_fn, a[0], a[1], map_values(c, a, at));
}

// ---------------------------------------------------------------- BEZIER

// Coordinate j of control point `p` at `x`: a number, or a function of the point.
double control_coordinate(Context& c, const ValuePtr& p, std::size_t j, const ValuePtr& x,
                          Range at) {
  if (p->is_function()) {
    const ValuePtr image = c.apply(p, x, at);
    const Sequence& coords = c.seq(image, "BEZIER", at);
    if (j >= coords.size())
      c.fail("PSM402", "'BEZIER': a control point function gave too few coordinates", at);
    return number_result(c, coords[j], "BEZIER", at);
  }
  const ValuePtr& e = p->sequence()[j];
  return number_result(c, e->is_function() ? c.apply(e, x, at) : e, "BEZIER", at);
}

// The j-th coordinate function of a Bezier map: bound are the parameter selector, the control
// points and j; the last argument is the point.
ValuePtr bezier_coordinate_fn(Context& c, const Function&, Args a, Range at) {
  const double u = number_result(c, c.apply(a[0], a[3], at), "BEZIER", at);
  const Sequence& controls = a[1]->sequence();
  const auto j = static_cast<std::size_t>(a[2]->number());
  const std::size_t n = controls.size() - 1;
  // Bernstein polynomials B(n, i)(u) = C(n, i) u^i (1 - u)^(n - i), by de Casteljau's recurrence
  // on the coordinates (stable for any u).
  std::vector<double> b(n + 1);
  for (std::size_t i = 0; i <= n; ++i) b[i] = control_coordinate(c, controls[i], j, a[3], at);
  for (std::size_t level = 1; level <= n; ++level)
    for (std::size_t i = 0; i + level <= n; ++i) b[i] = (1 - u) * b[i] + u * b[i + 1];
  return make_number(b[0]);
}

// BEZIER:sel:<p0, ..., pn>: the coordinate functions of the Bezier map of degree n in the
// parameter sel picks from a point. A control point is a sequence of numbers or functions, or a
// function giving a sequence; the map has as many coordinates as the sequences.
ValuePtr bezier_fn(Context& c, const Function&, Args a, Range at) {
  if (!a[0]->is_function())
    c.fail("PSM402",
           text({"'BEZIER' needs a parameter selector such as S1, found ", kind_name(a[0]->kind()),
                 " ", summary(*a[0])}),
           at);
  const Sequence& controls = c.seq(a[1], "BEZIER", at);
  if (controls.size() < 2) c.fail("PSM402", "'BEZIER' needs at least two control points", at);
  std::size_t dim = 0;
  for (std::size_t i = 0; i < controls.size(); ++i) {
    const ValuePtr& p = controls[i];
    if (p->is_function()) continue;
    const std::size_t n = c.seq(p, "BEZIER", at).size();
    if (dim != 0 && n != dim)
      c.fail("PSM402",
             text({"'BEZIER': control point ", std::to_string(i + 1), " has ", std::to_string(n),
                   " coordinates, the others ", std::to_string(dim)}),
             at);
    dim = n;
  }
  if (dim == 0)
    c.fail("PSM402", "'BEZIER' needs a control point given as a sequence of coordinates", at);
  Sequence functions;
  for (std::size_t j = 0; j < dim; ++j)
    functions.push_back(c.native("BEZIER", 4, bezier_coordinate_fn,
                                 Sequence{a[0], a[1], make_number(static_cast<double>(j))}, at));
  return c.sequence(std::move(functions), at);
}

// ---------------------------------------------------------------- curved primitives

// A grid of boxes over [0, size_i] with divisions_i cells along each axis.
FlatComplex grid(const std::vector<double>& sizes, const std::vector<std::size_t>& divisions) {
  FlatComplex g;
  g.dim = static_cast<int>(sizes.size());
  std::vector<std::size_t> stride(sizes.size(), 1);
  std::size_t count = 1;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    stride[i] = count;
    count *= divisions[i] + 1;
  }
  for (std::size_t v = 0; v < count; ++v) {
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      const std::size_t k = v / stride[i] % (divisions[i] + 1);
      g.points.push_back(sizes[i] * static_cast<double>(k) / static_cast<double>(divisions[i]));
    }
  }
  const std::size_t corners = std::size_t{1} << sizes.size();
  for (std::size_t v = 0; v < count; ++v) {
    bool inner = true;
    for (std::size_t i = 0; i < sizes.size(); ++i)
      inner = inner && v / stride[i] % (divisions[i] + 1) < divisions[i];
    if (!inner) continue;
    Cell cell;
    for (std::size_t k = 0; k < corners; ++k) {
      std::size_t corner = v;
      for (std::size_t i = 0; i < sizes.size(); ++i)
        if ((k >> i & 1U) != 0) corner += stride[i];
      cell.push_back(static_cast<std::uint32_t>(corner));
    }
    g.cells.push_back(std::move(cell));
  }
  return g;
}

std::vector<std::size_t> divisions(Context& c, const ValuePtr& v, std::size_t count,
                                   std::string_view who, Range at) {
  std::vector<std::size_t> out;
  if (v->is_number()) {
    out.push_back(count_arg(c, v, 100'000, who, at));
  } else {
    for (const ValuePtr& e : c.seq(v, who, at)) out.push_back(count_arg(c, e, 100'000, who, at));
  }
  while (out.size() < count) out.push_back(1);
  if (out.size() != count)
    c.fail("PSM402", text({"'", who, "' needs ", std::to_string(count), " subdivision numbers"}),
           at);
  double cells = 1;
  for (std::size_t n : out) {
    if (n == 0) c.fail("PSM402", text({"'", who, "' needs subdivisions of at least 1"}), at);
    cells *= static_cast<double>(n);
  }
  c.charge(cells, at);
  return out;
}

double positive(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  const double x = c.number(v, who, at);
  if (!(x > 0) || !std::isfinite(x))
    c.fail("PSM402", text({"'", who, "' needs positive sizes, found ", summary(*v)}), at);
  return x;
}

constexpr double kTau = 2 * std::numbers::pi;

// CIRCLE:r:<n, m>: the disk of radius r, n sectors and m rings.
ValuePtr circle_fn(Context& c, const Function&, Args a, Range at) {
  const double r = positive(c, a[0], "CIRCLE", at);
  const std::vector<std::size_t> n = divisions(c, a[1], 2, "CIRCLE", at);
  const PointMap f = [](const double* in, double* out) {
    out[0] = in[1] * std::cos(in[0]);
    out[1] = in[1] * std::sin(in[0]);
  };
  return polyhedron_value(c, map_complex(c, grid({kTau, r}, n), 2, f, "CIRCLE", at), at);
}

// SPHERE:r:<n, m>: the sphere surface, n parallels' bands and m meridians' sectors, from the
// north pole down so that the surface faces outward.
ValuePtr sphere_fn(Context& c, const Function&, Args a, Range at) {
  const double r = positive(c, a[0], "SPHERE", at);
  const std::vector<std::size_t> n = divisions(c, a[1], 2, "SPHERE", at);
  const PointMap f = [r](const double* in, double* out) {
    const double lat = std::numbers::pi / 2 - in[0];
    out[0] = r * std::cos(lat) * std::cos(in[1]);
    out[1] = r * std::cos(lat) * std::sin(in[1]);
    out[2] = r * std::sin(lat);
  };
  return polyhedron_value(c, map_complex(c, grid({std::numbers::pi, kTau}, n), 3, f, "SPHERE", at),
                          at);
}

// TORUS:<r1, r2>:<n, m>: the surface of a tube of radius r1 around a circle of radius r2 in the
// xy plane, n sectors around the tube and m around the axis (docs/plasm-language.md); the tube
// angle runs from the outer equator downwards, so that the surface faces outward.
ValuePtr torus_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& radii = c.seq_of(a[0], 2, "TORUS", at);
  const double r1 = positive(c, radii[0], "TORUS", at);
  const double r2 = positive(c, radii[1], "TORUS", at);
  const std::vector<std::size_t> n = divisions(c, a[1], 2, "TORUS", at);
  const PointMap f = [r1, r2](const double* in, double* out) {
    const double ring = r2 + r1 * std::cos(in[0]);
    out[0] = ring * std::cos(in[1]);
    out[1] = ring * std::sin(in[1]);
    out[2] = -r1 * std::sin(in[0]);
  };
  return polyhedron_value(c, map_complex(c, grid({kTau, kTau}, n), 3, f, "TORUS", at), at);
}

// TRUNCONE:<r1, r2, h>:n: the side of a truncated cone, radius r1 at z = 0 and r2 at z = h.
ValuePtr truncone_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& args = c.seq_of(a[0], 3, "TRUNCONE", at);
  const double r1 = c.number(args[0], "TRUNCONE", at);
  const double r2 = c.number(args[1], "TRUNCONE", at);
  const double h = c.number(args[2], "TRUNCONE", at);
  if (r1 < 0 || r2 < 0 || (r1 == 0 && r2 == 0) || h == 0)
    c.fail("PSM402", "'TRUNCONE' needs radii >= 0, not both 0, and a height other than 0", at);
  const std::vector<std::size_t> n = divisions(c, a[1], 2, "TRUNCONE", at);
  const PointMap f = [r1, r2, h](const double* in, double* out) {
    const double r = r1 + (r2 - r1) * in[1];
    out[0] = r * std::cos(in[0]);
    out[1] = r * std::sin(in[0]);
    out[2] = h * in[1];
  };
  return polyhedron_value(c, map_complex(c, grid({kTau, 1.0}, n), 3, f, "TRUNCONE", at), at);
}

// CYLINDER:<r, h>:n: a solid prism over a regular n-gon inscribed in the circle of radius r.
ValuePtr cylinder_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& args = c.seq_of(a[0], 2, "CYLINDER", at);
  const double r = positive(c, args[0], "CYLINDER", at);
  const double h = positive(c, args[1], "CYLINDER", at);
  const std::size_t n = count_arg(c, a[1], 100'000, "CYLINDER", at);
  if (n < 3) c.fail("PSM402", "'CYLINDER' needs at least 3 sides", at);
  c.charge(static_cast<double>(n), at);
  std::vector<double> points;
  Cell cell;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = kTau * static_cast<double>(i) / static_cast<double>(n);
    for (double z : {0.0, h}) {
      points.insert(points.end(), {r * std::cos(t), r * std::sin(t), z});
      cell.push_back(static_cast<std::uint32_t>(cell.size()));
    }
  }
  return polyhedron_value(c, make_leaf(3, std::move(points), {std::move(cell)}), at);
}

const Native kMap[] = {
    {"BEZIER", 2, bezier_fn},     {"CIRCLE", 2, circle_fn}, {"CYLINDER", 2, cylinder_fn},
    {"MAP", 2, map_fn},           {"SPHERE", 2, sphere_fn}, {"TORUS", 2, torus_fn},
    {"TRUNCONE", 2, truncone_fn},
};

}  // namespace

std::span<const Native> map_natives() {
  return kMap;
}

}  // namespace insula::lang::plasm
