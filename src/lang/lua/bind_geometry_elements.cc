// Lua bindings of the architectural elements of seed 001 §4.4-4.5: door() and window() add
// openings through regions or wall faces, solidGeometry() turns boundaries into geometry with the
// openings cut out (§3.6), place() puts furniture and fixtures on regions without overlapping
// doors and windows, sharing one mesh between the copies (instancing).
#include <cmath>
#include <map>
#include <unordered_map>

#include "lang/lua/bind_geometry_internal.h"
#include "lang/lua/bindings_internal.h"
#include "shape/scene.h"

namespace insula::lua {

using kernel::Vec3;
using shape::ShapeId;

namespace {

// Every opening the program made, bucketed on a world grid so solidGeometry only tests the
// openings near each wall (linear cost in the number of walls, not walls x openings).
struct OpeningIndex {
  static constexpr double kCell = 4.0;  // meters
  std::vector<ShapeId> all;
  std::unordered_map<std::uint64_t, std::vector<ShapeId>> cells;

  static std::uint64_t key(long long x, long long y, long long z) {
    const auto u = [](long long v) {
      return static_cast<std::uint64_t>(v + (1LL << 20)) & 0x1fffffULL;
    };
    return (u(x) << 42) | (u(y) << 21) | u(z);
  }
  template <typename F>
  static void for_cells(const kernel::Bounds3& b, F f) {
    const auto lo = [](double v) { return static_cast<long long>(std::floor(v / kCell)); };
    for (long long x = lo(b.min.x); x <= lo(b.max.x); ++x) {
      for (long long y = lo(b.min.y); y <= lo(b.max.y); ++y) {
        for (long long z = lo(b.min.z); z <= lo(b.max.z); ++z) f(key(x, y, z));
      }
    }
  }
  void add(const shape::Scope& scope, ShapeId id) {
    all.push_back(id);
    kernel::Bounds3 b;
    for (const Vec3& c : scope.corners()) b.add(c);
    for_cells(b, [&](std::uint64_t k) { cells[k].push_back(id); });
  }
  std::vector<ShapeId> near(const shape::Scope& scope) const {
    kernel::Bounds3 b;
    for (const Vec3& c : scope.corners()) b.add(c);
    std::vector<ShapeId> out;
    for_cells(b, [&](std::uint64_t k) {
      if (auto it = cells.find(k); it != cells.end())
        out.insert(out.end(), it->second.begin(), it->second.end());
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
};

// Asset meshes normalised once (bounding box at the origin), shared by every placed copy.
struct AssetCache {
  std::map<std::string, std::shared_ptr<const kernel::Mesh>, std::less<>> by_name;
  std::map<const kernel::Mesh*, std::shared_ptr<const kernel::Mesh>> by_mesh;
  std::map<std::pair<ShapeId, std::uint32_t>, std::uint64_t> draws;  // placements per region
};

// door(target [, opts]) / window(target [, opts]): target is a region on a flat wall component
// or the wall component itself. opts: width, height, sill, u (centre along the wall), depth,
// frame, and labels/attributes.
template <shape::OpeningKind kKind>
int lua_opening(lua_State* L) {
  const bool door = kKind == shape::OpeningKind::kDoor;
  const char* op = door ? "door" : "window";
  Program& p = program(L);
  ShapeId owner = shape::kNoShape;
  std::optional<shape::Region> region;
  if (const auto ref = to_region(L, 1)) {
    owner = ref->id;
    region = p.tree[owner].regions.at(ref->index);
  } else {
    owner = check_component(L, 1, op);
  }
  if (!p.tree[owner].is_flat()) op_error(op, "the wall must be a flat component (a face)");
  if (!lua_isnoneornil(L, 2) && !lua_istable(L, 2)) arg_error(op, 2, "expected a table");
  const auto opt = [&](const char* key, double fallback) {
    return lua_istable(L, 2) ? field_number(L, 2, key, op).value_or(fallback) : fallback;
  };
  shape::OpeningSpec spec;
  spec.kind = kKind;
  spec.width = opt("width", door ? 0.9 : 1.2);
  spec.height = opt("height", door ? 2.1 : 1.3);
  spec.depth = opt("depth", 0.5);
  spec.frame = opt("frame", 0.05);
  const double lo = region ? region->min.x : 0;
  const double hi = region ? region->max.x : p.tree[owner].scope.size.x;
  double u = (lo + hi) / 2;
  if (region) {
    const double a = lo + spec.width / 2;
    const double b = hi - spec.width / 2;
    u = b > a ? p.rng.uniform(a, b) : u;
  }
  spec.u = opt("u", u);
  spec.sill = opt("sill", region ? region->min.y : (door ? 0.0 : 0.9));
  const shape::OpResult r = shape::add_opening(p.tree, owner, spec);
  check_op(L, op, r);
  const ShapeId id = r.children.at(0);
  p.extension<OpeningIndex>("luageom.openings").add(p.tree[id].scope, id);
  apply_spec(L, 2, r.children, op, {"width", "height", "sill", "u", "depth", "frame"});
  push_component(L, id);
  return 1;
}

// solidGeometry(c or list [, color | {openings=, uv=, material=, ...}]): §3.6 / Fig. 3.
int lua_solid_geometry(lua_State* L) {
  const char* op = "solidGeometry";
  Program& p = program(L);
  const bool single = to_component(L, 1).has_value();
  const std::vector<ShapeId> ids = check_components(L, 1, op);
  shape::SolidOptions options;
  std::optional<std::vector<ShapeId>> given;
  Spec spec;
  if (lua_istable(L, 2)) {
    if (lua_getfield(L, 2, "openings") != LUA_TNIL) given = check_components(L, lua_gettop(L), op);
    lua_pop(L, 1);
    options.uv_scale = field_number(L, 2, "uv", op).value_or(1.0);
    options.material = field_string(L, 2, "material", op).value_or("");
    if (!(options.uv_scale >= 0)) arg_error(op, 2, "field 'uv' must be >= 0");
    spec = check_spec(L, 2, op, {"openings", "uv", "material"});
  } else if (!lua_isnoneornil(L, 2)) {
    spec.attributes.emplace_back("color",
                                 check_value(L, 2, op));  // Fig. 3: solidGeometry(c, c.color)
  }
  const auto& index = p.extension<OpeningIndex>("luageom.openings");
  std::vector<ShapeId> created;
  for (ShapeId id : ids) {
    options.openings = given ? *given : index.near(p.tree[id].scope);
    const shape::OpResult r = shape::solid_geometry(p.tree, id, options);
    check_op(L, op, r);
    apply_spec(p.tree, spec, r.children);
    created.insert(created.end(), r.children.begin(), r.children.end());
  }
  if (single) {
    push_component(L, created.at(0));
    return 1;
  }
  return push_components(L, created);
}

std::shared_ptr<const kernel::Mesh> asset_mesh(lua_State* L, int arg, const char* op) {
  Program& p = program(L);
  AssetCache& cache = p.extension<AssetCache>("luageom.assets");
  if (lua_type(L, arg) == LUA_TSTRING) {
    const std::string name = lua_tostring(L, arg);
    if (auto it = cache.by_name.find(name); it != cache.by_name.end()) return it->second;
    if (p.assets == nullptr) op_error(op, "no asset folder was given (--assets DIR)");
    std::string error;
    auto mesh = p.assets->find(name, error);
    if (!mesh) op_error(op, error.empty() ? "asset '" + name + "' not found" : error);
    return cache.by_name[name] = shape::normalized_asset(*mesh);
  }
  const ShapeId source = check_component(L, arg, op);
  const auto& mesh = p.tree[source].mesh;
  if (!mesh || mesh->empty()) arg_error(op, arg, "the component has no geometry");
  // The template itself is not exported (as with connect()).
  p.tree.set_attribute(source, kConnectedAttribute, true);
  auto& slot = cache.by_mesh[mesh.get()];
  if (!slot) slot = shape::normalized_asset(*mesh);
  return slot;
}

// place(region, asset [, {avoid=, clearance=, attempts=, kind=, label=...}]): furniture (§4.5). The
// asset is an asset name or a component (e.g. from componentFromFile). `kind` says what outputs
// call it: "furniture" (the default: CityJSON BuildingFurniture) or "installation" (a balcony on a
// facade: BuildingInstallation). Returns the placed component, or nil when no place in the region
// keeps clear of `avoid`.
int lua_place(lua_State* L) {
  const char* op = "place";
  Program& p = program(L);
  const auto ref = to_region(L, 1);
  if (!ref) arg_error(op, 1, "expected a region (from region() or rquery())");
  const std::shared_ptr<const kernel::Mesh> mesh = asset_mesh(L, 2, op);
  shape::PlaceOptions options;
  if (lua_istable(L, 3)) {
    if (lua_getfield(L, 3, "avoid") != LUA_TNIL)
      options.avoid = check_components(L, lua_gettop(L), op);
    lua_pop(L, 1);
    options.clearance = field_number(L, 3, "clearance", op).value_or(0);
    options.attempts = static_cast<int>(field_number(L, 3, "attempts", op).value_or(32));
    if (options.attempts < 1 || options.attempts > 10000) {
      arg_error(op, 3, "field 'attempts' must be in [1, 10000]");
    }
  } else if (!lua_isnoneornil(L, 3)) {
    arg_error(op, 3, "expected a table {avoid=, clearance=, attempts=, kind=, label=...}");
  }
  std::string_view kind_label = shape::kFurnitureLabel;
  if (lua_istable(L, 3)) {
    const std::string kind = field_string(L, 3, "kind", op).value_or("furniture");
    if (kind == "installation") {
      kind_label = shape::kInstallationLabel;
    } else if (kind != "furniture") {
      arg_error(op, 3, "field 'kind' must be furniture or installation; got '" + kind + "'");
    }
  }
  const Spec spec = check_spec(L, 3, op, {"avoid", "clearance", "attempts", "kind"});
  options.draw = p.extension<AssetCache>("luageom.assets").draws[{ref->id, ref->index}]++;
  const shape::Connected c = shape::place_on_region(p.tree, ref->id, ref->index, mesh, options);
  ++p.operations;
  if (c.id == shape::kNoShape) {
    lua_pushnil(L);
    return 1;
  }
  apply_spec(p.tree, spec, std::span<const ShapeId>(&c.id, 1));
  // After the user's labels (the first names the part): outputs read the kind from this label.
  p.tree.add_label(c.id, kind_label);
  push_component(L, c.id);
  return 1;
}

}  // namespace

void register_element_bindings(Api& api) {
  api.function("door", protect<lua_opening<shape::OpeningKind::kDoor>>,
               "door(region or wall [, {width=, height=, u=, sill=, depth=, label=...}])");
  api.function("window", protect<lua_opening<shape::OpeningKind::kWindow>>,
               "window(region or wall [, {width=, height=, u=, sill=, depth=, label=...}])");
  api.function(
      "solidGeometry", protect<lua_solid_geometry>,
      "solidGeometry(c [, color | {openings=, uv=, material=}]): geometry with openings cut");
  api.function(
      "place", protect<lua_place>,
      "place(region, asset [, {avoid=, clearance=, attempts=, kind=, label=...}]): furniture");
}

}  // namespace insula::lua
