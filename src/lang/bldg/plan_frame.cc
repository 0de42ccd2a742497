// The building's own frame (seed 000 §3.2: the treemap is "a simplified axis-aligned version of the
// oriented bounding boxes' subdivision"): a lot turned 11 degrees, as most register footprints
// are, is planned in the frame of its walls, so rooms are cut along the walls and not across them
// in diamonds. docs/bldg-floorplan.md, "The building's frame". Also a plan's translation.
#include <cmath>
#include <numbers>

#include "lang/bldg/plan_stages.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;
using kernel::Vec2;

constexpr double kQuarter = std::numbers::pi / 2;
// Edges within this angle of a direction (modulo 90 degrees) count as running along it.
constexpr double kAlong = 3 * std::numbers::pi / 180;

// Direction of p->q modulo 90 degrees, in [0, pi/2).
double quarter_angle(Vec2 p, Vec2 q) {
  double a = std::fmod(std::atan2(q.y - p.y, q.x - p.x), kQuarter);
  if (a < 0) a += kQuarter;
  return a >= kQuarter ? 0 : a;
}

double quarter_distance(double a, double b) {
  const double d = std::abs(a - b);
  return std::min(d, kQuarter - d);
}

Vec2 turn(Vec2 p, Vec2 pivot, double c, double s) {
  const Vec2 d = p - pivot;
  return {pivot.x + c * d.x - s * d.y, pivot.y + s * d.x + c * d.y};
}

// Rounds to the boolean grid (kernel/boolean2d.h rounds to micrometres anyway), so walls the
// rotation left a few 1e-15 m off the axes lie on them again.
double snap(double v) {
  return std::round(v * 1e6) / 1e6;
}

// Calls `point` on every position of the plan (not on directions or lengths).
template <typename F>
void each_point(FloorPlan& plan, F point) {
  auto polygon = [&](Polygon& p) {
    for (Vec2& v : p.outer) point(v);
    for (kernel::Ring& h : p.holes)
      for (Vec2& v : h) point(v);
  };
  auto door = [&](PlanDoor& d) {
    point(d.a);
    point(d.b);
    point(d.center);
  };
  polygon(plan.outline);
  for (Polygon& p : plan.footprint) polygon(p);
  for (PlanPart& part : plan.parts) polygon(part.outline);
  for (PlanStorey& storey : plan.storeys) {
    for (PlanRoom& r : storey.rooms) polygon(r.cell);
    for (PlanWall& w : storey.walls) {
      point(w.a);
      point(w.b);
    }
    for (PlanDoor& d : storey.doors) door(d);
    for (PlanDoor& d : storey.entrances) door(d);
    for (PlanWindow& w : storey.windows) {
      point(w.a);
      point(w.b);
      point(w.center);
    }
    for (PlanStair& st : storey.stairs) {
      polygon(st.footprint);
      point(st.foot);
      point(st.head);
    }
    for (PlanDeadZone& z : storey.dead_zones) polygon(z.cell);
  }
}

}  // namespace

PlanFrame lot_frame(const Polygon& outline) {
  // The direction the most wall length runs along (modulo 90 degrees), its longest edge's exactly.
  std::vector<std::pair<double, double>> edges;  // angle, length
  auto add_ring = [&](const kernel::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 p = ring[i];
      const Vec2 q = ring[(i + 1) % ring.size()];
      edges.push_back({quarter_angle(p, q), kernel::length(q - p)});
    }
  };
  add_ring(outline.outer);
  for (const kernel::Ring& h : outline.holes) add_ring(h);
  double best_score = -1;
  double best_length = 0;
  double angle = 0;
  for (const auto& [a, len] : edges) {
    double score = 0;
    for (const auto& [b, other] : edges)
      score += other * std::max(0.0, 1 - quarter_distance(a, b) / kAlong);
    if (score > best_score + 1e-9 || (score > best_score - 1e-9 && len > best_length)) {
      best_score = score;
      best_length = len;
      angle = a;
    }
  }
  if (angle > kQuarter / 2) angle -= kQuarter;
  PlanFrame frame;
  if (std::abs(angle) < 1e-9) return frame;  // axis-aligned lots are planned as they are
  frame.angle = angle;
  const kernel::Bounds2 box = kernel::bounds(outline);
  frame.pivot = {snap((box.min.x + box.max.x) / 2), snap((box.min.y + box.max.y) / 2)};
  return frame;
}

void into_frame(Polygon& outline, const PlanFrame& frame) {
  if (!frame.rotated()) return;
  const double c = std::cos(-frame.angle);
  const double s = std::sin(-frame.angle);
  auto move = [&](kernel::Ring& ring) {
    for (Vec2& v : ring) {
      v = turn(v, frame.pivot, c, s);
      v = {snap(v.x), snap(v.y)};
    }
  };
  move(outline.outer);
  for (kernel::Ring& h : outline.holes) move(h);
}

void out_of_frame(FloorPlan& plan, const PlanFrame& frame) {
  if (!frame.rotated()) return;
  const double c = std::cos(frame.angle);
  const double s = std::sin(frame.angle);
  each_point(plan, [&](Vec2& v) { v = turn(v, frame.pivot, c, s); });
}

}  // namespace insula::lang::bldg::plan

namespace insula::lang::bldg {

void translate(FloorPlan& plan, kernel::Vec2 offset) {
  plan::each_point(plan, [offset](kernel::Vec2& v) { v += offset; });
}

}  // namespace insula::lang::bldg
