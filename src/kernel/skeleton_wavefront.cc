// Straight skeleton of any simple polygon by a kinetic wavefront in double precision.
//
// Each contour edge e moves inward at unit speed: at time t it lies on the line
// dot(n_e, x) = c_e + t (n_e its inward unit normal). A wavefront vertex sits where the lines of
// its two edges meet and moves along their bisector. The simulation repeatedly takes the earliest
// event over the whole wavefront, found by brute force (the outlines it is used for have a few
// dozen vertices):
//  - edge event: a wavefront edge between vertices a and b shrinks to a point where the lines of
//    a's other edge, the edge and b's other edge are concurrent; a and b end there and one vertex
//    between the two outer edges starts;
//  - split event: a reflex vertex reaches the line of a wavefront edge it is not part of, within
//    that edge's current extent; it ends there and two vertices start, one on each side of the
//    edge, which splits the vertex's cycle in two (or joins a hole's cycle to the one around it).
// A cycle left with two vertices has closed to a segment (two edges' lines coincide): it becomes
// the ridge between them. Event points are computed from three lines at once, as
// ConvexSkeleton in skeleton.cc does, so a vertex racing along a near-rectangle's ridge still
// ends where the lines say. Nodes within a tolerance of one another in place and time are one
// node (the simultaneous events of symmetric outlines).
//
// Degenerate events are not classified: what comes out is checked instead (faces simple,
// counter-clockwise, tiling the polygon, every vertex at its time above its face's edge line),
// and anything that fails goes to CGAL's exact builder.
#include "kernel/skeleton_wavefront.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "kernel/skeleton_faces.h"

namespace insula::kernel {
namespace {

constexpr std::uint32_t kNone = 0xffffffffU;

// Past this many contour vertices the brute-force event search (reflex vertices x wavefront edges
// per event) costs more than CGAL's builder: a 100-vertex outline took CGAL ~10 ms.
constexpr std::size_t kMaxVertices = 160;

// Contour edge e's supporting line, relative to the builder's origin: dot(normal, x) = offset + t
// at time t.
struct Line {
  Vec2 normal;     // unit, inward
  Vec2 direction;  // unit, along the edge
  double offset = 0;
};

struct WaveVertex {
  std::uint32_t left = kNone;   // the contour edge before it
  std::uint32_t right = kNone;  // the contour edge after it
  std::uint32_t prev = kNone;   // wavefront neighbours
  std::uint32_t next = kNone;
  std::uint32_t node = kNone;  // the skeleton node its trace starts at
  Vec2 start;                  // its position at `born`
  Vec2 velocity;
  double born = 0;
  bool reflex = false;
  bool alive = true;
  Vec2 at(double t) const { return start + velocity * (t - born); }
};

struct Event {
  double time = std::numeric_limits<double>::infinity();
  Vec2 point;
  std::uint32_t vertex = kNone;  // edge event: the edge's first vertex; split: the reflex vertex
  std::uint32_t target = kNone;  // split event: the first vertex of the edge reached
};

// Where the lines of edges p, e and q, each moved inward by t, meet, and that t.
std::optional<Event> concurrent(const Line& p, const Line& e, const Line& q) {
  // (n_p - n_e) . x = c_p - c_e and (n_q - n_e) . x = c_q - c_e; then t = n_e . x - c_e.
  const Vec2 u = p.normal - e.normal;
  const Vec2 v = q.normal - e.normal;
  const double det = cross(u, v);
  if (!(std::abs(det) > 1e-12)) return std::nullopt;
  const double cu = p.offset - e.offset;
  const double cv = q.offset - e.offset;
  Event event;
  event.point = Vec2{cu * v.y - cv * u.y, cv * u.x - cu * v.x} / det;
  event.time = dot(e.normal, event.point) - e.offset;
  if (!std::isfinite(event.time) || !std::isfinite(event.point.x) ||
      !std::isfinite(event.point.y)) {
    return std::nullopt;
  }
  return event;
}

class Builder {
 public:
  Builder(const Polygon& polygon, Skeleton& out) : out_(out) {
    origin_ = polygon.outer[0];
    Vec2 lo = origin_, hi = origin_;
    auto add_ring = [&](const Ring& ring) {
      const auto first = static_cast<std::uint32_t>(out_.vertices.size());
      const auto m = static_cast<std::uint32_t>(ring.size());
      out_.ring_starts.push_back(first);
      for (std::uint32_t k = 0; k < m; ++k) {
        out_.vertices.push_back({ring[k], 0.0});
        const Vec2 a = ring[k] - origin_;
        const Vec2 b = ring[(k + 1) % m] - origin_;
        const Vec2 direction = normalized(b - a);
        lines_.push_back({perp(direction), direction, dot(perp(direction), a)});
        lo = {std::min(lo.x, ring[k].x), std::min(lo.y, ring[k].y)};
        hi = {std::max(hi.x, ring[k].x), std::max(hi.y, ring[k].y)};
      }
      for (std::uint32_t k = 0; k < m; ++k) {
        const std::uint32_t id = first + k;
        WaveVertex v;
        v.left = first + (k + m - 1) % m;
        v.right = id;
        v.prev = first + (k + m - 1) % m;
        v.next = first + (k + 1) % m;
        v.node = id;
        v.start = ring[k] - origin_;
        set_motion(v);
        wave_.push_back(v);
      }
    };
    add_ring(polygon.outer);
    for (const Ring& hole : polygon.holes) add_ring(hole);
    out_.contour_count = static_cast<std::uint32_t>(out_.vertices.size());
    out_.ring_starts.push_back(out_.contour_count);
    scale_ = std::max(length(hi - lo), 1e-300);
    area_ = area(polygon);
  }

