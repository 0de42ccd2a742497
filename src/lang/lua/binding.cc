// The binding helpers of binding.h: handles, argument readers, specs, errors and registration.
#include "lang/lua/binding.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "lang/lua/bindings_internal.h"

#if __has_include("lang/lua/bind_geometry.cc")
#define INSULA_LUA_HAS_GEOMETRY 1
#endif

namespace insula::lua {

using shape::ShapeId;

Program& program(lua_State* L) {
  return **static_cast<Program**>(lua_getextraspace(L));
}

// ---- errors

void arg_error(std::string_view operation, int arg, std::string_view message) {
  std::string text = "argument ";
  text += std::to_string(arg);
  text += ": ";
  text.append(message);
  throw Error(std::string(operation), std::move(text));
}

void op_error(std::string_view operation, std::string_view message) {
  throw Error(std::string(operation), std::string(message));
}

void check_op(lua_State* L, std::string_view operation, const shape::OpResult& result) {
  Program& p = program(L);
  ++p.operations;
  if (!result.ok()) op_error(operation, result.error);
  check_component_limit(L, operation);
}

void check_component_limit(lua_State* L, std::string_view operation) {
  Program& p = program(L);
  if (p.tree.size() > p.max_components) {
    p.stopped = true;  // the located message is kept by call_body
    op_error(operation, "component limit of " + std::to_string(p.max_components) + " reached");
  }
}

namespace {

// "file:line: " of the innermost Lua frame that called into C (luaL_where, skipping C frames).
void push_where(lua_State* L) {
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar) != 0; ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline > 0) {
      lua_pushfstring(L, "%s:%d: ", ar.short_src, ar.currentline);
      return;
    }
  }
  lua_pushliteral(L, "");
}

}  // namespace

bool call_body(lua_State* L, Body body, int& results) noexcept {
  std::string operation;
  std::string message;
  try {
    results = body(L);
    return true;
  } catch (const Error& e) {
    operation = e.operation();
    message = e.what();
  } catch (const std::bad_alloc&) {
    message = "not enough memory";
  } catch (const std::exception& e) {
    message = std::string("internal error: ") + e.what();
  }
  if (!operation.empty()) message = "in " + operation + ": " + message;
  push_where(L);
  lua_pushlstring(L, message.data(), message.size());
  lua_concat(L, 2);
  Program& p = program(L);
  if (p.stopped && p.stop_message.empty()) p.stop_message = lua_tostring(L, -1);
  return false;
}

// ---- components

namespace {

constexpr const char* kComponentCache = "insula.component_cache";
constexpr const char* kSetMeta = "insula.Set";

struct ComponentRef {
  ShapeId id;
};

const char* type_name(lua_State* L, int arg) {
  if (luaL_testudata(L, arg, kComponentMeta) != nullptr) return "component";
  if (luaL_testudata(L, arg, kFaceMeta) != nullptr) return "face";
  if (luaL_testudata(L, arg, kRegionMeta) != nullptr) return "region";
  return luaL_typename(L, arg);
}

}  // namespace

void push_component(lua_State* L, ShapeId id) {
  // One userdata per component (weak cache), so components compare and hash by identity.
  lua_getfield(L, LUA_REGISTRYINDEX, kComponentCache);
  if (lua_rawgeti(L, -1, static_cast<lua_Integer>(id)) == LUA_TUSERDATA) {
    lua_remove(L, -2);
    return;
  }
  lua_pop(L, 1);
  auto* ref = static_cast<ComponentRef*>(lua_newuserdatauv(L, sizeof(ComponentRef), 0));
  ref->id = id;
  luaL_setmetatable(L, kComponentMeta);
  lua_pushvalue(L, -1);
  lua_rawseti(L, -3, static_cast<lua_Integer>(id));
  lua_remove(L, -2);
}

std::optional<ShapeId> to_component(lua_State* L, int arg) {
  const auto* ref = static_cast<const ComponentRef*>(luaL_testudata(L, arg, kComponentMeta));
  if (ref == nullptr || !program(L).tree.contains(ref->id)) return std::nullopt;
  return ref->id;
}

