// The derivation loop and the successor interpreter (seed 004 §II; header comment in derive.h).
#include "lang/cga/derive.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <span>

#include "lang/cga/eval.h"
#include "shape/ops.h"
#include "shape/ops_fast.h"
#include "shape/query.h"
#include "shape/rng.h"
#include "shape/shape_tree.h"

namespace insula::lang::cga {

using kernel::FaceTag;
using kernel::Mesh;
using kernel::Vec3;
using shape::Axis;
using shape::Scope;
using shape::SizeMode;
using shape::SizeSpec;
using shape::Value;

namespace {

constexpr std::size_t kFirstBlock = 32;   // records in block 0; block k < 7 holds 32 << k
constexpr std::size_t kLastBlock = 4096;  // records in every block from block 7 on
constexpr std::size_t kGrowing = 4064;    // records in blocks 0..6 (32 + 64 + ... + 2048)

// Block index and offset of record i.
std::pair<std::size_t, std::size_t> locate_record(std::size_t i) {
  if (i < kGrowing) {
    const std::size_t k = static_cast<std::size_t>(std::bit_width(i + kFirstBlock)) - 6;
    return {k, i + kFirstBlock - (kFirstBlock << k)};
  }
  return {7 + (i - kGrowing) / kLastBlock, (i - kGrowing) % kLastBlock};
}

}  // namespace

void TerminalStore::push(const Terminal& t) {
  if (size_ == capacity_) {
    const std::size_t k = blocks_.size();
    const std::size_t n = k < 7 ? kFirstBlock << k : kLastBlock;
    blocks_.push_back(std::unique_ptr<Terminal[]>(new Terminal[n]));
    capacity_ += n;
  }
  const auto [block, offset] = locate_record(size_);
  blocks_[block][offset] = t;
  ++size_;
}

const Terminal& TerminalStore::operator[](std::size_t i) const {
  const auto [block, offset] = locate_record(i);
  return blocks_[block][offset];
}

std::shared_ptr<const Mesh> BuiltinAssets::find(std::string_view name, std::string& error) const {
  if (name == "cube" || name == "builtin:cube") {
    static const std::shared_ptr<const Mesh> cube =
        shape::box_mesh({1, 1, 1}, shape::mass_box_tags());
    return cube;
  }
  if (next_ == nullptr) {
    error = "asset '" + std::string(name) + "' not found (no asset folder; \"cube\" is built in)";
    return nullptr;
  }
  return next_->find(name, error);
}

namespace {

// A pending shape (derive.h: "compact state").
struct Work {
  Scope scope;
  std::uint64_t seed = 0;
  SymbolId symbol = kNoSymbol;
  std::uint32_t geometry = 0;
  std::uint32_t attrs = 0;
  std::uint32_t index = 0;  // split.index / comp.index
  std::uint32_t total = 1;  // split.total
  std::uint16_t depth = 0;
  std::uint16_t level = 0;
};

// The current shape while a successor runs.
struct State {
  Scope scope;
  std::uint64_t seed = 0;
  std::uint32_t geometry = 0;
  std::uint32_t attrs = 0;
  std::uint32_t index = 0;
  std::uint32_t total = 1;
  std::uint32_t next_child = 0;  // children seeded so far (child_seed index)
  bool consumed = false;         // replaced by a symbol, a block operation or ε
  bool modified = false;         // changed since the last `[` (a `]` then leaves it as a leaf)
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

std::string hex_color(double r, double g, double b, double a, bool alpha) {
  const auto byte = [](double v) {
    return static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
  };
  char text[16];
  if (alpha) {
    std::snprintf(text, sizeof text, "#%02x%02x%02x%02x", byte(r), byte(g), byte(b), byte(a));
  } else {
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(r), byte(g), byte(b));
  }
  return text;
}

bool valid_hex_color(const std::string& s) {
  if (s.size() != 7 && s.size() != 9) return false;
  if (s[0] != '#') return false;
  return std::all_of(s.begin() + 1, s.end(),
                     [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; });
}

shape::FaceSelector face_selector(std::string_view name) {
  if (name == "front") return shape::FaceSelector::kFront;
  if (name == "back") return shape::FaceSelector::kBack;
  if (name == "left") return shape::FaceSelector::kLeft;
  if (name == "right") return shape::FaceSelector::kRight;
  if (name == "top") return shape::FaceSelector::kTop;
  if (name == "bottom") return shape::FaceSelector::kBottom;
  if (name == "side") return shape::FaceSelector::kSide;
  return shape::FaceSelector::kAll;
}

std::string_view axis_name(Axis a) {
  return a == Axis::kX ? "x" : a == Axis::kY ? "y" : "z";
}

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
    out_.geometry.push_back(Geometry{});  // handle 0: none
    out_.attr_nodes.push_back(AttrNode{});
    out_.symbol_counts.assign(program.symbols.size(), 0);
    pending_.resize(std::max<std::size_t>(1, program.priorities.size()));
    values_.resize(program.attrs.size());
    status_.resize(program.attrs.size(), 0);
  }

  void run() {
    try {
      start();
      loop();
      out_.ok = true;
    } catch (const DeriveError& e) {
      out_.diagnostics.push_back(e.diagnostic);
    } catch (const EvalError& e) {
      base::Diagnostic d = base::Diagnostic::error("CGA603", e.message, program_.span(e.range));
      if (rule_ != nullptr) d.notes.push_back("in " + program_.describe(*rule_));
      d.notes.push_back("in lot '" + lot_.id + "'");
      out_.diagnostics.push_back(std::move(d));
    }
    flush_warnings();
  }

