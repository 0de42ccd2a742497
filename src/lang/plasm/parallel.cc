// Parallel evaluation (seed 002, §1: the model's generating expressions become "a dataflow network
// of concurrent threads" and the model "fragments ... generated independently"): the elements
// of a sequence <...> or construction [...] that apply functions, and AA over a sequence with a
// user function, are evaluated as tasks of a TBB parallel section. Values are immutable, so
// tasks share them freely; what tasks must not share is the memo of lazy bindings and the
// budgets' counters. Each task is a Frame: bindings of scopes older than the task are memoised
// in the task's own table (the parent adopts them after the join, first task first), steps and
// cells are counted from the parent's totals at the fork and added up after the join, and the
// error of the lowest failing index is the one reported. The same program therefore does the
// same work, meets the same budget errors and gives the same bytes for any number of threads.
#include <tbb/parallel_for.h>

#include <exception>
#include <optional>

#include "lang/plasm/eval_context.h"

namespace insula::lang::plasm {
namespace {

thread_local Frame* current_frame = nullptr;

// Sets the thread's frame for as long as it lives (TBB may run another task of this or another
// evaluator on a thread that waits in a parallel section).
class FrameScope {
 public:
  explicit FrameScope(Frame& frame) : saved_(current_frame) { current_frame = &frame; }
  ~FrameScope() { current_frame = saved_; }
  FrameScope(const FrameScope&) = delete;
  FrameScope& operator=(const FrameScope&) = delete;

 private:
  Frame* saved_;
};

// Elements worth a task: applications (of functions, infix functions) may do any amount of work;
// names, literals, ranges and operators are evaluated in place.
bool worth_a_task(const Expr& e) {
  return e.kind == ExprKind::kApply || e.kind == ExprKind::kInfix;
}

}  // namespace

Frame& Context::frame() {
  Frame* f = current_frame;
  return f != nullptr && f->context == this ? *f : root_;
}

ValuePtr Context::force_shared(Binding& binding, Env* env, Frame& frame, Range at) {
  const Def& def = *binding.def;
  const auto cycle = [&] {
    fail("PSM408",
         text({"the value of '", def.name, "' depends on itself (found while evaluating it)"}), at);
  };
  // Only the tasks' ancestors, waiting at their forks, may have marked it busy.
  if (binding.state == Binding::State::kBusy) cycle();
  for (const Frame* f = &frame; f != nullptr; f = f->parent) {
    const auto it = f->memo.find(&binding);
    if (it == f->memo.end()) continue;
    if (it->second.state == Binding::State::kBusy) cycle();
    return it->second.value;
  }
  frame.memo[&binding] = Frame::Memo{Binding::State::kBusy, {}, env};
  ValuePtr value;
  try {
    value = binding_value(binding, env, at);
  } catch (...) {
    frame.memo.erase(&binding);
    throw;
  }
  frame.memo[&binding] = Frame::Memo{Binding::State::kDone, value, env};
  return value;
}

Sequence Context::parallel(std::size_t n, const std::function<ValuePtr(std::size_t)>& task,
                           Range at) {
  Frame& parent = frame();
  std::vector<Frame> frames(n);
  const std::uint64_t first_serial = next_serial_.load();
  for (Frame& f : frames) {
    f.parent = &parent;
    f.context = this;
    f.first_serial = first_serial;
    f.base_steps = parent.base_steps + parent.steps;
    f.base_cells = parent.base_cells + parent.cells;
    f.depth = parent.depth;
  }
  Sequence results(n);
  std::vector<std::optional<EvalError>> errors(n);
  std::vector<std::exception_ptr> failures(n);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, n, 1),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const FrameScope scope(frames[i]);
          try {
            results[i] = task(i);
          } catch (const EvalError& e) {
            errors[i] = e;
          } catch (...) {
            failures[i] = std::current_exception();
          }
        }
      },
      tbb::simple_partitioner());
  // The join: counts added up, memos adopted in task order (equal bindings give equal values).
  for (Frame& f : frames) {
    parent.steps += f.steps;
    parent.cells += f.cells;
    for (auto& [key, entry] : f.natives) parent.natives.emplace(key, std::move(entry));
    for (auto& [binding, memo] : f.memo) {
      if (memo.state != Binding::State::kDone) continue;
      auto& b = const_cast<Binding&>(*binding);
      if (memo.env->serial >= parent.first_serial) {
        if (b.state == Binding::State::kPending) {
          b.value = memo.value;
          b.state = Binding::State::kDone;
        }
      } else {
        parent.memo.emplace(binding, memo);
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (failures[i]) std::rethrow_exception(failures[i]);
    if (errors[i]) throw *errors[i];
  }
  if (parent.base_steps + parent.steps > budgets_.steps)
    fail("PSM411",
         text({"evaluation takes more than ", std::to_string(budgets_.steps),
               " steps (the step budget)"}),
         at);
  if (parent.base_cells + parent.cells > budgets_.cells)
    fail("PSM413",
         text({"evaluation needs more than ", std::to_string(budgets_.cells),
               " cells of memory (the memory budget)"}),
         at);
  return results;
}

void Context::eval_items(const Expr& expr, Env* env, Sequence& items) {
  const std::size_t n = expr.operands.size();
  std::vector<std::size_t> heavy;
  for (std::size_t i = 0; i < n; ++i)
    if (worth_a_task(*expr.operands[i])) heavy.push_back(i);
  items.assign(n, nullptr);
  if (heavy.size() < 2) {
    for (std::size_t i = 0; i < n; ++i) items[i] = eval(*expr.operands[i], env);
    return;
  }
  // Light elements in place, their first error kept for its position in the sequence.
  std::optional<std::pair<std::size_t, EvalError>> light_error;
  for (std::size_t i = 0; i < n; ++i) {
    if (worth_a_task(*expr.operands[i])) continue;
    try {
      items[i] = eval(*expr.operands[i], env);
    } catch (const EvalError& e) {
      light_error.emplace(i, e);
      break;
    }
  }
  const std::size_t limit = light_error ? light_error->first : n;
  std::vector<std::size_t> run;
  for (std::size_t i : heavy)
    if (i < limit) run.push_back(i);
  // A task's error comes first when its element precedes the failing light one (run holds only
  // those).
  const Sequence done = parallel(
      run.size(), [&](std::size_t k) { return eval(*expr.operands[run[k]], env); }, expr.range);
  for (std::size_t k = 0; k < run.size(); ++k) items[run[k]] = done[k];
  if (light_error) throw light_error->second;
}

}  // namespace insula::lang::plasm
