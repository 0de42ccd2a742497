// CityEngine's scope operations (alignScopeToAxes, alignScopeToGeometry, rotateScope, setPivot,
// mirror, and translate/rotate in a named frame): they change the scope and leave the geometry
// where it is in the world (mirror and translate/rotate excepted). Choices and differences from
// CityEngine: docs/operations-cityengine.md.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "kernel/convex_hull.h"
#include "shape/ops.h"

namespace insula::shape {

using kernel::Mesh;
using kernel::Polygon;
using kernel::Vec2;
using kernel::Vec3;

namespace {

constexpr double kParallel = 1 - 1e-9;

// Axes as CityEngine names them: x, up (its y) and z = x cross up, with an origin.
struct Axes {
  Vec3 origin;
  Vec3 x{1, 0, 0};
  Vec3 up{0, 0, 1};
  Vec3 z{0, -1, 0};
};

Axes ce_axes(const Shape& s) {
  if (s.is_flat()) return {s.scope.origin, s.scope.x, s.scope.z, -s.scope.y};
  return {s.scope.origin, s.scope.x, s.scope.y, s.scope.z};
}

// Back to an Insula scope's axes: a flat shape keeps its normal on z.
void to_scope_axes(bool flat, const Axes& a, Scope& scope) {
  scope.x = normalized(a.x);
  if (flat) {
    scope.z = normalized(a.up);
    scope.y = cross(scope.z, scope.x);
  } else {
    scope.y = normalized(a.up);
    scope.z = cross(scope.x, scope.y);
  }
}

Axes frame_axes(const ShapeTree& tree, ShapeId id, Frame frame, const Scope* object) {
  switch (frame) {
    case Frame::kWorld:
      return {};
    case Frame::kObject:
      if (object != nullptr) {
        // A root scope of zero depth is a footprint: its normal is z.
        if (object->size.z == 0) return {object->origin, object->x, object->z, -object->y};
        return {object->origin, object->x, object->y, object->z};
      }
      return ce_axes(tree[tree.root_of(id)]);
    case Frame::kScope:
    case Frame::kPivot:
      break;
  }
  return ce_axes(tree[id]);
}

// `v` without its part along unit `n`, normalised; zero when `v` is (nearly) parallel to `n`.
Vec3 project_out(Vec3 v, Vec3 n) {
  const Vec3 p = v - n * dot(v, n);
  return length(p) < 1e-9 ? Vec3{} : normalized(p);
}

// Replaces `id` by a child whose scope has `target`'s frame: the geometry is re-expressed in it
// and stays put in the world. With `fit` the scope is refitted to the geometry (the scope box when
// the shape has none), else `target` keeps its origin and size.
OpResult reframed(ShapeTree& tree, ShapeId id, Scope target, bool fit, std::string warning = {}) {
  const Shape& s = tree[id];
  const Scope old = s.scope;
  const Scope frame = target;  // before the fit moves target's origin
  const auto map = [&](Vec3 p) { return frame.to_local(old.to_world(p)); };
  Vec3 shift;
  if (fit) {
    kernel::Bounds3 b;
    if (s.mesh && !s.mesh->empty()) {
      for (const Vec3& p : s.mesh->positions()) b.add(map(p));
    } else {
      for (const Vec3& c : old.corners()) b.add(frame.to_local(c));
    }
    shift = b.min;
    target.origin = target.to_world(b.min);
    target.size = b.max - b.min;
  }
  const bool keeps_plane = s.is_flat() && dot(target.z, old.z) > kParallel;
  std::shared_ptr<const Mesh> mesh;
  if (s.mesh) {
    auto m = std::make_shared<Mesh>(*s.mesh);
    for (Vec3& p : m->positions()) {
      p = map(p) - shift;
      if (keeps_plane) p.z = 0;  // rounding only: the plane is the scope's xy plane
    }
    mesh = std::move(m);
  }
  std::shared_ptr<const Polygon> outline;
  if (keeps_plane) {
    auto o = std::make_shared<Polygon>(*s.outline);
    const auto move_ring = [&](kernel::Ring& ring) {
      for (Vec2& p : ring) p = kernel::drop(map(kernel::lift(p, 0)) - shift);
    };
    move_ring(o->outer);
    for (auto& hole : o->holes) move_ring(hole);
    outline = std::move(o);
    target.size.z = 0;
  }
  return relabelled_child(tree, id, target, std::move(mesh), std::move(outline),
                          std::move(warning));
}

// The face picked by `pick` (world heights for kLowest), or an error.
bool pick_face(const Shape& s, GeometryPick pick, std::size_t& face, std::string& error) {
  const Mesh& mesh = *s.mesh;
  const std::size_t n = mesh.face_count();
  const auto usable = [&](std::size_t f) { return kernel::face_area(mesh, f) > 1e-12; };
  switch (pick.kind) {
    case GeometryPick::Kind::kIndex:
      if (pick.index >= n) {
        error = "face index " + std::to_string(pick.index) + " is out of range (the shape has " +
                std::to_string(n) + " faces)";
        return false;
      }
      face = pick.index;
      return true;
    case GeometryPick::Kind::kLargest: {
      double best = -1;
      for (std::size_t f = 0; f < n; ++f) {
        const double a = kernel::face_area(mesh, f);
        if (a > best + 1e-12) best = a, face = f;
      }
      return true;
    }
    case GeometryPick::Kind::kLowest: {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t f = 0; f < n; ++f) {
        if (!usable(f)) continue;
        Vec3 c;
        for (std::uint32_t v : mesh.face(f)) c += mesh.position(v);
        const double h = s.scope.to_world(c * (1.0 / static_cast<double>(mesh.face(f).size()))).z;
        if (h < best - 1e-9) best = h, face = f;
      }
      return std::isfinite(best) || (error = "the shape has no face with an area", false);
    }
    case GeometryPick::Kind::kAny:
    case GeometryPick::Kind::kLongest:
      break;
  }
  for (std::size_t f = 0; f < n; ++f) {
    if (usable(f)) return face = f, true;
  }
  error = "the shape has no face with an area";
  return false;
}

// Edge `edge` of face `face` runs from loop[edge] to loop[edge + 1].
bool pick_edge(const Shape& s, std::size_t face, GeometryPick pick, std::size_t& edge,
               std::string& error) {
  const Mesh& mesh = *s.mesh;
  const auto loop = mesh.face(face);
  const std::size_t n = loop.size();
  const auto a = [&](std::size_t i) { return mesh.position(loop[i]); };
  const auto b = [&](std::size_t i) { return mesh.position(loop[(i + 1) % n]); };
  switch (pick.kind) {
    case GeometryPick::Kind::kIndex:
      if (pick.index >= n) {
        error = "edge index " + std::to_string(pick.index) + " is out of range (face " +
                std::to_string(face) + " has " + std::to_string(n) + " edges)";
        return false;
      }
      edge = pick.index;
      return true;
    case GeometryPick::Kind::kLongest: {
      double best = -1;
      for (std::size_t i = 0; i < n; ++i) {
        const double l = length(b(i) - a(i));
        if (l > best + 1e-9) best = l, edge = i;
      }
      return true;
    }
    case GeometryPick::Kind::kLowest: {
      // The lowest edge in the world (a roof face's eave); among equally low ones the longest.
      double best = std::numeric_limits<double>::infinity();
      double best_length = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double l = length(b(i) - a(i));
        if (l < 1e-12) continue;
        const double h = s.scope.to_world((a(i) + b(i)) * 0.5).z;
        if (h < best - 1e-9 || (h < best + 1e-9 && l > best_length + 1e-9)) {
          best = h, best_length = l, edge = i;
        }
      }
      return true;
    }
    case GeometryPick::Kind::kAny:
    case GeometryPick::Kind::kLargest:
      break;
  }
  edge = 0;
  return true;
}

