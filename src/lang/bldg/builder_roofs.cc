// Roofs (seed 000, §4.1: "the geometry of the roof is created according to the type of roof defined
// for each building part. Flat, pyramidal, hipped, mansard, holed mansard, and none"; §4.6: every
// group of "HipGlued" parts "in spatial contact with others, at the ground level" gets one
// straight-skeleton roof over the polygon clustering their layouts, Fig. 10).
//
// Each roof comes from kernel/roof.h over the part's outline at its eaves, closed underneath by a
// face over the wall-top vertices (plus the gable triangles kernel::add_roof returns as caps), so
// every roof is one closed solid. The grammar gives a roof height, not a pitch: the roof is built
// at the kernel's default pitch and its heights above the eaves are scaled so the ridge (or the
// apex, or the mansard's top) lies `height` above the eaves; an affine scaling of z keeps every
// face planar, so this is the same roof at the pitch that gives that height.
// HipGlued: parts touching along an edge are grouped (union-find over pairwise unions that give
// one polygon), their outlines united with kernel/boolean2d.h, and one hip roof built at the
// group's highest eaves; a lower part of the group is raised to those eaves by a filler block.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "base/union_find.h"
#include "kernel/boolean2d.h"
#include "kernel/roof.h"
#include "lang/bldg/builder_detail.h"

namespace insula::lang::bldg::detail {
namespace {

kernel::RoofType roof_type(RoofKind kind) {
  switch (kind) {
    case RoofKind::kFlat:
      return kernel::RoofType::kFlat;
    case RoofKind::kPyramid:
      return kernel::RoofType::kPyramid;
    case RoofKind::kMansard:
      return kernel::RoofType::kMansard;
    case RoofKind::kHoledMansard:
      return kernel::RoofType::kHoledMansard;
    case RoofKind::kGable:
      return kernel::RoofType::kGable;
    case RoofKind::kHip:
    case RoofKind::kHipGlued:
    case RoofKind::kNone:
      break;
  }
  return kernel::RoofType::kHip;
}

// Outer ring, then holes: the index of the vertex after `e` in its ring.
std::vector<std::uint32_t> ring_successors(const kernel::Polygon& p) {
  std::vector<std::uint32_t> next;
  std::uint32_t begin = 0;
  const auto add_ring = [&](const kernel::Ring& ring) {
    const auto n = static_cast<std::uint32_t>(ring.size());
    for (std::uint32_t i = 0; i < n; ++i) next.push_back(begin + (i + 1) % n);
    begin += n;
  };
  add_ring(p.outer);
  for (const kernel::Ring& hole : p.holes) add_ring(hole);
  return next;
}

// One closed roof solid over `footprint` with its eaves at `eave_z`, `height` high.
// The compluvium (§4.1 "holed mansard"): kernel::add_roof closes the opening with a floor at the
// eaves (OuterFloorSurface). Here that floor is removed and the roof closed underneath by the
// footprint minus the opening, so the opening goes through the roof; its outline (the floor's
// boundary loops) is returned so the rooms below can leave their ceilings open under it.
std::vector<kernel::Polygon> open_compluvium(kernel::Mesh& mesh, const kernel::Polygon& footprint,
                                             const std::vector<std::uint32_t>& wall_top,
                                             kernel::FaceTag bottom) {
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
  kernel::Polygon region = footprint;
  std::vector<std::uint32_t> ids = wall_top;
  std::vector<kernel::Polygon> openings;
  for (std::vector<std::uint32_t>& loop : loops) {
    kernel::Ring ring;
    for (std::uint32_t v : loop) ring.push_back(kernel::drop(mesh.position(v)));
    openings.push_back({ring, {}});
    // A hole of the bottom region runs clockwise: the floor's boundary ran counter-clockwise.
    std::reverse(loop.begin(), loop.end());
    std::reverse(ring.begin(), ring.end());
    region.holes.push_back(std::move(ring));
    ids.insert(ids.end(), loop.begin(), loop.end());
  }
  kernel::Mesh opened;
  opened.reserve(mesh.vertex_count(), mesh.face_count(), 0);
  for (const Vec3& p : mesh.positions()) opened.add_vertex(p);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.tag(f).semantic != SemanticClass::kOuterFloorSurface) {
      opened.add_face(mesh.face(f), mesh.tag(f));
    }
  }
  if (!kernel::add_region_faces(opened, region, ids, true, bottom)) return {};
  mesh = std::move(opened);
  return openings;
}

