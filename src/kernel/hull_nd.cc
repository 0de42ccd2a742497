#include "kernel/hull_nd.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <string>

#include "base/union_find.h"
#include "kernel/convex_hull.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace insula::kernel {

namespace {

// The extent the default tolerance scales with: the diagonal of the points' bounding box.
double extent(std::span<const double> points, int n) {
  double sum = 0;
  for (int c = 0; c < n; ++c) {
    double lo = points[c], hi = points[c];
    for (std::size_t i = c; i < points.size(); i += n) {
      lo = std::min(lo, points[i]);
      hi = std::max(hi, points[i]);
    }
    sum += (hi - lo) * (hi - lo);
  }
  return std::sqrt(sum);
}

double dot(const double* a, const double* b, int n) {
  double sum = 0;
  for (int c = 0; c < n; ++c) sum += a[c] * b[c];
  return sum;
}

// The part of `v` orthogonal to the frame's basis so far. Two passes of Gram-Schmidt keep the
// residual orthogonal to working precision ("twice is enough", Giraud et al. 2005).
void remove_span(const AffineFrame& frame, std::vector<double>& v) {
  const int n = frame.space_dim;
  for (int pass = 0; pass < 2; ++pass) {
    for (int b = 0; b < frame.dim; ++b) {
      const double* axis = frame.basis.data() + static_cast<std::size_t>(b) * n;
      const double d = dot(v.data(), axis, n);
      for (int c = 0; c < n; ++c) v[c] -= d * axis[c];
    }
  }
}

// The affine frame with at most `max_dim` axes: a facet's vertices span one dimension less than
// its polytope even when Qhull merged facets that bend by up to the tolerance.
AffineFrame frame_upto(std::span<const double> points, int n, double tolerance, int max_dim) {
  AffineFrame frame;
  frame.space_dim = n;
  if (n <= 0 || points.size() < static_cast<std::size_t>(n)) return frame;
  const std::size_t count = points.size() / n;
  frame.origin.assign(points.begin(), points.begin() + n);
  frame.dim = 0;
  std::vector<double> residual(n), best(n);
  while (frame.dim < max_dim) {
    double best_distance = tolerance;
    bool found = false;
    for (std::size_t i = 1; i < count; ++i) {
      for (int c = 0; c < n; ++c) residual[c] = points[i * n + c] - frame.origin[c];
      remove_span(frame, residual);
      const double distance = std::sqrt(dot(residual.data(), residual.data(), n));
      if (distance > best_distance) {
        best_distance = distance;
        best = residual;
        found = true;
      }
    }
    if (!found) break;
    remove_span(frame, best);
    const double length = std::sqrt(dot(best.data(), best.data(), n));
    for (double& x : best) frame.basis.push_back(x / length);
    ++frame.dim;
  }
  return frame;
}

// The points' coordinates in the frame, frame.dim per point.
void project(const AffineFrame& frame, const double* point, double* out) {
  const int n = frame.space_dim;
  for (int b = 0; b < frame.dim; ++b) {
    const double* axis = frame.basis.data() + static_cast<std::size_t>(b) * n;
    double sum = 0;
    for (int c = 0; c < n; ++c) sum += (point[c] - frame.origin[c]) * axis[c];
    out[b] = sum;
  }
}

std::vector<double> local_points(const AffineFrame& frame, std::span<const double> points) {
  const std::size_t n = frame.space_dim, count = points.size() / n;
  std::vector<double> local(count * frame.dim);
  for (std::size_t i = 0; i < count; ++i)
    project(frame, points.data() + i * n, local.data() + i * frame.dim);
  return local;
}

// A file that swallows what Qhull writes: its traces and warnings must not reach our stdout or
// stderr, and a cookie file needs neither a descriptor nor /dev/null.
FILE* null_file() {
  static FILE* const file = [] {
    cookie_io_functions_t discard{};
    discard.write = [](void*, const char*, size_t size) { return static_cast<ssize_t>(size); };
    return fopencookie(nullptr, "w", discard);
  }();
  return file;
}

// The facets of a full-dimensional hull of `count` points in R^dim (dim >= 3) from Qhull, each as
// the set of positions of its vertices in the input; nullopt when Qhull reports an error. Qhull's
// errors longjmp back into qh_new_qhull itself (its setjmp), never through our frames. Facets
// whose centrums lie within the tolerance of a neighbour's hyperplane are merged ('C-'), so a
// cube has square facets.
std::optional<std::vector<IndexSet>> qhull_facets(std::vector<double> coords, int dim,
                                                  double tolerance) {
  const auto qh_storage = std::make_unique<qhT>();
  qhT* qh = qh_storage.get();
  FILE* quiet = null_file();
  if (quiet == nullptr) return std::nullopt;
  qh_zero(qh, quiet);
  std::string command = "qhull";
  if (tolerance > 0) {
    char option[48];
    std::snprintf(option, sizeof option, " C-%.17g", tolerance);
    command += option;
  }
  const int count = static_cast<int>(coords.size() / dim);
  const int exit_code =
      qh_new_qhull(qh, dim, count, coords.data(), False, command.data(), nullptr, quiet);
  std::optional<std::vector<IndexSet>> facets;
  if (exit_code == qh_ERRnone) {
    facets.emplace();
    facetT* facet;
    FORALLfacets {
      IndexSet set;
      vertexT *vertex, **vertexp;
      FOREACHvertex_(facet->vertices)
          set.push_back(static_cast<PointIndex>(qh_pointid(qh, vertex->point)));
      std::sort(set.begin(), set.end());
      facets->push_back(std::move(set));
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int current_long = 0, total_long = 0;
  qh_memfreeshort(qh, &current_long, &total_long);
  return facets;
}

double cross(const double* o, const double* a, const double* b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// The edges of a convex polygon (Andrew's monotone chain), as pairs of positions. A point within
// the tolerance of the line through its neighbours on the chain is not a corner.
std::vector<IndexSet> polygon_edges(const std::vector<double>& coords, double tolerance) {
  const std::size_t count = coords.size() / 2;
  std::vector<PointIndex> order(count);
  std::iota(order.begin(), order.end(), PointIndex{0});
  const auto at = [&](PointIndex i) { return coords.data() + 2 * i; };
  std::sort(order.begin(), order.end(), [&](PointIndex a, PointIndex b) {
    return std::make_tuple(at(a)[0], at(a)[1], a) < std::make_tuple(at(b)[0], at(b)[1], b);
  });
  std::vector<PointIndex> hull(2 * count);
  std::size_t size = 0;
  const auto push = [&](PointIndex i, std::size_t floor) {
    while (size >= floor + 2) {
      const double* o = at(hull[size - 2]);
      const double* b = at(i);
      const double chord = std::hypot(b[0] - o[0], b[1] - o[1]);
      if (cross(o, at(hull[size - 1]), b) > tolerance * chord) break;
      --size;
    }
    hull[size++] = i;
  };
  for (PointIndex i : order) push(i, 0);
  const std::size_t lower = size - 1;
  for (std::size_t k = count - 1; k-- > 0;) push(order[k], lower);
  std::vector<IndexSet> edges;
  if (size < 4) return edges;  // fewer than three corners: flat within the tolerance
  for (std::size_t k = 0; k + 1 < size; ++k) {
    edges.push_back({std::min(hull[k], hull[k + 1]), std::max(hull[k], hull[k + 1])});
  }
  return edges;
}

// The faces of a solid from the kernel's own quickhull (convex_hull.h), which merges coplanar
// triangles like Qhull's 'C-' but costs a tenth of a Qhull run on a box (docs/kernel-polytopes.md).
// Its mesh keeps the input positions exactly, so a sorted look-up names them by position again.
std::vector<IndexSet> solid_faces(const std::vector<double>& coords, double tolerance) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i + 3 <= coords.size(); i += 3)
    points.push_back({coords[i], coords[i + 1], coords[i + 2]});
  HullOptions options;
  options.tolerance = tolerance;
  const Hull3Result hull = convex_hull_3d(points, options);
  if (!hull.ok()) return {};
  const auto key = [](Vec3 p) { return std::make_tuple(p.x, p.y, p.z); };
  std::vector<PointIndex> sorted(points.size());
  std::iota(sorted.begin(), sorted.end(), PointIndex{0});
  std::sort(sorted.begin(), sorted.end(),
            [&](PointIndex a, PointIndex b) { return key(points[a]) < key(points[b]); });
  std::vector<PointIndex> input(hull.mesh.vertex_count());
  for (std::uint32_t v = 0; v < input.size(); ++v) {
    const Vec3 p = hull.mesh.position(v);
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), p,
                                     [&](PointIndex a, Vec3 q) { return key(points[a]) < key(q); });
    if (it == sorted.end() || key(points[*it]) != key(p)) return {};
    input[v] = *it;
  }
  std::vector<IndexSet> faces;
  for (std::size_t f = 0; f < hull.mesh.face_count(); ++f) {
    IndexSet face;
    for (std::uint32_t v : hull.mesh.face(f)) face.push_back(input[v]);
    std::sort(face.begin(), face.end());
    faces.push_back(std::move(face));
  }
  return faces;
}

