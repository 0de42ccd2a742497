// The concrete syntax of a CGA AST (seed 004 §VI): the model-to-text direction back to `.cga`,
// used by `insula transform --to cga` (after reading a BuildingGen XML) and by the round-trip
// and fuzz tests. The contract: parse(print(g)) succeeds and has the same AST dump as `g`
// (ast_dump.h) apart from source positions, for every grammar `parse` returns.
#pragma once

#include <string>

#include "lang/cga/ast.h"

namespace insula::lang::cga {

// The whole grammar as `.cga` text: attributes first, then each priority set with one rule per
// line (further alternatives on indented continuation lines). Ends with a newline. Expressions
// get only the parentheses their precedence needs; numbers use the shortest exact text.
std::string print(const Grammar& grammar);

// One expression on one line, e.g. `Shape.occ("all") == "none"`.
std::string print(const Expr& expr);

// The shortest decimal text that reads back to `value` (non-negative finite values only).
std::string number_text(double value);

// `text` as a CGA string literal with `"`, `\`, newline and tab escaped.
std::string string_literal(const std::string& text);

// True when `name` is a CGA identifier that is not a keyword (so it can name a symbol, a rule or
// an attribute).
bool is_identifier(const std::string& name);

}  // namespace insula::lang::cga
