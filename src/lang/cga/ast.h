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
  // CityEngine's dialect (docs/cityengine-dialect.md §2):
  kCase,    // operands: condition, value, condition, value, ..., else value (odd count)
  kChance,  // operands: percentage, value, percentage, value, ..., else value (odd count)
  kArray,   // operands: the elements (`[1, 2, 3]`); boolean: `;` rows, each operand a kArray row
  kIndex,   // operands[0] indexed by operands[1] (`a[i]`) or operands[1], operands[2] (`a[r, c]`)
  kComp,    // comp function `comp(fe){ sel : v | sel = w }`: operands[0] the component type, then
            // selector, value, selector, value, ...; text: each branch's operator, ':' or '='
  kRange,   // the colon operator inside `[ ]`: base, limit (`1:5`) or base, step, limit (`1:2:9`)
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
  bool elementwise = false;  // CityEngine's `.==`, `.+`, ...: the operator per array element
  std::vector<std::unique_ptr<Expr>> operands;
};

using ExprPtr = std::unique_ptr<Expr>;

// `world.up.flatTop`, `material.color`, `x` as text: a name or a chain of member accesses on
// names; empty for any other expression.
std::string dotted_name(const Expr& expr);

// A deep copy of `expr` (an import's override given to the imported attribute keeps the
// importing file's model intact).
ExprPtr clone(const Expr& expr);

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

// kCase and kChance are CityEngine's conditional and stochastic successors
// (`case c : A else : B`, `30% : A else : B`): branches whose key is the condition or the
// percentage, the last one (`else`) without a key. They always end their sequence.
enum class ItemKind { kSymbol, kEmpty, kPush, kPop, kOp, kCase, kChance };

struct Branch;

// One element of a successor sequence: a shape symbol, ε, `[`, `]`, or an operation.
struct Item {
  ItemKind kind = ItemKind::kSymbol;
  Range range;
  std::string name;  // symbol, or the operation name as written
  OpKind op = OpKind::kGeneric;
  char axis = 0;              // kRotate: 'x', 'y' or 'z'
  std::vector<ExprPtr> args;  // operation arguments; a symbol's rule arguments (`Floor(3)`)
  bool has_block = false;     // `{ ... }` written after the arguments
  bool terminal = false;      // kSymbol written `Name.` (CityEngine: a leaf, no rule wanted)
  // CityEngine's `split(u|v, unitSpace|uvSpace, uvSet)`, read as split(x|y) (the checker warns).
  bool along_uv = false;
  // CityEngine roof arguments Insula does not run, dropped by the parser (the checker warns):
  // roofHip's `even`, roofGable's `overhangY, even, index`.
  std::string dropped;
  std::vector<Branch> branches;
};

// One `|`-separated part of an operation block. `key` is the text before `:` when present: a
// size (`2: A`, `~1: B`) or a component selector (`front: Door`). A repeat pattern `{ A | B }*`
// has repeat = true and its parts in `pattern` instead of items.
struct Branch {
  Range range;
  ExprPtr key;
  bool merged = false;  // CityEngine's `top = Roof`: the selected components as one shape
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

// `@Name` or `@Name(arg, key = arg, ...)` before a CityEngine declaration: metadata for tools
// (the studio's parameter panel, --set checks), no effect on derivation.
struct Annotation {
  Range range;
  std::string name;
  std::vector<std::string> keys;  // "" for a positional argument; parallel to args
  std::vector<ExprPtr> args;
};

struct Rule {
  Range range;
  std::vector<std::string> params;  // CityEngine's parametric rules `Name(a, b) --> ...`
  std::vector<Annotation> annotations;
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
  std::vector<Annotation> annotations;
};

// CityEngine's functions `name(a, b) = expr` and `const name = expr` (a function without
// parameters that cannot be overridden).
struct FunctionDecl {
  Range range;
  std::string name;
  Range name_range;
  std::vector<std::string> params;
  ExprPtr body;
  bool is_const = false;
  std::vector<Annotation> annotations;
};

// `import alias : "file.cga"` with an optional list after the path: `(a, b)` protects those
// attributes from the importer's values, `(a = expr)` overrides them, `()` protects all,
// `(Name --> ...)` redefines a rule.
struct ImportDecl {
  Range range;
  std::string alias;
  Range alias_range;
  std::string path;
  Range path_range;
  bool has_list = false;
  std::vector<std::string> protected_attrs;
  std::vector<std::pair<std::string, ExprPtr>> overrides;
  // `(Roof(a) --> roofGable(a))`: a rule of the imported file (CityEngine's extension rules)
  // redefined, its body in the importing file's names.
  std::vector<Rule> rule_overrides;
  std::vector<Annotation> annotations;
};

enum class Dialect { kSeed004, kCityEngine };

struct Grammar {
  std::string file;
  Dialect dialect = Dialect::kSeed004;
  std::string version;  // CityEngine's `version "2019.0"`, empty when absent
  std::vector<AttrDecl> attrs;
  std::vector<FunctionDecl> functions;
  std::vector<ImportDecl> imports;
  std::vector<std::string> styles;  // `style Name` sections, in order (rules of Default kept)
  std::vector<PrioritySet> sets;
};

}  // namespace insula::lang::cga