// The facets of a j-dimensional polytope given by `coords` (j per point), as sets of positions:
// one algorithm per dimension (the two extremes, the monotone chain, Qhull). Empty on failure.
std::vector<IndexSet> facets_of(const std::vector<double>& coords, int j, double tolerance) {
  if (j == 1) {
    const auto [lo, hi] = std::minmax_element(coords.begin(), coords.end());
    const auto a = static_cast<PointIndex>(lo - coords.begin());
    const auto b = static_cast<PointIndex>(hi - coords.begin());
    if (a == b) return {};
    return {{std::min(a, b)}, {std::max(a, b)}};
  }
  if (j == 2) return polygon_edges(coords, tolerance);
  if (j == 3) return solid_faces(coords, tolerance);
  return qhull_facets(coords, j, tolerance).value_or(std::vector<IndexSet>{});
}

// Builds the face lattice top-down. A face arrives as a candidate set of points (a facet as
// Qhull or the chain reports it, which may hold points in its relative interior or on its
// boundary); its true vertices are the union of its facets' true vertices, so only corners
// reach the lattice. Candidates are memoised per dimension, so a face shared by several facets is
// decomposed once.
class LatticeBuilder {
 public:
  LatticeBuilder(int dim, double tolerance)
      : tolerance_(tolerance), memo_(dim + 1), faces_(dim + 1) {}