// Rotation of `v` about the unit axes `k` in turn by `degrees` (x, then y, then z).
Vec3 turned(Vec3 v, const Axes& k, Vec3 degrees) {
  const double r = std::numbers::pi / 180.0;
  if (degrees.x != 0) v = rotate_about(v, k.x, degrees.x * r);
  if (degrees.y != 0) v = rotate_about(v, k.up, degrees.y * r);
  if (degrees.z != 0) v = rotate_about(v, k.z, degrees.z * r);
  return v;
}

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

const char* const kAbsAsRel =
    "abs in the scope or pivot frame is read as rel (Insula keeps no pivot apart from the scope)";

}  // namespace

namespace {

constexpr std::array<std::pair<std::string_view, FaceSelector>, 7> kWorldWords = {{
    {"world.north", FaceSelector::kBack},
    {"world.south", FaceSelector::kFront},
    {"world.east", FaceSelector::kRight},
    {"world.west", FaceSelector::kLeft},
    {"world.up", FaceSelector::kTop},
    {"world.down", FaceSelector::kBottom},
    {"world.side", FaceSelector::kSide},
}};
constexpr std::array<std::string_view, 7> kObjectWords = {"front", "back",   "left", "right",
                                                          "top",   "bottom", "side"};

}  // namespace

std::optional<FrameSelector> frame_selector_named(std::string_view word) {
  for (const auto& [name, selector] : kWorldWords) {
    if (name == word) return FrameSelector{Frame::kWorld, selector};
  }
  // street.*: without street data CityEngine reads the initial shape's own sides (object.*).
  if (word.starts_with("object.") || word.starts_with("street.")) {
    const std::string_view side = word.substr(7);
    if (std::find(kObjectWords.begin(), kObjectWords.end(), side) != kObjectWords.end()) {
      return FrameSelector{Frame::kObject, face_selector_named(side).value()};
    }
  }
  return std::nullopt;
}

