// Geometry builtins that make and place polyhedra (seed 002, §2 and Listing 2; the PLaSM library
// as pyplasm documents it): QUOTE, Q, INTERVALS, CUBOID, SIMPLEX, MKPOL, the affine maps T, S, R,
// STRUCT, EMBED, the measures SIZE, MIN, MAX, MED and the placements ALIGN, TOP, BOTTOM, LEFT,
// RIGHT.
#include "lang/plasm/geometry.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "base/format.h"

namespace insula::lang::plasm {

const PolyPtr& polyhedron(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  if (!v->is_polyhedron())
    c.fail("PSM402",
           text({"'", who, "' needs a polyhedron, found ", kind_name(v->kind()), " ", summary(*v)}),
           at);
  return v->polyhedron();
}

ValuePtr polyhedron_value(Context& c, PolyPtr p, Range at) {
  c.charge(static_cast<double>(p->cells.size() + p->children.size() + p->points.size() / 4 + 1),
           at);
  if (p->depth > kMaxPolyhedronDepth)
    c.fail("PSM413",
           text({"a polyhedron nests deeper than ", std::to_string(kMaxPolyhedronDepth),
                 " levels of STRUCT"}),
           at);
  return make_polyhedron(std::move(p));
}

std::vector<double> numbers(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  if (v->is_number()) return {v->number()};
  std::vector<double> out;
  for (const ValuePtr& e : c.seq(v, who, at)) out.push_back(c.number(e, who, at));
  return out;
}

std::vector<int> axes(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  std::vector<int> out;
  for (double x : numbers(c, v, who, at)) {
    if (x != std::floor(x) || x < 1 || x > kMaxDimension)
      c.fail("PSM402",
             text({"'", who, "' needs coordinate indices from 1 to ", std::to_string(kMaxDimension),
                   ", found ", base::shortest_number(x)}),
             at);
    out.push_back(static_cast<int>(x) - 1);
  }
  return out;
}

kernel::PolytopeNd hull(Context& c, std::span<const double> points, int dim, std::string_view who,
                        Range at) {
  const std::size_t count = points.size() / static_cast<std::size_t>(std::max(dim, 1));
  if (dim >= 5 && count > kMaxHighHullPoints)
    c.fail("PSM418",
           text({"'", who, "': a convex hull of ", std::to_string(count), " points in ",
                 std::to_string(dim), "D is too large (at most ",
                 std::to_string(kMaxHighHullPoints), " points from 5D on)"}),
           at);
  kernel::PolytopeNd p = kernel::polytope_nd(points, dim);
  if (!p.ok())
    c.fail("PSM414",
           text({"'", who, "': no convex hull (", kernel::hull_nd_status_message(p.status), ")"}),
           at);
  double faces = 0;
  for (const auto& level : p.faces) faces += static_cast<double>(level.size());
  c.charge(faces / 8, at);
  return p;
}

void cells_only(Context& c, const FlatComplex& flat, std::string_view who, Range at) {
  if (!flat.solids.empty())
    c.fail("PSM416",
           text({"'", who,
                 "' works on convex cells, and the result of a boolean is a solid "
                 "without them (apply '",
                 who, "' to the operands instead)"}),
           at);
}

std::size_t count_arg(Context& c, const ValuePtr& v, std::size_t limit, std::string_view who,
                      Range at) {
  const double n = c.number(v, who, at);
  if (n < 0 || n != std::floor(n) || n > static_cast<double>(limit))
    c.fail("PSM402",
           text({"'", who, "' needs a whole number from 0 to ", std::to_string(limit), ", found ",
                 summary(*v)}),
           at);
  return static_cast<std::size_t>(n);
}

namespace {

double finite(Context& c, double x, std::string_view who, Range at) {
  if (!std::isfinite(x)) c.fail("PSM406", text({"'", who, "' gives no finite number here"}), at);
  return x;
}

// ---------------------------------------------------------------- primitives

// 1D cells from signed lengths: a positive length is a cell, a negative one a gap (QUOTE).
PolyPtr quote(Context& c, const std::vector<double>& lengths, std::string_view who, Range at) {
  std::vector<double> points{0.0};
  std::vector<Cell> cells;
  double x = 0;
  for (double length : lengths) {
    if (length == 0) c.fail("PSM402", text({"'", who, "' needs lengths other than 0"}), at);
    x = finite(c, x + std::abs(length), who, at);
    if (length > 0) {
      if (points.back() != x - length) points.push_back(x - length);
      points.push_back(x);
      cells.push_back({static_cast<std::uint32_t>(points.size() - 2),
                       static_cast<std::uint32_t>(points.size() - 1)});
    }
  }
  return make_leaf(1, std::move(points), std::move(cells));
}

ValuePtr quote_fn(Context& c, const Function& self, Args a, Range at) {
  const std::vector<double> lengths = numbers(c, a[0], self.label, at);
  c.charge(static_cast<double>(lengths.size()), at);
  return polyhedron_value(c, quote(c, lengths, self.label, at), at);
}

ValuePtr intervals_fn(Context& c, const Function&, Args a, Range at) {
  const double length = c.number(a[0], "INTERVALS", at);
  // The memory budget bounds n (charged below, before anything is allocated); the limit here
  // only keeps cell indices in 32 bits.
  const std::size_t n = count_arg(c, a[1], 0xFFFF'FFFE, "INTERVALS", at);
  if (n == 0 || length <= 0)
    c.fail("PSM402",
           text({"'INTERVALS' needs a positive length and at least one interval, found ",
                 summary(*a[0]), " and ", summary(*a[1])}),
           at);
  c.charge(static_cast<double>(n), at);
  std::vector<double> points(n + 1);
  std::vector<Cell> cells(n);
  for (std::size_t i = 0; i <= n; ++i)
    points[i] = length * static_cast<double>(i) / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i)
    cells[i] = {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)};
  return polyhedron_value(c, make_leaf(1, std::move(points), std::move(cells)), at);
}

ValuePtr cuboid_fn(Context& c, const Function&, Args a, Range at) {
  const std::vector<double> sizes = numbers(c, a[0], "CUBOID", at);
  const int d = static_cast<int>(sizes.size());
  if (d == 0 || d > kMaxDimension)
    c.fail("PSM402",
           text({"'CUBOID' needs 1 to ", std::to_string(kMaxDimension), " sizes, found ",
                 std::to_string(d)}),
           at);
  const std::size_t corners = std::size_t{1} << d;
  c.charge(static_cast<double>(corners), at);
  std::vector<double> points(corners * static_cast<std::size_t>(d));
  Cell cell(corners);
  for (std::size_t k = 0; k < corners; ++k) {
    for (int i = 0; i < d; ++i)
      points[k * static_cast<std::size_t>(d) + static_cast<std::size_t>(i)] =
          (k >> i & 1U) != 0 ? sizes[static_cast<std::size_t>(i)] : 0.0;
    cell[k] = static_cast<std::uint32_t>(k);
  }
  return polyhedron_value(c, make_leaf(d, std::move(points), {std::move(cell)}), at);
}

ValuePtr simplex_fn(Context& c, const Function&, Args a, Range at) {
  const auto d = static_cast<int>(count_arg(c, a[0], kMaxDimension, "SIMPLEX", at));
  if (d == 0) c.fail("PSM402", "'SIMPLEX' needs a dimension of at least 1", at);
  std::vector<double> points(static_cast<std::size_t>((d + 1) * d), 0.0);
  Cell cell{0};
  for (int i = 0; i < d; ++i) {
    points[static_cast<std::size_t>((i + 1) * d + i)] = 1.0;
    cell.push_back(static_cast<std::uint32_t>(i + 1));
  }
  return polyhedron_value(c, make_leaf(d, std::move(points), {std::move(cell)}), at);
}

// MKPOL:<verts, cells, pols>: vertices (1-based in cells), convex cells as vertex lists, and
// polyhedral cells as lists of convex cells; a convex cell no polyhedral cell names is left out.
ValuePtr mkpol_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& parts = c.seq_of(a[0], 3, "MKPOL", at);
  const Sequence& verts = c.seq(parts[0], "MKPOL", at);
  const Sequence& cells = c.seq(parts[1], "MKPOL", at);
  const Sequence& pols = c.seq(parts[2], "MKPOL", at);
  int d = -1;
  std::vector<double> points;
  c.charge(static_cast<double>(verts.size() + cells.size()), at);
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const std::vector<double> p = numbers(c, verts[i], "MKPOL", at);
    if (d == -1) d = static_cast<int>(p.size());
    if (static_cast<int>(p.size()) != d || d == 0 || d > kMaxDimension)
      c.fail("PSM402",
             text({"'MKPOL': vertex ", std::to_string(i + 1), " has ", std::to_string(p.size()),
                   " coordinates, vertex 1 has ", std::to_string(std::max(d, 0))}),
             at);
    for (double x : p) points.push_back(finite(c, x, "MKPOL", at));
  }
  std::vector<bool> used(cells.size(), false);
  for (const ValuePtr& pol : pols) {
    for (double k : numbers(c, pol, "MKPOL", at)) {
      if (k != std::floor(k) || k < 1 || k > static_cast<double>(cells.size()))
        c.fail("PSM402",
               text({"'MKPOL': a polyhedral cell names convex cell ", base::shortest_number(k),
                     "; there are ", std::to_string(cells.size())}),
               at);
      used[static_cast<std::size_t>(k) - 1] = true;
    }
  }
  std::vector<Cell> out;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!used[i]) continue;
    Cell cell;
    for (double k : numbers(c, cells[i], "MKPOL", at)) {
      if (k != std::floor(k) || k < 1 || k > static_cast<double>(verts.size()))
        c.fail("PSM402",
               text({"'MKPOL': convex cell ", std::to_string(i + 1), " names vertex ",
                     base::shortest_number(k), "; there are ", std::to_string(verts.size())}),
               at);
      cell.push_back(static_cast<std::uint32_t>(k) - 1);
    }
    if (cell.empty())
      c.fail("PSM402", text({"'MKPOL': convex cell ", std::to_string(i + 1), " is empty"}), at);
    out.push_back(std::move(cell));
  }
  return polyhedron_value(c, make_leaf(std::max(d, 1), std::move(points), std::move(out)), at);
}

