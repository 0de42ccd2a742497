#include "lang/plasm/eval.h"

#include <cmath>
#include <cstddef>
#include <memory>
#include <new>
#include <utility>

#include "base/format.h"
#include "lang/plasm/eval_context.h"
#include "lang/plasm/geometry.h"

namespace insula::lang::plasm {

// Counts one level of nested evaluation for as long as it lives (PSM412).
struct DepthGuard {
  DepthGuard(Context& context, Range at) : context_(context), frame_(context.frame()) {
    if (++frame_.depth > context_.budgets_.depth) {
      --frame_.depth;
      context_.fail("PSM412",
                    text({"recursion deeper than ", std::to_string(context_.budgets_.depth),
                          " levels (the depth budget)"}),
                    at);
    }
  }
  ~DepthGuard() { --frame_.depth; }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;

 private:
  Context& context_;
  Frame& frame_;
};

namespace {

const char* op_text(Op op) {
  switch (op) {
    case Op::kAdd:
      return "+";
    case Op::kSub:
      return "-";
    case Op::kMul:
      return "*";
    case Op::kDiv:
      return "/";
    case Op::kPow:
      return "**";
    case Op::kCompose:
      return "~";
    case Op::kRepeat:
      return "#";
    case Op::kRepeatCat:
      return "##";
  }
  return "?";
}

Op op_of(const ValuePtr& v) {
  return static_cast<Op>(static_cast<int>(v->number()));
}

ValuePtr compose_fn(Context& c, const Function&, std::span<const ValuePtr> args, Range at) {
  return c.apply(args[0], c.apply(args[1], args[2], at), at);
}

ValuePtr construct_fn(Context& c, const Function&, std::span<const ValuePtr> args, Range at) {
  Sequence out;
  out.reserve(args.size() - 1);
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    out.push_back(c.apply(args[i], args.back(), at));
  return c.sequence(std::move(out), at);
}

ValuePtr if_fn(Context& c, const Function&, std::span<const ValuePtr> args, Range at) {
  const bool test = c.truth(c.apply(args[0], args[3], at), "the predicate of IF", at);
  return c.apply(test ? args[1] : args[2], args[3], at);
}

// (f op g):x is f:x op g:x; a number stands for the constant function.
ValuePtr lifted_fn(Context& c, const Function&, std::span<const ValuePtr> args, Range at) {
  const auto side = [&](const ValuePtr& v) {
    return v->is_function() ? c.apply(v, args[3], at) : v;
  };
  return c.binary(op_of(args[0]), side(args[1]), side(args[2]), at);
}

ValuePtr repeat_op_fn(Context& c, const Function&, std::span<const ValuePtr> args, Range at) {
  return repeat(c, args[1], args[2], op_of(args[0]) == Op::kRepeatCat, at);
}

// An infix operator used as a value: `+:<a, b, c>` folds from the left, `-:x` negates,
// `~:<f, g>` composes, `#:n:x` repeats, `##:n:<...>` repeats and concatenates.
ValuePtr operator_fn(Context& c, const Function& self, std::span<const ValuePtr> args, Range at) {
  const Op op = op_of(args[0]);
  const ValuePtr& x = args[1];
  if (op == Op::kRepeat || op == Op::kRepeatCat)
    return c.native(self.label, 3, repeat_op_fn, Sequence{args[0], x}, at);
  if (op == Op::kSub && x->is_number()) return c.result(-x->number(), "-", at);
  const Sequence& items = c.seq(x, self.label, at);
  if (items.empty()) c.fail("PSM407", text({"'", self.label, "' of an empty sequence"}), at);
  if (op == Op::kSub && items.size() == 1) return c.binary(op, make_number(0), items[0], at);
  ValuePtr acc = items[0];
  for (std::size_t i = 1; i < items.size(); ++i) acc = c.binary(op, acc, items[i], at);
  return acc;
}

}  // namespace

std::string text(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view part : parts) out.append(part);
  return out;
}

void Context::fail(const char* code, std::string message, Range at) const {
  throw EvalError{base::Diagnostic::error(code, std::move(message), span_of(source_, at))};
}

std::string Context::text_of(Range range) const {
  const std::string& text = source_.text();
  if (range.begin >= range.end || range.end > text.size()) return {};
  return text.substr(range.begin, range.end - range.begin);
}

