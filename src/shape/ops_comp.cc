// Component split (seed 004, "Component Split Rule": faces, edges, vertices, side faces): a shape
// of lower dimension per face, edge or vertex of the parent's geometry.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "shape/ops.h"

namespace insula::shape {

using kernel::Mesh;
using kernel::Vec3;

bool face_matches(FaceSelector selector, Vec3 n) {
  if (selector == FaceSelector::kAll) return true;
  if (selector >= FaceSelector::kBorder) return false;  // by the mesh, not by the normal
  if (selector >= FaceSelector::kVertical) {
    const double len = length(n);
    if (len == 0) return false;
    const double sine = n.y / len;  // of the angle between the normal and the xz plane
    const double edge = std::sin(11.25 * std::numbers::pi / 180);
    const double steep = std::sin(78.75 * std::numbers::pi / 180);
    switch (selector) {
      case FaceSelector::kHorizontal:
        return std::fabs(sine) > steep;
      case FaceSelector::kAslant:
        return sine > edge && sine <= steep;
      case FaceSelector::kNutant:
        return sine < -edge && sine >= -steep;
      default:
        return std::fabs(sine) <= edge;
    }
  }
  const double ax = std::fabs(n.x);
  const double ay = std::fabs(n.y);
  const double az = std::fabs(n.z);
  // The dominant direction decides; ties go to y (top/bottom), then z (front/back).
  const bool vertical_axis = ay >= ax && ay >= az;
  if (vertical_axis) {
    return (selector == FaceSelector::kTop && n.y > 0) ||
           (selector == FaceSelector::kBottom && n.y < 0);
  }
  if (selector == FaceSelector::kSide) return true;
  if (az >= ax) {
    return (selector == FaceSelector::kFront && n.z > 0) ||
           (selector == FaceSelector::kBack && n.z < 0);
  }
  return (selector == FaceSelector::kRight && n.x > 0) ||
         (selector == FaceSelector::kLeft && n.x < 0);
}

namespace {

// Face `f` of `mesh` (parent scope space) as a flat child: scope fitted to the face with
// z = normal, x horizontal (scope y is up), outline = the loop in the child's xy plane.
bool face_child(const Scope& parent, const Mesh& mesh, std::size_t f, Refit& out,
                kernel::Polygon& outline) {
  Scope local;  // in parent scope space
  if (!face_scope(mesh, f, {0, 1, 0}, {1, 0, 0}, local)) return false;
  Mesh face;
  std::vector<Vec3> loop;
  for (std::uint32_t v : mesh.face(f)) loop.push_back(mesh.position(v));
  face.add_polygon(loop, mesh.tag(f));
  out = refit(parent, face, local.x, local.y, local.z);
  out.scope.size.z = 0;
  outline.outer.clear();
  for (Vec3& p : out.mesh.positions()) {
    p.z = 0;  // planar by construction; drop rounding
    outline.outer.push_back(kernel::drop(p));
  }
  return true;
}

}  // namespace

std::optional<ShapeId> add_face_child(ShapeTree& tree, ShapeId id, std::size_t face) {
  const Shape& s = tree[id];
  Refit child;
  auto outline = std::make_shared<kernel::Polygon>();
  if (!s.mesh || !face_child(s.scope, *s.mesh, face, child, *outline)) return std::nullopt;
  auto child_mesh = std::make_shared<Mesh>(std::move(child.mesh));
  return tree.add_child(id, child.scope, std::move(child_mesh), std::move(outline));
}

std::vector<bool> border_faces(const Mesh& mesh) {
  const Mesh welded = kernel::weld(mesh);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t f = 0; f < welded.face_count(); ++f) {
    const auto loop = welded.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = loop[i];
      const std::uint32_t b = loop[(i + 1) % loop.size()];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::vector<bool> border(welded.face_count(), false);
  for (std::size_t f = 0; f < welded.face_count(); ++f) {
    const auto loop = welded.face(f);
    for (std::size_t i = 0; i < loop.size() && !border[f]; ++i) {
      const std::uint32_t a = loop[i];
      const std::uint32_t b = loop[(i + 1) % loop.size()];
      border[f] = uses[{std::min(a, b), std::max(a, b)}] == 1;
    }
  }
  return border;
}

OpResult comp_faces(ShapeTree& tree, ShapeId id, FaceSelector selector) {
  const Shape& s = tree[id];
  if (!s.mesh) return OpResult::failure("the shape has no faces");
  const std::shared_ptr<const Mesh> mesh = s.mesh;
  const bool by_border = selector == FaceSelector::kBorder || selector == FaceSelector::kInside;
  const std::vector<bool> border = by_border ? border_faces(*mesh) : std::vector<bool>();
  OpResult result;
  for (std::size_t f = 0; f < mesh->face_count(); ++f) {
    if (by_border ? border[f] != (selector == FaceSelector::kBorder)
                  : !face_matches(selector, kernel::face_normal(*mesh, f))) {
      continue;
    }
    const std::optional<ShapeId> child = add_face_child(tree, id, f);
    if (child) result.add(*child, static_cast<std::uint32_t>(f));  // else a degenerate face
  }
  return finish(tree, id, std::move(result));
}

OpResult comp_faces_in_frame(ShapeTree& tree, ShapeId id, const FrameSelector& selector,
                             const Scope* object) {
  const Shape& s = tree[id];
  if (!s.mesh) return OpResult::failure("the shape has no faces");
  const std::shared_ptr<const Mesh> mesh = s.mesh;
  const Scope scope = s.scope;
  OpResult result;
  for (std::size_t f = 0; f < mesh->face_count(); ++f) {
    const Vec3 n = scope.direction_to_world(kernel::face_normal(*mesh, f));
    if (!face_matches_in_frame(selector, n, object)) continue;
    const std::optional<ShapeId> child = add_face_child(tree, id, f);
    if (child) result.add(*child, static_cast<std::uint32_t>(f));
  }
  return finish(tree, id, std::move(result));
}

OpResult comp_edges(ShapeTree& tree, ShapeId id, FaceSelector selector) {
  const Shape& s = tree[id];
  if (!s.mesh) return OpResult::failure("the shape has no edges");
  const Mesh welded = kernel::weld(*s.mesh);
  const std::vector<MeshEdge> edges = mesh_edges(welded);
  const std::vector<bool> selected = select_edges(welded, edges, selector);
  const Scope scope = s.scope;
  OpResult result;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!selected[e]) continue;
    const Vec3 a = welded.position(edges[e].a);
    const Vec3 b = welded.position(edges[e].b);
    Vec3 n;
    for (std::uint32_t f : edges[e].faces) n += kernel::face_normal(welded, f);
    Scope local;
    if (length(cross(n, b - a)) < 1e-12) n = cross(b - a, {0, 1, 0});  // no usable face normal
    if (length(cross(n, b - a)) < 1e-12) n = cross(b - a, {1, 0, 0});
    if (!make_frame(b - a, n, local.x, local.y, local.z)) continue;
    Scope child = scope;
    child.origin = scope.to_world(a);
    child.x = scope.direction_to_world(local.x);
    child.y = scope.direction_to_world(local.y);
    child.z = scope.direction_to_world(local.z);
    child.size = {length(b - a), 0, 0};
    result.add(tree.add_child(id, child), static_cast<std::uint32_t>(e));
  }
  return finish(tree, id, std::move(result));
}

