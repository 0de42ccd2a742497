// The derivation engine's state and its interpreter (derive.h has the contract): one Engine
// derives one lot. Its methods live in files by idea: derive_engine.cc (the derivation loop,
// rule choice, the successor interpreter and CGA's own built-ins), derive_splits.cc (split,
// repeat, comp and setback: the operations whose pieces go to keyed successors) and
// derive_registry.cc (every other operation, run through the shape registry). Small methods on
// the hot path of every piece are defined here so each file inlines them.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "kernel/shared_meshes.h"
#include "lang/cga/derive.h"
#include "lang/cga/eval.h"
#include "shape/ops_fast.h"
#include "shape/rng.h"

namespace insula::lang::cga::detail {

using kernel::FaceTag;
using kernel::Mesh;
using kernel::Vec3;
using shape::Axis;
using shape::Scope;
using shape::SizeMode;
using shape::SizeSpec;

struct State;

// A pending shape (derive.h: "compact state").
struct Work {
  Work() = default;
  // Shape `shape_symbol` with `st`'s state, pending at `shape_depth` and priority level
  // `shape_level`.
  Work(const State& st, SymbolId shape_symbol, std::uint16_t shape_depth,
       std::uint16_t shape_level);

  Scope scope;
  std::uint64_t seed = 0;
  SymbolId symbol = kNoSymbol;
  std::uint32_t geometry = 0;
  std::uint32_t attrs = 0;
  std::uint32_t index = 0;                // split.index / comp.index
  std::uint32_t total = 1;                // split.total
  std::uint32_t frame = 0;                // the rule's arguments (Engine::frames_; 0: none)
  const std::string* selector = nullptr;  // comp.sel (a CBranch's selector of the program)
  std::uint16_t depth = 0;
  std::uint16_t level = 0;
  std::uint32_t lineage = 0;  // State::lineage
  bool lot_axes = false;      // State::lot_axes
};

// The current shape while a successor runs.
struct State {
  Scope scope;
  std::uint64_t seed = 0;
  std::uint32_t geometry = 0;
  std::uint32_t attrs = 0;
  std::uint32_t index = 0;
  std::uint32_t total = 1;
  std::uint32_t frame = 0;                // the arguments of the rule being applied
  const std::string* selector = nullptr;  // comp.sel
  std::uint32_t next_child = 0;           // children seeded so far (child_seed index)
  bool consumed = false;                  // replaced by a symbol, a block operation or ε
  bool modified = false;      // changed since the last `[` (a `]` then leaves it as a leaf)
  std::uint32_t lineage = 0;  // Engine::lineage_ entry (occlusion queries only; 0: untracked)
  // CityEngine names a lot's axes with y its normal, a face component's with z its normal
  // (Insula: z for both). True while a flat shape descends from the lot (or from
  // alignScopeToGeometry(yUp)) and not from comp: Engine::lot_axes() maps CityEngine's y and z.
  bool lot_axes = false;

