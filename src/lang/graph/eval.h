// Evaluating checked expressions (graph-format.md §5) on run-time values. The executor supplies
// an EvalEnv: graph parameters, the current entity's attributes and properties, other input
// ports' entities and the random stream of (entity seed, node, parameter) of §9.9.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "lang/graph/expr.h"
#include "lang/graph/value.h"
#include "shape/rng.h"

namespace insula::lang::graph {

class EvalEnv {
 public:
  virtual ~EvalEnv() = default;
  // A graph parameter's value (the checker has made sure it exists).
  virtual Value parameter(const std::string& name) = 0;
  // `@name` of the current entity (`port` empty) or of the entity at input `port` this round:
  // its stored value, an ancestor's, or the declared default. nullopt: there is no such entity
  // (an evaluation error).
  virtual std::optional<Value> attribute(const std::string& port, const std::string& name) = 0;
  // An entity property function of §5 (area, perimeter, volume, sx, sy, sz, pos, centroid,
  // normal, type) on the current entity; nullopt with `error` set when it does not apply.
  virtual std::optional<Value> property(const std::string& name, std::string& error) = 0;
  // The stream rand(), rand(a,b) and randint(a,b) draw from (one per evaluation of a parameter).
  virtual shape::Rng& rng() = 0;
};

struct EvalError {
  std::string message;  // e.g. "division by zero", "index 3 is outside the list of 2"
  std::size_t at = 0;   // byte of the expression text at fault (Expr::at)
};

// Evaluates a checked expression. if() evaluates only its chosen branch; integer arithmetic that
// overflows, integer division or modulo by zero, an index out of range, a non-finite result and a
// math domain error (sqrt(-1)) are errors.
std::optional<Value> evaluate(const Expr& expr, EvalEnv& env, EvalError& error);

}  // namespace insula::lang::graph