// ---------------------------------------------------------------- affine maps

// T, S and R take their axes, then their values, then the polyhedron (arity 3); as_affine reads
// the first two.
ValuePtr transform_fn(Context& c, const Function& self, Args a, Range at);

}  // namespace

bool as_affine(Context& c, const Function& f, Affine& out, Range at);

namespace {

ValuePtr transform_fn(Context& c, const Function& self, Args a, Range at) {
  Affine map;
  as_affine(c, self, map, at);  // self.bound holds the axes and the values
  const PolyPtr& p = polyhedron(c, a[2], self.label, at);
  return polyhedron_value(c, make_placed(p, std::move(map)), at);
}

}  // namespace

bool as_affine(Context& c, const Function& f, Affine& out, Range at) {
  if (affine_from_points(c, f, out, at)) return true;
  if (f.native != transform_fn || f.bound.size() != 2) return false;
  const std::string& who = f.label;
  const std::vector<int> ax = axes(c, f.bound[0], who, at);
  const std::vector<double> by = numbers(c, f.bound[1], who, at);
  int n = 0;
  for (int i : ax) n = std::max(n, i + 1);
  if (who == "R") {
    if (ax.size() != 2 || by.size() != 1 || ax[0] == ax[1])
      c.fail("PSM402",
             "'R' needs two different coordinate indices and one angle, as R:<1, 2>:angle", at);
    out = Affine::rotation(n, ax[0], ax[1], finite(c, by[0], who, at));
    return true;
  }
  if (ax.size() != by.size())
    c.fail("PSM402",
           text({"'", who, "' needs as many values as coordinate indices, found ",
                 std::to_string(ax.size()), " and ", std::to_string(by.size())}),
           at);
  for (double x : by) finite(c, x, who, at);
  out = who == "T" ? Affine::translation(n, ax, by) : Affine::scaling(n, ax, by);
  return true;
}