  // A new shape from `parent` (a symbol of its successor) with its own seed, lineage and rule
  // arguments, not yet consumed or modified. Member by member, never reading the parent's
  // flags: a copy of the whole state read them in 16-byte pieces just after touch() wrote them
  // a byte each, and waited for the stores.
  static State successor(const State& parent, std::uint64_t seed, std::uint32_t lineage,
                         std::uint32_t frame) {
    State s;
    s.scope = parent.scope;
    s.seed = seed;
    s.geometry = parent.geometry;
    s.attrs = parent.attrs;
    s.index = parent.index;
    s.total = parent.total;
    s.frame = frame;
    s.selector = parent.selector;
    s.lineage = lineage;
    s.lot_axes = parent.lot_axes;
    return s;
  }
};

// Every member from its source: push_or_terminal constructs works in place, and a default
// construction first would clear the record only to overwrite it.
inline Work::Work(const State& st, SymbolId shape_symbol, std::uint16_t shape_depth,
                  std::uint16_t shape_level)
    : scope(st.scope),
      seed(st.seed),
      symbol(shape_symbol),
      geometry(st.geometry),
      attrs(st.attrs),
      index(st.index),
      total(st.total),
      frame(st.frame),
      selector(st.selector),
      depth(shape_depth),
      level(shape_level),
      lineage(st.lineage),
      lot_axes(st.lot_axes) {}

// A shape CityEngine's occlusion queries ask about: a label()led shape, or a closed leaf
// (label ""). `lineage` holds the seeds from the initial shape down to it, so that a query
// skips its own ancestors and descendants as CityEngine does.
struct Occluder {
  std::string label;
  Scope scope;
  std::uint64_t seed = 0;
  std::vector<std::uint64_t> lineage;
};

// A limit or evaluation error: ends the lot's derivation.
struct DeriveError {
  base::Diagnostic diagnostic;
};

struct Materialized {
  std::shared_ptr<const Mesh> mesh;
  std::shared_ptr<const kernel::Polygon> outline;
};

// Children of an operation run through the shape layer, as states.
struct OpOutcome {
  std::vector<State> children;
  std::vector<std::uint32_t> pieces;
  std::shared_ptr<const Mesh> parent_mesh;  // the operand's geometry (comp needs face normals)
  std::string error;
  std::string warning;
};

class Engine final : public EvalContext {
 public:
  Engine(const Program& program, const Lot& lot, std::size_t lot_index,
         const DeriveOptions& options, LotResult& out)
      : program_(program),
        lot_(lot),
        options_(options),
        out_(out),
        assets_(options.assets),
        lot_seed_(
            shape::child_seed(shape::mix64(options.seed), static_cast<std::uint32_t>(lot_index))),
        rng_(lot_seed_) {
    context_.assets = &assets_;
    keep_ = options.keep_terminals || program.uses_occlusion;
    track_lineage_ = program.uses_occlusion_queries;
    lineage_.push_back({0, 0});           // entry 0: untracked
    out_.geometry.push_back(Geometry{});  // handle 0: none
    out_.attr_nodes.push_back(AttrNode{});
    out_.symbol_counts.assign(program.symbols.size(), 0);
    pending_.resize(std::max<std::size_t>(1, program.priorities.size()));
    values_.resize(program.attrs.size());
    lot_conditions_.assign(program.rules.size(), -1);
    status_.resize(program.attrs.size(), 0);
  }

  void run();
  // CityEngine's two passes (derive.cc): the first pass's occluders answer the second's queries;
  // without them every query is false, as in CityEngine's first pass.
  void set_occluders(const std::vector<Occluder>* occluders) { occluders_ = occluders; }
  std::vector<Occluder> take_occluders() { return std::move(made_occluders_); }

  // ---- EvalContext
  Value attribute(std::uint32_t attr, Range range) override;

  double shape_attribute(ShapeAttr a) override;
  Vec3 object_position(const State& s) const;
  std::string comp_selector() override {
    return cur_ != nullptr && cur_->selector != nullptr ? *cur_->selector : std::string();
  }
  double geometry(shape::GeometryQuery query, std::uint8_t option, double tolerance) override;

  std::string occlusion(const std::string& /*what*/, Range /*range*/) override;

  shape::Rng& rng() override { return rng_; }

  Value file_function(Function f, const std::vector<Value>& args, Range range) override;

  Value comp_function(std::uint32_t index, Range range) override;

  void print(Range range, const std::string& text) override;
  double geo_coord(const std::string& which, Range range) override;
  std::string images_by_ratio(const std::string& list, const std::string& axes, Range range);
  std::vector<std::string> assets_sorted(std::vector<std::string> assets, const std::string& axes,
                                         bool ratio, double max_error, Range range);
  double uv_extent(std::uint8_t which, int set, bool unit_space) override;
  void warning(Range range, std::string message) override {
    ++warnings_[{range.begin, std::move(message)}];
  }

