// Roof planning: which type can be built, the overhang's eave polygon, the gable ends, the shed
// plane (docs/kernel-roofs.md). Emission of faces is in roof_emit.cc; the mansard split in
// roof_mansard.cc. Planning does everything that can fail, so emission never has to undo writes to
// the caller's mesh.
#include "kernel/roof.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "base/format.h"
#include "kernel/contract_loop.h"
#include "kernel/party_walls.h"
#include "kernel/roof_detail.h"

namespace insula::kernel {

using roof_detail::Contour;
using roof_detail::GableEnd;
using roof_detail::kEaveMiterLimit;
using roof_detail::RoofPlan;

namespace {
constexpr double kPi = 3.14159265358979323846;
// Gable ends need the two neighbouring edges to run back from the end within this angle of
// antiparallel, so the end closes a ridge (docs/kernel-roofs.md, "Gable").
constexpr double kGableParallelDeg = 30;
}  // namespace

namespace roof_detail {

// Signed distance of `p` from the supporting line of contour edge e, positive on the interior side.
double edge_distance(const Contour& c, std::uint32_t e, Vec2 p) {
  const Vec2 a = c.points[e];
  const Vec2 d = c.points[c.next(e)] - a;
  return cross(d, p - a) / length(d);
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

}  // namespace roof_detail

using roof_detail::edge_distance;
using roof_detail::gable_apex;

namespace {

// Skeleton nodes closer than this fraction of the footprint's extent are one node.
constexpr double kNodeMerge = 1e-6;

// A pyramid accepts a footprint whose outer ring turns clockwise by at most this much in total
// (digitizing noise on nearly straight edges), docs/kernel-roofs.md, "Pyramid on concave input".
constexpr double kPyramidReflexDeg = 1;

// A vertex where the outer ring turns by less than this (either way) is not a corner when a roof
// type asks for a quadrilateral or a convex footprint (docs/kernel-roofs.md, "Nearly straight
// vertices"). OpenStreetMap outlines keep vertices a few centimetres from a corner or along a
// straight wall that turn by a degree or two (a near-rectangle with a 4 cm edge at 181 degrees was
// refused a pyramid and every quadrilateral shape); a designed corner turns by far more (a regular
// 60-gon, the finest circle footprints commonly get, turns by 6 degrees per vertex).
constexpr double kCornerMinTurnDeg = 3;

double tan_deg(double degrees) {
  return std::tan(degrees * kPi / 180);
}

// Offsets every edge e outward (to its right) by distances[e] >= 0 with mitred corners, so vertex
// k of the result corresponds to vertex k of `c`. Returns false when a corner is undefined
// (parallel neighbours with different distances), reaches beyond kEaveMiterLimit, or an edge
// flips.
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
    if (length(q) > kEaveMiterLimit * std::max(distances[p], distances[k])) return false;
    out.points[k] = c.points[k] + q;
  }
  for (std::uint32_t k = 0; k < c.points.size(); ++k) {
    const Vec2 before = c.points[c.next(k)] - c.points[k];
    const Vec2 after = out.points[out.next(k)] - out.points[k];
    if (dot(before, after) <= 0) return false;
  }
  return is_simple_polygon(out.polygon());
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
    case RoofType::kGambrel:
      return tan_deg(spec.mansard_pitch_deg);
    default:
      return tan_deg(spec.pitch_deg);
  }
}

// The edges of `c` that run along one of `walls` (RoofSpec::party_walls), and the edges that
// continue them around a bend of less than kPartyWallBendDeg or are shorter than twice the
// overhang (unless nearly in line with their other neighbour): where an overhanging edge meets a
// flush one nearly in line, the mitred eave corner runs off toward infinity, and a short step
// between a flush and an overhanging edge flips (offset_contour); both are part of the party wall's
// line in mapped outlines.
constexpr double kPartyWallBendDeg = 20;