  // The true vertex set of the j-face whose candidate points are `members` (sorted), with
  // coordinates `coords` (j per member) in a frame of the face; nullopt when a step failed.
  std::optional<IndexSet> face(const IndexSet& members, const std::vector<double>& coords, int j) {
    if (members.size() == static_cast<std::size_t>(j + 1)) return simplex(members);
    const std::vector<IndexSet> facets = facets_of(coords, j, tolerance_);
    if (facets.size() < static_cast<std::size_t>(j + 1)) return std::nullopt;
    IndexSet vertices;
    for (const IndexSet& positions : facets) {
      const std::optional<IndexSet> facet = sub_face(members, coords, j, positions);
      if (!facet) return std::nullopt;
      vertices.insert(vertices.end(), facet->begin(), facet->end());
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    faces_[j].push_back(vertices);
    return vertices;
  }

  // Every face once, each dimension's faces in lexicographic order.
  std::vector<std::vector<IndexSet>> faces() && {
    for (std::vector<IndexSet>& level : faces_) {
      std::sort(level.begin(), level.end());
      level.erase(std::unique(level.begin(), level.end()), level.end());
    }
    return std::move(faces_);
  }

 private:
  // A face of j + 1 points spanning j dimensions is a simplex: every subset of its points is a
  // face, so its lattice needs no geometry (most facets of hulls of scattered points).
  IndexSet simplex(const IndexSet& members) {
    const std::size_t count = members.size();
    for (std::uint32_t mask = 1; mask < (1U << count); ++mask) {
      IndexSet subset;
      for (std::size_t b = 0; b < count; ++b) {
        if (mask & (1U << b)) subset.push_back(members[b]);
      }
      faces_[subset.size() - 1].push_back(std::move(subset));
    }
    return members;
  }

  std::optional<IndexSet> sub_face(const IndexSet& members, const std::vector<double>& coords,
                                   int j, const IndexSet& positions) {
    IndexSet sub;
    for (PointIndex p : positions) sub.push_back(members[p]);
    if (sub.size() == static_cast<std::size_t>(j)) return simplex(sub);
    if (const auto it = memo_[j - 1].find(sub); it != memo_[j - 1].end()) return it->second;
    std::vector<double> sub_coords;
    for (PointIndex p : positions) {
      sub_coords.insert(sub_coords.end(), coords.begin() + p * j, coords.begin() + (p + 1) * j);
    }
    const AffineFrame frame = frame_upto(sub_coords, j, tolerance_, j - 1);
    if (frame.dim != j - 1) return std::nullopt;
    std::optional<IndexSet> vertices = face(sub, local_points(frame, sub_coords), j - 1);
    if (vertices) memo_[j - 1].emplace(std::move(sub), *vertices);
    return vertices;
  }

  double tolerance_;
  // Per dimension: candidate points -> true vertices, for the faces that are not simplices.
  std::vector<std::map<IndexSet, IndexSet>> memo_;
  std::vector<std::vector<IndexSet>> faces_;  // per dimension, with repeats until faces()
};

// The points that stand for themselves: of points within the tolerance of each other (in the
// frame, so distances across the flat do not count), the lowest index. Sorted.
IndexSet representatives(const std::vector<double>& local, int dim, std::size_t count,
                         double tolerance) {
  IndexSet all(count);
  std::iota(all.begin(), all.end(), PointIndex{0});
  if (dim == 0) return {0};
  const auto at = [&](PointIndex i) { return local.data() + static_cast<std::size_t>(i) * dim; };
  IndexSet by_x = all;
  std::sort(by_x.begin(), by_x.end(),
            [&](PointIndex a, PointIndex b) { return at(a)[0] < at(b)[0]; });
  base::UnionFind groups(count);
  for (std::size_t s = 0; s < count; ++s) {
    for (std::size_t t = s + 1; t < count && at(by_x[t])[0] - at(by_x[s])[0] <= tolerance; ++t) {
      double sum = 0;
      for (int c = 0; c < dim; ++c)
        sum += (at(by_x[t])[c] - at(by_x[s])[c]) * (at(by_x[t])[c] - at(by_x[s])[c]);
      if (std::sqrt(sum) <= tolerance) groups.unite(by_x[s], by_x[t]);
    }
  }
  std::vector<PointIndex> lowest(count, static_cast<PointIndex>(count));
  for (PointIndex i : all) lowest[groups.find(i)] = std::min(lowest[groups.find(i)], i);
  IndexSet result;
  for (PointIndex i : all) {
    if (lowest[groups.find(i)] == i) result.push_back(i);
  }
  return result;
}

HullNdStatus validate(std::span<const double> points, int n) {
  if (n <= 0 || points.empty()) return HullNdStatus::kEmpty;
  if (points.size() % static_cast<std::size_t>(n) != 0) return HullNdStatus::kFailed;
  for (double x : points) {
    if (!std::isfinite(x)) return HullNdStatus::kNonFinite;
  }
  return HullNdStatus::kOk;
}

double resolve_tolerance(std::span<const double> points, int n, double tolerance) {
  return tolerance > 0 ? tolerance : 1e-9 * extent(points, n);
}

// The pulling triangulation of every face reached, memoised per face.
class Puller {
 public:
  Puller(const PolytopeNd& polytope, std::span<const std::uint64_t> order)
      : p_(polytope), order_(order) {
    for (const auto& level : p_.faces) memo_.emplace_back(level.size());
  }

