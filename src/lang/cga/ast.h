// Abstract syntax of the CGA shape grammar language (seed 004, §III and §VI). The AST is the
// metamodel of §IV: ShapeGrammar -> PrioritySet -> ProductionRule -> RulePart (alternative) ->
// successor items (shapes, scope rules, basic/repeat/component splits). Every node keeps the byte
// range of the source text it came from; `span_of` turns a range into a base::Span when a
// diagnostic needs one (a file name string per node would dominate the memory of large grammars).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "base/diagnostic.h"

namespace insula::lang::cga {

// Half-open byte range [begin, end) in the source text.
struct Range {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
};

// The span of `range` in `source` (1-based line and byte column of both ends).
base::Span span_of(const base::Source& source, Range range);

enum class ExprKind {
  kNumber,  // number
  kString,  // text (escapes resolved)
  kBool,    // boolean
  kIdent,   // text: a name (attribute, parameter, or a bare word such as an axis)
  kMember,  // operands[0].text: `Shape.sx`
  kCall,    // operands[0] is the callee (identifier or member), operands[1..] the arguments
  kUnary,   // unary_op, operands[0]
  kBinary,  // binary_op, operands[0] and operands[1]
};

// kRelative is `2r` (§II: size proportional to the scope), kFloating is `~2` (a size that
// stretches to fill the remainder, as CityEngine's floating sizes).
enum class UnaryOp { kNot, kNegate, kRelative, kFloating };
enum class BinaryOp { kOr, kAnd, kEq, kNe, kLt, kLe, kGt, kGe, kAdd, kSub, kMul, kDiv, kMod };

struct Expr {
  ExprKind kind = ExprKind::kNumber;
  Range range;
  double number = 0.0;
  bool boolean = false;
  std::string text;
  UnaryOp unary_op = UnaryOp::kNot;
  BinaryOp binary_op = BinaryOp::kOr;
  std::vector<std::unique_ptr<Expr>> operands;
};

using ExprPtr = std::unique_ptr<Expr>;

// Operations recognised by name. The paper's spellings and their long forms map to one kind:
// BS/Subdiv -> kSplit, RR/Repeat -> kRepeat, CS/Comp -> kComp, T -> kTranslate, S -> kScale,
// Rx/Ry/Rz -> kRotate, I -> kInsert, Pshape -> kPredefined. Every other name is kGeneric
// (extrude, roof operations, offset, setback, color, print, ...), resolved by the checker.
enum class OpKind {
  kSplit,
  kRepeat,
  kComp,
  kTranslate,
  kScale,
  kRotate,
  kInsert,
  kPredefined,
  kGeneric
};

enum class ItemKind { kSymbol, kEmpty, kPush, kPop, kOp };

struct Branch;

// One element of a successor sequence: a shape symbol, ε, `[`, `]`, or an operation.
struct Item {
  ItemKind kind = ItemKind::kSymbol;
  Range range;
  std::string name;  // symbol, or the operation name as written
  OpKind op = OpKind::kGeneric;
  char axis = 0;  // kRotate: 'x', 'y' or 'z'
  std::vector<ExprPtr> args;
  bool has_block = false;  // `{ ... }` written after the arguments
  std::vector<Branch> branches;
};

// One `|`-separated part of an operation block. `key` is the text before `:` when present: a
// size (`2: A`, `~1: B`) or a component selector (`front: Door`). A repeat pattern `{ A | B }*`
// has repeat = true and its parts in `pattern` instead of items.
struct Branch {
  Range range;
  ExprPtr key;
  bool repeat = false;
  std::vector<Branch> pattern;
  std::vector<Item> items;
};

// A RulePart of the metamodel: `~> successor : probability`.
struct Alternative {
  Range range;
  std::string arrow;  // "~>", "->" or "-->" as written
  std::vector<Item> items;
  ExprPtr probability;  // null when omitted
};

struct Rule {
  Range range;
  std::string id;  // as written ("3", "r12"); empty for an unnamed `Pred --> ...` rule
  Range id_range;
  std::string predecessor;
  Range predecessor_range;
  ExprPtr condition;  // null when omitted
  std::vector<Alternative> alternatives;
};

struct PrioritySet {
  Range range;
  std::uint32_t priority = 1;
  bool implicit = false;  // rules written before any `PRIORITY n:` header
  std::vector<Rule> rules;
};

// `attr name = expr`: a grammar attribute with its default (overridable from outside).
struct AttrDecl {
  Range range;
  std::string name;
  Range name_range;
  ExprPtr value;
};

struct Grammar {
  std::string file;
  std::vector<AttrDecl> attrs;
  std::vector<PrioritySet> sets;
};

}  // namespace insula::lang::cga