ShapeId check_component(lua_State* L, int arg, std::string_view operation) {
  if (auto id = to_component(L, arg)) return *id;
  arg_error(operation, arg, std::string("expected a component, got ") + type_name(L, arg));
}

std::vector<ShapeId> check_components(lua_State* L, int arg, std::string_view operation) {
  if (auto id = to_component(L, arg)) return {*id};
  if (!lua_istable(L, arg)) {
    arg_error(
        operation, arg,
        std::string("expected a component or a list of components, got ") + type_name(L, arg));
  }
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, arg));
  std::vector<ShapeId> ids;
  ids.reserve(static_cast<std::size_t>(n));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, arg, i);
    const auto id = to_component(L, -1);
    const char* got = type_name(L, -1);
    lua_pop(L, 1);
    if (!id) {
      arg_error(operation, arg,
                "entry " + std::to_string(i) + " is not a component (got " + got + ")");
    }
    ids.push_back(*id);
  }
  return ids;
}

int push_components(lua_State* L, std::span<const ShapeId> ids) {
  lua_createtable(L, static_cast<int>(ids.size()), 0);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    push_component(L, ids[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  luaL_setmetatable(L, kSetMeta);
  return 1;
}

// ---- arguments

double check_number(lua_State* L, int arg, std::string_view operation) {
  int ok = 0;
  const double d = lua_tonumberx(L, arg, &ok);
  if (ok == 0 || lua_type(L, arg) != LUA_TNUMBER) {
    arg_error(operation, arg, std::string("expected a number, got ") + type_name(L, arg));
  }
  if (!std::isfinite(d)) arg_error(operation, arg, "expected a finite number");
  return d;
}

double opt_number(lua_State* L, int arg, double fallback, std::string_view operation) {
  return lua_isnoneornil(L, arg) ? fallback : check_number(L, arg, operation);
}

std::int64_t check_integer(lua_State* L, int arg, std::string_view operation) {
  const double d = check_number(L, arg, operation);
  if (d != std::floor(d) || std::fabs(d) > 9e15) {
    arg_error(operation, arg, "expected a whole number");
  }
  return static_cast<std::int64_t>(d);
}

std::string check_string(lua_State* L, int arg, std::string_view operation) {
  if (lua_type(L, arg) != LUA_TSTRING) {
    arg_error(operation, arg, std::string("expected a string, got ") + type_name(L, arg));
  }
  std::size_t length = 0;
  const char* text = lua_tolstring(L, arg, &length);
  return std::string(text, length);
}

std::optional<std::string> opt_string(lua_State* L, int arg, std::string_view operation) {
  if (lua_isnoneornil(L, arg)) return std::nullopt;
  return check_string(L, arg, operation);
}

kernel::Vec3 check_vec3(lua_State* L, int arg, std::string_view operation, bool partial) {
  if (!lua_istable(L, arg)) {
    arg_error(operation, arg, std::string("expected {x, y, z}, got ") + type_name(L, arg));
  }
  double v[3] = {0, 0, 0};
  static constexpr const char* kNames[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    int type = lua_rawgeti(L, arg, i + 1);
    if (type == LUA_TNIL) {
      lua_pop(L, 1);
      type = lua_getfield(L, arg, kNames[i]);
    }
    if (type == LUA_TNIL && partial) {
      lua_pop(L, 1);
      continue;
    }
    int ok = 0;
    v[i] = lua_tonumberx(L, -1, &ok);
    lua_pop(L, 1);
    if (ok == 0 || type != LUA_TNUMBER || !std::isfinite(v[i])) {
      arg_error(operation, arg,
                std::string("expected {x, y, z}: entry ") + kNames[i] + " is not a finite number");
    }
  }
  return {v[0], v[1], v[2]};
}

std::vector<double> check_numbers(lua_State* L, int arg, std::string_view operation) {
  if (!lua_istable(L, arg)) {
    arg_error(operation, arg, std::string("expected a list of numbers, got ") + type_name(L, arg));
  }
  std::vector<double> out;
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, arg));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, arg, i);
    int ok = 0;
    const double d = lua_tonumberx(L, -1, &ok);
    const bool number = lua_type(L, -1) == LUA_TNUMBER;
    lua_pop(L, 1);
    if (ok == 0 || !number || !std::isfinite(d)) {
      arg_error(operation, arg, "entry " + std::to_string(i) + " is not a finite number");
    }
    out.push_back(d);
  }
  return out;
}

