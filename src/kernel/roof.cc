// Roof planning: which type can be built, the overhang's eave polygon, the gable ends, the shed
// plane (docs/kernel-roofs.md). Emission of faces is in roof_emit.cc; the mansard split in
// roof_mansard.cc. Planning does everything that can fail, so emission never has to undo writes to
// the caller's mesh.
#include "kernel/roof.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "kernel/contract_loop.h"
#include "kernel/roof_detail.h"

namespace insula::kernel {

using roof_detail::Contour;
using roof_detail::GableEnd;
using roof_detail::RoofPlan;

namespace {

constexpr double kPi = 3.14159265358979323846;
// Gable ends need the two neighbouring edges to run back from the end within this angle of
// antiparallel, so the end closes a ridge (docs/kernel-roofs.md, "Gable").
constexpr double kGableParallelDeg = 30;
// Quadrilaterals whose opposite-edge sums differ by at most this fraction take the square rule for
// their ridge (docs/kernel-roofs.md, "Square footprints").
constexpr double kNearSquare = 0.05;
// Skeleton nodes closer than this fraction of the footprint's extent are one node.
constexpr double kNodeMerge = 1e-6;

// A pyramid accepts a footprint whose outer ring turns clockwise by at most this much in total
// (digitizing noise on nearly straight edges), docs/kernel-roofs.md, "Pyramid on concave input".
constexpr double kPyramidReflexDeg = 1;

double tan_deg(double degrees) {
  return std::tan(degrees * kPi / 180);
}

// Signed distance of `p` from the supporting line of contour edge e, positive on the interior side.
double edge_distance(const Contour& c, std::uint32_t e, Vec2 p) {
  const Vec2 a = c.points[e];
  const Vec2 d = c.points[c.next(e)] - a;
  return cross(d, p - a) / length(d);
}

// Offsets every edge e outward (to its right) by distances[e] >= 0 with mitred corners, so vertex
// k of the result corresponds to vertex k of `c`. Returns false when a corner is undefined
// (parallel neighbours with different distances) or an edge flips.
bool offset_contour(const Contour& c, const std::vector<double>& distances, Contour& out) {
  out.ring_starts = c.ring_starts;
  out.points.resize(c.points.size());
  for (std::uint32_t k = 0; k < c.points.size(); ++k) {
    const std::uint32_t p = c.prev(k);
    const Vec2 np = -perp(normalized(c.points[k] - c.points[p]));  // right normal of edge p
    const Vec2 nk = -perp(normalized(c.points[c.next(k)] - c.points[k]));
    const double det = cross(np, nk);
    if (std::abs(det) < 1e-9) {
      if (std::abs(distances[p] - distances[k]) > 1e-12) return false;
      out.points[k] = c.points[k] + nk * distances[k];
      continue;
    }
    // Solve dot(q, np) = distances[p], dot(q, nk) = distances[k] for the displacement q.
    const Vec2 q =
        Vec2{distances[p] * nk.y - distances[k] * np.y, distances[k] * np.x - distances[p] * nk.x} /
        det;
    out.points[k] = c.points[k] + q;
  }
  for (std::uint32_t k = 0; k < c.points.size(); ++k) {
    const Vec2 before = c.points[c.next(k)] - c.points[k];
    const Vec2 after = out.points[out.next(k)] - out.points[k];
    if (dot(before, after) <= 0) return false;
  }
  return is_simple_polygon(out.polygon());
}

// The ridge point of a gable on edge e: on e's line, equally far from the lines of the
// neighbouring edges, strictly inside the edge. Nothing unless those neighbours run back from e
// within kGableParallelDeg of antiparallel (the edge closes the end of a wing).
std::optional<GableEnd> gable_apex(const Contour& c, std::uint32_t e) {
  const std::uint32_t prev = c.prev(e);
  const std::uint32_t next = c.next(e);
  const Vec2 dp = normalized(c.points[e] - c.points[prev]);
  const Vec2 dn = normalized(c.points[c.next(next)] - c.points[next]);
  if (dot(dp, dn) > -std::cos(kGableParallelDeg * kPi / 180)) return std::nullopt;
  const Vec2 a = c.points[e];
  const Vec2 b = c.points[next];
  const double f0 = edge_distance(c, prev, a) - edge_distance(c, next, a);
  const double f1 = edge_distance(c, prev, b) - edge_distance(c, next, b);
  if (f0 == f1) return std::nullopt;
  const double t = f0 / (f0 - f1);
  if (!(t > 1e-6 && t < 1 - 1e-6)) return std::nullopt;
  const Vec2 apex = a + (b - a) * t;
  const double time = edge_distance(c, prev, apex);
  if (!(time > 1e-9)) return std::nullopt;
  return GableEnd{e, 0, apex, time};
}

// Groups of skeleton nodes contracted to one node, each represented by its lowest id.
class NodeGroups {
 public:
  explicit NodeGroups(std::uint32_t n) : root_(n) {
    for (std::uint32_t v = 0; v < n; ++v) root_[v] = v;
  }
  std::uint32_t find(std::uint32_t v) {
    while (root_[v] != v) v = root_[v] = root_[root_[v]];
    return v;
  }
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    root_[std::max(a, b)] = std::min(a, b);
    return true;
  }

