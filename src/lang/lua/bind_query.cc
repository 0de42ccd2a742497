// Queries (seed 001 §3.3): components by label expression, attributes, parent(), occlusion and
// proximity, limited to source components and their children when sources are given; faces of
// boundaries (fquery); the occlusion fraction and proximity as plain functions.
#include <algorithm>

#include "lang/lua/bindings_internal.h"
#include "shape/query.h"
#include "shape/query_expr.h"

namespace insula::lua {

using shape::QueryExpr;
using shape::ShapeId;

namespace {

// A parsed query string, or an error naming the column inside it.
QueryExpr parse_query(lua_State* L, int arg, const char* op, bool faces) {
  const std::string text = check_string(L, arg, op);
  base::Result<QueryExpr> expr =
      faces ? QueryExpr::parse_faces(text, "query") : QueryExpr::parse(text, "query");
  if (!expr) {
    const base::Diagnostic& d = expr.diagnostics().front();
    op_error(op, d.message + " (column " + std::to_string(d.span.column) + " of \"" + text + "\")");
  }
  return std::move(expr.value());
}

// The candidates of a query: every component, or the sources and their descendants (§3.3).
std::vector<ShapeId> candidates(const shape::ShapeTree& tree,
                                const std::optional<std::vector<ShapeId>>& sources) {
  std::vector<ShapeId> out;
  if (!sources) {
    out.resize(tree.size());
    for (ShapeId i = 0; i < tree.size(); ++i) out[i] = i;
    return out;
  }
  std::vector<bool> seen(tree.size(), false);
  for (ShapeId source : *sources) {
    if (seen[source]) continue;
    for (ShapeId id : tree.subtree(source)) seen[id] = true;
  }
  for (ShapeId i = 0; i < tree.size(); ++i) {
    if (seen[i]) out.push_back(i);
  }
  return out;
}

bool is_string(lua_State* L, int arg) {
  return lua_type(L, arg) == LUA_TSTRING;
}

// query(expr [, sources]) or query(sources, expr): a set of components in creation order.
int lua_query(lua_State* L) {
  const char* op = "query";
  int expr_arg = 1;
  int sources_arg = 2;
  if (!is_string(L, 1)) std::swap(expr_arg, sources_arg);
  const QueryExpr expr = parse_query(L, expr_arg, op, false);
  std::optional<std::vector<ShapeId>> sources;
  if (!lua_isnoneornil(L, sources_arg)) sources = check_components(L, sources_arg, op);
  const shape::ShapeTree& tree = program(L).tree;
  QueryExpr::Evaluator eval(expr, tree);
  std::vector<ShapeId> out;
  for (ShapeId id : candidates(tree, sources)) {
    if (eval.matches(id)) out.push_back(id);
  }
  return push_components(L, out);
}

// fquery(c or list, expr): the faces of the boundaries matching a face query (SIDE, TOP, BOTTOM,
// ..., face id names), in component then face order.
int lua_fquery(lua_State* L) {
  const char* op = "fquery";
  const std::vector<ShapeId> ids = check_components(L, 1, op);
  const QueryExpr expr = parse_query(L, 2, op, true);
  const shape::ShapeTree& tree = program(L).tree;
  std::vector<FaceRef> faces;
  for (ShapeId id : ids) {
    const shape::Shape& s = tree[id];
    if (!s.mesh) continue;
    for (std::size_t f = 0; f < s.mesh->face_count(); ++f) {
      const std::string_view name = tree.face_name(s.mesh->tag(f).face_id);
      if (expr.matches_face(kernel::face_normal(*s.mesh, f), name)) {
        faces.push_back({id, static_cast<std::uint32_t>(f)});
      }
    }
  }
  return push_array(L, faces, push_face);
}

// Components given as a list / set, or as a query string over the whole tree.
std::vector<ShapeId> components_or_query(lua_State* L, int arg, const char* op) {
  if (!is_string(L, arg)) return check_components(L, arg, op);
  const QueryExpr expr = parse_query(L, arg, op, false);
  const shape::ShapeTree& tree = program(L).tree;
  QueryExpr::Evaluator eval(expr, tree);
  std::vector<ShapeId> out;
  for (ShapeId id = 0; id < tree.size(); ++id) {
    if (eval.matches(id)) out.push_back(id);
  }
  return out;
}

// occlusion(c, others): the fraction of c covered by the projection of `others` (§3.3).
int lua_occlusion(lua_State* L) {
  const char* op = "occlusion";
  const ShapeId id = check_component(L, 1, op);
  const std::vector<ShapeId> others = components_or_query(L, 2, op);
  lua_pushnumber(L, shape::occlusion(program(L).tree, id, others));
  return 1;
}

// proximity(c, distance [, candidates]): components whose scope centre is within `distance`
// meters of c's, nearest first (§3.3).
int lua_proximity(lua_State* L) {
  const char* op = "proximity";
  const ShapeId id = check_component(L, 1, op);
  const double distance = check_number(L, 2, op);
  if (distance < 0) arg_error(op, 2, "the distance must be >= 0");
  const shape::ShapeTree& tree = program(L).tree;
  std::vector<ShapeId> pool;
  if (lua_isnoneornil(L, 3)) {
    pool = candidates(tree, std::nullopt);
  } else {
    pool = components_or_query(L, 3, op);
  }
  const std::vector<ShapeId> near = shape::within_distance(tree, id, distance, pool);
  // Nearest first: not id order, so the result is a plain list (still iterable).
  return push_components(L, near);
}

}  // namespace

void register_query_bindings(Api& api) {
  api.function("query", protect<lua_query>,
               "query(expr [, sources]) / query(sources, expr): matching components");
  api.function("fquery", protect<lua_fquery>,
               "fquery(c or list, expr): faces matching SIDE/TOP/BOTTOM/... or face ids");
  api.function("occlusion", protect<lua_occlusion>,
               "occlusion(c, others or query): covered fraction of c in [0, 1]");
  api.function("proximity", protect<lua_proximity>,
               "proximity(c, distance [, candidates or query]): nearby components, nearest first");
}

}  // namespace insula::lua