std::vector<std::uint32_t> party_edges(const Contour& c, std::span<const PartyWall> walls,
                                       double overhang) {
  std::vector<std::uint32_t> edges;
  if (walls.empty() || !(overhang > 0)) return edges;
  std::vector<bool> flush(c.points.size(), false);
  for (std::uint32_t e = 0; e < c.points.size(); ++e) {
    flush[e] = on_party_wall(c.points[e], c.points[c.next(e)], walls);
  }
  const double straight = std::cos(kPartyWallBendDeg * kPi / 180);
  const auto direction = [&](std::uint32_t e) {
    return normalized(c.points[c.next(e)] - c.points[e]);
  };
  const auto joins = [&](std::uint32_t e, std::uint32_t f) {  // f follows e
    return dot(direction(e), direction(f)) > straight;
  };
  const auto is_short = [&](std::uint32_t e) {
    return length(c.points[c.next(e)] - c.points[e]) < 2 * overhang;
  };
  for (bool grew = true; grew;) {
    grew = false;
    for (std::uint32_t e = 0; e < c.points.size(); ++e) {
      if (!flush[e]) continue;
      const std::uint32_t after = c.next(e);
      const std::uint32_t before = c.prev(e);
      // A short edge nearly in line with its other neighbour belongs to that neighbour's line
      // (a survey's 4 cm corner edge on a slope side): flushing it would flush the whole side.
      if (!flush[after] && (joins(e, after) || (is_short(after) && !joins(after, c.next(after))))) {
        flush[after] = grew = true;
      }
      if (!flush[before] &&
          (joins(before, e) || (is_short(before) && !joins(c.prev(before), before)))) {
        flush[before] = grew = true;
      }
    }
  }
  for (std::uint32_t e = 0; e < c.points.size(); ++e) {
    if (flush[e]) edges.push_back(e);
  }
  return edges;
}

// The eave polygon for `overhang` with per-edge distances (0 on gable ends and party walls).
bool plan_eave(RoofPlan& plan, double overhang, const std::vector<std::uint32_t>& flush_edges) {
  plan.offsets.assign(plan.footprint.points.size(), overhang);
  for (std::uint32_t e : flush_edges) plan.offsets[e] = 0;
  for (std::uint32_t e : plan.party_edges) plan.offsets[e] = 0;
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
  if (reflex_turning_deg(roof_detail::outline_core(plan.footprint)) > kPyramidReflexDeg) {
    return false;
  }
  const Polygon polygon = plan.eave.polygon();
  const Vec2 c = centroid(polygon);
  for (std::uint32_t e = 0; e < plan.eave.points.size(); ++e) {
    if (!(edge_distance(plan.eave, e, c) > 1e-6)) return false;
  }
  // The height from the corners' edges: the line of a 4 cm edge turned by 1 degree passes 0.1 m
  // nearer the centre of a 12 m rectangle, and would lower the whole roof for its sliver of a face.
  const Contour core = roof_detail::outline_core(plan.eave);
  double nearest = 1e300;
  for (std::uint32_t e = 0; e < core.points.size(); ++e) {
    nearest = std::min(nearest, edge_distance(core, e, c));
  }
  if (!(nearest > 1e-6)) return false;
  plan.apex = c;
  plan.apex_time = nearest;
  return true;
}

