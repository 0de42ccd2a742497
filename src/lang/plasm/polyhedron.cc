#include "lang/plasm/polyhedron.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace insula::lang::plasm {

Affine Affine::identity(int n) {
  Affine a;
  a.n = n;
  a.m.assign(static_cast<std::size_t>((n + 1) * (n + 1)), 0.0);
  for (int i = 0; i <= n; ++i) a.m[static_cast<std::size_t>(i * (n + 1) + i)] = 1.0;
  return a;
}

Affine Affine::translation(int n, const std::vector<int>& axes, const std::vector<double>& by) {
  Affine a = identity(n);
  for (std::size_t k = 0; k < axes.size(); ++k)
    a.m[static_cast<std::size_t>(axes[k] * (n + 1) + n)] += by[k];
  return a;
}

Affine Affine::scaling(int n, const std::vector<int>& axes, const std::vector<double>& by) {
  Affine a = identity(n);
  for (std::size_t k = 0; k < axes.size(); ++k)
    a.m[static_cast<std::size_t>(axes[k] * (n + 1) + axes[k])] *= by[k];
  return a;
}

Affine Affine::rotation(int n, int i, int j, double angle) {
  Affine a = identity(n);
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  const auto cell = [&](int r, int col) -> double& {
    return a.m[static_cast<std::size_t>(r * (n + 1) + col)];
  };
  cell(i, i) = c;
  cell(i, j) = -s;
  cell(j, i) = s;
  cell(j, j) = c;
  return a;
}

Affine Affine::widened(int k) const {
  if (k <= n) return *this;
  Affine w = identity(k);
  for (int r = 0; r < n; ++r) {
    for (int col = 0; col < n; ++col) w.m[static_cast<std::size_t>(r * (k + 1) + col)] = at(r, col);
    w.m[static_cast<std::size_t>(r * (k + 1) + k)] = at(r, n);
  }
  return w;
}

Affine Affine::then(const Affine& after) const {
  const int k = std::max(n, after.n);
  const Affine a = widened(k);
  const Affine b = after.widened(k);
  Affine out;
  out.n = k;
  out.m.assign(static_cast<std::size_t>((k + 1) * (k + 1)), 0.0);
  for (int r = 0; r <= k; ++r) {
    for (int col = 0; col <= k; ++col) {
      double sum = 0;
      for (int t = 0; t <= k; ++t) sum += b.at(r, t) * a.at(t, col);
      out.m[static_cast<std::size_t>(r * (k + 1) + col)] = sum;
    }
  }
  return out;
}

void Affine::apply(const double* in, int in_dim, double* out) const {
  for (int r = 0; r < n; ++r) {
    double sum = at(r, n);
    for (int col = 0; col < std::min(in_dim, n); ++col) sum += at(r, col) * in[col];
    out[r] = sum;
  }
  for (int r = n; r < in_dim; ++r) out[r] = in[r];  // the identity on coordinates past n
}

int Affine::orientation() const {
  // Gaussian elimination with partial pivoting on the linear part.
  std::vector<double> a(static_cast<std::size_t>(n * n));
  for (int r = 0; r < n; ++r)
    for (int col = 0; col < n; ++col) a[static_cast<std::size_t>(r * n + col)] = at(r, col);
  bool negative = false;
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int r = col + 1; r < n; ++r) {
      if (std::abs(a[static_cast<std::size_t>(r * n + col)]) >
          std::abs(a[static_cast<std::size_t>(pivot * n + col)]))
        pivot = r;
    }
    const double p = a[static_cast<std::size_t>(pivot * n + col)];
    if (p == 0) return 0;
    if (pivot != col) {
      for (int t = 0; t < n; ++t)
        std::swap(a[static_cast<std::size_t>(pivot * n + t)],
                  a[static_cast<std::size_t>(col * n + t)]);
      negative = !negative;
    }
    if (p < 0) negative = !negative;
    for (int r = col + 1; r < n; ++r) {
      const double f = a[static_cast<std::size_t>(r * n + col)] / p;
      for (int t = col; t < n; ++t)
        a[static_cast<std::size_t>(r * n + t)] -= f * a[static_cast<std::size_t>(col * n + t)];
    }
  }
  return negative ? -1 : 1;
}