shape::Axis check_axis(lua_State* L, int arg, std::string_view operation) {
  // "x" "y" "z" (any case) or 0 1 2 / "0" "1" "2" (seed 001 Fig. 3 writes split(c, "2", ...)).
  std::string text;
  if (lua_type(L, arg) == LUA_TNUMBER) {
    text = std::to_string(check_integer(L, arg, operation));
  } else if (lua_type(L, arg) == LUA_TSTRING) {
    text = check_string(L, arg, operation);
  } else {
    arg_error(operation, arg,
              std::string("expected an axis (x, y or z), got ") + type_name(L, arg));
  }
  if (text == "x" || text == "X" || text == "0") return shape::Axis::kX;
  if (text == "y" || text == "Y" || text == "1") return shape::Axis::kY;
  if (text == "z" || text == "Z" || text == "2") return shape::Axis::kZ;
  arg_error(operation, arg, "expected an axis (x, y or z), got '" + text + "'");
}

namespace {

bool parse_size_text(const std::string& text, shape::SizeSpec& out) {
  const std::optional<shape::SizeSpec> size = shape::parse_size(text);
  if (size) out = *size;
  return size.has_value() && size->value >= 0;
}

}  // namespace

shape::SizeSpec check_size(lua_State* L, int arg, std::string_view operation) {
  shape::SizeSpec size;
  if (lua_type(L, arg) == LUA_TNUMBER) {
    size.value = check_number(L, arg, operation);
    if (size.value < 0) arg_error(operation, arg, "a size must be >= 0");
    return size;
  }
  if (lua_type(L, arg) == LUA_TSTRING) {
    const std::string text = check_string(L, arg, operation);
    if (!parse_size_text(text, size)) {
      arg_error(operation, arg, "expected a size such as 2, '0.5 or ~1, got '" + text + "'");
    }
    return size;
  }
  if (!lua_istable(L, arg)) {
    arg_error(operation, arg, std::string("expected a size, got ") + type_name(L, arg));
  }
  const std::optional<double> abs = field_number(L, arg, "abs", operation);
  const std::optional<double> rel = field_number(L, arg, "rel", operation);
  const std::optional<double> frac = field_number(L, arg, "frac", operation);
  const int given = int{abs.has_value()} + int{rel.has_value()} + int{frac.has_value()};
  if (given != 1) arg_error(operation, arg, "a piece needs exactly one of abs, rel or frac");
  // seed 001 §3.4.3: "absolute sizes are first deducted ..., the remaining space is divided
  // amongst all of the relative ones, weighted": `rel` is a floating (weighted) size.
  if (abs) size = {*abs, shape::SizeMode::kAbsolute};
  if (rel) size = {*rel, shape::SizeMode::kFloating};
  if (frac) size = {*frac, shape::SizeMode::kRelative};
  if (size.value < 0) arg_error(operation, arg, "a size must be >= 0");
  return size;
}

std::optional<double> field_number(lua_State* L, int arg, const char* key,
                                   std::string_view operation) {
  const int type = lua_getfield(L, arg, key);
  int ok = 0;
  const double d = lua_tonumberx(L, -1, &ok);
  lua_pop(L, 1);
  if (type == LUA_TNIL) return std::nullopt;
  if (type != LUA_TNUMBER || ok == 0 || !std::isfinite(d)) {
    arg_error(operation, arg, std::string("field '") + key + "' must be a finite number");
  }
  return d;
}

