// Writes a planned roof (roof_detail.h) into a mesh: wall-top ring, soffits, fascias, the roof
// faces of each type, and the gable caps returned to the wall builder.
#include <algorithm>
#include <array>

#include "kernel/roof_detail.h"
#include "kernel/triangulate.h"

namespace insula::kernel::roof_detail {
namespace {

class RoofEmitter {
 public:
  RoofEmitter(const RoofPlan& plan, double eave_z, Mesh& mesh, RoofBuild& build)
      : plan_(plan), eave_z_(eave_z), mesh_(mesh), build_(build), face_id_(build.next_face_id) {
    low_z_ = eave_z - plan.overhang * plan.eave_slope;
  }

  void run() {
    const std::uint32_t n = plan_.footprint.size();
    mesh_.reserve(mesh_.vertex_count() + 4 * n + 8, mesh_.face_count() + 4 * n + 8,
                  mesh_.face_count() * 4 + 24 * n);
    make_rings();
    find_jogs();
    build_.cap_offsets.assign(n + 1, 0);
    emit_soffits_and_fascias();
    emit_body();
    for (std::uint32_t e = 0; e < n; ++e) build_.cap_offsets[e + 1] += build_.cap_offsets[e];
    // cap_offsets held per-edge counts until here; gable caps were written in edge order.
    build_.next_face_id = face_id_;
  }

 private:
  double roof_z(Vec2 p) const {
    switch (plan_.type) {
      case RoofType::kFlat:
        return eave_z_;
      case RoofType::kShed:
        return eave_z_ + plan_.slope * shed_distance(plan_, p);
      default:
        return low_z_;
    }
  }
  double soffit_z(Vec2 p) const { return roof_z(p) - plan_.fascia; }

  void make_rings() {
    const Contour& f = plan_.footprint;
    const Contour& e = plan_.eave;
    const std::uint32_t n = f.size();
    build_.wall_top.resize(n);
    // The S3DB shapes pass above (or below) a footprint vertex that is not a corner of their
    // quadrilateral (CustomRoof::eave_rise); planning keeps such a vertex off overhanging edges
    // (roof_shapes.cc, meets_soffits), so its wall top is also its eave.
    const std::vector<double>& rise = plan_.custom.eave_rise;
    const bool custom = plan_.type >= RoofType::kGambrel && rise.size() == n;
    for (std::uint32_t k = 0; k < n; ++k) {
      const double z = soffit_z(f.points[k]) + (custom ? rise[k] : 0.0);
      build_.wall_top[k] = mesh_.add_vertex(lift(f.points[k], z));
    }
    soffit_ = build_.wall_top;
    if (plan_.overhang > 0) {
      for (std::uint32_t k = 0; k < n; ++k) {
        soffit_[k] = plan_.offsets[k] > 0 || plan_.offsets[f.prev(k)] > 0
                         ? mesh_.add_vertex(lift(e.points[k], soffit_z(e.points[k])))
                         : build_.wall_top[k];
      }
    }
    eave_ = soffit_;
    if (plan_.fascia > 0) {
      for (std::uint32_t k = 0; k < n; ++k) {
        eave_[k] = mesh_.add_vertex(lift(e.points[k], roof_z(e.points[k])));
      }
    }
  }

  void face(std::initializer_list<std::uint32_t> loop, SemanticClass semantic) {
    loop_.assign(loop);
    insert_wall_tops(jogs_, loop_);
    mesh_.add_face(loop_, {semantic, 0, face_id_++});
  }

  // The edges without overhang whose eave edge reaches past their wall top (WallTopJog). Gable
  // ends are left out: their wall continues up into the gable (add_cap), as does the end wall of
  // an S3DB shape (its cap: emit_custom).
  void find_jogs() {
    if (!(plan_.overhang > 0)) return;
    const Contour& f = plan_.footprint;
    std::vector<std::uint8_t> gable(f.size(), 0);
    for (const GableEnd& g : plan_.gables) gable[g.edge] = 1;
    const auto& ends = plan_.custom.ends;
    for (std::uint32_t e = 0; e < f.size() && e < ends.size(); ++e) gable[e] |= ends[e];
    const auto& w = build_.wall_top;
    for (std::uint32_t e = 0; e < f.size(); ++e) {
      const std::uint32_t j = f.next(e);
      if (plan_.offsets[e] > 0 || gable[e] || (soffit_[e] == w[e] && soffit_[j] == w[j])) continue;
      jogs_.push_back({soffit_[e], soffit_[j], w[e], w[j]});
    }
  }