namespace {

class Flattener {
 public:
  Flattener(FlatComplex& out, bool with_groups) : out_(out), with_groups_(with_groups) {}

  void walk(const Polyhedron& node, const Affine& to_root, std::uint32_t group,
            const std::string& path) {
    std::string here = path;
    if (with_groups_ && !node.label.empty()) {
      here = path.empty() ? node.label : path + "/" + node.label;
      if (node.part || group == 0) {
        // A new instance: the innermost part label names it; unlabelled groups keep the path.
        CellGroup g{node.part ? node.label : out_.groups[group].part, here};
        out_.groups.push_back(std::move(g));
        group = static_cast<std::uint32_t>(out_.groups.size() - 1);
      }
    }
    add_leaf(node, to_root, group);
    for (const Polyhedron::Child& child : node.children) {
      Affine placed = child.transform.n == 0 && child.transform.m.empty()
                          ? to_root
                          : child.transform.then(to_root);
      // A STRUCT's T:1:x or R:<1, 2>:a has fewer coordinates than its parts: it leaves the
      // others as they are (applied narrow, it dropped them, and a box came out flat).
      if (!placed.m.empty() && placed.n < out_.dim) placed = placed.widened(out_.dim);
      walk(*child.part, placed, group, here);
    }
  }

 private:
  void add_solid(const Polyhedron& node, const Affine& to_root, std::uint32_t group) {
    kernel::Mesh mesh = *node.solid;
    if (!to_root.m.empty()) {
      std::vector<double> out(static_cast<std::size_t>(std::max(to_root.n, 3)),
                              0.0);  // apply's max
      for (kernel::Vec3& p : mesh.positions()) {
        const double in[3] = {p.x, p.y, p.z};
        to_root.apply(in, 3, out.data());
        p = {out[0], out[1], out[2]};
      }
      if (to_root.reverses_orientation()) mesh.flip();
    }
    out_.solids.push_back(std::move(mesh));
    out_.solid_group.push_back(group);
  }

  void add_leaf(const Polyhedron& node, const Affine& to_root, std::uint32_t group) {
    if (node.solid) add_solid(node, to_root, group);
    if (node.cells.empty()) return;
    const auto base = static_cast<std::uint32_t>(out_.point_count());
    const std::size_t count = node.point_count();
    const std::size_t dim = static_cast<std::size_t>(out_.dim);
    out_.points.resize(out_.points.size() + count * dim, 0.0);
    double* target = out_.points.data() + std::size_t(base) * dim;
    for (std::size_t p = 0; p < count; ++p) {
      const double* source = node.points.data() + p * static_cast<std::size_t>(node.dim);
      if (to_root.m.empty()) {
        std::copy(source, source + node.dim, target + p * dim);
      } else {
        to_root.apply(source, node.dim, target + p * dim);
      }
    }
    std::uint32_t first = 0;
    std::uint32_t mirrored = 0;
    const int orientation = to_root.m.empty() ? 1 : to_root.orientation();
    if (with_groups_) {
      const auto [it, added] = origins_.emplace(&node, out_.origins);
      if (added) out_.origins += static_cast<std::uint32_t>(node.cells.size());
      first = it->second;
      if (orientation < 0) mirrored = FlatComplex::kMirrored;
    }
    for (std::size_t k = 0; k < node.cells.size(); ++k) {
      Cell shifted(node.cells[k]);
      for (std::uint32_t& v : shifted) v += base;
      out_.cells.push_back(std::move(shifted));
      if (with_groups_) {
        out_.group.push_back(group);
        out_.origin.push_back(orientation == 0
                                  ? FlatComplex::kNoOrigin
                                  : (first + static_cast<std::uint32_t>(k)) | mirrored);
      }
    }
  }

