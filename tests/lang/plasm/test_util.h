// Helpers shared by the PLaSM front-end tests.
#pragma once

#include <filesystem>
#include <string>

#include "../../common/test_util.h"
#include "base/diagnostic.h"
#include "lang/plasm/ast_dump.h"
#include "lang/plasm/checker.h"
#include "lang/plasm/eval.h"
#include "lang/plasm/output.h"
#include "lang/plasm/parser.h"

namespace insula::lang::plasm::testing {

inline std::filesystem::path data_dir() {
  return std::filesystem::path(INSULA_TEST_DATA) / "plasm";
}
inline std::filesystem::path examples_dir() {
  return std::filesystem::path(INSULA_SOURCE_DIR) / "examples" / "plasm";
}

using insula::test::files_in;
using insula::test::read_file;

// The first diagnostic of parsing and then checking `text` as `name`, rendered without source
// lines; empty when both pass.
inline std::string first_error(const std::string& text, const std::string& name = "t.psm") {
  const base::Source source(name, text);
  const auto result = parse(source);
  if (!result.ok()) return base::render(result.diagnostics().front());
  const CheckResult checked = check(result.value(), source);
  if (checked.diagnostics.empty()) return {};
  return base::render(checked.diagnostics.front());
}

// As first_error, then evaluating every statement in order (value_summaries).
inline std::string first_run_error(const std::string& text, const std::string& name = "t.psm",
                                   Budgets budgets = {}) {
  const base::Source source(name, text);
  const auto result = parse(source);
  if (!result.ok()) return base::render(result.diagnostics().front());
  const CheckResult checked = check(result.value(), source);
  if (!checked.diagnostics.empty()) return base::render(checked.diagnostics.front());
  const auto values = value_summaries(result.value(), source, budgets);
  if (!values.ok()) return base::render(values.diagnostics().front());
  return {};
}

// As first_run_error, then converting the program's polyhedra as `insula build` does
// (program_scene: PSM420 when nothing is drawn).
inline std::string first_build_error(const std::string& text, const std::string& name = "t.psm",
                                     Budgets budgets = {}) {
  if (std::string error = first_run_error(text, name, budgets); !error.empty()) return error;
  const base::Source source(name, text);
  const auto result = parse(source);
  const auto scene = program_scene(result.value(), source, budgets);
  if (!scene.ok()) return base::render(scene.diagnostics().front());
  return {};
}

// The value summary of the top-level DEF `name` of `text` (a whole program), or its first error.
inline std::string value_of(const std::string& text, const std::string& name,
                            Budgets budgets = {}) {
  const base::Source source("t.psm", text);
  const auto result = parse(source);
  if (!result.ok()) return "error: " + base::render(result.diagnostics().front());
  const CheckResult checked = check(result.value(), source);
  if (!checked.diagnostics.empty()) return "error: " + base::render(checked.diagnostics.front());
  Evaluator evaluator(result.value(), source, budgets);
  const auto value = evaluator.value_of(name);
  if (!value.ok()) return base::render(value.diagnostics().front());
  return summary(*value.value());
}

// The one-line dump of the expression of `text`, a single expression statement (`;` appended).
inline std::string expr_dump(const std::string& text) {
  const base::Source source("t.psm", text + ";");
  const auto result = parse(source);
  if (!result.ok()) return "error: " + base::render(result.diagnostics().front());
  if (result->statements.size() != 1 || result->statements[0].is_def) return "not one expression";
  return dump(*result->statements[0].expr);
}

}  // namespace insula::lang::plasm::testing