  void emit_soffits_and_fascias() {
    const Contour& f = plan_.footprint;
    const auto& w = build_.wall_top;
    for (std::uint32_t e = 0; e < f.size(); ++e) {
      const std::uint32_t j = f.next(e);
      if (plan_.overhang > 0 && plan_.offsets[e] > 0) {
        face({w[e], w[j], soffit_[j], soffit_[e]}, SemanticClass::kOuterCeilingSurface);
      }
      if (plan_.fascia > 0) {
        face({soffit_[e], soffit_[j], eave_[j], eave_[e]}, SemanticClass::kRoofSurface);
      }
    }
  }

  void emit_body() {
    switch (plan_.type) {
      case RoofType::kFlat:
      case RoofType::kShed:
        add_region(plan_.eave, eave_, {SemanticClass::kRoofSurface, 0, face_id_++}, false, mesh_);
        return;
      case RoofType::kPyramid:
        emit_pyramid();
        return;
      case RoofType::kHip:
      case RoofType::kGable:
        emit_skeleton_faces();
        return;
      case RoofType::kMansard:
      case RoofType::kHoledMansard:
        emit_mansard(plan_, low_z_, low_z_, eave_, jogs_, mesh_, face_id_);
        return;
      case RoofType::kGambrel:
      case RoofType::kHalfHipped:
      case RoofType::kSaltbox:
      case RoofType::kRound:
      case RoofType::kDome:
      case RoofType::kOnion:
        emit_custom();
        return;
    }
  }

  // The S3DB shapes, planned as faces over the eave vertices. With overhang (gambrel, half-hipped,
  // saltbox) those are the eave polygon's; an end wall's cap then runs, as a gable's, from its
  // end's wall top over the eave corner through the roof points on the end and back over the
  // other eave corner.
  void emit_custom() {
    const CustomRoof& roof = plan_.custom;
    const Contour& c = plan_.footprint;
    const std::uint32_t n = c.size();
    const auto& w = build_.wall_top;
    std::vector<std::uint32_t> ids(eave_.begin(), eave_.end());
    for (const Vec3& p : roof.points) ids.push_back(mesh_.add_vertex({p.x, p.y, low_z_ + p.z}));
    std::vector<std::uint32_t> loop;
    for (std::size_t f = 0; f + 1 < roof.face_offsets.size(); ++f) {
      loop.clear();
      for (std::uint32_t k = roof.face_offsets[f]; k < roof.face_offsets[f + 1]; ++k) {
        loop.push_back(ids[roof.face_indices[k]]);
      }
      insert_wall_tops(jogs_, loop);
      mesh_.add_face(loop, {SemanticClass::kRoofSurface, 0, face_id_++});
    }
    for (std::uint32_t e = 0; e < n && e < roof.caps.size(); ++e) {
      const bool end = e < roof.ends.size() && roof.ends[e];
      if (roof.caps[e].empty() && !end) continue;
      const std::uint32_t j = c.next(e);
      const std::size_t before = build_.cap_indices.size();
      if (soffit_[j] != w[j]) build_.cap_indices.push_back(soffit_[j]);
      for (std::uint32_t k : roof.caps[e]) build_.cap_indices.push_back(ids[k]);
      if (soffit_[e] != w[e]) build_.cap_indices.push_back(soffit_[e]);
      build_.cap_offsets[e + 1] = static_cast<std::uint32_t>(build_.cap_indices.size() - before);
    }
  }

  void emit_pyramid() {
    const Contour& e = plan_.eave;
    const std::uint32_t apex =
        mesh_.add_vertex(lift(plan_.apex, low_z_ + plan_.apex_time * plan_.slope));
    for (std::uint32_t k = 0; k < e.size(); ++k) {
      face({eave_[k], eave_[e.next(k)], apex}, SemanticClass::kRoofSurface);
    }
  }

