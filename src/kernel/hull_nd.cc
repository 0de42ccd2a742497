#include "kernel/hull_nd.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// Gram-Schmidt with pivoting: each new axis points to the point farthest from the flat so far.
AffineFrame frame_of(std::span<const double> points, int n, double tolerance) {
  AffineFrame frame;
  frame.space_dim = n;
  if (n <= 0 || points.size() < static_cast<std::size_t>(n)) return frame;
  const std::size_t count = points.size() / n;
  frame.origin.assign(points.begin(), points.begin() + n);
  frame.dim = 0;
  std::vector<double> residual(n), best(n);
  while (frame.dim < n) {
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

// Facets (and edges of polygons) merge when they are coplanar within this fraction of the
// tolerance. Merging within the full tolerance drops real vertices of polytopes only a few
// tolerances thick (a unit 3-cube in R^4 with one corner lifted by 2e-9 came out as a simplex);
// a hundredth leaves them a hundred merging radii thick.
constexpr double kMergeFraction = 0.01;

// Qhull's options, tried in turn until the facets form a polytope's lattice (lattice()). Merged
// facets are fragile when the input's noise is close to the merging radius: Qhull then stops with
// a "wide merge" or topology error, or reports facets whose intersections form no lattice. So:
// merging within the merging radius ('C-'), within Qhull's own roundoff estimate (its default),
// then triangulated ('Qt') and finally joggled ('QJ') output, which is simplicial and succeeds.
constexpr int kQhullAttempts = 4;

std::string qhull_command(int attempt, double tolerance) {
  switch (attempt) {
    case 0: {
      char option[48];
      std::snprintf(option, sizeof option, "qhull C-%.17g", tolerance);
      return option;
    }
    case 1:
      return "qhull";
    case 2:
      return "qhull Qt";
    default:
      return "qhull QJ";
  }
}

// The facets of a full-dimensional hull of points in R^dim (dim >= 4) from Qhull, each as the set
// of positions of its vertices in the input; nullopt when Qhull reports an error. Qhull's errors
// longjmp back into qh_new_qhull itself (its setjmp), never through our frames.
std::optional<std::vector<IndexSet>> qhull_facets(std::vector<double> coords, int dim,
                                                  std::string command) {
  const auto qh_storage = std::make_unique<qhT>();
  qhT* qh = qh_storage.get();
  FILE* quiet = null_file();
  if (quiet == nullptr) return std::nullopt;
  qh_zero(qh, quiet);
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
// the merging radius of the line through its neighbours on the chain is not a corner.
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
// triangles like Qhull's 'C-' and halves polytope_nd's time on a box (docs/kernel-polytopes.md).
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
// one algorithm per dimension (the two extremes, the monotone chain, the kernel's quickhull,
// Qhull with the attempt's options). Empty on failure.
std::vector<IndexSet> facets_of(const std::vector<double>& coords, int j, double tolerance,
                                int attempt) {
  if (j == 1) {
    const auto [lo, hi] = std::minmax_element(coords.begin(), coords.end());
    const auto a = static_cast<PointIndex>(lo - coords.begin());
    const auto b = static_cast<PointIndex>(hi - coords.begin());
    if (a == b) return {};
    return {{std::min(a, b)}, {std::max(a, b)}};
  }
  if (j == 2) return polygon_edges(coords, tolerance);
  if (j == 3) return solid_faces(coords, tolerance);
  return qhull_facets(coords, j, qhull_command(attempt, tolerance))
      .value_or(std::vector<IndexSet>{});
}

// The facets of a face F are the inclusion-maximal sets F ∩ G over the polytope's facets G that
// neither hold F nor miss it: every face is the intersection of the facets holding it, so a facet
// R of F is F ∩ G for any facet G that holds R but not F. The lattice thus follows from the
// facets' vertex sets alone (Kaibel and Pfetsch, "Computing the face lattice of a polytope from
// its vertex-facet incidences", 2002, in the plain quadratic form), and stays consistent however
// the facets were merged: a geometric recursion into each facet could split a shared ridge
// differently on its two sides.
std::vector<IndexSet> sub_facets(const IndexSet& face, const std::vector<IndexSet>& facets,
                                 const std::vector<std::vector<std::uint32_t>>& facets_at) {
  std::vector<std::uint32_t> near;  // the facets that meet the face
  for (PointIndex v : face) near.insert(near.end(), facets_at[v].begin(), facets_at[v].end());
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  std::vector<IndexSet> cuts;
  IndexSet cut;
  for (std::uint32_t g : near) {
    cut.clear();
    std::set_intersection(face.begin(), face.end(), facets[g].begin(), facets[g].end(),
                          std::back_inserter(cut));
    if (cut.size() < face.size()) cuts.push_back(cut);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<IndexSet> maximal;
  for (const IndexSet& c : cuts) {
    const bool covered = std::any_of(cuts.begin(), cuts.end(), [&](const IndexSet& d) {
      return d.size() > c.size() && std::includes(d.begin(), d.end(), c.begin(), c.end());
    });
    if (!covered) maximal.push_back(c);
  }
  return maximal;
}

void sort_unique(std::vector<IndexSet>& sets) {
  std::sort(sets.begin(), sets.end());
  sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
}

// Every ridge lies in exactly two facets.
bool ridges_pair_up(std::vector<IndexSet>& ridges) {
  std::sort(ridges.begin(), ridges.end());
  for (std::size_t i = 0; i < ridges.size(); i += 2) {
    if (i + 1 >= ridges.size() || ridges[i + 1] != ridges[i]) return false;
    if (i + 2 < ridges.size() && ridges[i + 2] == ridges[i]) return false;
  }
  return true;
}

// Euler's relation with the polytope itself counted: sum of (-1)^k f_k over k = 0 ... dim is 1.
bool euler_holds(const std::vector<std::vector<IndexSet>>& faces) {
  long sum = 0;
  for (std::size_t k = 0; k < faces.size(); ++k) {
    sum += (k % 2 ? -1 : 1) * static_cast<long>(faces[k].size());
  }
  return sum == 1;
}

// The face lattice of a dim-polytope (dim >= 1) from its facets; nullopt when the facets do not
// form one (ridges not in pairs, Euler's relation broken). A point the facet algorithm kept on a
// ridge or inside a facet is in no 0-face (a point inside edge ab lies on exactly the facets that
// hold a and b), so it is dropped from every face at the end.
std::optional<std::vector<std::vector<IndexSet>>> lattice(std::vector<IndexSet> facets, int dim) {
  std::vector<std::vector<IndexSet>> faces(dim + 1);
  sort_unique(facets);
  faces[dim - 1] = facets;
  std::vector<std::vector<std::uint32_t>> facets_at;  // point -> the facets holding it
  for (std::uint32_t g = 0; g < facets.size(); ++g) {
    for (PointIndex v : facets[g]) {
      if (v >= facets_at.size()) facets_at.resize(v + 1);
      facets_at[v].push_back(g);
    }
  }
  for (int j = dim - 1; j >= 1; --j) {
    for (const IndexSet& face : faces[j]) {
      if (face.size() == static_cast<std::size_t>(j + 1)) {
        // A j-face of j + 1 points is a simplex: its facets are its j-subsets.
        for (std::size_t drop = 0; drop < face.size(); ++drop) {
          IndexSet sub = face;
          sub.erase(sub.begin() + static_cast<std::ptrdiff_t>(drop));
          faces[j - 1].push_back(std::move(sub));
        }
        continue;
      }
      for (IndexSet& sub : sub_facets(face, facets, facets_at))
        faces[j - 1].push_back(std::move(sub));
    }
    if (j == dim - 1 && dim >= 2 && !ridges_pair_up(faces[j - 1])) return std::nullopt;
    sort_unique(faces[j - 1]);
  }
  IndexSet vertices;
  for (const IndexSet& v : faces[0]) vertices.push_back(v.front());
  std::sort(vertices.begin(), vertices.end());
  for (int j = 1; j < dim; ++j) {
    for (IndexSet& face : faces[j]) {
      std::erase_if(face, [&](PointIndex i) {
        return !std::binary_search(vertices.begin(), vertices.end(), i);
      });
    }
    sort_unique(faces[j]);
  }
  faces[dim] = {std::move(vertices)};
  if (!euler_holds(faces)) return std::nullopt;
  return faces;
}

// The (j - 1)-faces inside a j-face of a lattice: those that meet it in all their vertices.
// Counting the meetings through each vertex's faces costs the sizes of those lists, not a test of
// every face.
class Containment {
 public:
  explicit Containment(const std::vector<std::vector<IndexSet>>& faces)
      : faces_(faces), faces_at_(faces.size()) {}

  std::vector<std::uint32_t> facets(int j, const IndexSet& face) {
    std::vector<std::vector<std::uint32_t>>& at = faces_at_[j - 1];
    const std::vector<IndexSet>& level = faces_[j - 1];
    if (at.empty()) {
      at.resize(faces_.back().front().back() + 1);
      for (std::uint32_t g = 0; g < level.size(); ++g) {
        for (PointIndex v : level[g]) at[v].push_back(g);
      }
    }
    meetings_.resize(std::max(meetings_.size(), level.size()));
    std::vector<std::uint32_t> inside;
    for (PointIndex v : face) {
      for (std::uint32_t g : at[v]) {
        if (++meetings_[g] == level[g].size()) inside.push_back(g);
      }
    }
    for (PointIndex v : face) {
      for (std::uint32_t g : at[v]) meetings_[g] = 0;
    }
    std::sort(inside.begin(), inside.end());
    return inside;
  }

 private:
  const std::vector<std::vector<IndexSet>>& faces_;
  std::vector<std::vector<std::vector<std::uint32_t>>> faces_at_;  // per level: vertex -> faces
  std::vector<std::uint32_t> meetings_;                            // per face of a level, zeroed
};

// The diamond property of a polytope's lattice: between a face and a face two dimensions lower
// inside it lie exactly two faces (and every edge has two vertices). Qhull's merged facets of
// noisy near-degenerate input in 6D once passed the ridge and Euler checks but not this one, and
// their pulling triangulation put a ridge into three simplices (tests/data/hull_nd/diamond_6d.txt).
bool diamonds_hold(const std::vector<std::vector<IndexSet>>& faces) {
  Containment inside(faces);
  const int dim = static_cast<int>(faces.size()) - 1;
  std::vector<std::vector<std::vector<std::uint32_t>>> children(dim + 1);
  for (int j = 1; j <= dim; ++j) {
    for (const IndexSet& face : faces[j]) children[j].push_back(inside.facets(j, face));
  }
  for (const std::vector<std::uint32_t>& edge : children[1]) {
    if (edge.size() != 2) return false;
  }
  std::vector<std::uint32_t> below;
  for (int j = 2; j <= dim; ++j) {
    for (const std::vector<std::uint32_t>& facets : children[j]) {
      below.clear();
      for (std::uint32_t f : facets) {
        below.insert(below.end(), children[j - 1][f].begin(), children[j - 1][f].end());
      }
      std::sort(below.begin(), below.end());
      for (std::size_t i = 0; i < below.size(); i += 2) {
        if (i + 1 >= below.size() || below[i + 1] != below[i]) return false;
        if (i + 2 < below.size() && below[i + 2] == below[i]) return false;
      }
    }
  }
  return true;
}

// The lattice of the full-dimensional polytope of the points `coords` (dim per point), whose
// input indices are `members`.
std::optional<std::vector<std::vector<IndexSet>>> face_lattice(const std::vector<double>& coords,
                                                               int dim, double tolerance,
                                                               const IndexSet& members) {
  const int attempts = dim >= 4 ? kQhullAttempts : 1;
  for (int attempt = 0; attempt < attempts; ++attempt) {
    std::vector<IndexSet> facets = facets_of(coords, dim, tolerance, attempt);
    if (facets.size() < static_cast<std::size_t>(dim + 1)) continue;
    for (IndexSet& facet : facets) {
      for (PointIndex& i : facet) i = members[i];  // positions -> input indices, still ascending
    }
    // The diamond check costs about as much as the lattice; below 4D no Qhull merging needs it.
    std::optional<std::vector<std::vector<IndexSet>>> faces = lattice(std::move(facets), dim);
    if (faces && (dim < 4 || diamonds_hold(*faces))) return faces;
  }
  return std::nullopt;
}

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

// The default tolerance grows with the coordinates' size as well as the extent: rounding a
// coordinate of size M moves it by up to about 1e-16 M, so a rotated unit cube at UTM northings
// (5e6) has facets bent by 2e-10, and the merging radius (a hundredth of the tolerance) must stay
// above that.
double resolve_tolerance(std::span<const double> points, int n, double tolerance) {
  if (tolerance > 0) return tolerance;
  double largest = 0;
  for (double x : points) largest = std::max(largest, std::abs(x));
  return 1e-9 * extent(points, n) + 1e-12 * largest;
}

// The pulling triangulation of every face reached, memoised per face.
class Puller {
 public:
  Puller(const PolytopeNd& polytope, std::span<const std::uint64_t> order)
      : p_(polytope), order_(order), inside_(polytope.faces) {
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
      for (std::uint32_t g : inside_.facets(j, face)) {
        const IndexSet& facet = p_.faces[j - 1][g];
        if (std::binary_search(facet.begin(), facet.end(), apex)) continue;
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
  Containment inside_;
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
  return frame_of(points, n, resolve_tolerance(points, n, tolerance));
}

PolytopeNd polytope_nd(std::span<const double> points, int n, double tolerance) {
  PolytopeNd result;
  result.status = validate(points, n);
  if (!result.ok()) return result;
  const double tol = resolve_tolerance(points, n, tolerance);
  const AffineFrame frame = frame_of(points, n, tol);
  const std::vector<double> local = local_points(frame, points);
  const IndexSet members = representatives(local, frame.dim, points.size() / n, tol);
  std::vector<double> coords;
  for (PointIndex i : members) {
    coords.insert(coords.end(), local.begin() + i * frame.dim, local.begin() + (i + 1) * frame.dim);
  }
  result.dim = frame.dim;
  if (frame.dim == 0) {
    result.faces = {{members}};
    return result;
  }
  std::optional<std::vector<std::vector<IndexSet>>> faces =
      face_lattice(coords, frame.dim, tol * kMergeFraction, members);
  if (!faces) {
    result.status = HullNdStatus::kFailed;
    result.dim = -1;
    return result;
  }
  result.faces = std::move(*faces);
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