OpResult comp_face_edges(ShapeTree& tree, ShapeId id) {
  const Shape& s = tree[id];
  if (!s.mesh) return OpResult::failure("the shape has no edges");
  const std::shared_ptr<const Mesh> mesh = s.mesh;
  const Scope scope = s.scope;
  OpResult result;
  std::uint32_t index = 0;
  for (std::size_t f = 0; f < mesh->face_count(); ++f) {
    const Vec3 n = kernel::face_normal(*mesh, f);
    const auto loop = mesh->face(f);
    for (std::size_t i = 0; i < loop.size(); ++i, ++index) {
      const Vec3 a = mesh->position(loop[i]);
      const Vec3 d = mesh->position(loop[(i + 1) % loop.size()]) - a;
      // x along the edge in loop order, y the face's normal, z out of the face in its plane.
      const Vec3 z = cross(d, n);
      if (length(n) < 0.5 || length(z) < 1e-12) continue;
      Scope child = scope;
      child.origin = scope.to_world(a);
      child.x = scope.direction_to_world(normalized(d));
      child.z = scope.direction_to_world(normalized(z));
      child.y = cross(child.z, child.x);
      child.size = {length(d), 0, 0};
      result.add(tree.add_child(id, child), index);
    }
  }
  return finish(tree, id, std::move(result));
}

OpResult comp_vertices(ShapeTree& tree, ShapeId id, FaceSelector selector) {
  const Shape& s = tree[id];
  if (!s.mesh) return OpResult::failure("the shape has no vertices");
  const Mesh welded = kernel::weld(*s.mesh);
  std::vector<bool> used(welded.vertex_count(), false);
  for (std::size_t f = 0; f < welded.face_count(); ++f) {
    for (std::uint32_t v : welded.face(f)) used[v] = true;
  }
  const std::vector<bool> selected = select_vertices(welded, selector);
  const Scope scope = s.scope;
  OpResult result;
  for (std::uint32_t v = 0; v < welded.vertex_count(); ++v) {
    if (!used[v] || !selected[v]) continue;
    result.add(tree.add_child(id, scope.sub(welded.position(v), {})), v);
  }
  return finish(tree, id, std::move(result));
}

namespace {

std::vector<std::string> comp_selector_words() {
  std::vector<std::string> words = {
      "front",      "back",   "left",   "right",  "top",    "bottom", "side", "all",    "vertical",
      "horizontal", "aslant", "nutant", "border", "inside", "eave",   "hip",  "valley", "ridge"};
  for (std::string& word : frame_selector_words()) words.push_back(std::move(word));
  return words;
}

}  // namespace

std::vector<Operation> comp_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"comp",
       "Splits a shape into its faces (by selector), edges, vertices or face edges (CGA comp); "
       "faces become flat shapes with z = outward normal, edges and face edges line scopes (a "
       "face edge: x along the face's loop, y its normal, z out of the face), vertices point "
       "scopes.",
       {{"type",
         ParamType::kEnum,
         "component kind",
         ArgValue{std::string("faces")},
         {"faces", "edges", "vertices", "faceedges"},
         {},
         {}},
        {"select",
         ParamType::kEnum,
         "which components (the roof classes eave, hip, valley, ridge: edges only; face edges: "
         "all)",
         ArgValue{std::string("all")},
         comp_selector_words(),
         {},
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context& context) {
         const std::string& type = a.string("type");
         if (const std::optional<FrameSelector> in_frame = frame_selector_named(a.string("select"));
             in_frame && type == "faces") {
           return comp_faces_in_frame(t, id, *in_frame, context.object);
         }
         const FaceSelector selector =
             face_selector_named(a.string("select")).value_or(FaceSelector::kAll);
         if (type == "edges") return comp_edges(t, id, selector);
         if (type == "vertices") return comp_vertices(t, id, selector);
         if (type == "faceedges") return comp_face_edges(t, id);
         return comp_faces(t, id, selector);
       }});
  return ops;
}

}  // namespace insula::shape