namespace {

// STRUCT:<p, f, q, ...>: polyhedra side by side; a transformation applies to everything after
// it (cumulatively), any other function to the STRUCT of everything after it.
PolyPtr structure(Context& c, const Sequence& items, std::size_t from, Range at) {
  std::vector<Polyhedron::Child> children;
  Affine current;  // empty: the identity
  for (std::size_t i = from; i < items.size(); ++i) {
    const ValuePtr& item = items[i];
    if (item->is_polyhedron()) {
      children.push_back({current, item->polyhedron()});
      continue;
    }
    if (!item->is_function())
      c.fail("PSM402",
             text({"'STRUCT' holds polyhedra and transformations, found ", kind_name(item->kind()),
                   " ", summary(*item), " at position ", std::to_string(i + 1)}),
             at);
    Affine map;
    if (as_affine(c, item->function(), map, at)) {
      current = current.m.empty() ? map : map.then(current);
      continue;
    }
    const ValuePtr rest = polyhedron_value(c, structure(c, items, i + 1, at), at);
    const ValuePtr mapped = c.apply(item, rest, at);
    children.push_back({current, polyhedron(c, mapped, "STRUCT", at)});
    break;
  }
  return make_group(std::move(children));
}

ValuePtr struct_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& items = c.seq(a[0], "STRUCT", at);
  return polyhedron_value(c, structure(c, items, 0, at), at);
}