// The two-slope gable over a quadrilateral with its slopes on edges r and r + 2 and its ends at
// edges r + 1 and r + 3 (r from quad_slope_pair: roof:direction, roof:orientation, the square rule
// of docs/kernel-roofs.md, "Square footprints", or the longer pair), as a roof skeleton: the two
// slope faces meet along the ridge between the two gable apexes, the end faces are the gable
// triangles. Each apex is equally far from the lines of the slope edges, so lifting by
// time * slope keeps both slopes planar.
bool plan_quad_gable(RoofPlan& plan, const RoofSpec& spec, double overhang) {
  if (plan.footprint.ring_starts.size() != 2 || plan.footprint.size() != 4) return false;
  const std::uint32_t r = roof_detail::quad_slope_pair(plan.footprint, spec);
  const std::uint32_t e1 = r + 1, e3 = (r + 3) % 4;
  if (!plan_eave(plan, overhang, {e1, e3})) return false;
  const Contour& c = plan.eave;
  std::optional<GableEnd> end1 = gable_apex(c, e1);
  std::optional<GableEnd> end3 = gable_apex(c, e3);
  if (!end1 || !end3) return false;
  end1->node = 4;
  end3->node = 5;
  Skeleton s;
  for (const Vec2& p : c.points) s.vertices.push_back({p, 0});
  s.vertices.push_back({end1->apex, end1->time});
  s.vertices.push_back({end3->apex, end3->time});
  std::vector<std::vector<std::uint32_t>> faces(4);
  faces[r] = {r, r + 1, 4, 5};
  faces[e1] = {e1, (e1 + 1) % 4, 4};
  faces[r + 2] = {r + 2, (r + 3) % 4, 5, 4};
  faces[e3] = {e3, (e3 + 1) % 4, 5};
  s.face_offsets = {0};
  for (const auto& f : faces) {
    s.face_indices.insert(s.face_indices.end(), f.begin(), f.end());
    s.face_offsets.push_back(static_cast<std::uint32_t>(s.face_indices.size()));
  }
  s.ring_starts = c.ring_starts;
  s.contour_count = 4;
  for (std::uint32_t e : {r, r + 2}) {
    Polygon slope;
    for (std::uint32_t v : s.face(e)) slope.outer.push_back(s.vertices[v].position);
    if (!is_simple_polygon(slope)) return false;
  }
  plan.skeleton = std::move(s);
  plan.gables = {*end1, *end3};
  return true;
}

