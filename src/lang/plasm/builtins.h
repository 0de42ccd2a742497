// The names every PLaSM program may use without defining them: the FL toolbox and the geometry
// library of issue 13 (docs/plasm-language.md, "Builtins"). This table is the one list the
// checker resolves names against and suggests from, and the evaluator implements each entry;
// docs/plasm-library.md is generated from it.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace insula::lang::plasm {

// Marks a builtin whose argument is not one literal sequence of a fixed length.
inline constexpr int kAnyArity = -1;

struct Builtin {
  std::string_view name;  // upper case, as the library reference spells it
  // How many elements the sequence it is applied to must have (`TRUNCONE:<r1, r2, h>` is 3;
  // `a AL b` passes <a, b>, so only arity 2 or kAnyArity may be used infix).
  int arity = kAnyArity;
  std::string_view summary;
};

std::span<const Builtin> builtins();

// The builtin named `key` (a case-folded name), or null.
const Builtin* find_builtin(std::string_view key);

// docs/plasm-library.md: every builtin with what it is applied to and its summary, as one
// Markdown table (tests/lang/plasm/library_doc_test.cc keeps the committed page up to date).
std::string library_reference_markdown();

}  // namespace insula::lang::plasm
