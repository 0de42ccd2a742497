// The PLaSM evaluator (docs/plasm-language.md, "Evaluation"): evaluates a program that parse()
// and check() accepted. Strict application, lazy memoised bindings (top-level DEFs and WHERE
// locals, order-free), arithmetic lifted pointwise to functions, the FL toolbox of builtins.
// Evaluation is bounded by Budgets; every runtime error is one positioned PSM4xx diagnostic.
// The builtins that make polyhedra are geometry.h's (docs/plasm-language.md, "Geometry").
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "lang/plasm/ast.h"
#include "lang/plasm/value.h"

namespace insula::lang::plasm {

struct Budgets {
  // Expression evaluations and function applications, in all (PSM411).
  std::uint64_t steps = 10'000'000;
  // Nested evaluations and applications at once: recursion depth (PSM412).
  int depth = 2'000;
  // Sequence elements and bindings created, in all: the memory budget (PSM413).
  std::uint64_t cells = 4'000'000;
  // How deeply sequences and partial applications may nest inside one value (PSM413).
  int nesting = 500;
  // Asked every 4096 steps; true stops the evaluation with PSM419 (the app's interrupt flag:
  // SIGINT during a long evaluation ends it within a few milliseconds, not at its end).
  std::function<bool()> stop;
};

// A drawing's outlines for SVG:"file.svg" (seed 002, §5): the app reads and parses the file
// (lang/plasm reads no files); coordinates as the drawing has them (SVG: y down).
struct Outline {
  std::string id;
  std::vector<double> xy;  // x0, y0, x1, y1, ...
  bool closed = false;
};
// Fills `out` with the outlines of `file`, or returns false with `error` set.
using OutlineReader =
    std::function<bool(const std::string& file, std::vector<Outline>& out, std::string& error)>;

// Evaluates the statements and DEFs of one program on demand; values stay valid as long as the
// evaluator (closures refer to its scopes). After an error the evaluator may still be asked
// for other values; the budgets are shared by everything it evaluates.
class Evaluator {
 public:
  Evaluator(const Program& program, const base::Source& source, Budgets budgets = {});
  ~Evaluator();
  Evaluator(const Evaluator&) = delete;
  Evaluator& operator=(const Evaluator&) = delete;

  // The value of the top-level DEF `name` (case-insensitive); a function DEF gives its closure.
  base::Result<ValuePtr> value_of(std::string_view name);
  // The value of statement `index` of the program (a DEF's value or an expression's).
  base::Result<ValuePtr> statement(std::size_t index);
  // `function:argument`, as the program would apply it (the error, if any, points at `at`).
  base::Result<ValuePtr> apply(const ValuePtr& function, const ValuePtr& argument, Range at = {});
  std::uint64_t steps_used() const;
  // Where SVG:"file" finds its outlines; without one, SVG fails with PSM417.
  void set_outline_reader(OutlineReader reader);

 private:
  const Program& program_;
  std::unique_ptr<Context> context_;
};

// The golden text of a program's values: one line per statement, `name = summary` for a DEF and
// `line N = summary` for an expression, in source order. Fails with the first runtime error.
base::Result<std::string> value_summaries(const Program& program, const base::Source& source,
                                          Budgets budgets = {});

}  // namespace insula::lang::plasm
