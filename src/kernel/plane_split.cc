#include "kernel/plane_split.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "kernel/extrude.h"
#include "kernel/polygon.h"

namespace insula::kernel {

namespace {

constexpr int kNegative = 0;
constexpr int kPositive = 1;

std::uint64_t edge_key(std::uint32_t from, std::uint32_t to) {
  return (static_cast<std::uint64_t>(from) << 32) | to;
}

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A unit vector perpendicular to the unit vector `n`.
Vec3 any_perpendicular(Vec3 n) {
  const Vec3 helper = std::abs(n.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return normalized(cross(n, helper));
}

// Newell vector area (twice the area vector) of a loop of global vertex ids.
Vec3 loop_area_vector(const std::vector<Vec3>& points, std::span<const std::uint32_t> loop) {
  Vec3 n;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = points[loop[i]];
    const Vec3 b = points[loop[(i + 1) % loop.size()]];
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

// Splits a closed walk that may visit a vertex twice (a weakly simple polygon: two lobes touching
// at a point, or a hole touching its outer ring) into simple loops.
std::vector<std::vector<std::uint32_t>> split_at_repeats(const std::vector<std::uint32_t>& walk) {
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<std::uint32_t> sorted = walk;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) {
    if (walk.size() >= 3) loops.push_back(walk);
    return loops;  // the common case: already simple
  }
  std::vector<std::uint32_t> stack;
  std::unordered_map<std::uint32_t, std::size_t> position;
  for (std::uint32_t v : walk) {
    auto it = position.find(v);
    if (it == position.end()) {
      position[v] = stack.size();
      stack.push_back(v);
      continue;
    }
    std::vector<std::uint32_t> lobe(stack.begin() + static_cast<std::ptrdiff_t>(it->second),
                                    stack.end());
    for (std::size_t i = 1; i < lobe.size(); ++i) position.erase(lobe[i]);
    stack.resize(it->second + 1);
    if (lobe.size() >= 3) loops.push_back(std::move(lobe));
  }
  if (stack.size() >= 3) loops.push_back(std::move(stack));
  return loops;
}

// One vertex of a face loop after cut points were inserted: its global id, its side of the plane
// (-1, 0, +1) and, on the plane, its coordinate along the face's cut line.
struct LoopVertex {
  std::uint32_t id = 0;
  int side = 0;
  double t = 0;
};

// A maximal run of face-boundary edges on one side; it starts and ends on the cut line.
struct Chain {
  std::size_t first = 0;  // index in the face loop of its start vertex
  std::size_t count = 0;  // number of vertices (edges + 1)
  double t_start = 0;
  double t_end = 0;
  std::size_t next = 0;  // chain reached by following the cut line from this chain's end
};

class Splitter {
 public:
  Splitter(const Mesh& mesh, Vec3 normal, double offset, const SplitOptions& options)
      : mesh_(mesh), normal_(normal), offset_(offset), options_(options) {
    points_ = mesh.positions();
    side_.resize(points_.size());
    for (std::size_t v = 0; v < points_.size(); ++v) {
      const double s = dot(normal_, points_[v]) - offset_;
      side_[v] = s > options_.tolerance ? 1 : (s < -options_.tolerance ? -1 : 0);
      distance_.push_back(s);
    }
  }

  SplitResult run();

 private:
  void split_face(std::size_t face);
  std::uint32_t cut_point(std::uint32_t a, std::uint32_t b);
  void emit_side(const std::vector<LoopVertex>& loop, int sigma, Vec3 face_normal, FaceTag tag);
  std::vector<Chain> chains(const std::vector<LoopVertex>& loop, int sigma) const;
  void add_piece(int part, std::span<const std::uint32_t> loop, FaceTag tag) {
    parts_[part].add_face(loop, tag);
  }
  SplitStatus cap(int part, std::size_t& loop_count);
  Mesh compact(const Mesh& part) const;

  const Mesh& mesh_;
  Vec3 normal_;
  double offset_;
  SplitOptions options_;
  std::vector<Vec3> points_;
  std::vector<double> distance_;
  std::vector<int> side_;
  std::unordered_map<std::uint64_t, std::uint32_t> cuts_;
  Mesh parts_[2];  // faces over the global vertex ids in points_ (positions filled at the end)
};

std::uint32_t Splitter::cut_point(std::uint32_t a, std::uint32_t b) {
  // Keyed and computed from the lower id so both faces around the edge get the same vertex.
  if (a > b) std::swap(a, b);
  auto [it, inserted] = cuts_.try_emplace(edge_key(a, b), 0);
  if (!inserted) return it->second;
  const double sa = distance_[a];
  const double sb = distance_[b];
  const Vec3 p = points_[a] + (points_[b] - points_[a]) * (sa / (sa - sb));
  it->second = static_cast<std::uint32_t>(points_.size());
  points_.push_back(p);
  distance_.push_back(0);
  side_.push_back(0);
  return it->second;
}

void Splitter::split_face(std::size_t face) {
  const auto loop = mesh_.face(face);
  if (loop.size() < 3) return;
  bool negative = false;
  bool positive = false;
  for (std::uint32_t v : loop) {
    negative |= side_[v] < 0;
    positive |= side_[v] > 0;
  }
  if (negative != positive) {
    add_piece(positive ? kPositive : kNegative, loop, mesh_.tag(face));
    return;
  }
  const Vec3 face_normal = kernel::face_normal(mesh_, face);
  if (!negative) {
    // In the plane: it bounds the part it faces away from.
    if (face_normal == Vec3{}) return;
    add_piece(dot(face_normal, normal_) > 0 ? kNegative : kPositive, loop, mesh_.tag(face));
    return;
  }
  // Direction of the cut line: walking along +d, the face lies on the left of the line on the
  // negative side (left of d is face_normal x d = -normal_ + (face_normal . normal_) face_normal).
  Vec3 d = normalized(cross(face_normal, normal_));
  if (d == Vec3{}) d = any_perpendicular(normal_);
  std::vector<LoopVertex> ring;
  ring.reserve(loop.size() + 4);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::uint32_t a = loop[i];
    const std::uint32_t b = loop[(i + 1) % loop.size()];
    ring.push_back({a, side_[a], dot(points_[a], d)});
    if (side_[a] * side_[b] < 0) {
      const std::uint32_t c = cut_point(a, b);
      ring.push_back({c, 0, dot(points_[c], d)});
    }
  }
  emit_side(ring, -1, face_normal, mesh_.tag(face));
  emit_side(ring, 1, face_normal, mesh_.tag(face));
}

std::vector<Chain> Splitter::chains(const std::vector<LoopVertex>& loop, int sigma) const {
  const std::size_t m = loop.size();
  // Edge i (loop[i] -> loop[i+1]) bounds the sigma side when it has a vertex there, or when it
  // runs along the cut line with the face on that side (direction +d means the negative side).
  std::vector<char> on(m);
  for (std::size_t i = 0; i < m; ++i) {
    const LoopVertex& a = loop[i];
    const LoopVertex& b = loop[(i + 1) % m];
    if (a.side == sigma || b.side == sigma) {
      on[i] = 1;
    } else if (a.side == 0 && b.side == 0) {
      on[i] = sigma < 0 ? b.t > a.t : b.t < a.t;
    }
  }
  std::size_t first = 0;
  while (first < m && on[first]) ++first;
  std::vector<Chain> result;
  if (first == m) return result;
  bool open = false;
  for (std::size_t k = 1; k <= m; ++k) {
    const std::size_t i = (first + k) % m;
    if (!on[i]) {
      open = false;
      continue;
    }
    if (!open) {
      result.push_back({i, 1, loop[i].t, 0, 0});
      open = true;
    }
    ++result.back().count;
    result.back().t_end = loop[(i + 1) % m].t;
  }
  return result;
}

void Splitter::emit_side(const std::vector<LoopVertex>& loop, int sigma, Vec3 face_normal,
                         FaceTag tag) {
  std::vector<Chain> runs = chains(loop, sigma);
  if (runs.empty()) return;
  // Each run's end is joined to the nearest run start ahead along the cut line: ahead is +d on
  // the negative side and -d on the positive side (the side's region stays on the left).
  const double tol = options_.tolerance;
  std::vector<char> taken(runs.size(), 0);
  for (Chain& run : runs) {
    std::size_t best = runs.size();
    double best_gap = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < runs.size(); ++j) {
      if (taken[j]) continue;
      const double gap = (runs[j].t_start - run.t_end) * (sigma < 0 ? 1 : -1);
      const double score = gap >= -tol ? gap : 1e300 - gap;  // behind: only as a last resort
      if (score < best_gap) {
        best_gap = score;
        best = j;
      }
    }
    run.next = best;
    taken[best] = 1;
  }
  // Cut-line vertices of this face that a chord passes through are inserted into it, so the
  // pieces never leave a T-junction and a pinched piece splits into its lobes.
  std::vector<LoopVertex> on_line;
  for (const LoopVertex& v : loop) {
    if (v.side == 0) on_line.push_back(v);
  }
  std::sort(on_line.begin(), on_line.end(), [&](const LoopVertex& a, const LoopVertex& b) {
    return sigma < 0 ? a.t < b.t : a.t > b.t;
  });
  std::vector<char> visited(runs.size(), 0);
  for (std::size_t start = 0; start < runs.size(); ++start) {
    if (visited[start]) continue;
    std::vector<std::uint32_t> walk;
    for (std::size_t k = start; !visited[k]; k = runs[k].next) {
      visited[k] = 1;
      for (std::size_t j = 0; j < runs[k].count; ++j) {
        walk.push_back(loop[(runs[k].first + j) % loop.size()].id);
      }
      const double lo = std::min(runs[k].t_end, runs[runs[k].next].t_start) + tol;
      const double hi = std::max(runs[k].t_end, runs[runs[k].next].t_start) - tol;
      for (const LoopVertex& v : on_line) {
        if (v.t > lo && v.t < hi) walk.push_back(v.id);
      }
    }
    for (const auto& piece : split_at_repeats(walk)) {
      // Lobes walked against the face's orientation are zero-area slivers of the walk.
      if (dot(loop_area_vector(points_, piece), face_normal) <= 0) continue;
      add_piece(sigma < 0 ? kNegative : kPositive, piece, tag);
    }
  }
}

// 2D coordinates in the cut plane, right-handed seen from the cap's outward normal, so outer cap
// loops run counter-clockwise and holes clockwise.
struct CapFrame {
  Vec3 u;
  Vec3 v;
  Vec2 operator()(Vec3 p) const { return {dot(p, u), dot(p, v)}; }
};

struct CapLoop {
  std::vector<std::uint32_t> ids;
  Ring ring;
  double area = 0;
  std::vector<std::size_t> holes;
};

// Clockwise angle in (0, 2 pi] from `from` to `to`: the smallest is the sharpest left turn.
double clockwise_angle(Vec2 from, Vec2 to) {
  double angle = std::atan2(cross(to, from), dot(from, to));
  if (angle <= 0) angle += 2 * M_PI;
  return angle;
}

// True when some vertex of `hole` lies strictly inside `outer` (vertices on its boundary, where a
// hole touches its outer ring, do not decide).
bool encloses(const Ring& outer, const Ring& hole, double tolerance) {
  const Polygon region{outer, {}};
  for (Vec2 p : hole) {
    const PointLocation where = locate(region, p, tolerance);
    if (where != PointLocation::kBoundary) return where == PointLocation::kInside;
  }
  return false;
}

// Gives each clockwise loop to the smallest counter-clockwise loop around it; holes with no
// enclosing loop are dropped (they cannot bound a solid's cross-section).
void nest(std::vector<CapLoop>& loops, double tolerance) {
  for (std::size_t h = 0; h < loops.size(); ++h) {
    if (loops[h].area >= 0) continue;
    std::size_t best = loops.size();
    for (std::size_t o = 0; o < loops.size(); ++o) {
      if (loops[o].area <= 0 || !encloses(loops[o].ring, loops[h].ring, tolerance)) continue;
      if (best == loops.size() || loops[o].area < loops[best].area) best = o;
    }
    if (best < loops.size()) loops[best].holes.push_back(h);
  }
}

// Walks the reversed open boundary edges of a part (all in the plane) into closed loops, turning
// sharply left where several continue, so loops that touch at a vertex come out separately.
bool trace_cap_loops(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
                     const std::vector<Vec2>& flat,
                     std::vector<std::vector<std::uint32_t>>& walks) {
  std::unordered_map<std::uint32_t, std::vector<std::size_t>> outgoing;
  for (std::size_t i = 0; i < edges.size(); ++i) outgoing[edges[i].first].push_back(i);
  std::vector<char> used(edges.size(), 0);
  bool all_closed = true;
  for (std::size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    used[first] = 1;
    std::vector<std::uint32_t> walk{edges[first].first};
    std::size_t current = first;
    bool closed = false;
    while (true) {
      const auto [from, to] = edges[current];
      if (to == edges[first].first) {
        closed = true;
        break;
      }
      std::size_t next = edges.size();
      double best = 0;
      const std::vector<std::size_t>& choices = outgoing[to];
      for (std::size_t candidate : choices) {
        if (used[candidate]) continue;
        if (choices.size() == 1) {
          next = candidate;  // no junction: no angle needed
          break;
        }
        const double turn =
            clockwise_angle(flat[from] - flat[to], flat[edges[candidate].second] - flat[to]);
        if (next == edges.size() || turn < best) {
          next = candidate;
          best = turn;
        }
      }
      if (next == edges.size()) break;
      walk.push_back(to);
      used[next] = 1;
      current = next;
    }
    if (closed) {
      walks.push_back(std::move(walk));
    } else {
      all_closed = false;
    }
  }
  return all_closed;
}

SplitStatus Splitter::cap(int part, std::size_t& loop_count) {
  Mesh& faces = parts_[part];
  // Directed edges in the plane; those without a twin are the part's open boundary.
  std::unordered_map<std::uint64_t, int> in_plane;
  for (std::size_t f = 0; f < faces.face_count(); ++f) {
    const auto loop = faces.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = loop[i];
      const std::uint32_t b = loop[(i + 1) % loop.size()];
      if (side_[a] == 0 && side_[b] == 0) ++in_plane[edge_key(a, b)];
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::size_t f = 0; f < faces.face_count(); ++f) {
    const auto loop = faces.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = loop[i];
      const std::uint32_t b = loop[(i + 1) % loop.size()];
      if (side_[a] != 0 || side_[b] != 0 || in_plane.contains(edge_key(b, a))) continue;
      edges.emplace_back(b, a);
    }
  }
  if (edges.empty()) return SplitStatus::kOk;
  const Vec3 outward = part == kNegative ? normal_ : -normal_;
  const Vec3 u = any_perpendicular(outward);
  const CapFrame frame{u, cross(outward, u)};
  std::vector<Vec2> flat(points_.size());
  for (const auto& [a, b] : edges) {
    flat[a] = frame(points_[a]);
    flat[b] = frame(points_[b]);
  }
  std::vector<std::vector<std::uint32_t>> walks;
  SplitStatus status =
      trace_cap_loops(edges, flat, walks) ? SplitStatus::kOk : SplitStatus::kOpenCut;
  std::vector<CapLoop> loops;
  const double min_area = options_.tolerance * options_.tolerance;
  for (const auto& walk : walks) {
    for (auto& ids : split_at_repeats(walk)) {
      CapLoop loop{std::move(ids), {}, 0, {}};
      for (std::uint32_t id : loop.ids) loop.ring.push_back(flat[id]);
      loop.area = signed_area(loop.ring);
      if (std::abs(loop.area) > min_area) loops.push_back(std::move(loop));
    }
  }
  loop_count += loops.size();
  nest(loops, options_.tolerance);
  for (const CapLoop& outer : loops) {
    if (outer.area <= 0) continue;
    Polygon region{outer.ring, {}};
    std::vector<std::uint32_t> ids = outer.ids;
    for (std::size_t h : outer.holes) {
      region.holes.push_back(loops[h].ring);
      ids.insert(ids.end(), loops[h].ids.begin(), loops[h].ids.end());
    }
    if (!add_region_faces(faces, region, ids, false, options_.cap_tag)) {
      status = SplitStatus::kCapTriangulationFailed;
    }
  }
  return status;
}

