// Operations run through the shape registry (shape::registry() on a one-shape tree): extrude,
// scale, center, i, roofs, offset and every registry operation CGA reaches under its own name.
// Their arguments are bound by the registry's declarations (operations.h), so nothing here
// knows an operation's parameters.
#include <algorithm>
#include <bit>
#include <cctype>
#include <unordered_map>

#include "lang/cga/derive_engine.h"
#include "shape/ops.h"
#include "shape/shape_tree.h"

namespace insula::lang::cga::detail {

OpOutcome Engine::run_op(const State& st, std::string_view name,
                         const std::vector<shape::ArgInput>& args, const Scope* parent) {
  if (name == "offset") {
    if (std::optional<OpOutcome> inset = inset_rectangle(st, args)) return std::move(*inset);
  }
  OpOutcome out;
  const Materialized m = materialize(out_.geometry[st.geometry], st.scope.size);
  out.parent_mesh = m.mesh;
  // Seeded from the shape, so an operation that draws random numbers (scatter) differs from
  // shape to shape and repeats with the derivation's seed.
  shape::ShapeTree tree(st.seed);
  shape::ShapeId id;
  if (parent != nullptr) {
    id = tree.add_child(tree.add_root(*parent), st.scope, m.mesh, m.outline);
  } else {
    id = tree.add_root(st.scope, m.mesh, m.outline);
  }
  // State the operation keeps in attributes (texture projections, uv sets) goes in from the
  // shape's attribute chain and comes back onto each child's.
  const shape::Operation* op = shape::registry().find(name);
  const bool stateful = op != nullptr && !op->state.empty();
  std::vector<shape::Value> before;
  if (stateful) {
    for (const Value& v : state_values(st)) before.push_back(to_shape(v));
    for (std::size_t k = 0; k < before.size(); ++k) {
      if (!shape::is_null(before[k])) {
        tree.set_attribute(id, program_.attrs[program_.state_attrs[k]].name, before[k]);
      }
    }
  }
  const shape::OpResult r = shape::registry().run(tree, id, name, args, context_);
  if (!r.ok()) {
    out.error = r.error;
    return out;
  }
  out.warning = r.warning;
  for (std::size_t k = 0; k < r.children.size(); ++k) {
    const shape::Shape& s = tree[r.children[k]];
    State c = st;
    c.scope = s.scope;
    const bool share = options_.share_inserts && name == "insert" && s.mesh && !s.outline;
    c.geometry = add_mesh(share ? inserted_.share(s.mesh) : s.mesh, s.outline, s.scope.size);
    for (std::size_t a = 0; stateful && a < before.size(); ++a) {
      const std::uint32_t attr = program_.state_attrs[a];
      const shape::Value* v = tree.attribute(r.children[k], program_.attrs[attr].name);
      if (v != nullptr && *v != before[a]) {
        out_.attr_nodes.push_back({c.attrs, attr, from_shape(*v)});
        c.attrs = static_cast<std::uint32_t>(out_.attr_nodes.size() - 1);
      }
    }
    out.children.push_back(c);
    out.pieces.push_back(r.pieces[k]);
  }
  return out;
}

namespace {

// The box of a flat shape's outline when it is an axis-aligned rectangle.
std::optional<kernel::Bounds2> rectangle_box(const Geometry& g, Vec3 size) {
  if (g.kind == Geometry::Kind::kRect) {  // rectangle_outline(size.x, size.y)
    if (!(size.x > 0 && size.y > 0)) return std::nullopt;
    return kernel::Bounds2{{0, 0}, {size.x, size.y}};
  }
  if (g.kind == Geometry::Kind::kMesh && g.outline) return shape::as_rectangle(*g.outline);
  return std::nullopt;
}

}  // namespace

std::optional<OpOutcome> Engine::inset_rectangle(const State& st,
                                                 const std::vector<shape::ArgInput>& args) {
  const std::optional<shape::OffsetRequest> request = shape::offset_request(args);
  if (!request) return std::nullopt;
  const double distance = request->distance;
  // The pieces kept (0 inside, 1 border): [first, end).
  const std::uint32_t first = request->part == shape::OffsetPart::kBorder ? 1 : 0;
  const std::uint32_t end = request->part == shape::OffsetPart::kInside ? 1 : 2;
  const Geometry& g = out_.geometry[st.geometry];
  const std::optional<kernel::Bounds2> box = rectangle_box(g, st.scope.size);
  if (!box || !shape::is_rectangle_inset(*box, distance)) return std::nullopt;
  const FaceTag tag = g.tag;  // the first face's, as the registry's offset takes it
  OpOutcome out;
  for (std::uint32_t piece = first; piece < end; ++piece) {
    const InsetPiece& made = inset_piece(*box, distance, tag, piece);
    State c = st;
    c.scope = st.scope.sub(made.offset, made.size);
    c.geometry = made.geometry;
    out.children.push_back(c);
    out.pieces.push_back(piece);
  }
  return out;
}

const Engine::InsetPiece& Engine::inset_piece(const kernel::Bounds2& box, double distance,
                                              const FaceTag& tag, std::uint32_t piece) {
  const InsetKey key{std::bit_cast<std::uint64_t>(box.min.x),
                     std::bit_cast<std::uint64_t>(box.min.y),
                     std::bit_cast<std::uint64_t>(box.max.x),
                     std::bit_cast<std::uint64_t>(box.max.y),
                     std::bit_cast<std::uint64_t>(distance),
                     tag_key(tag),
                     piece};
  auto [it, added] = insets_.try_emplace(key);
  if (added) {
    const InsetShape& made = inset_shape(key, box, distance, tag, piece);
    it->second = {add_mesh(made.mesh, made.outline, made.size), made.offset, made.size};
  }
  return it->second;
}

const Engine::InsetShape& Engine::inset_shape(const InsetKey& key, const kernel::Bounds2& box,
                                              double distance, const FaceTag& tag,
                                              std::uint32_t piece) {
  // The piece is a function of the key alone, and most lots' windows have one of a few sizes:
  // made once per thread rather than once per lot (the frame's triangulation is most of a
  // window's inset). Lots share the meshes only to read them. Bounded: a city of windows of
  // ever new sizes starts over now and then.
  constexpr std::size_t kMostShapes = 4096;
  thread_local std::unordered_map<InsetKey, InsetShape, InsetKeyHash> made;
  if (const auto it = made.find(key); it != made.end()) return it->second;
  if (made.size() >= kMostShapes) made.clear();
  shape::FlatRegion region =
      shape::flat_region(shape::rectangle_inset_piece(box, -distance, piece));
  auto outline = std::make_shared<const kernel::Polygon>(std::move(region.outline));
  std::shared_ptr<const Mesh> mesh = shape::flat_mesh(*outline, tag);
  return made
      .try_emplace(key, InsetShape{std::move(mesh), std::move(outline), region.offset, region.size})
      .first->second;
}

std::vector<Value> Engine::state_values(const State& st) const {
  std::vector<Value> values(program_.state_attrs.size());
  std::vector<bool> found(values.size(), false);
  for (std::uint32_t n = st.attrs; n != 0; n = out_.attr_nodes[n].parent) {
    const AttrNode& node = out_.attr_nodes[n];
    const auto it = std::find(program_.state_attrs.begin(), program_.state_attrs.end(), node.attr);
    if (it == program_.state_attrs.end()) continue;
    const auto k = static_cast<std::size_t>(it - program_.state_attrs.begin());
    if (!found[k]) values[k] = node.value, found[k] = true;  // the nearest wins
  }
  return values;
}

std::vector<shape::ArgInput> Engine::registry_args(const CItem& c, State& st) {
  std::vector<shape::ArgInput> out = c.info->fixed;
  std::size_t next_size = 0;
  for (std::size_t i = 0; i < c.args.size(); ++i) {
    const shape::ParamDecl* p = c.info->param_of(i);
    if (p == nullptr) continue;
    switch (p->type) {
      case shape::ParamType::kNumber:
      case shape::ParamType::kInteger:
        out.push_back({p->name, number(c.args[i], st)});
        break;
      case shape::ParamType::kBool:
        out.push_back({p->name, as_bool(eval(c.args[i], st), program_.nodes[c.args[i]].range)});
        break;
      case shape::ParamType::kString:
        out.push_back({p->name, as_text(eval(c.args[i], st))});
        break;
      case shape::ParamType::kEnum: {
        // Choices are lower case; CGA writes them in either case (center("XZ")).
        std::string text = as_text(eval(c.args[i], st));
        for (char& ch : text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        out.push_back({p->name, std::move(text)});
        break;
      }
      case shape::ParamType::kSize:
        out.push_back({p->name, size_of(c.sizes[next_size++], st)});
        break;
      case shape::ParamType::kSizeList: {
        std::vector<SizeSpec> sizes;
        while (next_size < c.sizes.size()) sizes.push_back(size_of(c.sizes[next_size++], st));
        out.push_back({p->name, std::move(sizes)});
        return out;
      }
    }
  }
  return out;
}

OpOutcome Engine::run_registry(const CItem& c, State& st) {
  // The operation's shape sits in the one the rule rewrites (center() centres on it).
  std::vector<shape::ArgInput> args = registry_args(c, st);
  const std::string& op = c.info->registry_op;
  if (!program_.cityengine) return run_op(st, op, args, &rule_scope_);
  if (op == "extrude") return extrude_behind(st, args);
  if (lot_axes(st)) to_lot_axes(op, args);
  if (op == "scale") return scale_mirrored(st, args);
  OpOutcome o = run_op(st, op, args, &rule_scope_);
  if (op == "alignScopeToGeometry") {  // yUp names a flat shape's normal y, as on a lot
    bool y_up = true;
    for (const shape::ArgInput& a : args) {
      if (a.name == "up") y_up = std::get<std::string>(a.value) != "zup";
    }
    for (State& child : o.children) child.lot_axes = y_up;
  }
  return o;
}

// CityEngine's s() with a negative size mirrors the shape along that axis: the registry's scale
// to the size's magnitude, its mirror, and the scope moved back by that size, so the geometry
// lies on the negative side of the scope's origin as in CityEngine.
OpOutcome Engine::scale_mirrored(const State& st, std::vector<shape::ArgInput>& args) {
  std::vector<shape::ArgInput> mirror;
  Vec3 back{};
  for (shape::ArgInput& a : args) {
    auto* size = std::get_if<SizeSpec>(&a.value);
    const bool negative = size != nullptr && size->value < 0;
    if (negative) size->value = -size->value;
    mirror.push_back({a.name, negative});
  }
  OpOutcome o = run_op(st, "scale", args, &rule_scope_);
  if (!o.error.empty() || o.children.size() != 1) return o;
  bool any = false;
  for (const shape::ArgInput& m : mirror) any = any || std::get<bool>(m.value);
  if (!any) return o;
  const State scaled = o.children.front();
  OpOutcome m = run_op(scaled, "mirror", mirror, &rule_scope_);
  if (!m.error.empty() || m.children.size() != 1) return m;
  for (const shape::ArgInput& a : mirror) {
    if (!std::get<bool>(a.value)) continue;
    const double s = a.name == "x"   ? scaled.scope.size.x
                     : a.name == "y" ? scaled.scope.size.y
                                     : scaled.scope.size.z;
    (a.name == "x" ? back.x : a.name == "y" ? back.y : back.z) = -s;
  }
  State& child = m.children.front();
  child.scope.origin = child.scope.to_world(back);
  m.warning = o.warning.empty() ? m.warning : o.warning;
  return m;
}

void Engine::to_lot_axes(std::string_view op, std::vector<shape::ArgInput>& args) {
  if (op == "insertAlongUV") {  // scope.y (the default) is a lot's normal: Insula's scope z
    const auto given = std::find_if(args.begin(), args.end(), [](const shape::ArgInput& a) {
      return a.name == "heightDirection";
    });
    if (given == args.end()) args.push_back({"heightDirection", std::string("scope.z")});
    if (given != args.end() && std::get<std::string>(given->value) == "scope.y") {
      given->value = std::string("scope.z");
    }
    return;
  }
  const bool moves = op == "translate";
  const bool sizes = op == "scale" || op == "mirror";
  for (const shape::ArgInput& a : args) {  // translate in the world or object frame: no change
    if (moves && a.name == "frame" && std::get<std::string>(a.value) != "scope") return;
  }
  for (shape::ArgInput& a : args) {
    if (op == "center" && a.name == "axes") {
      std::string& axes = std::get<std::string>(a.value);
      for (char& ch : axes) ch = ch == 'y' ? 'z' : ch == 'z' ? 'y' : ch;
      std::sort(axes.begin(), axes.end());
    } else if ((moves || sizes) && a.name == "y") {
      a.name = "z";
    } else if ((moves || sizes) && a.name == "z") {
      a.name = "y";  // CityEngine's z is Insula's −y: a move along it turns round
      if (moves) a.value = -std::get<double>(a.value);
    }
  }
}

// CityEngine's extrude(-d) makes the prism behind the face: the registry's extrude of d, moved
// back by d along the extrusion (the child's scope y).
OpOutcome Engine::extrude_behind(const State& st, std::vector<shape::ArgInput>& args) {
  double* height = nullptr;
  for (shape::ArgInput& a : args) {
    if (a.name == "height") height = std::get_if<double>(&a.value);
  }
  if (height == nullptr || !(*height < 0)) return run_op(st, "extrude", args, &rule_scope_);
  const double depth = -*height;
  *height = depth;
  OpOutcome o = run_op(st, "extrude", args, &rule_scope_);
  for (State& child : o.children) child.scope.origin = child.scope.to_world({0, -depth, 0});
  return o;
}

bool Engine::replace(const CItem& c, const std::vector<CItem>& items, std::size_t i, State& st,
                     std::vector<State>& stack) {
  const OpOutcome o = run_registry(c, st);
  if (!check(c, o)) return true;  // the shape stays as it was
  if (o.children.size() == 1) {
    st = o.children.front();  // a copy of st with the new scope and geometry
    touch(st);
    return true;
  }
  // Several results (an offset into separate regions): the rest of the successor runs on each.
  for (std::size_t k = 0; k < o.children.size(); ++k) {
    State child =
        child_of(st, o.children[k].scope, o.children[k].geometry, static_cast<std::uint32_t>(k),
                 static_cast<std::uint32_t>(o.children.size()));
    child.modified = true;
    // An offset's pieces remember which they are (comp's `inside` / `border` read it).
    if (c.info->selectors_are_pieces && o.pieces[k] < c.info->selectors.size()) {
      child.selector = &c.info->selectors[o.pieces[k]];
    }
    std::vector<State> fork_stack = stack;
    run_items(items, i + 1, child, fork_stack);
    if (!child.consumed) terminal(child, rule_->predecessor);
  }
  st.consumed = true;
  return false;
}

// An unkeyed branch takes every child; a keyed one (offset's inside, border) the children of the
// piece its selector names.
void Engine::block_operation(const CItem& c, State& st) {
  const OpOutcome o = run_registry(c, st);
  if (!check(c, o)) {
    terminal(st, rule_->predecessor);
    return;
  }
  const std::vector<std::string>& pieces = c.info->selectors;
  const auto total = static_cast<std::uint32_t>(o.children.size());
  for (std::uint32_t k = 0; k < total; ++k) {
    const CBranch* target = nullptr;
    for (const CBranch& b : c.branches) {
      const bool match =
          !b.has_key || (c.info->selectors_are_pieces && o.pieces[k] < pieces.size() &&
                         b.selector == pieces[o.pieces[k]]);
      if (match) {
        target = &b;
        break;
      }
    }
    if (target == nullptr) continue;
    State piece = child_of(st, o.children[k].scope, o.children[k].geometry, k, total);
    run_branch(*target, piece);
  }
}

void Engine::insert_shape(const CItem& c, State& st) {
  OpOutcome o = run_op(st, c.info->registry_op, registry_args(c, st));
  count_shape(rule_->predecessor);
  State shape = st;
  if (o.error.empty() && o.children.size() == 1) {
    shape.scope = o.children.front().scope;
    shape.geometry = o.children.front().geometry;
  } else {
    warn(c, o.error + "; the shape keeps its own geometry");
  }
  terminal(shape, rule_->predecessor);
  st.consumed = true;
}

}  // namespace insula::lang::cga::detail
