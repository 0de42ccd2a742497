// The API every Lua binding is written against (seed 001 §3: components, queries, operations as a
// programming language). The runtime (runtime.h) owns the lua_State and the component tree; binding
// files (bind_*.cc) add functions to the program's global namespace and to the `insula` table.
//
// Writing a binding:
//
//   int lua_subtract(lua_State* L) {               // a body: may throw, never calls lua_error
//     Program& p = program(L);
//     shape::ShapeId target = check_component(L, 1, "subtract");
//     std::vector<shape::ShapeId> cutters = check_components(L, 2, "subtract");
//     shape::OpResult r = my_subtract(p.tree, target, cutters);
//     check_op(L, "subtract", r);                  // throws "in subtract: <r.error>"
//     apply_spec(L, 3, r.children, "subtract");    // {label="room", color=1}
//     return push_components(L, r.children);       // an array of components
//   }
//   void register_geometry_bindings(Api& api) {
//     api.function("subtract", protect<lua_subtract>, "subtract(c, others, spec): ...");
//   }
//
// Error rule: a body reports failure by throwing Error (arg_error / op_error below); protect<>
// catches it after every C++ destructor has run and raises the Lua error "in <operation>:
// <message>" located at the calling Lua line, which the runtime prints as
// `file:line: error: in <operation>: <message>`. Never call lua_error / luaL_error / luaL_check*
// from a body: they longjmp over C++ destructors. The helpers below only throw.
//
// Registration: the runtime calls, in this order, register_core_bindings (luacore: components,
// attributes, queries, the registry operations) and then register_geometry_bindings (luageom,
// defined in src/lang/lua/bind_geometry.cc). The runtime calls the latter only when that file
// exists (`__has_include`), so the library links with or without it, and a direct call (not a
// static registrar) keeps the linker from dropping bind_geometry.o from the static library.
// Further bind_geometry_*.cc files are reached from register_geometry_bindings.
#pragma once

#include <lua.hpp>

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/vec.h"
#include "lang/lua/program.h"
#include "shape/operation.h"
#include "shape/rng.h"
#include "shape/shape_tree.h"
#include "shape/value.h"

namespace insula::lua {

// The program a state belongs to (stored in the state's extra space; O(1)).
Program& program(lua_State* L);

// ---- errors
// What a binding body throws. `operation` names the Lua function ("split", "query").
class Error : public std::runtime_error {
 public:
  Error(std::string operation, std::string message)
      : std::runtime_error(message), operation_(std::move(operation)) {}
  const std::string& operation() const { return operation_; }

