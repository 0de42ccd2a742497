// Static checks of a parsed PLaSM program that need no evaluation (docs/plasm-language.md,
// "Checks"): every name resolves (to a parameter, a WHERE local, a top-level DEF or a builtin of
// builtins.h; PSM301 suggests the nearest), no name is defined twice in one scope (PSM302-304),
// builtins of fixed arity get sequences of that length (PSM306), and no value binding depends on
// itself (PSM305). Top-level DEFs and WHERE locals are order-free: a name may be used before its
// definition, as the bindings are lazy.
#pragma once

#include <cstddef>
#include <vector>

#include "base/diagnostic.h"
#include "lang/plasm/ast.h"

namespace insula::lang::plasm {

struct CheckResult {
  std::vector<base::Diagnostic> diagnostics;  // sorted by position
  bool ok = false;
  std::size_t functions = 0;    // top-level DEFs with parameter groups
  std::size_t values = 0;       // top-level DEFs without
  std::size_t expressions = 0;  // top-level expression statements
};

// Checks `program` (parsed from `source`, used for positions). Never throws, never prints.
CheckResult check(const Program& program, const base::Source& source);

}  // namespace insula::lang::plasm