 private:
  static kernel::Bounds3 bounds(const Scope& s) {
    kernel::Bounds3 b;
    for (const Vec3& p : s.corners()) b.add(p);
    return b;
  }

  // ---- attributes of the lot: --set > lot property > default (evaluated once per lot)
  Value lot_value(std::uint32_t attr, Range range);
  const shape::Value* lot_property(const std::string& name) const;

  // ---- geometry handles
  std::uint32_t add_geometry(Geometry g) {
    out_.geometry.push_back(std::move(g));
    return static_cast<std::uint32_t>(out_.geometry.size() - 1);
  }
  static std::uint64_t tag_key(const FaceTag& t) {
    return static_cast<std::uint64_t>(t.semantic) | (static_cast<std::uint64_t>(t.material) << 8) |
           (static_cast<std::uint64_t>(t.face_id) << 24);
  }
  std::uint32_t intern_box(const std::array<FaceTag, 6>& tags) {
    std::array<std::uint64_t, 6> key;
    for (std::size_t i = 0; i < 6; ++i) key[i] = tag_key(tags[i]);
    auto [it, inserted] = boxes_.emplace(key, 0);
    if (inserted) {
      Geometry g;
      g.kind = Geometry::Kind::kBox;
      g.tags = tags;
      it->second = add_geometry(std::move(g));
    }
    return it->second;
  }
  std::uint32_t intern_rect(const FaceTag& tag) {
    auto [it, inserted] = rects_.emplace(tag_key(tag), 0);
    if (inserted) {
      Geometry g;
      g.kind = Geometry::Kind::kRect;
      g.tag = tag;
      it->second = add_geometry(std::move(g));
    }
    return it->second;
  }
  std::uint32_t add_mesh(std::shared_ptr<const Mesh> mesh,
                         std::shared_ptr<const kernel::Polygon> outline, Vec3 size);

 public:
  static Materialized materialize(const Geometry& g, Vec3 size);

 private:
  // ---- the derivation loop
  // The polygon with its outer ring rotated so the input's first edge comes first.
  kernel::Polygon oriented(std::size_t i) const;

  void start();

  void loop();

  void flush_batch();

  void count_shape(SymbolId symbol) {
    ++out_.shapes;
    if (symbol != kNoSymbol) ++out_.symbol_counts[symbol];
    if (out_.shapes > options_.limits.max_shapes) {
      limit_error("CGA602",
                  "shape limit of " + std::to_string(options_.limits.max_shapes) + " reached");
    }
  }

  [[noreturn]] void limit_error(std::string code, std::string what);

  void terminal(const State& st, SymbolId symbol) {
    ++out_.terminals;
    if (track_lineage_ && st.scope.size.x > 0 && st.scope.size.y > 0 && st.scope.size.z > 0) {
      add_occluder(st, "");  // a closed leaf
    }
    if (keep_) out_.terminals_store.push({st.scope, symbol, st.geometry, st.attrs});
  }

  // A new shape `symbol` from `st` at derivation depth `depth`: pending when it has rules.
  void push_or_terminal(const State& st, SymbolId symbol, std::uint32_t depth) {
    if (!program_.has_rules(symbol)) {
      terminal(st, symbol);
      return;
    }
    if (depth > std::min<std::uint32_t>(options_.limits.max_depth, 0xffff)) {
      limit_error("CGA601", "derivation depth limit of " +
                                std::to_string(options_.limits.max_depth) + " reached");
    }
    // Constructed in place: a Work built aside and copied in was read back in 16-byte pieces
    // over fields just written in 2 to 8 (perf: the store-forwarding stall was a third of this).
    batch_.emplace_back(st, symbol, static_cast<std::uint16_t>(depth),
                        static_cast<std::uint16_t>(program_.levels_of[symbol].front()));
  }

  void process(const Work& w);

  // Whether the condition of rule `r` holds on the current shape; a condition with one value
  // per lot (CRule::condition_per_lot) is evaluated once.
  bool condition_holds(std::uint32_t r, const CRule& rule);

