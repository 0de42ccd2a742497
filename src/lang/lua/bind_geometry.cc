// Lua bindings of seed 001's geometry operations (shape/component_ops.h): slices with left-over
// policies and constraints (§3.4.3, §3.5), booleans of components (§3.4.3), joint extrusion
// (Fig. 6), instancing with clipping, doors and windows (§4.4), solid geometry (§3.6) and
// furniture on regions (§4.5). The element half (openings, solids, placement) is in
// bind_geometry_elements.cc. Reference: docs/lua-geometry.md.
#include <cstring>

#include "lang/lua/bind_geometry_internal.h"
#include "lang/lua/bindings_internal.h"
#include "shape/component_ops.h"

namespace insula::lua {

using shape::ShapeId;

namespace {

shape::LeftOver check_leftover(lua_State* L, int arg, const char* op) {
  const auto text = field_string(L, arg, "leftover", op);
  if (!text || *text == "first") return shape::LeftOver::kFirst;
  if (*text == "last") return shape::LeftOver::kLast;
  if (*text == "both") return shape::LeftOver::kBoth;
  if (*text == "spread") return shape::LeftOver::kSpread;
  arg_error(op, arg,
            "field 'leftover' must be one of first, last, both, spread; got '" + *text + "'");
}

// snap(components, distance) / repel(components, distance): a constraint value (§3.5), a table
// {constraint = "snap", distance = d, components = {...}} that slice, sliceAt and
// constrainedSplit accept (alone or in a list).
template <shape::ConstraintKind kKind>
int lua_constraint(lua_State* L) {
  const char* op = kKind == shape::ConstraintKind::kSnap ? "snap" : "repel";
  const std::vector<ShapeId> ids = check_components(L, 1, op);
  const double distance = opt_number(L, 2, 0, op);
  if (!(distance >= 0)) arg_error(op, 2, "the distance must be >= 0");
  lua_createtable(L, 0, 3);
  lua_pushstring(L, op);
  lua_setfield(L, -2, "constraint");
  lua_pushnumber(L, distance);
  lua_setfield(L, -2, "distance");
  push_components(L, ids);
  lua_setfield(L, -2, "components");
  return 1;
}

void add_constraint(lua_State* L, int t, std::vector<shape::Constraint>& out, const char* op,
                    int arg) {
  const auto kind = field_string(L, t, "constraint", op);
  if (!kind) arg_error(op, arg, "expected a constraint from snap() or repel()");
  const double distance = field_number(L, t, "distance", op).value_or(0);
  lua_getfield(L, t, "components");
  const std::vector<ShapeId> ids = check_components(L, lua_gettop(L), op);
  lua_pop(L, 1);
  const Program& p = program(L);
  for (ShapeId id : ids) {
    shape::Constraint c;
    c.kind = *kind == "snap" ? shape::ConstraintKind::kSnap : shape::ConstraintKind::kRepel;
    c.box = p.tree[id].scope;
    c.distance = distance;
    out.push_back(c);
  }
}

}  // namespace

std::vector<shape::Constraint> check_constraints(lua_State* L, int arg, const char* op) {
  std::vector<shape::Constraint> out;
  if (lua_isnoneornil(L, arg)) return out;
  if (!lua_istable(L, arg)) arg_error(op, arg, "expected a constraint or a list of constraints");
  arg = lua_absindex(L, arg);
  lua_getfield(L, arg, "constraint");
  const bool single = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (single) {
    add_constraint(L, arg, out, op, arg);
    return out;
  }
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, arg));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, arg, i);
    if (!lua_istable(L, -1))
      arg_error(op, arg, "entry " + std::to_string(i) + " is not a constraint");
    add_constraint(L, lua_gettop(L), out, op, arg);
    lua_pop(L, 1);
  }
  return out;
}

