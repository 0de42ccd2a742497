#include "kernel/roof_solid.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "kernel/boolean2d.h"
#include "kernel/extrude.h"
#include "kernel/solids.h"

namespace insula::kernel {
namespace {

// Outer ring, then holes: the index of the vertex after `e` in its ring.
std::vector<std::uint32_t> ring_successors(const Polygon& p) {
  std::vector<std::uint32_t> next;
  std::uint32_t begin = 0;
  const auto add_ring = [&](const Ring& ring) {
    const auto n = static_cast<std::uint32_t>(ring.size());
    for (std::uint32_t i = 0; i < n; ++i) next.push_back(begin + (i + 1) % n);
    begin += n;
  };
  add_ring(p.outer);
  for (const Ring& hole : p.holes) add_ring(hole);
  return next;
}

// The compluvium (seed 000 §4.1 "holed mansard"): add_roof closes the opening with a floor at the
// eaves (OuterFloorSurface). That floor is removed and the roof closed underneath by the
// footprint minus the opening, so the opening goes through the roof; its outline (the floor's
// boundary loops) is returned. Nothing changes (empty result) when the floor has no boundary.
std::vector<Polygon> open_compluvium(Mesh& mesh, const Polygon& footprint,
                                     const std::vector<std::uint32_t>& wall_top, FaceTag bottom) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.tag(f).semantic != SemanticClass::kOuterFloorSurface) continue;
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) ++edges[{loop[i], loop[(i + 1) % loop.size()]}];
  }
  std::map<std::uint32_t, std::uint32_t> next;  // boundary edges of the opening's floor
  for (const auto& [edge, n] : edges) {
    if (!edges.contains({edge.second, edge.first})) next[edge.first] = edge.second;
  }
  std::vector<std::vector<std::uint32_t>> loops;
  while (!next.empty()) {
    std::vector<std::uint32_t> loop;
    std::uint32_t v = next.begin()->first;
    while (next.contains(v)) {
      loop.push_back(v);
      const std::uint32_t w = next.at(v);
      next.erase(v);
      v = w;
    }
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  if (loops.empty()) return {};
  Polygon region = footprint;
  std::vector<std::uint32_t> ids = wall_top;
  std::vector<Polygon> openings;
  for (std::vector<std::uint32_t>& loop : loops) {
    Ring ring;
    for (std::uint32_t v : loop) ring.push_back(drop(mesh.position(v)));
    openings.push_back({ring, {}});
    // A hole of the bottom region runs clockwise: the floor's boundary ran counter-clockwise.
    std::reverse(loop.begin(), loop.end());
    std::reverse(ring.begin(), ring.end());
    region.holes.push_back(std::move(ring));
    ids.insert(ids.end(), loop.begin(), loop.end());
  }
  Mesh opened;
  opened.reserve(mesh.vertex_count(), mesh.face_count(), 0);
  for (const Vec3& p : mesh.positions()) opened.add_vertex(p);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.tag(f).semantic != SemanticClass::kOuterFloorSurface) {
      opened.add_face(mesh.face(f), mesh.tag(f));
    }
  }
  if (!add_region_faces(opened, region, ids, true, bottom)) return {};
  mesh = std::move(opened);
  return openings;
}

RoofSolid flat_slab(const Polygon& footprint, const RoofSolidSpec& spec, double eave_z) {
  RoofSolid out;
  if (!(spec.flat_thickness > 0)) {
    out.message = "a flat roof solid needs a thickness > 0";
    return out;
  }
  std::vector<Polygon> slab{footprint};
  if (spec.roof.overhang > 0) {
    BooleanResult grown = offset(slab, spec.roof.overhang);
    if (grown.ok() && grown.polygons.size() == 1) slab = std::move(grown.polygons);
  }
  const PrismTags tags{{SemanticClass::kOuterCeilingSurface, 0, 0},
                       {SemanticClass::kRoofSurface, 0, 1},
                       {SemanticClass::kWallSurface, 0, 2}};
  for (const Polygon& p : slab) {
    if (!add_prism(out.mesh, p, eave_z, eave_z + spec.flat_thickness, tags)) {
      out.mesh = {};
      out.message = "the flat roof could not be built";
      return out;
    }
  }
  out.status = RoofStatus::kOk;
  return out;
}