// EMBED:n:p gives p n more coordinates, all zero.
ValuePtr embed_fn(Context& c, const Function&, Args a, Range at) {
  const auto extra = static_cast<int>(count_arg(c, a[0], kMaxDimension, "EMBED", at));
  const PolyPtr& p = polyhedron(c, a[1], "EMBED", at);
  if (p->dim + extra > kMaxDimension)
    c.fail("PSM402",
           text({"'EMBED' would give more than ", std::to_string(kMaxDimension), " coordinates"}),
           at);
  return polyhedron_value(c, make_placed(p, Affine::identity(p->dim + extra)), at);
}

// ---------------------------------------------------------------- measures and placement

enum class Measure { kSize, kMin, kMax, kMed };

template <Measure kMeasure>
ValuePtr measure_fn(Context& c, const Function& self, Args a, Range at) {
  const std::vector<int> ax = axes(c, a[0], self.label, at);
  const PolyPtr& p = polyhedron(c, a[1], self.label, at);
  const FlatComplex flat = flatten_cells(*p);
  const std::vector<double> points = used_points(flat);
  const auto d = static_cast<std::size_t>(std::max(flat.dim, 1));
  Sequence out;
  for (int axis : ax) {
    double lo = 0;
    double hi = 0;
    for (std::size_t i = 0; i < points.size(); i += d) {
      const double x = axis < flat.dim ? points[i + static_cast<std::size_t>(axis)] : 0.0;
      lo = i == 0 ? x : std::min(lo, x);
      hi = i == 0 ? x : std::max(hi, x);
    }
    double value = 0;
    switch (kMeasure) {
      case Measure::kSize:
        value = hi - lo;
        break;
      case Measure::kMin:
        value = lo;
        break;
      case Measure::kMax:
        value = hi;
        break;
      case Measure::kMed:
        value = (lo + hi) / 2;
        break;
    }
    out.push_back(make_number(value));
  }
  if (a[0]->is_number()) return out.front();
  return c.sequence(std::move(out), at);
}