const ValuePtr* Context::memo(NativeFn fn, const ValuePtr& a, const ValuePtr& b) {
  const NativeMemoKey key{fn, a.get(), b.get()};
  for (const Frame* f = &frame(); f != nullptr; f = f->parent) {
    const auto it = f->natives.find(key);
    if (it != f->natives.end()) return &it->second.result;
  }
  return nullptr;
}

ValuePtr Context::remember(NativeFn fn, const ValuePtr& a, const ValuePtr& b, ValuePtr result) {
  frame().natives[{fn, a.get(), b.get()}] = NativeMemo{a, b, result};
  return result;
}

void Context::step(Range at) {
  Frame& f = frame();
  if (f.base_steps + ++f.steps > budgets_.steps)
    fail("PSM411",
         text({"evaluation takes more than ", std::to_string(budgets_.steps),
               " steps (the step budget)"}),
         at);
  if ((f.steps & 4095U) == 0 && budgets_.stop && budgets_.stop())
    fail("PSM419", "evaluation interrupted", at);
}

void Context::charge(double cells, Range at) {
  Frame& f = frame();
  const std::uint64_t used = std::min(f.base_cells + f.cells, budgets_.cells);
  if (cells > static_cast<double>(budgets_.cells - used))
    fail("PSM413",
         text({"evaluation needs more than ", std::to_string(budgets_.cells),
               " cells of memory (the memory budget)"}),
         at);
  f.cells += static_cast<std::uint64_t>(cells);
}

ValuePtr Context::shallow(ValuePtr value, Range at) const {
  if (value->depth > budgets_.nesting)
    fail("PSM413",
         text({"a value nests deeper than ", std::to_string(budgets_.nesting),
               " levels (the nesting budget)"}),
         at);
  return value;
}

ValuePtr Context::sequence(Sequence elements, Range at) {
  charge(static_cast<double>(elements.size() + 1), at);
  return shallow(make_sequence(std::move(elements)), at);
}

ValuePtr Context::function(Function function, Range at) {
  charge(static_cast<double>(function.bound.size() + 1), at);
  return shallow(make_function(std::move(function)), at);
}

ValuePtr Context::native(std::string label, std::size_t arity, NativeFn fn, Sequence bound,
                         Range at) {
  Function f;
  f.label = std::move(label);
  f.native = fn;
  f.arity = arity;
  f.captured = bound.size();
  f.bound = std::move(bound);
  return function(std::move(f), at);
}

Env* Context::new_env(Env* parent, std::size_t bindings, Range at) {
  charge(static_cast<double>(bindings + 1), at);
  auto owned = std::make_unique<Env>();
  Env* env = owned.get();
  env->serial = next_serial_++;
  {
    const std::lock_guard<std::mutex> lock(envs_mutex_);
    envs_.push_back(std::move(owned));
  }
  env->parent = parent;
  env->bindings.reserve(bindings);
  return env;
}

double Context::number(const ValuePtr& v, std::string_view who, Range at) const {
  if (!v->is_number())
    fail("PSM402",
         text({"'", std::string(who), "' needs a number, found ", kind_name(v->kind()), " ",
               summary(*v)}),
         at);
  return v->number();
}

const Sequence& Context::seq(const ValuePtr& v, std::string_view who, Range at) const {
  if (!v->is_sequence())
    fail("PSM402",
         text({"'", std::string(who), "' needs a sequence, found ", kind_name(v->kind()), " ",
               summary(*v)}),
         at);
  return v->sequence();
}

const Sequence& Context::seq_of(const ValuePtr& v, std::size_t count, std::string_view who,
                                Range at) const {
  const Sequence& s = seq(v, who, at);
  if (s.size() != count)
    fail("PSM404",
         text({"'", std::string(who), "' takes a sequence of ", std::to_string(count),
               " values, found ", std::to_string(s.size())}),
         at);
  return s;
}

bool Context::truth(const ValuePtr& v, std::string_view who, Range at) const {
  if (!v->is_bool())
    fail("PSM409",
         text({std::string(who), " must give TRUE or FALSE, found ", kind_name(v->kind()), " ",
               summary(*v)}),
         at);
  return v->boolean();
}

ValuePtr Context::result(double value, std::string_view who, Range at) const {
  if (!std::isfinite(value))
    fail("PSM406", text({"'", std::string(who), "' gives no finite number here"}), at);
  return make_number(value);
}

