// The shape operations of the registry (shape/operation.h) as Lua functions, plus seed 001's
// split with labelled pieces (Fig. 3). Every operation takes a component or a list of them
// (Fig. 5: "operation on all of the queried components at once") and returns the set of the
// children it created.
//
// Generic calling convention, driven by the registry's declarations:
//   op(target, arg1, arg2, ..., {name=value, pieces={spec1, spec2, ...}, label=..., attr=...})
// positional arguments follow the declaration order; a trailing table holds named arguments (its
// keys that are parameter names), per-piece specs (`pieces[i]` for piece i - 1, e.g. offset's
// inside and border) and a spec for every child (labels and attributes).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "lang/lua/bindings_internal.h"
#include "lang/lua/operations.h"
#include "shape/ops.h"

namespace insula::lua {

using shape::ArgInput;
using shape::ArgValue;
using shape::ShapeId;

namespace {

bool parse_size(const std::string& text, shape::SizeSpec& out) {
  const std::optional<shape::SizeSpec> size = shape::parse_size(text);
  if (size) out = *size;
  return size.has_value();
}

// One Lua value as the registry argument of `param`.
ArgValue to_arg(lua_State* L, int arg, const shape::ParamDecl& param, const char* op) {
  using shape::ParamType;
  switch (lua_type(L, arg)) {
    case LUA_TBOOLEAN:
      return lua_toboolean(L, arg) != 0;
    case LUA_TNUMBER:
      return check_number(L, arg, op);
    case LUA_TSTRING: {
      std::string text = check_string(L, arg, op);
      shape::SizeSpec size;
      if (param.type == ParamType::kSize && parse_size(text, size)) return size;
      return text;
    }
    case LUA_TTABLE: {
      if (param.type != ParamType::kSizeList) break;
      std::vector<shape::SizeSpec> sizes;
      const auto n = static_cast<lua_Integer>(lua_rawlen(L, arg));
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, arg, i);
        sizes.push_back(check_size(L, lua_gettop(L), op));
        lua_pop(L, 1);
      }
      return sizes;
    }
    default:
      break;
  }
  arg_error(op, arg, "parameter '" + param.name + "' cannot take a " + luaL_typename(L, arg));
}

// Registry errors read "<op>: <message>"; the Lua error already names the operation.
std::string strip_name(const std::string& error, const std::string& name) {
  const std::string prefix = name + ": ";
  return error.compare(0, prefix.size(), prefix) == 0 ? error.substr(prefix.size()) : error;
}

// Piece specs: pieces[i] applies to the children of piece i - 1.
std::vector<Spec> piece_specs(lua_State* L, int options, const char* op) {
  std::vector<Spec> specs;
  if (options == 0 || lua_getfield(L, options, "pieces") == LUA_TNIL) {
    if (options != 0) lua_pop(L, 1);
    return specs;
  }
  const int t = lua_gettop(L);
  if (!lua_istable(L, t)) arg_error(op, options, "field 'pieces' must be a list of specs");
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, t));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, t, i);
    specs.push_back(check_spec(L, lua_gettop(L), op));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return specs;
}

// Guards against operations whose piece count follows from an argument (repeat with a tiny
// size): refused before they run instead of filling memory.
void check_piece_count(lua_State* L, const shape::Operation& op, ShapeId id,
                       const std::vector<ArgInput>& inputs) {
  if (op.name != "repeat") return;
  const Program& p = program(L);
  double size = 0;
  shape::Axis axis = shape::Axis::kX;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string& name =
        inputs[i].name.empty() && i < op.params.size() ? op.params[i].name : inputs[i].name;
    if (name == "size" && std::holds_alternative<double>(inputs[i].value)) {
      size = std::get<double>(inputs[i].value);
    }
    if (name == "axis" && std::holds_alternative<std::string>(inputs[i].value)) {
      const std::string& a = std::get<std::string>(inputs[i].value);
      axis = a == "y" ? shape::Axis::kY : (a == "z" ? shape::Axis::kZ : shape::Axis::kX);
    }
  }
  if (size <= 0) return;
  const double pieces = std::floor(p.tree[id].scope.extent(axis) / size);
  if (pieces > static_cast<double>(p.max_components - std::min(p.max_components, p.tree.size()))) {
    op_error(op.name, "would create " + std::to_string(static_cast<long long>(pieces)) +
                          " components (component limit " + std::to_string(p.max_components) + ")");
  }
}

