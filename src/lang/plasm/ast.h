// Abstract syntax of PLaSM (seed 002; docs/plasm-language.md): a program is a list of statements,
// each a definition `DEF name (group)... = body WHERE locals END;` or an expression. Every node
// keeps the byte range of its source text; `span_of` turns one into a base::Span for diagnostics.
// Names keep their written spelling (`text`, for messages) and a case-folded `key` (upper case),
// since PLaSM identifiers are case-insensitive.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"

namespace insula::lang::plasm {

// Half-open byte range [begin, end) in the source text.
struct Range {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
};

base::Span span_of(const base::Source& source, Range range);

// The case-folded key of an identifier: PLaSM reads `Bezier`, `BEZIER` and `bezier` as one name.
std::string name_key(std::string_view text);

enum class ExprKind {
  kNumber,     // number (an integer is a real)
  kString,     // text, escapes resolved
  kName,       // text as written, key
  kOperator,   // op: an infix operator used as a value (`AA:-`, `C:*:(PI/6)`), or `#`, `##`
  kApply,      // operands[0] : operands[1]
  kCompose,    // operands[0] ~ operands[1]
  kConstruct,  // [operands...]
  kSequence,   // <operands...>
  kRange,      // operands[0] .. operands[1]
  kBinary,     // op, operands[0] and operands[1]
  kInfix,      // `a NAME b`: text/key name the function (at name_range), operands[0], operands[1]
  kIf,         // IF:<operands[0], operands[1], operands[2]>
};

enum class Op { kAdd, kSub, kMul, kDiv, kPow, kCompose, kRepeat, kRepeatCat };

struct Expr {
  ExprKind kind = ExprKind::kNumber;
  Range range;
  double number = 0.0;
  std::string text;
  std::string key;
  Op op = Op::kAdd;
  Range name_range;  // kInfix: the function name
  std::vector<std::unique_ptr<Expr>> operands;
};

using ExprPtr = std::unique_ptr<Expr>;

struct Param {
  std::string text;
  std::string key;
  Range range;
};

// `a, b :: IsReal`: the names share the predicate; predicate is null when no `::` is written.
struct ParamDecl {
  std::vector<Param> names;
  ExprPtr predicate;
};

// One parenthesised group of a curried definition; `;` separates its declarations.
struct ParamGroup {
  Range range;
  std::vector<ParamDecl> decls;
};

// A binding: a top-level `DEF` or a WHERE local. Without groups it is a value binding, with
// groups a function of as many curried arguments as it has groups.
struct Def {
  Range range;
  std::string name;
  std::string key;
  Range name_range;
  std::vector<ParamGroup> groups;
  ExprPtr body;
  bool has_where = false;
  std::vector<Def> locals;

  bool is_function() const { return !groups.empty(); }
};

// A top-level statement: a definition, or an expression whose value the program produces.
struct Statement {
  Range range;
  bool is_def = false;
  Def def;
  ExprPtr expr;
};

struct Program {
  std::string file;
  std::vector<Statement> statements;
};

}  // namespace insula::lang::plasm