std::vector<std::string> frame_selector_words() {
  std::vector<std::string> words;
  for (std::string_view side : kObjectWords) words.push_back("object." + std::string(side));
  for (const auto& [name, selector] : kWorldWords) words.emplace_back(name);
  for (std::string_view side : kObjectWords) words.push_back("street." + std::string(side));
  return words;
}

bool face_matches_in_frame(const FrameSelector& selector, Vec3 n, const Scope* object) {
  Axes axes;  // the world's
  if (selector.frame == Frame::kObject && object != nullptr) {
    axes = object->size.z == 0 ? Axes{object->origin, object->x, object->z, -object->y}
                               : Axes{object->origin, object->x, object->y, object->z};
  }
  // The normal in CityEngine's reading of the frame: x, y up, z.
  return face_matches(selector.selector, {dot(n, axes.x), dot(n, axes.up), dot(n, axes.z)});
}

namespace {

Axes scope_axes(const Scope& s) {
  if (s.size.z == 0) return {s.origin, s.x, s.z, -s.y};
  return {s.origin, s.x, s.y, s.z};
}

Axes axes_of(Frame frame, const Scope& scope, const Scope* object) {
  if (frame == Frame::kWorld || (frame == Frame::kObject && object == nullptr)) return {};
  return scope_axes(frame == Frame::kObject ? *object : scope);
}

// Columns c0, c1, c2 of a rotation; (R v) = v.x c0 + v.y c1 + v.z c2.
using Basis = std::array<Vec3, 3>;

Vec3 apply(const Basis& b, Vec3 v) {
  return b[0] * v.x + b[1] * v.y + b[2] * v.z;
}

Basis rotation_xyz(Vec3 degrees) {  // intrinsic x, then y, then z
  const kernel::Transform rx = kernel::rotation({1, 0, 0}, degrees.x);
  const kernel::Transform ry = kernel::rotation({0, 1, 0}, degrees.y);
  const kernel::Transform rz = kernel::rotation({0, 0, 1}, degrees.z);
  const kernel::Transform r = rx * ry * rz;
  return {r.x, r.y, r.z};
}

Vec3 angles_xyz(const Basis& r) {  // the inverse of rotation_xyz (r = columns)
  constexpr double kDeg = 180 / std::numbers::pi;
  const double b = std::asin(std::clamp(r[2].x, -1.0, 1.0));
  const double a = std::atan2(-r[2].y, r[2].z);
  const double c = std::atan2(-r[1].x, r[0].x);
  return {a * kDeg, b * kDeg, c * kDeg};
}

}  // namespace