  bool run() {
    const std::size_t limit = 8 * out_.contour_count + 64;
    std::size_t alive = wave_.size();
    for (std::size_t steps = 0; alive > 0; ++steps) {
      if (steps == limit) return false;
      bool tied = false;
      const Event event = next_event(tied);
      // A split event at the time of another event elsewhere (exactly rectilinear outlines turned
      // to an angle have many) can be taken in an order that leaves a valid-looking but wrong
      // skeleton: two parallel edges' faces traded a 5 m2 region on a 257 m2 outline. CGAL
      // decides those. Edge events alone at one time (a near-rectangle's two ridge ends) are not
      // affected.
      if (!std::isfinite(event.time) || tied) return false;
      now_ = std::max(now_, event.time);
      if (event.target == kNone) {
        edge_event(event);
      } else {
        split_event(event);
      }
      alive = static_cast<std::size_t>(
          std::count_if(wave_.begin(), wave_.end(), [](const WaveVertex& v) { return v.alive; }));
    }
    return assemble_skeleton_faces(arcs_, out_) && faces_valid();
  }

 private:
  // Its velocity (along its right edge's normal at unit speed, sliding along the edge as far as
  // the left edge's line requires) and whether it is reflex.
  void set_motion(WaveVertex& v) const {
    const Line& l = lines_[v.left];
    const Line& r = lines_[v.right];
    v.reflex = cross(l.direction, r.direction) < -1e-12;
    const double along = dot(l.normal, r.direction);
    const double facing = dot(l.normal, r.normal);
    // Parallel edges on one line: the vertex moves straight in. Antiparallel ones: the lines
    // coincide now and the vertex has no single place; its cycle is about to close.
    const double slide = std::abs(along) > 1e-12 ? (1 - facing) / along : 0.0;
    v.velocity = r.normal + r.direction * slide;
  }

  double tolerance() const { return 1e-9 * scale_; }

