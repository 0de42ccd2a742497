// The operations whose pieces go to keyed successors: split and repeat (seed 004 "Basic Split
// Rule", "Repeat Rule"; CityEngine's split with repeat patterns), comp (seed 004 "Component Split
// Rule"; CityEngine selectors) and setback. Boxes, rectangles and pure scopes split by scope math
// (shape/ops_fast.h, the cores of shape::split); every other geometry through the registry.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "lang/cga/derive_engine.h"
#include "shape/ops.h"
#include "shape/query.h"

namespace insula::lang::cga::detail {

namespace {

shape::FaceSelector face_selector(std::string_view name) {
  return shape::face_selector_named(name).value_or(shape::FaceSelector::kAll);
}

std::string_view axis_name(Axis a) {
  return a == Axis::kX ? "x" : a == Axis::kY ? "y" : "z";
}

}  // namespace

template <typename Visit>
std::string Engine::for_each_piece(State& st, Axis axis, std::span<const SizeSpec> sizes,
                                   std::vector<shape::Piece>& pieces, Visit&& visit) {
  const double total = shape::component(st.scope.size, axis);
  if (!(total > 0)) return "the scope has size 0 along the split axis";
  const Geometry& g = out_.geometry[st.geometry];
  const bool flat = g.flat();
  const bool fast = g.kind != Geometry::Kind::kMesh || (flat ? g.rect_like : g.box_like);
  if (!fast) {
    std::vector<shape::ArgInput> a{{"axis", std::string(axis_name(axis))},
                                   {"sizes", std::vector<SizeSpec>(sizes.begin(), sizes.end())}};
    OpOutcome o = run_op(st, "split", a);
    if (!o.error.empty()) return o.error;
    const auto n = static_cast<std::uint32_t>(o.children.size());
    for (std::uint32_t k = 0; k < n; ++k) {
      State piece = child_of(st, o.children[k].scope, o.children[k].geometry, k, n);
      visit(piece, o.pieces[k]);
    }
    return {};
  }
  shape::resolve_sizes_into(total, sizes, pieces);
  const Geometry::Kind kind = g.kind;  // copies: interning below may grow out_.geometry
  const std::array<FaceTag, 6> tags = g.tags;
  const auto n = static_cast<std::uint32_t>(pieces.size());
  const std::uint32_t rect = flat && n > 0 ? intern_rect(g.tag) : 0;  // every piece's when flat
  for (std::uint32_t k = 0; k < n; ++k) {
    std::uint32_t geometry = 0;
    if (flat) {
      geometry = rect;
    } else if (kind != Geometry::Kind::kNone) {
      geometry = intern_box(shape::split_box_tags(tags, axis, pieces[k], total));
    }
    State piece = child_of(st, shape::split_piece_scope(st.scope, axis, pieces[k]), geometry, k, n);
    visit(piece, pieces[k].entry);
  }
  return {};
}

double Engine::nominal(const CSize& s, State& st, double total) {
  const SizeSpec v = size_of(s, st);
  return v.mode == SizeMode::kRelative ? v.value * total : v.value;
}

double Engine::pattern_length(const std::vector<CBranch>& pattern, State& st, double total) {
  double sum = 0;
  for (const CBranch& b : pattern) {
    sum += b.repeat ? pattern_length(b.pattern, st, total) : nominal(b.size, st, total);
  }
  return sum;
}

void Engine::append_pattern(const std::vector<CBranch>& pattern, State& st,
                            std::vector<SizeSpec>& sizes, std::vector<const CBranch*>& targets) {
  for (const CBranch& b : pattern) {
    if (b.repeat) {
      append_pattern(b.pattern, st, sizes, targets);  // a pattern inside a pattern: once
      continue;
    }
    sizes.push_back(size_of(b.size, st));
    targets.push_back(&b);
  }
}

void Engine::keyed_sizes(const CItem& c, State& st, double total, std::vector<SizeSpec>& sizes,
                         std::vector<const CBranch*>& targets) {
  double fixed = 0;
  std::size_t repeats = 0;
  for (const CBranch& b : c.branches) {
    if (b.repeat) {
      ++repeats;
    } else {
      fixed += nominal(b.size, st, total);
    }
  }
  const double share =
      repeats > 0 ? std::max(0.0, total - fixed) / static_cast<double>(repeats) : 0;
  for (const CBranch& b : c.branches) {
    if (!b.repeat) {
      sizes.push_back(size_of(b.size, st));
      targets.push_back(&b);
      continue;
    }
    const double length = pattern_length(b.pattern, st, total);
    std::string error;
    const std::size_t n = length > 0 ? shape::repeat_count(share, length, error) : 1;
    if (n == 0) throw EvalError{b.range, "repeat pattern: " + error};
    for (std::size_t k = 0; k < n; ++k) append_pattern(b.pattern, st, sizes, targets);
  }
}

void Engine::split(const CItem& c, State& st) {
  if (c.code == OpCode::kRepeat) {
    repeat(c, st, 0);
    return;
  }
  if (c.by_area) {
    split_area(c, st);
    return;
  }
  Lease scratch(*this);
  Axis axis = c.axes.front();
  bool mirrored = false;
  if (lot_axes(st) && axis != Axis::kX &&
      !c.along_uv) {  // CityEngine's y is the lot's normal, its z is −y
    mirrored = axis == Axis::kZ;
    axis = mirrored ? Axis::kY : Axis::kZ;
  }
  const double total = shape::component(st.scope.size, axis);
  if (!c.sizes.empty()) {  // BS(axis, sizes...){ one successor per size }
    for (std::size_t k = 0; k < c.sizes.size(); ++k) {
      scratch->sizes.push_back(size_of(c.sizes[k], st));
      scratch->targets.push_back(k < c.branches.size() ? &c.branches[k] : nullptr);
    }
  } else {
    keyed_sizes(c, st, total, scratch->sizes, scratch->targets);
  }
  std::vector<std::uint32_t> order;
  if (mirrored && total > 0) order = mirror_pieces(total, scratch->sizes, scratch->targets);
  const std::vector<const CBranch*>& targets = scratch->targets;
  const std::span<const SizeSpec> sizes = scratch->sizes;
  const std::string error =
      for_each_piece(st, axis, sizes, scratch->pieces, [&](State& piece, std::uint32_t entry) {
        if (targets[entry] == nullptr) return;
        if (!order.empty()) {  // split.index and split.total count CityEngine's pieces
          piece.index = order[entry];
          piece.total = order.back();
        }
        if (c.axes.size() > 1) {
          split_cells(c, piece, sizes, 1, *targets[entry]);
        } else {
          run_branch(*targets[entry], piece);
        }
      });
  if (!error.empty()) {
    warn(c, error);
    terminal(st, rule_->predecessor);
  }
}

// CityEngine's splitArea(axis){ area : A | { ~a : B }* }: the keys are areas of the flat shape
// (repeats fit into its area), cut by the registry's splitArea.
void Engine::split_area(const CItem& c, State& st) {
  Lease scratch(*this);
  Axis axis = c.axes.front();
  if (lot_axes(st) && axis != Axis::kX) axis = axis == Axis::kZ ? Axis::kY : Axis::kZ;
  const Geometry& g = out_.geometry[st.geometry];
  const double area =
      g.kind == Geometry::Kind::kMesh && g.outline ? g.area : st.scope.size.x * st.scope.size.y;
  keyed_sizes(c, st, area, scratch->sizes, scratch->targets);
  const std::vector<shape::ArgInput> args{
      {"axis", std::string(axis_name(axis))},
      {"sizes", std::vector<SizeSpec>(scratch->sizes.begin(), scratch->sizes.end())}};
  const OpOutcome o = run_op(st, "splitArea", args);
  if (!check(c, o)) {
    terminal(st, rule_->predecessor);
    return;
  }
  const auto n = static_cast<std::uint32_t>(o.children.size());
  for (std::uint32_t k = 0; k < n; ++k) {
    const CBranch* target = scratch->targets[o.pieces[k]];
    State piece = child_of(st, o.children[k].scope, o.children[k].geometry, k, n);
    if (target != nullptr) run_branch(*target, piece);
  }
}

// The pieces resolve in CityEngine's order (the first at the scope's far side in Insula's y,
// where CityEngine's z starts) and come back as absolute sizes in Insula's order, a shortfall
// as a leading gap with no target. Returns each entry's index in CityEngine's order, and last
// the number of pieces.
std::vector<std::uint32_t> Engine::mirror_pieces(double total, std::vector<SizeSpec>& sizes,
                                                 std::vector<const CBranch*>& targets) {
  const std::vector<shape::Piece> pieces = shape::resolve_sizes(total, sizes);
  const std::vector<const CBranch*> forward = targets;
  sizes.clear();
  targets.clear();
  std::vector<std::uint32_t> order;
  double cursor = 0;
  for (std::size_t k = pieces.size(); k-- > 0;) {
    const shape::Piece& p = pieces[k];
    const double start = total - p.start - p.size;
    if (start > cursor + 1e-9) {
      sizes.push_back({start - cursor, SizeMode::kAbsolute});
      targets.push_back(nullptr);
      order.push_back(0);
    }
    sizes.push_back({p.size, SizeMode::kAbsolute});
    targets.push_back(forward[p.entry]);
    order.push_back(static_cast<std::uint32_t>(k));
    cursor = start + p.size;
  }
  order.push_back(static_cast<std::uint32_t>(pieces.size()));
  return order;
}

void Engine::split_cells(const CItem& c, State& st, std::span<const SizeSpec> sizes,
                         std::size_t axis_index, const CBranch& target) {
  Lease scratch(*this);
  const std::string error = for_each_piece(st, c.axes[axis_index], sizes, scratch->pieces,
                                           [&](State& cell, std::uint32_t) {
                                             if (axis_index + 1 < c.axes.size()) {
                                               split_cells(c, cell, sizes, axis_index + 1, target);
                                             } else {
                                               run_branch(target, cell);
                                             }
                                           });
  if (!error.empty()) {
    warn(c, error);
    terminal(st, rule_->predecessor);
  }
}

void Engine::repeat(const CItem& c, State& st, std::size_t axis_index) {
  const Axis axis = c.axes[axis_index];
  std::string error;
  const double size = size_of(c.sizes.front(), st).value;
  const std::size_t n = shape::repeat_count(shape::component(st.scope.size, axis), size, error);
  if (n > 0) {
    Lease scratch(*this);
    scratch->sizes.assign(n, SizeSpec{1, SizeMode::kFloating});
    error =
        for_each_piece(st, axis, scratch->sizes, scratch->pieces, [&](State& piece, std::uint32_t) {
          if (axis_index + 1 < c.axes.size()) {
            repeat(c, piece, axis_index + 1);
          } else if (!c.branches.empty()) {
            run_branch(c.branches.front(), piece);
          }
        });
  }
  if (!error.empty()) {
    warn(c, error);
    terminal(st, rule_->predecessor);
  }
}

const CBranch* Engine::comp_target(const CItem& c, std::uint32_t piece, std::size_t ordinal,
                                   const Mesh* parent, const std::vector<bool>* border,
                                   const std::vector<std::vector<bool>>* selected,
                                   const std::vector<std::int64_t>* computed) {
  if (!c.indices.empty()) {  // CS(type, i, j, ...){ A | B | ... }: component i -> A, ...
    for (std::size_t j = 0; j < c.indices.size() && j < c.branches.size(); ++j) {
      if (c.indices[j] == piece) return &c.branches[j];
    }
    return nullptr;
  }
  const bool faces = c.comp == CompKind::kFaces || c.comp == CompKind::kSideFaces;
  const Vec3 n = faces && parent != nullptr ? kernel::face_normal(*parent, piece) : Vec3{};
  const bool unkeyed = std::none_of(c.branches.begin(), c.branches.end(),
                                    [](const CBranch& b) { return b.has_key; });
  if (unkeyed && c.branches.size() > 1) {  // positional: the k-th component to the k-th branch
    if (c.comp == CompKind::kSideFaces && !shape::face_matches(shape::FaceSelector::kSide, n)) {
      return nullptr;
    }
    return ordinal < c.branches.size() ? &c.branches[ordinal] : nullptr;
  }
  for (const CBranch& b : c.branches) {
    if (!b.has_key) {
      if (c.comp == CompKind::kSideFaces && !shape::face_matches(shape::FaceSelector::kSide, n)) {
        continue;
      }
      return &b;
    }
    const std::size_t branch = static_cast<std::size_t>(&b - c.branches.data());
    if (b.index_expr != kNoExpr) {  // an index computed on the shape (CityEngine)
      if (computed != nullptr && (*computed)[branch] == piece) return &b;
      continue;
    }
    if (b.index >= 0) {
      if (b.index == piece) return &b;
      continue;
    }
    if (selected != nullptr && !(*selected)[branch].empty()) {  // precomputed: edges, frames
      if (piece < (*selected)[branch].size() && (*selected)[branch][piece]) return &b;
      continue;
    }
    const shape::FaceSelector selector = face_selector(b.selector);
    if (faces &&
        (selector == shape::FaceSelector::kBorder || selector == shape::FaceSelector::kInside)) {
      if (border != nullptr && piece < border->size() &&
          (*border)[piece] == (selector == shape::FaceSelector::kBorder)) {
        return &b;
      }
      continue;
    }
    if (faces && shape::face_matches(selector, n)) return &b;
  }
  return nullptr;
}

namespace {

// Per branch of a face split keyed by a world.* or object.* selector: which faces it picks.
std::vector<std::vector<bool>> frame_selections(const CItem& c, const Mesh& parent,
                                                const Scope& scope, const Scope* object) {
  std::vector<std::vector<bool>> selected(c.branches.size());
  for (std::size_t b = 0; b < c.branches.size(); ++b) {
    const std::optional<shape::FrameSelector> in_frame =
        shape::frame_selector_named(c.branches[b].selector);
    if (!in_frame) continue;
    selected[b].resize(parent.face_count());
    for (std::size_t f = 0; f < parent.face_count(); ++f) {
      const Vec3 n = scope.direction_to_world(kernel::face_normal(parent, f));
      selected[b][f] = shape::face_matches_in_frame(*in_frame, n, object);
    }
  }
  return selected;
}

// Per branch of an edge or vertex split keyed by selectors: which components it picks (the
// registry's own selection, shape/ops_comp_select.cc, on the same welded mesh).
std::vector<std::vector<bool>> edge_or_vertex_selections(const CItem& c, const Mesh& parent) {
  std::vector<std::vector<bool>> selected(c.branches.size());
  const Mesh welded = kernel::weld(parent);
  const std::vector<shape::MeshEdge> edges =
      c.comp == CompKind::kEdges ? shape::mesh_edges(welded) : std::vector<shape::MeshEdge>();
  for (std::size_t b = 0; b < c.branches.size(); ++b) {
    const CBranch& branch = c.branches[b];
    if (!branch.has_key || branch.index >= 0) continue;
    const shape::FaceSelector selector = face_selector(branch.selector);
    selected[b] = c.comp == CompKind::kEdges ? shape::select_edges(welded, edges, selector)
                                             : shape::select_vertices(welded, selector);
  }
  return selected;
}

}  // namespace

template <typename Visit>
bool Engine::for_each_component(const CItem& c, State& st, std::uint32_t& total, Visit&& visit) {
  const char* type = c.comp == CompKind::kEdges       ? "edges"
                     : c.comp == CompKind::kVertices  ? "vertices"
                     : c.comp == CompKind::kFaceEdges ? "faceedges"
                                                      : "faces";
  OpOutcome o = run_op(st, c.info->registry_op, {{"type", std::string(type)}});
  if (!check(c, o)) return false;
  total = static_cast<std::uint32_t>(o.children.size());
  // CityEngine's border / inside selectors need the faces' neighbours: computed when used.
  const bool by_border = std::any_of(c.branches.begin(), c.branches.end(), [](const CBranch& b) {
    return b.selector == "border" || b.selector == "inside";
  });
  std::vector<bool> border =
      by_border && o.parent_mesh ? shape::border_faces(*o.parent_mesh) : std::vector<bool>();
  // A piece of an offset (CityEngine keeps both in one shape; Insula forks them) is all inside or
  // all border, as its faces were in CityEngine's shape.
  if (by_border && st.selector != nullptr &&
      (*st.selector == "inside" || *st.selector == "border")) {
    border.assign(border.size(), *st.selector == "border");
  }
  const bool faces = c.comp == CompKind::kFaces || c.comp == CompKind::kSideFaces;
  std::vector<std::vector<bool>> selected;
  if (o.parent_mesh && faces) {
    selected = frame_selections(c, *o.parent_mesh, st.scope, context_.object);
  } else if (o.parent_mesh && c.comp != CompKind::kFaceEdges) {
    selected = edge_or_vertex_selections(c, *o.parent_mesh);
  }
  std::vector<std::int64_t> computed(c.branches.size(), -1);
  for (std::size_t b = 0; b < c.branches.size(); ++b) {
    if (c.branches[b].index_expr != kNoExpr) {
      computed[b] = static_cast<std::int64_t>(std::llround(number(c.branches[b].index_expr, st)));
    }
  }
  std::size_t ordinal = 0;
  for (std::uint32_t k = 0; k < total; ++k) {
    if (c.comp == CompKind::kSideFaces &&
        !shape::face_matches(shape::FaceSelector::kSide,
                             kernel::face_normal(*o.parent_mesh, o.pieces[k]))) {
      continue;
    }
    const CBranch* b =
        c.comp == CompKind::kFaceEdges
            ? face_edge_target(c, o.pieces[k], st, o.children[k].scope.z)
            : comp_target(c, o.pieces[k], ordinal++, faces ? o.parent_mesh.get() : nullptr, &border,
                          &selected, &computed);
    if (b == nullptr) continue;
    State piece = child_of(st, o.children[k].scope, o.children[k].geometry, k, total);
    piece.selector = &b->selector;
    piece.lot_axes = false;  // CityEngine's components have their normal on z, as Insula's
    visit(piece, *b, k);
  }
  return true;
}

const CBranch* Engine::face_edge_target(const CItem& c, std::uint32_t piece, const State& st,
                                        Vec3 outward) const {
  for (const CBranch& b : c.branches) {
    if (!b.has_key || b.selector == "all") return &b;
    if (b.index >= 0 ? b.index == piece : edge_selected(b.selector, st, outward)) return &b;
  }
  return nullptr;
}

void Engine::comp(const CItem& c, State& st) {
  std::uint32_t total = 0;
  if (!for_each_component(c, st, total, [&](State& piece, const CBranch& b, std::uint32_t) {
        run_branch(b, piece);
      })) {
    terminal(st, rule_->predecessor);
  }
}

// One value per component; `sel = value` evaluates once, on the first component it takes; the
// components no branch takes get the type's default (docs/cga-cityengine.md, "Arrays").
Value Engine::comp_function(std::uint32_t index, Range range) {
  const CItem& c = program_.comp_functions[index];
  State* const caller = cur_;
  const std::span<const Value> caller_frame = frame;
  State st = *caller;  // a copy: the components' seeds do not move the shape's own
  std::uint32_t total = 0;
  std::vector<std::optional<shape::Value>> values;
  std::map<const CBranch*, shape::Value> merged;
  std::optional<ElementType> type;
  const bool ok =
      for_each_component(c, st, total, [&](State& piece, const CBranch& b, std::uint32_t k) {
        shape::Value v;
        if (auto it = merged.find(&b); it != merged.end()) {
          v = it->second;
        } else {
          cur_ = &piece;
          frame = caller_frame;  // the values read the caller's parameters
          const Value raw = evaluate(program_, b.condition, *this);
          v = to_shape(raw);
          const ElementType* t =
              std::holds_alternative<ArrayPtr>(raw) ? nullptr : element_type_of(v);
          if (t == nullptr || (type && *type != *t)) {
            throw EvalError{
                program_.nodes[b.condition].range,
                "the values of comp() must all be floats, bools or strings of one type, "
                "found a " +
                    std::string(type_name(raw))};
          }
          type = *t;
          if (b.merged) merged.emplace(&b, v);
        }
        values.resize(total);
        values[k] = std::move(v);
      });
  cur_ = caller;
  frame = caller_frame;
  if (!ok) throw EvalError{range, "comp(): the shape has no such components"};
  std::vector<shape::Value> items;
  items.reserve(total);
  const ElementType element = type.value_or(ElementType::kFloat);
  for (std::uint32_t k = 0; k < total; ++k) {
    items.push_back(k < values.size() && values[k] ? *values[k] : default_element(element));
  }
  return make_row(element, std::move(items));
}

bool Engine::edge_selected(const std::string& selector, const State& st, Vec3 outward) const {
  // CityEngine 2012's street selectors: the street side is street.front without street data.
  if (selector == "streetSide") return edge_selected("street.front", st, outward);
  if (selector == "noStreetSide") return !edge_selected("street.front", st, outward);
  if (selector.starts_with("uv.")) {
    // The uv side the edge faces most: left / right against / along u, bottom / top along v
    // (uv set 0; a shape without it has no such edges).
    const std::optional<shape::UvMap> map = uv_map(st, 0);
    if (!map) return false;
    const double u = dot(map->du, outward), v = dot(map->dv, outward);
    const std::string side = selector.substr(3);
    const bool along_u = std::fabs(u) >= std::fabs(v);
    return (side == "left" && along_u && u < 0) || (side == "right" && along_u && u > 0) ||
           (side == "bottom" && !along_u && v < 0) || (side == "top" && !along_u && v > 0);
  }
  if (selector.starts_with("world.")) {
    // The compass side the edge faces most: x east, y north (world.side: any of them).
    const std::string side = selector.substr(6);
    if (side == "side") return std::fabs(outward.z) < 1 - 1e-9;
    const bool along_x = std::fabs(outward.x) >= std::fabs(outward.y);
    return (side == "east" && along_x && outward.x > 0) ||
           (side == "west" && along_x && outward.x < 0) ||
           (side == "north" && !along_x && outward.y > 0) ||
           (side == "south" && !along_x && outward.y < 0);
  }
  std::string side = selector;
  const Scope* axes = &st.scope;
  // street.* falls back to object.* without the lot's streetWidth (CityEngine does the same
  // without that attribute map); object.* classifies in the lot's own scope.
  if (side.rfind("street.", 0) == 0 || side.rfind("object.", 0) == 0) {
    side = side.substr(side.find('.') + 1);
    axes = &start_state_.scope;
  }
  const Vec3 local = axes->direction_to_local(outward);
  const shape::EdgeSelector facing = shape::edge_side({local.x, local.y});
  if (side == "side") {
    return facing == shape::EdgeSelector::kLeft || facing == shape::EdgeSelector::kRight;
  }
  return (side == "front" && facing == shape::EdgeSelector::kFront) ||
         (side == "back" && facing == shape::EdgeSelector::kBack) ||
         (side == "left" && facing == shape::EdgeSelector::kLeft) ||
         (side == "right" && facing == shape::EdgeSelector::kRight);
}

void Engine::setback(const CItem& c, State& st) {
  // The distance once, on the shape the rule rewrites; each strip adds its edges.
  const Value distance = eval(c.args.front(), st);
  if (const ArrayPtr* depths = std::get_if<ArrayPtr>(&distance)) {
    setback_per_edge(c, st, depths->get(), 0);
    return;
  }
  const double depth = as_number(distance, program_.nodes[c.args.front()].range);
  // world.*, object.* and the street side keys pick edges by their world or object direction:
  // edge by edge.
  if (std::any_of(c.branches.begin(), c.branches.end(), [](const CBranch& b) {
        return b.selector.starts_with("world.") || b.selector.starts_with("object.") ||
               b.selector.starts_with("uv.") || b.selector == "streetSide" ||
               b.selector == "noStreetSide";
      })) {
    const bool by_index = std::any_of(c.branches.begin(), c.branches.end(), [](const CBranch& b) {
      return b.index >= 0 || b.index_expr != kNoExpr;
    });
    if (!by_index) return setback_in_turn(c, st, depth);
    setback_per_edge(c, st, nullptr, depth);
    return;
  }
  std::vector<shape::ArgInput> args = c.info->fixed;
  args.push_back({"distance", depth});
  args.push_back({"edges", std::string()});
  const CBranch* remainder = nullptr;
  for (const CBranch& b : c.branches) {
    if (b.selector == "remainder") remainder = &b;
  }
  State rest = st;
  bool cut = false;
  for (const CBranch& b : c.branches) {
    if (b.selector == "remainder") continue;
    args.back().value = b.selector == "street" || b.selector.empty() ? "front" : b.selector;
    OpOutcome o = run_op(rest, c.info->registry_op, args);
    if (!check(c, o)) continue;
    const auto total = static_cast<std::uint32_t>(o.children.size());
    std::vector<State> rests;
    for (std::uint32_t k = 0; k < total; ++k) {
      State piece = child_of(st, o.children[k].scope, o.children[k].geometry, k, total);
      if (o.pieces[k] == 0) {
        run_branch(b, piece);
      } else {
        rests.push_back(piece);
      }
    }
    cut = true;
    if (rests.empty()) return;  // the strips took everything
    rest = rests.front();
    // A remainder in several parts: the extra parts go to the remainder successor as they are.
    for (std::size_t k = 1; k < rests.size(); ++k) {
      if (remainder != nullptr) run_branch(*remainder, rests[k]);
    }
  }
  if (remainder == nullptr) return;
  State piece = cut ? rest : child_of(st, rest.scope, rest.geometry, 0, 1);
  run_branch(*remainder, piece);
}

namespace {

struct WorldEdge {
  Vec3 a, b;
};

// The outline's edges in setback's order (outer ring, then holes) in world space.
std::vector<WorldEdge> world_edges(const kernel::Polygon& outline, const shape::Scope& scope) {
  std::vector<WorldEdge> out;
  const auto ring_edges = [&](const kernel::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const kernel::Vec2 p = ring[i], q = ring[(i + 1) % ring.size()];
      out.push_back({scope.to_world({p.x, p.y, 0}), scope.to_world({q.x, q.y, 0})});
    }
  };
  ring_edges(outline.outer);
  for (const kernel::Ring& hole : outline.holes) ring_edges(hole);
  return out;
}

// The index of the edge of `original` that `e` lies on (a piece of it after earlier cuts), or -1
// for an edge a cut made.
int original_edge(const WorldEdge& e, const std::vector<WorldEdge>& original, double tolerance) {
  const auto on = [&](Vec3 p, const WorldEdge& s) {
    const Vec3 d = s.b - s.a;
    const double len2 = dot(d, d);
    const double t = len2 > 0 ? std::clamp(dot(p - s.a, d) / len2, 0.0, 1.0) : 0.0;
    return kernel::length(s.a + d * t - p) <= tolerance;
  };
  for (std::size_t j = 0; j < original.size(); ++j) {
    if (on(e.a, original[j]) && on(e.b, original[j])) return static_cast<int>(j);
  }
  return -1;
}

}  // namespace

