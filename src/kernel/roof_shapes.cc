// The remaining shapes of OpenStreetMap's Simple 3D Buildings (docs/kernel-roofs.md, "S3DB
// shapes"), planned as explicit faces: on a quadrilateral, two-sided profiles across a ridge
// (gambrel, saltbox, round) and the half-hipped gable; over a footprint star-shaped about its
// centroid, a dome or an onion of scaled copies of the outline.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "kernel/roof_detail.h"

namespace insula::kernel::roof_detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::uint32_t kQuad = 4;

// f(p) = dot(g, p) + h.
struct Linear {
  Vec2 g;
  double h = 0;
  double at(Vec2 p) const { return dot(g, p) + h; }
};

Linear distance_function(const Contour& c, std::uint32_t e) {
  const Vec2 a = c.points[e];
  const Vec2 n = perp(normalized(c.points[c.next(e)] - a));
  return {n, -dot(n, a)};
}

// Sutherland-Hodgman: the part of `poly` where f >= 0, a point within `tolerance` of the line
// counting as on it. Without the tolerance a ridge that runs along a cut line (a rectangle's
// crest, where both are the same line up to rounding) would be cut at a random point, which
// the neighbouring face does not have.
std::vector<Vec2> clip(const std::vector<Vec2>& poly, const Linear& f, double tolerance) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 p = poly[i];
    const Vec2 q = poly[(i + 1) % poly.size()];
    const double fp = f.at(p), fq = f.at(q);
    const bool p_in = fp >= -tolerance, q_in = fq >= -tolerance;
    if (p_in) out.push_back(p);
    if (p_in != q_in && std::abs(fp) > tolerance && std::abs(fq) > tolerance) {
      out.push_back(p + (q - p) * (fp / (fp - fq)));
    }
  }
  return out;
}

// A roof's points, merged within a tolerance so faces clipped separately share their vertices.
// The footprint's vertices come first; the height the roof has over each is kept as its eave rise.
class PointSet {
 public:
  PointSet(const Contour& c, double tolerance)
      : tolerance_(tolerance), count_(c.size()), rise_(c.size(), 0) {
    for (const Vec2& p : c.points) points_.push_back(lift(p, 0));
  }
  std::uint32_t id(Vec3 p) {
    for (std::uint32_t k = 0; k < points_.size(); ++k) {
      if (length(drop(points_[k]) - drop(p)) > tolerance_) continue;
      // A corner of the core is at the eave up to rounding; a dropped vertex is not.
      if (k < count_ && std::abs(p.z) > 1e-9) rise_[k] = p.z;
      return k;
    }
    points_.push_back(p);
    return static_cast<std::uint32_t>(points_.size() - 1);
  }
  void move_to(CustomRoof& roof) const {
    roof.points.assign(points_.begin() + count_, points_.end());
    if (std::any_of(rise_.begin(), rise_.end(), [](double z) { return z != 0; })) {
      roof.eave_rise = rise_;
    }
  }
  std::span<const Vec3> all() const { return points_; }

 private:
  double tolerance_;
  std::uint32_t count_;
  std::vector<Vec3> points_;
  std::vector<double> rise_;
};