  // The earliest event; `tied` tells whether another one elsewhere comes at the same time, one of
  // the two a split event.
  Event next_event(bool& tied) const {
    Event best;
    Event rival;
    for (std::uint32_t a = 0; a < wave_.size(); ++a) {
      if (!wave_[a].alive) continue;
      consider(edge_event_of(a), best, rival);
      if (!wave_[a].reflex) continue;
      for (std::uint32_t s = 0; s < wave_.size(); ++s) {
        if (wave_[s].alive) consider(split_event_of(a, s), best, rival);
      }
    }
    tied = rival.vertex != kNone && rival.time <= best.time + tolerance() &&
           (best.target != kNone || rival.target != kNone);
    return best;
  }

  // Earlier events win; of events at one time (within the tolerance), edge events first. `rival`
  // keeps the earliest event at another place than the best.
  void consider(const std::optional<Event>& event, Event& best, Event& rival) const {
    if (!event) return;
    Event e = *event;
    e.time = std::max(e.time, now_);
    const bool elsewhere = length(e.point - best.point) > tolerance();
    if (e.time < best.time - tolerance() ||
        (e.time <= best.time + tolerance() && e.target == kNone && best.target != kNone)) {
      if (elsewhere && best.time < rival.time) rival = best;
      best = e;
    } else if (elsewhere && e.time < rival.time) {
      rival = e;
    }
  }

  // Where the wavefront edge from vertex a to its next vertex shrinks to a point, if it shrinks.
  std::optional<Event> edge_event_of(std::uint32_t a) const {
    const WaveVertex& va = wave_[a];
    const WaveVertex& vb = wave_[va.next];
    const Line& e = lines_[va.right];
    if (!(dot(e.direction, vb.velocity - va.velocity) < 0)) return std::nullopt;
    std::optional<Event> event = concurrent(lines_[va.left], e, lines_[vb.right]);
    if (!event || event->time < now_ - tolerance()) return std::nullopt;
    event->vertex = a;
    return event;
  }

  // Where reflex vertex r reaches the wavefront edge from vertex s to its next vertex, if it does
  // while the edge is there.
  std::optional<Event> split_event_of(std::uint32_t r, std::uint32_t s) const {
    const WaveVertex& vr = wave_[r];
    const WaveVertex& vs = wave_[s];
    if (s == r || vs.next == r || vs.right == vr.left || vs.right == vr.right) return std::nullopt;
    const Line& e = lines_[vs.right];
    // r must be ahead of the edge's line and closing on it.
    const double gap = dot(e.normal, vr.at(now_)) - e.offset - now_;
    if (gap < -tolerance() || !(dot(e.normal, vr.velocity) < 1)) return std::nullopt;
    std::optional<Event> event = concurrent(lines_[vr.left], e, lines_[vr.right]);
    // A vertex reaches no edge where it starts: that edge's own vertices meet it there.
    if (!event || event->time < now_ - tolerance() || event->time <= vr.born + tolerance()) {
      return std::nullopt;
    }
    const double t = std::max(event->time, now_);
    const double along = dot(e.direction, event->point);
    const double from = dot(e.direction, vs.at(t));
    const double to = dot(e.direction, wave_[vs.next].at(t));
    if (along < from - tolerance() || along > to + tolerance()) return std::nullopt;
    event->vertex = r;
    event->target = s;
    return event;
  }

  void edge_event(const Event& event) {
    const std::uint32_t a = event.vertex;
    const std::uint32_t b = wave_[a].next;
    const std::uint32_t node = node_at(event.point, now_);
    end_trace(a, node);
    end_trace(b, node);
    const std::uint32_t c = start_vertex(wave_[a].left, wave_[b].right, node, event.point);
    link(wave_[a].prev, c);
    link(c, wave_[b].next);
    close_if_flat(c);
  }

  void split_event(const Event& event) {
    const std::uint32_t r = event.vertex;
    const std::uint32_t s = event.target;
    const std::uint32_t edge = wave_[s].right;
    const std::uint32_t node = node_at(event.point, now_);
    end_trace(r, node);
    const std::uint32_t before = wave_[r].prev, after = wave_[r].next, past = wave_[s].next;
    const std::uint32_t v1 = start_vertex(wave_[r].left, edge, node, event.point);
    const std::uint32_t v2 = start_vertex(edge, wave_[r].right, node, event.point);
    link(before, v1);
    link(v1, past);
    link(s, v2);
    link(v2, after);
    close_if_flat(v1);
    close_if_flat(v2);
  }

