// Components (seed 001 §3.1): creation (boxes, footprints, faces, OBJ assets), fields, labels,
// inherited attributes (§3.4.1 alteration) and face ids (§3.1.1); the face handle type.
#include <algorithm>
#include <array>
#include <cmath>

#include "kernel/polygon.h"
#include "lang/lua/bindings_internal.h"
#include "shape/ops.h"
#include "shape/query_expr.h"

namespace insula::lua {

using kernel::Vec3;
using shape::QueryExpr;
using shape::ShapeId;

namespace {

// World frame of root components: x east, y up, z = x cross y (south), as every mass scope
// (docs/shape-model.md), so `size = {w, h, d}` and `position = {x, y, z}` read like the paper's
// Fig. 3 (`size={10, 2.5, 10}`: 2.5 m high).
shape::Scope root_frame(Vec3 position, Vec3 size) {
  shape::Scope s;
  s.x = {1, 0, 0};
  s.y = {0, 0, 1};
  s.z = {0, -1, 0};
  s.origin = s.to_world(position);  // the frame at the world origin maps position too
  s.size = size;
  return s;
}

// Box sides of a component: mass classes (walls, ground below, roof above) without face ids, so
// face ids stay the names a program sets (§3.1.1).
std::shared_ptr<const kernel::Mesh> component_box(Vec3 size) {
  return shape::box_mesh(size, shape::mass_box_tags());
}

std::string describe_component(const shape::ShapeTree& tree, ShapeId id) {
  std::string out = "component " + std::to_string(id);
  const auto labels = tree.labels(id);
  if (!labels.empty()) {
    out += " (";
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (i > 0) out += ", ";
      out.append(labels[i]);
    }
    out += ")";
  }
  return out;
}

void push_vec3(lua_State* L, Vec3 v) {
  lua_createtable(L, 3, 0);
  const double xyz[3] = {v.x, v.y, v.z};
  for (int i = 0; i < 3; ++i) {
    lua_pushnumber(L, xyz[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

Vec3 check_size_vec(lua_State* L, int arg, const char* op) {
  const Vec3 size = check_vec3(L, arg, op);
  if (size.x < 0 || size.y < 0 || size.z < 0) arg_error(op, arg, "sizes must be >= 0");
  return size;
}

// Field `key` of the table at `arg` as a Vec3, or `fallback`.
Vec3 field_vec3(lua_State* L, int arg, const char* key, Vec3 fallback, const char* op,
                bool size = false) {
  if (lua_getfield(L, arg, key) == LUA_TNIL) {
    lua_pop(L, 1);
    return fallback;
  }
  const Vec3 v = size ? check_size_vec(L, lua_gettop(L), op) : check_vec3(L, lua_gettop(L), op);
  lua_pop(L, 1);
  return v;
}

kernel::Ring check_ring(lua_State* L, int arg, const char* op) {
  if (!lua_istable(L, arg)) arg_error(op, arg, "expected a list of {x, y} points");
  kernel::Ring ring;
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, arg));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, arg, i);
    const Vec3 p = check_vec3(L, lua_gettop(L), op, true);
    lua_pop(L, 1);
    ring.push_back({p.x, p.y});
  }
  return ring;
}

// ---- component(...)

// component{size=, position=} or component{polygon=, holes=, elevation=}: a root (§3.1:
// "multiple trees can exist simultaneously").
ShapeId create_root(lua_State* L, int spec) {
  Program& p = program(L);
  const char* op = "component";
  const bool has_polygon = lua_getfield(L, spec, "polygon") != LUA_TNIL;
  lua_pop(L, 1);
  if (has_polygon) {
    kernel::Polygon polygon;
    lua_getfield(L, spec, "polygon");
    polygon.outer = check_ring(L, lua_gettop(L), op);
    lua_pop(L, 1);
    if (lua_getfield(L, spec, "holes") != LUA_TNIL) {
      const int holes = lua_gettop(L);
      if (!lua_istable(L, holes)) arg_error(op, 1, "field 'holes' must be a list of rings");
      const auto n = static_cast<lua_Integer>(lua_rawlen(L, holes));
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, holes, i);
        polygon.holes.push_back(check_ring(L, lua_gettop(L), op));
        lua_pop(L, 1);
      }
    }
    lua_pop(L, 1);
    const double elevation = field_number(L, spec, "elevation", op).value_or(0);
    const shape::RootResult root = p.tree.create_root(polygon, elevation);
    if (!root.ok()) op_error(op, "polygon: " + root.error);
    return root.id;
  }
  const bool has_size = lua_getfield(L, spec, "size") != LUA_TNIL;
  lua_pop(L, 1);
  if (!has_size) arg_error(op, 1, "a root component needs size={w, h, d} or polygon={...}");
  const Vec3 size = field_vec3(L, spec, "size", {}, op, true);
  const Vec3 position = field_vec3(L, spec, "position", {}, op);
  if (size.x <= 0 || size.y <= 0 || size.z <= 0) arg_error(op, 1, "a box needs sizes > 0");
  return p.tree.add_root(root_frame(position, size), component_box(size));
}