// Quadrilaterals take the quad gable, so their ridge follows roof:direction / roof:orientation
// and an overhang cannot turn it (a 6 x 6.5 m footprint whose eaves overhang becomes wider than
// long); other footprints and quadrilaterals it cannot build take the skeleton's ridges.
bool plan_gable(RoofPlan& plan, const RoofSpec& spec) {
  if (plan_quad_gable(plan, spec, spec.overhang)) return true;
  plan.reason = "skeleton: the straight skeleton could not be computed";
  auto base = roof_skeleton(plan.footprint.polygon());
  if (!base) return false;
  std::vector<GableEnd> gables = find_gables(*base, plan.footprint);
  plan.reason = "roof faces: no footprint edge ends a ridge as a gable";
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
  plan.reason = "roof faces: the overhanging eaves do not end their ridges at the same gables";
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
bool is_custom(RoofType type) {
  return type >= RoofType::kGambrel;
}

// The S3DB shapes built without overhang whatever is asked: round, dome and onion spring from the
// wall (gambrel, half-hipped and saltbox overhang their slope sides, roof_shapes.cc).
bool springs_from_wall(RoofType type) {
  return type == RoofType::kRound || type == RoofType::kDome || type == RoofType::kOnion;
}

// The shed plane: rising from the edge asked or the longest outer edge, or, with roof:direction,
// falling toward that azimuth from the footprint's highest point (docs/kernel-roofs.md, "Shed
// direction").
void plan_shed(RoofPlan& plan, const RoofSpec& spec) {
  const Contour& c = plan.footprint;
  if (spec.direction_deg) {
    const double a = *spec.direction_deg * kPi / 180;
    plan.shed_normal = Vec2{-std::sin(a), -std::cos(a)};  // uphill
    plan.shed_origin = c.points[0];
    for (std::uint32_t k = 0; k < c.ring_starts[1]; ++k) {
      if (dot(plan.shed_normal, c.points[k] - plan.shed_origin) < 0) plan.shed_origin = c.points[k];
    }
  } else {
    const int asked = spec.shed_edge;
    const std::uint32_t e = asked >= 0 && static_cast<std::uint32_t>(asked) < c.ring_starts[1]
                                ? static_cast<std::uint32_t>(asked)
                                : longest_outer_edge(c);
    plan.shed_origin = c.points[e];
    plan.shed_normal = perp(normalized(c.points[c.next(e)] - c.points[e]));
    // On a footprint that is not convex, corners can lie behind the edge's line: the low side
    // moves back to the one farthest behind, so no part of the roof dips below the eave (a real
    // OpenStreetMap outline reaching 60 m behind its longest edge put the roof 35 m under it).
    for (std::uint32_t k = 0; k < c.ring_starts[1]; ++k) {
      if (dot(plan.shed_normal, c.points[k] - plan.shed_origin) < 0) plan.shed_origin = c.points[k];
    }
  }
  if (spec.height || spec.height_limit) {
    double far = 0;
    for (std::uint32_t k = 0; k < c.ring_starts[1]; ++k) {
      far = std::max(far, roof_detail::shed_distance(plan, c.points[k]));
    }
    if (far > 0 && spec.height) {
      plan.slope = *spec.height / far;
    } else if (far > 0 && plan.slope * far > *spec.height_limit) {
      plan.slope = *spec.height_limit / far;
    }
  }
}

bool plan_type(RoofPlan& plan, const RoofSpec& spec, RoofType type, double overhang) {
  plan.type = type;
  plan.custom = roof_detail::CustomRoof();
  plan.skeleton.reset();
  plan.gables.clear();
  plan.reason.clear();
  plan.slope = type == RoofType::kFlat ? 0 : tan_deg(spec.pitch_deg);
  plan.eave_slope = eave_slope(spec, type);
  plan.fascia = 0;
  if (type == RoofType::kGable) {
    RoofSpec with_overhang = spec;
    with_overhang.overhang = overhang;
    return plan_gable(plan, with_overhang);
  }
  if (is_custom(type)) {
    plan_eave(plan, 0, {});
    plan.reason = "roof faces: the footprint is not a quadrilateral with two opposite ends";
    if (type == RoofType::kDome || type == RoofType::kOnion) {
      plan.reason = "roof faces: the footprint is not star-shaped about its centroid";
    }
    return roof_detail::plan_custom(plan, spec, springs_from_wall(type) ? 0 : overhang);
  }
  plan.reason = "roof faces: the eave polygon of the overhang is not simple";
  if (!plan_eave(plan, overhang, {})) return false;
  if ((type == RoofType::kFlat || type == RoofType::kShed) && overhang > 0) {
    plan.fascia = spec.fascia;
  }
  if (type == RoofType::kShed) plan_shed(plan, spec);
  plan.reason = "roof faces: the footprint is not convex";
  if (type == RoofType::kPyramid) return plan_pyramid(plan);
  if (type == RoofType::kMansard || type == RoofType::kHoledMansard) {
    plan.upper_slope = tan_deg(std::max(0.0, spec.pitch_deg));
    plan.break_time = overhang + spec.mansard_break_height / plan.eave_slope;
  }
  if (uses_skeleton(type)) {
    plan.reason = "skeleton: the straight skeleton could not be computed";
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
  } else if ((spec.type == RoofType::kMansard || spec.type == RoofType::kHoledMansard ||
              spec.type == RoofType::kGambrel) &&
             !(spec.mansard_pitch_deg > 0 && spec.mansard_pitch_deg <= 89 &&
               spec.mansard_break_height > 0)) {
    why = "mansard needs a lower pitch in (0, 89] degrees and a break height > 0";
  } else if (!(spec.fascia > 0)) {
    why = "fascia must be > 0 m";
  } else if (spec.height && !(*spec.height > 0 && *spec.height < 1e4)) {
    why = "roof height must be in (0, 10000) m";
  } else if (spec.height_limit && !(*spec.height_limit > 0 && *spec.height_limit < 1e4)) {
    why = "roof height limit must be in (0, 10000) m";
  } else if (spec.direction_deg && !std::isfinite(*spec.direction_deg)) {
    why = "roof direction must be a finite angle";
  } else {
    return true;
  }
  return false;
}

// Requested type, then the shape's own fallback, then hip, then flat (docs/kernel-roofs.md,
// "Fallbacks").
std::array<RoofType, 4> fallback_chain(RoofType asked) {
  RoofType second = RoofType::kHip;
  switch (asked) {
    case RoofType::kGambrel:
      second = RoofType::kMansard;
      break;
    case RoofType::kHalfHipped:
    case RoofType::kSaltbox:
    case RoofType::kRound:
      second = RoofType::kGable;
      break;
    default:
      break;
  }
  return {asked, second, RoofType::kHip, RoofType::kFlat};
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
    case RoofType::kGambrel:
      return "gambrel";
    case RoofType::kHalfHipped:
      return "half_hipped";
    case RoofType::kSaltbox:
      return "saltbox";
    case RoofType::kRound:
      return "round";
    case RoofType::kDome:
      return "dome";
    case RoofType::kOnion:
      return "onion";
  }
  return "flat";
}

