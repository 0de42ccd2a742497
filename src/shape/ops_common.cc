// Helpers shared by the operation families: box geometry, shape refitting, bookkeeping.
#include <array>
#include <cmath>

#include "shape/ops.h"

namespace insula::shape {

using kernel::FaceTag;
using kernel::Mesh;
using kernel::SemanticClass;
using kernel::Vec3;

namespace {

// Corner i of a box has x = bit 0, y = bit 1, z = bit 2. Loops run counter-clockwise seen from
// outside, sides in the order -x, +x, -y, +y, -z, +z.
constexpr std::array<std::array<std::uint32_t, 4>, 6> kBoxLoops = {{
    {2, 0, 4, 6},
    {1, 3, 7, 5},
    {0, 1, 5, 4},
    {3, 2, 6, 7},
    {0, 2, 3, 1},
    {4, 5, 7, 6},
}};

// Side index (0..5, order of kBoxLoops) of an axis-aligned face lying on a box side, or -1.
int box_side(const Mesh& mesh, std::size_t face, Vec3 size, double tolerance) {
  const auto loop = mesh.face(face);
  if (loop.size() != 4) return -1;
  const std::array<double, 3> s = {size.x, size.y, size.z};
  for (int axis = 0; axis < 3; ++axis) {
    for (int high = 0; high < 2; ++high) {
      const double target = high != 0 ? s[static_cast<std::size_t>(axis)] : 0.0;
      bool on_side = true;
      for (std::uint32_t v : loop) {
        const Vec3 p = mesh.position(v);
        const std::array<double, 3> q = {p.x, p.y, p.z};
        on_side = on_side && std::fabs(q[static_cast<std::size_t>(axis)] - target) <= tolerance;
      }
      if (on_side) return axis * 2 + high;
    }
  }
  return -1;
}

bool on_corners(const Mesh& mesh, Vec3 size, double tolerance) {
  const auto near = [&](double v, double s) {
    return std::fabs(v) <= tolerance || std::fabs(v - s) <= tolerance;
  };
  for (const Vec3& p : mesh.positions()) {
    if (!near(p.x, size.x) || !near(p.y, size.y) || !near(p.z, size.z)) return false;
  }
  return true;
}

}  // namespace

std::shared_ptr<const Mesh> box_mesh(Vec3 size, std::span<const FaceTag, 6> tags) {
  auto mesh = std::make_shared<Mesh>();
  mesh->reserve(8, 6, 24);
  for (int i = 0; i < 8; ++i) {
    mesh->add_vertex({(i & 1) ? size.x : 0, (i & 2) ? size.y : 0, (i & 4) ? size.z : 0});
  }
  for (std::size_t side = 0; side < 6; ++side) {
    mesh->add_face(std::span<const std::uint32_t>(kBoxLoops[side]), tags[side]);
  }
  return mesh;
}

// No face ids (0): a face id is an interned name of the shape tree (ShapeTree::face_id, seed 001
// §3.1.1), so raw side numbers 1-5 would read as whichever names a tree interned first.
std::array<FaceTag, 6> mass_box_tags() {
  return {{{SemanticClass::kWallSurface, 0, 0},
           {SemanticClass::kWallSurface, 0, 0},
           {SemanticClass::kGroundSurface, 0, 0},
           {SemanticClass::kRoofSurface, 0, 0},
           {SemanticClass::kWallSurface, 0, 0},
           {SemanticClass::kWallSurface, 0, 0}}};
}

bool is_box(const Mesh& mesh, Vec3 size, std::array<FaceTag, 6>* tags, double tolerance) {
  if (mesh.face_count() != 6 || !(size.x > 0 && size.y > 0 && size.z > 0)) return false;
  if (!on_corners(mesh, size, tolerance)) return false;
  std::array<bool, 6> seen{};
  for (std::size_t f = 0; f < 6; ++f) {
    const int side = box_side(mesh, f, size, tolerance);
    if (side < 0 || seen[static_cast<std::size_t>(side)]) return false;
    // The face must face outward: its normal along the side's direction.
    const Vec3 n = kernel::face_normal(mesh, f);
    const std::array<double, 3> q = {n.x, n.y, n.z};
    const double along = q[static_cast<std::size_t>(side / 2)];
    if ((side % 2 == 1 ? along : -along) < 0.5) return false;
    seen[static_cast<std::size_t>(side)] = true;
    if (tags != nullptr) (*tags)[static_cast<std::size_t>(side)] = mesh.tag(f);
  }
  return true;
}

bool is_rectangle(const kernel::Polygon& outline, double w, double h, double tolerance) {
  if (!outline.holes.empty() || outline.outer.size() != 4) return false;
  int corners = 0;
  for (kernel::Vec2 p : outline.outer) {
    const bool x_ok = std::fabs(p.x) <= tolerance || std::fabs(p.x - w) <= tolerance;
    const bool y_ok = std::fabs(p.y) <= tolerance || std::fabs(p.y - h) <= tolerance;
    if (!x_ok || !y_ok) return false;
    corners |= 1 << ((std::fabs(p.x) <= tolerance ? 0 : 1) + (std::fabs(p.y) <= tolerance ? 0 : 2));
  }
  return corners == 0b1111 && std::fabs(kernel::signed_area(outline.outer) - w * h) <= tolerance;
}

Refit refit(const Scope& parent, const Mesh& mesh, Vec3 x, Vec3 y, Vec3 z) {
  kernel::Bounds3 b;
  for (const Vec3& p : mesh.positions()) b.add({dot(p, x), dot(p, y), dot(p, z)});
  if (b.empty()) b.add({});
  Refit out;
  out.mesh = mesh;
  for (Vec3& p : out.mesh.positions()) p = Vec3{dot(p, x), dot(p, y), dot(p, z)} - b.min;
  out.scope.origin = parent.to_world(x * b.min.x + y * b.min.y + z * b.min.z);
  out.scope.x = parent.direction_to_world(x);
  out.scope.y = parent.direction_to_world(y);
  out.scope.z = parent.direction_to_world(z);
  out.scope.size = b.max - b.min;
  return out;
}

OpResult replace_with(ShapeTree& tree, ShapeId id, const Mesh& mesh, Vec3 x, Vec3 y, Vec3 z,
                      std::string warning) {
  Refit child = refit(tree[id].scope, mesh, x, y, z);
  OpResult result;
  result.add(tree.add_child(id, child.scope, std::make_shared<Mesh>(std::move(child.mesh))), 0);
  result.warning = std::move(warning);
  return finish(tree, id, std::move(result));
}

OpResult relabelled_child(ShapeTree& tree, ShapeId id, const Scope& scope,
                          std::shared_ptr<const Mesh> mesh,
                          std::shared_ptr<const kernel::Polygon> outline, std::string warning) {
  const ShapeId child = tree.add_child(id, scope, std::move(mesh), std::move(outline));
  // The moved shape is the same grammar symbol: keep its labels (they are not inherited by
  // children in general, seed 001 §3.1, but a scope rule does not make a new kind of shape).
  tree[child].labels = tree[id].labels;
  OpResult r;
  r.add(child, 0);
  r.warning = std::move(warning);
  return finish(tree, id, std::move(r));
}

OpResult finish(ShapeTree& tree, ShapeId id, OpResult result) {
  if (result.ok() && !result.children.empty()) tree.deactivate(id);
  return result;
}

std::shared_ptr<const kernel::Mesh> find_asset(const Context& context, const std::string& name,
                                               std::string& error) {
  if (context.assets == nullptr) {
    error = "no asset provider";
    return nullptr;
  }
  auto mesh = context.assets->find(name, error);
  if (!mesh && error.empty()) error = "asset '" + name + "' not found";
  return mesh;
}

}  // namespace insula::shape