  void link(std::uint32_t from, std::uint32_t to) {
    wave_[from].next = to;
    wave_[to].prev = from;
  }

  // Vertex v's trace ends at `node`.
  void end_trace(std::uint32_t v, std::uint32_t node) {
    WaveVertex& w = wave_[v];
    arcs_.push_back({w.node, node, w.left, w.right});
    w.alive = false;
  }

  std::uint32_t start_vertex(std::uint32_t left, std::uint32_t right, std::uint32_t node, Vec2 p) {
    WaveVertex v;
    v.left = left;
    v.right = right;
    v.node = node;
    v.start = p;
    v.born = now_;
    set_motion(v);
    wave_.push_back(v);
    return static_cast<std::uint32_t>(wave_.size() - 1);
  }

  // A cycle of two vertices has closed to a segment: the ridge between its two edges' faces. A
  // vertex alone (its edge event took its cycle's other two) ends where it is.
  void close_if_flat(std::uint32_t v) {
    WaveVertex& w = wave_[v];
    if (!w.alive) return;
    if (w.next == v) {
      w.alive = false;
      return;
    }
    const std::uint32_t other = w.next;
    if (wave_[other].next != v) return;
    arcs_.push_back({w.node, wave_[other].node, w.left, w.right});
    w.alive = false;
    wave_[other].alive = false;
  }

  // A node at p (relative to origin_) and `time`, or the node already there.
  std::uint32_t node_at(Vec2 p, double time) {
    const Vec2 q = p + origin_;
    for (std::uint32_t v = out_.contour_count; v < out_.vertices.size(); ++v) {
      const SkeletonVertex& s = out_.vertices[v];
      if (std::abs(s.time - time) <= tolerance() && length(s.position - q) <= tolerance()) return v;
    }
    out_.vertices.push_back({q, time});
    return static_cast<std::uint32_t>(out_.vertices.size() - 1);
  }

  // Every face simple and counter-clockwise, every face vertex at its time above the face's edge
  // line, and the faces' areas adding up to the polygon's.
  bool faces_valid() const {
    const double distance_tolerance = 1e-7 * scale_;
    double total = 0;
    Polygon face;
    for (std::uint32_t e = 0; e < out_.contour_count; ++e) {
      face.outer.clear();
      const Line& line = lines_[e];
      for (std::uint32_t v : out_.face(e)) {
        const SkeletonVertex& s = out_.vertices[v];
        const double distance = dot(line.normal, s.position - origin_) - line.offset;
        if (!(s.time >= 0) || !(std::abs(distance - s.time) <= distance_tolerance)) return false;
        face.outer.push_back(s.position);
      }
      const double a = signed_area(face.outer);
      if (!(a > 0) || !is_simple_polygon(face)) return false;
      total += a;
    }
    return std::abs(total - area_) <= 1e-9 * area_ + 1e-12 * scale_ * scale_;
  }

  Skeleton& out_;
  Vec2 origin_;
  double scale_ = 1;  // the contour's bounding diagonal
  double area_ = 0;
  double now_ = 0;
  std::vector<Line> lines_;  // per contour edge
  std::vector<WaveVertex> wave_;
  std::vector<SkeletonArc> arcs_;
};

}  // namespace

std::optional<Skeleton> wavefront_straight_skeleton(const Polygon& polygon) {
  std::size_t count = polygon.outer.size();
  for (const Ring& hole : polygon.holes) count += hole.size();
  if (count < 3 || count > kMaxVertices) return std::nullopt;
  Skeleton out;
  if (!Builder(polygon, out).run()) return std::nullopt;
  return out;
}

}  // namespace insula::kernel