double extent(const Contour& c) {
  Vec2 lo = c.points[0], hi = lo;
  for (const Vec2& p : c.points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  return length(hi - lo);
}

void add_face(CustomRoof& roof, std::vector<std::uint32_t> loop) {
  loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
  while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
  if (loop.size() < 3) return;
  roof.face_indices.insert(roof.face_indices.end(), loop.begin(), loop.end());
  roof.face_offsets.push_back(static_cast<std::uint32_t>(roof.face_indices.size()));
}

// The wall above edge e is closed by every roof point on it, from its end back to its start.
std::vector<std::uint32_t> cap_on_edge(const Contour& c, std::uint32_t e,
                                       std::span<const Vec3> points, double tolerance) {
  const Vec2 a = c.points[e];
  const Vec2 d = c.points[c.next(e)] - a;
  const Linear f = distance_function(c, e);
  std::vector<std::pair<double, std::uint32_t>> on;
  for (std::uint32_t k = c.size(); k < points.size(); ++k) {
    const Vec2 p = drop(points[k]);
    const double s = dot(p - a, d) / dot(d, d);
    if (std::abs(f.at(p)) <= tolerance && s > 0 && s < 1) on.emplace_back(-s, k);
  }
  std::sort(on.begin(), on.end());
  std::vector<std::uint32_t> cap;
  for (const auto& [s, k] : on) cap.push_back(k);
  return cap;
}

// One side of a profile roof: heights rise from the slope edge as z = z_k + slope_k * (d - t_k)
// on [t_k, t_{k+1}), d the distance from the edge; the last piece runs on to the ridge.
struct Piece {
  double t = 0, z = 0, slope = 0;
};

struct QuadFrame {
  std::uint32_t side_a = 0, side_b = 2;  // slope edges
  double half_width = 0;                 // plan distance from a slope edge to the ridge
  double widest = 0;                     // the same at the wider end
};

bool quad_frame(const Contour& c, const RoofSpec& spec, QuadFrame& frame) {
  if (c.ring_starts.size() != 2 || c.size() != kQuad) return false;
  const std::uint32_t r = quad_slope_pair(c, spec);
  frame.side_a = r;
  frame.side_b = r + 2;
  const std::optional<GableEnd> end1 = gable_apex(c, r + 1);
  const std::optional<GableEnd> end3 = gable_apex(c, (r + 3) % kQuad);
  if (!end1 || !end3) return false;
  frame.half_width = std::min(end1->time, end3->time);
  frame.widest = std::max(end1->time, end3->time);
  return frame.half_width > 0;
}

// How far the eave lines of the two slope sides lie outside the core's slope edges: distances from
// an eave line are the core's plus these. Both 0 without overhang.
struct EaveShift {
  double a = 0, b = 0;
};

// Per footprint edge, the side of the quadrilateral `core` (outline_core of `c`, or `c` itself)
// it runs along: outline_core copies the corners, so the footprint vertex equal to core vertex i
// starts side i, and the edges after it up to the next corner belong to that side.
std::vector<std::uint32_t> core_sides(const Contour& c, const Contour& core) {
  const std::uint32_t n = c.size();
  std::vector<int> corner(n, -1);
  for (std::uint32_t k = 0; k < n; ++k) {
    for (std::uint32_t i = 0; i < core.size(); ++i) {
      if (c.points[k] == core.points[i]) corner[k] = static_cast<int>(i);
    }
  }
  std::uint32_t start = 0;
  while (start < n && corner[start] < 0) ++start;
  std::vector<std::uint32_t> side(n, 0);
  if (start == n) return side;
  std::uint32_t current = static_cast<std::uint32_t>(corner[start]);
  for (std::uint32_t m = 0; m < n; ++m) {
    const std::uint32_t k = (start + m) % n;
    if (corner[k] >= 0) current = static_cast<std::uint32_t>(corner[k]);
    side[k] = current;
  }
  return side;
}

// The eave polygon of a quadrilateral shape with overhang (docs/kernel-roofs.md, "Overhang"): the
// edges along slope side A move out by `out_a`, those along side B by `out_b`, the ends stay flush
// (offset 0, as a gable's), and so do party walls. `overhang` sets the drop: the roof starts at
// eave_z - overhang * eave_slope. Every eave vertex of an overhanging side lies on that side's
// eave line, the core's slope edge moved out, so the roof, planned from those lines, meets every
// soffit at the eave (the soffits are horizontal whatever their shape). An eave corner is where
// the eave line meets the flush edge next to it; a vertex outline_core dropped on the side is not
// mitred from its own edges but divides the eave edge between the side's two eave corners as it
// divides the side (a perpendicular projection would flip a 5 cm edge at a skewed end). False,
// with the reason, when the eave polygon cannot be made or a party wall keeps only part of a side
// flush (its eave line would bend).
bool overhang_eave(RoofPlan& plan, const Contour& core, std::uint32_t side_a, std::uint32_t side_b,
                   double overhang, double out_a, double out_b, EaveShift& shift) {
  shift = {};
  if (!(overhang > 0)) return true;
  const Contour& c = plan.footprint;
  const std::uint32_t n = c.size();
  const std::vector<std::uint32_t> sides = core_sides(c, core);
  plan.overhang = overhang;
  plan.offsets.assign(n, 0);
  for (std::uint32_t k = 0; k < n; ++k) {
    plan.offsets[k] = sides[k] == side_a ? out_a : sides[k] == side_b ? out_b : 0;
  }
  for (std::uint32_t e : plan.party_edges) plan.offsets[e] = 0;
  plan.custom.ends.assign(n, 0);
  for (std::uint32_t k = 0; k < n; ++k) {
    plan.custom.ends[k] = sides[k] != side_a && sides[k] != side_b;
  }
  std::array<double, kQuad> side_offset{-1, -1, -1, -1};
  for (std::uint32_t k = 0; k < n; ++k) {
    double& o = side_offset[sides[k]];
    if (o < 0) {
      o = plan.offsets[k];
    } else if (o != plan.offsets[k]) {
      plan.reason = "roof faces: a party wall keeps only part of a slope side flush";
      return false;
    }
  }
  // Each edge's eave line: its side's core edge moved out, or the edge itself when flush.
  std::vector<Vec2> from(n), along(n);
  for (std::uint32_t e = 0; e < n; ++e) {
    if (plan.offsets[e] > 0) {
      const std::uint32_t side = sides[e];
      along[e] = normalized(core.points[(side + 1) % kQuad] - core.points[side]);
      from[e] = core.points[side] - perp(along[e]) * plan.offsets[e];
    } else {
      along[e] = normalized(c.points[c.next(e)] - c.points[e]);
      from[e] = c.points[e];
    }
  }
  plan.reason = "roof faces: the eave polygon of the overhang is not simple";
  Contour& eave = plan.eave;
  eave.ring_starts = c.ring_starts;
  eave.points.resize(n);
  const auto inside_side = [&](std::uint32_t k) {
    const std::uint32_t p = c.prev(k);
    return plan.offsets[p] > 0 && plan.offsets[k] > 0 && sides[p] == sides[k];
  };
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t p = c.prev(k);
    if (inside_side(k)) continue;
    if (plan.offsets[p] == 0 && plan.offsets[k] == 0) {
      eave.points[k] = c.points[k];
      continue;
    }
    const double det = cross(along[p], along[k]);
    if (std::abs(det) < 1e-9) return false;
    eave.points[k] = from[p] + along[p] * (cross(from[k] - from[p], along[k]) / det);
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    if (!inside_side(k)) continue;
    std::uint32_t first = k, last = k;
    double before = 0, after = 0;
    for (std::uint32_t steps = 0; inside_side(first) && steps < n; ++steps) {
      before += length(c.points[first] - c.points[c.prev(first)]);
      first = c.prev(first);
    }
    for (std::uint32_t steps = 0; inside_side(last) && steps < n; ++steps) {
      after += length(c.points[c.next(last)] - c.points[last]);
      last = c.next(last);
    }
    if (inside_side(first) || inside_side(last)) return false;
    eave.points[k] =
        eave.points[first] + (eave.points[last] - eave.points[first]) * (before / (before + after));
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    if (length(eave.points[k] - c.points[k]) > kEaveMiterLimit * std::max(out_a, out_b))
      return false;
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    const Vec2 before = c.points[c.next(k)] - c.points[k];
    const Vec2 after = eave.points[eave.next(k)] - eave.points[k];
    if (dot(before, after) <= 0) return false;
  }
  if (!is_simple_polygon(eave.polygon())) return false;
  shift = {side_offset[side_a], side_offset[side_b]};
  return true;
}

