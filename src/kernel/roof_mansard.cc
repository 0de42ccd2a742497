// Mansard roofs from one straight skeleton: the wavefront at time t is the polygon offset inward by
// t, so cutting every skeleton face at the break time splits the roof into a steep lower band and
// the skeleton roof of the offset polygon above it (docs/kernel-roofs.md, "Mansard").
//
// Each face of edge e is swept by e moving inward, so the part below the break (time <= t_b) is
// one polygon reached from e by perpendiculars: Sutherland-Hodgman clipping gives it exactly. The
// part above may be several pieces (the edge was split by a split event): those are rebuilt from
// the runs of the face loop above the cut, closing each run along the cut line towards the next
// run entry in the direction of e.
#include <algorithm>
#include <unordered_map>

#include "kernel/roof_detail.h"

namespace insula::kernel::roof_detail {
namespace {

constexpr std::uint32_t kNone = 0xffffffffU;

struct Crossing {
  std::uint32_t rim = kNone;    // on the break line, at the break height
  std::uint32_t floor = kNone;  // holed mansard: the same point on the opening's floor
  Vec2 position;
};

struct Run {
  std::vector<std::uint32_t> ids;  // upper-piece vertex ids from the entry to the exit crossing
  double s_in = 0;                 // entry and exit along the edge direction
  double s_out = 0;
  bool used = false;
};

class MansardEmitter {
 public:
  MansardEmitter(const RoofPlan& plan, double z_eave, double floor_z,
                 std::span<const std::uint32_t> eave_ids, std::span<const WallTopJog> jogs,
                 Mesh& mesh, std::uint32_t& face_id)
      : plan_(plan),
        s_(*plan.skeleton),
        holed_(plan.type == RoofType::kHoledMansard),
        z_eave_(z_eave),
        z_break_(z_eave + plan.break_time * plan.eave_slope),
        floor_z_(floor_z),
        jogs_(jogs),
        mesh_(mesh),
        face_id_(face_id) {
    low_.assign(s_.vertices.size(), kNone);
    high_.assign(s_.vertices.size(), kNone);
    for (std::uint32_t k = 0; k < s_.contour_count; ++k) low_[k] = eave_ids[k];
  }

  void run() {
    for (std::uint32_t e = 0; e < s_.contour_count; ++e) split_face(e);
  }

 private:
  double value(std::uint32_t v) const { return s_.vertices[v].time - plan_.break_time; }
  bool below(std::uint32_t v) const { return value(v) <= 0; }

  std::uint32_t low_id(std::uint32_t v) {
    if (low_[v] == kNone) {
      const SkeletonVertex& sv = s_.vertices[v];
      low_[v] = mesh_.add_vertex(lift(sv.position, z_eave_ + sv.time * plan_.eave_slope));
    }
    return low_[v];
  }

  std::uint32_t high_id(std::uint32_t v) {
    if (high_[v] == kNone) {
      const SkeletonVertex& sv = s_.vertices[v];
      const double z =
          holed_ ? floor_z_ : z_break_ + (sv.time - plan_.break_time) * plan_.upper_slope;
      high_[v] = mesh_.add_vertex(lift(sv.position, z));
    }
    return high_[v];
  }

  // The point where the loop edge (u, w) meets the break line; shared by both faces of the edge.
  const Crossing& crossing(std::uint32_t u, std::uint32_t w) {
    const std::uint32_t b = below(u) ? u : w;
    const bool on_line = value(b) == 0;
    const std::uint64_t key =
        on_line ? (static_cast<std::uint64_t>(b) << 32 | b)
                : (static_cast<std::uint64_t>(std::min(u, w)) << 32 | std::max(u, w));
    auto [it, inserted] = crossings_.try_emplace(key);
    Crossing& c = it->second;
    if (!inserted) return c;
    if (on_line) {
      c.position = s_.vertices[b].position;
      c.rim = low_id(b);
    } else {
      const std::uint32_t p = std::min(u, w);
      const std::uint32_t q = std::max(u, w);
      const double lambda = value(p) / (value(p) - value(q));
      c.position =
          s_.vertices[p].position + (s_.vertices[q].position - s_.vertices[p].position) * lambda;
      c.rim = mesh_.add_vertex(lift(c.position, z_break_));
    }
    if (holed_) c.floor = mesh_.add_vertex(lift(c.position, floor_z_));
    return c;
  }