  // The value of probability expression `p` of `rule`. Seed 004 §IV.B constraint 1 asks for a
  // probability in (0, 1]; the checker enforces it on constants (CGA301). A computed one (an
  // attribute, a function) that is negative, NaN or above 1 is an error here (CGA605) rather
  // than a weight silently clamped to 0; 0 itself is allowed, so an attribute can switch an
  // alternative off (docs/cga-derivation.md, "Errors").
  double probability(const CRule& rule, std::uint32_t p);

  const CAlternative& choose(const CRule& rule);

  void apply(const CRule& rule, State& st);

  // ---- successor interpreter
  Value eval(std::uint32_t e, State& st) {
    cur_ = &st;
    frame = frame_of(st.frame);
    return evaluate(program_, e, *this);
  }

  // ---- rule arguments (CityEngine's parametric rules): frame k holds
  // frame_values_[frame_begin_[k] .. frame_begin_[k + 1]); frame 0 is empty.
  std::span<const Value> frame_of(std::uint32_t f) const {
    return {frame_values_.data() + frame_begin_[f], frame_begin_[f + 1] - frame_begin_[f]};
  }
  std::uint32_t new_frame(const std::vector<std::uint32_t>& args, State& st);
  double number(std::uint32_t e, State& st) {
    return as_number(eval(e, st), program_.nodes[e].range);
  }
  SizeSpec size_of(const CSize& s, State& st) {
    return {s.expr == kNoExpr ? s.value : number(s.expr, st), s.mode};
  }

  State child_of(State& parent, const Scope& scope, std::uint32_t geometry, std::uint32_t index,
                 std::uint32_t total) {
    // Operation pieces count against the shape limit too: a piece that never becomes a symbol
    // (a failed nested split, a branch of ε) still costs work (RR("XYZ", 0.001) on a lot).
    if (++pieces_ > options_.limits.max_shapes) {
      limit_error("CGA602", "shape limit of " + std::to_string(options_.limits.max_shapes) +
                                " reached (operation pieces)");
    }
    State c;
    c.scope = scope;
    c.seed = shape::child_seed(parent.seed, parent.next_child++);
    if (track_lineage_) c.lineage = add_lineage(parent.lineage, c.seed);
    c.geometry = geometry;
    c.attrs = parent.attrs;
    c.index = index;
    c.total = total;
    c.frame = parent.frame;
    c.selector = parent.selector;
    c.lot_axes = parent.lot_axes;
    return c;
  }

  // A flat shape whose CityEngine axes are a lot's (State::lot_axes): CityEngine's y is its
  // normal (Insula's z) and CityEngine's z runs along Insula's −y.
  bool lot_axes(const State& st) const { return st.lot_axes && out_.geometry[st.geometry].flat(); }
  // A registry operation's axis arguments (s, center, mirror, translate in the scope frame)
  // from CityEngine's lot axes to Insula's.
  static void to_lot_axes(std::string_view op, std::vector<shape::ArgInput>& args);

  void warn(const CItem& c, std::string message);

  void flush_warnings();

  void run_items(const std::vector<CItem>& items, std::size_t from, State& st,
                 std::vector<State>& stack);

  void touch(State& st) {
    st.modified = true;
    st.consumed = false;
  }

  void rotate(const CItem& c, State& st);

  const CBranch& choose_branch(const CItem& c, State& st);

  void set_attr(State& st, std::uint32_t attr, Value value);
  void set_scope_translation(const CItem& c, State& st);

  void color(const CItem& c, State& st);
  // color()'s value as set_attr takes it ("#rrggbb", lower case); nullopt when CityEngine's
  // dialect keeps the colour (warned).
  std::optional<std::string> color_hex(const CItem& c, State& st);

  void print(const CItem& c, State& st);

  void report(const CItem& c, State& st);

