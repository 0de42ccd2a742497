// Doors and windows (seed 001 §4.4): "a combination of boolean operations that will first cut a
// hole in the wall prior to adding the frame, then add the door or window pane. This composite
// boolean operation (a subtract followed by a union) is stored with the component's geometry".
// An opening is a component whose box reaches through the walls on both sides of a face and whose
// own geometry is the frame and leaf (the union half); solid_geometry() cuts the boxes of the
// openings out of a wall's geometry (the subtract half), with kernel/wall.h when the wall is a
// slab through its face (planar, no 3D boolean) and kernel/boolean3d.h otherwise.
#include <algorithm>
#include <array>
#include <cmath>

#include "kernel/boolean2d.h"
#include "kernel/boolean3d.h"
#include "kernel/plane_split.h"
#include "shape/component_ops.h"

namespace insula::shape {

using kernel::FaceTag;
using kernel::Mesh;
using kernel::SemanticClass;
using kernel::Vec2;
using kernel::Vec3;

namespace {

constexpr double kEps = 1e-6;  // meters

// Appends the box [lo, hi] with every face tagged `tag`.
void append_box(Mesh& mesh, Vec3 lo, Vec3 hi, FaceTag tag) {
  if (!(hi.x - lo.x > kEps && hi.y - lo.y > kEps && hi.z - lo.z > kEps)) return;
  const std::array<FaceTag, 6> tags = {tag, tag, tag, tag, tag, tag};
  Mesh box = *box_mesh(hi - lo, tags);
  for (Vec3& p : box.positions()) p += lo;
  mesh.append(box);
}

// The union half: frame (jambs, head, and a sill for windows) and the leaf or pane, in the
// opening's scope space (box [0, w] x [0, h] x [0, 2 depth], the face plane at z = depth).
Mesh opening_mesh(const OpeningSpec& spec) {
  const bool door = spec.kind == OpeningKind::kDoor;
  const FaceTag tag{door ? SemanticClass::kDoor : SemanticClass::kWindow, 0, 0};
  const double w = spec.width;
  const double h = spec.height;
  const double f = std::min(spec.frame, std::min(w, h) / 4);
  const double z = spec.depth;
  const double half = std::min(spec.depth, 0.1);  // the frame's depth through the walls
  Mesh mesh;
  append_box(mesh, {0, 0, z - half}, {f, h, z + half}, tag);
  append_box(mesh, {w - f, 0, z - half}, {w, h, z + half}, tag);
  append_box(mesh, {f, h - f, z - half}, {w - f, h, z + half}, tag);
  if (!door) append_box(mesh, {f, 0, z - half}, {w - f, f, z + half}, tag);
  const double leaf = door ? 0.02 : 0.005;
  append_box(mesh, {f, door ? 0 : f, z - leaf}, {w - f, h - f, z + leaf}, tag);
  return mesh;
}

// Bounds of the other scope's corners in `frame`'s scope space.
kernel::Bounds3 bounds_in(const Scope& frame, const Scope& other) {
  kernel::Bounds3 b;
  for (const Vec3& c : other.corners()) b.add(frame.to_local(c));
  return b;
}

// The faces of `mesh` lying in the plane w = at with normal sign `sign`, as 2D polygons in (u, v).
std::vector<kernel::Polygon> caps(const Mesh& mesh, double at, double sign, FaceTag* tag) {
  std::vector<kernel::Polygon> out;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Vec3 n = kernel::face_normal(mesh, f);
    if (n.z * sign < 1 - 1e-9) continue;
    const auto loop = mesh.face(f);
    if (std::fabs(mesh.position(loop[0]).z - at) > kEps) continue;
    kernel::Polygon& p = out.emplace_back();
    for (std::uint32_t v : loop) p.outer.push_back(kernel::drop(mesh.position(v)));
    if (tag != nullptr) *tag = mesh.tag(f);
  }
  return kernel::union_all(out);
}

bool is_slab(const Mesh& mesh, double thickness) {
  for (const Vec3& p : mesh.positions()) {
    if (std::fabs(p.z) > kEps && std::fabs(p.z - thickness) > kEps) return false;
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const double nz = std::fabs(kernel::face_normal(mesh, f).z);
    if (nz > 1e-9 && nz < 1 - 1e-9) return false;
  }
  return true;
}

struct Pieces {
  std::vector<Mesh> ends;  // the mitred ends, kept as they are
  Mesh core;               // the slab through the face
};

// Cuts the wall (local space) by the planes bounding its core (where it has full thickness).
bool split_core(const Mesh& wall, const kernel::Bounds2& core, Pieces& out) {
  Mesh rest = kernel::weld(wall);
  const kernel::Bounds3 b = rest.bounds();
  kernel::SplitOptions options;
  options.cap_tag = {SemanticClass::kClosureSurface, 0, 0};
  // The core comes from a 2D boolean whose output is rounded (3e-7 m on a 249 m facade): move
  // each plane onto the wall's own vertex within kEps, or it cuts a sliver of the mitre off into
  // the core, which then is no slab.
  const auto snap = [&](double at, bool along_x) {
    for (const Vec3& p : rest.positions()) {
      const double c = along_x ? p.x : p.y;
      if (std::fabs(c - at) <= kEps) return c;
    }
    return at;
  };
  const std::array<std::pair<Vec3, double>, 4> planes = {{{{-1, 0, 0}, -snap(core.min.x, true)},
                                                          {{1, 0, 0}, snap(core.max.x, true)},
                                                          {{0, -1, 0}, -snap(core.min.y, false)},
                                                          {{0, 1, 0}, snap(core.max.y, false)}}};
  const std::array<double, 4> outer = {-b.min.x, b.max.x, -b.min.y, b.max.y};
  for (std::size_t i = 0; i < 4; ++i) {
    if (planes[i].second >= outer[i] - kEps) continue;  // the wall ends there anyway
    kernel::SplitResult r = kernel::split(rest, {planes[i].first, planes[i].second}, options);
    if (!r.ok()) return false;
    if (!r.positive.empty()) out.ends.push_back(std::move(r.positive));
    rest = kernel::weld(r.negative);
  }
  out.core = std::move(rest);
  return true;
}

// The planar path: openings cut into the wall's slab core with kernel::build_wall. `cut` gets the
// indices of the openings it cut (the others reach into the mitred ends or overlap each other).
bool cut_planar(const Mesh& wall, double thickness, std::vector<kernel::Opening> openings,
                Pieces& out, std::vector<std::size_t>& cut) {
  FaceTag front_tag;
  FaceTag back_tag;
  const auto front = caps(wall, thickness, 1, &front_tag);
  const auto back = caps(wall, 0, -1, &back_tag);
  const kernel::BooleanResult core = kernel::intersect(front, back);
  if (!core.ok() || core.polygons.size() != 1) return false;
  Pieces pieces;
  if (!split_core(wall, kernel::bounds(core.polygons[0]), pieces)) return false;
  if (!is_slab(pieces.core, thickness)) return false;
  const auto outline = caps(pieces.core, thickness, 1, nullptr);
  if (outline.size() != 1 || !outline[0].holes.empty()) return false;
  const kernel::Bounds2 ob = kernel::bounds(outline[0]);
  for (kernel::Opening& o : openings) {  // a door reaching below the core becomes a notch
    if (o.sill < ob.min.y + kEps && o.sill + o.height > ob.min.y + kEps) {
      o.height -= ob.min.y - o.sill;
      o.sill = ob.min.y;
    }
  }
  kernel::WallSpec spec;
  spec.outline = outline[0].outer;
  spec.thickness = thickness;
  spec.openings = std::move(openings);
  spec.min_margin = 0.01;
  spec.policy = kernel::OpeningPolicy::kSkip;
  spec.tags.front = front_tag;
  spec.tags.back = back_tag;
  kernel::WallResult built = kernel::build_wall(spec);
  if (!built.ok()) return false;
  cut = std::move(built.cut);
  out.core = std::move(built.mesh);
  out.ends = std::move(pieces.ends);
  return true;
}

bool overlaps(const kernel::Bounds3& a, const kernel::Bounds3& b) {
  return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y &&
         a.min.z < b.max.z && b.min.z < a.max.z;
}

// The general path: opening boxes subtracted by CGAL corefinement from every closed piece they
// reach (the slab with its planar cuts and the mitred ends are separate closed meshes); the
// reveals keep the jamb, sill and lintel classes. Returns how many openings were cut.
//
// Corefinement costs with the mesh's size, so a large slab is swept along u: the openings are
// taken in order of u, grouped where their neighbourhoods (0.05 m either side) overlap, and each
// group is cut from the slab's not yet visited remainder after two plane splits hand CGAL only the
// group's neighbourhood. Finished parts are never split, welded or corefined again, so a facade
// with n openings costs O(n) corefinements of bounded size (it was O(n) on the whole, growing
// slab: 40 row houses took 19 s, docs/PERFORMANCE.md).
std::size_t cut_general(Pieces& pieces, const std::vector<kernel::Bounds3>& boxes) {
  constexpr double kReach = 0.05;         // meters of slab kept around an opening for CGAL
  constexpr std::size_t kSplitFrom = 64;  // smaller meshes go to CGAL whole
  const FaceTag jamb{SemanticClass::kJamb, 0, 0};
  const std::array<FaceTag, 6> tags = {
      jamb, jamb, FaceTag{SemanticClass::kSill, 0, 0}, FaceTag{SemanticClass::kLintel, 0, 0},
      jamb, jamb};
  std::vector<Mesh> box_meshes;
  box_meshes.reserve(boxes.size());
  for (const kernel::Bounds3& b : boxes) {
    Mesh box = *box_mesh(b.max - b.min, tags);
    for (Vec3& p : box.positions()) p += b.min;
    box_meshes.push_back(std::move(box));
  }
  std::vector<bool> cut(boxes.size(), false);
  // Subtracts box i from a piece small enough (or already cut down) to hand to CGAL as it is.
  const auto subtract = [&](Mesh& piece, std::size_t i) {
    if (piece.empty() || !overlaps(piece.bounds(), boxes[i])) return;
    kernel::Boolean3dResult r =
        kernel::boolean3d(kernel::weld(piece), box_meshes[i], kernel::BooleanOp::kDifference);
    if (r.status != kernel::Boolean3dStatus::kOk) return;
    piece = std::move(r.mesh);
    cut[i] = true;
  };
  for (Mesh& end : pieces.ends) {  // the mitred ends are a few faces each
    for (std::size_t i = 0; i < boxes.size(); ++i) subtract(end, i);
  }
  if (!pieces.core.empty()) {
    std::vector<std::size_t> order(boxes.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return boxes[a].min.x < boxes[b].min.x; });
    kernel::SplitOptions split_options;
    split_options.cap_tag = {SemanticClass::kClosureSurface, 0, 0};
    Mesh done;
    Mesh rest = kernel::weld(pieces.core);
    for (std::size_t first = 0; first < order.size();) {
      double lo = boxes[order[first]].min.x - kReach;
      double hi = boxes[order[first]].max.x + kReach;
      std::size_t last = first + 1;
      while (last < order.size() && boxes[order[last]].min.x - kReach < hi) {
        hi = std::max(hi, boxes[order[last]].max.x + kReach);
        ++last;
      }
      // Cut the group's neighbourhood [lo, hi] out of the remainder: the part left of it is
      // finished, the part right of it is the next remainder.
      Mesh middle = std::move(rest);
      rest = Mesh();
      if (middle.face_count() >= kSplitFrom) {
        const kernel::Bounds3 mb = middle.bounds();
        if (lo > mb.min.x + kEps) {
          kernel::SplitResult r = kernel::split(middle, {{-1, 0, 0}, -lo}, split_options);
          if (r.ok()) {
            done.append(r.positive);
            middle = kernel::weld(r.negative);
          }
        }
        if (hi < mb.max.x - kEps) {
          kernel::SplitResult r = kernel::split(middle, {{1, 0, 0}, hi}, split_options);
          if (r.ok()) {
            rest = kernel::weld(r.positive);
            middle = kernel::weld(r.negative);
          }
        }
      }
      for (std::size_t k = first; k < last; ++k) subtract(middle, order[k]);
      if (rest.empty()) {
        rest = std::move(middle);  // not split off: the next group cuts the same mesh
      } else {
        done.append(middle);
      }
      first = last;
    }
    done.append(rest);
    pieces.core = std::move(done);
  }
  return static_cast<std::size_t>(std::count(cut.begin(), cut.end(), true));
}

}  // namespace