  std::uint32_t upper_crossing_id(const Crossing& c) const { return holed_ ? c.floor : c.rim; }

  void push_unique(std::vector<std::uint32_t>& loop, std::uint32_t id) {
    if (loop.empty() || loop.back() != id) loop.push_back(id);
  }

  void add_face(std::vector<std::uint32_t>& loop, SemanticClass semantic) {
    while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
    if (loop.size() >= 3) mesh_.add_face(loop, {semantic, 0, face_id_++});
  }

  void split_face(std::uint32_t e) {
    const auto loop = s_.face(e);
    const Vec2 dir = normalized(s_.vertices[loop[1]].position - s_.vertices[loop[0]].position);
    lower_.clear();
    runs_.clear();
    const Crossing* entry = nullptr;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t cur = loop[i];
      const std::uint32_t nxt = loop[(i + 1) % loop.size()];
      if (below(cur)) {
        push_unique(lower_, low_id(cur));
      } else {
        runs_.back().ids.push_back(high_id(cur));
      }
      if (below(cur) == below(nxt)) continue;
      const Crossing& c = crossing(cur, nxt);
      push_unique(lower_, c.rim);
      if (below(cur)) {  // entering the upper part
        runs_.push_back({{upper_crossing_id(c)}, dot(c.position, dir), 0, false});
        entry = &c;
      } else {  // leaving it: the lower piece follows the cut from the entry to here
        runs_.back().ids.push_back(upper_crossing_id(c));
        runs_.back().s_out = dot(c.position, dir);
        if (holed_ && entry != nullptr) add_opening_wall(*entry, c);
      }
    }
    insert_wall_tops(jogs_, lower_);
    add_face(lower_, SemanticClass::kRoofSurface);
    emit_upper_pieces();
  }

  // Vertical wall of the opening under the cut from `from` to `to` (the roof on its left).
  void add_opening_wall(const Crossing& from, const Crossing& to) {
    if (from.rim == to.rim) return;
    mesh_.add_face({from.rim, from.floor, to.floor, to.rim},
                   {SemanticClass::kWallSurface, 0, face_id_++});
  }

  // Closes each run along the cut towards the nearest run entry ahead in the edge direction.
  void emit_upper_pieces() {
    const SemanticClass semantic =
        holed_ ? SemanticClass::kOuterFloorSurface : SemanticClass::kRoofSurface;
    for (std::size_t r = 0; r < runs_.size(); ++r) {
      if (runs_[r].used) continue;
      piece_.clear();
      std::size_t cur = r;
      for (std::size_t guard = 0; guard <= runs_.size(); ++guard) {
        runs_[cur].used = true;
        for (std::uint32_t id : runs_[cur].ids) push_unique(piece_, id);
        const std::size_t next = next_run(runs_[cur].s_out);
        if (next == r || next == runs_.size() || runs_[next].used) break;
        cur = next;
      }
      add_face(piece_, semantic);
    }
  }

  std::size_t next_run(double s_out) const {
    std::size_t best = runs_.size();
    double best_gap = 1e300;
    for (std::size_t k = 0; k < runs_.size(); ++k) {
      const double gap = runs_[k].s_in - s_out;
      if (gap > -1e-9 && gap < best_gap) best_gap = gap, best = k;
    }
    return best;
  }

  const RoofPlan& plan_;
  const Skeleton& s_;
  bool holed_;
  double z_eave_;
  double z_break_;
  double floor_z_;
  std::span<const WallTopJog> jogs_;
  Mesh& mesh_;
  std::uint32_t& face_id_;
  std::vector<std::uint32_t> low_;   // skeleton vertex -> mesh id below or on the break
  std::vector<std::uint32_t> high_;  // skeleton vertex -> mesh id above the break
  std::unordered_map<std::uint64_t, Crossing> crossings_;
  std::vector<std::uint32_t> lower_;
  std::vector<std::uint32_t> piece_;
  std::vector<Run> runs_;
};

}  // namespace

void emit_mansard(const RoofPlan& plan, double z_eave, double floor_z,
                  std::span<const std::uint32_t> eave_ids, std::span<const WallTopJog> jogs,
                  Mesh& mesh, std::uint32_t& face_id) {
  MansardEmitter(plan, z_eave, floor_z, eave_ids, jogs, mesh, face_id).run();
}

}  // namespace insula::kernel::roof_detail
