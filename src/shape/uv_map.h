// Texture coordinates as CityEngine's texturing operations make them (issue 20 item 3;
// docs/operations-cityengine.md, "Texture coordinates"): a uv set is an affine map from a point in
// world space (the tree's coordinates, meters) to (u, v). setupProjection records a projection on
// the shape, inherited by its descendants like a colour; projectUV copies it into the uv set;
// translateUV, scaleUV, rotateUV, tileUV and normalizeUV compose with it; deleteUV clears it.
// Writers evaluate the map at each vertex, so geometry split after projectUV interpolates exactly.
// Both are kept as inherited string attributes, so every front-end's attribute store carries them
// (kUvSetAttribute, kUvProjectionAttribute).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/transform.h"
#include "kernel/vec.h"
#include "shape/value.h"

namespace insula::shape {

struct UvMap {
  kernel::Vec3 du;  // u = dot(du, p) + u0
  double u0 = 0;
  kernel::Vec3 dv;  // v = dot(dv, p) + v0
  double v0 = 0;

  kernel::Vec2 at(kernel::Vec3 p) const { return {dot(du, p) + u0, dot(dv, p) + v0}; }
  // The map followed by (u, v) -> (a u + b v + c, d u + e v + f).
  UvMap then(double a, double b, double c, double d, double e, double f) const;
  // The same coordinates for geometry moved by the rigid transform `t` (a rule's model placed on
  // its lot): the map of t(p) is this map's of p.
  UvMap moved(const kernel::Transform& t) const;
  friend bool operator==(const UvMap&, const UvMap&) = default;
};

// The attribute names of uv set `set` (0..9) and of its projection.
std::string uv_set_attribute(int set);
std::string uv_projection_attribute(int set);
// Every attribute the texturing operations read and write (the colour map, each set and its
// projection): the front-ends that keep attributes in a store of their own (CGA's derivation)
// pass these in and take them back (Operation::state).
std::vector<std::string> uv_attributes();
// The attribute CityEngine's texture() and set(material.colormap, ...) assign.
inline constexpr std::string_view kColormapAttribute = "material.colormap";

// Exact text form (17 significant digits), so a map survives any attribute store.
std::string encode(const UvMap& map);
// The map of an attribute value; nullopt for null, "" (a deleted set) or other text.
std::optional<UvMap> decode_uv_map(const Value& value);

// Range of the map over the vertices of `mesh` (world space): {u min, v min, u max, v max};
// nullopt for an empty mesh.
struct UvRange {
  kernel::Vec2 min;
  kernel::Vec2 max;
};
std::optional<UvRange> uv_range(const UvMap& map, std::span<const kernel::Vec3> world_points);

}  // namespace insula::shape