  const std::vector<IndexSet>& simplices(int j, std::size_t f) {
    std::optional<std::vector<IndexSet>>& memo = memo_[j][f];
    if (memo) return *memo;
    const IndexSet& face = p_.faces[j][f];
    std::vector<IndexSet> out;
    if (j == 0) {
      out.push_back(face);
    } else {
      const PointIndex apex =
          *std::min_element(face.begin(), face.end(), [&](PointIndex a, PointIndex b) {
            return std::make_pair(key(a), a) < std::make_pair(key(b), b);
          });
      for (std::size_t g = 0; g < p_.faces[j - 1].size(); ++g) {
        const IndexSet& facet = p_.faces[j - 1][g];
        if (std::binary_search(facet.begin(), facet.end(), apex)) continue;
        if (!std::includes(face.begin(), face.end(), facet.begin(), facet.end())) continue;
        for (IndexSet s : simplices(j - 1, g)) {
          s.insert(std::upper_bound(s.begin(), s.end(), apex), apex);
          out.push_back(std::move(s));
        }
      }
    }
    memo = std::move(out);
    return *memo;
  }

 private:
  std::uint64_t key(PointIndex i) const { return order_.empty() ? i : order_[i]; }

  const PolytopeNd& p_;
  std::span<const std::uint64_t> order_;
  std::vector<std::vector<std::optional<std::vector<IndexSet>>>> memo_;
};

}  // namespace

