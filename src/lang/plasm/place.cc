// The paper's reconstruction workflow (seed 002, §5): outlines traced in a drawing program and
// imported from SVG, and parts modelled in local coordinates placed into the site either by the
// affine map that 4 affinely independent points define (AFFINE) or by the trilinear map of a
// containment box onto 8 corner points of an irregular volume (TRILINEAR).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "kernel/triangulate.h"
#include "lang/plasm/geometry.h"

namespace insula::lang::plasm {
namespace {

// A point given as a sequence of numbers of the expected dimension.
std::vector<double> point_arg(Context& c, const ValuePtr& v, std::size_t dim, std::string_view who,
                              Range at) {
  std::vector<double> p = numbers(c, v, who, at);
  if (p.size() != dim)
    c.fail("PSM402",
           text({"'", who, "' needs points of ", std::to_string(dim), " coordinates, found ",
                 summary(*v)}),
           at);
  for (double x : p)
    if (!std::isfinite(x)) c.fail("PSM406", text({"'", who, "' needs finite coordinates"}), at);
  return p;
}

// Solves a x = b for the n x n row-major matrix a (partial pivoting); false when singular
// relative to the matrix's scale.
bool solve(std::vector<double> a, std::vector<double>& b, std::size_t n, std::size_t rhs) {
  double scale = 0;
  for (double x : a) scale = std::max(scale, std::abs(x));
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r)
      if (std::abs(a[r * n + col]) > std::abs(a[pivot * n + col])) pivot = r;
    if (std::abs(a[pivot * n + col]) <= 1e-12 * scale) return false;
    for (std::size_t t = 0; t < n; ++t) std::swap(a[pivot * n + t], a[col * n + t]);
    for (std::size_t t = 0; t < rhs; ++t) std::swap(b[pivot * rhs + t], b[col * rhs + t]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == col) continue;
      const double f = a[r * n + col] / a[col * n + col];
      for (std::size_t t = col; t < n; ++t) a[r * n + t] -= f * a[col * n + t];
      for (std::size_t t = 0; t < rhs; ++t) b[r * rhs + t] -= f * b[col * rhs + t];
    }
  }
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t t = 0; t < rhs; ++t) b[r * rhs + t] /= a[r * n + r];
  return true;
}

ValuePtr affine_fn(Context& c, const Function& self, Args a, Range at);

}  // namespace

// AFFINE:<<p0, ..., pd>, <q0, ..., qd>> is the affine map of R^d sending each p_i to q_i (d + 1
// affinely independent points: 4 in space).
bool affine_from_points(Context& c, const Function& f, Affine& out, Range at) {
  if (f.native != affine_fn || f.bound.size() != 1) return false;
  const Sequence& pair = c.seq_of(f.bound[0], 2, "AFFINE", at);
  const Sequence& from = c.seq(pair[0], "AFFINE", at);
  const Sequence& to = c.seq(pair[1], "AFFINE", at);
  const std::size_t d = from.size() - 1;
  if (from.size() < 2 || from.size() != to.size() || d > static_cast<std::size_t>(kMaxDimension))
    c.fail("PSM402",
           "'AFFINE' needs two sequences of d + 1 points each, as "
           "AFFINE:<<p0, p1, p2, p3>, <q0, q1, q2, q3>>",
           at);
  std::vector<std::vector<double>> p, q;
  for (std::size_t i = 0; i <= d; ++i) {
    p.push_back(point_arg(c, from[i], d, "AFFINE", at));
    q.push_back(point_arg(c, to[i], d, "AFFINE", at));
  }
  // Rows: (p_i - p_0)^T A^T = (q_i - q_0)^T for i = 1..d, solved for A^T.
  std::vector<double> m(d * d), rhs(d * d);
  for (std::size_t i = 0; i < d; ++i) {
    for (std::size_t k = 0; k < d; ++k) {
      m[i * d + k] = p[i + 1][k] - p[0][k];
      rhs[i * d + k] = q[i + 1][k] - q[0][k];
    }
  }
  if (!solve(m, rhs, d, d))
    c.fail("PSM402", "'AFFINE': the first points are not affinely independent", at);
  out = Affine::identity(static_cast<int>(d));
  const int n = static_cast<int>(d);
  for (std::size_t r = 0; r < d; ++r) {
    double t = q[0][r];
    for (std::size_t k = 0; k < d; ++k) {
      const double entry = rhs[k * d + r];  // A[r][k] = (A^T)[k][r]
      out.m[r * static_cast<std::size_t>(n + 1) + k] = entry;
      t -= entry * p[0][k];
    }
    out.m[r * static_cast<std::size_t>(n + 1) + d] = t;
  }
  return true;
}