// component(parent, {boundary=face}): a 2D component from a face of the parent's boundary
// (§3.4.3: "a face of a boundary ... first needs to be converted into 2D components"). Its scope
// follows comp's face convention (z = outward normal, x horizontal); the face id is kept.
ShapeId create_from_face(lua_State* L, ShapeId parent, FaceRef face) {
  const char* op = "component";
  Program& p = program(L);
  if (face.id != parent) arg_error(op, 2, "the boundary face belongs to another component");
  const std::optional<ShapeId> child = shape::add_face_child(p.tree, parent, face.face);
  if (!child) op_error(op, "face " + std::to_string(face.face) + " is degenerate");
  ++p.operations;
  return *child;
}

// component(parent, {size=, position=}): a box child in the parent's scope space (§3.4.3
// instancing). The box is clipped to the parent's scope box (exact for box parents; a general
// clip against the parent's boundary is luageom's instancing).
ShapeId create_child_box(lua_State* L, ShapeId parent, int spec) {
  const char* op = "component";
  Program& p = program(L);
  const shape::Scope& ps = p.tree[parent].scope;
  Vec3 lo = field_vec3(L, spec, "position", {}, op);
  Vec3 hi = lo + field_vec3(L, spec, "size", ps.size, op, true);
  lo = {std::max(lo.x, 0.0), std::max(lo.y, 0.0), std::max(lo.z, 0.0)};
  hi = {std::min(hi.x, ps.size.x), std::min(hi.y, ps.size.y), std::min(hi.z, ps.size.z)};
  const Vec3 size = hi - lo;
  if (size.x <= 0 || size.y <= 0 || size.z <= 0) {
    op_error(op, "the box lies outside its parent (nothing left after clipping)");
  }
  ++p.operations;
  return p.tree.add_child(parent, ps.sub(lo, size), component_box(size));
}

int lua_component(lua_State* L) {
  Program& p = program(L);
  ShapeId id = shape::kNoShape;
  int spec = 1;
  if (const auto parent = to_component(L, 1)) {
    spec = 2;
    if (!lua_istable(L, 2)) arg_error("component", 2, "expected a table {boundary=..., label=...}");
    lua_getfield(L, 2, "boundary");
    const auto face = to_face(L, -1);
    const bool has_boundary = !lua_isnil(L, -1);
    lua_pop(L, 1);
    if (has_boundary && !face) arg_error("component", 2, "field 'boundary' must be a face");
    if (face && !p.tree[*parent].mesh) op_error("component", "the parent has no boundary");
    id = face ? create_from_face(L, *parent, *face) : create_child_box(L, *parent, 2);
  } else {
    if (!lua_istable(L, 1)) {
      arg_error("component", 1, "expected a table {size=..., label=...} or a parent component");
    }
    id = create_root(L, 1);
  }
  check_component_limit(L, "component");
  apply_spec(L, spec, std::span<const ShapeId>(&id, 1), "component",
             {"size", "position", "polygon", "holes", "elevation", "boundary"});
  push_component(L, id);
  return 1;
}