Vec3 convert_between_frames(Frame from, Frame to, bool orientation, Vec3 v, const Scope& scope,
                            const Scope* object) {
  const Axes f = axes_of(from, scope, object);
  const Axes t = axes_of(to, scope, object);
  const Basis from_basis = {f.x, f.up, f.z};
  const auto in_to = [&](Vec3 w) { return Vec3{dot(w, t.x), dot(w, t.up), dot(w, t.z)}; };
  if (!orientation) return in_to(f.origin + apply(from_basis, v) - t.origin);
  const Basis r = rotation_xyz(v);
  Basis world;
  for (std::size_t i = 0; i < 3; ++i) world[i] = apply(from_basis, r[i]);
  Basis relative;
  for (std::size_t i = 0; i < 3; ++i) relative[i] = in_to(world[i]);
  return angles_xyz(relative);
}

Frame frame_from(std::string_view name) {
  if (name == "world") return Frame::kWorld;
  if (name == "object") return Frame::kObject;
  if (name == "pivot") return Frame::kPivot;
  return Frame::kScope;
}

OpResult align_scope_to_axes(ShapeTree& tree, ShapeId id, Frame frame, char axis,
                             const Scope* object) {
  const Shape& s = tree[id];
  const Axes f = frame_axes(tree, id, frame, object);
  const Axes cur = ce_axes(s);
  Axes a = f;
  if (axis == 'y') {
    a.x = project_out(cur.x, f.up);
    if (length(a.x) == 0) a.x = cross(f.up, project_out(cur.z, f.up));
  } else if (axis == 'x') {
    a.up = project_out(cur.up, f.x);
    if (length(a.up) == 0) a.up = cross(project_out(cur.z, f.x), f.x);
  } else if (axis == 'z') {
    a.x = project_out(cur.x, f.z);
    if (length(a.x) == 0) a.x = cross(project_out(cur.up, f.z), f.z);
    a.up = cross(f.z, a.x);
  }
  Scope target = s.scope;
  to_scope_axes(s.is_flat(), a, target);
  return reframed(tree, id, target, true);
}

OpResult align_scope_to_geometry_bbox(ShapeTree& tree, ShapeId id, std::string_view axes) {
  const Shape& s = tree[id];
  Axes a = ce_axes(s);
  const auto axis = [&](char c) -> Vec3& { return c == 'x' ? a.x : c == 'y' ? a.up : a.z; };
  const char first = axes[0], second = axes[1];
  const char fixed = static_cast<char>('x' + 'y' + 'z' - first - second);
  const Vec3 u = axis(first), v = axis(second), w = axis(fixed);
  std::vector<kernel::Vec2> points;
  if (s.mesh) {
    for (const Vec3& p : s.mesh->positions()) {
      const Vec3 q = s.scope.to_world(p);
      points.push_back({dot(q, u), dot(q, v)});
    }
  }
  const std::optional<kernel::Vec2> d = kernel::min_area_rectangle_direction(points);
  if (!d) return reframed(tree, id, s.scope, true);  // nothing to align to: only refitted
  const Vec3 along = normalized(u * d->x + v * d->y);
  // x, y (up), z stay right-handed: in cyclic order the second axis is fixed x first.
  const bool cyclic = (first == 'x' && second == 'y') || (first == 'y' && second == 'z') ||
                      (first == 'z' && second == 'x');
  axis(first) = along;
  axis(second) = cyclic ? cross(w, along) : cross(along, w);
  Scope target = s.scope;
  to_scope_axes(s.is_flat(), a, target);
  return reframed(tree, id, target, true);
}

OpResult align_scope_to_geometry(ShapeTree& tree, ShapeId id, Axis up, GeometryPick face,
                                 GeometryPick edge) {
  const Shape& s = tree[id];
  if (!s.mesh || s.mesh->empty()) return OpResult::failure("the shape has no faces");
  std::string error;
  std::size_t f = 0;
  std::size_t e = 0;
  if (!pick_face(s, face, f, error) || !pick_edge(s, f, edge, e, error)) {
    return OpResult::failure(error);
  }
  const Mesh& mesh = *s.mesh;
  const auto loop = mesh.face(f);
  const Vec3 a = mesh.position(loop[e]);
  const Vec3 b = mesh.position(loop[(e + 1) % loop.size()]);
  const Vec3 n = s.scope.direction_to_world(kernel::face_normal(mesh, f));
  const Vec3 along = s.scope.direction_to_world(b - a);
  if (length(n) < 0.5) return OpResult::failure("face " + std::to_string(f) + " is degenerate");
  Vec3 x = project_out(along, n);
  if (length(x) == 0) return OpResult::failure("edge " + std::to_string(e) + " has no length");
  Scope target = s.scope;
  target.x = x;
  if (up == Axis::kY && !s.is_flat()) {
    target.y = n;
    target.z = cross(x, n);
  } else {
    target.z = n;
    target.y = cross(n, x);
  }
  return reframed(tree, id, target, true);
}