std::optional<RoofType> roof_type_from_name(std::string_view name) {
  std::string lower(name);
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (RoofType t : kRoofTypes) {
    if (lower == roof_type_name(t)) return t;
  }
  // Other spellings, OpenStreetMap's roof:shape values among them.
  static constexpr std::pair<std::string_view, RoofType> kAliases[] = {
      {"holedmansard", RoofType::kHoledMansard},
      {"compluvium", RoofType::kHoledMansard},
      {"gabled", RoofType::kGable},
      {"hipped", RoofType::kHip},
      {"pyramidal", RoofType::kPyramid},
      {"skillion", RoofType::kShed},
      {"half-hipped", RoofType::kHalfHipped},
      {"halfhipped", RoofType::kHalfHipped},
      {"half_hip", RoofType::kHalfHipped}};
  for (const auto& [alias, type] : kAliases) {
    if (lower == alias) return type;
  }
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

Contour outline_core(const Contour& c) {
  const std::uint32_t n = c.ring_starts[1];
  std::vector<std::uint32_t> prev(n), next(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    prev[k] = (k + n - 1) % n;
    next[k] = (k + 1) % n;
  }
  const auto turn = [&](std::uint32_t k) {
    const Vec2 in = c.points[k] - c.points[prev[k]];
    const Vec2 out = c.points[next[k]] - c.points[k];
    return std::abs(std::atan2(cross(in, out), dot(in, out))) * 180 / kPi;
  };
  // The straightest vertex first, its neighbours' turns updated after each drop.
  std::vector<double> turns(n);
  std::set<std::pair<double, std::uint32_t>> straight;
  for (std::uint32_t k = 0; k < n; ++k) {
    turns[k] = turn(k);
    if (turns[k] < kCornerMinTurnDeg) straight.insert({turns[k], k});
  }
  std::vector<std::uint8_t> dropped(n, 0);
  std::uint32_t left = n;
  while (!straight.empty() && left > 3) {
    const std::uint32_t k = straight.begin()->second;
    straight.erase(straight.begin());
    next[prev[k]] = next[k];
    prev[next[k]] = prev[k];
    dropped[k] = 1;
    --left;
    for (const std::uint32_t j : {prev[k], next[k]}) {
      straight.erase({turns[j], j});
      turns[j] = turn(j);
      if (turns[j] < kCornerMinTurnDeg) straight.insert({turns[j], j});
    }
  }
  if (left == n) return c;
  Polygon core = c.polygon();
  core.outer.clear();
  for (std::uint32_t k = 0; k < n; ++k) {
    if (!dropped[k]) core.outer.push_back(c.points[k]);
  }
  return Contour::from(core);
}

double shed_distance(const RoofPlan& plan, Vec2 p) {
  return dot(plan.shed_normal, p - plan.shed_origin);
}

bool plan_roof(const Polygon& footprint, const RoofSpec& spec, RoofPlan& plan) {
  if (!spec_valid(spec, plan.message)) return false;
  if (!is_simple_polygon(footprint)) {
    plan.message = "footprint is not a simple polygon with holes";
    return false;
  }
  plan.footprint = Contour::from(footprint);
  plan.party_edges = party_edges(plan.footprint, spec.party_walls, spec.overhang);
  double overhang = spec.overhang;
  // Party walls make the eave polygon's offsets uneven; where that polygon cannot be made, the
  // roof overhangs all round as it would alone rather than nowhere.
  if (overhang > 0 && !plan.party_edges.empty() && !plan_eave(plan, overhang, {})) {
    plan.party_edges.clear();
  }
  // Where the eave cannot go all round (a sharply skewed parallelogram's mitred corners), the
  // types that need it are built without overhang; a gable and the quadrilateral shapes keep
  // theirs, their ends being flush.
  const bool all_round = !(overhang > 0) || plan_eave(plan, overhang, {});
  const auto overhang_for = [&](RoofType type) {
    return all_round || type == RoofType::kGable || is_custom(type) ? overhang : 0.0;
  };
  std::vector<RoofType> tried;
  std::string why;  // the stage and finding that stopped the asked type
  for (RoofType type : fallback_chain(spec.type)) {
    if (std::find(tried.begin(), tried.end(), type) != tried.end()) continue;
    tried.push_back(type);
    double used = overhang_for(type);
    bool planned = plan_type(plan, spec, type, used);
    if (!planned && why.empty()) why = plan.reason;
    // Another type than the one asked, where the eave cannot go all round: without overhang, as
    // the types that need that eave are built.
    if (!planned && !all_round && used > 0 && type != spec.type) {
      used = 0;
      planned = plan_type(plan, spec, type, 0);
    }
    if (planned) {
      if (used < overhang) {
        plan.message = "overhang of " + base::shortest_number(overhang) +
                       " m makes the eave polygon self-intersect or reach too far out at a sharp "
                       "corner; built without overhang";
      }
      if (type != spec.type) {
        if (!plan.message.empty()) plan.message += "; ";
        plan.message += std::string(roof_type_name(spec.type)) + " roof could not be built; " +
                        std::string(roof_type_name(type)) + " roof instead";
        if (!why.empty()) plan.message += " (" + why + ")";
      }
      if (springs_from_wall(type) && used > 0) {
        if (!plan.message.empty()) plan.message += "; ";
        plan.message += std::string(roof_type_name(type)) + " roofs are built without overhang";
      }
      plan.status = plan.message.empty() ? RoofStatus::kOk : RoofStatus::kFallback;
      return true;
    }
    // The asked type without its overhang is nearer what was asked than another type with it:
    // an 8 cm jog in a real outline made the overhanging eave's skeleton end a ridge elsewhere,
    // and one gable in nine became a hip.
    if (type == spec.type && overhang_for(type) > 0 && plan_type(plan, spec, type, 0)) {
      if (!plan.message.empty()) plan.message += "; ";
      plan.message +=
          std::string(roof_type_name(type)) + " roof built without overhang (" + why + ")";
      plan.status = RoofStatus::kFallback;
      return true;
    }
  }
  plan.message = "no roof could be built" + (why.empty() ? "" : " (" + why + ")");
  return false;
}

}  // namespace roof_detail

