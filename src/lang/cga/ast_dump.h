// A deterministic S-expression text of a CGA AST, for golden tests and debugging. Every node
// shows its kind, its content and its start position `@line:col`; expressions are one line.
#pragma once

#include <string>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

// The dump of `grammar`, parsed from `source` (used to turn byte ranges into line:col).
// Ends with a newline. Numbers use the shortest text that reads back to the same double.
std::string dump(const Grammar& grammar, const base::Source& source);

// One expression as a single-line S-expression, e.g. `(== (call (. Shape occ) "all") "none")`.
std::string dump(const Expr& expr);

}  // namespace insula::lang::cga