// The wall caps of every footprint edge: the roof points on it.
void add_caps(const Contour& c, const PointSet& points, double tolerance, CustomRoof& roof) {
  roof.caps.assign(c.size(), {});
  for (std::uint32_t e = 0; e < c.size(); ++e) {
    roof.caps[e] = cap_on_edge(c, e, points.all(), tolerance);
  }
}

// Faces of a two-sided profile roof over footprint `c`, its slope edges those of `frame` on the
// quadrilateral `core` (outline_core of `c`): side A where ka * d_a <= kb * d_b, side B the rest.
// The faces are cut from `c` itself, so a vertex the core dropped keeps its place in the roof,
// at the height the profile has there.
// With overhang, `c` is the eave polygon and the distances are measured from the eave lines,
// `shift` outside the core's slope edges.
void profile_faces(const Contour& c, const Contour& core, const QuadFrame& frame, EaveShift shift,
                   const std::vector<Piece>& a, const std::vector<Piece>& b, double ka, double kb,
                   CustomRoof& roof) {
  const double tolerance = 1e-7 * extent(c);
  PointSet points(c, tolerance);
  Linear da = distance_function(core, frame.side_a);
  Linear db = distance_function(core, frame.side_b);
  da.h += shift.a;
  db.h += shift.b;
  const std::vector<Vec2> outline(c.points.begin(), c.points.end());
  const auto side = [&](const Linear& mine, const Linear& other, double km, double ko,
                        const std::vector<Piece>& profile) {
    const Linear split{other.g * ko - mine.g * km, other.h * ko - mine.h * km};
    const std::vector<Vec2> region = clip(outline, split, tolerance);
    for (std::size_t k = 0; k < profile.size(); ++k) {
      const Piece& piece = profile[k];
      // The first piece reaches out to footprint vertices just outside the core's slope edge.
      std::vector<Vec2> poly =
          k == 0 ? region : clip(region, {mine.g, mine.h - piece.t}, tolerance);
      if (k + 1 < profile.size()) {
        poly = clip(poly, {-mine.g, profile[k + 1].t - mine.h}, tolerance);
      }
      std::vector<std::uint32_t> loop;
      for (const Vec2& p : poly) {
        loop.push_back(points.id(lift(p, piece.z + piece.slope * (mine.at(p) - piece.t))));
      }
      add_face(roof, std::move(loop));
    }
  };
  side(da, db, ka, kb, a);
  side(db, da, kb, ka, b);
  add_caps(c, points, tolerance, roof);
  points.move_to(roof);
}