// componentFromFile(name [, spec]): a root component whose boundary is an OBJ asset (y up),
// scope fitted to it (§3.6: "geometry ... from any other external source").
int lua_component_from_file(lua_State* L) {
  const char* op = "componentFromFile";
  Program& p = program(L);
  const std::string name = check_string(L, 1, op);
  if (p.assets == nullptr) op_error(op, "no asset folder was given (--assets DIR)");
  std::string error;
  const std::shared_ptr<const kernel::Mesh> asset = p.assets->find(name, error);
  if (!asset) op_error(op, error);
  const kernel::Bounds3 b = asset->bounds();
  if (b.empty()) op_error(op, "'" + name + "' has no geometry");
  kernel::Mesh mesh = *asset;
  for (Vec3& q : mesh.positions()) q -= b.min;
  Vec3 position;
  if (lua_istable(L, 2)) position = field_vec3(L, 2, "position", {}, op);
  const ShapeId id = p.tree.add_root(root_frame(position, b.size()),
                                     std::make_shared<kernel::Mesh>(std::move(mesh)));
  check_component_limit(L, op);
  if (lua_isnoneornil(L, 2)) {
    std::string label = name;
    if (const std::size_t slash = label.find_last_of('/'); slash != std::string::npos) {
      label.erase(0, slash + 1);
    }
    if (const std::size_t dot = label.rfind('.'); dot != std::string::npos && dot > 0) {
      label.erase(dot);
    }
    p.tree.add_label(id, label);
  } else {
    apply_spec(L, 2, std::span<const ShapeId>(&id, 1), op, {"position"});
  }
  ++p.operations;
  push_component(L, id);
  return 1;
}

// ---- attributes (§3.4.1) and labels

int lua_get(lua_State* L) {
  const ShapeId id = check_component(L, 1, "get");
  const std::string name = check_string(L, 2, "get");
  const shape::Value* v = program(L).tree.attribute(id, name);
  if (v == nullptr) {
    lua_pushnil(L);
  } else {
    push_value(L, *v);
  }
  return 1;
}

int lua_set(lua_State* L) {
  const std::vector<ShapeId> ids = check_components(L, 1, "set");
  const std::string name = check_string(L, 2, "set");
  if (name.empty()) arg_error("set", 2, "an attribute name cannot be empty");
  const shape::Value value = check_value(L, 3, "set");
  Program& p = program(L);
  for (ShapeId id : ids) p.tree.set_attribute(id, name, value);
  ++p.operations;
  return 0;
}