Mesh Splitter::compact(const Mesh& part) const {
  std::vector<std::uint32_t> remap(points_.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::size_t f = 0; f < part.face_count(); ++f) {
    for (std::uint32_t v : part.face(f)) remap[v] = 0;
  }
  Mesh out;
  for (std::size_t v = 0; v < points_.size(); ++v) {
    if (remap[v] == 0) remap[v] = out.add_vertex(points_[v]);
  }
  std::vector<std::uint32_t> loop;
  for (std::size_t f = 0; f < part.face_count(); ++f) {
    loop.clear();
    for (std::uint32_t v : part.face(f)) loop.push_back(remap[v]);
    out.add_face(loop, part.tag(f));
  }
  return out;
}

SplitResult Splitter::run() {
  SplitResult result;
  for (std::size_t f = 0; f < mesh_.face_count(); ++f) split_face(f);
  if (options_.cap) {
    for (int part : {kNegative, kPositive}) {
      const SplitStatus status = cap(part, result.cap_loops);
      if (result.status == SplitStatus::kOk) result.status = status;
    }
  }
  result.negative = compact(parts_[kNegative]);
  result.positive = compact(parts_[kPositive]);
  return result;
}

}  // namespace

std::string_view split_status_message(SplitStatus status) {
  switch (status) {
    case SplitStatus::kOk:
      return "ok";
    case SplitStatus::kInvalidPlane:
      return "the cutting plane has a zero or non-finite normal or a non-finite offset";
    case SplitStatus::kNonFiniteInput:
      return "the mesh has a non-finite vertex coordinate";
    case SplitStatus::kOpenCut:
      return "the cut edges do not close into loops (is the mesh closed?); caps left out";
    case SplitStatus::kCapTriangulationFailed:
      return "a cap with holes could not be triangulated; that cap was left out";
    case SplitStatus::kInvalidPositions:
      return "split positions must be finite and non-decreasing";
  }
  return "unknown split status";
}