// ALIGN:<<axis, f, g>, ...>:<p, q>: q translated so that g of q along axis meets f of p (f and
// g are MIN, MED, MAX or any function of axis and polyhedron); the result is STRUCT:<p, q'>.
ValuePtr align(Context& c, const Sequence& rules, const ValuePtr& pair, std::string_view who,
               Range at) {
  const Sequence& pq = c.seq_of(pair, 2, who, at);
  const PolyPtr& p = polyhedron(c, pq[0], who, at);
  const PolyPtr& q = polyhedron(c, pq[1], who, at);
  std::vector<int> ax;
  std::vector<double> by;
  for (const ValuePtr& rule : rules) {
    const Sequence& r = c.seq_of(rule, 3, who, at);
    const std::vector<int> axis = axes(c, r[0], who, at);
    if (axis.size() != 1) c.fail("PSM402", text({"'", who, "' aligns one axis per rule"}), at);
    const double from = c.number(c.apply(c.apply(r[1], r[0], at), pq[0], at), who, at);
    const double to = c.number(c.apply(c.apply(r[2], r[0], at), pq[1], at), who, at);
    ax.push_back(axis[0]);
    by.push_back(from - to);
  }
  int n = 0;
  for (int i : ax) n = std::max(n, i + 1);
  std::vector<Polyhedron::Child> children;
  children.push_back({Affine{}, p});
  children.push_back({Affine::translation(std::max(n, q->dim), ax, by), q});
  return polyhedron_value(c, make_group(std::move(children)), at);
}

ValuePtr align_fn(Context& c, const Function&, Args a, Range at) {
  return align(c, c.seq(a[0], "ALIGN", at), a[1], "ALIGN", at);
}

// TOP, BOTTOM, LEFT, RIGHT: ALIGN with fixed rules, as the PLaSM library defines them.
template <int kWhich>
ValuePtr placement_fn(Context& c, const Function& self, Args a, Range at) {
  const auto fn = [&](std::string_view name) {
    const Native* n = find_native(name);
    return c.native(std::string(n->name), n->arity, n->fn, {}, at);
  };
  const ValuePtr lo = fn("MIN");
  const ValuePtr med = fn("MED");
  const ValuePtr hi = fn("MAX");
  const auto rule = [&](int axis, const ValuePtr& f, const ValuePtr& g) {
    return c.sequence(Sequence{make_number(axis), f, g}, at);
  };
  Sequence rules;
  switch (kWhich) {
    case 0:  // TOP
      rules = {rule(3, hi, lo), rule(1, med, med), rule(2, med, med)};
      break;
    case 1:  // BOTTOM
      rules = {rule(3, lo, hi), rule(1, med, med), rule(2, med, med)};
      break;
    case 2:  // LEFT
      rules = {rule(1, lo, hi), rule(3, lo, lo)};
      break;
    default:  // RIGHT
      rules = {rule(1, hi, lo), rule(3, lo, lo)};
      break;
  }
  return align(c, rules, a[0], self.label, at);
}

const Native kGeometry[] = {
    {"ALIGN", 2, align_fn},
    {"BOTTOM", 1, placement_fn<1>},
    {"CUBOID", 1, cuboid_fn},
    {"EMBED", 2, embed_fn},
    {"INTERVALS", 2, intervals_fn},
    {"LEFT", 1, placement_fn<2>},
    {"MAX", 2, measure_fn<Measure::kMax>},
    {"MED", 2, measure_fn<Measure::kMed>},
    {"MIN", 2, measure_fn<Measure::kMin>},
    {"MKPOL", 1, mkpol_fn},
    {"Q", 1, quote_fn},
    {"QUOTE", 1, quote_fn},
    {"R", 3, transform_fn},
    {"RIGHT", 1, placement_fn<3>},
    {"S", 3, transform_fn},
    {"SIMPLEX", 1, simplex_fn},
    {"SIZE", 2, measure_fn<Measure::kSize>},
    {"STRUCT", 1, struct_fn},
    {"T", 3, transform_fn},
    {"TOP", 1, placement_fn<0>},
};

}  // namespace

std::span<const Native> geometry_natives() {
  return kGeometry;
}

}  // namespace insula::lang::plasm
