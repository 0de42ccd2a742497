// Roofs (seed 000, §4.1: "the geometry of the roof is created according to the type of roof defined
// for each building part. Flat, pyramidal, hipped, mansard, holed mansard, and none"; §4.6: every
// group of "HipGlued" parts "in spatial contact with others, at the ground level" gets one
// straight-skeleton roof over the polygon clustering their layouts, Fig. 10).
//
// Each roof is a closed solid from kernel/roof_solid.h (the shape operation roof with closed = true
// builds the same): the grammar gives a roof height, not a pitch, so the roof is built at the
// kernel's default pitch and scaled to that height; a flat roof is a slab kFlatThickness thick.
// HipGlued: parts touching along an edge are grouped (union-find over pairwise unions that give
// one polygon), their outlines united with kernel/boolean2d.h, and one hip roof built at the
// group's highest eaves; a lower part of the group is raised to those eaves by a filler block.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "base/union_find.h"
#include "kernel/boolean2d.h"
#include "kernel/planar.h"
#include "kernel/roof_solid.h"
#include "kernel/skeleton.h"
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

// A flat roof is a slab this thick (m, the kernel's fascia) over the outline grown by the overhang.
constexpr double kFlatThickness = 0.25;

// One closed roof solid over `footprint` with its eaves at `eave_z`, `height` high
// (kernel/roof_solid.h); a holed mansard's opening is returned in `openings`.
kernel::Mesh roof_solid(const kernel::Polygon& footprint, RoofKind kind, double height,
                        double eave_z, double overhang, std::string& message,
                        std::vector<kernel::Polygon>* openings) {
  kernel::RoofSolidSpec spec;
  spec.roof.type = roof_type(kind);
  spec.roof.overhang = overhang;
  spec.height = height;
  spec.flat_thickness = kFlatThickness;
  if (kind == RoofKind::kHoledMansard && height > 0) {
    // The Roman compluvium roof: the roof band slopes down inwards... as a mansard's lower band it
    // rises from the eaves to the opening's rim `height` above them; its width (the roof's reach
    // from the outline, 0.55 x twice the area over the perimeter: 3.9 m on a 20 x 14 m part)
    // covers the rooms around a central atrium and leaves the middle open.
    const double reach = 0.55 * 2 * kernel::area(footprint) / kernel::perimeter(footprint);
    spec.roof.mansard_break_height = height;
    spec.roof.mansard_pitch_deg = std::atan2(height, reach) * 180 / 3.141592653589793;
  }
  kernel::RoofSolid built = kernel::build_roof_solid(footprint, spec, eave_z);
  message = std::move(built.message);
  if (openings != nullptr) *openings = std::move(built.openings);
  return std::move(built.mesh);
}

// The footprint a roof stands on: normalised, without collinear vertices (a union of parts keeps
// the vertices where their outlines met); nothing when that is not a simple polygon.
std::optional<kernel::Polygon> clean(const kernel::Polygon& polygon) {
  kernel::RepairResult repaired = kernel::repair(polygon, 1e-6);
  if (!repaired.ok || !kernel::is_simple_polygon(repaired.polygon)) return std::nullopt;
  return std::move(repaired.polygon);
}

// Each polygon cleaned; nothing unless all are simple.
std::vector<kernel::Polygon> all_clean(const std::vector<kernel::Polygon>& polygons) {
  std::vector<kernel::Polygon> out;
  for (const kernel::Polygon& p : polygons) {
    std::optional<kernel::Polygon> c = clean(p);
    if (!c) return {};
    out.push_back(std::move(*c));
  }
  return out;
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

// One roof per simple piece of `footprint` (simple_pieces), named `name`, `name`#2, ...; false,
// with a warning, when a piece gets none. `extra` (fillers) goes with the first roof built.
bool add_roof_part(const Context& c, const std::string& name, const kernel::Polygon& footprint,
                   const std::vector<const PlanPart*>& own, RoofKind kind, double height,
                   double eave_z, std::vector<shape::Part>& parts, kernel::Mesh* extra = nullptr) {
  const std::vector<kernel::Polygon> pieces = simple_pieces(footprint);
  if (pieces.empty()) {
    c.warn(name + ": no roof: its outline is not a simple polygon and could not be made one");
    return false;
  }
  const double overhang = touches_other_part(c, footprint, own) ? 0 : c.options.roof_overhang;
  bool all = true;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const std::string piece = k == 0 ? name : name + "#" + std::to_string(k + 1);
    std::string message;
    std::vector<kernel::Polygon> openings;
    kernel::Mesh mesh = roof_solid(pieces[k], kind, height, eave_z, overhang, message, &openings);
    for (const PlanPart* p : own) {
      if (openings.empty()) break;
      auto& held = (*c.compluvia)[p->symbol];
      held.insert(held.end(), openings.begin(), openings.end());
    }
    if (mesh.empty()) {
      c.warn(piece + ": no roof: " + (message.empty() ? "the roof could not be built" : message));
      all = false;
      continue;
    }
    if (!message.empty()) c.warn(piece + ": " + message);
    if (extra != nullptr) {
      mesh.append(*extra);
      *extra = {};
    }
    shape::Part part;
    part.name = piece;
    part.kind = shape::PartKind::kBuildingPart;
    part.attributes["roof_height"] = height;
    part.mesh = std::move(mesh);
    parts.push_back(std::move(part));
    ++c.result.stats.roofs;
  }
  return all;
}

}  // namespace

std::vector<kernel::Polygon> simple_pieces(const kernel::Polygon& polygon) {
  if (std::optional<kernel::Polygon> p = clean(polygon)) return {std::move(*p)};
  const kernel::TouchSplit split = kernel::split_touching_rings(polygon);
  if (!split.points.empty()) {
    std::vector<kernel::Polygon> pieces = all_clean(split.polygons);
    if (!pieces.empty()) return pieces;
  }
  // Crossings and near-touches: the union's output is strictly simple on its micrometre grid.
  std::vector<kernel::Polygon> pieces = all_clean(kernel::union_all({polygon}));
  if (!pieces.empty()) return pieces;
  // Rings within a micrometre of each other: closed over (or opened) by a millimetre.
  const kernel::BooleanResult grown = kernel::offset({polygon}, 1e-3);
  if (!grown.ok()) return {};
  const kernel::BooleanResult back = kernel::offset(grown.polygons, -1e-3);
  return back.ok() ? all_clean(back.polygons) : std::vector<kernel::Polygon>{};
}

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
        kernel::add_prism(fillers, p->outline, eave_z(*p), eaves,
                          {{SemanticClass::kClosureSurface, 0, 0},
                           {SemanticClass::kClosureSurface, 0, 1},
                           {SemanticClass::kWallSurface, 0, 2}});
      }
    }
    const std::vector<kernel::Polygon> merged = merge(outlines);
    bool roofed = !merged.empty();
    for (std::size_t k = 0; k < merged.size(); ++k) {
      std::string piece = name;
      if (k > 0) piece.append("#").append(std::to_string(k + 1));
      roofed = add_roof_part(c, piece, merged[k], group, RoofKind::kHip, height, eaves, parts,
                             &fillers) &&
               roofed;
    }
    if (roofed || group.size() < 2) continue;
    // No glued roof over the whole group: each part gets its own at the common eaves.
    c.warn(name + ": the parts' merged outline takes no single roof; one roof per part instead");
    for (const PlanPart* p : group) {
      add_roof_part(c, std::string("roof ").append(p->symbol), p->outline, {p}, RoofKind::kHip,
                    height, eaves, parts, &fillers);
    }
  }
}

}  // namespace insula::lang::bldg::detail