  // ---- operations through the shape layer (shape::registry() on a one-shape tree)
  OpOutcome run_op(const State& st, std::string_view name, const std::vector<shape::ArgInput>& args,
                   const Scope* parent = nullptr);
  // offset(d < 0) of a rectangle (every window and frame of a façade grammar): the shape layer's
  // inset cores (shape/ops_fast.h) on the scope alone, each piece's geometry interned, instead
  // of a one-shape tree and two new meshes per window. nullopt: not such an offset.
  std::optional<OpOutcome> inset_rectangle(const State& st,
                                           const std::vector<shape::ArgInput>& args);
  struct InsetPiece {
    std::uint32_t geometry = 0;
    Vec3 offset;  // the piece's scope in the inset shape's (shape::FlatRegion)
    Vec3 size;
  };
  // Piece `piece` of offset(distance) of the rectangle `box` with face tag `tag`, made once per
  // lot (the rectangle's own position is its scope's: the piece is the same for every window).
  const InsetPiece& inset_piece(const kernel::Bounds2& box, double distance, const FaceTag& tag,
                                std::uint32_t piece);
  // Such a piece's key: the box's corners and the distance bit for bit, the tag and the piece.
  using InsetKey = std::array<std::uint64_t, 7>;
  struct InsetKeyHash {
    std::size_t operator()(const InsetKey& key) const {
      std::uint64_t h = 0;
      for (const std::uint64_t word : key) h = shape::mix64(h ^ word);
      return static_cast<std::size_t>(h);
    }
  };
  // The geometry of such a piece, shared by the lots one thread derives.
  struct InsetShape {
    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<const kernel::Polygon> outline;
    Vec3 offset;
    Vec3 size;
  };
  static const InsetShape& inset_shape(const InsetKey& key, const kernel::Bounds2& box,
                                       double distance, const FaceTag& tag, std::uint32_t piece);
  // The values of Program::state_attrs the shape sees (null where none is set).
  std::vector<Value> state_values(const State& st) const;
  // The shape's uv set `set` (setupProjection + projectUV), if it has one.
  std::optional<shape::UvMap> uv_map(const State& st, int set) const;

  bool check(const CItem& c, const OpOutcome& o) {
    if (!o.warning.empty()) warn(c, o.warning);
    if (o.error.empty()) return true;
    warn(c, o.error);
    return false;
  }

  // The registry arguments of a compiled operation: each positional argument as the parameter
  // operations.h maps it to, plus the ones its spelling fixes.
  std::vector<shape::ArgInput> registry_args(const CItem& c, State& st);
  OpOutcome run_registry(const CItem& c, State& st);
  OpOutcome extrude_behind(const State& st, std::vector<shape::ArgInput>& args);
  OpOutcome scale_mirrored(const State& st, std::vector<shape::ArgInput>& args);

  // Runs a replacing operation; returns false when it forked (the rest of the successor already
  // ran once per result) or removed the shape.
  bool replace(const CItem& c, const std::vector<CItem>& items, std::size_t i, State& st,
               std::vector<State>& stack);

  void run_branch(const CBranch& b, State& piece) {
    std::vector<State> stack;
    run_items(b.items, 0, piece, stack);
    if (!piece.consumed) terminal(piece, rule_->predecessor);
  }

  // roof { ... }, offset { inside: ... | border: ... } and any registry operation with a block.
  void block_operation(const CItem& c, State& st);

  // ---- split and repeat: scope math for boxes, rectangles and pure scopes (shape/ops_fast.h),
  // the shape layer's split for any other geometry. Buffers are reused per nesting level (a
  // split inside a split's branch takes the next level), so the hot path does not allocate.
  struct Scratch {
    std::vector<SizeSpec> sizes;
    std::vector<const CBranch*> targets;
    std::vector<shape::Piece> pieces;
  };
  class Lease {
   public:
    explicit Lease(Engine& e) : e_(e) {
      if (e.nest_ == e.scratch_.size()) e.scratch_.push_back(std::make_unique<Scratch>());
      s_ = e.scratch_[e.nest_++].get();
      s_->sizes.clear();
      s_->targets.clear();
    }
    ~Lease() { --e_.nest_; }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Scratch& operator*() { return *s_; }
    Scratch* operator->() { return s_; }