// Gambrel: the mansard's two slopes with gable ends. The break lies where the lower slope has
// risen mansard_break_height, but at most 60 % of the way to the ridge. With overhang the slope
// sides' eaves move out and the lower slope starts overhang * tan(lower pitch) below the eave, so
// the break, `overhang + t` from the eave lines, is where and as high as it is without.
bool plan_gambrel(RoofPlan& plan, const RoofSpec& spec, const Contour& core, double overhang) {
  QuadFrame frame;
  if (!quad_frame(core, spec, frame)) return false;
  const double lower = std::tan(spec.mansard_pitch_deg * kPi / 180);
  const double upper = plan.slope;
  const double t = std::min(spec.mansard_break_height / lower, 0.6 * frame.half_width);
  EaveShift shift;
  if (!overhang_eave(plan, core, frame.side_a, frame.side_b, overhang, overhang, overhang, shift)) {
    return false;
  }
  const double t_break = plan.overhang + t;
  const std::vector<Piece> profile = {{0, 0, lower}, {t_break, t_break * lower, upper}};
  profile_faces(plan.eave, core, frame, shift, profile, profile, 1, 1, plan.custom);
  return true;
}

// Saltbox: the ridge a third of the way across, the short side twice as steep as the long one
// (which has the pitch); both eaves at the same height. The long side faces direction_deg when
// given, else it rises from the second slope edge.
bool plan_saltbox(RoofPlan& plan, const RoofSpec& spec, const Contour& core, double overhang) {
  QuadFrame frame;
  if (!quad_frame(core, spec, frame)) return false;
  if (spec.direction_deg) {
    const double a = *spec.direction_deg * kPi / 180;
    const Vec2 downhill{std::sin(a), std::cos(a)};
    const Contour& c = core;
    const auto outward = [&](std::uint32_t e) {
      return -perp(normalized(c.points[c.next(e)] - c.points[e]));
    };
    if (dot(outward(frame.side_a), downhill) > dot(outward(frame.side_b), downhill)) {
      std::swap(frame.side_a, frame.side_b);
    }
  }
  const double s = plan.slope;
  const double steep = 2 * s;
  // Both soffits at one height: the long side's eave drops overhang * s (plan.eave_slope), so the
  // steep side overhangs overhang * s / steep, which drops as much (half the overhang here, the
  // steep side having twice the slope; with pitch angles, tan(2 * pitch) != 2 * tan(pitch), so
  // the offset is computed from the slopes, not halved).
  EaveShift shift;
  if (!overhang_eave(plan, core, frame.side_a, frame.side_b, overhang, overhang * s / steep,
                     overhang, shift)) {
    return false;
  }
  profile_faces(plan.eave, core, frame, shift, {{0, 0, steep}}, {{0, 0, s}}, 2, 1, plan.custom);
  return true;
}