SplitResult split(const Mesh& mesh, const Plane& plane, const SplitOptions& options) {
  SplitResult result;
  const double scale = length(plane.normal);
  if (!finite(plane.normal) || !std::isfinite(plane.offset) || !(scale > 0)) {
    result.status = SplitStatus::kInvalidPlane;
    return result;
  }
  for (Vec3 p : mesh.positions()) {
    if (!finite(p)) {
      result.status = SplitStatus::kNonFiniteInput;
      return result;
    }
  }
  SplitOptions checked = options;
  if (!(checked.tolerance >= 0)) checked.tolerance = 0;
  return Splitter(mesh, plane.normal / scale, plane.offset / scale, checked).run();
}

SlabResult split_into_slabs(const Mesh& mesh, Vec3 direction, std::span<const double> positions,
                            const SplitOptions& options) {
  SlabResult result;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!std::isfinite(positions[i]) || (i > 0 && positions[i] < positions[i - 1])) {
      result.status = SplitStatus::kInvalidPositions;
      return result;
    }
  }
  const double scale = length(direction);
  if (!finite(direction) || !(scale > 0)) {
    result.status = SplitStatus::kInvalidPlane;
    return result;
  }
  const Vec3 axis = direction / scale;
  Mesh rest = mesh;
  for (double position : positions) {
    SplitResult cut = split(rest, Plane{axis, position}, options);
    if (result.status == SplitStatus::kOk) result.status = cut.status;
    result.pieces.push_back(std::move(cut.negative));
    rest = std::move(cut.positive);
  }
  result.pieces.push_back(std::move(rest));
  return result;
}

}  // namespace insula::kernel
