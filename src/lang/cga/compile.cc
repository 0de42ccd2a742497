#include "lang/cga/compile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>

#include "lang/cga/checker.h"
#include "lang/cga/cityengine_names.h"
#include "lang/cga/eval.h"
#include "lang/cga/geometry_functions.h"
#include "lang/cga/operations.h"
#include "shape/uv_map.h"

namespace insula::lang::cga {

using shape::SizeMode;

const CAttr* Program::find_attr(std::string_view name) const {
  for (const CAttr& a : attrs) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

std::string Program::describe(const CRule& rule) const {
  const std::string name = rule.id.empty() ? symbols[rule.predecessor] + " -->" : rule.id;
  return "rule '" + name + "' (line " + std::to_string(span(rule.range).line) + ")";
}

namespace {

constexpr std::pair<std::string_view, ShapeAttr> kShapeAttrs[] = {
    {"sx", ShapeAttr::kSx},
    {"sy", ShapeAttr::kSy},
    {"sz", ShapeAttr::kSz},
    {"tx", ShapeAttr::kTx},
    {"ty", ShapeAttr::kTy},
    {"tz", ShapeAttr::kTz},
    {"elevation", ShapeAttr::kElevation},
    {"area", ShapeAttr::kArea},
    {"volume", ShapeAttr::kVolume},
    {"depth", ShapeAttr::kDepth},
    {"index", ShapeAttr::kIndex},
    {"total", ShapeAttr::kTotal},
};

constexpr std::pair<std::string_view, Function> kFunctionCodes[] = {
    {"rand", Function::kRand},
    {"rint", Function::kRint},
    {"round", Function::kRound},
    {"floor", Function::kFloor},
    {"ceil", Function::kCeil},
    {"abs", Function::kAbs},
    {"min", Function::kMin},
    {"max", Function::kMax},
    {"clamp", Function::kClamp},
    {"sqrt", Function::kSqrt},
    {"pow", Function::kPow},
    {"exp", Function::kExp},
    {"ln", Function::kLn},
    {"sin", Function::kSin},
    {"cos", Function::kCos},
    {"tan", Function::kTan},
    {"asin", Function::kAsin},
    {"acos", Function::kAcos},
    {"atan", Function::kAtan},
    {"atan2", Function::kAtan2},
    {"p", Function::kP},
    {"float", Function::kFloat},
    {"str", Function::kStr},
    {"bool", Function::kBool},
    {"len", Function::kLen},
    {"find", Function::kFind},
    {"substring", Function::kSubstring},
    {"count", Function::kCount},
    {"replace", Function::kReplace},
    {"getPrefix", Function::kGetPrefix},
    {"getSuffix", Function::kGetSuffix},
    {"colorRGBToHex", Function::kColorRGBToHex},
    {"colorHSVToHex", Function::kColorHSVToHex},
    {"colorRamp", Function::kColorRamp},
    {"getRange", Function::kGetRange},
    {"fileName", Function::kFileName},
    {"fileBasename", Function::kFileBasename},
    {"fileDirectory", Function::kFileDirectory},
    {"fileExtension", Function::kFileExtension},
    {"colorHexToR", Function::kColorHexToR},
    {"colorHexToG", Function::kColorHexToG},
    {"colorHexToB", Function::kColorHexToB},
    {"colorHexToO", Function::kColorHexToO},
    {"colorHexToH", Function::kColorHexToH},
    {"colorHexToS", Function::kColorHexToS},
    {"colorHexToV", Function::kColorHexToV},
    {"listSize", Function::kListSize},
    {"listItem", Function::kListItem},
    {"listFirst", Function::kListFirst},
    {"listLast", Function::kListLast},
    {"listRange", Function::kListRange},
    {"listIndex", Function::kListIndex},
    {"listCount", Function::kListCount},
    {"listAdd", Function::kListAdd},
    {"listRemove", Function::kListRemove},
    {"listRandom", Function::kListRandom},
    {"log10", Function::kLog10},
    {"isnan", Function::kIsNan},
    {"isinf", Function::kIsInf},
    {"fileExists", Function::kFileExists},
    {"fileSearch", Function::kFileSearch},
    {"fileRandom", Function::kFileRandom},
    {"assetInfo", Function::kAssetInfo},
    {"imageInfo", Function::kImageInfo},
    {"imageBestRatio", Function::kImageBestRatio},
    {"imagesSortRatio", Function::kImagesSortRatio},
    {"assetsSortSize", Function::kAssetsSortSize},
    {"assetsSortRatio", Function::kAssetsSortRatio},
    {"assetBestSize", Function::kAssetBestSize},
    {"assetBestRatio", Function::kAssetBestRatio},
    {"assetApproxSize", Function::kAssetApproxSize},
    {"assetApproxRatio", Function::kAssetApproxRatio},
    {"assetFitSize", Function::kAssetFitSize},
    {"size", Function::kSize},
    {"nRows", Function::kNRows},
    {"nColumns", Function::kNColumns},
    {"findFirst", Function::kFindFirst},
    {"findLast", Function::kFindLast},
    {"sortIndices", Function::kSortIndices},
    {"transpose", Function::kTranspose},
    {"floatArray", Function::kFloatArray},
    {"boolArray", Function::kBoolArray},
    {"stringArray", Function::kStringArray},
    {"listToArray", Function::kListToArray},
    {"listFromArray", Function::kListFromArray},
    {"readStringTable", Function::kReadStringTable},
    {"readFloatTable", Function::kReadFloatTable},
    {"print", Function::kPrint},
    {"listTerminate", Function::kListTerminate},
    {"getGeoCoord", Function::kGetGeoCoord},
};

// An expression that names a word: a string literal or a bare identifier (`split(x)`).
const std::string* word_of(const Expr& e) {
  if (e.kind == ExprKind::kString || e.kind == ExprKind::kIdent) return &e.text;
  return nullptr;
}

// The attribute set(name, value) assigns: a string, a name, or CityEngine's dotted names
// (`material.colormap`, `trim.vertical`).
std::string set_target(const Expr& e) {
  if (e.kind == ExprKind::kString) return e.text;
  return dotted_name(e);
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::optional<ShapeAttr> initial_shape_part(const std::string& name) {
  if (name == "initialShape.origin.px") return ShapeAttr::kInitialPx;
  if (name == "initialShape.origin.py") return ShapeAttr::kInitialPy;
  if (name == "initialShape.origin.pz") return ShapeAttr::kInitialPz;
  return std::nullopt;
}

// geometry.du, dv (extent of the uv set along u or v) and uMin .. vMax: the codes of
// EvalContext::uv_extent.
std::optional<std::uint8_t> uv_extent_code(const std::string& name) {
  static constexpr std::string_view kNames[] = {"geometry.du",   "geometry.dv",   "geometry.uMin",
                                                "geometry.uMax", "geometry.vMin", "geometry.vMax"};
  for (std::size_t i = 0; i < std::size(kNames); ++i) {
    if (name == kNames[i]) return static_cast<std::uint8_t>(i);
  }
  return std::nullopt;
}

std::optional<Function> material_color_part(const std::string& name) {
  if (name == "material.color.r") return Function::kColorHexToR;
  if (name == "material.color.g") return Function::kColorHexToG;
  if (name == "material.color.b") return Function::kColorHexToB;
  return std::nullopt;
}

class Compiler {
 public:
  Compiler(const Grammar& grammar, const base::Source& source) : grammar_(grammar) {
    program_ = std::make_shared<Program>();
    program_->source = std::make_shared<base::Source>(source);  // with its imported parts
  }

  base::Result<std::shared_ptr<const Program>> run(const CompileOptions& options) {
    program_->cityengine = grammar_.dialect == Dialect::kCityEngine;
    declare_functions();
    declare_attributes(options.extra_attributes);
    compile_functions();
    collect_levels();
    for (const PrioritySet& set : grammar_.sets) {
      const std::uint32_t level = level_of(set.priority);
      for (const Rule& rule : set.rules) compile_rule(rule, level);
    }
    mark_on_chains(program_->color_attr);
    for (const std::uint32_t a : program_->state_attrs) mark_on_chains(a);
    for (CRule& r : program_->rules) {
      r.condition_per_lot = r.condition != kNoExpr && per_lot(r.condition);
    }
    index_rules();
    choose_start(options);
    if (base::has_errors(diagnostics_)) {
      return base::Result<std::shared_ptr<const Program>>::failure(std::move(diagnostics_));
    }
    return {std::shared_ptr<const Program>(std::move(program_)), std::move(diagnostics_)};
  }

 private:
  void error(std::string code, std::string message, Range range) {
    diagnostics_.push_back(
        base::Diagnostic::error(std::move(code), std::move(message), program_->span(range)));
  }

  void mark_on_chains(std::uint32_t attr) {
    if (program_->on_chains.size() <= attr) program_->on_chains.resize(attr + 1, false);
    program_->on_chains[attr] = true;
  }

  // Whether expression `e` has one value per lot: constants and attributes no shape's chain can
  // hold (their value is the lot's, fixed before any rule runs) under operators. Shape
  // attributes, parameters, functions (rand() draws from the shape's generator) and the rest
  // can differ from shape to shape.
  bool per_lot(std::uint32_t e) const {
    const ENode& n = program_->nodes[e];
    switch (n.code) {
      case ECode::kConst:
        return true;
      case ECode::kAttr:
        return n.a >= program_->on_chains.size() || !program_->on_chains[n.a];
      case ECode::kUnary:
      case ECode::kBinary:
        return std::all_of(n.kids.begin(), n.kids.end(),
                           [this](std::uint32_t k) { return per_lot(k); });
      default:
        return false;
    }
  }

  // ---- attributes: every `attr` plus every name a set() assigns
  void declare_attributes(const std::vector<std::string>& extra) {
    for (const AttrDecl& a : grammar_.attrs) {
      if (program_->find_attr(a.name) != nullptr) continue;  // the checker reports duplicates
      program_->attrs.push_back({a.name, kNoExpr, a.range});
    }
    for (const std::string& name : extra) {
      if (program_->find_attr(name) == nullptr) program_->attrs.push_back({name, kNoExpr, {}});
    }
    program_->color_attr = static_cast<std::uint32_t>(program_->attrs.size());
    program_->attrs.push_back({"#color", kNoExpr, {}});
    for (const PrioritySet& set : grammar_.sets) {
      for (const Rule& rule : set.rules) {
        for (const Alternative& alt : rule.alternatives) declare_set_targets(alt.items);
      }
    }
    for (const shape::Operation& op : shape::registry().operations()) {
      for (const std::string& name : op.state) {
        std::uint32_t index = attr_index(name);
        if (index == kNoExpr) {
          index = static_cast<std::uint32_t>(program_->attrs.size());
          program_->attrs.push_back({name, kNoExpr, {}});
        }
        if (std::find(program_->state_attrs.begin(), program_->state_attrs.end(), index) ==
            program_->state_attrs.end()) {
          program_->state_attrs.push_back(index);
        }
      }
    }
    // Defaults compile after every name is known (one attr may use another).
    for (const AttrDecl& a : grammar_.attrs) {
      CAttr& target = program_->attrs[attr_index(a.name)];
      if (target.value == kNoExpr && a.value) target.value = expr(*a.value);
    }
  }

  void declare_set_targets(const std::vector<Item>& items) {
    for (const Item& item : items) {
      if (item.kind == ItemKind::kOp && item.name == "set" && !item.args.empty()) {
        if (const std::string name = set_target(*item.args[0]);
            !name.empty() && !scope_translation(name) && program_->find_attr(name) == nullptr) {
          program_->attrs.push_back({name, kNoExpr, item.range});
        }
      }
      for (const Branch& b : item.branches) declare_branch_targets(b);
    }
  }
  void declare_branch_targets(const Branch& b) {
    declare_set_targets(b.items);
    for (const Branch& p : b.pattern) declare_branch_targets(p);
  }

  // A bare word that is a parameter, a constant, a function or an attribute is that value,
  // else the word itself (center(xz), texture(woodTex) reading an imported file's constant).
  bool names_a_value(const std::string& name) {
    return parameter(name) != kNoExpr || function_id(name, 0) != kNoExpr ||
           attr_index(name) != kNoExpr;
  }

  std::uint32_t attr_index(std::string_view name) const {
    for (std::size_t i = 0; i < program_->attrs.size(); ++i) {
      if (program_->attrs[i].name == name) return static_cast<std::uint32_t>(i);
    }
    return kNoExpr;
  }

  // ---- expressions
  std::uint32_t add(ENode node) {
    program_->nodes.push_back(std::move(node));
    return static_cast<std::uint32_t>(program_->nodes.size() - 1);
  }
  std::uint32_t constant(Value v, Range range) {
    program_->consts.push_back(std::move(v));
    ENode n;
    n.code = ECode::kConst;
    n.a = static_cast<std::uint32_t>(program_->consts.size() - 1);
    n.range = range;
    return add(std::move(n));
  }
  bool is_const(std::uint32_t e) const { return program_->nodes[e].code == ECode::kConst; }
  const Value& const_value(std::uint32_t e) const { return program_->consts[program_->nodes[e].a]; }

  std::uint32_t expr(const Expr& e) {
    switch (e.kind) {
      case ExprKind::kNumber:
        return constant(e.number, e.range);
      case ExprKind::kString:
        return constant(e.text, e.range);
      case ExprKind::kBool:
        return constant(e.boolean, e.range);
      case ExprKind::kIdent: {
        if (const std::uint32_t p = parameter(e.text); p != kNoExpr) {
          return add(ENode{ECode::kParam, 0, p, e.range, {}});
        }
        if (program_->cityengine && e.text == "seedian" && !names_a_value(e.text)) {
          return add(ENode{
              ECode::kShapeAttr, 0, static_cast<std::uint32_t>(ShapeAttr::kSeedian), e.range, {}});
        }
        if (const std::uint32_t fn = function_id(e.text, 0); fn != kNoExpr) {
          return add(ENode{ECode::kCall, 0, fn, e.range, {}});
        }
        const std::uint32_t a = attr_index(e.text);
        if (a == kNoExpr && program_->cityengine) {
          // CityEngine calls a built-in function without arguments written without parentheses
          // (`~(rand)` in its 2011 International City rules).
          const FunctionInfo* info = find_function(e.text);
          if (info != nullptr && signature_accepts(info->signature, 0)) {
            for (const auto& [name, code] : kFunctionCodes) {
              if (name == e.text) {
                return fold(
                    ENode{ECode::kFunction, 0, static_cast<std::uint32_t>(code), e.range, {}});
              }
            }
          }
        }
        if (a == kNoExpr) {
          error("CGA501", "unknown attribute '" + e.text + "'", e.range);
          return constant(Value{}, e.range);
        }
        ENode n{ECode::kAttr, 0, a, e.range, {}};
        return add(std::move(n));
      }
      case ExprKind::kMember:
        return member(e);
      case ExprKind::kCall:
        return call(e);
      case ExprKind::kUnary: {
        if (e.unary_op == UnaryOp::kRelative || e.unary_op == UnaryOp::kFloating) {
          error("CGA502",
                "a relative ('r) or floating (~) size is only allowed as a split or scale size",
                e.range);
          return constant(Value{}, e.range);
        }
        const std::uint32_t k = expr(*e.operands[0]);
        return fold(ENode{ECode::kUnary, static_cast<std::uint8_t>(e.unary_op), 0, e.range, {k}});
      }
      case ExprKind::kBinary: {
        const std::uint32_t a = expr(*e.operands[0]);
        const std::uint32_t b = expr(*e.operands[1]);
        return fold(ENode{ECode::kBinary,
                          static_cast<std::uint8_t>(e.binary_op),
                          e.elementwise ? 1U : 0U,
                          e.range,
                          {a, b}});
      }
      case ExprKind::kCase:
      case ExprKind::kChance: {
        std::vector<std::uint32_t> kids;
        for (const ExprPtr& operand : e.operands) kids.push_back(expr(*operand));
        const ECode code = e.kind == ExprKind::kCase ? ECode::kCase : ECode::kChance;
        return add(ENode{code, 0, 0, e.range, std::move(kids)});
      }
      case ExprKind::kArray:
        return array(e);
      case ExprKind::kIndex: {
        std::vector<std::uint32_t> kids;
        for (const ExprPtr& operand : e.operands) kids.push_back(expr(*operand));
        return add(ENode{ECode::kIndex, 0, 0, e.range, std::move(kids)});
      }
      case ExprKind::kComp:
        return comp_function(e);
      case ExprKind::kRange: {
        std::vector<std::uint32_t> kids;
        for (const ExprPtr& operand : e.operands) kids.push_back(expr(*operand));
        return fold(ENode{ECode::kFunction, 0, static_cast<std::uint32_t>(Function::kRange),
                          e.range, std::move(kids)});
      }
    }
    return constant(Value{}, e.range);
  }

  // An array literal; one of constants is built once, here.
  std::uint32_t array(const Expr& e) {
    ENode n{ECode::kArray, static_cast<std::uint8_t>(e.boolean ? 1 : 0), 0, e.range, {}};
    std::vector<std::vector<Value>> groups;
    bool constant_elements = true;
    const auto row = [&](const Expr& r) {
      std::vector<std::uint32_t> kids;
      groups.emplace_back();
      for (const ExprPtr& operand : r.operands) {
        kids.push_back(expr(*operand));
        constant_elements = constant_elements && is_const(kids.back());
        if (constant_elements) groups.back().push_back(const_value(kids.back()));
      }
      return kids;
    };
    if (e.boolean) {
      for (const ExprPtr& r : e.operands) {
        n.kids.push_back(add(ENode{ECode::kArray, 0, 0, r->range, row(*r)}));
      }
    } else {
      n.kids = row(e);
    }
    if (constant_elements) {
      try {
        return constant(array_literal(groups, e.range), e.range);
      } catch (const EvalError&) {
        // not foldable: evaluate (and report) when derived
      }
    }
    return add(std::move(n));
  }

  // CityEngine's comp function: compiled as a comp operation whose branches carry values.
  std::uint32_t comp_function(const Expr& e) {
    CItem c;
    c.code = OpCode::kComp;
    c.range = e.range;
    c.info = find_operation("comp");
    const std::string* w = word_of(*e.operands[0]);
    if (const std::optional<CompTypeSpelling> type = comp_type_of(w != nullptr ? *w : "")) {
      c.comp = comp_kind(type->type);
    } else {
      error("CGA508", "unknown component type of comp()", e.operands[0]->range);
    }
    for (std::size_t i = 1; i + 1 < e.operands.size(); i += 2) {
      const Expr& key = *e.operands[i];
      CBranch b;
      b.range = Range{key.range.begin, e.operands[i + 1]->range.end};
      b.has_key = true;
      b.merged = e.text[i / 2] == '=';
      if (key.kind == ExprKind::kNumber && key.number >= 0 &&
          key.number == std::floor(key.number)) {
        b.index = static_cast<std::int64_t>(key.number);
      } else {
        b.selector = dotted_name(key);
      }
      b.condition = expr(*e.operands[i + 1]);
      c.branches.push_back(std::move(b));
    }
    program_->comp_functions.push_back(std::move(c));
    return add(ENode{ECode::kCompFunc,
                     0,
                     static_cast<std::uint32_t>(program_->comp_functions.size() - 1),
                     e.range,
                     {}});
  }

  static CompKind comp_kind(CompType type) {
    switch (type) {
      case CompType::kFaces:
        return CompKind::kFaces;
      case CompType::kSideFaces:
        return CompKind::kSideFaces;
      case CompType::kEdges:
        return CompKind::kEdges;
      case CompType::kVertices:
        return CompKind::kVertices;
      case CompType::kFaceEdges:
        return CompKind::kFaceEdges;
    }
    return CompKind::kFaces;
  }

  // Folds operators over constants (errors such as 1/0 stay for run time, at their position).
  std::uint32_t fold(ENode n) {
    const bool all_const =
        std::all_of(n.kids.begin(), n.kids.end(), [&](std::uint32_t k) { return is_const(k); });
    if (all_const && !(n.code == ECode::kFunction && is_random(static_cast<Function>(n.a)))) {
      try {
        Value v;
        if (n.code == ECode::kUnary) {
          v = apply_unary(static_cast<UnaryOp>(n.op), const_value(n.kids[0]), n.range);
        } else if (n.code == ECode::kBinary && n.a != 0) {
          v = apply_elementwise(static_cast<BinaryOp>(n.op), const_value(n.kids[0]),
                                const_value(n.kids[1]), n.range);
        } else if (n.code == ECode::kBinary) {
          v = apply_binary(static_cast<BinaryOp>(n.op), const_value(n.kids[0]),
                           const_value(n.kids[1]), n.range);
        } else {
          std::vector<Value> args;
          for (std::uint32_t k : n.kids) args.push_back(const_value(k));
          v = apply_function(static_cast<Function>(n.a), args, n.range);
        }
        return constant(std::move(v), n.range);
      } catch (const EvalError&) {
        // not foldable: evaluate (and report) when derived
      }
    }
    return add(std::move(n));
  }

  std::uint32_t member(const Expr& e) {
    const Expr& object = *e.operands[0];
    if (const std::uint32_t a = attr_index(dotted_name(e)); a != kNoExpr) {
      // CityEngine's material.colormap reads "" where no texture was set (op 1: null as "").
      const bool text = dotted_name(e) == shape::kColormapAttribute;
      return add(ENode{ECode::kAttr, static_cast<std::uint8_t>(text ? 1 : 0), a, e.range, {}});
    }
    if (const std::uint32_t fn = function_id(dotted_name(e), 0); fn != kNoExpr) {
      return add(ENode{ECode::kCall, 0, fn, e.range, {}});  // an imported constant
    }
    if (const shape::GeometryQueryInfo* query = geometry_query_of(e)) {
      return geometry(*query, nullptr, e.range);
    }
    if (const std::optional<std::uint8_t> uv = uv_extent_code(dotted_name(e));
        uv && program_->cityengine) {  // geometry.uMin: uv set 0, in uv space
      return add(ENode{ECode::kFunction,
                       *uv,
                       static_cast<std::uint32_t>(Function::kUvExtent),
                       e.range,
                       {constant(0.0, e.range), constant(0.0, e.range)}});
    }
    if (program_->cityengine && dotted_name(e) == "initialShape.startRule") {
      return add(ENode{
          ECode::kFunction, 0, static_cast<std::uint32_t>(Function::kStartRule), e.range, {}});
    }
    if (const std::optional<ShapeAttr> part = initial_shape_part(dotted_name(e))) {
      return add(ENode{ECode::kShapeAttr, 0, static_cast<std::uint32_t>(*part), e.range, {}});
    }
    if (const std::optional<Function> part = material_color_part(dotted_name(e))) {
      // CityEngine's material.color.r/g/b: a component of the shape's colour (white unset).
      const std::uint32_t color = add(ENode{ECode::kAttr, 0, program_->color_attr, e.range, {}});
      return add(ENode{ECode::kFunction, 0, static_cast<std::uint32_t>(*part), e.range, {color}});
    }
    if (object.kind == ExprKind::kIdent && e.text == "sel" && is_shape_object(object.text)) {
      return add(ENode{ECode::kCompSel, 0, 0, e.range, {}});
    }
    if (object.kind == ExprKind::kIdent) {
      if (const AttributeInfo* info = find_shape_attribute(object.text, e.text);
          info != nullptr && info->args == 0) {
        for (const auto& [name, code] : kShapeAttrs) {
          if (name == e.text)
            return add(ENode{ECode::kShapeAttr, 0, static_cast<std::uint32_t>(code), e.range, {}});
        }
      }
    }
    error("CGA503",
          "unknown shape attribute '" +
              (object.kind == ExprKind::kIdent ? object.text + "." : std::string()) + e.text + "'",
          e.range);
    return constant(Value{}, e.range);
  }

  std::uint32_t call(const Expr& e) {
    const Expr& callee = *e.operands[0];
    const std::size_t argc = e.operands.size() - 1;
    if (const shape::GeometryQueryInfo* query = geometry_query_of(callee); query && argc <= 1) {
      return geometry(*query, argc == 1 ? e.operands[1].get() : nullptr, e.range);
    }
    if (const std::optional<std::uint8_t> uv = uv_extent_code(dotted_name(callee));
        uv && program_->cityengine && argc <= 2) {
      // geometry.du(uvSet, unitSpace | uvSpace): the space word is compiled to 1 or 0.
      const std::uint32_t set = argc >= 1 ? expr(*e.operands[1]) : constant(0.0, e.range);
      const bool unit = argc == 2 && dotted_name(*e.operands[2]) == "unitSpace";
      return add(ENode{ECode::kFunction,
                       *uv,
                       static_cast<std::uint32_t>(Function::kUvExtent),
                       e.range,
                       {set, constant(unit ? 1.0 : 0.0, e.range)}});
    }
    if (callee.kind == ExprKind::kIdent && callee.text == "convert" && program_->cityengine &&
        (argc == 7 || argc == 4)) {
      return convert(e);
    }
    if (const std::optional<OcclusionRelation> relation = occlusion_relation(callee);
        relation && program_->cityengine && argc <= 2) {
      return occlusion_query(*relation, e);
    }
    const FunctionInfo* known =
        callee.kind == ExprKind::kIdent ? find_function(callee.text) : nullptr;
    std::vector<std::uint32_t> kids;
    for (std::size_t i = 1; i < e.operands.size(); ++i) {
      const Expr& a = *e.operands[i];
      const bool word = known != nullptr && signature_accepts(known->signature, argc) &&
                        signature_letter(known->signature, argc, i - 1) == 'w' &&
                        a.kind == ExprKind::kIdent && !names_a_value(a.text);
      kids.push_back(word ? constant(a.text, a.range) : expr(a));
    }
    if (callee.kind == ExprKind::kMember && callee.text == "occ" &&
        callee.operands[0]->kind == ExprKind::kIdent && is_shape_object(callee.operands[0]->text)) {
      if (argc != 1) {
        error("CGA504", "'occ' expects 1 argument, found " + std::to_string(argc), e.range);
        return constant(Value{}, e.range);
      }
      program_->uses_occlusion = true;
      return add(ENode{ECode::kOcc, 0, 0, e.range, kids});
    }
    if (function_ids_.count(dotted_name(callee))) {
      const std::uint32_t fn = function_id(dotted_name(callee), argc);
      if (fn == kNoExpr) {
        error("CGA504",
              "'" + dotted_name(callee) + "' takes no " + std::to_string(argc) + " arguments",
              e.range);
        return constant(Value{}, e.range);
      }
      return add(ENode{ECode::kCall, 0, fn, e.range, kids});
    }
    if (callee.kind == ExprKind::kIdent) {
      if (const FunctionInfo* info = find_function(callee.text)) {
        if (!signature_accepts(info->signature, argc)) {
          error("CGA504",
                "'" + callee.text + "' cannot take " + std::to_string(argc) + " argument" +
                    (argc == 1 ? "" : "s"),
                e.range);
          return constant(Value{}, e.range);
        }
        for (const auto& [name, code] : kFunctionCodes) {
          if (name == callee.text) {
            return fold(
                ENode{ECode::kFunction, 0, static_cast<std::uint32_t>(code), e.range, kids});
          }
        }
      }
    }
    error("CGA505",
          "unknown function '" +
              (callee.kind == ExprKind::kIdent ? callee.text : std::string("?")) + "'",
          e.range);
    return constant(Value{}, e.range);
  }

  // A size: `2`, `~2` (floating), `'0.5` (a fraction of the scope), `1r`. In a split the paper's
  // `1r` is Müller et al.'s relative size, a share of what the absolute sizes leave (seed 004
  // §II: "Subdiv("X",2,1r,1r,2)"), i.e. a floating weight; in a scale it is relative to the
  // current size, as `'`.
  CSize size(const Expr& e, bool split) {
    CSize s;
    const Expr* inner = &e;
    if (e.kind == ExprKind::kUnary && e.unary_op == UnaryOp::kFloating) {
      s.mode = SizeMode::kFloating;
      inner = e.operands[0].get();
    } else if (e.kind == ExprKind::kUnary && e.unary_op == UnaryOp::kRelative) {
      const std::string& text = program_->source->text();
      const bool r_suffix =
          e.range.end > e.range.begin && e.range.end <= text.size() && text[e.range.end - 1] == 'r';
      s.mode = split && r_suffix ? SizeMode::kFloating : SizeMode::kRelative;
      inner = e.operands[0].get();
    }
    const std::uint32_t x = expr(*inner);
    if (is_const(x)) {
      if (const double* d = std::get_if<double>(&const_value(x))) {
        s.value = *d;
        return s;
      }
    }
    s.expr = x;
    return s;
  }

  // ---- successors
  std::vector<CItem> items(const std::vector<Item>& source) {
    std::vector<CItem> out;
    for (const Item& item : source) out.push_back(compile_item(item));
    return out;
  }

  // CityEngine overloads rules by their number of parameters (`Wall --> Wall(0.3)` next to
  // `Wall(t) --> ...`): each count is a symbol of its own, all shown by the rule's name.
  SymbolId symbol(const std::string& name, std::size_t arity = 0) {
    const std::string key = arity == 0 ? name : name + "/" + std::to_string(arity);
    auto [it, inserted] =
        program_->symbol_ids.emplace(key, static_cast<SymbolId>(program_->symbols.size()));
    if (inserted) program_->symbols.push_back(name);
    return it->second;
  }

  CItem compile_item(const Item& item) {
    CItem c;
    c.range = item.range;
    switch (item.kind) {
      case ItemKind::kSymbol:
        c.code = OpCode::kSymbol;
        c.symbol = symbol(item.name, item.terminal ? 0 : item.args.size());
        c.terminal = item.terminal;
        for (const ExprPtr& arg : item.args) c.args.push_back(expr(*arg));
        return c;
      case ItemKind::kCase:
      case ItemKind::kChance:
        c.code = item.kind == ItemKind::kCase ? OpCode::kCase : OpCode::kChance;
        for (const Branch& b : item.branches) {
          CBranch out;
          out.range = b.range;
          if (b.key) out.condition = expr(*b.key);
          out.items = items(b.items);
          c.branches.push_back(std::move(out));
        }
        return c;
      case ItemKind::kEmpty:
        c.code = OpCode::kEmpty;
        return c;
      case ItemKind::kPush:
        c.code = OpCode::kPush;
        return c;
      case ItemKind::kPop:
        c.code = OpCode::kPop;
        return c;
      case ItemKind::kOp:
        break;
    }
    c.info = find_operation(item.name);
    if (c.info == nullptr && grammar_.dialect == Dialect::kCityEngine &&
        contains(kDetailOperations, item.name)) {
      c.code = OpCode::kNoOp;  // warned by the checker (CGA903)
      return c;
    }
    if (c.info == nullptr) {
      error("CGA506", "unknown operation '" + item.name + "'", item.range);
      c.code = OpCode::kEmpty;
      return c;
    }
    c.has_block = item.has_block;
    const bool pivoted_rotation =  // CityEngine's r(scopeCenter, x, y, z)
        item.args.size() == 4 && c.info->registry_op == "rotate" && pivot_word(*item.args[0]);
    if (!pivoted_rotation && !signature_accepts(c.info->signature, item.args.size())) {
      error("CGA504",
            "'" + item.name + "' cannot take " + std::to_string(item.args.size()) + " argument" +
                (item.args.size() == 1 ? "" : "s"),
            item.range);
      c.code = OpCode::kEmpty;
      return c;
    }
    if (c.info->block == BlockUse::kRequired && !item.has_block) {
      error("CGA507", "'" + item.name + "' needs a successor block '{ ... }'", item.range);
    }
    if (c.info->block == BlockUse::kNone && item.has_block) {
      error("CGA507", "'" + item.name + "' takes no successor block", item.range);
    }
    operation(item, c);
    for (const Branch& b : item.branches) c.branches.push_back(branch(b, *c.info));
    return c;
  }

  void operation(const Item& item, CItem& c) {
    switch (item.op) {
      case OpKind::kSplit:
        split_args(item, c, true);
        c.along_uv = item.along_uv;
        return;
      case OpKind::kRepeat:
        split_args(item, c, false);
        c.code = OpCode::kRepeat;
        return;
      case OpKind::kComp:
        comp_args(item, c);
        return;
      case OpKind::kRotate: {
        // Rx(a) is r(a, 0, 0) and so on: three arguments, two of them constant zero.
        c.code = OpCode::kRotate;
        for (char axis : {'x', 'y', 'z'}) {
          c.args.push_back(axis == item.axis ? expr(*item.args[0]) : constant(0.0, item.range));
        }
        return;
      }
      case OpKind::kInsert:
      case OpKind::kPredefined:
        c.code = OpCode::kInsertShape;
        registry_args(item, c);
        return;
      default:
        break;
    }
    if (c.info->op == nullptr) {
      built_in(item, c);
      return;
    }
    const std::string& op = c.info->registry_op;
    if (op == "split") {
      split_args(item, c, false);
      c.along_uv = item.along_uv;
    } else if (op == "splitArea" && item.has_block) {
      split_args(item, c, false);
      c.by_area = true;
    } else if (op == "comp") {
      comp_args(item, c);
    } else if (op == "setback") {
      c.code = OpCode::kSetback;
      registry_args(item, c);
    } else if (op == "rotate" && item.args.size() == 4 && pivot_word(*item.args[0])) {
      // CityEngine's r(scopeOrigin | scopeCenter, x, y, z).
      c.code = OpCode::kRotate;
      c.about_center = dotted_name(*item.args[0]) == "scopeCenter";
      for (std::size_t i = 1; i < 4; ++i) c.args.push_back(expr(*item.args[i]));
    } else if ((op == "translate" || op == "rotate") && scope_math(item, *c.info)) {
      // T, t and r move the scope by scope math, as shape::translate and shape::rotate do.
      c.code = op == "translate" ? OpCode::kTranslate : OpCode::kRotate;
      if (op == "translate") {
        translate_args(item, c);
      } else {
        plain_args(item, c);
      }
    } else {
      c.code = OpCode::kRegistry;
      registry_args(item, c);
    }
  }

  // t(x, y, z): CityEngine's `'d` is d times the scope's size on that axis (t(0, 0, '-1)).
  void translate_args(const Item& item, CItem& c) {
    constexpr ShapeAttr kSizes[] = {ShapeAttr::kSx, ShapeAttr::kSy, ShapeAttr::kSz};
    for (std::size_t i = 0; i < item.args.size(); ++i) {
      const Expr& a = *item.args[i];
      if (a.kind != ExprKind::kUnary || a.unary_op != UnaryOp::kRelative) {
        c.args.push_back(expr(a));
        continue;
      }
      const std::uint32_t share = expr(*a.operands[0]);
      const std::uint32_t size =
          add(ENode{ECode::kShapeAttr, 0, static_cast<std::uint32_t>(kSizes[i]), a.range, {}});
      c.args.push_back(add(ENode{
          ECode::kBinary, static_cast<std::uint8_t>(BinaryOp::kMul), 0, a.range, {share, size}}));
    }
  }

  // CityEngine's geometry.area(top) and friends (geometry_functions.h): the selector or angle
  // type is a word fixed here, a tolerance an expression.
  std::uint32_t geometry(const shape::GeometryQueryInfo& query, const Expr* arg, Range range) {
    ENode node{ECode::kGeometry, 0, static_cast<std::uint32_t>(query.query), range, {}};
    if (arg != nullptr && query.argument == shape::QueryArgument::kTolerance) {
      node.kids.push_back(expr(*arg));
    } else if (arg != nullptr && query.argument == shape::QueryArgument::kAngleType) {
      node.op = static_cast<std::uint8_t>(
          shape::angle_type_named(dotted_name(*arg)).value_or(shape::AngleType::kMaxSlope));
    } else if (arg != nullptr) {
      node.op = shape::face_option_named(dotted_name(*arg))
                    .value_or(static_cast<std::uint8_t>(shape::FaceSelector::kAll));
    } else {
      node.op = static_cast<std::uint8_t>(shape::FaceSelector::kAll);
    }
    return add(std::move(node));
  }

  // convert(coordinate, from, to, type, x, y, z) or convert(from, to, type, coordinates[]); the
  // checker has vetted the words.
  std::uint32_t convert(const Expr& e) {
    const bool tuple = e.operands.size() == 8;
    const std::size_t first = tuple ? 2 : 1;
    const auto frame = [&](std::size_t i) {
      return static_cast<std::uint32_t>(shape::frame_from(dotted_name(*e.operands[i])));
    };
    const std::string coordinate = tuple ? dotted_name(*e.operands[1]) : std::string();
    ENode node{ECode::kConvert,
               static_cast<std::uint8_t>(coordinate == "x"   ? 0
                                         : coordinate == "y" ? 1
                                         : coordinate == "z" ? 2
                                                             : 3),
               frame(first) | frame(first + 1) << 2 |
                   (dotted_name(*e.operands[first + 2]) == "orient" ? 1U : 0U) << 4,
               e.range,
               {}};
    for (std::size_t i = first + 3; i < e.operands.size(); ++i) {
      node.kids.push_back(expr(*e.operands[i]));
    }
    return add(std::move(node));
  }

  // CityEngine's inside/overlaps/touches([target[, label]]).
  static std::optional<OcclusionRelation> occlusion_relation(const Expr& callee) {
    if (callee.kind != ExprKind::kIdent) return std::nullopt;
    if (callee.text == "inside") return OcclusionRelation::kInside;
    if (callee.text == "overlaps") return OcclusionRelation::kOverlaps;
    if (callee.text == "touches") return OcclusionRelation::kTouches;
    if (callee.text == "minimumDistance") return OcclusionRelation::kMinimumDistance;
    return std::nullopt;
  }

  std::uint32_t occlusion_query(OcclusionRelation relation, const Expr& e) {
    program_->uses_occlusion_queries = true;
    ENode node{ECode::kOcclusion, static_cast<std::uint8_t>(relation), 0, e.range, {}};
    const Expr* computed = nullptr;
    if (e.operands.size() > 1) {
      // The target word, or the same in quotes (Complete Street's minimumDistance("inter", ...)).
      const Expr& word = *e.operands[1];
      const std::string target = word.kind == ExprKind::kString ? word.text : dotted_name(word);
      node.a = static_cast<std::uint32_t>(target == "intra"   ? OcclusionTarget::kIntra
                                          : target == "inter" ? OcclusionTarget::kInter
                                                              : OcclusionTarget::kAll);
      computed = sel_argument(*e.operands[1]);
      if (computed != nullptr) node.a = static_cast<std::uint32_t>(OcclusionTarget::kComputed);
    }
    if (e.operands.size() > 2) node.kids.push_back(expr(*e.operands[2]));
    if (computed != nullptr) node.kids.push_back(expr(*computed));
    return add(std::move(node));
  }

  // The argument of CityEngine's `sel(expr)` (a text made a selector word), else null.
  static const Expr* sel_argument(const Expr& e) {
    if (e.kind != ExprKind::kCall || e.operands.size() != 2) return nullptr;
    const Expr& callee = *e.operands[0];
    return callee.kind == ExprKind::kIdent && callee.text == "sel" ? e.operands[1].get() : nullptr;
  }

  static bool pivot_word(const Expr& e) {
    const std::string word = dotted_name(e);
    return word == "scopeCenter" || word == "scopeOrigin";
  }

  // Whether the arguments are exactly x, y and z of translate or rotate (no pivot).
  static bool scope_math(const Item& item, const OperationInfo& info) {
    if (item.args.size() != 3) return false;
    for (std::size_t i = 0; i < 3; ++i) {
      const shape::ParamDecl* p = info.param_of(i);
      if (p == nullptr || p->name != std::string(1, static_cast<char>('x' + i))) return false;
    }
    return true;
  }

  // CityEngine's set(scope.tx, v) and its y and z: the axis moved along (0, 1, 2).
  std::optional<std::uint32_t> scope_translation(const std::string& name) const {
    if (!program_->cityengine || name.size() != 8 || !name.starts_with("scope.t")) return {};
    const char axis = name.back();
    if (axis < 'x' || axis > 'z') return {};
    return static_cast<std::uint32_t>(axis - 'x');
  }

  // color, set, print, report, nil: CGA's own successor items.
  void built_in(const Item& item, CItem& c) {
    if (item.name == "set") {
      c.code = OpCode::kSet;
      const std::string name = set_target(*item.args[0]);
      if (const std::optional<std::uint32_t> axis = scope_translation(name)) {
        c.code = OpCode::kSetScope;
        c.attr = *axis;
        c.args.push_back(expr(*item.args[1]));
        return;
      }
      // CityEngine's set(material.color, "#...") is color("#...").
      const std::uint32_t attr = name == "material.color" ? program_->color_attr : attr_index(name);
      if (name.empty() || attr == kNoExpr) {
        error("CGA508", "set() expects an attribute name first", item.args[0]->range);
        return;
      }
      c.attr = attr;
      mark_on_chains(attr);
      c.args.push_back(expr(*item.args[1]));
      return;
    }
    c.code = item.name == "color"    ? OpCode::kColor
             : item.name == "print"  ? OpCode::kPrint
             : item.name == "report" ? OpCode::kReport
             : item.name == "label"  ? OpCode::kLabel
                                     : OpCode::kEmpty;  // nil
    plain_args(item, c);
  }

  void plain_args(const Item& item, CItem& c) {
    for (const ExprPtr& a : item.args) c.args.push_back(expr(*a));
  }

  // The arguments of a registry operation, one per positional argument (operations.h maps each
  // to its parameter): sizes into c.sizes (c.args holds kNoExpr there); a string or choice
  // written as a bare word (`I(box)`, `center(xz)`) is that word unless it names an attribute;
  // a constant choice must be one the registry declares.
  void registry_args(const Item& item, CItem& c) {
    const std::size_t count = item.args.size();
    for (std::size_t i = 0; i < count; ++i) {
      const Expr& a = *item.args[i];
      const shape::ParamDecl* p = c.info->param_of(i);
      if (signature_letter(c.info->signature, count, i) == 'z') {
        c.sizes.push_back(size(a, false));
        c.args.push_back(kNoExpr);
        continue;
      }
      const std::string* w = word_of(a);
      // CityEngine's dotted words (alignScopeToGeometry(yUp, 0, world.lowest)).
      const std::string dotted = a.kind == ExprKind::kMember ? dotted_name(a) : std::string();
      if (w == nullptr && p != nullptr && p->type == shape::ParamType::kEnum &&
          std::find(p->choices.begin(), p->choices.end(), lower(dotted)) != p->choices.end()) {
        w = &dotted;
      }
      const bool word = w != nullptr && (a.kind == ExprKind::kString || !names_a_value(*w));
      if (!word || p == nullptr ||
          (p->type != shape::ParamType::kString && p->type != shape::ParamType::kEnum)) {
        c.args.push_back(expr(a));
        continue;
      }
      if (p->type == shape::ParamType::kEnum &&
          std::find(p->choices.begin(), p->choices.end(), lower(*w)) == p->choices.end()) {
        std::string list;
        for (const std::string& choice : p->choices) list += (list.empty() ? "" : ", ") + choice;
        error("CGA508",
              "'" + item.name + "' argument " + std::to_string(i + 1) + " (" + p->name +
                  ") must be one of " + list,
              a.range);
      }
      c.args.push_back(constant(*w, a.range));
    }
  }

  std::vector<shape::Axis> axes(const Expr& e, bool several) {
    const std::string* w = word_of(e);
    const std::optional<std::string> text = canonical_axis(w != nullptr ? *w : "");
    std::vector<shape::Axis> out;
    if (text) {
      for (char ch : *text) {
        out.push_back(ch == 'x' ? shape::Axis::kX : ch == 'y' ? shape::Axis::kY : shape::Axis::kZ);
      }
    }
    if (out.empty() || (!several && out.size() != 1)) {
      error("CGA508",
            several ? "expected axes x, y, z or a combination such as \"XY\""
                    : "expected one axis: x, y or z",
            e.range);
      out = {shape::Axis::kX};
    }
    return out;
  }

  // BS(axis, sizes...) / split(axis){ sizes: ... } / RR(axis, size).
  void split_args(const Item& item, CItem& c, bool basic) {
    c.code = OpCode::kSplit;
    // RR and the paper's BS take axis combinations (§VI); CityEngine's split(axis) one axis.
    const bool several = item.op == OpKind::kRepeat || item.op == OpKind::kSplit;
    c.axes = axes(*item.args[0], several);
    for (std::size_t i = 1; i < item.args.size(); ++i) {
      c.sizes.push_back(size(*item.args[i], true));
    }
    if (basic && c.sizes.size() != item.branches.size()) {
      error("CGA509",
            "'" + item.name + "' has " + std::to_string(c.sizes.size()) + " sizes but " +
                std::to_string(item.branches.size()) + " successors",
            item.range);
    }
  }

  void comp_args(const Item& item, CItem& c) {
    c.code = OpCode::kComp;
    // The checker's normalisation (checker.h): the paper's spellings and CityEngine's letters.
    const std::string* w = word_of(*item.args[0]);
    const std::optional<CompTypeSpelling> type = comp_type_of(w != nullptr ? *w : "");
    if (!type) {
      error("CGA508",
            "unknown component type '" + (w != nullptr ? *w : std::string("?")) +
                "' (faces, sidefaces, edges, vertices)",
            item.args[0]->range);
    } else {
      c.comp = comp_kind(type->type);
    }
    for (std::size_t i = 1; i < item.args.size(); ++i) {
      const std::uint32_t e = expr(*item.args[i]);
      const double* d = is_const(e) ? std::get_if<double>(&const_value(e)) : nullptr;
      if (d == nullptr || *d < 0 || *d != std::floor(*d)) {
        error("CGA508", "component indices must be constant whole numbers >= 0",
              item.args[i]->range);
        continue;
      }
      c.indices.push_back(static_cast<std::int64_t>(*d));
    }
  }

  CBranch branch(const Branch& b, const OperationInfo& info) {
    CBranch out;
    out.range = b.range;
    out.repeat = b.repeat;
    for (const Branch& p : b.pattern) out.pattern.push_back(branch(p, info));
    out.items = items(b.items);
    if (!b.key) return out;
    out.has_key = true;
    if (info.keys == KeyUse::kSize) {
      out.size = size(*b.key, true);
    } else if (info.keys == KeyUse::kSelector) {
      const Expr& key = *b.key;
      if (key.kind == ExprKind::kNumber && key.number >= 0 &&
          key.number == std::floor(key.number)) {
        out.index = static_cast<std::int64_t>(key.number);
      } else if (grammar_.dialect == Dialect::kCityEngine &&
                 ((key.kind != ExprKind::kIdent && key.kind != ExprKind::kString &&
                   key.kind != ExprKind::kMember) ||
                  (!is_selector(info, dotted_name(key)) && names_a_value(dotted_name(key))))) {
        out.index_expr = expr(key);  // evaluated on the shape the comp splits
      } else if (const std::string* w = word_of(key); w != nullptr && is_selector(info, *w)) {
        out.selector = *w;
      } else if (key.kind == ExprKind::kMember && is_selector(info, dotted_name(key))) {
        out.selector = dotted_name(key);  // world.up, object.front
      } else if (const std::string word = dotted_name(key); word.starts_with("street.") &&
                                                            is_selector(info, "street") &&
                                                            is_selector(info, word.substr(7))) {
        out.selector = word.substr(7);  // setback's street.front: the lot's own front
      } else {
        error("CGA510",
              "'" + std::string(info.name) + "' has no selector '" +
                  (word_of(key) ? *word_of(key) : std::string("?")) + "'",
              key.range);
      }
    } else {
      error("CGA510", "the branches of '" + std::string(info.name) + "' take no keys",
            b.key->range);
    }
    return out;
  }

  // ---- rules
  void collect_levels() {
    for (const PrioritySet& set : grammar_.sets) program_->priorities.push_back(set.priority);
    std::sort(program_->priorities.begin(), program_->priorities.end());
    program_->priorities.erase(
        std::unique(program_->priorities.begin(), program_->priorities.end()),
        program_->priorities.end());
  }
  std::uint32_t level_of(std::uint32_t priority) const {
    const auto& p = program_->priorities;
    return static_cast<std::uint32_t>(std::lower_bound(p.begin(), p.end(), priority) - p.begin());
  }

  void compile_rule(const Rule& rule, std::uint32_t level) {
    CRule r;
    r.id = rule.id;
    r.range = rule.range;
    r.id_range = rule.id.empty() ? rule.predecessor_range : rule.id_range;
    r.predecessor = symbol(rule.predecessor, rule.params.size());
    r.level = level;
    r.params = static_cast<std::uint32_t>(rule.params.size());
    params_ = &rule.params;
    if (rule.condition) r.condition = expr(*rule.condition);
    for (const Alternative& alt : rule.alternatives) {
      CAlternative a;
      a.range = alt.range;
      a.items = items(alt.items);
      if (alt.probability) a.probability = expr(*alt.probability);
      r.alternatives.push_back(std::move(a));
    }
    params_ = nullptr;
    program_->rules.push_back(std::move(r));
  }

  void index_rules() {
    const std::size_t n = program_->symbols.size();
    const std::size_t levels = program_->priorities.size();
    program_->rules_at.assign(n, std::vector<std::vector<std::uint32_t>>(levels));
    program_->levels_of.assign(n, {});
    for (std::uint32_t i = 0; i < program_->rules.size(); ++i) {
      const CRule& r = program_->rules[i];
      program_->rules_at[r.predecessor][r.level].push_back(i);
    }
    for (std::size_t s = 0; s < n; ++s) {
      for (std::uint32_t l = 0; l < levels; ++l) {
        if (!program_->rules_at[s][l].empty()) program_->levels_of[s].push_back(l);
      }
    }
  }

  void choose_start(const CompileOptions& options) {
    if (!options.start.empty()) {
      auto it = program_->symbol_ids.find(options.start);
      if (it == program_->symbol_ids.end()) {
        diagnostics_.push_back(base::Diagnostic::error(
            "CGA511", "start symbol '" + options.start + "' does not occur in the grammar",
            base::Span::whole(program_->source->name())));
        return;
      }
      program_->start = it->second;
      return;
    }
    // §VI: the derivation starts from the first rule of the lowest priority set.
    const CRule* first = nullptr;
    for (const CRule& r : program_->rules) {
      if (first == nullptr || r.level < first->level) first = &r;
    }
    if (first == nullptr) {
      diagnostics_.push_back(base::Diagnostic::error("CGA512", "the grammar has no rules",
                                                     base::Span::whole(program_->source->name())));
      return;
    }
    program_->start = first->predecessor;
  }

  // ---- CityEngine's functions and parameters
  // Ids first, bodies after, so functions may call each other (and themselves) in any order.
  void declare_functions() {
    for (const FunctionDecl& fn : grammar_.functions) {
      auto [it, inserted] = function_ids_[fn.name].emplace(
          fn.params.size(), static_cast<std::uint32_t>(program_->functions.size()));
      if (!inserted) continue;  // the checker reports duplicates
      program_->functions.push_back(
          {fn.name, static_cast<std::uint32_t>(fn.params.size()), kNoExpr, fn.range});
    }
  }
  // The function `name` taking `count` arguments (CityEngine overloads by count), or kNoExpr.
  std::uint32_t function_id(std::string_view name, std::size_t count) const {
    auto it = function_ids_.find(name);
    if (it == function_ids_.end()) return kNoExpr;
    auto fn = it->second.find(count);
    return fn == it->second.end() ? kNoExpr : fn->second;
  }
  void compile_functions() {
    for (const FunctionDecl& fn : grammar_.functions) {
      CFunction& target = program_->functions[function_id(fn.name, fn.params.size())];
      if (target.body != kNoExpr) continue;
      params_ = &fn.params;
      target.body = expr(*fn.body);
      params_ = nullptr;
    }
  }
  std::uint32_t parameter(std::string_view name) const {
    if (params_ == nullptr) return kNoExpr;
    for (std::size_t i = 0; i < params_->size(); ++i) {
      if ((*params_)[i] == name) return static_cast<std::uint32_t>(i);
    }
    return kNoExpr;
  }

  const Grammar& grammar_;
  std::shared_ptr<Program> program_;
  std::vector<base::Diagnostic> diagnostics_;
  std::map<std::string, std::map<std::size_t, std::uint32_t>, std::less<>> function_ids_;
  const std::vector<std::string>* params_ = nullptr;
};

}  // namespace

base::Result<std::shared_ptr<const Program>> compile(const Grammar& grammar,
                                                     const base::Source& source,
                                                     const CompileOptions& options) {
  return Compiler(grammar, source).run(options);
}

}  // namespace insula::lang::cga