OpResult rotate_scope(ShapeTree& tree, ShapeId id, Vec3 degrees) {
  if (!finite(degrees)) return OpResult::failure("angles must be finite");
  Scope target = tree[id].scope;
  if (degrees.x != 0) target = rotated(target, Axis::kX, degrees.x, {});
  if (degrees.y != 0) target = rotated(target, Axis::kY, degrees.y, {});
  if (degrees.z != 0) target = rotated(target, Axis::kZ, degrees.z, {});
  return reframed(tree, id, target, true);
}

OpResult set_pivot(ShapeTree& tree, ShapeId id, std::string_view axis_map, int corner) {
  if (corner < 0 || corner > 7) return OpResult::failure("corner must be in [0, 7]");
  const Scope& old = tree[id].scope;
  // Inward axes at the corner: an axis whose bit is set points back along the old axis.
  const Vec3 size = old.size;
  const std::array<Vec3, 3> inward = {old.x * ((corner & 1) ? -1.0 : 1.0),
                                      old.y * ((corner & 2) ? -1.0 : 1.0),
                                      old.z * ((corner & 4) ? -1.0 : 1.0)};
  const std::array<double, 3> extent = {size.x, size.y, size.z};
  std::array<std::size_t, 3> from = {0, 1, 2};
  if (axis_map == "yzx") from = {2, 0, 1};
  if (axis_map == "zxy") from = {1, 2, 0};
  Scope target = old;
  target.origin = old.corners()[static_cast<std::size_t>(corner)];
  target.x = inward[from[0]];
  target.y = inward[from[1]];
  target.z = inward[from[2]];
  target.size = {extent[from[0]], extent[from[1]], extent[from[2]]};
  // An odd number of reversed axes makes the frame left-handed: swap x and z (y keeps its line,
  // as CityEngine keeps y on the old y at every corner).
  if (dot(cross(target.x, target.y), target.z) < 0) {
    std::swap(target.x, target.z);
    std::swap(target.size.x, target.size.z);
  }
  return reframed(tree, id, target, false);
}

OpResult mirror(ShapeTree& tree, ShapeId id, bool x, bool y, bool z) {
  const Shape& s = tree[id];
  const Vec3 size = s.scope.size;
  // A flat shape has no depth to mirror; its z flag changes nothing.
  const bool flip[3] = {x, y, z && !s.is_flat()};
  const auto map = [&](Vec3 p) {
    return Vec3{flip[0] ? size.x - p.x : p.x, flip[1] ? size.y - p.y : p.y,
                flip[2] ? size.z - p.z : p.z};
  };
  const bool reverse = (int{flip[0]} + int{flip[1]} + int{flip[2]}) % 2 == 1;
  std::shared_ptr<const Mesh> mesh = s.mesh;
  if (mesh) {
    auto m = std::make_shared<Mesh>();
    m->reserve(mesh->vertex_count(), mesh->face_count(), 0);
    for (const Vec3& p : mesh->positions()) m->add_vertex(map(p));
    std::vector<std::uint32_t> loop;
    for (std::size_t f = 0; f < mesh->face_count(); ++f) {
      const auto face = mesh->face(f);
      loop.assign(face.begin(), face.end());
      // A reflection turns faces inside out; reversing the loops keeps them outward.
      if (reverse) std::reverse(loop.begin(), loop.end());
      m->add_face(loop, mesh->tag(f));
    }
    mesh = std::move(m);
  }
  std::shared_ptr<const Polygon> outline = s.outline;
  if (outline) {
    auto o = std::make_shared<Polygon>(*outline);
    const auto move_ring = [&](kernel::Ring& ring) {
      for (Vec2& p : ring) p = kernel::drop(map(kernel::lift(p, 0)));
      if (reverse) std::reverse(ring.begin(), ring.end());
    };
    move_ring(o->outer);
    for (auto& hole : o->holes) move_ring(hole);
    outline = std::move(o);
  }
  return relabelled_child(tree, id, s.scope, std::move(mesh), std::move(outline));
}

