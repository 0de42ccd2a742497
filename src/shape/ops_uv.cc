// CityEngine's texturing operations (setupProjection, projectUV, texture, translateUV, scaleUV,
// rotateUV, tileUV, normalizeUV, deleteUV) over the uv maps of shape/uv_map.h. Each makes one
// child with the shape's scope and geometry and sets the changed state on it as an attribute, so
// its descendants inherit it (docs/operations-cityengine.md, "Texture coordinates").
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "shape/ops.h"
#include "shape/uv_map.h"

namespace insula::shape {

using kernel::Vec3;

namespace {

constexpr int kUvSets = 10;  // CityEngine's uv sets 0..9

std::vector<Vec3> world_points(const Shape& s) {
  std::vector<Vec3> out;
  if (!s.mesh) return out;
  out.reserve(s.mesh->vertex_count());
  for (const Vec3& p : s.mesh->positions()) out.push_back(s.scope.to_world(p));
  return out;
}

// One child like the shape, carrying `name` = `value` (a null value changes nothing).
OpResult with_state(ShapeTree& tree, ShapeId id, std::string_view name, Value value,
                    std::string warning = {}) {
  const Shape& s = tree[id];
  OpResult r = relabelled_child(tree, id, s.scope, s.mesh, s.outline, std::move(warning));
  if (r.ok() && !is_null(value)) tree.set_attribute(r.children.front(), name, std::move(value));
  return r;
}

// CityEngine's axis `c` ('x', 'y', 'z') of the shape's scope or the world, and the extent of the
// shape along it. CityEngine's world is x east, y up, z south. A flat shape (Insula keeps its
// normal on scope z) is read as CityEngine reads a façade (x along, y up the face, z the normal)
// unless the selector names z, as a lot's projection scope.xz does: then as CityEngine reads a
// lot (y the normal, z = -y), so both keep the projection plane in the face.
struct Axes {
  Vec3 origin;
  std::array<Vec3, 3> axis;  // CityEngine's x, y, z
};

Axes frame_of(const Shape& s, bool world, bool names_z) {
  if (world) return {{}, {Vec3{1, 0, 0}, Vec3{0, 0, 1}, Vec3{0, -1, 0}}};
  const Scope& sc = s.scope;
  if (s.is_flat() && names_z) return {sc.origin, {sc.x, sc.z, sc.y * -1.0}};
  return {sc.origin, {sc.x, sc.y, sc.z}};
}

double extent_along(std::span<const Vec3> points, Vec3 axis) {
  if (points.empty()) return 0;
  double lo = dot(points.front(), axis), hi = lo;
  for (const Vec3& p : points) lo = std::min(lo, dot(p, axis)), hi = std::max(hi, dot(p, axis));
  return hi - lo;
}

// A texture size as CityEngine reads it: meters, 'f of `extent`, or ~w: the size nearest w that
// fits `extent` a whole number of times (at least once).
double offset_size(SizeSpec size, double extent) {
  return size.mode == SizeMode::kRelative ? size.value * extent : size.value;
}

double texture_size(SizeSpec size, double extent) {
  switch (size.mode) {
    case SizeMode::kAbsolute:
      return size.value;
    case SizeMode::kRelative:
      return size.value * extent;
    case SizeMode::kFloating: {
      if (!(extent > 0)) return size.value;
      const double n = std::max(1.0, std::round(extent / std::fabs(size.value)));
      return std::copysign(extent / n, size.value);
    }
  }
  return size.value;
}

OpResult setup_projection(ShapeTree& tree, ShapeId id, int set, std::string_view axes,
                          SizeSpec width, SizeSpec height, SizeSpec width_offset,
                          SizeSpec height_offset, double uw_factor) {
  const Shape& s = tree[id];
  const bool world = axes.starts_with("world.");
  const char cu = axes[axes.size() - 2];
  const char cv = axes[axes.size() - 1];
  const Axes f = frame_of(s, world, cu == 'z' || cv == 'z');
  const auto index = [](char c) { return static_cast<std::size_t>(c - 'x'); };
  const Vec3 au = f.axis[index(cu)];
  const Vec3 av = f.axis[index(cv)];
  const Vec3 aw = f.axis[3 - index(cu) - index(cv)];
  const std::vector<Vec3> points = world_points(s);
  const double extent_u = extent_along(points, au);
  const double extent_v = extent_along(points, av);
  const double w = texture_size(width, extent_u);
  const double h = texture_size(height, extent_v);
  // CityEngine's offsets may be relative too ('f: f of the extent along u or v).
  const double u_offset = offset_size(width_offset, extent_u);
  const double v_offset = offset_size(height_offset, extent_v);
  if (!std::isfinite(w) || !std::isfinite(h) || w == 0 || h == 0) {
    return OpResult::failure("texture width and height must be finite and not 0");
  }
  // u = (a_u . (p - o) + uwFactor a_w . (p - o) - widthOffset) / width, v alike.
  UvMap map;
  map.du = (au + aw * uw_factor) * (1 / w);
  map.u0 = -(dot(map.du, f.origin) + u_offset / w);
  map.dv = av * (1 / h);
  map.v0 = -(dot(map.dv, f.origin) + v_offset / h);
  return with_state(tree, id, uv_projection_attribute(set), Value{encode(map)});
}

std::optional<UvMap> uv_set(const ShapeTree& tree, ShapeId id, int set) {
  const Value* v = tree.attribute(id, uv_set_attribute(set));
  return v != nullptr ? decode_uv_map(*v) : std::nullopt;
}

std::string no_uvs(int set) {
  return "the shape has no texture coordinates in uv set " + std::to_string(set) +
         " (projectUV first); nothing changed";
}

// translateUV, scaleUV, rotateUV: (u, v) -> (a u + b v + c, d u + e v + f) on the set.
OpResult transform_uv(ShapeTree& tree, ShapeId id, int set, std::array<double, 6> m) {
  for (double x : m) {
    if (!std::isfinite(x)) return OpResult::failure("values must be finite");
  }
  const std::optional<UvMap> map = uv_set(tree, id, set);
  if (!map) return with_state(tree, id, {}, Value{}, no_uvs(set));
  return with_state(tree, id, uv_set_attribute(set),
                    Value{encode(map->then(m[0], m[1], m[2], m[3], m[4], m[5]))});
}

OpResult project_uv(ShapeTree& tree, ShapeId id, int set) {
  const Value* projection = tree.attribute(id, uv_projection_attribute(set));
  if (projection == nullptr || !decode_uv_map(*projection)) {
    return with_state(tree, id, {}, Value{},
                      "no projection set up for uv set " + std::to_string(set) +
                          " (setupProjection first); no texture coordinates");
  }
  return with_state(tree, id, uv_set_attribute(set), *projection);
}

OpResult tile_uv(ShapeTree& tree, ShapeId id, int set, SizeSpec width, SizeSpec height) {
  const std::optional<UvMap> map = uv_set(tree, id, set);
  if (!map) return with_state(tree, id, {}, Value{}, no_uvs(set));
  const std::vector<Vec3> points = world_points(tree[id]);
  const std::optional<UvRange> range = uv_range(*map, points);
  if (!range) return OpResult::failure("the shape has no geometry");
  // Meters per uv unit along u and v (the map's gradients), so a tile is `width` meters.
  const auto factor = [](SizeSpec size, Vec3 gradient, double span) {
    const double per_meter = length(gradient);
    if (size.value == 0 || !(per_meter > 0)) return 1.0;  // 0: leave the axis
    const double t = texture_size(size, span / per_meter);
    return 1 / (per_meter * t);
  };
  const double fu = factor(width, map->du, range->max.x - range->min.x);
  const double fv = factor(height, map->dv, range->max.y - range->min.y);
  if (!std::isfinite(fu) || !std::isfinite(fv)) {
    return OpResult::failure("texture width and height must be finite");
  }
  return with_state(tree, id, uv_set_attribute(set), Value{encode(map->then(fu, 0, 0, 0, fv, 0))});
}

OpResult normalize_uv(ShapeTree& tree, ShapeId id, int set, std::string_view mode) {
  const std::optional<UvMap> map = uv_set(tree, id, set);
  if (!map) return with_state(tree, id, {}, Value{}, no_uvs(set));
  const std::vector<Vec3> points = world_points(tree[id]);
  const std::optional<UvRange> range = uv_range(*map, points);
  if (!range) return OpResult::failure("the shape has no geometry");
  const double su = range->max.x - range->min.x;
  const double sv = range->max.y - range->min.y;
  const double uniform = std::max(su, sv);
  const auto scale = [](double span) { return span > 0 ? 1 / span : 1.0; };
  double fu = 1, fv = 1;
  if (mode == "uv") fu = scale(su), fv = scale(sv);
  if (mode == "uvuniform") fu = fv = scale(uniform);
  const bool touch_u = mode != "v", touch_v = mode != "u";
  if (mode == "u") fu = scale(su);
  if (mode == "v") fv = scale(sv);
  return with_state(tree, id, uv_set_attribute(set),
                    Value{encode(map->then(fu, 0, touch_u ? -range->min.x * fu : 0, 0, fv,
                                           touch_v ? -range->min.y * fv : 0))});
}

ParamDecl set_param() {
  return {"uvSet",
          ParamType::kInteger,
          "uv set (texture layer) 0..9; 0 is the colour map's, the only one written out",
          std::nullopt,
          {},
          0.0,
          static_cast<double>(kUvSets - 1)};
}

ParamDecl number_param(std::string name, std::string doc, std::optional<double> fallback) {
  std::optional<ArgValue> value;
  if (fallback) value = ArgValue{*fallback};
  return {std::move(name), ParamType::kNumber, std::move(doc), std::move(value), {}, {}, {}};
}

ParamDecl texture_size_param(std::string name, std::string doc) {
  return {std::move(name), ParamType::kSize, std::move(doc), std::nullopt, {}, {}, {}};
}

ParamDecl offset_param(std::string name, std::string doc) {
  return {std::move(name),
          ParamType::kSize,
          std::move(doc),
          ArgValue{SizeSpec{0, SizeMode::kAbsolute}},
          {},
          {},
          {}};
}

int set_of(const Arguments& a) {
  return static_cast<int>(a.integer("uvSet"));
}

}  // namespace

std::vector<Operation> uv_operations() {
  const std::vector<std::string> state = uv_attributes();
  std::vector<std::string> selectors;
  for (std::string_view frame : {"scope.", "world."}) {
    for (std::string_view pair : {"xy", "xz", "yx", "yz", "zx", "zy"}) {
      selectors.push_back(std::string(frame).append(pair));
    }
  }
  std::vector<Operation> ops;
  ops.push_back(
      {"setupProjection",
       "Sets up the projection of a uv set: the chosen axes of the scope (origin at the scope's) "
       "or of the world (x east, y up, z south) become u and v, one texture repeat per "
       "textureWidth x textureHeight meters; projectUV applies it. Inherited by descendants.",
       {set_param(),
        {"axes",
         ParamType::kEnum,
         "scope.xy .. scope.zy, world.xy .. world.zy: the origin and the axes taken as u and v",
         std::nullopt,
         selectors,
         {},
         {}},
        texture_size_param("textureWidth",
                           "meters per repeat along u; 'f: f of the shape's extent along u; ~w: "
                           "about w, fitting the extent a whole number of times; < 0 mirrors"),
        texture_size_param("textureHeight", "the same along v"),
        offset_param("widthOffset", "u offset in meters; 'f: f of the shape's extent along u"),
        offset_param("heightOffset", "the same along v"),
        number_param("uwFactor", "how much the third axis adds to u (0: none)", 0.0)},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return setup_projection(t, id, set_of(a), a.string("axes"), a.size("textureWidth"),
                                 a.size("textureHeight"), a.size("widthOffset"),
                                 a.size("heightOffset"), a.number("uwFactor"));
       },
       state});
  ops.push_back({"projectUV",
                 "Gives the shape's geometry texture coordinates from the uv set's projection "
                 "(setupProjection); geometry cut from it later keeps them.",
                 {set_param()},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return project_uv(t, id, set_of(a));
                 },
                 state});
  ops.push_back(
      {"texture",
       "Sets the colour map (material.colormap) to an image file, found as assets are; "
       "\"\" removes it. A missing file leaves the colour only, with a warning.",
       {{"path", ParamType::kString, "image file (PNG or JPEG)", std::nullopt, {}, {}, {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return with_state(t, id, kColormapAttribute, Value{a.string("path")});
       },
       state});
  ops.push_back(
      {"translateUV",
       "Adds (u, v) to the uv set's texture coordinates.",
       {set_param(), number_param("u", "added to u", std::nullopt),
        number_param("v", "added to v", std::nullopt)},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return transform_uv(t, id, set_of(a), {1, 0, a.number("u"), 0, 1, a.number("v")});
       },
       state});
  ops.push_back({"scaleUV",
                 "Multiplies the uv set's u and v (about uv (0, 0)).",
                 {set_param(), number_param("uFactor", "factor on u", std::nullopt),
                  number_param("vFactor", "factor on v", std::nullopt)},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return transform_uv(t, id, set_of(a),
                                       {a.number("uFactor"), 0, 0, 0, a.number("vFactor"), 0});
                 },
                 state});
  ops.push_back({"rotateUV",
                 "Turns the uv set's coordinates about uv (0, 0), counter-clockwise.",
                 {set_param(), number_param("rotation", "degrees", std::nullopt)},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   const double r = a.number("rotation") * std::numbers::pi / 180;
                   const double c = std::cos(r), s = std::sin(r);
                   return transform_uv(t, id, set_of(a), {c, -s, 0, s, c, 0});
                 },
                 state});
  ops.push_back(
      {"tileUV",
       "Rescales the uv set so one texture repeat covers textureWidth x textureHeight meters of "
       "the geometry ('f: f of its extent; ~w: about w, fitting it; 0 leaves the axis).",
       {set_param(), texture_size_param("textureWidth", "meters per repeat along u"),
        texture_size_param("textureHeight", "meters per repeat along v")},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return tile_uv(t, id, set_of(a), a.size("textureWidth"), a.size("textureHeight"));
       },
       state});
  ops.push_back(
      {"normalizeUV",
       "Moves and scales the uv set so the geometry's coordinates span [0, 1]: uv both axes, "
       "uvUniform both by the larger span, u or v one axis. Insula normalises the whole shape "
       "for either type (separatePerFace differs only on shapes of several faces).",
       {set_param(),
        {"mode",
         ParamType::kEnum,
         "uv, uvUniform, u or v",
         std::nullopt,
         {"uv", "uvuniform", "u", "v"},
         {},
         {}},
        {"type",
         ParamType::kEnum,
         "separatePerFace or collectiveAllFaces",
         ArgValue{std::string("collectiveallfaces")},
         {"separateperface", "collectiveallfaces"},
         {},
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return normalize_uv(t, id, set_of(a), a.string("mode"));
       },
       state});
  ops.push_back({"deleteUV",
                 "Removes the uv set's texture coordinates (its projection stays).",
                 {set_param()},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return with_state(t, id, uv_set_attribute(set_of(a)), Value{std::string()});
                 },
                 state});
  return ops;
}

}  // namespace insula::shape