// Keys that pick edges by direction (world.*, object.*, street sides, uv.*) with one distance:
// each branch cuts its strips from what the branches before it left, so strips meeting at a
// corner do not overlap (the first branch takes the corner, as the uniform setback does); only
// edges of the original outline count, never the lines earlier cuts made.
void Engine::setback_in_turn(const CItem& c, State& st, double depth) {
  const Materialized m = materialize(out_.geometry[st.geometry], st.scope.size);
  if (!m.outline) {
    warn(c, "needs a flat shape (a footprint or a face)");
    terminal(st, rule_->predecessor);
    return;
  }
  const std::vector<WorldEdge> original = world_edges(*m.outline, st.scope);
  const double tolerance = 1e-7 * (1 + kernel::length(st.scope.size));
  std::vector<bool> taken(original.size(), false);
  std::vector<State> rests{st};
  const CBranch* remainder = nullptr;
  for (const CBranch& b : c.branches) {
    if (b.selector == "remainder") {
      remainder = &b;
      continue;
    }
    std::vector<bool> mine_taken = taken;
    std::vector<State> left;
    for (State& rest : rests) {
      const Materialized r = materialize(out_.geometry[rest.geometry], rest.scope.size);
      if (!r.outline) continue;
      const std::vector<WorldEdge> edges = world_edges(*r.outline, rest.scope);
      std::vector<SizeSpec> mine(edges.size(), SizeSpec{0, SizeMode::kAbsolute});
      bool any = false;
      for (std::size_t i = 0; i < edges.size(); ++i) {
        const int j = original_edge(edges[i], original, tolerance);
        if (j < 0 || taken[static_cast<std::size_t>(j)]) continue;
        const Vec3 d = edges[i].b - edges[i].a;
        const Vec3 outward = kernel::normalized(cross(d, rest.scope.z));
        const bool picked =
            !b.has_key || b.selector == "all" || edge_selected(b.selector, st, outward);
        if (!picked) continue;
        mine[i].value = depth;
        mine_taken[static_cast<std::size_t>(j)] = true;
        any = true;
      }
      if (!any) {
        left.push_back(rest);
        continue;
      }
      OpOutcome strips =
          run_op(rest, "setbackEdges", {{"depths", mine}, {"part", std::string("shape")}});
      if (!check(c, strips)) continue;
      const auto total = static_cast<std::uint32_t>(strips.children.size());
      for (std::uint32_t k = 0; k < total; ++k) {
        State piece = child_of(st, strips.children[k].scope, strips.children[k].geometry, k, total);
        run_branch(b, piece);
      }
      OpOutcome rest_pieces =
          run_op(rest, "setbackEdges", {{"depths", mine}, {"part", std::string("remainder")}});
      if (!check(c, rest_pieces)) continue;
      for (const State& piece : rest_pieces.children) left.push_back(piece);
    }
    taken = mine_taken;
    rests = std::move(left);
  }
  if (remainder == nullptr) return;
  const auto total = static_cast<std::uint32_t>(rests.size());
  for (std::uint32_t k = 0; k < total; ++k) {
    State piece = child_of(st, rests[k].scope, rests[k].geometry, k, total);
    run_branch(*remainder, piece);
  }
}