// A flat roof is a slab kFlatThickness thick over the outline grown by the overhang: the kernel's
// flat roof is a single face, which over an outline without overhang would enclose no volume.
constexpr double kFlatThickness = 0.25;  // m, the kernel's fascia

kernel::Mesh flat_roof(const kernel::Polygon& footprint, double eave_z, double overhang,
                       std::string& message) {
  std::vector<kernel::Polygon> slab{footprint};
  if (overhang > 0) {
    kernel::BooleanResult grown = kernel::offset(slab, overhang);
    if (grown.ok() && grown.polygons.size() == 1) slab = std::move(grown.polygons);
  }
  kernel::Mesh mesh;
  for (const kernel::Polygon& p : slab) {
    if (!add_prism(mesh, p, eave_z, eave_z + kFlatThickness,
                   {SemanticClass::kOuterCeilingSurface, 0, 0}, {SemanticClass::kRoofSurface, 0, 1},
                   {SemanticClass::kWallSurface, 0, 2})) {
      message = "the flat roof could not be built";
      return {};
    }
  }
  return mesh;
}

kernel::Mesh roof_solid(const kernel::Polygon& footprint, RoofKind kind, double height,
                        double eave_z, double overhang, std::string& message,
                        std::vector<kernel::Polygon>* openings) {
  if (kind == RoofKind::kFlat) return flat_roof(footprint, eave_z, overhang, message);
  kernel::Mesh mesh;
  kernel::RoofSpec spec;
  spec.type = roof_type(kind);
  spec.overhang = overhang;
  if (kind == RoofKind::kHoledMansard && height > 0) {
    // The Roman compluvium roof: the roof band slopes down inwards... as a mansard's lower band it
    // rises from the eaves to the opening's rim `height` above them; its width (the roof's reach
    // from the outline, 0.55 x twice the area over the perimeter: 3.9 m on a 20 x 14 m part)
    // covers the rooms around a central atrium and leaves the middle open.
    const double reach = 0.55 * 2 * kernel::area(footprint) / kernel::perimeter(footprint);
    spec.mansard_break_height = height;
    spec.mansard_pitch_deg = std::atan2(height, reach) * 180 / 3.141592653589793;
  }
  const kernel::RoofBuild build = kernel::add_roof(footprint, spec, eave_z, mesh);
  if (build.status == kernel::RoofStatus::kFailed) {
    message = build.message.empty() ? "the roof could not be built" : build.message;
    return {};
  }
  if (build.status == kernel::RoofStatus::kFallback) message = build.message;
  const std::vector<std::uint32_t> next = ring_successors(footprint);
  if (build.wall_top.size() == next.size() && build.cap_offsets.size() == next.size() + 1) {
    std::vector<std::uint32_t> loop;
    for (std::uint32_t e = 0; e < next.size(); ++e) {
      if (build.cap_offsets[e] == build.cap_offsets[e + 1]) continue;
      loop.assign({build.wall_top[e], build.wall_top[next[e]]});
      loop.insert(loop.end(), build.cap_indices.begin() + build.cap_offsets[e],
                  build.cap_indices.begin() + build.cap_offsets[e + 1]);
      mesh.add_face(loop, {SemanticClass::kWallSurface, 0, build.next_face_id});
    }
    const FaceTag bottom{SemanticClass::kClosureSurface, 0, build.next_face_id + 1};
    std::vector<kernel::Polygon> opened;
    if (build.built == kernel::RoofType::kHoledMansard) {
      opened = open_compluvium(mesh, footprint, build.wall_top, bottom);
    }
    if (opened.empty()) {
      kernel::add_region_faces(mesh, footprint, build.wall_top, true, bottom);
    } else if (openings != nullptr) {
      *openings = std::move(opened);
    }
  }
  // Scale the heights above the eaves so the top is `height` above them (see the file comment).
  double top = eave_z;
  for (const Vec3& p : mesh.positions()) top = std::max(top, p.z);
  if (top - eave_z > 1e-6 && height > 0) {
    const double scale = height / (top - eave_z);
    for (Vec3& p : mesh.positions()) p.z = eave_z + (p.z - eave_z) * scale;
  }
  return mesh;
}