// Round: a barrel vault whose cross-section is a quarter circle on each side (a half circle over
// the width; height = half the width before RoofSpec::height scales it), in 6 planar strips per
// side.
bool plan_round(RoofPlan& plan, const RoofSpec& spec, const Contour& core) {
  QuadFrame frame;
  if (!quad_frame(core, spec, frame)) return false;
  constexpr int kStrips = 6;
  const double w = frame.half_width;
  // The first strip is steep and narrow (3.4 % of the half width): a corner the core dropped that
  // lies further inside than half of it is not reached by the strip's lower edge, and the roof
  // would leave it open (a 54 x 10.5 m outline dented 0.2 m). Such an outline is no quadrilateral
  // for a barrel.
  const double first_strip = w * (1 - std::cos(kPi / 2 / kStrips));
  for (const Vec2& p : plan.footprint.points) {
    double inside = 1e300;
    for (std::uint32_t e = 0; e < core.size(); ++e) {
      inside = std::min(inside, distance_function(core, e).at(p));
    }
    if (inside > first_strip / 2) return false;
  }
  std::vector<Piece> profile;
  for (int k = 0; k < kStrips; ++k) {
    const double a0 = kPi / 2 * k / kStrips, a1 = kPi / 2 * (k + 1) / kStrips;
    const double t0 = w * (1 - std::cos(a0)), t1 = w * (1 - std::cos(a1));
    profile.push_back({t0, w * std::sin(a0), w * (std::sin(a1) - std::sin(a0)) / (t1 - t0)});
  }
  // A crest where the ridge runs wider than the narrower end; not when it would be a sliver (a
  // parallelogram skewed by 0.15 degrees had a crest 1.4 micrometres wide, a degenerate face in
  // OBJ's six decimals): under 1 % of the half width the last strip runs on to the ridge, at most
  // 0.13 % of the half width higher than the circle.
  if (frame.widest - w > 0.01 * w) profile.push_back({w, w, 0});
  profile_faces(plan.footprint, core, frame, {}, profile, profile, 1, 1, plan.custom);
  return true;
}