  // ---- EvalContext
  Value attribute(std::uint32_t attr, Range range) override {
    for (std::uint32_t n = cur_ != nullptr ? cur_->attrs : 0; n != 0;
         n = out_.attr_nodes[n].parent) {
      if (out_.attr_nodes[n].attr == attr) return out_.attr_nodes[n].value;
    }
    return lot_value(attr, range);
  }

  double shape_attribute(ShapeAttr a) override {
    const State& s = *cur_;
    switch (a) {
      case ShapeAttr::kSx:
        return s.scope.size.x;
      case ShapeAttr::kSy:
        return s.scope.size.y;
      case ShapeAttr::kSz:
        return s.scope.size.z;
      case ShapeAttr::kTx:
        return s.scope.origin.x;
      case ShapeAttr::kTy:
        return s.scope.origin.y;
      case ShapeAttr::kTz:
        return s.scope.origin.z;
      case ShapeAttr::kArea: {
        const Geometry& g = out_.geometry[s.geometry];
        if (g.kind == Geometry::Kind::kMesh && g.outline) return g.area;
        return s.scope.size.x * s.scope.size.y;
      }
      case ShapeAttr::kVolume:
        return s.scope.volume();
      case ShapeAttr::kDepth:
        return depth_;
      case ShapeAttr::kIndex:
        return s.index;
      case ShapeAttr::kTotal:
        return s.total;
    }
    return 0;
  }

  std::string occlusion(const std::string& /*what*/, Range /*range*/) override {
    // The configuration (seed 004 §II): every pending and terminal shape of this lot but the
    // asking one, as boxes (shape::occlusion's box approximation).
    const Scope& self = cur_->scope;
    const kernel::Bounds3 mine = bounds(self);
    shape::ShapeTree tree;
    const shape::ShapeId id = tree.add_root(self);
    std::vector<shape::ShapeId> others;
    const auto consider = [&](const Scope& s) {
      const kernel::Bounds3 b = bounds(s);
      constexpr double kTol = 1e-3;
      if (b.min.x > mine.max.x + kTol || b.max.x < mine.min.x - kTol ||
          b.min.y > mine.max.y + kTol || b.max.y < mine.min.y - kTol ||
          b.min.z > mine.max.z + kTol || b.max.z < mine.min.z - kTol) {
        return;
      }
      others.push_back(tree.add_root(s));
    };
    for (std::size_t i = 0; i < out_.terminals_store.size(); ++i)
      consider(out_.terminals_store[i].scope);
    for (const auto& bucket : pending_) {
      for (const Work& w : bucket) consider(w.scope);
    }
    for (const Work& w : batch_) consider(w.scope);
    const double f = shape::occlusion(tree, id, others);
    return f <= 1e-6 ? "none" : f >= 1 - 1e-6 ? "full" : "part";
  }

  shape::Rng& rng() override { return rng_; }

 private:
  static kernel::Bounds3 bounds(const Scope& s) {
    kernel::Bounds3 b;
    for (const Vec3& p : s.corners()) b.add(p);
    return b;
  }

