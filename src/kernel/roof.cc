// Roof planning: which type can be built, the overhang's eave polygon, the gable ends, the shed
// plane (docs/kernel-roofs.md). Emission of faces is in roof_emit.cc; the mansard split in
// roof_mansard.cc. Planning does everything that can fail, so emission never has to undo writes to
// the caller's mesh.
#include "kernel/roof.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

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

// Seed 000 §4.6 hip faces become gables where a ridge ends: see docs/kernel-roofs.md.
std::optional<GableEnd> gable_end(const Skeleton& s, const Contour& c,
                                  const std::vector<std::uint32_t>& face_count, std::uint32_t e) {
  const auto loop = s.face(e);
  if (loop.size() != 3 || loop[2] < s.contour_count || face_count[loop[2]] != 3) {
    return std::nullopt;
  }
  const std::uint32_t prev = c.prev(e);
  const std::uint32_t next = c.next(e);
  const Vec2 dp = normalized(c.points[e] - c.points[prev]);
  const Vec2 dn = normalized(c.points[c.next(next)] - c.points[next]);
  if (dot(dp, dn) > -std::cos(kGableParallelDeg * kPi / 180)) return std::nullopt;
  // The ridge point on edge e's line: equally far from the neighbouring edges' lines.
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
  return GableEnd{e, loop[2], apex, time};
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

bool plan_gable(RoofPlan& plan, const RoofSpec& spec) {
  auto base = interior_straight_skeleton(plan.footprint.polygon());
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
  plan.skeleton = interior_straight_skeleton(plan.eave.polygon());
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
    plan.skeleton = interior_straight_skeleton(plan.eave.polygon());
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
