// Regions and connection (seed 001 §3.1.2, §3.4.2): a region is a named range of connector
// positions and orientations on a component; connect() aligns a component's connector (its scope
// origin and axes) to a placement in the region, given or drawn at random within the ranges.
#include <algorithm>
#include <cmath>

#include "lang/lua/bindings_internal.h"
#include "shape/query_expr.h"

namespace insula::lua {

using kernel::Vec3;
using shape::QueryExpr;
using shape::ShapeId;

namespace {

void push_vec3(lua_State* L, Vec3 v) {
  lua_createtable(L, 3, 0);
  const double xyz[3] = {v.x, v.y, v.z};
  for (int i = 0; i < 3; ++i) {
    lua_pushnumber(L, xyz[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

Vec3 field_vec3(lua_State* L, int arg, const char* key, Vec3 fallback, const char* op) {
  if (lua_getfield(L, arg, key) == LUA_TNIL) {
    lua_pop(L, 1);
    return fallback;
  }
  const Vec3 v = check_vec3(L, lua_gettop(L), op);
  lua_pop(L, 1);
  return v;
}

bool below(Vec3 a, Vec3 b) {
  return a.x <= b.x && a.y <= b.y && a.z <= b.z;
}

const shape::Region& region_of(lua_State* L, RegionRef r) {
  return program(L).tree[r.id].regions[r.index];
}

// region(c, {label=, min=, max=, minAngles=, maxAngles=, face=}): adds a region to c. Positions
// are in c's scope space (default: the whole scope box; flat for a 2D component), angles in
// degrees about c's x, y, z axes (default 0).
int lua_region(lua_State* L) {
  const char* op = "region";
  Program& p = program(L);
  const std::vector<ShapeId> ids = check_components(L, 1, op);
  if (!lua_istable(L, 2)) arg_error(op, 2, "expected a table {label=..., min=..., max=...}");
  const std::optional<std::string> label = field_string(L, 2, "label", op);
  if (!label || label->empty()) arg_error(op, 2, "a region needs a label");
  const std::optional<std::string> face = field_string(L, 2, "face", op);
  std::vector<RegionRef> made;
  for (ShapeId id : ids) {
    shape::Region r;
    r.name = *label;
    r.face_id = face ? p.tree.face_id(*face) : 0;
    r.min = field_vec3(L, 2, "min", {}, op);
    r.max = field_vec3(L, 2, "max", p.tree[id].scope.size, op);
    r.min_degrees = field_vec3(L, 2, "minAngles", {}, op);
    r.max_degrees = field_vec3(L, 2, "maxAngles", r.min_degrees, op);
    if (!below(r.min, r.max)) op_error(op, "min must not exceed max on any axis");
    if (!below(r.min_degrees, r.max_degrees)) {
      op_error(op, "minAngles must not exceed maxAngles on any axis");
    }
    p.tree[id].regions.push_back(std::move(r));
    made.push_back({id, static_cast<std::uint32_t>(p.tree[id].regions.size() - 1)});
  }
  ++p.operations;
  if (made.size() == 1 && to_component(L, 1)) {
    push_region(L, made.front());
    return 1;
  }
  return push_array(L, made, push_region);
}

// rquery(expr [, sources]): regions whose name matches a label expression (and/or/not), over every
// component or the sources and their children.
int lua_rquery(lua_State* L) {
  const char* op = "rquery";
  int expr_arg = 1;
  int sources_arg = 2;
  if (lua_type(L, 1) != LUA_TSTRING) std::swap(expr_arg, sources_arg);
  const std::string text = check_string(L, expr_arg, op);
  base::Result<QueryExpr> expr = QueryExpr::parse(text, "query");
  if (!expr) {
    const base::Diagnostic& d = expr.diagnostics().front();
    op_error(op, d.message + " (column " + std::to_string(d.span.column) + " of \"" + text + "\")");
  }
  for (const QueryExpr::Node& n : expr->nodes()) {
    using K = QueryExpr::Kind;
    if (n.kind != K::kLabel && n.kind != K::kNot && n.kind != K::kAnd && n.kind != K::kOr) {
      arg_error(op, expr_arg, "region queries match names only (and, or, not, labels)");
    }
  }
  const shape::ShapeTree& tree = program(L).tree;
  std::vector<ShapeId> pool;
  if (lua_isnoneornil(L, sources_arg)) {
    pool.resize(tree.size());
    for (ShapeId i = 0; i < tree.size(); ++i) pool[i] = i;
  } else {
    std::vector<bool> seen(tree.size(), false);
    for (ShapeId s : check_components(L, sources_arg, op)) {
      for (ShapeId id : tree.subtree(s)) seen[id] = true;
    }
    for (ShapeId i = 0; i < tree.size(); ++i) {
      if (seen[i]) pool.push_back(i);
    }
  }
  std::vector<RegionRef> out;
  for (ShapeId id : pool) {
    const auto& regions = tree[id].regions;
    for (std::size_t i = 0; i < regions.size(); ++i) {
      if (expr->matches_name(regions[i].name)) {
        out.push_back({id, static_cast<std::uint32_t>(i)});
      }
    }
  }
  return push_array(L, out, push_region);
}

// The copy of `source` (and its subtree) as a child of `parent` with scope `placed`; descendants
// keep their placement relative to the source (§3.4.2: "the resulting rigid transformation is then
// propagated to the source component's children"). Geometry is shared, not copied.
ShapeId place_copy(shape::ShapeTree& tree, ShapeId source, ShapeId parent,
                   const shape::Scope& placed) {
  const shape::Shape& s = tree[source];
  const shape::Scope from = s.scope;
  const ShapeId copy = tree.add_child(parent, placed, s.mesh, s.outline);
  for (shape::SymbolId label : std::vector<shape::SymbolId>(tree[source].labels)) {
    tree.add_label(copy, tree.symbol(label));
  }
  for (const auto& [name, value] : std::vector(tree[source].attributes)) {
    const std::string key(tree.symbol(name));
    if (key != kConnectedAttribute) tree.set_attribute(copy, key, value);
  }
  tree[copy].regions = tree[source].regions;
  for (ShapeId child : std::vector<ShapeId>(tree[source].children)) {
    const shape::Scope& c = tree[child].scope;
    shape::Scope moved = c;
    moved.origin = placed.to_world(from.to_local(c.origin));
    moved.x = placed.direction_to_world(from.direction_to_local(c.x));
    moved.y = placed.direction_to_world(from.direction_to_local(c.y));
    moved.z = placed.direction_to_world(from.direction_to_local(c.z));
    place_copy(tree, child, copy, moved);
  }
  return copy;
}

bool within(Vec3 v, Vec3 lo, Vec3 hi, double tolerance) {
  return v.x >= lo.x - tolerance && v.x <= hi.x + tolerance && v.y >= lo.y - tolerance &&
         v.y <= hi.y + tolerance && v.z >= lo.z - tolerance && v.z <= hi.z + tolerance;
}

// connect(c, region [, {position=, angles=, label=, ...}]): places c on the region (§3.4.2). The
// placed component is a copy made a child of the region's component (so it belongs to that
// building and inherits its attributes); c itself is marked as moved and not exported. Without a
// position or angles, they are drawn uniformly within the region's ranges from the program's
// seeded generator.
int lua_connect(lua_State* L) {
  const char* op = "connect";
  Program& p = program(L);
  const ShapeId source = check_component(L, 1, op);
  const auto ref = to_region(L, 2);
  if (!ref) arg_error(op, 2, "expected a region (from region() or rquery())");
  const shape::Region region = region_of(L, *ref);
  const shape::RegionPlacement drawn = shape::sample(region, p.rng);
  Vec3 position = drawn.position;
  Vec3 angles = drawn.degrees;
  if (lua_istable(L, 3)) {
    position = field_vec3(L, 3, "position", position, op);
    angles = field_vec3(L, 3, "angles", angles, op);
  } else if (!lua_isnoneornil(L, 3)) {
    arg_error(op, 3, "expected a table {position=..., angles=...}");
  }
  if (!region.contains(position, 1e-9)) {
    op_error(op, "position is outside region '" + region.name + "'");
  }
  if (!within(angles, region.min_degrees, region.max_degrees, 1e-9)) {
    op_error(op, "angles are outside the range of region '" + region.name + "'");
  }
  for (ShapeId a = ref->id; a != shape::kNoShape; a = p.tree.parent(a)) {
    if (a == source) op_error(op, "a component cannot be connected to a region of its own subtree");
  }
  const shape::Scope& owner = p.tree[ref->id].scope;
  shape::Scope placed = owner;
  placed.origin = owner.to_world(position);
  placed.size = p.tree[source].scope.size;
  placed = shape::rotated(placed, shape::Axis::kX, angles.x, {});
  placed = shape::rotated(placed, shape::Axis::kY, angles.y, {});
  placed = shape::rotated(placed, shape::Axis::kZ, angles.z, {});
  const ShapeId copy = place_copy(p.tree, source, ref->id, placed);
  p.tree.set_attribute(source, kConnectedAttribute, true);
  if (lua_istable(L, 3)) {
    apply_spec(L, 3, std::span<const ShapeId>(&copy, 1), op, {"position", "angles"});
  }
  ++p.operations;
  if (p.tree.size() > p.max_components) {
    p.stopped = true;
    op_error(op, "component limit of " + std::to_string(p.max_components) + " reached");
  }
  push_component(L, copy);
  return 1;
}

int region_index(lua_State* L) {
  const auto ref = to_region(L, 1);
  if (!ref) arg_error("index", 1, "expected a region");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("index", 2, "region fields are strings");
  const std::string key = lua_tostring(L, 2);
  const shape::Region& r = region_of(L, *ref);
  if (key == "component") {
    push_component(L, ref->id);
  } else if (key == "name" || key == "label") {
    lua_pushlstring(L, r.name.data(), r.name.size());
  } else if (key == "min") {
    push_vec3(L, r.min);
  } else if (key == "max") {
    push_vec3(L, r.max);
  } else if (key == "minAngles") {
    push_vec3(L, r.min_degrees);
  } else if (key == "maxAngles") {
    push_vec3(L, r.max_degrees);
  } else {
    lua_pushnil(L);
  }
  return 1;
}

int region_tostring(lua_State* L) {
  const auto ref = to_region(L, 1);
  if (!ref) arg_error("tostring", 1, "expected a region");
  const std::string text =
      "region '" + region_of(L, *ref).name + "' of component " + std::to_string(ref->id);
  lua_pushlstring(L, text.data(), text.size());
  return 1;
}

}  // namespace

void push_region(lua_State* L, RegionRef region) {
  auto* ref = static_cast<RegionRef*>(lua_newuserdatauv(L, sizeof(RegionRef), 0));
  *ref = region;
  luaL_setmetatable(L, kRegionMeta);
}

std::optional<RegionRef> to_region(lua_State* L, int arg) {
  const auto* ref = static_cast<const RegionRef*>(luaL_testudata(L, arg, kRegionMeta));
  if (ref == nullptr) return std::nullopt;
  return *ref;
}

void register_region_bindings(Api& api) {
  lua_State* L = api.state();
  luaL_newmetatable(L, kRegionMeta);
  lua_pushcfunction(L, protect<region_index>);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, protect<region_tostring>);
  lua_setfield(L, -2, "__tostring");
  lua_pushliteral(L, "locked");
  lua_setfield(L, -2, "__metatable");
  lua_pop(L, 1);
  api.function("region", protect<lua_region>,
               "region(c, {label=, min=, max=, minAngles=, maxAngles=, face=}): adds a region");
  api.function("rquery", protect<lua_rquery>, "rquery(expr [, sources]): regions by name");
  api.function("connect", protect<lua_connect>,
               "connect(c, region [, {position=, angles=, label=...}]): places c on the region");
}

}  // namespace insula::lua