ValuePtr Context::binary(Op op, const ValuePtr& a, const ValuePtr& b, Range at) {
  const char* name = op_text(op);
  if (op == Op::kCompose) {
    if (!a->is_function() || !b->is_function())
      fail("PSM402",
           text({std::string("'~' composes functions, found "), kind_name(a->kind()), " and ",
                 kind_name(b->kind())}),
           at);
    return native("~", 3, compose_fn, Sequence{a, b}, at);
  }
  if (a->is_number() && b->is_number()) {
    const double x = a->number();
    const double y = b->number();
    switch (op) {
      case Op::kAdd:
        return result(x + y, name, at);
      case Op::kSub:
        return result(x - y, name, at);
      case Op::kMul:
        return result(x * y, name, at);
      case Op::kDiv:
        if (y == 0.0) fail("PSM405", "division by zero", at);
        return result(x / y, name, at);
      case Op::kPow:
        return result(std::pow(x, y), name, at);
      default:
        break;
    }
  }
  const bool numeric = op != Op::kRepeat && op != Op::kRepeatCat;
  if (numeric && (a->is_function() || b->is_function()) && (a->is_function() || a->is_number()) &&
      (b->is_function() || b->is_number()))
    return native(name, 4, lifted_fn, Sequence{make_number(static_cast<int>(op)), a, b}, at);
  if (a->is_polyhedron() && b->is_polyhedron() &&
      (op == Op::kAdd || op == Op::kSub || op == Op::kMul))
    return polyhedron_binary(*this, op, a, b, at);
  fail("PSM402",
       text({std::string("'"), name, "' needs numbers or functions, found ", kind_name(a->kind()),
             " ", summary(*a), " and ", kind_name(b->kind()), " ", summary(*b)}),
       at);
}

ValuePtr Context::lookup(const std::string& key, const std::string& written, Env* env, Range at) {
  for (Env* e = env; e != nullptr; e = e->parent) {
    for (Binding& b : e->bindings)
      if (b.key == key) return force(b, e, at);
  }
  if (ValuePtr c = find_constant(key)) return c;
  if (const Native* n = find_native(key))
    return native(std::string(n->name), n->arity, n->fn, {}, at);
  fail("PSM301", text({"unknown name '", written, "'"}), at);
}

ValuePtr Context::force(Binding& binding, Env* env, Range at) {
  if (binding.state == Binding::State::kDone) return binding.value;
  Frame& f = frame();
  if (env->serial < f.first_serial) return force_shared(binding, env, f, at);
  const Def& def = *binding.def;
  if (binding.state == Binding::State::kBusy)
    fail("PSM408",
         text({"the value of '", def.name, "' depends on itself (found while evaluating it)"}), at);
  if (!def.is_function()) binding.state = Binding::State::kBusy;
  try {
    binding.value = binding_value(binding, env, at);
  } catch (...) {
    binding.state = Binding::State::kPending;
    throw;
  }
  binding.state = Binding::State::kDone;
  return binding.value;
}

// The value a DEF or WHERE local binds: its closure, or its body evaluated in a scope of its
// own locals.
ValuePtr Context::binding_value(Binding& binding, Env* env, Range at) {
  const Def& def = *binding.def;
  if (def.is_function()) {
    Function f;
    f.label = def.name;
    f.def = &def;
    f.env = env;
    f.arity = def.groups.size();
    return function(std::move(f), at);
  }
  Env* scope = env;
  if (!def.locals.empty()) {
    scope = new_env(env, def.locals.size(), def.range);
    for (const Def& local : def.locals)
      scope->bindings.push_back(Binding{local.key, &local, {}, {}});
  }
  return labelled(eval(*def.body, scope), def, env == &top_);
}