// Half-hipped: the gable's end walls stop halfway up, where a small hip at the roof's pitch
// takes over and meets the ridge set back from the end. The roof is the lower envelope of four
// planes at the pitch: the two slopes, rising from the slope edges, and the two hips, rising from
// the lines half a gable's height up each end wall (distance T/2 + d_end, T the gable apex's
// distance from the slope edges); each plane's face is the part of the footprint where it is
// lowest. With overhang, the slope planes rise from the eave lines of the slope sides, and the
// hips, overhang * tan(pitch) higher above the lowered eave, are where they are without: the
// faces are cut from the eave polygon (ends flush), the roof over the walls is unchanged.
bool plan_half_hipped(RoofPlan& plan, const RoofSpec& spec, const Contour& core, double overhang) {
  if (core.ring_starts.size() != 2 || core.size() != kQuad) return false;
  const std::uint32_t r = quad_slope_pair(core, spec);
  const std::uint32_t e1 = r + 1, e3 = (r + 3) % kQuad;
  const std::optional<GableEnd> g1 = gable_apex(core, e1);
  const std::optional<GableEnd> g3 = gable_apex(core, e3);
  if (!g1 || !g3) return false;
  const double ridge = length(g3->apex - g1->apex);
  if (!(g1->time / 2 + g3->time / 2 < 0.9 * ridge)) return false;
  EaveShift shift;
  if (!overhang_eave(plan, core, r, r + 2, overhang, overhang, overhang, shift)) return false;
  const Contour& c = plan.eave;
  const Linear side_a = distance_function(core, r);
  const Linear side_b = distance_function(core, r + 2);
  const Linear hip1 = distance_function(core, e1);
  const Linear hip3 = distance_function(core, e3);
  const std::array<Linear, 4> planes = {Linear{side_a.g, side_a.h + shift.a},
                                        Linear{side_b.g, side_b.h + shift.b},
                                        Linear{hip1.g, hip1.h + g1->time / 2 + plan.overhang},
                                        Linear{hip3.g, hip3.h + g3->time / 2 + plan.overhang}};
  const double s = plan.slope;
  const double tolerance = 1e-7 * extent(c);
  PointSet points(c, tolerance);
  const std::vector<Vec2> outline(c.points.begin(), c.points.end());
  CustomRoof& roof = plan.custom;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    std::vector<Vec2> poly = outline;
    for (std::size_t j = 0; j < planes.size() && !poly.empty(); ++j) {
      if (j != i) {
        poly = clip(poly, {planes[j].g - planes[i].g, planes[j].h - planes[i].h}, tolerance);
      }
    }
    std::vector<std::uint32_t> loop;
    for (const Vec2& p : poly) loop.push_back(points.id(lift(p, planes[i].at(p) * s)));
    add_face(roof, std::move(loop));
  }
  add_caps(c, points, tolerance, roof);
  points.move_to(roof);
  return true;
}

// Dome and onion: copies of the outline scaled about its centroid, stacked on a profile; each
// band between two copies is a trapezoid per edge, so planar. Defined when the centroid sees
// every edge from its inner side (the footprint is star-shaped about it).
bool plan_dome(RoofPlan& plan, bool onion) {
  const Contour& c = plan.footprint;
  if (c.ring_starts.size() != 2) return false;
  const Vec2 center = centroid(c.polygon());
  double nearest = 1e300;
  for (std::uint32_t e = 0; e < c.size(); ++e) {
    nearest = std::min(nearest, edge_distance(c, e, center));
  }
  if (!(nearest > 1e-3 * extent(c))) return false;
  // (scale of the outline, height as a fraction of the top); the dome a quarter circle.
  std::vector<std::pair<double, double>> profile;
  if (onion) {
    profile = {{1.1, 0.05},  {1.22, 0.13}, {1.28, 0.22}, {1.27, 0.3},  {1.18, 0.4},  {1.0, 0.49},
               {0.75, 0.57}, {0.5, 0.64},  {0.3, 0.71},  {0.17, 0.78}, {0.09, 0.86}, {0.04, 0.93}};
  } else {
    constexpr int kRings = 8;
    for (int k = 1; k < kRings; ++k) {
      const double a = kPi / 2 * k / kRings;
      profile.emplace_back(std::cos(a), std::sin(a));
    }
  }
  // A hemisphere over a circle: the top as high as the centroid is far from the edges (an onion
  // twice as high, its spire included).
  const double top = nearest * (onion ? 2.0 : 1.0);
  const std::uint32_t n = c.size();
  CustomRoof& roof = plan.custom;
  std::vector<std::uint32_t> below(n);
  for (std::uint32_t k = 0; k < n; ++k) below[k] = k;
  std::vector<std::uint32_t> ring(n);
  for (const auto& [scale, z] : profile) {
    for (std::uint32_t k = 0; k < n; ++k) {
      ring[k] = n + static_cast<std::uint32_t>(roof.points.size());
      roof.points.push_back(lift(center + (c.points[k] - center) * scale, z * top));
    }
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t j = (k + 1) % n;
      add_face(roof, {below[k], below[j], ring[j], ring[k]});
    }
    below = ring;
  }
  const std::uint32_t apex = n + static_cast<std::uint32_t>(roof.points.size());
  roof.points.push_back(lift(center, top));
  for (std::uint32_t k = 0; k < n; ++k) add_face(roof, {below[k], below[(k + 1) % n], apex});
  roof.caps.assign(n, {});
  return true;
}

}  // namespace