int lua_labels(lua_State* L) {
  const ShapeId id = check_component(L, 1, "labels");
  const auto labels = program(L).tree.labels(id);
  lua_createtable(L, static_cast<int>(labels.size()), 0);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    lua_pushlstring(L, labels[i].data(), labels[i].size());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int lua_has(lua_State* L) {
  const ShapeId id = check_component(L, 1, "has");
  const std::string label = check_string(L, 2, "has");
  lua_pushboolean(L, program(L).tree.has_label(id, label) ? 1 : 0);
  return 1;
}

int lua_roots(lua_State* L) {
  return push_components(L, program(L).tree.roots());
}

// setFaceId(c, selector, name): tags the faces of c's boundary matching the face query (e.g.
// "FRONT", "SIDE") with face id `name`; faces made from them later keep it (§3.1.1).
int lua_set_face_id(lua_State* L) {
  const char* op = "setFaceId";
  Program& p = program(L);
  const std::vector<ShapeId> ids = check_components(L, 1, op);
  const std::string query = check_string(L, 2, op);
  const std::string name = check_string(L, 3, op);
  base::Result<QueryExpr> expr = QueryExpr::parse_faces(query, "query");
  if (!expr) arg_error(op, 2, expr.diagnostics().front().message);
  const std::uint32_t face_id = name.empty() ? 0 : p.tree.face_id(name);
  std::size_t tagged = 0;
  for (ShapeId id : ids) {
    shape::Shape& s = p.tree[id];
    if (!s.mesh) continue;
    auto mesh = std::make_shared<kernel::Mesh>(*s.mesh);
    for (std::size_t f = 0; f < mesh->face_count(); ++f) {
      const std::string_view current = p.tree.face_name(mesh->tag(f).face_id);
      if (!expr->matches_face(kernel::face_normal(*mesh, f), current)) continue;
      mesh->tag(f).face_id = face_id;
      ++tagged;
    }
    s.mesh = std::move(mesh);
  }
  ++p.operations;
  lua_pushinteger(L, static_cast<lua_Integer>(tagged));
  return 1;
}

// ---- component fields (c.id, c.size, ...; anything else is an attribute)

int component_index(lua_State* L) {
  Program& p = program(L);
  const ShapeId id = check_component(L, 1, "index");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("index", 2, "component fields are strings");
  const std::string key = lua_tostring(L, 2);
  const shape::Shape& s = p.tree[id];
  if (key == "id") {
    lua_pushinteger(L, id);
  } else if (key == "parent") {
    if (s.parent == shape::kNoShape) {
      lua_pushnil(L);
    } else {
      push_component(L, s.parent);
    }
  } else if (key == "children") {
    push_components(L, s.children);
  } else if (key == "labels") {
    return lua_labels(L);
  } else if (key == "size") {
    push_vec3(L, s.scope.size);
  } else if (key == "origin") {
    push_vec3(L, s.scope.origin);
  } else if (key == "center") {
    push_vec3(L, s.scope.center());
  } else if (key == "active") {
    lua_pushboolean(L, s.active ? 1 : 0);
  } else if (key == "flat") {
    lua_pushboolean(L, s.is_flat() ? 1 : 0);
  } else if (key == "area") {
    lua_pushnumber(L, s.outline ? kernel::area(*s.outline)
                      : s.mesh  ? kernel::surface_area(*s.mesh)
                                : 0.0);
  } else if (key == "volume") {
    lua_pushnumber(L, s.mesh && !s.is_flat() ? kernel::volume(*s.mesh) : 0.0);
  } else if (key == "faces") {
    lua_pushinteger(L, s.mesh ? static_cast<lua_Integer>(s.mesh->face_count()) : 0);
  } else if (key == "has" || key == "get" || key == "set") {
    lua_getglobal(L, "insula");
    lua_getfield(L, -1, key.c_str());
  } else if (const shape::Value* v = p.tree.attribute(id, key)) {
    push_value(L, *v);
  } else {
    lua_pushnil(L);
  }
  return 1;
}

constexpr const char* kReadOnly[] = {"id",     "parent", "children", "labels", "size",
                                     "origin", "center", "active",   "flat",   "area",
                                     "volume", "faces",  "has",      "get",    "set"};

int component_newindex(lua_State* L) {
  const ShapeId id = check_component(L, 1, "set");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("set", 2, "attribute names are strings");
  const std::string key = lua_tostring(L, 2);
  for (const char* name : kReadOnly) {
    if (key == name) op_error("set", "field '" + key + "' is read-only (use set(c, name, v))");
  }
  Program& p = program(L);
  p.tree.set_attribute(id, key, check_value(L, 3, "set"));
  ++p.operations;
  return 0;
}

int component_tostring(lua_State* L) {
  const ShapeId id = check_component(L, 1, "tostring");
  const std::string text = describe_component(program(L).tree, id);
  lua_pushlstring(L, text.data(), text.size());
  return 1;
}

int component_eq(lua_State* L) {
  const auto a = to_component(L, 1);
  const auto b = to_component(L, 2);
  lua_pushboolean(L, a && b && *a == *b ? 1 : 0);
  return 1;
}

// ---- faces

int face_index(lua_State* L) {
  const auto face = to_face(L, 1);
  if (!face) arg_error("index", 1, "expected a face");
  Program& p = program(L);
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("index", 2, "face fields are strings");
  const std::string key = lua_tostring(L, 2);
  const shape::Shape& s = p.tree[face->id];
  const kernel::Mesh& mesh = *s.mesh;
  if (key == "component") {
    push_component(L, face->id);
  } else if (key == "index") {
    lua_pushinteger(L, face->face + 1);
  } else if (key == "id") {
    const std::string_view name = p.tree.face_name(mesh.tag(face->face).face_id);
    if (name.empty()) {
      lua_pushnil(L);
    } else {
      lua_pushlstring(L, name.data(), name.size());
    }
  } else if (key == "normal") {
    push_vec3(L, s.scope.direction_to_world(kernel::face_normal(mesh, face->face)));
  } else if (key == "area") {
    lua_pushnumber(L, kernel::face_area(mesh, face->face));
  } else if (key == "center") {
    Vec3 c;
    const auto loop = mesh.face(face->face);
    for (std::uint32_t v : loop) c += mesh.position(v);
    push_vec3(L, s.scope.to_world(c / static_cast<double>(loop.size())));
  } else {
    lua_pushnil(L);
  }
  return 1;
}

int face_tostring(lua_State* L) {
  const auto face = to_face(L, 1);
  if (!face) arg_error("tostring", 1, "expected a face");
  lua_pushfstring(L, "face %d of component %d", static_cast<int>(face->face + 1),
                  static_cast<int>(face->id));
  return 1;
}

void set_metatable(lua_State* L, const char* name,
                   std::initializer_list<std::pair<const char*, lua_CFunction>> methods) {
  luaL_newmetatable(L, name);
  for (const auto& [key, fn] : methods) {
    lua_pushcfunction(L, fn);
    lua_setfield(L, -2, key);
  }
  lua_pushliteral(L, "locked");
  lua_setfield(L, -2, "__metatable");
  lua_pop(L, 1);
}

}  // namespace

