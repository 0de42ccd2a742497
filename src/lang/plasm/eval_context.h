// The evaluator's state, shared by eval.cc and the builtin implementations (toolbox.cc): scopes,
// budgets, and the helpers natives use to apply functions, build values and report errors.
// Internal to lang/plasm.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "base/diagnostic.h"
#include "lang/plasm/ast.h"
#include "lang/plasm/eval.h"
#include "lang/plasm/value.h"

namespace insula::lang::plasm {

// Messages are joined by appending: GCC 12 reports a false -Wrestrict on "x" + std::string chains.
std::string text(std::initializer_list<std::string_view> parts);

// Thrown inside the evaluator only; the Evaluator's entry points turn it into a failed Result.
struct EvalError {
  base::Diagnostic diagnostic;
};

// A name in a scope: a parameter (value set), or a DEF / WHERE local evaluated on first use.
struct Binding {
  enum class State { kPending, kBusy, kDone };
  std::string key;
  const Def* def = nullptr;
  ValuePtr value;
  State state = State::kPending;
};

struct Env {
  Env* parent = nullptr;
  std::vector<Binding> bindings;
  // Creation order: a task of a parallel section writes only the bindings of scopes created
  // since it started (parallel.cc).
  std::uint64_t serial = 0;
};

// A builtin's result remembered by the identity of its two arguments (Context::memo); holding the
// arguments keeps their addresses theirs.
struct NativeMemo {
  ValuePtr a, b, result;
};
using NativeMemoKey = std::tuple<NativeFn, const Value*, const Value*>;

// One strand of evaluation (parallel.cc, docs/plasm-language.md "Parallel evaluation"): the
// evaluator's own, or one task of a parallel section. A task counts its steps and cells from its
// parent's totals at the fork and keeps the values of bindings of older scopes in its own memo,
// so no two tasks write the same memory and every count is the same for any number of threads.
struct Frame {
  struct Memo {
    Binding::State state = Binding::State::kPending;
    ValuePtr value;
    Env* env = nullptr;
  };
  const Frame* parent = nullptr;
  const Context* context = nullptr;
  std::uint64_t first_serial = 0;  // scopes with a smaller serial are older than the task
  std::uint64_t base_steps = 0;
  std::uint64_t steps = 0;
  std::uint64_t base_cells = 0;
  std::uint64_t cells = 0;
  int depth = 0;
  std::unordered_map<const Binding*, Memo> memo;
  std::map<NativeMemoKey, NativeMemo> natives;  // Context::memo's entries made in this strand
};

inline Frame root_frame(const Context* context) {
  Frame f;
  f.context = context;
  return f;
}

// A builtin this stage implements. `arity` counts curried arguments: AA:f:x takes 2.
struct Native {
  std::string_view name;
  std::size_t arity;
  NativeFn fn;
};

// The implemented builtins (toolbox.cc); find_native gives null when `key` is none of them.
std::span<const Native> natives();
const Native* find_native(std::string_view key);
// PI, TRUE and FALSE; null for other keys.
ValuePtr find_constant(std::string_view key);

class Context;
// `#:n:x` is <x, ..., x> (n times); with `cat`, `##:n:s` concatenates n copies of the sequence s.
ValuePtr repeat(Context& context, const ValuePtr& n, const ValuePtr& x, bool cat, Range at);
// `from .. to`: the integers from `from` to `to` (empty when to < from); `who` names the caller.
ValuePtr fromto(Context& context, const ValuePtr& from, const ValuePtr& to, std::string_view who,
                Range at);

class Context {
 public:
  Context(const base::Source& source, Budgets budgets) : source_(source), budgets_(budgets) {}

  [[noreturn]] void fail(const char* code, std::string message, Range at) const;

  ValuePtr eval(const Expr& expr, Env* env);
  ValuePtr apply(const ValuePtr& function, const ValuePtr& argument, Range at);
  // `a op b` on numbers, lifted to functions (a number beside a function acts as a constant).
  ValuePtr binary(Op op, const ValuePtr& a, const ValuePtr& b, Range at);
  // The value of a name: a binding of `env` or an enclosing scope, else a builtin.
  ValuePtr lookup(const std::string& key, const std::string& text, Env* env, Range at);
  ValuePtr force(Binding& binding, Env* env, Range at);

  // Values built through the context count against the memory and nesting budgets.
  ValuePtr sequence(Sequence elements, Range at);
  ValuePtr function(Function function, Range at);
  ValuePtr native(std::string label, std::size_t arity, NativeFn fn, Sequence bound, Range at);
  Env* new_env(Env* parent, std::size_t bindings, Range at);
  // Counts `cells` against the memory budget before they are allocated (PSM413).
  void charge(double cells, Range at);

  // Argument checks shared by the builtins; they name `who` in the message.
  double number(const ValuePtr& v, std::string_view who, Range at) const;
  const Sequence& seq(const ValuePtr& v, std::string_view who, Range at) const;
  const Sequence& seq_of(const ValuePtr& v, std::size_t count, std::string_view who,
                         Range at) const;
  bool truth(const ValuePtr& v, std::string_view who, Range at) const;
  // A number checked to be finite (PSM406), for arithmetic results.
  ValuePtr result(double value, std::string_view who, Range at) const;

  // Results of an expensive pure builtin by the identity of its two arguments: values are
  // immutable, so the same function applied to the same values gives the same value, and a
  // program that maps one domain twice (Listing 6's Dome, for its ceiling and its body) maps it
  // once. Entries live in the strand that made them (a task sees its ancestors' and its own; the
  // parent adopts a task's at the join), so what a task finds never depends on the other tasks.
  const ValuePtr* memo(NativeFn fn, const ValuePtr& a, const ValuePtr& b);
  ValuePtr remember(NativeFn fn, const ValuePtr& a, const ValuePtr& b, ValuePtr result);

  std::string text_of(Range range) const;
  std::uint64_t steps() const { return root_.steps; }
  // Runs task(0), ..., task(n - 1) as a parallel section (TBB): each in its own Frame, results
  // in index order; the error of the lowest failing index is thrown after all have run
  // (parallel.cc).
  Sequence parallel(std::size_t n, const std::function<ValuePtr(std::size_t)>& task, Range at);
  // The strand this thread evaluates for this context.
  Frame& frame();
  OutlineReader outline_reader;  // for SVG (geometry.h); may be empty
  Env* top() { return &top_; }

 private:
  void step(Range at);
  ValuePtr shallow(ValuePtr value, Range at) const;  // PSM413 past the nesting budget
  ValuePtr call(const ValuePtr& closure, const ValuePtr& argument, Range at);
  void bind_group(Env* env, const Def& def, std::size_t group, const ValuePtr& argument, Range at);
  ValuePtr labelled(ValuePtr value, const Def& def, bool top_level);
  ValuePtr binding_value(Binding& binding, Env* env, Range at);
  ValuePtr force_shared(Binding& binding, Env* env, Frame& frame, Range at);
  void eval_items(const Expr& expr, Env* env, Sequence& items);
  void check_group(const Def& def, std::size_t group, Env* earlier, Env* bound, Range at);

  friend struct DepthGuard;
  const base::Source& source_;
  Budgets budgets_;
  Frame root_ = root_frame(this);
  Env top_;
  std::atomic<std::uint64_t> next_serial_{1};
  std::mutex envs_mutex_;
  std::vector<std::unique_ptr<Env>> envs_;
};

}  // namespace insula::lang::plasm