void Engine::setback_per_edge(const CItem& c, State& st, const Array* depths, double uniform) {
  if (depths != nullptr && depths->type != ElementType::kFloat) {
    throw EvalError{program_.nodes[c.args.front()].range,
                    "setback() takes a distance or a float[], got a " +
                        std::string(array_type_name(depths->type))};
  }
  const Geometry& g = out_.geometry[st.geometry];
  const Materialized m = materialize(g, st.scope.size);
  if (!m.outline) {
    warn(c, "needs a flat shape (a footprint or a face)");
    terminal(st, rule_->predecessor);
    return;
  }
  // The outline's edges in setback's order (outer ring, then holes) with their outward
  // directions in world space.
  std::vector<Vec3> outward;
  const auto ring_edges = [&](const kernel::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const kernel::Vec2 d = ring[(i + 1) % ring.size()] - ring[i];
      outward.push_back(st.scope.direction_to_world(kernel::normalized(Vec3{d.y, -d.x, 0})));
    }
  };
  ring_edges(m.outline->outer);
  for (const kernel::Ring& hole : m.outline->holes) ring_edges(hole);
  std::vector<bool> taken(outward.size(), false);
  std::vector<SizeSpec> all(outward.size(), SizeSpec{0, SizeMode::kAbsolute});
  const CBranch* remainder = nullptr;
  for (const CBranch& b : c.branches) {
    if (b.selector == "remainder") {
      remainder = &b;
      continue;
    }
    std::vector<SizeSpec> mine(outward.size(), SizeSpec{0, SizeMode::kAbsolute});
    const std::size_t edges =
        depths != nullptr ? std::min(outward.size(), depths->items.size()) : outward.size();
    for (std::size_t i = 0; i < edges; ++i) {
      const bool picked = !b.has_key || b.selector == "all" ||
                          (b.index >= 0 ? b.index == static_cast<std::int64_t>(i)
                                        : edge_selected(b.selector, st, outward[i]));
      if (!picked || taken[i]) continue;
      taken[i] = true;
      mine[i].value = all[i].value =
          depths != nullptr ? std::get<double>(depths->items[i]) : uniform;
    }
    OpOutcome o = run_op(st, "setbackEdges", {{"depths", mine}, {"part", std::string("shape")}});
    if (!check(c, o)) continue;
    const auto total = static_cast<std::uint32_t>(o.children.size());
    for (std::uint32_t k = 0; k < total; ++k) {
      State piece = child_of(st, o.children[k].scope, o.children[k].geometry, k, total);
      run_branch(b, piece);
    }
  }
  if (remainder == nullptr) return;
  OpOutcome o = run_op(st, "setbackEdges", {{"depths", all}, {"part", std::string("remainder")}});
  if (!check(c, o)) return;
  const auto total = static_cast<std::uint32_t>(o.children.size());
  for (std::uint32_t k = 0; k < total; ++k) {
    State piece = child_of(st, o.children[k].scope, o.children[k].geometry, k, total);
    run_branch(*remainder, piece);
  }
}

}  // namespace insula::lang::cga::detail