  FlatComplex& out_;
  bool with_groups_;
  std::unordered_map<const Polyhedron*, std::uint32_t> origins_;  // first cell number per node
};

FlatComplex flatten_impl(const Polyhedron& polyhedron, bool with_groups) {
  FlatComplex out;
  out.dim = polyhedron.dim;
  if (with_groups) out.groups.push_back(CellGroup{});
  Flattener walker(out, with_groups);
  Affine root;  // empty: the identity, without arithmetic
  walker.walk(polyhedron, root, 0, "");
  return out;
}

}  // namespace

FlatComplex flatten(const Polyhedron& polyhedron) {
  return flatten_impl(polyhedron, true);
}

FlatComplex flatten_cells(const Polyhedron& polyhedron) {
  return flatten_impl(polyhedron, false);
}

namespace {

// Sets the totals of a node from its cells and children.
void count(Polyhedron& p) {
  p.total_cells = p.cells.size() + (p.solid ? 1 : 0);
  p.depth = 0;
  for (const Polyhedron::Child& child : p.children) {
    p.total_cells += child.part->total_cells;
    p.depth = std::max(p.depth, child.part->depth + 1);
  }
}

}  // namespace

PolyPtr make_leaf(int dim, std::vector<double> points, std::vector<Cell> cells) {
  auto p = std::make_shared<Polyhedron>();
  p->dim = dim;
  p->points = std::move(points);
  p->cells = std::move(cells);
  count(*p);
  return p;
}

PolyPtr make_solid(kernel::Mesh mesh) {
  auto p = std::make_shared<Polyhedron>();
  p->dim = 3;
  p->solid = std::make_shared<const kernel::Mesh>(std::move(mesh));
  count(*p);
  return p;
}

PolyPtr make_placed(const PolyPtr& part, Affine transform) {
  auto p = std::make_shared<Polyhedron>();
  p->dim = std::max(part->dim, transform.n);
  if (transform.n < p->dim) transform = transform.widened(p->dim);
  p->children.push_back({std::move(transform), part});
  count(*p);
  return p;
}

PolyPtr make_group(std::vector<Polyhedron::Child> children) {
  auto p = std::make_shared<Polyhedron>();
  for (const Polyhedron::Child& c : children)
    p->dim = std::max({p->dim, c.part->dim, c.transform.n});
  // A map of fewer coordinates (T:1:2 in a STRUCT of solids) leaves the others as they are.
  for (Polyhedron::Child& c : children)
    if (!c.transform.m.empty() && c.transform.n < p->dim) c.transform = c.transform.widened(p->dim);
  p->children = std::move(children);
  count(*p);
  return p;
}

PolyPtr make_labelled(const PolyPtr& polyhedron, std::string label, bool part) {
  auto p = std::make_shared<Polyhedron>();
  p->dim = polyhedron->dim;
  p->children.push_back({Affine{}, polyhedron});
  p->label = std::move(label);
  p->part = part;
  count(*p);
  return p;
}

std::vector<double> used_points(const FlatComplex& flat) {
  std::vector<bool> used(flat.point_count(), false);
  for (const Cell& cell : flat.cells)
    for (std::uint32_t v : cell) used[v] = true;
  std::vector<double> out;
  for (std::uint32_t v = 0; v < used.size(); ++v)
    if (used[v]) out.insert(out.end(), flat.point(v), flat.point(v) + flat.dim);
  for (const kernel::Mesh& mesh : flat.solids) {
    for (const kernel::Vec3& p : mesh.positions()) {
      const double xyz[3] = {p.x, p.y, p.z};
      out.insert(out.end(), xyz, xyz + std::min(flat.dim, 3));
      out.insert(out.end(), static_cast<std::size_t>(std::max(flat.dim - 3, 0)), 0.0);
    }
  }
  return out;
}

}  // namespace insula::lang::plasm
