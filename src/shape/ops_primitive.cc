// CityEngine's primitives (primitiveCube, primitiveCylinder, primitiveCone, primitiveSphere,
// primitiveQuad, primitiveDisk): geometry made in the scope rather than read from an asset. Sizes
// are CityEngine's: width along x, height along the up axis (a volume's y, a flat shape's normal
// z), depth along the third axis.
#include <cmath>
#include <numbers>

#include "shape/ops.h"

namespace insula::shape {

using kernel::Mesh;
using kernel::Vec3;

namespace {

// The scope's extents as CityEngine names them: width, height (up), depth.
Vec3 ce_extent(const Shape& s) {
  if (s.is_flat()) return {s.scope.size.x, 0, s.scope.size.y};
  return s.scope.size;
}

// CityEngine's fit of a unit primitive to the scope (as its i() does): zero extents keep
// proportions, from the mean of the other factors (all zero: 1 m).
Vec3 filled(Vec3 extent) {
  const double e[3] = {extent.x, extent.y, extent.z};
  double sum = 0;
  int count = 0;
  for (double v : e) {
    if (v > 0) sum += v, ++count;
  }
  const double keep = count > 0 ? sum / count : 1.0;
  return {extent.x > 0 ? extent.x : keep, extent.y > 0 ? extent.y : keep,
          extent.z > 0 ? extent.z : keep};
}

// Maps CityEngine-frame points (x, up, depth) into the shape's scope space: a flat shape's up is
// its z and its depth runs along -y (a proper rotation: faces stay outward).
Vec3 to_scope(const Shape& s, Vec3 p, double depth) {
  if (s.is_flat()) return {p.x, depth - p.z, p.y};
  return p;
}

// Corner k of `sides` round the unit square's centre (x, z in [0, 1]), counter-clockwise seen
// from +y (CityEngine's up).
kernel::Vec2 circle_corner(int k, int sides) {
  const double a = 2 * std::numbers::pi * k / sides;
  return {0.5 + 0.5 * std::cos(a), 0.5 - 0.5 * std::sin(a)};
}

Mesh unit_cylinder(int sides) {
  Mesh m;
  for (int k = 0; k < sides; ++k) {
    const kernel::Vec2 c = circle_corner(k, sides);
    m.add_vertex({c.x, 0, c.y});
    m.add_vertex({c.x, 1, c.y});
  }
  const auto n = static_cast<std::uint32_t>(sides);
  std::vector<std::uint32_t> bottom;
  std::vector<std::uint32_t> top;
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t next = (k + 1) % n;
    m.add_face({2 * k, 2 * next, 2 * next + 1, 2 * k + 1},
               {kernel::SemanticClass::kWallSurface, 0, 0});
    bottom.push_back(2 * (n - 1 - k));
    top.push_back(2 * k + 1);
  }
  m.add_face(bottom, {kernel::SemanticClass::kGroundSurface, 0, 0});
  m.add_face(top, {kernel::SemanticClass::kRoofSurface, 0, 0});
  if (kernel::volume(m) < 0) m.flip();
  return m;
}

// A cone in the unit box: `sides` triangles up to the apex over a base polygon on y = 0.
Mesh unit_cone(int sides) {
  Mesh m;
  const auto n = static_cast<std::uint32_t>(sides);
  for (int k = 0; k < sides; ++k) {
    const kernel::Vec2 c = circle_corner(k, sides);
    m.add_vertex({c.x, 0, c.y});
  }
  const std::uint32_t apex = m.add_vertex({0.5, 1, 0.5});
  std::vector<std::uint32_t> bottom;
  for (std::uint32_t k = 0; k < n; ++k) {
    m.add_face({k, (k + 1) % n, apex}, {kernel::SemanticClass::kRoofSurface, 0, 0});
    bottom.push_back(n - 1 - k);
  }
  m.add_face(bottom, {kernel::SemanticClass::kGroundSurface, 0, 0});
  if (kernel::volume(m) < 0) m.flip();
  return m;
}

// A UV sphere in the unit box: `sides` segments round the axis, `divisions` bands from the
// bottom pole to the top one (triangles at the poles, quads between).
Mesh unit_sphere(int sides, int divisions) {
  Mesh m;
  const auto n = static_cast<std::uint32_t>(sides);
  const std::uint32_t bottom = m.add_vertex({0.5, 0, 0.5});
  for (int ring = 1; ring < divisions; ++ring) {
    const double polar = std::numbers::pi * ring / divisions;  // from the bottom pole
    const double y = 0.5 - 0.5 * std::cos(polar), r = std::sin(polar);
    for (int k = 0; k < sides; ++k) {
      const kernel::Vec2 c = circle_corner(k, sides);
      m.add_vertex({0.5 + (c.x - 0.5) * r, y, 0.5 + (c.y - 0.5) * r});
    }
  }
  const std::uint32_t top = m.add_vertex({0.5, 1, 0.5});
  const auto at = [&](int ring, std::uint32_t k) {  // ring 1 .. divisions - 1
    return 1 + static_cast<std::uint32_t>(ring - 1) * n + k % n;
  };
  const kernel::FaceTag tag{kernel::SemanticClass::kNone, 0, 0};
  for (std::uint32_t k = 0; k < n; ++k) {
    m.add_face({bottom, at(1, k + 1), at(1, k)}, tag);
    for (int ring = 1; ring + 1 < divisions; ++ring) {
      m.add_face({at(ring, k), at(ring, k + 1), at(ring + 1, k + 1), at(ring + 1, k)}, tag);
    }
    m.add_face({at(divisions - 1, k), at(divisions - 1, k + 1), top}, tag);
  }
  if (kernel::volume(m) < 0) m.flip();
  return m;
}

}  // namespace