// The footprint a roof stands on: normalised, without collinear vertices (a union of parts keeps
// the vertices where their outlines met).
kernel::Polygon clean(const kernel::Polygon& polygon) {
  kernel::RepairResult repaired = kernel::repair(polygon, 1e-6);
  return repaired.ok ? repaired.polygon : polygon;
}

// Parts "in spatial contact [...] at the ground level" (§4.6): they share at least kContact of
// boundary, edges closer than kGap counting as shared (the treemap's cells may leave micrometre
// gaps between neighbours).
constexpr double kGap = 1e-3;     // m
constexpr double kContact = 0.5;  // m of shared wall

// Length of boundary that `a` and `b` share: collinear overlaps of their edges, within kGap.
double shared_length(const kernel::Polygon& a, const kernel::Polygon& b) {
  double shared = 0;
  const auto edges = [](const kernel::Polygon& p, auto&& visit) {
    const auto ring_edges = [&](const kernel::Ring& r) {
      for (std::size_t i = 0; i < r.size(); ++i) visit(r[i], r[(i + 1) % r.size()]);
    };
    ring_edges(p.outer);
    for (const kernel::Ring& hole : p.holes) ring_edges(hole);
  };
  edges(a, [&](Vec2 p, Vec2 q) {
    const double length = kernel::length(q - p);
    if (length < kGap) return;
    const Vec2 dir = (q - p) / length;
    edges(b, [&](Vec2 r, Vec2 s) {
      if (kernel::distance_to_segment(r, p - dir * 1e9, q + dir * 1e9) > kGap ||
          kernel::distance_to_segment(s, p - dir * 1e9, q + dir * 1e9) > kGap) {
        return;
      }
      const double u0 = std::min(kernel::dot(r - p, dir), kernel::dot(s - p, dir));
      const double u1 = std::max(kernel::dot(r - p, dir), kernel::dot(s - p, dir));
      shared += std::max(0.0, std::min(u1, length) - std::max(u0, 0.0));
    });
  });
  return shared;
}

bool in_contact(const kernel::Polygon& a, const kernel::Polygon& b) {
  const kernel::Bounds2 ba = kernel::bounds(a);
  const kernel::Bounds2 bb = kernel::bounds(b);
  if (ba.min.x > bb.max.x + kGap || bb.min.x > ba.max.x + kGap || ba.min.y > bb.max.y + kGap ||
      bb.min.y > ba.max.y + kGap) {
    return false;
  }
  return shared_length(a, b) >= kContact;
}

// The union of touching outlines with the micrometre gaps closed (grow, unite, shrink back).
std::vector<kernel::Polygon> merge(const std::vector<kernel::Polygon>& outlines) {
  const kernel::BooleanResult grown = kernel::offset(outlines, kGap);
  if (!grown.ok()) return kernel::union_all(outlines);
  const kernel::BooleanResult back = kernel::offset(grown.polygons, -kGap);
  return back.ok() ? back.polygons : kernel::union_all(outlines);
}

// The eaves overhang only on free-standing roofs: the kernel's overhang runs along every edge, and
// on an edge shared with another part it would reach into that part's roof.
bool touches_other_part(const Context& c, const kernel::Polygon& footprint,
                        const std::vector<const PlanPart*>& own) {
  for (const PlanPart& p : c.plan.parts) {
    if (p.disposable || p.storeys == 0 || p.outline.outer.empty()) continue;
    if (std::find(own.begin(), own.end(), &p) != own.end()) continue;
    if (in_contact(footprint, p.outline)) return true;
  }
  return false;
}

