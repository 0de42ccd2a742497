// Component split (seed 004, "Component Split Rule": faces, edges, vertices, side faces): a shape
// of lower dimension per face, edge or vertex of the parent's geometry.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>

#include "base/union_find.h"

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

// The pieces of one logical face, by their first face: faces that share an edge, a plane and a
// tag. A region with holes is stored as several faces (extrude triangulates a courtyard lot's
// cap, or frames its hole with quads), and comp must give it as one face: each triangle of a
// courtyard's top got a roof of its own.
std::vector<std::vector<std::size_t>> face_groups(const Mesh& mesh) {
  const std::size_t n = mesh.face_count();
  std::vector<Vec3> normals(n);
  std::vector<double> offsets(n);
  for (std::size_t f = 0; f < n; ++f) {
    normals[f] = normalized(kernel::face_normal(mesh, f));
    offsets[f] = dot(normals[f], mesh.position(mesh.face(f)[0]));
  }
  // A face's tag and normal (to 1e-6). Most meshes (a lot's mass, a roof) have no two faces with
  // the same: nothing to weld.
  std::vector<std::array<std::int64_t, 6>> keys(n);
  for (std::size_t f = 0; f < n; ++f) {
    const kernel::FaceTag& t = mesh.tag(f);
    keys[f] = {static_cast<std::int64_t>(t.semantic),
               t.material,
               t.face_id,
               std::llround(normals[f].x * 1e6),
               std::llround(normals[f].y * 1e6),
               std::llround(normals[f].z * 1e6)};
  }
  std::vector<std::array<std::int64_t, 6>> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) {
    std::vector<std::vector<std::size_t>> singles(n);
    for (std::size_t f = 0; f < n; ++f) singles[f] = {f};
    return singles;
  }
  const double tolerance = 1e-7 * std::max(1.0, length(mesh.bounds().size()));
  const Mesh welded = kernel::weld(mesh);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> first_face_of_edge;
  base::UnionFind groups(n);
  for (std::size_t f = 0; f < n; ++f) {
    const auto loop = welded.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = loop[i];
      const std::uint32_t b = loop[(i + 1) % loop.size()];
      const auto [it, added] = first_face_of_edge.try_emplace({std::min(a, b), std::max(a, b)}, f);
      const std::size_t g = it->second;
      if (added || g == f) continue;
      if (keys[f] == keys[g] && std::fabs(offsets[f] - offsets[g]) <= tolerance) {
        groups.unite(static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(g));
      }
    }
  }
  std::vector<std::vector<std::size_t>> out;
  std::map<std::uint32_t, std::size_t> index_of_root;
  for (std::size_t f = 0; f < n; ++f) {
    const auto [it, added] =
        index_of_root.try_emplace(groups.find(static_cast<std::uint32_t>(f)), out.size());
    if (added) out.emplace_back();
    out[it->second].push_back(f);
  }
  return out;
}

// The region the faces of a flat `mesh` (in its xy plane, counter-clockwise) cover together:
// their boundary edges (those no other face runs back along) chained into rings, one
// counter-clockwise outer ring and clockwise holes. Nullopt when the boundary pinches (a vertex
// with two ways on) or makes more than one outer ring. Corners are the same vertex where their
// positions are equal: the faces come from one mesh.
std::optional<kernel::Polygon> faces_outline(const Mesh& mesh) {
  std::map<std::pair<double, double>, std::uint32_t> vertex_of;
  std::vector<kernel::Vec2> points;
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    std::vector<std::uint32_t> loop;
    for (std::uint32_t v : mesh.face(f)) {
      const Vec3 p = mesh.position(v);
      const auto [it, added] = vertex_of.try_emplace({p.x, p.y}, points.size());
      if (added) points.push_back({p.x, p.y});
      loop.push_back(it->second);
    }
    for (std::size_t i = 0; i < loop.size(); ++i)
      edges.insert({loop[i], loop[(i + 1) % loop.size()]});
  }
  std::map<std::uint32_t, std::uint32_t> next;
  for (const auto& [a, b] : edges) {
    if (edges.contains({b, a})) continue;  // inside: two faces share it
    if (!next.try_emplace(a, b).second) return std::nullopt;
  }
  kernel::Polygon region;
  bool outer = false;
  while (!next.empty()) {
    kernel::Ring ring;
    std::uint32_t v = next.begin()->first;
    for (auto it = next.find(v); it != next.end(); it = next.find(v)) {
      ring.push_back(points[v]);
      v = it->second;
      next.erase(it);
    }
    if (ring.size() < 3) return std::nullopt;
    if (kernel::signed_area(ring) > 0) {
      if (outer) return std::nullopt;
      outer = true;
      region.outer = std::move(ring);
    } else {
      region.holes.push_back(std::move(ring));
    }
  }
  if (!outer) return std::nullopt;
  return region;
}

// The faces `group` of the shape's mesh as one flat child, its outline their union (with the
// holes between them); nullopt when they do not unite into one polygon.
std::optional<ShapeId> add_group_child(ShapeTree& tree, ShapeId id,
                                       const std::vector<std::size_t>& group) {
  const Shape& s = tree[id];
  Scope local;
  if (!face_scope(*s.mesh, group.front(), {0, 1, 0}, {1, 0, 0}, local)) return std::nullopt;
  Mesh faces;
  for (const std::size_t f : group) {
    std::vector<Vec3> loop;
    for (std::uint32_t v : s.mesh->face(f)) loop.push_back(s.mesh->position(v));
    faces.add_polygon(loop, s.mesh->tag(f));
  }
  Refit child = refit(s.scope, faces, local.x, local.y, local.z);
  child.scope.size.z = 0;
  for (Vec3& p : child.mesh.positions()) p.z = 0;  // planar by construction; drop rounding
  std::optional<kernel::Polygon> region = faces_outline(child.mesh);
  if (!region) return std::nullopt;
  auto outline = std::make_shared<kernel::Polygon>(std::move(*region));
  auto child_mesh = std::make_shared<Mesh>(std::move(child.mesh));
  return tree.add_child(id, child.scope, std::move(child_mesh), std::move(outline));
}

// Adds the children of the faces `selected` says, a logical face of several pieces as one.
OpResult add_face_children(ShapeTree& tree, ShapeId id,
                           const std::function<bool(std::size_t)>& selected) {
  const std::shared_ptr<const Mesh> mesh = tree[id].mesh;
  OpResult result;
  for (const std::vector<std::size_t>& group : face_groups(*mesh)) {
    if (!selected(group.front())) continue;
    if (group.size() > 1) {
      if (const std::optional<ShapeId> child = add_group_child(tree, id, group)) {
        result.add(*child, static_cast<std::uint32_t>(group.front()));
        continue;
      }
    }
    for (const std::size_t f : group) {
      const std::optional<ShapeId> child = add_face_child(tree, id, f);
      if (child) result.add(*child, static_cast<std::uint32_t>(f));  // else a degenerate face
    }
  }
  return finish(tree, id, std::move(result));
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
  if (!by_border) {
    return add_face_children(tree, id, [&](std::size_t f) {
      return face_matches(selector, kernel::face_normal(*mesh, f));
    });
  }
  // Border and inside faces are told apart piece by piece: no grouping.
  const std::vector<bool> border = border_faces(*mesh);
  OpResult result;
  for (std::size_t f = 0; f < mesh->face_count(); ++f) {
    if (border[f] != (selector == FaceSelector::kBorder)) continue;
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
  return add_face_children(tree, id, [&](std::size_t f) {
    return face_matches_in_frame(selector, scope.direction_to_world(kernel::face_normal(*mesh, f)),
                                 object);
  });
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