void push_face(lua_State* L, FaceRef face) {
  auto* ref = static_cast<FaceRef*>(lua_newuserdatauv(L, sizeof(FaceRef), 0));
  *ref = face;
  luaL_setmetatable(L, kFaceMeta);
}

std::optional<FaceRef> to_face(lua_State* L, int arg) {
  const auto* ref = static_cast<const FaceRef*>(luaL_testudata(L, arg, kFaceMeta));
  if (ref == nullptr) return std::nullopt;
  return *ref;
}

void register_component_bindings(Api& api) {
  lua_State* L = api.state();
  set_metatable(L, kComponentMeta,
                {{"__index", protect<component_index>},
                 {"__newindex", protect<component_newindex>},
                 {"__tostring", protect<component_tostring>},
                 {"__eq", component_eq}});
  set_metatable(L, kFaceMeta,
                {{"__index", protect<face_index>}, {"__tostring", protect<face_tostring>}});
  api.function("component", protect<lua_component>,
               "component{size=, position=, label=...} | component{polygon=, holes=, "
               "elevation=} | component(parent, {boundary=face | size=, position=, ...})");
  api.function("componentFromFile", protect<lua_component_from_file>,
               "componentFromFile(name [, {position=, label=...}]): a root from an OBJ asset");
  api.function("get", protect<lua_get>, "get(c, name): the attribute c sees (inherited)");
  api.function("set", protect<lua_set>, "set(c or list, name, value): sets an attribute");
  api.function("labels", protect<lua_labels>, "labels(c): c's labels");
  api.function("has", protect<lua_has>, "has(c, label): whether c carries the label");
  api.function("roots", protect<lua_roots>, "roots(): every root component");
  api.function("setFaceId", protect<lua_set_face_id>,
               "setFaceId(c, facequery, name): tags the matching faces with a face id");
}

}  // namespace insula::lua