OpResult add_opening(ShapeTree& tree, ShapeId face, const OpeningSpec& spec) {
  if (!tree[face].is_flat()) return OpResult::failure("an opening needs a flat wall component");
  if (!(spec.width > 0 && spec.height > 0 && spec.depth > 0 && spec.frame >= 0) ||
      !std::isfinite(spec.u + spec.sill + spec.width + spec.height + spec.depth + spec.frame)) {
    return OpResult::failure("width, height and depth must be > 0");
  }
  const Scope scope = tree[face].scope.sub({spec.u - spec.width / 2, spec.sill, -spec.depth},
                                           {spec.width, spec.height, 2 * spec.depth});
  auto mesh = std::make_shared<Mesh>(opening_mesh(spec));
  const ShapeId id = tree.add_child(face, scope, std::move(mesh));
  tree.add_label(id, spec.kind == OpeningKind::kDoor ? "door" : "window");
  tree.add_label(id, "opening");
  OpResult result;
  result.add(id, 0);
  return result;
}

std::optional<kernel::Opening> opening_in_wall(const ShapeTree& tree, ShapeId wall,
                                               ShapeId opening) {
  const Scope& w = tree[wall].scope;
  const Scope& o = tree[opening].scope;
  if (std::fabs(std::fabs(dot(w.z, o.z)) - 1) > 1e-6 || w.size.z <= 0) return {};
  const kernel::Bounds3 b = bounds_in(w, o);
  if (b.min.z > kEps || b.max.z < w.size.z - kEps) return {};  // not through the thickness
  if (b.max.x <= kEps || b.min.x >= w.size.x - kEps || b.max.y <= kEps ||
      b.min.y >= w.size.y - kEps) {
    return {};
  }
  kernel::Opening out;
  out.u = b.min.x;
  out.sill = b.min.y;
  out.width = b.max.x - b.min.x;
  out.height = b.max.y - b.min.y;
  return out;
}