OpResult translate_in(ShapeTree& tree, ShapeId id, bool absolute, Frame frame, Vec3 v,
                      const Scope* object) {
  if (!finite(v)) return OpResult::failure("offset must be finite");
  const Shape& s = tree[id];
  const Axes f = frame_axes(tree, id, frame, object);
  const bool own = frame == Frame::kScope || frame == Frame::kPivot;
  Scope scope = s.scope;
  const Vec3 d = f.x * v.x + f.up * v.y + f.z * v.z;
  if (own) {
    scope.origin = s.scope.to_world(v);  // the scope's own axes, as t()
  } else {
    scope.origin = absolute ? f.origin + d : s.scope.origin + d;
  }
  return relabelled_child(tree, id, scope, s.mesh, s.outline,
                          absolute && own ? kAbsAsRel : std::string());
}

OpResult rotate_in(ShapeTree& tree, ShapeId id, bool absolute, Frame frame, Vec3 degrees,
                   const Scope* object) {
  if (!finite(degrees)) return OpResult::failure("angles must be finite");
  const Shape& s = tree[id];
  const bool own = frame == Frame::kScope || frame == Frame::kPivot;
  if (own) {
    OpResult r = rotate(tree, id, degrees, Pivot::kOrigin);
    if (absolute && r.ok()) r.warning = kAbsAsRel;
    return r;
  }
  const Axes f = frame_axes(tree, id, frame, object);
  Axes a = absolute ? f : ce_axes(s);
  if (absolute) {
    // CityEngine's ordered rotation from the frame: about x, then the turned y, then the turned z.
    const double r = std::numbers::pi / 180.0;
    const std::array<double, 3> angles = {degrees.x, degrees.y, degrees.z};
    for (std::size_t i = 0; i < 3; ++i) {
      if (angles[i] == 0) continue;
      const Vec3 axis = i == 0 ? a.x : i == 1 ? a.up : a.z;
      a.x = rotate_about(a.x, axis, angles[i] * r);
      a.up = rotate_about(a.up, axis, angles[i] * r);
      a.z = rotate_about(a.z, axis, angles[i] * r);
    }
  } else {
    a.x = turned(a.x, f, degrees);
    a.up = turned(a.up, f, degrees);
  }
  Scope scope = s.scope;
  to_scope_axes(s.is_flat(), a, scope);
  // Geometry turns with the scope (it is stored in scope space), about the scope origin.
  return relabelled_child(tree, id, scope, s.mesh, s.outline);
}

namespace {

ParamDecl number_param(std::string name, std::string doc, double fallback) {
  return {std::move(name), ParamType::kNumber, std::move(doc), ArgValue{fallback}, {}, {}, {}};
}

ParamDecl enum_param(std::string name, std::string doc, std::string fallback,
                     std::vector<std::string> choices) {
  return {std::move(name),
          ParamType::kEnum,
          std::move(doc),
          ArgValue{std::move(fallback)},
          std::move(choices),
          {},
          {}};
}

ParamDecl bool_param(std::string name, std::string doc) {
  return {std::move(name), ParamType::kBool, std::move(doc), ArgValue{false}, {}, {}, {}};
}

GeometryPick pick_from(const std::string& text) {
  GeometryPick p;
  if (text == "largest") p.kind = GeometryPick::Kind::kLargest;
  if (text == "any") p.kind = GeometryPick::Kind::kAny;
  if (text == "longest") p.kind = GeometryPick::Kind::kLongest;
  if (text == "world.lowest") p.kind = GeometryPick::Kind::kLowest;
  if (p.kind == GeometryPick::Kind::kIndex) {
    std::from_chars(text.data(), text.data() + text.size(), p.index);  // bind checked the digits
  }
  return p;
}

}  // namespace