 private:
  std::vector<std::uint32_t> root_;
};

// Unites the nodes closer than `tolerance`; false when there are none.
bool group_close_nodes(const Skeleton& s, double tolerance, NodeGroups& groups) {
  std::vector<std::uint32_t> order;
  for (auto v = s.contour_count; v < s.vertices.size(); ++v) order.push_back(v);
  const auto x = [&](std::uint32_t v) { return s.vertices[v].position.x; };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::make_pair(x(a), a) < std::make_pair(x(b), b);
  });
  bool merged = false;
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = i + 1; j < order.size() && x(order[j]) - x(order[i]) <= tolerance; ++j) {
      const Vec2 d = s.vertices[order[j]].position - s.vertices[order[i]].position;
      if (length(d) <= tolerance) merged = groups.unite(order[i], order[j]) || merged;
    }
  }
  return merged;
}

// The face loops with every group contracted (kernel::contract_loop); false when a face would come
// apart into several pieces or lose its contour edge.
bool contract_faces(const Skeleton& s, NodeGroups& groups, std::vector<std::uint32_t>& indices,
                    std::vector<std::uint32_t>& offsets) {
  indices.clear();
  offsets.assign(1, 0);
  std::vector<std::uint32_t> keys;
  for (std::size_t e = 0; e < s.face_count(); ++e) {
    keys.clear();
    for (std::uint32_t v : s.face(e)) keys.push_back(groups.find(v));
    const auto pieces = contract_loop(keys);
    if (pieces.size() != 1 || pieces[0][0] != 0 || pieces[0][1] != 1) return false;
    for (std::uint32_t corner : pieces[0]) indices.push_back(keys[corner]);
    offsets.push_back(static_cast<std::uint32_t>(indices.size()));
  }
  return true;
}

// Contracts skeleton nodes closer than `tolerance` to one node and rewrites the face loops, so no
// roof face keeps an edge shorter than the tolerance: near-regular footprints give clusters of
// nodes nanometres apart whose tiny ridges the wavefront can leave inconsistent, and which float32
// output cannot tell apart (docs/kernel-roofs.md, "Near-coincident nodes"). Where a group pinches
// the skeleton (its nodes are not joined by edges: every node-to-node edge must keep exactly one
// use each way) the ends of the offending edges are contracted too, for a few passes; contour
// vertices never move. If that does not give a clean skeleton, it is left as it was.
void merge_close_nodes(Skeleton& s, double tolerance) {
  NodeGroups groups(static_cast<std::uint32_t>(s.vertices.size()));
  if (!group_close_nodes(s, tolerance, groups)) return;
  std::vector<std::uint32_t> indices, offsets;
  for (int pass = 0; pass < 8; ++pass) {
    if (!contract_faces(s, groups, indices, offsets)) return;
    EdgeUses uses;
    for (std::size_t e = 0; e + 1 < offsets.size(); ++e) {
      uses.add_loop(std::span(indices).subspan(offsets[e], offsets[e + 1] - offsets[e]));
    }
    bool clean = true;
    for (const auto& [a, b] : uses.unpaired()) {
      if (a < s.contour_count && b < s.contour_count) continue;  // the polygon's own edges
      if (a < s.contour_count || b < s.contour_count) return;
      clean = false;
      groups.unite(a, b);
    }
    if (clean) {
      s.face_indices = std::move(indices);
      s.face_offsets = std::move(offsets);
      return;
    }
  }
}