namespace {

ValuePtr affine_fn(Context& c, const Function& self, Args a, Range at) {
  Affine map;
  affine_from_points(c, self, map, at);
  return polyhedron_value(c, make_placed(polyhedron(c, a[1], "AFFINE", at), std::move(map)), at);
}

// TRILINEAR:<q000, q100, q010, q110, q001, q101, q011, q111>:p maps p's bounding box onto the
// volume with those corners (x varies fastest), through MAP's simplicial decomposition, so a
// part modelled in a regular box fits an irregular containment volume.
ValuePtr trilinear_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& corners = c.seq_of(a[0], 8, "TRILINEAR", at);
  std::vector<std::vector<double>> q;
  for (const ValuePtr& v : corners) q.push_back(point_arg(c, v, 3, "TRILINEAR", at));
  const PolyPtr& p = polyhedron(c, a[1], "TRILINEAR", at);
  const FlatComplex flat = flatten_cells(*p);
  cells_only(c, flat, "TRILINEAR", at);
  if (flat.dim > 3) c.fail("PSM402", "'TRILINEAR' maps polyhedra of at most 3 coordinates", at);
  double lo[3] = {0, 0, 0};
  double size[3] = {1, 1, 1};
  const std::vector<double> used = used_points(flat);
  const auto d = static_cast<std::size_t>(flat.dim);
  for (std::size_t k = 0; k < d; ++k) {
    double mn = 0, mx = 0;
    for (std::size_t i = k; i < used.size(); i += d) {
      mn = i == k ? used[i] : std::min(mn, used[i]);
      mx = i == k ? used[i] : std::max(mx, used[i]);
    }
    lo[k] = mn;
    size[k] = mx > mn ? mx - mn : 1;
  }
  const int dim = flat.dim;
  const PointMap f = [&q, lo, size, dim](const double* in, double* out) {
    double u[3] = {0, 0, 0};
    for (int k = 0; k < dim; ++k) u[k] = (in[k] - lo[k]) / size[k];
    for (int r = 0; r < 3; ++r) {
      double sum = 0;
      for (std::size_t corner = 0; corner < 8; ++corner) {
        double w = 1;
        for (int k = 0; k < 3; ++k) w *= (corner >> k & 1U) != 0 ? u[k] : 1 - u[k];
        sum += w * q[corner][static_cast<std::size_t>(r)];
      }
      out[r] = sum;
    }
  };
  return polyhedron_value(c, map_complex(c, flat, 3, f, "TRILINEAR", at), at);
}

// One outline as a polyhedron of the plane (y flipped, so the drawing reads as seen from above):
// a closed outline is its polygon, triangulated into 2D cells; an open one its segments.
PolyPtr outline_polyhedron(Context& c, const Outline& o, Range at) {
  std::vector<double> points;
  std::vector<Cell> cells;
  const std::size_t n = o.xy.size() / 2;
  for (std::size_t i = 0; i < n; ++i) {
    points.push_back(o.xy[2 * i]);
    points.push_back(-o.xy[2 * i + 1]);
  }
  if (!o.closed) {
    for (std::size_t i = 0; i + 1 < n; ++i)
      cells.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)});
    return make_leaf(2, std::move(points), std::move(cells));
  }
  kernel::Polygon polygon;
  for (std::size_t i = 0; i < n; ++i) polygon.outer.push_back({points[2 * i], points[2 * i + 1]});
  kernel::Triangulation t;
  if (!kernel::triangulate(polygon, t))
    c.fail("PSM417",
           text({"'SVG': outline '", o.id, "' cannot be triangulated (",
                 kernel::to_string(t.status), ")"}),
           at);
  for (const auto& tri : t.triangles) cells.push_back({tri[0], tri[1], tri[2]});
  return make_leaf(2, std::move(points), std::move(cells));
}

// SVG:"plan.svg" is the sequence of the drawing's outlines as polyhedra of the plane, in
// document order; SVG:"plan.svg#room" the one outline whose id is room.
ValuePtr svg_fn(Context& c, const Function&, Args a, Range at) {
  if (a[0]->kind() != Kind::kString)
    c.fail("PSM402",
           text({"'SVG' needs a file name, found ", kind_name(a[0]->kind()), " ", summary(*a[0])}),
           at);
  const std::string& name = a[0]->string();
  const std::size_t hash = name.find('#');
  const std::string file = name.substr(0, hash);
  if (!c.outline_reader)
    c.fail("PSM417", text({"'SVG': no drawings can be read here (", file, ")"}), at);
  std::vector<Outline> outlines;
  std::string error;
  if (!c.outline_reader(file, outlines, error)) c.fail("PSM417", text({"'SVG': ", error}), at);
  c.charge(static_cast<double>(outlines.size()), at);
  if (hash != std::string::npos) {
    const std::string id = name.substr(hash + 1);
    for (const Outline& o : outlines)
      if (o.id == id) return polyhedron_value(c, outline_polyhedron(c, o, at), at);
    c.fail("PSM417", text({"'SVG': ", file, " has no outline with id '", id, "'"}), at);
  }
  Sequence out;
  for (const Outline& o : outlines)
    out.push_back(polyhedron_value(c, outline_polyhedron(c, o, at), at));
  return c.sequence(std::move(out), at);
}

const Native kPlace[] = {
    {"AFFINE", 2, affine_fn},
    {"SVG", 1, svg_fn},
    {"TRILINEAR", 2, trilinear_fn},
};

}  // namespace

std::span<const Native> place_natives() {
  return kPlace;
}

}  // namespace insula::lang::plasm