  // ---- attributes of the lot: --set > lot property > default (evaluated once per lot)
  Value lot_value(std::uint32_t attr, Range range) {
    if (status_[attr] == 2) return values_[attr];
    const CAttr& a = program_.attrs[attr];
    if (status_[attr] == 1) throw EvalError{range, "attribute '" + a.name + "' depends on itself"};
    status_[attr] = 1;
    Value v;
    bool found = false;
    for (const auto& [name, value] : options_.sets) {
      if (name == a.name) {
        v = value;
        found = true;
      }
    }
    if (!found) {
      if (auto it = lot_.properties.find(a.name);
          it != lot_.properties.end() && !shape::is_null(it->second)) {
        v = it->second;
        found = true;
      }
    }
    if (!found && a.value != kNoExpr) {
      State* saved = cur_;
      cur_ = &start_state_;
      v = evaluate(program_, a.value, *this);
      cur_ = saved;
    }
    values_[attr] = v;
    status_[attr] = 2;
    return v;
  }

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
                         std::shared_ptr<const kernel::Polygon> outline, Vec3 size) {
    if (!mesh && !outline) return 0;
    Geometry g;
    g.kind = Geometry::Kind::kMesh;
    if (outline) {
      g.rect_like = shape::is_rectangle(*outline, size.x, size.y);
      g.tag = mesh && !mesh->empty() ? mesh->tag(0) : FaceTag{};
      g.area = kernel::area(*outline);
    } else if (mesh) {
      g.box_like = shape::is_box(*mesh, size, &g.tags);
    }
    g.mesh = std::move(mesh);
    g.outline = std::move(outline);
    return add_geometry(std::move(g));
  }

 public:
  static Materialized materialize(const Geometry& g, Vec3 size) {
    switch (g.kind) {
      case Geometry::Kind::kNone:
        return {};
      case Geometry::Kind::kBox:
        return {shape::box_mesh(size, g.tags), nullptr};
      case Geometry::Kind::kRect: {
        auto outline = std::make_shared<kernel::Polygon>(shape::rectangle_outline(size.x, size.y));
        auto mesh = shape::flat_mesh(*outline, g.tag);
        return {std::move(mesh), std::move(outline)};
      }
      case Geometry::Kind::kMesh:
        return {g.mesh, g.outline};
    }
    return {};
  }

 private:
  // ---- the derivation loop
  // The polygon with its outer ring rotated so the input's first edge comes first.
  kernel::Polygon oriented(std::size_t i) const {
    kernel::Polygon polygon = lot_.polygons[i];
    kernel::normalize(polygon);
    if (i >= lot_.first_edges.size()) return polygon;
    const auto& [a, b] = lot_.first_edges[i];
    const auto near = [](kernel::Vec2 p, kernel::Vec2 q) {
      return std::fabs(p.x - q.x) <= 1e-6 && std::fabs(p.y - q.y) <= 1e-6;
    };
    kernel::Ring& ring = polygon.outer;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const kernel::Vec2 p = ring[k];
      const kernel::Vec2 q = ring[(k + 1) % ring.size()];
      if ((near(p, a) && near(q, b)) || (near(p, b) && near(q, a))) {
        std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(k), ring.end());
        break;
      }
    }
    return polygon;
  }

  void start() {
    for (std::size_t i = 0; i < lot_.polygons.size(); ++i) {
      shape::ShapeTree tree;
      const shape::RootResult root = tree.create_root(oriented(i));
      if (!root.ok()) {
        throw DeriveError{base::Diagnostic::error(
            "CGA606", "lot '" + lot_.id + "' polygon " + std::to_string(i) + ": " + root.error,
            base::Span::whole(program_.source->name()))};
      }
      const shape::Shape& s = tree[root.id];
      State st;
      st.scope = s.scope;
      st.seed = shape::child_seed(lot_seed_, static_cast<std::uint32_t>(i));
      st.geometry = add_mesh(s.mesh, s.outline, s.scope.size);
      if (i == 0) start_state_ = st;
      starts_.push_back(st);
    }
    // Attribute values are fixed per lot, before any rule runs (CityEngine's attr semantics),
    // with a generator of their own.
    rng_ = shape::Rng(shape::child_seed(lot_seed_, 0xfffffffeU));
    cur_ = &start_state_;
    for (std::uint32_t a = 0; a < program_.attrs.size(); ++a) {
      if (a == program_.color_attr) continue;
      const Value v = lot_value(a, program_.attrs[a].range);
      if (!shape::is_null(v)) out_.attributes[program_.attrs[a].name] = v;
    }
    for (const auto& [name, value] : lot_.properties) out_.attributes.emplace(name, value);
    for (State& st : starts_) {
      st.next_child = 0;
      count_shape(program_.start);
      push_or_terminal(st, program_.start, 0);
    }
    flush_batch();
  }

  void loop() {
    while (true) {
      std::size_t level = pending_.size();
      for (std::size_t l = 0; l < pending_.size(); ++l) {
        if (!pending_[l].empty()) {
          level = l;
          break;
        }
      }
      if (level == pending_.size()) return;
      const Work w = pending_[level].back();
      pending_[level].pop_back();
      --pending_count_;
      process(w);
      flush_batch();
    }
  }

  void flush_batch() {
    // Children go on the stack in reverse so the first one is derived first (depth first, in
    // successor order: the terminal list follows the grammar's reading order).
    for (auto it = batch_.rbegin(); it != batch_.rend(); ++it) pending_[it->level].push_back(*it);
    pending_count_ += batch_.size();
    out_.peak_pending = std::max(out_.peak_pending, pending_count_);
    batch_.clear();
  }

  void count_shape(SymbolId symbol) {
    ++out_.shapes;
    if (symbol != kNoSymbol) ++out_.symbol_counts[symbol];
    if (out_.shapes > options_.limits.max_shapes) {
      limit_error("CGA602",
                  "shape limit of " + std::to_string(options_.limits.max_shapes) + " reached");
    }
  }

  [[noreturn]] void limit_error(std::string code, std::string what) {
    base::Span span = base::Span::whole(program_.source->name());
    if (rule_ != nullptr) {
      span = program_.span(rule_->id_range);
      what += " in " + program_.describe(*rule_);
    }
    base::Diagnostic d = base::Diagnostic::error(std::move(code), std::move(what), span);
    d.notes.push_back("in lot '" + lot_.id + "'");
    throw DeriveError{std::move(d)};
  }

  void terminal(const State& st, SymbolId symbol) {
    ++out_.terminals;
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
    Work w;
    w.scope = st.scope;
    w.seed = st.seed;
    w.symbol = symbol;
    w.geometry = st.geometry;
    w.attrs = st.attrs;
    w.index = st.index;
    w.total = st.total;
    w.depth = static_cast<std::uint16_t>(depth);
    w.level = static_cast<std::uint16_t>(program_.levels_of[symbol].front());
    batch_.push_back(w);
  }

  void process(const Work& w) {
    State st;
    st.scope = w.scope;
    st.seed = w.seed;
    st.geometry = w.geometry;
    st.attrs = w.attrs;
    st.index = w.index;
    st.total = w.total;
    depth_ = w.depth;
    cur_ = &st;
    rng_ = shape::Rng(w.seed);
    rule_ = nullptr;
    for (std::uint32_t r : program_.rules_at[w.symbol][w.level]) {
      const CRule& rule = program_.rules[r];
      rule_ = &rule;
      if (rule.condition != kNoExpr && !as_bool(evaluate(program_, rule.condition, *this),
                                                program_.nodes[rule.condition].range)) {
        continue;
      }
      apply(rule, st);
      return;
    }
    // No rule of this level applies: try the next level with rules for the symbol (§II: a
    // shape with no applicable rule is terminal).
    for (std::uint32_t l : program_.levels_of[w.symbol]) {
      if (l > w.level) {
        Work next = w;
        next.level = static_cast<std::uint16_t>(l);
        batch_.push_back(next);
        return;
      }
    }
    terminal(st, w.symbol);
  }

  // The value of probability expression `p` of `rule`. Seed 004 §IV.B constraint 1 asks for a
  // probability in (0, 1]; the checker enforces it on constants (CGA301). A computed one (an
  // attribute, a function) that is negative, NaN or above 1 is an error here (CGA605) rather
  // than a weight silently clamped to 0; 0 itself is allowed, so an attribute can switch an
  // alternative off (docs/cga-derivation.md, "Errors").
  double probability(const CRule& rule, std::uint32_t p) {
    const Range range = program_.nodes[p].range;
    const double v = as_number(evaluate(program_, p, *this), range);
    if (!(v >= 0 && v <= 1)) {
      base::Diagnostic d = base::Diagnostic::error(
          "CGA605",
          "the probability of " + program_.describe(rule) + " evaluates to " + as_text(Value(v)) +
              ", not a number in [0, 1] (seed 004 §IV.B, constraint 1)",
          program_.span(range));
      d.notes.push_back("in lot '" + lot_.id + "'");
      throw DeriveError{std::move(d)};
    }
    return v;
  }

  const CAlternative& choose(const CRule& rule) {
    if (rule.alternatives.size() == 1) {
      const std::uint32_t p = rule.alternatives.front().probability;
      if (p != kNoExpr) probability(rule, p);  // checked even when there is nothing to choose
      return rule.alternatives.front();
    }
    // Probabilities from the shape's generator; alternatives without one share what is left.
    std::vector<double> weights(rule.alternatives.size(), -1.0);
    double given = 0;
    std::size_t missing = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
      const std::uint32_t p = rule.alternatives[i].probability;
      if (p == kNoExpr) {
        ++missing;
        continue;
      }
      weights[i] = probability(rule, p);
      given += weights[i];
    }
    const double share =
        missing > 0 ? std::max(0.0, 1.0 - given) / static_cast<double>(missing) : 0;
    for (double& w : weights) {
      if (w < 0) w = share;
    }
    const std::size_t k = rng_.choice(weights);
    return rule.alternatives[k < weights.size() ? k : 0];
  }

  void apply(const CRule& rule, State& st) {
    ++out_.rule_applications;
    const CAlternative& alt = choose(rule);
    rule_scope_ = st.scope;
    std::vector<State> stack;
    run_items(alt.items, 0, st, stack);
    if (!st.consumed) terminal(st, rule.predecessor);
  }

  // ---- successor interpreter
  Value eval(std::uint32_t e, State& st) {
    cur_ = &st;
    return evaluate(program_, e, *this);
  }
  double number(std::uint32_t e, State& st) {
    return as_number(eval(e, st), program_.nodes[e].range);
  }
  SizeSpec size_of(const CSize& s, State& st) {
    return {s.expr == kNoExpr ? s.value : number(s.expr, st), s.mode};
  }
  std::string text_arg(const CItem& c, State& st) {
    if (c.args.empty()) return c.text;
    return as_text(eval(c.args[0], st));
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
    c.geometry = geometry;
    c.attrs = parent.attrs;
    c.index = index;
    c.total = total;
    return c;
  }

  void warn(const CItem& c, std::string message) {
    const std::string name = c.info != nullptr ? std::string(c.info->name) : "operation";
    // Registry errors name the shape operation ("roof: ..."); say the CGA name instead.
    if (c.info != nullptr && !c.info->registry_op.empty()) {
      const std::string prefix = std::string(c.info->registry_op) + ": ";
      if (message.compare(0, prefix.size(), prefix) == 0) message.erase(0, prefix.size());
    }
    ++warnings_[{c.range.begin, name + ": " + message}];
  }

  void flush_warnings() {
    for (const auto& [key, count] : warnings_) {
      base::Diagnostic d = base::Diagnostic::warning(
          "CGA604",
          key.second + (count > 1 ? " (" + std::to_string(count) + " times)" : std::string()),
          program_.span(Range{key.first, key.first + 1}));
      out_.diagnostics.push_back(std::move(d));
    }
  }

  void run_items(const std::vector<CItem>& items, std::size_t from, State& st,
                 std::vector<State>& stack) {
    for (std::size_t i = from; i < items.size(); ++i) {
      const CItem& c = items[i];
      switch (c.code) {
        case OpCode::kSymbol:
          count_shape(c.symbol);
          {
            State child = st;
            child.seed = shape::child_seed(st.seed, st.next_child++);
            child.next_child = 0;
            push_or_terminal(child, c.symbol, depth_ + 1U);
          }
          st.consumed = true;
          break;
        case OpCode::kEmpty:
          st.consumed = true;
          break;
        case OpCode::kPush: {
          State inner = st;
          inner.seed = shape::child_seed(st.seed, st.next_child++);
          stack.push_back(st);
          inner.next_child = 0;
          inner.consumed = false;
          inner.modified = false;
          st = inner;
          break;
        }
        case OpCode::kPop:
          if (stack.empty()) break;  // the parser balances brackets
          if (!st.consumed && st.modified) terminal(st, rule_->predecessor);
          st = stack.back();
          stack.pop_back();
          break;
        case OpCode::kTranslate:
          st.scope.origin = st.scope.to_world(
              {number(c.args[0], st), number(c.args[1], st), number(c.args[2], st)});
          touch(st);
          break;
        case OpCode::kRotate:
          rotate(c, st);
          break;
        case OpCode::kColor:
          color(c, st);
          break;
        case OpCode::kSet:
          set_attr(st, c.attr, eval(c.args[0], st));
          break;
        case OpCode::kPrint:
          print(c, st);
          break;
        case OpCode::kReport:
          report(c, st);
          break;
        case OpCode::kInsertShape:
          insert_shape(c, st);
          break;
        case OpCode::kSplit:
        case OpCode::kRepeat:
          split(c, st);
          st.consumed = true;
          break;
        case OpCode::kComp:
          comp(c, st);
          st.consumed = true;
          break;
        case OpCode::kSetback:
          setback(c, st);
          st.consumed = true;
          break;
        default:
          // Operations through the shape layer that replace the current shape (extrude, scale,
          // center, i, roof and offset without a block) or feed a block (roof, offset).
          if (c.has_block) {
            block_operation(c, st);
            st.consumed = true;
            break;
          }
          if (!replace(c, items, i, st, stack)) return;
          break;
      }
    }
  }

  void touch(State& st) {
    st.modified = true;
    st.consumed = false;
  }

  void rotate(const CItem& c, State& st) {
    const Vec3 d{number(c.args[0], st), number(c.args[1], st), number(c.args[2], st)};
    if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) {
      warn(c, "angles must be finite");
      return;
    }
    // As shape::rotate: intrinsic rotations about x, then y, then z, about the scope origin.
    if (d.x != 0) st.scope = shape::rotated(st.scope, Axis::kX, d.x, {});
    if (d.y != 0) st.scope = shape::rotated(st.scope, Axis::kY, d.y, {});
    if (d.z != 0) st.scope = shape::rotated(st.scope, Axis::kZ, d.z, {});
    touch(st);
  }

  void set_attr(State& st, std::uint32_t attr, Value value) {
    out_.attr_nodes.push_back({st.attrs, attr, std::move(value)});
    st.attrs = static_cast<std::uint32_t>(out_.attr_nodes.size() - 1);
    touch(st);
  }

  void color(const CItem& c, State& st) {
    std::string hex;
    if (c.args.size() == 1) {
      const Value v = eval(c.args[0], st);
      hex = as_text(v);
      if (!valid_hex_color(hex)) {
        throw EvalError{program_.nodes[c.args[0]].range,
                        "color() expects \"#rrggbb\" or \"#rrggbbaa\", got \"" + hex + "\""};
      }
      std::transform(hex.begin(), hex.end(), hex.begin(), [](char ch) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      });
    } else {
      const double a = c.args.size() == 4 ? number(c.args[3], st) : 1.0;
      hex = hex_color(number(c.args[0], st), number(c.args[1], st), number(c.args[2], st), a,
                      c.args.size() == 4);
    }
    set_attr(st, program_.color_attr, std::move(hex));
  }

  void print(const CItem& c, State& st) {
    std::string line =
        program_.source->name() + ":" + std::to_string(program_.span(c.range).line) + ": print:";
    for (std::uint32_t a : c.args) line += " " + as_text(eval(a, st));
    out_.prints.push_back(std::move(line));
  }

  void report(const CItem& c, State& st) {
    const std::string name = as_text(eval(c.args[0], st));
    const double value = number(c.args[1], st);
    ReportEntry& e = out_.reports[name];
    e.sum += value;
    ++e.count;
  }

  // ---- operations through the shape layer (shape::registry() on a one-shape tree)
  OpOutcome run_op(const State& st, std::string_view name, const std::vector<shape::ArgInput>& args,
                   const Scope* parent = nullptr) {
    OpOutcome out;
    const Materialized m = materialize(out_.geometry[st.geometry], st.scope.size);
    out.parent_mesh = m.mesh;
    shape::ShapeTree tree;
    shape::ShapeId id;
    if (parent != nullptr) {
      id = tree.add_child(tree.add_root(*parent), st.scope, m.mesh, m.outline);
    } else {
      id = tree.add_root(st.scope, m.mesh, m.outline);
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
      c.geometry = add_mesh(s.mesh, s.outline, s.scope.size);
      out.children.push_back(c);
      out.pieces.push_back(r.pieces[k]);
    }
    return out;
  }

  bool check(const CItem& c, const OpOutcome& o) {
    if (!o.warning.empty()) warn(c, o.warning);
    if (o.error.empty()) return true;
    warn(c, o.error);
    return false;
  }

  std::vector<shape::ArgInput> roof_args(const CItem& c, State& st) {
    std::vector<shape::ArgInput> a{{"type", c.text}};
    const auto n = [&](std::size_t i) { return number(c.args[i], st); };
    if (c.text == "flat") {
      if (!c.args.empty()) a.push_back({"overhang", n(0)});
      if (c.args.size() > 1) a.push_back({"thickness", n(1)});
      return a;
    }
    if (!c.args.empty()) a.push_back({"pitch", n(0)});
    if (c.text == "mansard") {
      // roofMansard(upper angle, lower angle, break height, overhang)
      if (c.args.size() > 1) a.push_back({"mansard_pitch", n(1)});
      if (c.args.size() > 2) a.push_back({"break_height", n(2)});
      if (c.args.size() > 3) a.push_back({"overhang", n(3)});
      return a;
    }
    if (c.args.size() > 1) a.push_back({"overhang", n(1)});
    return a;
  }

  // A registry operation's positional arguments, in the registry's declaration order (the
  // registry's binder checks their types and ranges).
  std::vector<shape::ArgInput> registry_args(const CItem& c, State& st) {
    std::vector<shape::ArgInput> a;
    for (std::uint32_t e : c.args) {
      const Value v = eval(e, st);
      if (const auto* b = std::get_if<bool>(&v)) {
        a.push_back({"", *b});
      } else if (const auto* d = std::get_if<double>(&v)) {
        a.push_back({"", *d});
      } else {
        a.push_back({"", as_text(v)});
      }
    }
    return a;
  }

  // Runs a replacing operation; returns false when it forked (the rest of the successor already
  // ran once per result) or removed the shape.
  bool replace(const CItem& c, const std::vector<CItem>& items, std::size_t i, State& st,
               std::vector<State>& stack) {
    OpOutcome o;
    switch (c.code) {
      case OpCode::kExtrude:
        o = run_op(st, "extrude", {{"height", number(c.args[0], st)}});
        break;
      case OpCode::kScale: {
        std::vector<shape::ArgInput> a;
        const char* names[] = {"x", "y", "z"};
        for (std::size_t k = 0; k < 3; ++k) a.push_back({names[k], size_of(c.sizes[k], st)});
        o = run_op(st, "scale", a);
        break;
      }
      case OpCode::kCenter:
        o = run_op(st, "center", {{"axes", c.text}}, &rule_scope_);
        break;
      case OpCode::kInsert:
        o = run_op(st, "insert", {{"asset", text_arg(c, st)}});
        break;
      case OpCode::kRoof:
        o = run_op(st, "roof", roof_args(c, st));
        break;
      case OpCode::kOffset: {
        std::vector<shape::ArgInput> a{{"distance", number(c.args[0], st)}};
        if (!c.text.empty()) a.push_back({"part", c.text});
        o = run_op(st, "offset", a);
        break;
      }
      case OpCode::kRegistry:
        o = run_op(st, c.info->registry_op, registry_args(c, st));
        break;
      default:
        return true;
    }
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
      std::vector<State> fork_stack = stack;
      run_items(items, i + 1, child, fork_stack);
      if (!child.consumed) terminal(child, rule_->predecessor);
    }
    st.consumed = true;
    return false;
  }

  void run_branch(const CBranch& b, State& piece) {
    std::vector<State> stack;
    run_items(b.items, 0, piece, stack);
    if (!piece.consumed) terminal(piece, rule_->predecessor);
  }

  // roof { ... } and offset { inside: ... | border: ... }.
  void block_operation(const CItem& c, State& st) {
    OpOutcome o;
    if (c.code == OpCode::kRoof) {
      o = run_op(st, "roof", roof_args(c, st));
    } else {
      std::vector<shape::ArgInput> a{{"distance", number(c.args[0], st)}};
      if (!c.text.empty()) a.push_back({"part", c.text});
      o = run_op(st, "offset", a);
    }
    if (!check(c, o)) {
      terminal(st, rule_->predecessor);
      return;
    }
    const auto total = static_cast<std::uint32_t>(o.children.size());
    for (std::uint32_t k = 0; k < total; ++k) {
      const CBranch* target = nullptr;
      for (const CBranch& b : c.branches) {
        const bool match = !b.has_key || (c.code == OpCode::kOffset &&
                                          b.selector == (o.pieces[k] == 0 ? "inside" : "border"));
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
                             std::vector<shape::Piece>& pieces, Visit&& visit) {
    const double total = shape::component(st.scope.size, axis);
    if (!(total > 0)) return "the scope has size 0 along the split axis";
    const Geometry& g = out_.geometry[st.geometry];
    const bool flat =
        g.kind == Geometry::Kind::kRect || (g.kind == Geometry::Kind::kMesh && g.outline);
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
    const FaceTag tag = g.tag;
    const std::array<FaceTag, 6> tags = g.tags;
    const auto n = static_cast<std::uint32_t>(pieces.size());
    for (std::uint32_t k = 0; k < n; ++k) {
      std::uint32_t geometry = 0;
      if (flat) {
        geometry = intern_rect(tag);
      } else if (kind != Geometry::Kind::kNone) {
        geometry = intern_box(shape::split_box_tags(tags, axis, pieces[k], total));
      }
      State piece =
          child_of(st, shape::split_piece_scope(st.scope, axis, pieces[k]), geometry, k, n);
      visit(piece, pieces[k].entry);
    }
    return {};
  }

  // Nominal length of a size (floating sizes count their value) for repeat counting.
  double nominal(const CSize& s, State& st, double total) {
    const SizeSpec v = size_of(s, st);
    return v.mode == SizeMode::kRelative ? v.value * total : v.value;
  }
  double pattern_length(const std::vector<CBranch>& pattern, State& st, double total) {
    double sum = 0;
    for (const CBranch& b : pattern) {
      sum += b.repeat ? pattern_length(b.pattern, st, total) : nominal(b.size, st, total);
    }
    return sum;
  }
  void append_pattern(const std::vector<CBranch>& pattern, State& st, std::vector<SizeSpec>& sizes,
                      std::vector<const CBranch*>& targets) {
    for (const CBranch& b : pattern) {
      if (b.repeat) {
        append_pattern(b.pattern, st, sizes, targets);  // a pattern inside a pattern: once
        continue;
      }
      sizes.push_back(size_of(b.size, st));
      targets.push_back(&b);
    }
  }

  // split(axis){ size: A | { ~2: B | 1: C }* | ... }: repeat patterns expand to as many copies as
  // fit in what the other entries leave (at least one), then sizes resolve as for BS.
  void keyed_sizes(const CItem& c, State& st, double total, std::vector<SizeSpec>& sizes,
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

  void split(const CItem& c, State& st) {
    if (c.code == OpCode::kRepeat) {
      repeat(c, st, 0);
      return;
    }
    Lease scratch(*this);
    const Axis axis = c.axes.front();
    if (!c.sizes.empty()) {  // BS(axis, sizes...){ one successor per size }
      for (std::size_t k = 0; k < c.sizes.size(); ++k) {
        scratch->sizes.push_back(size_of(c.sizes[k], st));
        scratch->targets.push_back(k < c.branches.size() ? &c.branches[k] : nullptr);
      }
    } else {
      keyed_sizes(c, st, shape::component(st.scope.size, axis), scratch->sizes, scratch->targets);
    }
    const std::vector<const CBranch*>& targets = scratch->targets;
    const std::span<const SizeSpec> sizes = scratch->sizes;
    const std::string error =
        for_each_piece(st, axis, sizes, scratch->pieces, [&](State& piece, std::uint32_t entry) {
          if (targets[entry] == nullptr) return;
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

  // BS("XY", 3, 5, 7){ A | B | C } (§VI, docs/cga-language.md "Decisions"): the piece of the
  // first axis that successor `target` got is split along each further axis in turn by the same
  // sizes (evaluated once, on the shape the rule rewrites), and every cell of it gets `target`,
  // as RR("XY", 3) nests repeats. The same cores as a one-axis split (for_each_piece).
  void split_cells(const CItem& c, State& st, std::span<const SizeSpec> sizes,
                   std::size_t axis_index, const CBranch& target) {
    Lease scratch(*this);
    const std::string error = for_each_piece(
        st, c.axes[axis_index], sizes, scratch->pieces, [&](State& cell, std::uint32_t) {
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

  // RR(axes, size){ A }: along each listed axis in turn (RR("XY", 3) is a grid).
  void repeat(const CItem& c, State& st, std::size_t axis_index) {
    const Axis axis = c.axes[axis_index];
    std::string error;
    const double size = size_of(c.sizes.front(), st).value;
    const std::size_t n = shape::repeat_count(shape::component(st.scope.size, axis), size, error);
    if (n > 0) {
      Lease scratch(*this);
      scratch->sizes.assign(n, SizeSpec{1, SizeMode::kFloating});
      error = for_each_piece(st, axis, scratch->sizes, scratch->pieces,
                             [&](State& piece, std::uint32_t) {
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

  // ---- comp (seed 004 "Component Split Rule"; CityEngine selectors)
  const CBranch* comp_target(const CItem& c, std::uint32_t piece, std::size_t ordinal,
                             const Mesh* parent) {
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
      if (b.index >= 0) {
        if (b.index == piece) return &b;
        continue;
      }
      if (faces && shape::face_matches(face_selector(b.selector), n)) return &b;
    }
    return nullptr;
  }

  void comp(const CItem& c, State& st) {
    const char* type = c.comp == CompKind::kEdges      ? "edges"
                       : c.comp == CompKind::kVertices ? "vertices"
                                                       : "faces";
    OpOutcome o = run_op(st, "comp", {{"type", std::string(type)}});
    if (!check(c, o)) {
      terminal(st, rule_->predecessor);
      return;
    }
    const auto total = static_cast<std::uint32_t>(o.children.size());
    std::size_t ordinal = 0;
    for (std::uint32_t k = 0; k < total; ++k) {
      const bool faces = c.comp == CompKind::kFaces || c.comp == CompKind::kSideFaces;
      if (c.comp == CompKind::kSideFaces &&
          !shape::face_matches(shape::FaceSelector::kSide,
                               kernel::face_normal(*o.parent_mesh, o.pieces[k]))) {
        continue;
      }
      const CBranch* b =
          comp_target(c, o.pieces[k], ordinal++, faces ? o.parent_mesh.get() : nullptr);
      if (b == nullptr) continue;
      State piece = child_of(st, o.children[k].scope, o.children[k].geometry, k, total);
      run_branch(*b, piece);
    }
  }

  // ---- setback(d){ front: A | remainder: B }: one strip per edge selector, in order, each cut
  // from what the previous ones left; the remainder successor gets what is left at the end.
  void setback(const CItem& c, State& st) {
    const double distance = number(c.args[0], st);
    const CBranch* remainder = nullptr;
    for (const CBranch& b : c.branches) {
      if (b.selector == "remainder") remainder = &b;
    }
    State rest = st;
    bool cut = false;
    for (const CBranch& b : c.branches) {
      if (b.selector == "remainder") continue;
      const std::string edges = b.selector == "street" || b.selector.empty() ? "front" : b.selector;
      OpOutcome o = run_op(rest, "setback", {{"distance", distance}, {"edges", edges}});
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

  // ---- I(asset) / Pshape(file): a new terminal shape holding the asset in the current scope
  // (seed 004 "an insertion rule creates a given shape with the current scope"); the current
  // shape goes on unchanged.
  void insert_shape(const CItem& c, State& st) {
    const std::string asset = text_arg(c, st);
    OpOutcome o = run_op(st, "insert", {{"asset", asset}});
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

  const Program& program_;
  const Lot& lot_;
  const DeriveOptions& options_;
  LotResult& out_;
  BuiltinAssets assets_;
  shape::Context context_;
  std::uint64_t lot_seed_;
  shape::Rng rng_;
  bool keep_ = true;

  std::vector<std::vector<Work>> pending_;  // one stack per priority level
  std::size_t pending_count_ = 0;
  std::vector<Work> batch_;  // shapes created by the current rule application
  std::vector<State> starts_;
  State start_state_;
  State* cur_ = nullptr;
  const CRule* rule_ = nullptr;
  Scope rule_scope_;
  std::uint32_t depth_ = 0;

  std::vector<Value> values_;
  std::vector<std::uint8_t> status_;  // 0 not evaluated, 1 in progress, 2 done
  std::map<std::array<std::uint64_t, 6>, std::uint32_t> boxes_;
  std::map<std::uint64_t, std::uint32_t> rects_;
  std::map<std::pair<std::uint32_t, std::string>, std::size_t> warnings_;
  std::vector<std::unique_ptr<Scratch>> scratch_;
  std::size_t nest_ = 0;
  std::uint64_t pieces_ = 0;
};

}  // namespace

LotResult derive_lot(const Program& program, const Lot& lot, std::size_t lot_index,
                     const DeriveOptions& options) {
  LotResult out;
  Engine engine(program, lot, lot_index, options, out);
  engine.run();
  return out;
}

Lot default_lot(const Program& program, const DeriveOptions& options) {
  const auto constant_attr = [&](std::string_view name) -> double {
    for (const auto& [n, v] : options.sets) {
      if (n == name && std::holds_alternative<double>(v)) return std::get<double>(v);
    }
    const CAttr* a = program.find_attr(name);
    if (a != nullptr && a->value != kNoExpr && program.nodes[a->value].code == ECode::kConst) {
      const Value& v = program.consts[program.nodes[a->value].a];
      if (std::holds_alternative<double>(v)) return std::get<double>(v);
    }
    return 20.0;
  };
  const double w = constant_attr("lotWidth");
  const double d = constant_attr("lotDepth");
  Lot lot;
  lot.id = "lot_0";
  lot.polygons.push_back({{{0, 0}, {w, 0}, {w, d}, {0, d}}, {}});
  return lot;
}

Totals totals(const Program& program, const std::vector<LotResult>& results) {
  Totals t;
  std::vector<std::uint64_t> counts(program.symbols.size(), 0);
  for (const LotResult& r : results) {
    t.shapes += r.shapes;
    t.terminals += r.terminals;
    t.rule_applications += r.rule_applications;
    for (std::size_t s = 0; s < r.symbol_counts.size() && s < counts.size(); ++s) {
      counts[s] += r.symbol_counts[s];
    }
    for (const auto& [name, e] : r.reports) {
      t.reports[name].sum += e.sum;
      t.reports[name].count += e.count;
    }
  }
  for (std::size_t s = 0; s < counts.size(); ++s) {
    if (counts[s] > 0) t.symbols[program.symbols[s]] = counts[s];
  }
  return t;
}

std::string dump_derivation(const Program& program, const std::vector<LotResult>& results) {
  const Totals t = totals(program, results);
  std::string out = "shapes " + std::to_string(t.shapes) + "\nterminals " +
                    std::to_string(t.terminals) + "\nrule_applications " +
                    std::to_string(t.rule_applications) + "\n";
  for (const auto& [name, count] : t.symbols) {
    out += "symbol " + name + " " + std::to_string(count) + "\n";
  }
  const auto num = [](double v) {
    char text[32];
    const double r = std::round(v * 1e6) / 1e6;
    std::snprintf(text, sizeof text, "%.6f", r == 0 ? 0.0 : r);
    std::string s = text;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
  };
  const auto vec = [&](Vec3 v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); };
  static constexpr const char* kKinds[] = {"none", "box", "rect", "mesh"};
  for (std::size_t i = 0; i < results.size(); ++i) {
    const LotResult& r = results[i];
    out += "lot " + std::to_string(i) + " shapes " + std::to_string(r.shapes) + " terminals " +
           std::to_string(r.terminals) + "\n";
    for (std::size_t k = 0; k < r.terminals_store.size(); ++k) {
      const Terminal& term = r.terminals_store[k];
      const Geometry& g = r.geometry[term.geometry];
      out += "  " + std::string(program.symbol_name(term.symbol)) + " " +
             kKinds[static_cast<int>(g.kind)] + " at " + vec(term.scope.origin) + " size " +
             vec(term.scope.size) + "\n";
    }
  }
  return out;
}

namespace {

std::array<float, 4> rgba_of(const std::string& hex) {
  std::array<float, 4> c{0.8F, 0.8F, 0.8F, 1.0F};
  for (std::size_t k = 0; k * 2 + 1 < hex.size() && k < 4; ++k) {
    c[k] = static_cast<float>(std::stoul(hex.substr(1 + k * 2, 2), nullptr, 16)) / 255.0F;
  }
  return c;
}

}  // namespace

shape::Scene to_scene(const Program& program, const std::vector<Lot>& lots,
                      const std::vector<LotResult>& results) {
  shape::Scene scene;
  std::map<std::string, kernel::MaterialId> materials;
  for (std::size_t i = 0; i < results.size() && i < lots.size(); ++i) {
    const LotResult& r = results[i];
    shape::Building building;
    building.id = lots[i].id;
    building.attributes = r.attributes;
    for (std::size_t t = 0; t < r.terminals_store.size(); ++t) {
      const Terminal& term = r.terminals_store[t];
      const Materialized m = Engine::materialize(r.geometry[term.geometry], term.scope.size);
      if (!m.mesh || m.mesh->empty()) continue;
      shape::Part part;
      part.name = std::string(program.symbol_name(term.symbol));
      std::string color;
      for (std::uint32_t n = term.attrs; n != 0; n = r.attr_nodes[n].parent) {
        const AttrNode& node = r.attr_nodes[n];
        if (node.attr == program.color_attr) {
          if (color.empty()) color = std::get<std::string>(node.value);
          continue;
        }
        part.attributes.emplace(program.attrs[node.attr].name, node.value);  // nearest wins
      }
      part.mesh = shape::mesh_to_world(*m.mesh, term.scope);
      if (!color.empty()) {
        part.attributes["color"] = color;
        auto [it, inserted] = materials.emplace(color, 0);
        if (inserted) {
          it->second = static_cast<kernel::MaterialId>(scene.materials.size());
          scene.materials.push_back({color, rgba_of(color)});
        }
        for (std::size_t f = 0; f < part.mesh.face_count(); ++f)
          part.mesh.tag(f).material = it->second;
      }
      building.parts.push_back(std::move(part));
    }
    if (!building.parts.empty()) scene.buildings.push_back(std::move(building));
  }
  return scene;
}

}  // namespace insula::lang::cga