// The straight skeleton a roof is built on: near-coincident nodes merged within kNodeMerge of the
// polygon's extent.
std::optional<Skeleton> roof_skeleton(const Polygon& polygon) {
  std::optional<Skeleton> s = interior_straight_skeleton(polygon);
  if (!s) return s;
  const Bounds2 box = bounds(polygon);
  merge_close_nodes(*s, kNodeMerge * length(box.max - box.min));
  return s;
}

// Seed 000 §4.6 hip faces become gables where a ridge ends: see docs/kernel-roofs.md.
std::optional<GableEnd> gable_end(const Skeleton& s, const Contour& c,
                                  const std::vector<std::uint32_t>& face_count, std::uint32_t e) {
  const auto loop = s.face(e);
  if (loop.size() != 3 || loop[2] < s.contour_count || face_count[loop[2]] != 3) {
    return std::nullopt;
  }
  std::optional<GableEnd> end = gable_apex(c, e);
  if (end) end->node = loop[2];
  return end;
}

std::vector<GableEnd> find_gables(const Skeleton& s, const Contour& c) {
  std::vector<std::uint32_t> face_count(s.vertices.size(), 0);
  for (std::uint32_t v : s.face_indices) ++face_count[v];
  std::vector<GableEnd> gables;
  for (std::uint32_t e = 0; e < s.contour_count; ++e) {
    if (auto g = gable_end(s, c, face_count, e)) gables.push_back(*g);
  }
  return gables;
}

bool uses_skeleton(RoofType type) {
  return type == RoofType::kHip || type == RoofType::kGable || type == RoofType::kMansard ||
         type == RoofType::kHoledMansard;
}

double eave_slope(const RoofSpec& spec, RoofType type) {
  switch (type) {
    case RoofType::kFlat:
      return 0;
    case RoofType::kMansard:
    case RoofType::kHoledMansard:
      return tan_deg(spec.mansard_pitch_deg);
    default:
      return tan_deg(spec.pitch_deg);
  }
}

// The eave polygon for `overhang` with per-edge distances (0 on gable ends).
bool plan_eave(RoofPlan& plan, double overhang, const std::vector<std::uint32_t>& flush_edges) {
  plan.offsets.assign(plan.footprint.points.size(), overhang);
  for (std::uint32_t e : flush_edges) plan.offsets[e] = 0;
  plan.overhang = overhang;
  if (overhang <= 0) {
    plan.eave = plan.footprint;
    return true;
  }
  return offset_contour(plan.footprint, plan.offsets, plan.eave);
}

// Total clockwise (reflex) turning of the outer ring, in degrees, for the ring's own orientation:
// 0 for a convex ring, 90 per right-angle notch of an L, T or U.
double reflex_turning_deg(const Contour& c) {
  const double orientation = signed_area(c.polygon().outer) < 0 ? -1.0 : 1.0;
  double total = 0;
  for (std::uint32_t k = 0; k < c.ring_starts[1]; ++k) {
    const Vec2 in = c.points[k] - c.points[c.prev(k)];
    const Vec2 out = c.points[c.next(k)] - c.points[k];
    const double turn = std::atan2(orientation * cross(in, out), dot(in, out));
    if (turn < 0) total -= turn;
  }
  return total * 180 / kPi;
}

// A pyramid only over a convex footprint without holes (docs/kernel-roofs.md, "Pyramid on concave
// input"): with a reflex corner the apex over the centroid is limited by the nearest edge line, and
// the faces of the other wings fold into nearly flat tents.
bool plan_pyramid(RoofPlan& plan) {
  if (plan.eave.ring_starts.size() != 2 || plan.footprint.ring_starts.size() != 2) return false;
  if (reflex_turning_deg(plan.footprint) > kPyramidReflexDeg) return false;
  const Polygon polygon = plan.eave.polygon();
  const Vec2 c = centroid(polygon);
  double nearest = 1e300;
  for (std::uint32_t e = 0; e < plan.eave.points.size(); ++e) {
    nearest = std::min(nearest, edge_distance(plan.eave, e, c));
  }
  if (!(nearest > 1e-6)) return false;
  plan.apex = c;
  plan.apex_time = nearest;
  return true;
}