  // Hip faces are the skeleton faces lifted by time * slope (seed 000, §4.6); a gable end moves
  // its triangle's apex onto the end edge and becomes a cap of the wall below it.
  void emit_skeleton_faces() {
    const Skeleton& s = *plan_.skeleton;
    std::vector<std::uint32_t> ids(s.vertices.size(), 0xffffffffU);
    for (std::uint32_t k = 0; k < s.contour_count; ++k) ids[k] = eave_[k];
    std::vector<std::uint8_t> gable(s.contour_count, 0);
    for (const GableEnd& g : plan_.gables) {
      ids[g.node] = mesh_.add_vertex(lift(g.apex, low_z_ + g.time * plan_.slope));
      gable[g.edge] = 1;
    }
    std::vector<std::uint32_t> loop;
    for (std::uint32_t e = 0; e < s.contour_count; ++e) {
      const auto face_loop = s.face(e);
      if (gable[e]) {
        add_cap(e, ids[face_loop[2]]);
        continue;
      }
      loop.clear();
      for (std::uint32_t v : face_loop) {
        if (ids[v] == 0xffffffffU) {
          const SkeletonVertex& sv = s.vertices[v];
          ids[v] = mesh_.add_vertex(lift(sv.position, low_z_ + sv.time * plan_.slope));
        }
        loop.push_back(ids[v]);
      }
      insert_wall_tops(jogs_, loop);
      mesh_.add_face(loop, {SemanticClass::kRoofSurface, 0, face_id_++});
    }
  }

  // The wall under edge e continues from its end's wall top over the eave corner (when the
  // neighbouring eave overhangs) up to the gable apex and back.
  void add_cap(std::uint32_t e, std::uint32_t apex) {
    const std::uint32_t j = plan_.footprint.next(e);
    const std::size_t before = build_.cap_indices.size();
    if (soffit_[j] != build_.wall_top[j]) build_.cap_indices.push_back(soffit_[j]);
    build_.cap_indices.push_back(apex);
    if (soffit_[e] != build_.wall_top[e]) build_.cap_indices.push_back(soffit_[e]);
    build_.cap_offsets[e + 1] = static_cast<std::uint32_t>(build_.cap_indices.size() - before);
  }

  const RoofPlan& plan_;
  double eave_z_;
  double low_z_;  // eave height of pitched roofs (lower than eave_z_ by the overhang's drop)
  Mesh& mesh_;
  RoofBuild& build_;
  std::uint32_t face_id_;
  std::vector<std::uint32_t> soffit_;  // eave polygon vertices at soffit height
  std::vector<std::uint32_t> eave_;    // eave polygon vertices at roof height
  std::vector<WallTopJog> jogs_;
  std::vector<std::uint32_t> loop_;
};

}  // namespace

void insert_wall_tops(std::span<const WallTopJog> jogs, std::vector<std::uint32_t>& loop) {
  for (const WallTopJog& jog : jogs) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      if (loop[i] != jog.eave_from || loop[(i + 1) % loop.size()] != jog.eave_to) continue;
      std::array<std::uint32_t, 2> inner{};
      std::size_t count = 0;
      if (jog.wall_from != jog.eave_from) inner[count++] = jog.wall_from;
      if (jog.wall_to != jog.eave_to) inner[count++] = jog.wall_to;
      loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(i + 1), inner.begin(),
                  inner.begin() + static_cast<std::ptrdiff_t>(count));
      break;
    }
  }
}

bool add_region(const Contour& contour, std::span<const std::uint32_t> ids, FaceTag tag,
                bool downward, Mesh& mesh) {
  if (contour.ring_starts.size() == 2) {
    if (!downward) {
      mesh.add_face(ids, tag);
    } else {
      std::vector<std::uint32_t> loop(ids.rbegin(), ids.rend());
      mesh.add_face(loop, tag);
    }
    return true;
  }
  Triangulation t;
  if (!triangulate(contour.polygon(), t) || t.vertices.size() != contour.size()) return false;
  for (const auto& tri : t.triangles) {
    const Vec2 a = contour.points[tri[0]];
    const Vec2 b = contour.points[tri[1]];
    const Vec2 c = contour.points[tri[2]];
    const bool ccw = cross(b - a, c - a) > 0;
    if (ccw != downward) {
      mesh.add_face({ids[tri[0]], ids[tri[1]], ids[tri[2]]}, tag);
    } else {
      mesh.add_face({ids[tri[0]], ids[tri[2]], ids[tri[1]]}, tag);
    }
  }
  return true;
}

void emit_roof(const RoofPlan& plan, double eave_z, Mesh& mesh, RoofBuild& build) {
  RoofEmitter(plan, eave_z, mesh, build).run();
}

}  // namespace insula::kernel::roof_detail
