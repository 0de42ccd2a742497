// Values of PLaSM (docs/plasm-language.md, "Evaluation"): numbers (double; an integer is a real),
// truth values, strings, sequences, functions and polyhedral complexes. Values are immutable and
// shared. A function is a closure over a DEF or a WHERE local (its parameter groups bound one
// argument at a time), or a native function (a builtin, a composition, a construction, a lifted
// operator) with the arguments it has received so far.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "lang/plasm/ast.h"

namespace insula::lang::plasm {

struct Value;
using ValuePtr = std::shared_ptr<const Value>;
using Sequence = std::vector<ValuePtr>;

class Context;  // the evaluator's state (eval_context.h)
struct Env;     // a scope of bindings, owned by the evaluator
struct Function;

// A native function receives itself, its bound arguments and the last one together; `at` is the
// application it runs for (for diagnostics).
using NativeFn = ValuePtr (*)(Context& context, const Function& self,
                              std::span<const ValuePtr> args, Range at);

struct Function {
  std::string label;  // the builtin's or definition's name, or the operator ("~", "[2]", "+")
  NativeFn native = nullptr;
  const Def* def = nullptr;  // closures: the definition, whose groups are the arguments
  Env* env = nullptr;        // closures: the scope the definition lives in
  std::size_t arity = 1;     // arguments taken before it runs (bound ones included)
  Sequence bound;
  // How many of `bound` make the function what it is (the f and g of f ~ g) rather than being
  // arguments it was applied to; summaries count only the latter.
  std::size_t captured = 0;
};

// A hierarchical polyhedral complex (polyhedron.h).
struct Polyhedron;

enum class Kind { kNumber, kBool, kString, kSequence, kFunction, kPolyhedron };

struct Value {
  std::variant<double, bool, std::string, Sequence, Function, std::shared_ptr<const Polyhedron>>
      data;
  // How deeply sequences and bound arguments nest inside this value; the evaluator bounds it, so
  // printing, comparing and destroying a value never recurse without limit.
  int depth = 0;

  Kind kind() const { return static_cast<Kind>(data.index()); }
  bool is_number() const { return kind() == Kind::kNumber; }
  bool is_bool() const { return kind() == Kind::kBool; }
  bool is_sequence() const { return kind() == Kind::kSequence; }
  bool is_function() const { return kind() == Kind::kFunction; }
  double number() const { return std::get<double>(data); }
  bool boolean() const { return std::get<bool>(data); }
  const std::string& string() const { return std::get<std::string>(data); }
  const Sequence& sequence() const { return std::get<Sequence>(data); }
  const Function& function() const { return std::get<Function>(data); }
  bool is_polyhedron() const { return kind() == Kind::kPolyhedron; }
  const std::shared_ptr<const Polyhedron>& polyhedron() const {
    return std::get<std::shared_ptr<const Polyhedron>>(data);
  }
};

ValuePtr make_number(double value);
ValuePtr make_bool(bool value);
ValuePtr make_string(std::string value);
ValuePtr make_sequence(Sequence elements);
ValuePtr make_function(Function function);
ValuePtr make_polyhedron(std::shared_ptr<const Polyhedron> polyhedron);

// "a number", "a sequence", ... for messages.
std::string kind_name(Kind kind);

// The value as the goldens show it: numbers in their shortest round-trip text, TRUE/FALSE,
// strings quoted, sequences `<1, 2, 3>` (the first 16 elements, then `... (n elements)`), functions
// `<function fact>` or, applied to fewer arguments than they take, `<function f, 1 of 2
// arguments>`, polyhedra `<polyhedron 3D, 6 cells>` (cells of every instance counted); nesting
// below 8 levels as `<...>`.
std::string summary(const Value& value);

// Deep equality: numbers, truth values, strings and sequences by value, functions by identity.
bool equal(const ValuePtr& a, const ValuePtr& b);

}  // namespace insula::lang::plasm