// A quadrilateral without holes whose two pairs of opposite edges have nearly equal total
// lengths. Exactly equal sums (Pitot) are the quadrilaterals with an incircle (square, rhombus,
// kite), whose skeleton meets in one node and has no ridge to end in a gable; within the
// tolerance the skeleton's ridge, if any, is too short for its direction to matter to a user.
bool near_square(const Contour& c) {
  if (c.ring_starts.size() != 2 || c.size() != 4) return false;
  const auto edge = [&](std::uint32_t e) { return length(c.points[c.next(e)] - c.points[e]); };
  const double a = edge(0) + edge(2);
  const double b = edge(1) + edge(3);
  return std::abs(a - b) <= kNearSquare * std::max(a, b);
}

// The two-slope gable over a quadrilateral with its ends at edges 1 and 3, so the ridge runs
// parallel to edge 0 (docs/kernel-roofs.md, "Square footprints"), as a roof skeleton: faces 0 and 2
// meet along the ridge between the two gable apexes, faces 1 and 3 are the gable triangles. Each
// apex is equally far from the lines of edges 0 and 2, so lifting by time * slope keeps both
// slopes planar.
bool plan_quad_gable(RoofPlan& plan, double overhang) {
  if (!plan_eave(plan, overhang, {1, 3})) return false;
  const Contour& c = plan.eave;
  std::optional<GableEnd> end1 = gable_apex(c, 1);
  std::optional<GableEnd> end3 = gable_apex(c, 3);
  if (!end1 || !end3) return false;
  end1->node = 4;
  end3->node = 5;
  Skeleton s;
  for (const Vec2& p : c.points) s.vertices.push_back({p, 0});
  s.vertices.push_back({end1->apex, end1->time});
  s.vertices.push_back({end3->apex, end3->time});
  s.face_indices = {0, 1, 4, 5, 1, 2, 4, 2, 3, 5, 4, 3, 0, 5};
  s.face_offsets = {0, 4, 7, 11, 14};
  s.ring_starts = c.ring_starts;
  s.contour_count = 4;
  for (std::uint32_t e : {0U, 2U}) {
    Polygon slope;
    for (std::uint32_t v : s.face(e)) slope.outer.push_back(s.vertices[v].position);
    if (!is_simple_polygon(slope)) return false;
  }
  plan.skeleton = std::move(s);
  plan.gables = {*end1, *end3};
  return true;
}

bool plan_gable(RoofPlan& plan, const RoofSpec& spec) {
  if (near_square(plan.footprint) && plan_quad_gable(plan, spec.overhang)) return true;
  auto base = roof_skeleton(plan.footprint.polygon());
  if (!base) return false;
  std::vector<GableEnd> gables = find_gables(*base, plan.footprint);
  if (gables.empty()) return false;
  std::vector<std::uint32_t> edges;
  for (const GableEnd& g : gables) edges.push_back(g.edge);
  if (spec.overhang <= 0) {
    plan_eave(plan, 0, {});
    plan.gables = std::move(gables);
    plan.skeleton = std::move(base);
    return true;
  }
  // Gable ends stay flush with their wall; the eaves overhang. The skeleton of that eave polygon
  // must still end its ridges at the same edges.
  if (!plan_eave(plan, spec.overhang, edges)) return false;
  plan.skeleton = roof_skeleton(plan.eave.polygon());
  if (!plan.skeleton) return false;
  plan.gables = find_gables(*plan.skeleton, plan.eave);
  std::erase_if(plan.gables, [&](const GableEnd& g) {
    return std::find(edges.begin(), edges.end(), g.edge) == edges.end();
  });
  return plan.gables.size() == edges.size();
}

std::uint32_t longest_outer_edge(const Contour& c) {
  std::uint32_t best = 0;
  double best_length = -1;
  for (std::uint32_t e = 0; e < c.ring_starts[1]; ++e) {
    const double l = length(c.points[c.next(e)] - c.points[e]);
    if (l > best_length) best_length = l, best = e;
  }
  return best;
}