 private:
  std::string operation_;
};
// Throws Error(operation, "argument N: message").
[[noreturn]] void arg_error(std::string_view operation, int arg, std::string_view message);
// Throws Error(operation, message).
[[noreturn]] void op_error(std::string_view operation, std::string_view message);
// Throws op_error(operation, result.error) when the operation failed; counts the operation and
// stops the program when the tree passed Limits::components.
void check_op(lua_State* L, std::string_view operation, const shape::OpResult& result);
// Stops the program (as a limit does) when the tree holds more components than the limit: every
// binding that adds shapes without an operation (component, componentFromFile) calls it.
void check_component_limit(lua_State* L, std::string_view operation);

using Body = int (*)(lua_State*);
// Runs `body`; on a thrown Error (or std::exception, reported as "internal error: ...") pushes the
// located message "file:line: in <operation>: <message>" (the calling Lua line) and returns false,
// with every C++ object of the body already destroyed.
bool call_body(lua_State* L, Body body, int& results) noexcept;
// Register protect<body>, never the body itself: the Lua error is raised here, where no C++
// frame with a destructor is left to skip.
template <Body F>
int protect(lua_State* L) {
  int results = 0;
  if (call_body(L, F, results)) return results;
  return lua_error(L);
}

// ---- components: full userdata of metatable "insula.Component" holding a ShapeId. Fields:
// c.id, c.parent, c.labels, c.size (docs/lua-api.md); any other field reads or writes the
// attribute of that name (inherited on read, seed 001 §3.1; set on the component on write).
inline constexpr const char* kComponentMeta = "insula.Component";
void push_component(lua_State* L, shape::ShapeId id);
// The component at stack index `arg` (1-based argument number in messages), or nullopt.
std::optional<shape::ShapeId> to_component(lua_State* L, int arg);
// Throws "argument N: expected a component, got <type>" otherwise.
shape::ShapeId check_component(lua_State* L, int arg, std::string_view operation);
// A component, an array table of components, or a query result: all as ids (duplicates kept in
// order). Throws on anything else (an empty table is allowed).
std::vector<shape::ShapeId> check_components(lua_State* L, int arg, std::string_view operation);
// Pushes an array table of components; returns 1 (the number of pushed values).
int push_components(lua_State* L, std::span<const shape::ShapeId> ids);

// ---- arguments (all throw arg_error on a wrong type; `arg` is a stack index >= 1)
double check_number(lua_State* L, int arg, std::string_view operation);
double opt_number(lua_State* L, int arg, double fallback, std::string_view operation);
std::int64_t check_integer(lua_State* L, int arg, std::string_view operation);
std::string check_string(lua_State* L, int arg, std::string_view operation);
std::optional<std::string> opt_string(lua_State* L, int arg, std::string_view operation);
// {x, y, z} or {x=, y=, z=} (missing entries 0 when `partial`, else an error).
kernel::Vec3 check_vec3(lua_State* L, int arg, std::string_view operation, bool partial = false);
// An array of numbers.
std::vector<double> check_numbers(lua_State* L, int arg, std::string_view operation);
// "x" / "X" / "y" / ... as a scope axis.
shape::Axis check_axis(lua_State* L, int arg, std::string_view operation);
// Split sizes: each entry a number (meters), a string "2" / "'0.5" / "~1", or a piece table with
// abs=M, rel=F (seed 001 Fig. 3: weighted share of what absolute sizes leave) or frac=F (a
// fraction of the scope size).
shape::SizeSpec check_size(lua_State* L, int arg, std::string_view operation);
// For a table at `arg`: value of field `key` (nil -> nullopt); wrong type -> arg_error.
std::optional<double> field_number(lua_State* L, int arg, const char* key,
                                   std::string_view operation);
std::optional<std::string> field_string(lua_State* L, int arg, const char* key,
                                        std::string_view operation);
std::optional<bool> field_bool(lua_State* L, int arg, const char* key, std::string_view operation);

// ---- piece specs: tables such as { label="apartment", rel=1, color=2 } (seed 001 Fig. 3).
// `label` (a string) and `labels` (an array of strings) are labels; `reserved` keys belong to
// the operation (sizes, positions, ...) and are skipped; every other string key with a boolean,
// number or string value becomes an attribute of each component. Nil or absent spec: nothing.
struct Spec {
  std::vector<std::string> labels;
  std::vector<std::pair<std::string, shape::Value>> attributes;
};
Spec check_spec(lua_State* L, int arg, std::string_view operation,
                std::initializer_list<std::string_view> reserved = {});
void apply_spec(shape::ShapeTree& tree, const Spec& spec, std::span<const shape::ShapeId> ids);
// check_spec + apply_spec.
void apply_spec(lua_State* L, int arg, std::span<const shape::ShapeId> ids,
                std::string_view operation, std::initializer_list<std::string_view> reserved = {});

// A Lua value as an attribute value (nil -> null; tables and functions -> arg_error).
shape::Value check_value(lua_State* L, int arg, std::string_view operation);
void push_value(lua_State* L, const shape::Value& value);

// ---- registration
class Api {
 public:
  explicit Api(lua_State* L) : L_(L) {}
  // Sets global `name` and insula.<name> to `fn` (a protect<...> instantiation). `doc` is the
  // one-line signature shown by insula.help(name).
  void function(const char* name, lua_CFunction fn, const char* doc);
  // A constant global (and insula.<name>), e.g. SIDE = "side".
  void constant(const char* name, const char* value);
  lua_State* state() const { return L_; }

 private:
  lua_State* L_;
};

// luacore (bind_core.cc, bind_query.cc, bind_ops.cc).
void register_core_bindings(Api& api);
// luageom (bind_geometry.cc); called only when that file exists.
void register_geometry_bindings(Api& api);

}  // namespace insula::lua