// The roof's bottom corners: a footprint vertex's wall top where it lies at the lowest wall top
// (the eave, or the soffit where the custom shapes' overhang brings it down), else a new vertex
// under it at that height. A vertex inside a gable or half-hip end (a survey's near-collinear
// corner) has its wall top up the end's slope: a bottom through it would fold (0.6 m on a 6 m
// half-hip end) and leave the post under it short.
std::vector<std::uint32_t> bottom_corners(const RoofBuild& build, Mesh& mesh) {
  constexpr double kLevel = 1e-6;  // m
  double low = std::numeric_limits<double>::infinity();
  for (const std::uint32_t v : build.wall_top) low = std::min(low, mesh.position(v).z);
  std::vector<std::uint32_t> bottom = build.wall_top;
  for (std::uint32_t& v : bottom) {
    const Vec3 top = mesh.position(v);
    if (top.z > low + kLevel) v = mesh.add_vertex({top.x, top.y, low});
  }
  return bottom;
}

// The end walls between the bottom and the roof: under edge e, {bottom(e), bottom(next),
// wall_top(next), cap..., wall_top(e)} with the wall tops that are bottom corners left out (a
// gable's cap alone where both ends lie at the eave, nothing where there is no cap either).
void close_ends(const RoofBuild& build, const std::vector<std::uint32_t>& next,
                const std::vector<std::uint32_t>& bottom, Mesh& mesh) {
  std::vector<std::uint32_t> loop;
  for (std::uint32_t e = 0; e < next.size(); ++e) {
    const std::uint32_t n = next[e];
    loop.assign({bottom[e], bottom[n]});
    if (build.wall_top[n] != bottom[n]) loop.push_back(build.wall_top[n]);
    loop.insert(loop.end(), build.cap_indices.begin() + build.cap_offsets[e],
                build.cap_indices.begin() + build.cap_offsets[e + 1]);
    if (build.wall_top[e] != bottom[e]) loop.push_back(build.wall_top[e]);
    if (loop.size() >= 3) mesh.add_face(loop, {SemanticClass::kWallSurface, 0, build.next_face_id});
  }
}

}  // namespace

RoofSolid build_roof_solid(const Polygon& footprint, const RoofSolidSpec& spec, double eave_z) {
  if (spec.roof.type == RoofType::kFlat) return flat_slab(footprint, spec, eave_z);
  RoofSolid out;
  const RoofBuild build = add_roof(footprint, spec.roof, eave_z, out.mesh);
  if (build.status == RoofStatus::kFailed) {
    out.mesh = {};
    out.message = build.message.empty() ? "the roof could not be built" : build.message;
    return out;
  }
  out.status = build.status;
  out.message = build.message;
  const std::vector<std::uint32_t> next = ring_successors(footprint);
  if (build.wall_top.size() == next.size() && build.cap_offsets.size() == next.size() + 1) {
    const std::vector<std::uint32_t> corners = bottom_corners(build, out.mesh);
    close_ends(build, next, corners, out.mesh);
    const FaceTag bottom{SemanticClass::kClosureSurface, 0, build.next_face_id + 1};
    if (build.built == RoofType::kHoledMansard && spec.open_compluvium) {
      out.openings = open_compluvium(out.mesh, footprint, corners, bottom);
    }
    if (out.openings.empty()) add_region_faces(out.mesh, footprint, corners, true, bottom);
  }
  scale_roof_height(out.mesh, eave_z, spec.height);
  return out;
}

}  // namespace insula::kernel