ValuePtr Context::eval(const Expr& expr, Env* env) {
  step(expr.range);
  DepthGuard guard(*this, expr.range);
  switch (expr.kind) {
    case ExprKind::kNumber:
      return make_number(expr.number);
    case ExprKind::kString:
      return make_string(expr.text);
    case ExprKind::kName:
      return lookup(expr.key, expr.text, env, expr.range);
    case ExprKind::kOperator:
      return native(op_text(expr.op), 2, operator_fn,
                    Sequence{make_number(static_cast<int>(expr.op))}, expr.range);
    case ExprKind::kApply: {
      ValuePtr f = eval(*expr.operands[0], env);
      ValuePtr x = eval(*expr.operands[1], env);
      return apply(f, x, expr.range);
    }
    case ExprKind::kCompose:
    case ExprKind::kBinary: {
      ValuePtr a = eval(*expr.operands[0], env);
      ValuePtr b = eval(*expr.operands[1], env);
      return binary(expr.kind == ExprKind::kCompose ? Op::kCompose : expr.op, a, b, expr.range);
    }
    case ExprKind::kConstruct:
    case ExprKind::kSequence: {
      Sequence items;
      eval_items(expr, env, items);
      if (expr.kind == ExprKind::kSequence) return sequence(std::move(items), expr.range);
      for (std::size_t i = 0; i < items.size(); ++i) {
        if (!items[i]->is_function())
          fail("PSM402",
               text({"a construction [...] holds functions, found ", kind_name(items[i]->kind()),
                     " ", summary(*items[i])}),
               expr.operands[i]->range);
      }
      const std::size_t n = items.size();
      return native(text({"[", std::to_string(n), "]"}), n + 1, construct_fn, std::move(items),
                    expr.range);
    }
    case ExprKind::kRange: {
      ValuePtr from = eval(*expr.operands[0], env);
      ValuePtr to = eval(*expr.operands[1], env);
      return fromto(*this, from, to, "..", expr.range);
    }
    case ExprKind::kInfix: {
      ValuePtr f = lookup(expr.key, expr.text, env, expr.name_range);
      ValuePtr a = eval(*expr.operands[0], env);
      ValuePtr b = eval(*expr.operands[1], env);
      return apply(f, sequence(Sequence{a, b}, expr.range), expr.range);
    }
    case ExprKind::kIf: {
      Sequence parts;
      for (const ExprPtr& e : expr.operands) parts.push_back(eval(*e, env));
      return native("IF", 4, if_fn, std::move(parts), expr.range);
    }
  }
  fail("PSM402", "unknown expression", expr.range);
}

ValuePtr Context::apply(const ValuePtr& fv, const ValuePtr& x, Range at) {
  step(at);
  DepthGuard guard(*this, at);
  if (!fv->is_function())
    fail(
        "PSM401",
        text({"cannot apply ", kind_name(fv->kind()), " ", summary(*fv), ": it is not a function"}),
        at);
  const Function& f = fv->function();
  if (f.def != nullptr) return call(fv, x, at);
  if (f.bound.size() + 1 < f.arity) {
    Function partial = f;
    partial.bound.push_back(x);
    return function(std::move(partial), at);
  }
  // The arguments on the stack: MAP applies coordinate functions (compositions, lifted
  // operators, Bezier maps: a handful of arguments each) at every point of a domain.
  // Only the slots in use are constructed (an array of eight would clear and release all).
  constexpr std::size_t kOnStack = 8;
  if (f.bound.size() < kOnStack) {
    alignas(ValuePtr) std::byte storage[kOnStack * sizeof(ValuePtr)];
    auto* args = reinterpret_cast<ValuePtr*>(storage);
    const std::size_t n = f.bound.size() + 1;
    std::uninitialized_copy(f.bound.begin(), f.bound.end(), args);
    new (args + n - 1) ValuePtr(x);
    struct Release {
      ValuePtr* args;
      std::size_t n;
      ~Release() { std::destroy_n(args, n); }
    } release{args, n};
    return f.native(*this, f, std::span<const ValuePtr>(args, n), at);
  }
  Sequence args = f.bound;
  args.push_back(x);
  return f.native(*this, f, args, at);
}

// Binds the names of parameter group `group` of `def` to `argument` in `env`: one name takes the
// argument itself, several take the elements of a sequence of that length.
void Context::bind_group(Env* env, const Def& def, std::size_t group, const ValuePtr& argument,
                         Range at) {
  std::vector<const Param*> names;
  for (const ParamDecl& decl : def.groups[group].decls)
    for (const Param& p : decl.names) names.push_back(&p);
  if (names.size() == 1) {
    env->bindings.push_back(Binding{names[0]->key, nullptr, argument, Binding::State::kDone});
    return;
  }
  if (!argument->is_sequence() || argument->sequence().size() != names.size())
    fail("PSM404",
         text({"'", def.name, "' takes a sequence of ", std::to_string(names.size()),
               " values for its parameters ", text_of(def.groups[group].range), ", found ",
               kind_name(argument->kind()), " ", summary(*argument)}),
         at);
  for (std::size_t i = 0; i < names.size(); ++i)
    env->bindings.push_back(
        Binding{names[i]->key, nullptr, argument->sequence()[i], Binding::State::kDone});
}