namespace {

// slice(c, axis, size [, {leftover=, constraints=, label=, ...}]) (§3.4.3 "Slicing").
int lua_slice(lua_State* L) {
  const char* op = "slice";
  const std::vector<ShapeId> targets = check_components(L, 1, op);
  const shape::Axis axis = check_axis(L, 2, op);
  const double size = check_number(L, 3, op);
  shape::LeftOver policy = shape::LeftOver::kFirst;
  std::vector<shape::Constraint> constraints;
  if (lua_istable(L, 4)) {
    policy = check_leftover(L, 4, op);
    lua_getfield(L, 4, "constraints");
    constraints = check_constraints(L, lua_gettop(L), op);
    lua_pop(L, 1);
  } else if (!lua_isnoneornil(L, 4)) {
    arg_error(op, 4, "expected a table {leftover=..., constraints=..., label=...}");
  }
  const Spec spec = check_spec(L, 4, op, {"leftover", "constraints"});
  Program& p = program(L);
  std::vector<ShapeId> created;
  for (ShapeId id : targets) {
    const shape::OpResult r = shape::slice(p.tree, id, axis, size, policy, constraints);
    check_op(L, op, r);
    apply_spec(p.tree, spec, r.children);
    created.insert(created.end(), r.children.begin(), r.children.end());
  }
  return push_components(L, created);
}

// sliceAt(c, axis, constraints [, spec]): cuts at the constraints' planes (§3.5, stairwells).
int lua_slice_at(lua_State* L) {
  const char* op = "sliceAt";
  const std::vector<ShapeId> targets = check_components(L, 1, op);
  const shape::Axis axis = check_axis(L, 2, op);
  const std::vector<shape::Constraint> constraints = check_constraints(L, 3, op);
  const Spec spec = check_spec(L, 4, op);
  Program& p = program(L);
  std::vector<ShapeId> created;
  for (ShapeId id : targets) {
    const shape::OpResult r = shape::slice_at(p.tree, id, axis, constraints);
    check_op(L, op, r);
    apply_spec(p.tree, spec, r.children);
    created.insert(created.end(), r.children.begin(), r.children.end());
  }
  return push_components(L, created);
}

// constrainedSplit(c, axis, constraints, piece...): split() with boundaries snapped or repelled.
int lua_constrained_split(lua_State* L) {
  const char* op = "constrainedSplit";
  const std::vector<ShapeId> targets = check_components(L, 1, op);
  const shape::Axis axis = check_axis(L, 2, op);
  const std::vector<shape::Constraint> constraints = check_constraints(L, 3, op);
  std::vector<shape::SizeSpec> sizes;
  std::vector<Spec> specs;
  const int top = lua_gettop(L);
  for (int arg = 4; arg <= top; ++arg) {
    sizes.push_back(check_size(L, arg, op));
    specs.push_back(lua_istable(L, arg) ? check_spec(L, arg, op, {"abs", "rel", "frac"}) : Spec{});
  }
  if (sizes.empty()) arg_error(op, 4, "a split needs at least one piece");
  Program& p = program(L);
  std::vector<ShapeId> created;
  for (ShapeId id : targets) {
    const shape::OpResult r = shape::split_constrained(p.tree, id, axis, sizes, constraints);
    check_op(L, op, r);
    for (std::size_t i = 0; i < r.children.size(); ++i) {
      apply_spec(p.tree, specs[r.pieces[i]], std::span<const ShapeId>(&r.children[i], 1));
    }
    created.insert(created.end(), r.children.begin(), r.children.end());
  }
  return push_components(L, created);
}

// union(list [, spec]) / intersection(list [, spec]): new roots (§3.4.3).
template <bool kUnion>
int lua_set_boolean(lua_State* L) {
  const char* op = kUnion ? "union" : "intersection";
  const std::vector<ShapeId> ids = check_components(L, 1, op);
  if (ids.empty()) arg_error(op, 1, "needs at least one component");
  Program& p = program(L);
  const shape::OpResult r =
      kUnion ? shape::unite_components(p.tree, ids) : shape::intersect_components(p.tree, ids);
  check_op(L, op, r);
  apply_spec(L, 2, r.children, op);
  return push_components(L, r.children);
}

// subtract(c or list, others [, spec]): children of each c (§3.4.3).
int lua_subtract(lua_State* L) {
  const char* op = "subtract";
  const std::vector<ShapeId> targets = check_components(L, 1, op);
  const std::vector<ShapeId> cutters = check_components(L, 2, op);
  const Spec spec = check_spec(L, 3, op);
  Program& p = program(L);
  std::vector<ShapeId> created;
  for (ShapeId id : targets) {
    const shape::OpResult r = shape::subtract_components(p.tree, id, cutters);
    check_op(L, op, r);
    apply_spec(p.tree, spec, r.children);
    created.insert(created.end(), r.children.begin(), r.children.end());
  }
  return push_components(L, created);
}

// extrude(c, height [, spec]) on one component with a positive height: the registry's prism
// (scope y along the normal). extrude(list or query, distance [, spec]), or a negative
// distance: joint extrusion of the set (Fig. 6; Fig. 3's inward walls).
int lua_extrude(lua_State* L) {
  const char* op = "extrude";
  const bool single = to_component(L, 1).has_value();
  const std::vector<ShapeId> ids = check_components(L, 1, op);
  const double distance = check_number(L, 2, op);
  const Spec spec = check_spec(L, 3, op);
  Program& p = program(L);
  shape::OpResult r;
  if (single && distance > 0) {
    r = shape::extrude(p.tree, ids[0], distance);
  } else {
    if (ids.empty()) return push_components(L, ids);
    r = shape::extrude_joint(p.tree, ids, distance);
  }
  check_op(L, op, r);
  apply_spec(p.tree, spec, r.children);
  return push_components(L, r.children);
}

// instance(parent, {position=, size=, clip=true, label=...}): §3.4.3 instancing with clipping.
int lua_instance(lua_State* L) {
  const char* op = "instance";
  const ShapeId parent = check_component(L, 1, op);
  if (!lua_istable(L, 2)) arg_error(op, 2, "expected a table {position=, size=, clip=, ...}");
  Program& p = program(L);
  kernel::Vec3 position;
  if (lua_getfield(L, 2, "position") != LUA_TNIL) position = check_vec3(L, lua_gettop(L), op, true);
  lua_pop(L, 1);
  kernel::Vec3 size = p.tree[parent].scope.size;
  if (lua_getfield(L, 2, "size") != LUA_TNIL) size = check_vec3(L, lua_gettop(L), op);
  lua_pop(L, 1);
  const bool clip = field_bool(L, 2, "clip", op).value_or(true);
  const shape::OpResult r = shape::instance_box(p.tree, parent, position, size, clip);
  check_op(L, op, r);
  apply_spec(L, 2, r.children, op, {"position", "size", "clip"});
  push_component(L, r.children.at(0));
  return 1;
}

}  // namespace

