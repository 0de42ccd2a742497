// Parser of PLaSM (seed 002): the grammar of the original interpreter's parser as the paper's
// listings use it. The EBNF is at the top of parser.cc and in docs/plasm-language.md.
#pragma once

#include "base/diagnostic.h"
#include "lang/plasm/ast.h"

namespace insula::lang::plasm {

// Deepest nesting of parentheses, sequences, constructions, WHERE blocks and operator chains the
// parser accepts; deeper input gets PSM105 instead of exhausting the stack.
inline constexpr int kMaxNesting = 100;
// After this many errors the parser stops with PSM108.
inline constexpr int kMaxErrors = 50;

// Parses a whole `.psm` file. On success the program comes with no error diagnostics; otherwise
// the result is a failure holding every error found (the parser skips past the next `;` after
// each one), sorted by position. Never throws, never prints; any byte sequence is accepted.
base::Result<Program> parse(const base::Source& source);

}  // namespace insula::lang::plasm