std::uint32_t quad_slope_pair(const Contour& c, const RoofSpec& spec) {
  const auto dir = [&](std::uint32_t e) {
    return normalized(c.points[(e + 1) % kQuad] - c.points[e]);
  };
  const auto len = [&](std::uint32_t e) { return length(c.points[(e + 1) % kQuad] - c.points[e]); };
  if (spec.direction_deg) {
    // The ridge runs perpendicular to the downhill direction, along the slope edges.
    const double a = *spec.direction_deg * kPi / 180;
    const Vec2 downhill{std::sin(a), std::cos(a)};
    const double across0 = std::abs(dot(dir(0), downhill)) + std::abs(dot(dir(2), downhill));
    const double across1 = std::abs(dot(dir(1), downhill)) + std::abs(dot(dir(3), downhill));
    return across0 <= across1 ? 0 : 1;
  }
  const double pair0 = len(0) + len(2), pair1 = len(1) + len(3);
  const std::uint32_t along = pair0 >= pair1 ? 0 : 1;
  switch (spec.orientation) {
    case RidgeOrientation::kAlong:
      return along;
    case RidgeOrientation::kAcross:
      return 1 - along;
    case RidgeOrientation::kAuto:
      break;
  }
  // Within 5 % of a square the first edge decides (docs/kernel-roofs.md, "Square footprints").
  return std::abs(pair0 - pair1) <= 0.05 * std::max(pair0, pair1) ? 0 : along;
}

namespace {

bool plan_shape(RoofPlan& plan, const RoofSpec& spec, const Contour& core, double overhang) {
  switch (plan.type) {
    case RoofType::kGambrel:
      return plan_gambrel(plan, spec, core, overhang);
    case RoofType::kSaltbox:
      return plan_saltbox(plan, spec, core, overhang);
    case RoofType::kRound:
      return plan_round(plan, spec, core);
    case RoofType::kHalfHipped:
      return plan_half_hipped(plan, spec, core, overhang);
    case RoofType::kDome:
      return plan_dome(plan, false);
    case RoofType::kOnion:
      return plan_dome(plan, true);
    default:
      return false;
  }
}

// The overhanging shape meets its soffits edge to edge: the roof passes through every eave vertex
// of an overhanging edge (a vertex outline_core dropped would put the roof above or below the
// soffit's outer corner there) and has no point inside an overhanging eave edge (its wall is
// closed by the soffit, not a cap).
bool meets_soffits(RoofPlan& plan) {
  const Contour& c = plan.footprint;
  const CustomRoof& roof = plan.custom;
  for (std::uint32_t k = 0; k < c.size(); ++k) {
    const bool overhangs = plan.offsets[k] > 0 || plan.offsets[c.prev(k)] > 0;
    if (overhangs && !roof.eave_rise.empty() && roof.eave_rise[k] != 0) {
      plan.reason = "roof faces: a vertex between the corners of a slope side is off its eave line";
      return false;
    }
    if (plan.offsets[k] > 0 && k < roof.caps.size() && !roof.caps[k].empty()) {
      plan.reason = "roof faces: the roof has a point inside an overhanging eave";
      return false;
    }
  }
  return true;
}

}  // namespace

bool plan_custom(RoofPlan& plan, const RoofSpec& spec, double overhang) {
  plan.custom = CustomRoof();
  // The quadrilateral shapes are planned over the corners; their faces still cover every vertex.
  const Contour core =
      plan.footprint.ring_starts[1] > kQuad ? outline_core(plan.footprint) : plan.footprint;
  if (!plan_shape(plan, spec, core, overhang)) return false;
  return !(plan.overhang > 0) || meets_soffits(plan);
}

}  // namespace insula::kernel::roof_detail