void register_geometry_bindings(Api& api) {
  api.function("snap", protect<lua_constraint<shape::ConstraintKind::kSnap>>,
               "snap(components, distance): boundaries within distance move onto them (§3.5)");
  api.function("repel", protect<lua_constraint<shape::ConstraintKind::kRepel>>,
               "repel(components, margin): boundaries keep margin away from them (§3.5)");
  api.function("slice", protect<lua_slice>,
               "slice(c, axis, size [, {leftover=first|last|both|spread, constraints=, label=}])");
  api.function("sliceAt", protect<lua_slice_at>,
               "sliceAt(c, axis, constraints [, spec]): cuts at the constraints' planes");
  api.function("constrainedSplit", protect<lua_constrained_split>,
               "constrainedSplit(c, axis, constraints, piece...): split with snap/repel");
  api.function("union", protect<lua_set_boolean<true>>,
               "union(list [, spec]): the union as new root component(s)");
  api.function("intersection", protect<lua_set_boolean<false>>,
               "intersection(list [, spec]): the intersection as new root component(s)");
  api.function("subtract", protect<lua_subtract>,
               "subtract(c, others [, spec]): c minus others, as children of c");
  api.function("extrude", protect<lua_extrude>,
               "extrude(c, height [, spec]) | extrude(list, distance [, spec]): joint extrusion");
  api.function("instance", protect<lua_instance>,
               "instance(parent, {position=, size=, clip=true, label=...}): a clipped child box");
  register_element_bindings(api);
}

}  // namespace insula::lua
