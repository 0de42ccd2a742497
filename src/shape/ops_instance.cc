// Explicit creation of components (seed 001 §3.4.3 "Instancing": children in the parent's space,
// clipped by the parent's boundary), components from boundary faces, and connection of components
// to regions (§3.4.2, §4.5: furniture and fixtures on floor, wall and ceiling regions, kept clear
// of doors and windows).
#include <algorithm>
#include <cmath>

#include "kernel/boolean2d.h"
#include "kernel/plane_split.h"
#include "shape/component_ops.h"

namespace insula::shape {

using kernel::FaceTag;
using kernel::Mesh;
using kernel::Vec3;

namespace {

// `mesh` (closed, parent space) clipped to the box [lo, hi] by six plane cuts (kernel::split): the
// intersection of a solid with a box without a general 3D boolean.
Mesh clip_to_box(const Mesh& mesh, Vec3 lo, Vec3 hi) {
  Mesh current = kernel::weld(mesh);
  const std::array<kernel::Plane, 6> planes = {{{{-1, 0, 0}, -lo.x},
                                                {{1, 0, 0}, hi.x},
                                                {{0, -1, 0}, -lo.y},
                                                {{0, 1, 0}, hi.y},
                                                {{0, 0, -1}, -lo.z},
                                                {{0, 0, 1}, hi.z}}};
  for (const kernel::Plane& plane : planes) {
    kernel::SplitOptions options;
    options.cap_tag = {kernel::SemanticClass::kInteriorWallSurface, 0, 0};
    kernel::SplitResult r = kernel::split(current, plane, options);
    if (!r.ok()) return {};
    current = kernel::weld(r.negative);
    if (current.empty()) break;
  }
  return current;
}

Mesh translated(const Mesh& mesh, Vec3 by) {
  Mesh out = mesh;
  for (Vec3& p : out.positions()) p += by;
  return out;
}

}  // namespace

OpResult instance_box(ShapeTree& tree, ShapeId parent, Vec3 offset, Vec3 size, bool clip) {
  if (!(size.x >= 0 && size.y >= 0 && size.z >= 0) || !std::isfinite(size.x + size.y + size.z)) {
    return OpResult::failure("size must be finite and >= 0");
  }
  const bool flat = size.z == 0;
  if ((flat && !(size.x > 0 && size.y > 0)) || (!flat && !(size.x > 0 && size.y > 0))) {
    return OpResult::failure("a component needs a size > 0 along x and y");
  }
  Scope scope;
  if (parent == kNoShape) {
    scope.origin = offset;
  } else {
    scope = tree[parent].scope.sub(offset, size);
  }
  scope.size = size;
  OpResult result;
  if (flat) {
    auto outline = std::make_shared<kernel::Polygon>(
        kernel::Polygon{{{0, 0}, {size.x, 0}, {size.x, size.y}, {0, size.y}}, {}});
    if (clip && parent != kNoShape && tree[parent].is_flat()) {
      kernel::Polygon p = *tree[parent].outline;
      for (auto* ring : {&p.outer}) {
        for (auto& q : *ring) q -= kernel::Vec2{offset.x, offset.y};
      }
      for (auto& hole : p.holes) {
        for (auto& q : hole) q -= kernel::Vec2{offset.x, offset.y};
      }
      const kernel::BooleanResult r = kernel::intersect({*outline}, {p});
      if (!r.ok() || r.polygons.empty())
        return OpResult::failure("the component lies outside its parent");
      *outline = r.polygons[0];  // the largest piece (descending area)
    }
    auto mesh = flat_mesh(*outline, {kernel::SemanticClass::kNone, 0, 0});
    const ShapeId id = parent == kNoShape ? tree.add_root(scope, mesh, outline)
                                          : tree.add_child(parent, scope, mesh, outline);
    result.add(id, 0);
    return result;
  }
  std::shared_ptr<const Mesh> mesh = box_mesh(size, mass_box_tags());
  if (clip && parent != kNoShape && tree[parent].mesh && !tree[parent].is_flat()) {
    const Shape& p = tree[parent];
    if (!is_box(*p.mesh, p.scope.size, nullptr) || offset.x < 0 || offset.y < 0 || offset.z < 0 ||
        offset.x + size.x > p.scope.size.x || offset.y + size.y > p.scope.size.y ||
        offset.z + size.z > p.scope.size.z) {
      // Parent space: the child box is [offset, offset + size].
      Mesh clipped = clip_to_box(*p.mesh, offset, offset + size);
      if (clipped.empty()) return OpResult::failure("the component lies outside its parent");
      const kernel::Bounds3 b = clipped.bounds();
      scope = p.scope.sub(b.min, b.size());
      mesh = std::make_shared<Mesh>(translated(clipped, -b.min));
    }
  }
  result.add(parent == kNoShape ? tree.add_root(scope, mesh) : tree.add_child(parent, scope, mesh),
             0);
  return result;
}

OpResult face_component(ShapeTree& tree, ShapeId parent, std::size_t face) {
  const Shape& s = tree[parent];
  if (!s.mesh || face >= s.mesh->face_count()) return OpResult::failure("no such face");
  Scope local;
  if (!face_scope(*s.mesh, face, {0, 1, 0}, {1, 0, 0}, local)) {
    return OpResult::failure("the face is degenerate");
  }
  Mesh loop_mesh;
  std::vector<Vec3> loop;
  for (std::uint32_t v : s.mesh->face(face)) loop.push_back(s.mesh->position(v));
  loop_mesh.add_polygon(loop, s.mesh->tag(face));
  Refit fit = refit(s.scope, loop_mesh, local.x, local.y, local.z);
  fit.scope.size.z = 0;
  auto outline = std::make_shared<kernel::Polygon>();
  for (Vec3& p : fit.mesh.positions()) {
    p.z = 0;
    outline->outer.push_back(kernel::drop(p));
  }
  kernel::normalize(*outline);
  OpResult result;
  result.add(tree.add_child(parent, fit.scope, std::make_shared<Mesh>(std::move(fit.mesh)),
                            std::move(outline)),
             static_cast<std::uint32_t>(face));
  return result;
}

std::shared_ptr<const Mesh> normalized_asset(const Mesh& mesh) {
  const kernel::Bounds3 b = mesh.bounds();
  return std::make_shared<Mesh>(translated(mesh, b.empty() ? Vec3{} : -b.min));
}

namespace {

// The scope a connected component of extent `size` gets for `placement` on `owner`.
Scope connected_scope(const Scope& owner, const RegionPlacement& placement, Vec3 size) {
  Scope s = owner;
  s = rotated(s, Axis::kX, placement.degrees.x, {});
  s = rotated(s, Axis::kY, placement.degrees.y, {});
  s = rotated(s, Axis::kZ, placement.degrees.z, {});
  s.size = size;
  const Vec3 connector{size.x / 2, 0, size.z / 2};
  s.origin = owner.to_world(placement.position) - s.direction_to_world(connector);
  return s;
}

}  // namespace

Connected connect_mesh(ShapeTree& tree, ShapeId owner, const RegionPlacement& placement,
                       std::shared_ptr<const Mesh> mesh) {
  if (!mesh || mesh->empty()) return {kNoShape, "the component to connect has no geometry"};
  const Scope scope = connected_scope(tree[owner].scope, placement, mesh->bounds().size());
  return {tree.add_child(owner, scope, std::move(mesh)), {}};
}

bool boxes_overlap(const Scope& a, const Scope& b, double clearance) {
  const std::array<Vec3, 3> ax = {a.x, a.y, a.z};
  const std::array<Vec3, 3> bx = {b.x, b.y, b.z};
  const std::array<double, 3> ah = {a.size.x / 2, a.size.y / 2, a.size.z / 2};
  const std::array<double, 3> bh = {b.size.x / 2, b.size.y / 2, b.size.z / 2};
  const Vec3 d = b.center() - a.center();
  const auto separated = [&](Vec3 axis) {
    const double l = length(axis);
    if (l < 1e-9) return false;
    axis = axis / l;
    double ra = 0;
    double rb = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      ra += ah[i] * std::fabs(dot(ax[i], axis));
      rb += bh[i] * std::fabs(dot(bx[i], axis));
    }
    return std::fabs(dot(d, axis)) - ra - rb >= clearance;
  };
  for (std::size_t i = 0; i < 3; ++i) {
    if (separated(ax[i]) || separated(bx[i])) return false;
  }
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (separated(cross(ax[i], bx[j]))) return false;
    }
  }
  return true;
}

Connected place_on_region(ShapeTree& tree, ShapeId owner, std::size_t region,
                          std::shared_ptr<const Mesh> mesh, const PlaceOptions& options) {
  if (region >= tree[owner].regions.size()) return {kNoShape, "no such region"};
  if (!mesh || mesh->empty()) return {kNoShape, "the component to place has no geometry"};
  const Region r = tree[owner].regions[region];
  const Vec3 size = mesh->bounds().size();
  Rng rng(child_seed(tree[owner].seed ^ 0x9e3779b97f4a7c15ULL,
                     static_cast<std::uint32_t>(options.draw * 131 + region)));
  for (int attempt = 0; attempt < std::max(1, options.attempts); ++attempt) {
    const RegionPlacement placement = sample(r, rng);
    const Scope scope = connected_scope(tree[owner].scope, placement, size);
    const bool blocked = std::any_of(options.avoid.begin(), options.avoid.end(), [&](ShapeId o) {
      return boxes_overlap(scope, tree[o].scope, options.clearance);
    });
    if (!blocked) return {tree.add_child(owner, scope, std::move(mesh)), {}};
  }
  return {kNoShape, "no free place in region '" + r.name + "'"};
}

}  // namespace insula::shape