   private:
    Engine& e_;
    Scratch* s_ = nullptr;
  };

  // Calls visit(piece state, size entry) for each piece of splitting `st` along `axis`; returns
  // the operation's error ("" on success).
  template <typename Visit>
  std::string for_each_piece(State& st, Axis axis, std::span<const SizeSpec> sizes,
                             std::vector<shape::Piece>& pieces, Visit&& visit);

  // Nominal length of a size (floating sizes count their value) for repeat counting.
  double nominal(const CSize& s, State& st, double total);
  double pattern_length(const std::vector<CBranch>& pattern, State& st, double total);
  void append_pattern(const std::vector<CBranch>& pattern, State& st, std::vector<SizeSpec>& sizes,
                      std::vector<const CBranch*>& targets);

  // split(axis){ size: A | { ~2: B | 1: C }* | ... }: repeat patterns expand to as many copies as
  // fit in what the other entries leave (at least one), then sizes resolve as for BS.
  void keyed_sizes(const CItem& c, State& st, double total, std::vector<SizeSpec>& sizes,
                   std::vector<const CBranch*>& targets);

  void split(const CItem& c, State& st);
  void split_area(const CItem& c, State& st);
  // CityEngine's split(z) of a lot, laid out along Insula's y (docs/operations-cityengine.md).
  static std::vector<std::uint32_t> mirror_pieces(double total, std::vector<SizeSpec>& sizes,
                                                  std::vector<const CBranch*>& targets);

  // BS("XY", 3, 5, 7){ A | B | C } (§VI, docs/cga-language.md "Decisions"): the piece of the
  // first axis that successor `target` got is split along each further axis in turn by the same
  // sizes (evaluated once, on the shape the rule rewrites), and every cell of it gets `target`,
  // as RR("XY", 3) nests repeats. The same cores as a one-axis split (for_each_piece).
  void split_cells(const CItem& c, State& st, std::span<const SizeSpec> sizes,
                   std::size_t axis_index, const CBranch& target);

  // RR(axes, size){ A }: along each listed axis in turn (RR("XY", 3) is a grid).
  void repeat(const CItem& c, State& st, std::size_t axis_index);

  // ---- comp (seed 004 "Component Split Rule"; CityEngine selectors)
  const CBranch* comp_target(const CItem& c, std::uint32_t piece, std::size_t ordinal,
                             const Mesh* parent, const std::vector<bool>* border,
                             const std::vector<std::vector<bool>>* selected,
                             const std::vector<std::int64_t>* computed = nullptr);

  void comp(const CItem& c, State& st);

  // Calls visit(component, branch, k) for each component k (of `total`, in the operation's
  // order) a branch of comp `c` takes; false when the operation failed (warned).
  template <typename Visit>
  bool for_each_component(const CItem& c, State& st, std::uint32_t& total, Visit&& visit);
  // The branch of a face edge (fe) split that takes face edge `piece` facing `outward` (world).
  const CBranch* face_edge_target(const CItem& c, std::uint32_t piece, const State& st,
                                  Vec3 outward) const;

  // ---- setback(d){ front: A | remainder: B }: one strip per edge selector, in order, each cut
  // from what the previous ones left; the remainder successor gets what is left at the end.
  void setback(const CItem& c, State& st);
  // setback(float[]): a depth per edge of the outline; each branch takes the edges its selector
  // picks among those earlier branches left, all strips cut from the shape as it was.
  // Strips per edge: each edge's depth from `depths` (setback(float[])), else `uniform`.
  void setback_per_edge(const CItem& c, State& st, const Array* depths, double uniform);
  void setback_in_turn(const CItem& c, State& st, double depth);
  // Whether CityEngine's edge selector `selector` (front, street.left, all, ...) picks an edge
  // of `st` (flat) with outward direction `outward` (world).
  bool edge_selected(const std::string& selector, const State& st, Vec3 outward) const;