// Everything that can fail for one roof type; false when this type cannot be built.
bool plan_type(RoofPlan& plan, const RoofSpec& spec, RoofType type, double overhang) {
  plan.type = type;
  plan.skeleton.reset();
  plan.gables.clear();
  plan.slope = type == RoofType::kFlat ? 0 : tan_deg(spec.pitch_deg);
  plan.eave_slope = eave_slope(spec, type);
  plan.fascia = 0;
  if (type == RoofType::kGable) {
    RoofSpec with_overhang = spec;
    with_overhang.overhang = overhang;
    return plan_gable(plan, with_overhang);
  }
  if (!plan_eave(plan, overhang, {})) return false;
  if ((type == RoofType::kFlat || type == RoofType::kShed) && overhang > 0) {
    plan.fascia = spec.fascia;
  }
  if (type == RoofType::kShed) {
    const int asked = spec.shed_edge;
    plan.shed_edge = asked >= 0 && static_cast<std::uint32_t>(asked) < plan.footprint.ring_starts[1]
                         ? static_cast<std::uint32_t>(asked)
                         : longest_outer_edge(plan.footprint);
  }
  if (type == RoofType::kPyramid) return plan_pyramid(plan);
  if (type == RoofType::kMansard || type == RoofType::kHoledMansard) {
    plan.upper_slope = tan_deg(std::max(0.0, spec.pitch_deg));
    plan.break_time = overhang + spec.mansard_break_height / plan.eave_slope;
  }
  if (uses_skeleton(type)) {
    plan.skeleton = roof_skeleton(plan.eave.polygon());
    return plan.skeleton.has_value();
  }
  return true;
}

bool spec_valid(const RoofSpec& spec, std::string& why) {
  const bool pitched = spec.type != RoofType::kFlat;
  if (pitched && !(spec.pitch_deg > 0 && spec.pitch_deg <= 89)) {
    why = "pitch must be in (0, 89] degrees";
  } else if (!(spec.overhang >= 0 && spec.overhang < 1e3)) {
    why = "overhang must be >= 0 m";
  } else if ((spec.type == RoofType::kMansard || spec.type == RoofType::kHoledMansard) &&
             !(spec.mansard_pitch_deg > 0 && spec.mansard_pitch_deg <= 89 &&
               spec.mansard_break_height > 0)) {
    why = "mansard needs a lower pitch in (0, 89] degrees and a break height > 0";
  } else if (!(spec.fascia > 0)) {
    why = "fascia must be > 0 m";
  } else {
    return true;
  }
  return false;
}

// Requested type, then hip, then flat (docs/kernel-roofs.md, "Fallbacks").
std::array<RoofType, 3> fallback_chain(RoofType asked) {
  return {asked, RoofType::kHip, RoofType::kFlat};
}

}  // namespace

std::string_view roof_type_name(RoofType type) {
  switch (type) {
    case RoofType::kFlat:
      return "flat";
    case RoofType::kShed:
      return "shed";
    case RoofType::kGable:
      return "gable";
    case RoofType::kHip:
      return "hip";
    case RoofType::kPyramid:
      return "pyramid";
    case RoofType::kMansard:
      return "mansard";
    case RoofType::kHoledMansard:
      return "holed_mansard";
  }
  return "flat";
}

std::optional<RoofType> roof_type_from_name(std::string_view name) {
  std::string lower(name);
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (RoofType t : {RoofType::kFlat, RoofType::kShed, RoofType::kGable, RoofType::kHip,
                     RoofType::kPyramid, RoofType::kMansard, RoofType::kHoledMansard}) {
    if (lower == roof_type_name(t)) return t;
  }
  if (lower == "holedmansard" || lower == "compluvium") return RoofType::kHoledMansard;
  return std::nullopt;
}