std::string_view hull_nd_status_message(HullNdStatus status) {
  switch (status) {
    case HullNdStatus::kOk:
      return "ok";
    case HullNdStatus::kEmpty:
      return "no points";
    case HullNdStatus::kNonFinite:
      return "a coordinate is not a finite number";
    case HullNdStatus::kFailed:
      return "the convex hull could not be computed";
  }
  return "unknown status";
}

std::vector<double> AffineFrame::local(std::span<const double> point) const {
  std::vector<double> out(std::max(dim, 0));
  project(*this, point.data(), out.data());
  return out;
}

AffineFrame affine_frame(std::span<const double> points, int n, double tolerance) {
  if (validate(points, n) != HullNdStatus::kOk) {
    AffineFrame none;
    none.space_dim = n;
    return none;
  }
  return frame_upto(points, n, resolve_tolerance(points, n, tolerance), n);
}

PolytopeNd polytope_nd(std::span<const double> points, int n, double tolerance) {
  PolytopeNd result;
  result.status = validate(points, n);
  if (!result.ok()) return result;
  const double tol = resolve_tolerance(points, n, tolerance);
  const AffineFrame frame = frame_upto(points, n, tol, n);
  const std::vector<double> local = local_points(frame, points);
  const IndexSet members = representatives(local, frame.dim, points.size() / n, tol);
  std::vector<double> coords;
  for (PointIndex i : members) {
    coords.insert(coords.end(), local.begin() + i * frame.dim, local.begin() + (i + 1) * frame.dim);
  }
  LatticeBuilder builder(frame.dim, tol);
  if (!builder.face(members, coords, frame.dim)) {
    result.status = HullNdStatus::kFailed;
    return result;
  }
  result.dim = frame.dim;
  result.faces = std::move(builder).faces();
  return result;
}

std::vector<IndexSet> simplices_nd(const PolytopeNd& polytope,
                                   std::span<const std::uint64_t> order) {
  if (!polytope.ok() || polytope.faces.empty()) return {};
  if (!order.empty()) {
    for (PointIndex v : polytope.vertices()) {
      if (v >= order.size()) return {};
    }
  }
  Puller puller(polytope, order);
  return puller.simplices(polytope.dim, 0);
}

}  // namespace insula::kernel