std::optional<std::string> field_string(lua_State* L, int arg, const char* key,
                                        std::string_view operation) {
  const int type = lua_getfield(L, arg, key);
  if (type == LUA_TNIL) {
    lua_pop(L, 1);
    return std::nullopt;
  }
  if (type != LUA_TSTRING) {
    lua_pop(L, 1);
    arg_error(operation, arg, std::string("field '") + key + "' must be a string");
  }
  std::size_t length = 0;
  const char* text = lua_tolstring(L, -1, &length);
  std::string out(text, length);
  lua_pop(L, 1);
  return out;
}

std::optional<bool> field_bool(lua_State* L, int arg, const char* key, std::string_view operation) {
  const int type = lua_getfield(L, arg, key);
  const bool value = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  if (type == LUA_TNIL) return std::nullopt;
  if (type != LUA_TBOOLEAN) {
    arg_error(operation, arg, std::string("field '") + key + "' must be true or false");
  }
  return value;
}

// ---- values and specs

shape::Value check_value(lua_State* L, int arg, std::string_view operation) {
  switch (lua_type(L, arg)) {
    case LUA_TNIL:
    case LUA_TNONE:
      return std::monostate{};
    case LUA_TBOOLEAN:
      return lua_toboolean(L, arg) != 0;
    case LUA_TNUMBER:
      return check_number(L, arg, operation);
    case LUA_TSTRING:
      return check_string(L, arg, operation);
    default:
      arg_error(
          operation, arg,
          std::string("an attribute is a boolean, number or string, got ") + type_name(L, arg));
  }
}

void push_value(lua_State* L, const shape::Value& value) {
  if (const auto* b = std::get_if<bool>(&value)) {
    lua_pushboolean(L, *b ? 1 : 0);
  } else if (const auto* d = std::get_if<double>(&value)) {
    // Whole numbers come back as Lua integers, so "level " .. c.level reads "level 2".
    if (*d == std::floor(*d) && std::fabs(*d) < 9007199254740992.0) {
      lua_pushinteger(L, static_cast<lua_Integer>(*d));
    } else {
      lua_pushnumber(L, *d);
    }
  } else if (const auto* s = std::get_if<std::string>(&value)) {
    lua_pushlstring(L, s->data(), s->size());
  } else {
    lua_pushnil(L);
  }
}

Spec check_spec(lua_State* L, int arg, std::string_view operation,
                std::initializer_list<std::string_view> reserved) {
  Spec spec;
  if (lua_isnoneornil(L, arg)) return spec;
  if (!lua_istable(L, arg)) {
    arg_error(operation, arg,
              std::string("expected a table such as {label=\"room\"}, got ") + type_name(L, arg));
  }
  arg = lua_absindex(L, arg);
  if (auto label = field_string(L, arg, "label", operation)) spec.labels.push_back(*label);
  if (lua_getfield(L, arg, "labels") != LUA_TNIL) {
    const int t = lua_gettop(L);
    if (!lua_istable(L, t)) {
      lua_pop(L, 1);
      arg_error(operation, arg, "field 'labels' must be a list of strings");
    }
    const auto n = static_cast<lua_Integer>(lua_rawlen(L, t));
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, t, i);
      const bool ok = lua_type(L, -1) == LUA_TSTRING;
      if (ok) spec.labels.emplace_back(lua_tostring(L, -1));
      lua_pop(L, 1);
      if (!ok) {
        lua_pop(L, 1);
        arg_error(operation, arg, "field 'labels' must be a list of strings");
      }
    }
  }
  lua_pop(L, 1);
  // Other string keys are attributes (seed 001 Fig. 3: { label="iwall", color=i }), in a
  // deterministic (sorted) order.
  lua_pushnil(L);
  while (lua_next(L, arg) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      const std::string key = lua_tostring(L, -2);
      const bool skip = key == "label" || key == "labels" ||
                        std::find(reserved.begin(), reserved.end(), key) != reserved.end();
      const int type = lua_type(L, -1);
      if (!skip && type != LUA_TBOOLEAN && type != LUA_TNUMBER && type != LUA_TSTRING) {
        lua_pop(L, 2);
        arg_error(operation, arg,
                  "field '" + key + "' is not an attribute value (boolean, number or string)");
      }
      if (!skip) spec.attributes.emplace_back(key, check_value(L, lua_gettop(L), operation));
    }
    lua_pop(L, 1);
  }
  std::sort(spec.attributes.begin(), spec.attributes.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  return spec;
}

