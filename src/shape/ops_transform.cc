// Scope rules (seed 004, "Scope Rules": T, S, R) and CGA's center. Each creates one child that
// shares its parent's geometry (or a stretched copy for scale), so the parent stays queryable.
#include <cmath>
#include <memory>
#include <string>

#include "shape/ops.h"

namespace insula::shape {

using kernel::Mesh;
using kernel::Vec3;

namespace {

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

double resolve(SizeSpec s, double current) {
  return s.mode == SizeMode::kRelative ? s.value * current : s.value;
}

}  // namespace

OpResult translate(ShapeTree& tree, ShapeId id, Vec3 offset) {
  if (!finite(offset)) return OpResult::failure("offset must be finite");
  const Shape& s = tree[id];
  Scope scope = s.scope;
  scope.origin = scope.to_world(offset);
  return relabelled_child(tree, id, scope, s.mesh, s.outline);
}

OpResult rotate(ShapeTree& tree, ShapeId id, Vec3 degrees, Pivot pivot) {
  if (!finite(degrees)) return OpResult::failure("angles must be finite");
  const Shape& s = tree[id];
  const Vec3 p = pivot == Pivot::kCenter ? s.scope.size * 0.5 : Vec3{};
  Scope scope = s.scope;
  // Intrinsic rotations: each turns about the scope's axis as already rotated.
  if (degrees.x != 0) scope = rotated(scope, Axis::kX, degrees.x, p);
  if (degrees.y != 0) scope = rotated(scope, Axis::kY, degrees.y, p);
  if (degrees.z != 0) scope = rotated(scope, Axis::kZ, degrees.z, p);
  return relabelled_child(tree, id, scope, s.mesh, s.outline);
}

OpResult scale(ShapeTree& tree, ShapeId id, SizeSpec x, SizeSpec y, SizeSpec z) {
  const Shape& s = tree[id];
  for (SizeSpec v : {x, y, z}) {
    if (!std::isfinite(v.value) || v.value < 0) {
      return OpResult::failure("sizes must be finite and >= 0");
    }
    if (v.mode == SizeMode::kFloating) return OpResult::failure("sizes cannot be floating (~)");
  }
  const Vec3 old = s.scope.size;
  Scope scope = s.scope;
  scope.size = {resolve(x, old.x), resolve(y, old.y), resolve(z, old.z)};
  // Stretch factors about the origin; an axis of size 0 has nothing to stretch.
  const Vec3 f = {old.x > 0 ? scope.size.x / old.x : 1, old.y > 0 ? scope.size.y / old.y : 1,
                  old.z > 0 ? scope.size.z / old.z : 1};
  std::shared_ptr<const Mesh> mesh = s.mesh;
  std::shared_ptr<const kernel::Polygon> outline = s.outline;
  if (f.x != 1 || f.y != 1 || f.z != 1) {
    if (mesh) {
      // A zero factor flattens the mesh; transformed() keeps faces outward for mirror-free maps.
      mesh = std::make_shared<Mesh>(kernel::transformed(*mesh, kernel::scaling(f)));
    }
    if (outline) {
      auto o = std::make_shared<kernel::Polygon>(*outline);
      for (auto* ring : {&o->outer}) {
        for (kernel::Vec2& p : *ring) p = {p.x * f.x, p.y * f.y};
      }
      for (auto& hole : o->holes) {
        for (kernel::Vec2& p : hole) p = {p.x * f.x, p.y * f.y};
      }
      outline = std::move(o);
    }
  }
  return relabelled_child(tree, id, scope, std::move(mesh), std::move(outline));
}

OpResult center(ShapeTree& tree, ShapeId id, std::string_view axes) {
  const Shape& s = tree[id];
  if (s.parent == kNoShape) return OpResult::failure("a root shape has no parent to center in");
  const Vec3 target = s.scope.to_local(tree[s.parent].scope.center());  // in this scope's frame
  Vec3 shift;
  for (char a : axes) {
    const Axis axis = a == 'x' ? Axis::kX : a == 'y' ? Axis::kY : Axis::kZ;
    set_component(shift, axis, component(target, axis) - component(s.scope.size, axis) / 2);
  }
  Scope scope = s.scope;
  scope.origin = scope.to_world(shift);
  return relabelled_child(tree, id, scope, s.mesh, s.outline);
}

namespace {

ParamDecl number_param(std::string name, std::string doc, double fallback) {
  return {std::move(name), ParamType::kNumber, std::move(doc), ArgValue{fallback}, {}, {}, {}};
}

// CityEngine's translate(mode, frame, ...) and rotate(mode, frame, ...).
ParamDecl mode_param(std::string_view what) {
  return {"mode",
          ParamType::kEnum,
          "rel adds to the " + std::string(what) + ", abs sets it in the frame",
          ArgValue{std::string("rel")},
          {"rel", "abs"},
          {},
          {}};
}

ParamDecl frame_param() {
  return {"frame",
          ParamType::kEnum,
          "axes the values are in: the scope's (pivot: the same in Insula), the root shape's "
          "(object) or the world's (x east, y up, z south)",
          ArgValue{std::string("scope")},
          {"scope", "pivot", "object", "world"},
          {},
          {}};
}

ParamDecl size_param(std::string name, std::string doc) {
  return {std::move(name),
          ParamType::kSize,
          std::move(doc),
          ArgValue{SizeSpec{1, SizeMode::kRelative}},
          {},
          0.0,
          {}};
}

}  // namespace

std::vector<Operation> transform_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"translate",
       "Moves the scope along its own axes (CGA T); the child shares the geometry.",
       {number_param("x", "meters along scope x", 0), number_param("y", "meters along scope y", 0),
        number_param("z", "meters along scope z", 0), mode_param("translation"), frame_param()},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context& context) {
         const Vec3 v{a.number("x"), a.number("y"), a.number("z")};
         const Frame frame = frame_from(a.string("frame"));
         const bool absolute = a.string("mode") == "abs";
         if (!absolute && frame == Frame::kScope) return translate(t, id, v);
         return translate_in(t, id, absolute, frame, v, context.object);
       }});
  ops.push_back(
      {"rotate",
       "Rotates the scope about its own x, then y, then z axis (degrees, right-hand rule; CGA R).",
       {number_param("x", "degrees about scope x", 0),
        number_param("y", "degrees about scope y", 0),
        number_param("z", "degrees about scope z", 0),
        {"pivot",
         ParamType::kEnum,
         "point kept fixed",
         ArgValue{std::string("origin")},
         {"origin", "center"},
         {},
         {}},
        mode_param("rotation"),
        frame_param()},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context& context) {
         const Vec3 v{a.number("x"), a.number("y"), a.number("z")};
         const Frame frame = frame_from(a.string("frame"));
         const bool absolute = a.string("mode") == "abs";
         if (absolute || frame != Frame::kScope) {
           if (a.string("pivot") == "center") {
             return OpResult::failure("pivot center needs mode rel in the scope frame");
           }
           return rotate_in(t, id, absolute, frame, v, context.object);
         }
         return rotate(t, id, v, a.string("pivot") == "center" ? Pivot::kCenter : Pivot::kOrigin);
       }});
  ops.push_back({"scale",
                 "Sets the scope size (CGA S): meters, or relative ('r) to the current size; "
                 "geometry stretches with it.",
                 {size_param("x", "new size along x"), size_param("y", "new size along y"),
                  size_param("z", "new size along z")},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return scale(t, id, a.size("x"), a.size("y"), a.size("z"));
                 }});
  ops.push_back({"center",
                 "Moves the scope so its centre matches the parent shape's scope centre on the "
                 "chosen axes (CGA center).",
                 {{"axes",
                   ParamType::kEnum,
                   "axes to center on",
                   ArgValue{std::string("xyz")},
                   {"x", "y", "z", "xy", "xz", "yz", "xyz"},
                   {},
                   {}}},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return center(t, id, a.string("axes"));
                 }});
  return ops;
}

}  // namespace insula::shape