OpResult solid_geometry(ShapeTree& tree, ShapeId id, const SolidOptions& options) {
  const Shape& s = tree[id];
  if (!s.mesh || s.mesh->empty()) return OpResult::failure("the component has no boundary");
  std::vector<kernel::Opening> openings;
  std::vector<kernel::Bounds3> boxes;
  for (ShapeId o : options.openings) {
    if (o == id || !tree.contains(o)) continue;
    if (auto cut = opening_in_wall(tree, id, o)) {
      openings.push_back(*cut);
      boxes.push_back(bounds_in(s.scope, tree[o].scope));
    }
  }
  std::shared_ptr<const Mesh> mesh = s.mesh;
  std::size_t cut_count = 0;
  if (!openings.empty()) {
    Pieces pieces;
    std::vector<std::size_t> planar;
    std::vector<kernel::Bounds3> rest;  // openings the planar path could not cut
    if (cut_planar(*s.mesh, s.scope.size.z, openings, pieces, planar)) {
      std::vector<bool> done(openings.size(), false);
      for (std::size_t i : planar) done[i] = true;
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (!done[i]) rest.push_back(boxes[i]);
      }
    } else {
      pieces = {{}, *s.mesh};
      rest = boxes;
    }
    cut_count = planar.size() + cut_general(pieces, rest);
    for (const Mesh& end : pieces.ends) pieces.core.append(end);
    mesh = std::make_shared<Mesh>(std::move(pieces.core));
  }
  const std::string name(tree.first_label(id));
  const ShapeId child = tree.add_child(id, s.scope, std::move(mesh));
  tree.add_label(child, "solid");
  tree.set_attribute(child, "component", Value{name});
  if (options.uv_scale > 0) tree.set_attribute(child, "uv_scale", Value{options.uv_scale});
  if (!openings.empty()) {
    tree.set_attribute(child, "openings_cut", Value{static_cast<double>(cut_count)});
  }
  if (!options.material.empty()) tree.set_attribute(child, "material", Value{options.material});
  OpResult result;
  result.add(child, 0);
  return result;
}

}  // namespace insula::shape