void apply_spec(shape::ShapeTree& tree, const Spec& spec, std::span<const ShapeId> ids) {
  for (ShapeId id : ids) {
    for (const std::string& label : spec.labels) tree.add_label(id, label);
    for (const auto& [name, value] : spec.attributes) tree.set_attribute(id, name, value);
  }
}

void apply_spec(lua_State* L, int arg, std::span<const ShapeId> ids, std::string_view operation,
                std::initializer_list<std::string_view> reserved) {
  apply_spec(program(L).tree, check_spec(L, arg, operation, reserved), ids);
}

// ---- registration

void Api::function(const char* name, lua_CFunction fn, const char* doc) {
  lua_getglobal(L_, "insula");
  lua_pushcfunction(L_, fn);
  lua_setfield(L_, -2, name);
  lua_getfield(L_, -1, "docs");
  lua_pushstring(L_, doc);
  lua_setfield(L_, -2, name);
  lua_pop(L_, 2);
  lua_pushcfunction(L_, fn);
  lua_setglobal(L_, name);
}

void Api::constant(const char* name, const char* value) {
  lua_getglobal(L_, "insula");
  lua_pushstring(L_, value);
  lua_setfield(L_, -2, name);
  lua_pop(L_, 1);
  lua_pushstring(L_, value);
  lua_setglobal(L_, name);
}

void register_core_bindings(Api& api) {
  register_component_bindings(api);
  register_query_bindings(api);
  register_ops_bindings(api);
  register_region_bindings(api);
}

// ---- sets: arrays of components that are also iterators (seed 001 Fig. 5: `for c in query(..)`)

namespace {

// __call(set, _, previous): the component after `previous` (nil: the first). Query results are
// in id order, so the previous one is found by binary search; a reordered table falls back to a
// linear scan.
int set_next(lua_State* L) {
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, 1));
  lua_Integer next = 1;
  if (!lua_isnoneornil(L, 3)) {
    const auto prev = to_component(L, 3);
    next = n + 1;
    if (prev) {
      auto id_at = [&](lua_Integer i) {
        lua_rawgeti(L, 1, i);
        const auto id = to_component(L, -1);
        lua_pop(L, 1);
        return id ? static_cast<std::int64_t>(*id) : -1;
      };
      lua_Integer lo = 1;
      lua_Integer hi = n;
      while (lo <= hi) {
        const lua_Integer mid = lo + (hi - lo) / 2;
        const std::int64_t id = id_at(mid);
        if (id == *prev) {
          next = mid + 1;
          break;
        }
        if (id < *prev) {
          lo = mid + 1;
        } else {
          hi = mid - 1;
        }
      }
      if (lo > hi) {
        for (lua_Integer i = 1; i <= n; ++i) {
          if (id_at(i) == *prev) {
            next = i + 1;
            break;
          }
        }
      }
    }
  }
  if (next > n) return 0;
  lua_rawgeti(L, 1, next);
  return 1;
}

}  // namespace

void open_bindings(lua_State* L) {
  lua_newtable(L);  // weak-valued cache id -> component userdata
  lua_newtable(L);
  lua_pushliteral(L, "v");
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
  lua_setfield(L, LUA_REGISTRYINDEX, kComponentCache);

  luaL_newmetatable(L, kSetMeta);
  lua_pushcfunction(L, set_next);
  lua_setfield(L, -2, "__call");
  lua_pushliteral(L, "set");
  lua_setfield(L, -2, "__name");
  lua_pop(L, 1);

  lua_newtable(L);  // insula
  lua_newtable(L);
  lua_setfield(L, -2, "docs");
  lua_setglobal(L, "insula");

  Api api(L);
  register_core_bindings(api);
#ifdef INSULA_LUA_HAS_GEOMETRY
  register_geometry_bindings(api);
#endif
}

void print_line(lua_State* L, const char* text, std::size_t length) {
  Program& p = program(L);
  if (p.print) p.print(std::string(text, length));
}

}  // namespace insula::lua