int generic_operation(lua_State* L) {
  const std::string name = lua_tostring(L, lua_upvalueindex(1));
  const shape::Operation* op = shape::registry().find(name);
  if (op == nullptr) op_error(name, "not in the operation registry");
  const char* op_name = name.c_str();
  const std::vector<ShapeId> targets = check_components(L, 1, op_name);
  std::vector<ArgInput> inputs;
  const int top = lua_gettop(L);
  int options = 0;
  for (int arg = 2; arg <= top; ++arg) {
    const std::size_t index = static_cast<std::size_t>(arg - 2);
    const bool positional_table =
        index < op->params.size() && op->params[index].type == shape::ParamType::kSizeList;
    if (lua_istable(L, arg) && !positional_table) {
      if (arg != top) arg_error(op_name, arg, "the options table must be the last argument");
      options = arg;
      break;
    }
    if (index >= op->params.size()) {
      arg_error(
          op_name, arg,
          "too many arguments (" + name + " takes " + std::to_string(op->params.size()) + ")");
    }
    inputs.push_back({"", to_arg(L, arg, op->params[index], op_name)});
  }
  std::vector<std::string_view> param_names;
  if (options != 0) {
    for (const shape::ParamDecl& param : op->params) {
      if (lua_getfield(L, options, param.name.c_str()) != LUA_TNIL) {
        inputs.push_back({param.name, to_arg(L, lua_gettop(L), param, op_name)});
      }
      lua_pop(L, 1);
    }
  }
  std::vector<Spec> pieces = piece_specs(L, options, op_name);
  Spec common;
  if (options != 0) {
    // Every key that is not a parameter name or "pieces" is a label or attribute.
    lua_newtable(L);
    const int filtered = lua_gettop(L);
    lua_pushnil(L);
    while (lua_next(L, options) != 0) {
      bool skip = lua_type(L, -2) != LUA_TSTRING;
      if (!skip) {
        const char* key = lua_tostring(L, -2);
        skip = std::strcmp(key, "pieces") == 0 ||
               std::any_of(op->params.begin(), op->params.end(),
                           [&](const shape::ParamDecl& p) { return p.name == key; });
      }
      if (skip) {
        lua_pop(L, 1);
        continue;
      }
      lua_pushvalue(L, -2);
      lua_insert(L, -2);
      lua_rawset(L, filtered);
    }
    common = check_spec(L, filtered, op_name);
    lua_pop(L, 1);
  }
  Program& p = program(L);
  shape::Context context;
  context.assets = p.assets;
  std::vector<ShapeId> created;
  for (ShapeId id : targets) {
    check_piece_count(L, *op, id, inputs);
    shape::OpResult r = shape::registry().run(p.tree, id, name, inputs, context);
    if (!r.ok()) r.error = strip_name(r.error, name);
    check_op(L, op_name, r);
    apply_spec(p.tree, common, r.children);
    for (std::size_t i = 0; i < r.children.size(); ++i) {
      if (r.pieces[i] < pieces.size()) {
        apply_spec(p.tree, pieces[r.pieces[i]], std::span<const ShapeId>(&r.children[i], 1));
      }
    }
    created.insert(created.end(), r.children.begin(), r.children.end());
  }
  return push_components(L, created);
}

// split(c, axis, piece, piece, ...) or split(c, axis, {piece, ...}): seed 001 §3.4.3 / Fig. 3.
// A piece is a size (2, "'0.5", "~1") or a table {abs=m | rel=w | frac=f, label=..., attr=...}.
// Pieces of size zero are left out (shape::resolve_sizes); each child gets its piece's spec.
int lua_split(lua_State* L) {
  const char* op = "split";
  const std::vector<ShapeId> targets = check_components(L, 1, op);
  const shape::Axis axis = check_axis(L, 2, op);
  std::vector<shape::SizeSpec> sizes;
  std::vector<Spec> specs;
  auto add_piece = [&](int index) {
    sizes.push_back(check_size(L, index, op));
    specs.push_back(lua_istable(L, index) ? check_spec(L, index, op, {"abs", "rel", "frac"})
                                          : Spec{});
  };
  const int top = lua_gettop(L);
  const bool one_list = top == 3 && lua_istable(L, 3) && lua_rawlen(L, 3) > 0;
  if (one_list) {
    const auto n = static_cast<lua_Integer>(lua_rawlen(L, 3));
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, 3, i);
      add_piece(lua_gettop(L));
      lua_pop(L, 1);
    }
  } else {
    for (int arg = 3; arg <= top; ++arg) add_piece(arg);
  }
  if (sizes.empty()) arg_error(op, 3, "split needs at least one piece");
  Program& p = program(L);
  std::vector<ShapeId> created;
  for (ShapeId id : targets) {
    shape::OpResult r = shape::split(p.tree, id, axis, sizes);
    check_op(L, op, r);
    for (std::size_t i = 0; i < r.children.size(); ++i) {
      apply_spec(p.tree, specs[r.pieces[i]], std::span<const ShapeId>(&r.children[i], 1));
    }
    created.insert(created.end(), r.children.begin(), r.children.end());
  }
  return push_components(L, created);
}

}  // namespace

void register_ops_bindings(Api& api) {
  lua_State* L = api.state();
  for (const shape::Operation& op : shape::registry().operations()) {
    if (op.name == "split") continue;  // seed 001's labelled pieces below
    // `repeat` is a Lua keyword: the function is repeatSplit (and insula["repeat"]).
    const std::string global = global_name(op.name);
    lua_getglobal(L, "insula");
    lua_pushstring(L, op.name.c_str());
    lua_pushcclosure(L, protect<generic_operation>, 1);
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, op.name.c_str());
    lua_setglobal(L, global.c_str());
    lua_getfield(L, -1, "docs");
    lua_pushstring(L, op.doc.c_str());
    lua_setfield(L, -2, op.name.c_str());
    lua_pop(L, 2);
  }
  api.function("split", protect<lua_split>,
               "split(c, axis, piece...): pieces {abs=|rel=|frac=, label=, ...} or sizes");
}

}  // namespace insula::lua
