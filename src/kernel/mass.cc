#include "kernel/mass.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernel/roof_detail.h"
#include "kernel/roof_solid.h"
#include "kernel/skeleton.h"
#include "kernel/solids.h"

namespace insula::kernel {
namespace {

RoofSpec roof_spec(const MassSpec& spec) {
  RoofSpec r;
  r.type = spec.roof;
  r.pitch_deg = spec.pitch_deg;
  r.overhang = spec.overhang;
  r.mansard_pitch_deg = spec.mansard_pitch_deg;
  r.mansard_break_height = spec.mansard_break_height;
  r.shed_edge = spec.shed_edge;
  r.fascia = spec.fascia;
  r.height = spec.height;
  r.height_limit = spec.height_limit;
  r.direction_deg = spec.direction_deg;
  r.orientation = spec.orientation;
  r.party_walls = spec.party_walls;
  return r;
}

// The footprint as the roof needs it: simple, outer counter-clockwise, holes clockwise. Cheap when
// the input already is; otherwise repaired (duplicates, collinear vertices, orientation).
bool prepare(const Polygon& in, Polygon& out, std::string& message) {
  out = in;
  normalize(out);
  if (is_simple_polygon(out)) return true;
  RepairResult repaired = repair(in);
  if (!repaired.ok || !is_simple_polygon(repaired.polygon)) {
    message = "footprint is not a valid polygon";
    for (const PolygonIssue& issue : repaired.issues) {
      if (!issue.repaired) {
        message += ": " + issue.message;
        break;
      }
    }
    return false;
  }
  out = std::move(repaired.polygon);
  return true;
}

bool walls_above_ground(const Mesh& mesh, const RoofBuild& build, double ground_z) {
  for (std::uint32_t v : build.wall_top) {
    if (!(mesh.position(v).z > ground_z + 1e-6)) return false;
  }
  return true;
}

void add_walls(const roof_detail::Contour& c, std::uint32_t first_ground, const RoofBuild& build,
               Mesh& mesh, std::uint32_t face_id) {
  std::vector<std::uint32_t> loop;
  for (std::uint32_t e = 0; e < c.size(); ++e) {
    const std::uint32_t j = c.next(e);
    loop.assign({first_ground + e, first_ground + j, build.wall_top[j]});
    loop.insert(loop.end(), build.cap_indices.begin() + build.cap_offsets[e],
                build.cap_indices.begin() + build.cap_offsets[e + 1]);
    loop.push_back(build.wall_top[e]);
    mesh.add_face(loop, {SemanticClass::kWallSurface, 0, face_id++});
  }
}

MassResult try_build(const Polygon& footprint, const MassSpec& spec, const RoofSpec& roof) {
  MassResult result;
  const roof_detail::Contour c = roof_detail::Contour::from(footprint);
  Mesh& mesh = result.mesh;
  const auto first_ground = static_cast<std::uint32_t>(mesh.vertex_count());
  for (const Vec2& p : c.points) mesh.add_vertex(lift(p, spec.ground_z));
  std::vector<std::uint32_t> ground(c.size());
  for (std::uint32_t k = 0; k < c.size(); ++k) ground[k] = first_ground + k;
  if (!roof_detail::add_region(c, ground, {SemanticClass::kGroundSurface, 0, 0}, true, mesh)) {
    result.message = "ground: the ground face could not be triangulated";
    result.mesh = Mesh();
    return result;
  }
  const RoofBuild build = add_roof(footprint, roof, spec.ground_z + spec.wall_height, mesh, 1);
  result.roof = build.built;
  result.message = build.message;
  if (build.status == RoofStatus::kFailed) {
    result.message = "roof: " + build.message;
    result.mesh = Mesh();
    return result;
  }
  if (!walls_above_ground(mesh, build, spec.ground_z)) {
    result.message = "walls: the walls would end below the ground";
    result.mesh = Mesh();
    return result;
  }
  add_walls(c, first_ground, build, mesh, build.next_face_id);
  // The shell is checked here rather than trusted: an open roof must not reach the caller as a
  // building, and the message names the stage (docs/kernel-roofs.md, "Near-rectangles").
  const MeshCheck closure = check(mesh);
  if (!closure.closed || !closure.oriented) {
    result.message = "closure: the " + std::string(roof_type_name(build.built)) +
                     " roof and walls leave " + std::to_string(closure.boundary_edges) +
                     " open and " + std::to_string(closure.non_manifold_edges) +
                     " non-manifold edges";
    result.mesh = Mesh();
    return result;
  }
  result.status = build.status == RoofStatus::kOk ? MassStatus::kOk : MassStatus::kFallback;
  return result;
}

constexpr double kPostSide = 0.25;       // meters, the square posts of a roof without walls
constexpr double kSlabThickness = 0.25;  // flat and shed roofs on posts

void retag(Mesh& mesh, std::size_t first_face, SemanticClass from, SemanticClass to) {
  for (std::size_t f = first_face; f < mesh.face_count(); ++f) {
    if (mesh.tag(f).semantic == from) mesh.tag(f).semantic = to;
  }
}

// S3DB building=roof: the roof as a closed solid on a post under each outer-ring corner
// (docs/kernel-roofs.md, "Roofs on posts"). The roof's underside is flat at the eave (at the
// soffit with overhang); flat and shed roofs are slabs under their surface.
MassResult roof_on_posts(const Polygon& footprint, const MassSpec& spec, const RoofSpec& roof) {
  MassResult result;
  const double eave_z = spec.ground_z + spec.wall_height;
  roof_detail::RoofPlan plan;
  if (!roof_detail::plan_roof(footprint, roof, plan)) {
    result.message = "roof: " + plan.message;
    return result;
  }
  Mesh& mesh = result.mesh;
  // Height of the roof's underside above eave_z - kSlabThickness at p (flat and shed slabs).
  const auto rise = [&](Vec2 p) {
    return plan.type == RoofType::kShed ? plan.slope * roof_detail::shed_distance(plan, p) : 0.0;
  };
  const bool slab = plan.type == RoofType::kFlat || plan.type == RoofType::kShed;
  if (slab) {
    const PrismTags tags{{SemanticClass::kOuterCeilingSurface, 0, 1},
                         {SemanticClass::kRoofSurface, 0, 2},
                         {SemanticClass::kRoofSurface, 0, 3}};
    if (!add_prism(mesh, footprint, eave_z - kSlabThickness, eave_z, tags)) {
      result.message = "roof: the slab could not be built";
      result.mesh = Mesh();
      return result;
    }
    for (Vec3& p : mesh.positions()) p.z += rise(drop(p));  // a shear keeps faces planar
  } else {
    RoofSolidSpec solid_spec;
    solid_spec.roof = roof;
    RoofSolid solid = build_roof_solid(footprint, solid_spec, eave_z);
    if (solid.status == RoofStatus::kFailed) {
      result.message = "roof: " + solid.message;
      return result;
    }
    mesh = std::move(solid.mesh);
    // A roof without walls has no wall surfaces: its gable ends belong to the roof, its bottom is
    // seen from below.
    retag(mesh, 0, SemanticClass::kWallSurface, SemanticClass::kRoofSurface);
    retag(mesh, 0, SemanticClass::kClosureSurface, SemanticClass::kOuterCeilingSurface);
  }
  double underside = 1e300;
  for (const Vec3& p : mesh.positions()) underside = std::min(underside, p.z);
  const Ring& outer = footprint.outer;
  for (std::size_t k = 0; k < outer.size(); ++k) {
    // A square in the corner, along the edge that leaves it.
    const Vec2 u = normalized(outer[(k + 1) % outer.size()] - outer[k]) * kPostSide;
    const Vec2 v = perp(u);
    const Polygon post{{outer[k], outer[k] + u, outer[k] + u + v, outer[k] + v}, {}};
    double top = underside;
    if (slab) {
      double lowest = 1e300;
      for (const Vec2& q : post.outer) lowest = std::min(lowest, rise(q));
      top = eave_z - kSlabThickness + lowest;
    }
    if (!(top > spec.ground_z + 0.01)) {
      result.message = "posts: the roof's underside is not above the ground";
      result.mesh = Mesh();
      return result;
    }
    const PrismTags tags{{SemanticClass::kGroundSurface, 0, 0},
                         {SemanticClass::kClosureSurface, 0, 0},
                         {SemanticClass::kNone, 0, 0}};
    add_prism(mesh, post, spec.ground_z, top, tags);
  }
  result.roof = plan.type;
  result.message = plan.message;
  result.status = plan.status == RoofStatus::kOk ? MassStatus::kOk : MassStatus::kFallback;
  return result;
}

}  // namespace

MassResult build_mass(const Polygon& footprint, const MassSpec& spec) {
  MassResult failed;
  if (!(spec.wall_height > 0 && spec.wall_height < 1e4) || !std::isfinite(spec.ground_z)) {
    failed.message = "wall height must be in (0, 10000) m and ground height finite";
    return failed;
  }
  Polygon clean;
  if (!prepare(footprint, clean, failed.message)) return failed;
  const RoofSpec roof = roof_spec(spec);
  const auto attempt = [&](const RoofSpec& r) {
    return spec.walls ? try_build(clean, spec, r) : roof_on_posts(clean, spec, r);
  };
  // A large overhang on a steep roof can bring the soffit (or a roof on posts' underside) down to
  // the ground: drop the overhang.
  const auto attempt_flush_if_needed = [&](const RoofSpec& r) {
    MassResult result = attempt(r);
    if (result.status != MassStatus::kFailed || r.overhang <= 0) return result;
    RoofSpec flush = r;
    flush.overhang = 0;
    MassResult retry = attempt(flush);
    if (retry.status == MassStatus::kFailed) return result;
    retry.status = MassStatus::kFallback;
    retry.message = result.message + "; built without overhang" +
                    (retry.message.empty() ? "" : "; " + retry.message);
    return retry;
  };
  MassResult result = attempt_flush_if_needed(roof);
  if (result.status != MassStatus::kFailed) return result;
  // A shape that cannot close over this outline (a round roof over a near-rectangle with a nearly
  // collinear extra corner, from Philadelphia's and IGN's registers) gives the building a hip
  // roof, then a flat one, rather than no building at all.
  for (const RoofType other : {RoofType::kHip, RoofType::kFlat}) {
    if (other == roof.type) continue;
    RoofSpec plain = roof;
    plain.type = other;
    MassResult retry = attempt_flush_if_needed(plain);
    if (retry.status == MassStatus::kFailed) continue;
    retry.status = MassStatus::kFallback;
    retry.message = result.message + "; built with a " + std::string(roof_type_name(other)) +
                    " roof" + (retry.message.empty() ? "" : "; " + retry.message);
    return retry;
  }
  return result;
}

}  // namespace insula::kernel