// Runs the predicates of group `group`, whose names are bound in `bound`; they see the earlier
// groups (`earlier`) and the definition's scope, not their own group.
void Context::check_group(const Def& def, std::size_t group, Env* earlier, Env* bound, Range at) {
  std::size_t index = 0;
  for (const ParamDecl& decl : def.groups[group].decls) {
    if (!decl.predicate) {
      index += decl.names.size();
      continue;
    }
    const ValuePtr predicate = eval(*decl.predicate, earlier);
    for (const Param& p : decl.names) {
      const ValuePtr& value = bound->bindings[index++].value;
      const std::string who =
          text({"the predicate ", text_of(decl.predicate->range), " of '", p.text, "'"});
      if (!truth(apply(predicate, value, at), who, at))
        fail("PSM403",
             text({"'", def.name, "': parameter '", p.text, "' must satisfy ",
                   text_of(decl.predicate->range), ", found ", summary(*value)}),
             at);
    }
  }
}

ValuePtr Context::call(const ValuePtr& closure, const ValuePtr& x, Range at) {
  const Function& f = closure->function();
  const Def& def = *f.def;
  const std::size_t group = f.bound.size();
  Env* params = new_env(f.env, 8, at);
  for (std::size_t g = 0; g < group; ++g) bind_group(params, def, g, f.bound[g], at);
  Env* mine = new_env(params, 4, at);
  bind_group(mine, def, group, x, at);
  check_group(def, group, params, mine, at);
  if (group + 1 < def.groups.size()) {
    Function partial = f;
    partial.bound.push_back(x);
    return function(std::move(partial), at);
  }
  Env* scope = mine;
  if (!def.locals.empty()) {
    scope = new_env(mine, def.locals.size(), def.range);
    for (const Def& local : def.locals)
      scope->bindings.push_back(Binding{local.key, &local, {}, {}});
  }
  return labelled(eval(*def.body, scope), def, f.env == &top_);
}

// A polyhedron a DEF or WHERE local gives carries its name, so the output names its parts
// (docs/plasm-language.md, "Output"); top-level DEFs name parts, locals only paths.
ValuePtr Context::labelled(ValuePtr value, const Def& def, bool top_level) {
  if (!value->is_polyhedron()) return value;
  return make_polyhedron(make_labelled(value->polyhedron(), def.name, top_level));
}

Evaluator::Evaluator(const Program& program, const base::Source& source, Budgets budgets)
    : program_(program), context_(std::make_unique<Context>(source, budgets)) {
  for (const Statement& s : program.statements)
    if (s.is_def) context_->top()->bindings.push_back(Binding{s.def.key, &s.def, {}, {}});
}

Evaluator::~Evaluator() = default;

namespace {

template <typename F>
base::Result<ValuePtr> guarded(F&& body) {
  try {
    return base::Result<ValuePtr>(body());
  } catch (const EvalError& e) {
    return base::Result<ValuePtr>::failure({e.diagnostic});
  }
}

}  // namespace

base::Result<ValuePtr> Evaluator::value_of(std::string_view name) {
  const std::string key = name_key(name);
  return guarded([&] {
    for (Binding& b : context_->top()->bindings)
      if (b.key == key) return context_->force(b, context_->top(), b.def->name_range);
    context_->fail("PSM301", text({"no top-level DEF named '", std::string(name), "'"}), {});
  });
}

base::Result<ValuePtr> Evaluator::statement(std::size_t index) {
  const Statement& s = program_.statements.at(index);
  if (s.is_def) return value_of(s.def.key);
  return guarded([&] { return context_->eval(*s.expr, context_->top()); });
}

base::Result<ValuePtr> Evaluator::apply(const ValuePtr& function, const ValuePtr& argument,
                                        Range at) {
  return guarded([&] { return context_->apply(function, argument, at); });
}

void Evaluator::set_outline_reader(OutlineReader reader) {
  context_->outline_reader = std::move(reader);
}

std::uint64_t Evaluator::steps_used() const {
  return context_->steps();
}

base::Result<std::string> value_summaries(const Program& program, const base::Source& source,
                                          Budgets budgets) {
  Evaluator evaluator(program, source, budgets);
  std::string out;
  for (std::size_t i = 0; i < program.statements.size(); ++i) {
    const Statement& s = program.statements[i];
    base::Result<ValuePtr> value = evaluator.statement(i);
    if (!value.ok()) return base::Result<std::string>::failure(value.diagnostics());
    out +=
        s.is_def ? s.def.name : text({"line ", std::to_string(source.locate(s.range.begin).first)});
    out += text({" = ", summary(*value.value()), "\n"});
  }
  return out;
}

}  // namespace insula::lang::plasm
