// Compilation of a parsed CGA grammar (ast.h) into the form the derivation engine runs
// (derive.h): symbols interned to integers, rules indexed by predecessor and priority level,
// expressions flattened into a node array with names resolved (attributes, functions, shape
// attributes) and constants folded, operations resolved through operations.h (the shape
// registry's declarations and CGA's spellings of them),
// split sizes precomputed when constant. Compilation reports what the engine cannot run (unknown
// operations, functions or attributes, wrong argument counts) as CGA5xx diagnostics; the checker
// (checker.h) reports the language-level problems before it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"
#include "lang/cga/functions.h"
#include "lang/cga/operations.h"
#include "lang/cga/value.h"
#include "shape/operation.h"
#include "shape/scope.h"
#include "shape/value.h"

namespace insula::lang::cga {

using SymbolId = std::uint32_t;
inline constexpr SymbolId kNoSymbol = 0xffffffffU;
inline constexpr std::uint32_t kNoExpr = 0xffffffffU;

// ---- expressions

enum class ECode : std::uint8_t {
  kConst,      // value = consts[a]
  kAttr,       // attribute a (Program::attrs)
  kShapeAttr,  // shape attribute a (ShapeAttr)
  kOcc,        // Shape.occ(kids[0])
  kFunction,   // function a (Function), arguments kids
  kUnary,      // op (UnaryOp), kids[0]
  kBinary,     // op (BinaryOp), kids[0], kids[1]
  kParam,      // parameter a of the rule or function being evaluated (EvalContext::frame)
  kCall,       // function a of the grammar (Program::functions), arguments kids
  kCase,       // kids: condition, value, ..., else value (CityEngine's `case`)
  kChance,     // kids: percentage, value, ..., else value (CityEngine's `30% : v else : w`)
  kCompSel,    // comp.sel: the selector text of the comp branch the shape came from
  kOcclusion,  // CityEngine's inside/overlaps/touches: op the relation (OcclusionRelation), a
               // the target (OcclusionTarget), kids: the label when given
  kConvert,    // CityEngine's convert(): a = from | to << 2 | orient << 4 (shape::Frame), op the
               // component 0..2 (3: all, as a float[3]); kids: x, y, z, or one float[3]
  kGeometry,   // CityEngine's geometry.*: query a (shape::GeometryQuery), its selector or angle
               // type op, kids: the tolerance when it takes one
  // CityEngine's arrays:
  kArray,     // a literal: kids are its values (op 0), or its `;` rows, each a kArray (op 1)
  kIndex,     // kids[0][kids[1]] or kids[0][kids[1], kids[2]]
  kCompFunc,  // comp(f){ sel : value | ... } as a value: Program::comp_functions[a]
};

enum class ShapeAttr : std::uint8_t {
  kSx,
  kSy,
  kSz,
  kTx,
  kTy,
  kTz,
  kArea,
  kVolume,
  kDepth,
  kIndex,
  kTotal,
  kSeedian,    // CityEngine's `seedian`: the shape's random seed as a number
  kElevation,  // scope.elevation: the scope origin's height in the world
  kInitialPx,  // CityEngine's initialShape.origin.px/py/pz: the lot's origin in CityEngine's
  kInitialPy,  // world axes (x east, y up, z south)
  kInitialPz,
};

enum class Function : std::uint8_t {
  kRand,
  kRint,
  kRound,
  kFloor,
  kCeil,
  kAbs,
  kMin,
  kMax,
  kClamp,
  kSqrt,
  kPow,
  kExp,
  kLn,
  kSin,
  kCos,
  kTan,
  kAsin,
  kAcos,
  kAtan,
  kAtan2,
  kP,
  kFloat,
  kStr,
  kBool,
  kLen,
  kFind,
  kSubstring,
  kCount,
  kReplace,
  kGetPrefix,
  kGetSuffix,
  kGetRange,
  kFileName,       // CityEngine's file path utilities: "dir/name.ext" -> "name.ext"
  kFileBasename,   // -> "name"
  kFileDirectory,  // -> "dir/"
  kFileExtension,  // -> ".ext"
  // CityEngine's colour functions (colors.h)
  kColorRGBToHex,
  kColorHSVToHex,
  kColorRamp,
  kColorHexToR,
  kColorHexToG,
  kColorHexToB,
  kColorHexToO,
  kColorHexToH,
  kColorHexToS,
  kColorHexToV,
  kListSize,
  kListItem,
  kListFirst,
  kListLast,
  kListRange,
  kListIndex,
  kListCount,
  kListAdd,
  kListRemove,  // CityEngine's listRemove(list, item): every item equal to `item` taken out
  kListRandom,
  kLog10,
  kIsNan,
  kIsInf,
  kFileExists,
  kFileSearch,
  kFileRandom,
  kAssetInfo,
  kImageInfo,
  kImageBestRatio,
  kImagesSortRatio,  // CityEngine's imagesSortRatio(list, axes): that list, best ratio first  //
                     // CityEngine's imageBestRatio(query, axes): the image shaped most like the
                     // scope
  // CityEngine's asset selection (Engine::assets_sorted): assetsSortSize(list, axes, maxError),
  // assetsSortRatio(list, axes) sort a list (or string[]) of assets by how they fit the scope;
  // the others search (fileSearch) and take the best (Best), one of the n best (Approx) or one of
  // those within maxScaleError (Fit), drawn from the shape's seeded generator.
  kAssetsSortSize,
  kAssetsSortRatio,
  kAssetBestSize,
  kAssetBestRatio,
  kAssetApproxSize,
  kAssetApproxRatio,
  kAssetFitSize,
  // CityEngine's array functions (eval_arrays.cc)
  kSize,
  kNRows,
  kNColumns,
  kFindFirst,
  kFindLast,
  kSortIndices,
  kTranspose,
  kFloatArray,
  kBoolArray,
  kStringArray,
  kListToArray,
  kListFromArray,
  kReadStringTable,
  kReadFloatTable,
  kPrint,        // CityEngine's print() as a function: prints its argument and returns it
  kGetGeoCoord,  // CityEngine's getGeoCoord(x | y | lon | lat) of the scope origin
  // CityEngine's geometry.du/dv(uvSet, unitSpace | uvSpace) and geometry.uMin/uMax/vMin/vMax
  // (uv set 0): kids are the set and 1 for unitSpace; ENode::op says which (UvExtent).
  kUvExtent,
  kStartRule,      // CityEngine's initialShape.startRule: the start rule's name
  kListTerminate,  // the utility library's listTerminate: a string list ended by ';'
  kRange,          // the colon operator `a:b`, `a:s:b` (no name: only inside `[ ]`)
};

// kMinimumDistance: CityEngine's minimumDistance(), a number where the others are bools.
enum class OcclusionRelation : std::uint8_t { kInside, kOverlaps, kTouches, kMinimumDistance };
// kComputed: `sel(expr)`, the word computed when derived (ENode::kids.back()).
enum class OcclusionTarget : std::uint8_t { kAll, kIntra, kInter, kComputed };

struct ENode {
  ECode code = ECode::kConst;
  std::uint8_t op = 0;
  std::uint32_t a = 0;
  Range range;
  std::vector<std::uint32_t> kids;
};

// A split size: mode plus either a constant or an expression (evaluated per shape).
struct CSize {
  shape::SizeMode mode = shape::SizeMode::kAbsolute;
  std::uint32_t expr = kNoExpr;  // kNoExpr: `value` is the constant
  double value = 0;
};

// ---- successors

enum class OpCode : std::uint8_t {
  kSymbol,
  kEmpty,
  kPush,
  kPop,
  kSplit,        // BS/Subdiv/split
  kRepeat,       // RR/Repeat
  kComp,         // CS/Comp/comp
  kTranslate,    // T/t: scope math
  kRotate,       // Rx/Ry/Rz/r: scope math
  kInsertShape,  // I / Pshape: a new terminal shape with the asset, the current shape goes on
  kSetback,
  kRegistry,  // any other shape operation (extrude, S/s, center, i, roofs, offset, ...)
  kColor,
  kSet,
  kSetScope,  // CityEngine's set(scope.tx | ty | tz, v): the scope moved (attr: 0, 1, 2)
  kPrint,
  kReport,
  kLabel,   // CityEngine's label("name"): the shape becomes an occluder under that name
  kNoOp,    // a CityEngine operation skipped with warning CGA903 (texture coordinates, labels)
  kCase,    // branches keyed by conditions; the last one (`else`) has none
  kChance,  // branches keyed by percentages; the last one (`else`) takes the rest
};

// kFaceEdges: CityEngine's fe, every edge of every face in face order (shared edges twice).
enum class CompKind : std::uint8_t { kFaces, kSideFaces, kEdges, kVertices, kFaceEdges };

struct CItem;

// A branch of an operation block: its key (a size, a selector or an index), or a repeat pattern.
struct CBranch {
  Range range;
  bool has_key = false;
  CSize size;                          // split sizes
  std::string selector;                // comp / offset / setback selector ("front", "inside", ...)
  std::int64_t index = -1;             // comp index key
  std::uint32_t index_expr = kNoExpr;  // CityEngine: a comp index computed per shape
  // kCase / kChance: the condition or the percentage; a comp function's branch: its value
  std::uint32_t condition = kNoExpr;
  bool merged = false;  // CityEngine's `sel = ...`: the selected components as one shape
  bool repeat = false;  // `{ ... }*`
  std::vector<CBranch> pattern;
  std::vector<CItem> items;
};

struct CItem {
  OpCode code = OpCode::kSymbol;
  Range range;
  SymbolId symbol = kNoSymbol;          // kSymbol (args: the rule's arguments)
  bool terminal = false;                // kSymbol written `Name.`: a leaf even with rules
  const OperationInfo* info = nullptr;  // operations
  std::vector<std::uint32_t> args;      // expressions, positional (kNoExpr: a size)
  std::vector<shape::Axis> axes;        // split / repeat (RR "XY": two)
  std::vector<CSize> sizes;             // BS sizes, RR size, size arguments of registry operations
  CompKind comp = CompKind::kFaces;     // comp
  std::vector<std::int64_t> indices;    // CS index list
  std::uint32_t attr = 0;               // kSet: attribute index
  std::vector<CBranch> branches;
  bool has_block = false;
  bool about_center = false;  // CityEngine's r(scopeCenter, x, y, z)
  bool along_uv = false;      // CityEngine's split(u | v, ...): along Insula's scope x | y
  bool by_area = false;       // CityEngine's splitArea(axis){ area : ... }: sizes are areas
};

struct CAlternative {
  Range range;
  std::vector<CItem> items;
  std::uint32_t probability = kNoExpr;  // none: the alternatives share what is left equally
};

struct CRule {
  std::string id;  // as written; empty for an unnamed rule
  Range range;
  Range id_range;
  SymbolId predecessor = kNoSymbol;
  std::uint32_t level = 0;  // index into Program::priorities
  std::uint32_t condition = kNoExpr;
  // The condition has one value per lot (Compiler::per_lot): the engine evaluates it once a lot.
  bool condition_per_lot = false;
  std::uint32_t params = 0;  // CityEngine's parametric rules: arguments in the frame
  std::vector<CAlternative> alternatives;
};

// A function of the grammar (CityEngine's `f(a, b) = expr`, `const c = expr`).
struct CFunction {
  std::string name;
  std::uint32_t params = 0;
  std::uint32_t body = kNoExpr;
  Range range;
};

struct CAttr {
  std::string name;
  std::uint32_t value = kNoExpr;  // default; kNoExpr: only ever set() (starts null)
  Range range;
};

struct Program {
  std::shared_ptr<const base::Source> source;
  std::vector<std::string> symbols;  // names as shown (a rule's name, whatever its arity)
  // By name; CityEngine's rules with k > 0 parameters by "name/k" (compile.cc, symbol()).
  std::unordered_map<std::string, SymbolId> symbol_ids;
  std::vector<std::uint32_t> priorities;  // distinct priority numbers, ascending (levels)
  std::vector<CRule> rules;
  // rules_at[symbol][level]: rule indices in file order; levels_of[symbol]: levels with rules.
  std::vector<std::vector<std::vector<std::uint32_t>>> rules_at;
  std::vector<std::vector<std::uint32_t>> levels_of;
  std::vector<CAttr> attrs;
  std::vector<CFunction> functions;
  std::uint32_t color_attr = 0;  // the hidden attribute color() sets
  // Attributes registry operations keep as state (shape::Operation::state: uv sets, projections,
  // the colour map), handed to and taken back from the operations that declare them.
  std::vector<std::uint32_t> state_attrs;
  // By attribute: whether a shape's attribute chain can hold it (a set(), color(), or an
  // operation's state); an attribute that none can is the lot's value on every shape.
  std::vector<bool> on_chains;
  std::vector<ENode> nodes;
  std::vector<Value> consts;
  // CityEngine's comp functions (ECode::kCompFunc): code kComp, branches keyed by selector, each
  // branch's `condition` the value of the components it takes.
  std::vector<CItem> comp_functions;
  SymbolId start = kNoSymbol;
  bool uses_occlusion = false;
  // CityEngine's occlusion queries: the derivation runs twice (derive.cc), the second pass asking
  // about the shapes of the first.
  bool uses_occlusion_queries = false;
  bool cityengine = false;  // read from CityEngine's dialect (derive_registry.cc: extrude(-d))

  bool has_rules(SymbolId s) const { return s < levels_of.size() && !levels_of[s].empty(); }
  std::string_view symbol_name(SymbolId s) const { return symbols[s]; }
  // "rule 'r12' (line 7)" or "rule 'Lot -->' (line 7)" for an unnamed rule.
  std::string describe(const CRule& rule) const;
  base::Span span(Range range) const { return span_of(*source, range); }
  const CAttr* find_attr(std::string_view name) const;
};

struct CompileOptions {
  std::string start;  // --start SYMBOL; empty: the first rule of the lowest priority set
  // Names expressions may use besides the `attr`s (lot properties, --set names): attributes
  // without a default, null unless the lot or --set gives them a value.
  std::vector<std::string> extra_attributes;
};

// Compiles `grammar` (parsed from `source`). Fails with CGA5xx diagnostics for what the engine
// cannot run; never throws.
base::Result<std::shared_ptr<const Program>> compile(const Grammar& grammar,
                                                     const base::Source& source,
                                                     const CompileOptions& options = {});

}  // namespace insula::lang::cga