namespace {
// The highest point of the roof emitted from `first_vertex` on.
double roof_top(const Mesh& mesh, std::size_t first_vertex) {
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t v = first_vertex; v < mesh.vertex_count(); ++v) {
    top = std::max(top, mesh.positions()[v].z);
  }
  return top;
}
}  // namespace

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
  const std::size_t first_vertex = mesh.vertex_count();
  roof_detail::emit_roof(plan, eave_z, mesh, build);
  if (plan.type != RoofType::kFlat && plan.type != RoofType::kShed) {
    // A shed's slope is set from the height in planning, keeping its fascia's thickness.
    if (spec.height) {
      scale_roof_height(mesh, eave_z, *spec.height, first_vertex);
    } else if (spec.height_limit && roof_top(mesh, first_vertex) - eave_z > *spec.height_limit) {
      scale_roof_height(mesh, eave_z, *spec.height_limit, first_vertex);
    }
  }
  build.status = plan.status;
  build.built = plan.type;
  build.message = plan.message;
  return build;
}

void scale_roof_height(Mesh& mesh, double eave_z, double height, std::size_t first_vertex) {
  // Scaling about eave_z would scale the overhang's drop below it too: a 1 m² part with a 3.5 m
  // roof got its soffit 4.2 m below its walls' top, under the ground.
  double low = eave_z, top = eave_z;
  for (std::size_t v = first_vertex; v < mesh.vertex_count(); ++v) {
    const double z = mesh.positions()[v].z;
    low = std::min(low, z);
    top = std::max(top, z);
  }
  if (!(height > 0) || !(top - low > 1e-9)) return;
  const double k = height / (top - low);
  for (std::size_t v = first_vertex; v < mesh.vertex_count(); ++v) {
    Vec3& p = mesh.positions()[v];
    p.z = eave_z + (p.z - low) * k;
  }
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