namespace roof_detail {

Contour Contour::from(const Polygon& polygon) {
  Contour c;
  c.points.reserve(polygon.outer.size());
  c.ring_starts.push_back(0);
  c.points.insert(c.points.end(), polygon.outer.begin(), polygon.outer.end());
  c.ring_starts.push_back(static_cast<std::uint32_t>(c.points.size()));
  for (const Ring& hole : polygon.holes) {
    c.points.insert(c.points.end(), hole.begin(), hole.end());
    c.ring_starts.push_back(static_cast<std::uint32_t>(c.points.size()));
  }
  return c;
}

Polygon Contour::polygon() const {
  Polygon p;
  p.outer.assign(points.begin(), points.begin() + ring_starts[1]);
  for (std::size_t r = 1; r + 1 < ring_starts.size(); ++r) {
    p.holes.emplace_back(points.begin() + ring_starts[r], points.begin() + ring_starts[r + 1]);
  }
  return p;
}

std::uint32_t Contour::next(std::uint32_t k) const {
  std::size_t r = 1;
  while (ring_starts[r] <= k) ++r;
  return k + 1 == ring_starts[r] ? ring_starts[r - 1] : k + 1;
}

std::uint32_t Contour::prev(std::uint32_t k) const {
  std::size_t r = 1;
  while (ring_starts[r] <= k) ++r;
  return k == ring_starts[r - 1] ? ring_starts[r] - 1 : k - 1;
}

double shed_distance(const RoofPlan& plan, Vec2 p) {
  return edge_distance(plan.footprint, plan.shed_edge, p);
}

bool plan_roof(const Polygon& footprint, const RoofSpec& spec, RoofPlan& plan) {
  if (!spec_valid(spec, plan.message)) return false;
  if (!is_simple_polygon(footprint)) {
    plan.message = "footprint is not a simple polygon with holes";
    return false;
  }
  plan.footprint = Contour::from(footprint);
  double overhang = spec.overhang;
  if (overhang > 0 && !plan_eave(plan, overhang, {})) {
    plan.message = "overhang of " + std::to_string(overhang) +
                   " m makes the eave polygon self-intersect; built without overhang";
    overhang = 0;
  }
  RoofType previous = spec.type;
  for (RoofType type : fallback_chain(spec.type)) {
    if (type != spec.type && type == previous) continue;
    if (plan_type(plan, spec, type, overhang)) {
      if (type != spec.type) {
        if (!plan.message.empty()) plan.message += "; ";
        plan.message += std::string(roof_type_name(spec.type)) + " roof could not be built; " +
                        std::string(roof_type_name(type)) + " roof instead";
      }
      plan.status = plan.message.empty() ? RoofStatus::kOk : RoofStatus::kFallback;
      return true;
    }
    previous = type;
  }
  plan.message = "no roof could be built";
  return false;
}

}  // namespace roof_detail

RoofBuild add_roof(const Polygon& footprint, const RoofSpec& spec, double eave_z, Mesh& mesh,
                   std::uint32_t first_face_id) {
  RoofBuild build;
  build.next_face_id = first_face_id;
  RoofPlan plan;
  if (!std::isfinite(eave_z)) {
    build.message = "eave height is not finite";
    return build;
  }
  if (!roof_detail::plan_roof(footprint, spec, plan)) {
    build.message = plan.message;
    return build;
  }
  roof_detail::emit_roof(plan, eave_z, mesh, build);
  build.status = plan.status;
  build.built = plan.type;
  build.message = plan.message;
  return build;
}

RoofResult build_roof(const Polygon& footprint, const RoofSpec& spec, double eave_z) {
  RoofResult result;
  RoofBuild build = add_roof(footprint, spec, eave_z, result.mesh);
  result.status = build.status;
  result.built = build.built;
  result.message = build.message;
  if (build.status == RoofStatus::kFailed) return result;
  const Contour c = Contour::from(footprint);
  std::vector<std::uint32_t> loop;
  for (std::uint32_t e = 0; e < c.points.size(); ++e) {
    if (build.cap_offsets[e] == build.cap_offsets[e + 1]) continue;
    loop.assign({build.wall_top[e], build.wall_top[c.next(e)]});
    loop.insert(loop.end(), build.cap_indices.begin() + build.cap_offsets[e],
                build.cap_indices.begin() + build.cap_offsets[e + 1]);
    result.mesh.add_face(loop, {SemanticClass::kWallSurface, 0, build.next_face_id++});
  }
  return result;
}

}  // namespace insula::kernel