void add_roof_part(const Context& c, const std::string& name, const kernel::Polygon& footprint,
                   const std::vector<const PlanPart*>& own, RoofKind kind, double height,
                   double eave_z, std::vector<shape::Part>& parts, kernel::Mesh extra = {}) {
  std::string message;
  const double overhang = touches_other_part(c, footprint, own) ? 0 : c.options.roof_overhang;
  std::vector<kernel::Polygon> openings;
  kernel::Mesh mesh =
      roof_solid(clean(footprint), kind, height, eave_z, overhang, message, &openings);
  if (!openings.empty()) {
    for (const PlanPart* p : own) (*c.compluvia)[p->symbol] = openings;
  }
  if (!message.empty()) c.warn(name + ": " + message);
  if (mesh.empty()) return;
  mesh.append(extra);
  shape::Part part;
  part.name = name;
  part.kind = shape::PartKind::kBuildingPart;
  part.attributes["roof_height"] = height;
  part.mesh = std::move(mesh);
  parts.push_back(std::move(part));
  ++c.result.stats.roofs;
}

}  // namespace

void build_roofs(const Context& c, std::vector<shape::Part>& parts) {
  const std::vector<PlanPart>& plan_parts = c.plan.parts;
  const auto eave_z = [&](const PlanPart& p) { return c.rules.base_height + p.eaves; };
  std::vector<int> glued;
  for (std::size_t i = 0; i < plan_parts.size(); ++i) {
    const PlanPart& p = plan_parts[i];
    if (p.disposable || p.storeys == 0 || p.outline.outer.empty()) continue;
    if (p.roof == RoofKind::kNone) continue;
    if (p.roof == RoofKind::kHipGlued) {
      glued.push_back(static_cast<int>(i));
      continue;
    }
    add_roof_part(c, std::string("roof ").append(p.symbol), p.outline, {&p}, p.roof, p.roof_height,
                  eave_z(p), parts);
  }
  // §4.6: groups of HipGlued parts in contact.
  base::UnionFind groups(glued.size());
  for (std::size_t i = 0; i < glued.size(); ++i) {
    for (std::size_t j = i + 1; j < glued.size(); ++j) {
      const auto& a = plan_parts[static_cast<std::size_t>(glued[i])].outline;
      const auto& b = plan_parts[static_cast<std::size_t>(glued[j])].outline;
      if (in_contact(a, b)) {
        groups.unite(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
      }
    }
  }
  for (std::size_t root = 0; root < glued.size(); ++root) {
    if (groups.find(static_cast<std::uint32_t>(root)) != root) continue;
    std::vector<const PlanPart*> group;
    for (std::size_t i = 0; i < glued.size(); ++i) {
      if (groups.find(static_cast<std::uint32_t>(i)) == root) {
        group.push_back(&plan_parts[static_cast<std::size_t>(glued[i])]);
      }
    }
    std::string name = "roof ";
    std::vector<kernel::Polygon> outlines;
    double eaves = 0;
    double height = 0;
    for (const PlanPart* p : group) {
      if (p != group.front()) name += '+';
      name += p->symbol;
      outlines.push_back(p->outline);
      eaves = std::max(eaves, eave_z(*p));
      height = std::max(height, p->roof_height);
    }
    // Lower parts of the group are raised to the common eaves.
    kernel::Mesh fillers;
    for (const PlanPart* p : group) {
      if (eave_z(*p) < eaves - 1e-6) {
        add_prism(fillers, p->outline, eave_z(*p), eaves, {SemanticClass::kClosureSurface, 0, 0},
                  {SemanticClass::kClosureSurface, 0, 1}, {SemanticClass::kWallSurface, 0, 2});
      }
    }
    const std::vector<kernel::Polygon> merged = merge(outlines);
    for (std::size_t k = 0; k < merged.size(); ++k) {
      std::string piece = name;
      if (k > 0) piece.append("#").append(std::to_string(k + 1));
      add_roof_part(c, piece, merged[k], group, RoofKind::kHip, height, eaves, parts,
                    k == 0 ? std::move(fillers) : kernel::Mesh{});
    }
  }
}

}  // namespace insula::lang::bldg::detail