std::vector<Operation> scope_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"alignScopeToAxes",
       "Turns the scope parallel to the world's (or the root shape's) axes, x east, y up, z south "
       "(CityEngine's names; a flat shape keeps y up on its scope z), or only one of them with the "
       "others projected; the geometry stays put and the scope is refitted to it.",
       {enum_param("axis", "xyz: all three axes; x, y or z: that axis only (y = up)", "xyz",
                   {"xyz", "x", "y", "z", "world.xyz", "world.x", "world.y", "world.z",
                    "object.xyz", "object.x", "object.y", "object.z"})},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context& context) {
         std::string_view axis = a.string("axis");
         Frame frame = Frame::kWorld;
         if (axis.starts_with("object.")) frame = Frame::kObject;
         if (const std::size_t dot = axis.find('.'); dot != std::string_view::npos) {
           axis.remove_prefix(dot + 1);
         }
         const char which = axis == "xyz" ? 'a' : axis.front();
         return align_scope_to_axes(t, id, frame, which, context.object);
       }});
  ops.push_back(
      {"alignScopeToGeometry",
       "Turns the scope to a face of the geometry: x along one of its edges, the up axis along its "
       "normal (a flat shape keeps the normal on z); the geometry stays put and the scope is "
       "refitted to it.",
       {enum_param("up",
                   "scope axis that takes the face normal on volumes (CGA's yUp, zUp: enum words "
                   "are read in any case)",
                   "yup", {"yup", "zup"}),
        enum_param("face",
                   "face index N (0-based), the largest face, any face, the world.lowest one, or "
                   "auto (CityEngine 2011's word: the largest face and its longest edge)",
                   "0", {std::string(kIndexChoice), "largest", "any", "world.lowest", "auto"}),
        enum_param("edge",
                   "edge index N of that face (0-based, from its loop), the longest edge, or the "
                   "world.lowest one",
                   "0", {std::string(kIndexChoice), "longest", "world.lowest"})},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         const bool automatic = a.string("face") == "auto";
         return align_scope_to_geometry(t, id, a.string("up") == "zup" ? Axis::kZ : Axis::kY,
                                        pick_from(automatic ? "largest" : a.string("face")),
                                        pick_from(automatic ? "longest" : a.string("edge")));
       }});
  ops.push_back(
      {"alignScopeToGeometryBBox",
       "Turns the scope about its third axis so the two named axes span the minimum-area "
       "rectangle around the geometry seen along the third, the first along its longer side "
       "(CityEngine's axes: a flat shape's normal is y); the geometry stays put.",
       {enum_param("axes", "the two axes turned, the first along the longer side", "xz",
                   {"xy", "yx", "xz", "zx", "yz", "zy"})},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return align_scope_to_geometry_bbox(t, id, a.string("axes"));
       }});
  ops.push_back({"rotateScope",
                 "Turns only the scope about its own x, then y, then z axis (degrees), then "
                 "refits it to the geometry, which stays put.",
                 {number_param("x", "degrees about scope x", 0),
                  number_param("y", "degrees about scope y", 0),
                  number_param("z", "degrees about scope z", 0)},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return rotate_scope(t, id, {a.number("x"), a.number("y"), a.number("z")});
                 }});
  ops.push_back(
      {"setPivot",
       "Moves the scope origin to a corner of the scope box with permuted axes that point into "
       "the box; the box and the geometry stay put.",
       {enum_param("axes", "new x, y, z taken from the old axes", "xyz", {"xyz", "yzx", "zxy"}),
        {"corner",
         ParamType::kInteger,
         "corner index: bit 0 = far in x, bit 1 = far in y, bit 2 = far in z",
         ArgValue{std::int64_t{0}},
         {},
         0.0,
         7.0}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return set_pivot(t, id, a.string("axes"), static_cast<int>(a.integer("corner")));
       }});
  ops.push_back({"mirror",
                 "Mirrors the geometry inside the scope on the chosen scope axes (faces stay "
                 "outward); the scope does not change.",
                 {bool_param("x", "mirror along scope x"), bool_param("y", "mirror along scope y"),
                  bool_param("z", "mirror along scope z")},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return mirror(t, id, a.boolean("x"), a.boolean("y"), a.boolean("z"));
                 }});
  return ops;
}

}  // namespace insula::shape