  // ---- I(asset) / Pshape(file): a new terminal shape holding the asset in the current scope
  // (seed 004 "an insertion rule creates a given shape with the current scope"); the current
  // shape goes on unchanged.
  void insert_shape(const CItem& c, State& st);

  const Program& program_;
  const Lot& lot_;
  const DeriveOptions& options_;
  LotResult& out_;
  // The attribute nodes set_attr made, by (parent, attribute): a facade's hundreds of walls
  // coloured alike share one node, so the export reads each distinct attribute set once.
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> attr_nodes_made_;
  // color("#...") literals as set_attr takes them ("#rrggbb", lower case), by expression.
  std::unordered_map<std::uint32_t, std::string> literal_colors_;
  // The node a literal colour took, by (attribute chain, expression).
  std::unordered_map<std::uint64_t, std::uint32_t> literal_nodes_;
  // The last of those by expression (node 0: none yet; set_attr never gives node 0).
  struct LastLiteral {
    std::uint32_t chain = 0;
    std::uint32_t node = 0;
  };
  std::vector<LastLiteral> last_literal_;
  BuiltinAssets assets_;
  shape::Context context_;
  std::uint64_t lot_seed_;
  shape::Rng rng_;
  bool keep_ = true;
  // Occlusion queries (CityEngine): lineage entries (parent entry, seed), the occluders this pass
  // made, and the previous pass's that queries test against.
  bool track_lineage_ = false;
  std::vector<std::pair<std::uint32_t, std::uint64_t>> lineage_;
  std::vector<Occluder> made_occluders_;
  const std::vector<Occluder>* occluders_ = nullptr;
  std::uint32_t add_lineage(std::uint32_t parent, std::uint64_t seed) {
    lineage_.emplace_back(parent, seed);
    return static_cast<std::uint32_t>(lineage_.size() - 1);
  }
  std::vector<std::uint64_t> lineage_seeds(std::uint32_t entry) const;
  void add_occluder(const State& st, std::string label);
  double minimum_distance(OcclusionTarget target, const std::string& label) override;
  bool occlusion_query(OcclusionRelation relation, OcclusionTarget target,
                       const std::string& label) override;
  Vec3 convert(shape::Frame from, shape::Frame to, bool orientation, Vec3 v) override {
    return shape::convert_between_frames(from, to, orientation, v, cur_->scope, context_.object);
  }

  std::vector<std::vector<Work>> pending_;  // one stack per priority level
  std::size_t pending_count_ = 0;
  std::vector<Work> batch_;        // shapes created by the current rule application
  const Work* current_ = nullptr;  // the record being processed, still in pending_
  std::vector<State> starts_;
  State start_state_;
  State* cur_ = nullptr;
  const CRule* rule_ = nullptr;
  Scope rule_scope_;
  std::uint32_t depth_ = 0;

  std::vector<Value> values_;
  std::vector<std::uint8_t> status_;         // 0 not evaluated, 1 in progress, 2 done
  std::vector<std::int8_t> lot_conditions_;  // by rule: -1 not asked yet, else the answer
  std::vector<Value> frame_values_;
  std::vector<std::size_t> frame_begin_{0, 0};
  std::map<std::array<std::uint64_t, 6>, std::uint32_t> boxes_;
  std::map<std::uint64_t, std::uint32_t> rects_;
  // Pieces of rectangle insets by (box, distance, tag, piece): a façade's windows are alike.
  std::map<InsetKey, InsetPiece> insets_;  // a handful a lot: a tree is cheaper than hashing
  // i() results by content (DeriveOptions::share_inserts).
  kernel::SharedMeshes inserted_;
  std::map<std::pair<std::uint32_t, std::string>, std::size_t> warnings_;
  std::vector<std::unique_ptr<Scratch>> scratch_;
  std::size_t nest_ = 0;
  std::uint64_t pieces_ = 0;
};

}  // namespace insula::lang::cga::detail
