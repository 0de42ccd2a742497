// A deterministic S-expression text of a PLaSM AST, for golden tests and debugging. Definitions
// and statements show their start position `@line:col`; expressions are one line each.
#pragma once

#include <string>
#include <string_view>

#include "base/diagnostic.h"
#include "lang/plasm/ast.h"

namespace insula::lang::plasm {

// The dump of `program`, parsed from `source` (used to turn byte ranges into line:col). Ends
// with a newline. Numbers use the shortest text that reads back to the same double.
std::string dump(const Program& program, const base::Source& source);

// One expression as a single-line S-expression, e.g. `(: (: T 3) (: - ceiling))`.
std::string dump(const Expr& expr);

// The name of an operator as written (`+`, `**`, `~`, `##`).
std::string_view op_name(Op op);

}  // namespace insula::lang::plasm