OpResult primitive(ShapeTree& tree, ShapeId id, PrimitiveKind kind, int sides, Vec3 dims,
                   int divisions) {
  const Shape& s = tree[id];
  const bool round = kind != PrimitiveKind::kCube && kind != PrimitiveKind::kQuad;
  if (round && sides < 3) return OpResult::failure("at least 3 sides are needed");
  if (kind == PrimitiveKind::kSphere && divisions < 3) {
    return OpResult::failure("a sphere needs at least 3 divisions");
  }
  const Vec3 extent = ce_extent(s);
  const bool sized = dims.x > 0 || dims.y > 0 || dims.z > 0;
  if (sized && !(dims.x > 0 && dims.y > 0 && dims.z > 0)) {
    return OpResult::failure("sizes must all be > 0 (or none given)");
  }
  // Given sizes stand in the scope's xz centre on y = 0; none fill the scope.
  const Vec3 size = sized ? dims : filled(extent);
  const Vec3 at = sized ? Vec3{(extent.x - size.x) / 2, 0, (extent.z - size.z) / 2} : Vec3{};
  const double depth = s.is_flat() ? extent.z : 0;
  if (kind == PrimitiveKind::kQuad || kind == PrimitiveKind::kDisk) {
    // A face at y = 0 facing up: a flat child (normal on its scope z, x along the scope's x).
    const Vec3 corner = to_scope(s, at + Vec3{0, 0, size.z}, depth);
    Scope scope = s.scope;
    scope.origin = s.scope.to_world(corner);
    const Vec3 up =
        s.scope.direction_to_world(to_scope(s, {0, 1, 0}, 0) - to_scope(s, {0, 0, 0}, 0));
    scope.z = up;
    scope.y = cross(scope.z, scope.x);
    scope.size = {size.x, size.z, 0};
    auto outline = std::make_shared<kernel::Polygon>();
    if (kind == PrimitiveKind::kQuad) {
      outline->outer = {{0, 0}, {size.x, 0}, {size.x, size.z}, {0, size.z}};
    } else {  // CityEngine's z runs along the child's -y: the corner's z, turned round
      for (int k = 0; k < sides; ++k) {
        const kernel::Vec2 c = circle_corner(k, sides);
        outline->outer.push_back({c.x * size.x, (1 - c.y) * size.z});
      }
    }
    auto mesh = flat_mesh(*outline, {kernel::SemanticClass::kNone, 0, 0});
    OpResult result;
    result.add(tree.add_child(id, scope, std::move(mesh), std::move(outline)), 0);
    return finish(tree, id, std::move(result));
  }
  Mesh mesh = kind == PrimitiveKind::kCube       ? *box_mesh({1, 1, 1}, mass_box_tags())
              : kind == PrimitiveKind::kCylinder ? unit_cylinder(sides)
              : kind == PrimitiveKind::kCone     ? unit_cone(sides)
                                                 : unit_sphere(sides, divisions);
  for (Vec3& p : mesh.positions()) {
    p = to_scope(s, at + Vec3{p.x * size.x, p.y * size.y, p.z * size.z}, depth);
  }
  // The child is a volume: y up as an extrusion's (a flat shape's normal becomes its y).
  if (s.is_flat()) return replace_with(tree, id, mesh, {1, 0, 0}, {0, 0, 1}, {0, -1, 0});
  return replace_with(tree, id, mesh, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
}

namespace {

ParamDecl size_param(std::string name, std::string doc) {
  return {std::move(name), ParamType::kNumber, std::move(doc), ArgValue{0.0}, {}, 0.0, {}};
}

OpResult run_primitive(ShapeTree& t, ShapeId id, const Arguments& a, PrimitiveKind kind) {
  const auto get = [&](const char* name) { return a.has(name) ? a.number(name) : 0.0; };
  const double radius = get("radius");
  Vec3 dims;
  switch (kind) {
    case PrimitiveKind::kCube:
      dims = {get("width"), get("height"), get("depth")};
      break;
    case PrimitiveKind::kQuad:
      dims = {get("width"), 1, get("length")};
      break;
    case PrimitiveKind::kDisk:
      dims = {2 * radius, 1, 2 * radius};
      break;
    case PrimitiveKind::kSphere:
      dims = {2 * radius, 2 * radius, 2 * radius};
      break;
    case PrimitiveKind::kCylinder:
    case PrimitiveKind::kCone:
      dims = {2 * radius, get("height"), 2 * radius};
      break;
  }
  const bool flat = kind == PrimitiveKind::kQuad || kind == PrimitiveKind::kDisk;
  const bool none = flat ? dims.x == 0 && dims.z == 0 : dims.x == 0 && dims.y == 0 && dims.z == 0;
  const int sides = a.has("sides") ? static_cast<int>(a.integer("sides")) : 0;
  const int divisions = a.has("divisions") ? static_cast<int>(a.integer("divisions")) : 0;
  return primitive(t, id, kind, sides, none ? Vec3{} : dims, divisions);
}

ParamDecl count_param(std::string name, std::string doc) {
  return {std::move(name), ParamType::kInteger, std::move(doc), ArgValue{std::int64_t{16}}, {}, 3.0,
          4096.0};
}

}  // namespace

std::vector<Operation> primitive_operations() {
  const char* fill =
      " Without sizes it fills the scope (zero extents keep proportions, as i()); "
      "with sizes it stands in the scope's xz centre on y = 0.";
  std::vector<Operation> ops;
  ops.push_back({"primitiveCube",
                 std::string("Replaces the geometry by a box (CGA primitiveCube).") + fill,
                 {size_param("width", "along x (meters; 0: fill)"),
                  size_param("height", "along the up axis (meters; 0: fill)"),
                  size_param("depth", "along the third axis (meters; 0: fill)")},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return run_primitive(t, id, a, PrimitiveKind::kCube);
                 }});
  ops.push_back({"primitiveCylinder",
                 std::string("Replaces the geometry by an upright prism of `sides` sides "
                             "(CGA primitiveCylinder).") +
                     fill,
                 {count_param("sides", "number of sides"), size_param("radius", "meters (0: fill)"),
                  size_param("height", "meters (0: fill)")},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return run_primitive(t, id, a, PrimitiveKind::kCylinder);
                 }});
  ops.push_back({"primitiveCone",
                 std::string("Replaces the geometry by an upright cone of `sides` sides (CGA "
                             "primitiveCone).") +
                     fill,
                 {count_param("sides", "number of sides"), size_param("radius", "meters (0: fill)"),
                  size_param("height", "meters (0: fill)")},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return run_primitive(t, id, a, PrimitiveKind::kCone);
                 }});
  ops.push_back({"primitiveSphere",
                 std::string("Replaces the geometry by a sphere of `sides` segments round its "
                             "axis and `divisions` bands from pole to pole (CGA "
                             "primitiveSphere).") +
                     fill,
                 {count_param("sides", "segments round the vertical axis"),
                  count_param("divisions", "bands from the bottom pole to the top one"),
                  size_param("radius", "meters (0: fill)")},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return run_primitive(t, id, a, PrimitiveKind::kSphere);
                 }});
  ops.push_back({"primitiveQuad",
                 std::string("Replaces the geometry by an upward rectangle, a flat shape (CGA "
                             "primitiveQuad).") +
                     fill,
                 {size_param("width", "along x (meters; 0: fill)"),
                  size_param("length", "along the third axis (meters; 0: fill)")},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return run_primitive(t, id, a, PrimitiveKind::kQuad);
                 }});
  ops.push_back(
      {"primitiveDisk",
       std::string("Replaces the geometry by an upward disk of `sides` corners, a flat "
                   "shape (CGA primitiveDisk).") +
           fill,
       {count_param("sides", "corners round the rim"), size_param("radius", "meters (0: fill)")},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return run_primitive(t, id, a, PrimitiveKind::kDisk);
       }});
  return ops;
}

}  // namespace insula::shape
