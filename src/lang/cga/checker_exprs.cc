// Static semantics of CGA expressions: every identifier is a grammar attribute, a name given from
// outside (CheckOptions::known_attributes) or a shape attribute (`Shape.sx`, functions.h); every
// function exists with a fitting number of arguments (functions.h); literals fold to constants so
// the checks of §IV.B (probabilities, angles) can run on them.
#include <cmath>
#include <set>
#include <string>

#include "lang/cga/checker_internal.h"
#include "lang/cga/cityengine_names.h"
#include "lang/cga/functions.h"

namespace insula::lang::cga::detail {
namespace {

std::string arity_text(std::uint8_t min_args, std::uint8_t max_args) {
  if (max_args == kUnbounded) return "at least " + std::to_string(min_args);
  if (min_args == max_args) return std::to_string(min_args);
  return std::to_string(min_args) + " to " + std::to_string(max_args);
}

std::string plural(std::size_t count, const char* word) {
  return std::to_string(count) + " " + word + (count == 1 ? "" : "s");
}

bool is_edge_side(std::string_view name) {
  return name == "front" || name == "back" || name == "left" || name == "right" || name == "side";
}

std::optional<double> arithmetic(BinaryOp op, double a, double b) {
  switch (op) {
    case BinaryOp::kAdd:
      return a + b;
    case BinaryOp::kSub:
      return a - b;
    case BinaryOp::kMul:
      return a * b;
    case BinaryOp::kDiv:
      if (b == 0.0) return std::nullopt;
      return a / b;
    case BinaryOp::kMod:
      if (b == 0.0) return std::nullopt;
      return std::fmod(a, b);
    default:
      return std::nullopt;  // comparisons and logic are not numbers
  }
}

}  // namespace

std::optional<Constant> fold(const Expr& expr) {
  switch (expr.kind) {
    case ExprKind::kNumber:
      return Constant{expr.number};
    case ExprKind::kUnary: {
      if (expr.operands.empty() || expr.unary_op == UnaryOp::kNot) return std::nullopt;
      std::optional<Constant> inner = fold(*expr.operands[0]);
      if (!inner) return std::nullopt;
      if (expr.unary_op == UnaryOp::kNegate) inner->value = -inner->value;
      if (expr.unary_op == UnaryOp::kRelative) inner->relative = true;
      if (expr.unary_op == UnaryOp::kFloating) inner->floating = true;
      return inner;
    }
    case ExprKind::kBinary: {
      if (expr.operands.size() != 2) return std::nullopt;
      const std::optional<Constant> a = fold(*expr.operands[0]);
      const std::optional<Constant> b = fold(*expr.operands[1]);
      if (!a || !b || a->relative || a->floating || b->relative || b->floating) {
        return std::nullopt;
      }
      const std::optional<double> value = arithmetic(expr.binary_op, a->value, b->value);
      if (!value || !std::isfinite(*value)) return std::nullopt;
      return Constant{*value};
    }
    default:
      return std::nullopt;
  }
}

void Checker::check_expr(const Expr& expr, ExprRole role) {
  switch (expr.kind) {
    case ExprKind::kNumber:
    case ExprKind::kString:
    case ExprKind::kBool:
      return;
    case ExprKind::kIdent:
      check_identifier(expr, role);
      return;
    case ExprKind::kMember:
      // CityEngine's words with dots: `world.up`, `scope.xy` as operation arguments.
      if (cityengine() && role == ExprRole::kBareWord && !dotted_name(expr).empty()) return;
      check_member(expr);
      return;
    case ExprKind::kCall:
      check_call(expr);
      return;
    case ExprKind::kUnary:
      // A relative or floating size is a size of the scope, meaningful only where the operation
      // resolves it against one (shape::resolve_sizes): split, repeat and scale sizes.
      if ((expr.unary_op == UnaryOp::kRelative || expr.unary_op == UnaryOp::kFloating) &&
          role == ExprRole::kValue) {
        error("CGA320",
              "a relative ('r) or floating (~) size is only allowed as a split, repeat or scale "
              "size",
              expr.range);
      }
      for (const ExprPtr& operand : expr.operands) check_expr(*operand);
      return;
    case ExprKind::kBinary:
    case ExprKind::kCase:
    case ExprKind::kChance:
      for (const ExprPtr& operand : expr.operands) check_expr(*operand);
      return;
    case ExprKind::kArray:
    case ExprKind::kIndex:
    case ExprKind::kRange:
      for (const ExprPtr& operand : expr.operands) check_expr(*operand);
      return;
    case ExprKind::kComp:
      check_comp_function(expr);
      return;
  }
}

// CityEngine's comp function: a component type, selectors as the comp operation's (plus
// `street.*` and `object.*` on face edges), and a value per branch.
void Checker::check_comp_function(const Expr& expr) {
  const Expr& type = *expr.operands[0];
  const std::optional<CompTypeSpelling> spelling =
      type.kind == ExprKind::kIdent ? comp_type_of(type.text) : std::nullopt;
  const CompType kind = spelling.has_value() ? spelling.value().type : CompType::kSideFaces;
  if (kind == CompType::kSideFaces) {
    error("CGA309", "unknown component type of comp() (expected f, e, v or fe)", type.range);
  }
  const bool face_edges = kind == CompType::kFaceEdges;
  const OperationInfo* comp = find_operation("comp");
  std::set<std::string> seen;
  for (std::size_t i = 1; i + 1 < expr.operands.size(); i += 2) {
    const Expr& key = *expr.operands[i];
    std::string name = dotted_name(key);
    const std::size_t dot = name.find('.');
    const std::string side = dot == std::string::npos ? name : name.substr(dot + 1);
    const bool frame = dot != std::string::npos &&
                       (name.compare(0, dot, "street") == 0 || name.compare(0, dot, "object") == 0);
    if (const std::optional<Constant> index = fold(key)) {
      if (index->relative || index->floating || index->value < 0 ||
          index->value != std::floor(index->value)) {
        error("CGA315", "a component index must be a whole number >= 0", key.range);
      }
      name = std::to_string(index->value);
    } else if (frame && (face_edges || name.compare(0, dot, "street") == 0)) {
      if (!face_edges || !is_edge_side(side)) {
        error("CGA902",
              "comp selector '" + name +
                  "' is supported on face edges (fe) only, with front, back, left, right or side",
              key.range);
      }
    } else if (comp == nullptr || !is_selector(*comp, name)) {
      error("CGA315",
            "unknown selector of comp() (a comp selector such as front, side or all, or a "
            "component index)",
            key.range);
    } else if (face_edges && name != "all" && !is_edge_side(name)) {
      error("CGA315", "face edges (fe) take front, back, left, right, side, all or an index",
            key.range);
    } else if (kind != CompType::kFaces && dot != std::string::npos) {
      error("CGA315", "selector '" + name + "' applies to faces only", key.range);
    } else if (kind != CompType::kEdges &&
               (name == "eave" || name == "hip" || name == "valley" || name == "ridge")) {
      error("CGA315", "selector '" + name + "' applies to edges only (comp(e))", key.range);
    }
    if (!name.empty() && !seen.insert(name).second) {
      error("CGA315", "selector '" + name + "' appears twice", key.range);
    }
    check_expr(*expr.operands[i + 1]);
  }
}

// A bare identifier names a grammar attribute or a name given from outside (lot properties,
// --set). Where an operation accepts a bare word (an axis, an asset), an unknown identifier is
// that word and the operation's check decides (checker_successors.cc).
void Checker::check_identifier(const Expr& expr, ExprRole role) {
  if (is_parameter(expr.text)) return;
  if (functions_.count(expr.text)) {
    if (function(expr.text, 0) == nullptr) {
      error("CGA312", "function '" + expr.text + "' takes " + arities(expr.text) + ", found none",
            expr.range);
    }
    return;
  }
  if (attributes_.count(expr.text)) {
    used_attributes_.insert(expr.text);
    if (current_attribute_) attribute_deps_[current_attribute_->name].insert(expr.text);
    return;
  }
  if (known_.count(expr.text) || role == ExprRole::kBareWord) return;
  if (cityengine() && expr.text == "seedian") return;  // the shape's seed (compile.cc)
  if (cityengine()) {  // a built-in function without arguments, called without parentheses
    const FunctionInfo* info = find_function(expr.text);
    if (info != nullptr && signature_accepts(info->signature, 0)) return;
  }
  if (is_shape_object(expr.text)) {
    error("CGA322", "'" + expr.text + "' needs a member, e.g. '" + expr.text + ".sx'", expr.range);
    return;
  }
  error("CGA313",
        "undefined identifier '" + expr.text + "' (not an attribute or a shape attribute)",
        expr.range);
}

// `Shape.sx`, `Scope.sy`, ...: the members of functions.h's kShapeAttributes that take no
// argument (`Shape.occ` needs one and is a call).
void Checker::check_member(const Expr& expr) {
  const Expr& object = *expr.operands[0];
  // An attribute whose name has dots (set(material.colormap, ...), set(trim.vertical, ...)).
  if (const std::string dotted = dotted_name(expr);
      cityengine() && (attributes_.count(dotted) || known_.count(dotted))) {
    used_attributes_.insert(dotted);
    return;
  }
  if (cityengine() && function(dotted_name(expr), 0) != nullptr) return;  // imported constant
  if (cityengine() && dotted_name(expr) == "initialShape.startRule") return;
  // The colour map texture() sets: an attribute of every CityEngine program (shape/uv_map.h).
  if (cityengine() && dotted_name(expr) == "material.colormap") return;
  if (cityengine() && dotted_name(expr).starts_with("initialShape.origin.p") &&
      dotted_name(expr).size() == 22) {
    return;  // the lot's origin (compile.cc)
  }
  if (cityengine() &&
      (dotted_name(expr) == "material.color.r" || dotted_name(expr) == "material.color.g" ||
       dotted_name(expr) == "material.color.b")) {
    return;  // the shape's colour (compile.cc)
  }
  if (cityengine() && geometry_query_of(expr) != nullptr) return;
  if (cityengine() && object.kind == ExprKind::kIdent) {
    const std::string name = object.text + "." + expr.text;
    if (contains(kUnsupportedFunctions, name)) {
      error("CGA902", "CityEngine function '" + name + "' is not supported", expr.range);
      return;
    }
  }
  if (cityengine() && object.kind == ExprKind::kIdent && object.text == "geometry") {
    if (is_uv_extent(expr.text)) return;  // geometry.uMin ..: uv set 0 (compile.cc)
    error("CGA321", "unknown function 'geometry." + expr.text + "'", expr.range);
    return;
  }
  if (object.kind != ExprKind::kIdent || !is_shape_object(object.text)) {
    if (object.kind == ExprKind::kIdent && !attributes_.count(object.text) &&
        !known_.count(object.text)) {
      error("CGA322",
            "unknown object '" + object.text + "' (shape attributes are Shape.* and Scope.*)",
            object.range);
    } else {
      error("CGA322", "only Shape.* and Scope.* have members", expr.range);
    }
    return;
  }
  const AttributeInfo* info = find_shape_attribute(object.text, expr.text);
  if (!info) {
    error("CGA322", "unknown shape attribute '" + object.text + "." + expr.text + "'", expr.range);
    return;
  }
  if (info->args > 0) {
    error("CGA312",
          "'" + object.text + "." + expr.text + "' expects " + plural(info->args, "argument") +
              ", found 0",
          expr.range);
  }
}

// CityEngine's geometry.* functions (shape/geometry_queries.h): the argument each takes, a
// selector word where it is one.
void Checker::check_geometry_call(const Expr& expr, const shape::GeometryQueryInfo& query) {
  const std::string name = "geometry." + std::string(query.name);
  const std::size_t count = expr.operands.size() - 1;
  const bool takes = query.argument != shape::QueryArgument::kNone;
  if (count > (takes ? 1U : 0U) || (count == 0 && takes && !query.optional_argument)) {
    error("CGA312",
          "'" + name + "' expects " + (takes ? "1 argument" : std::string("no argument")) +
              ", found " + std::to_string(count),
          expr.range);
    return;
  }
  if (count == 0) return;
  const Expr& arg = *expr.operands[1];
  if (query.argument == shape::QueryArgument::kTolerance) {
    check_expr(arg);
    return;
  }
  const std::string word = dotted_name(arg);
  if (query.argument == shape::QueryArgument::kFaceSelector) {
    if (!shape::face_option_named(word)) {
      error("CGA315", "unknown selector '" + word + "' for '" + name + "'", arg.range);
    }
    return;
  }
  if (!shape::angle_type_named(word)) {
    error("CGA315",
          "unknown angle type '" + word + "' for '" + name + "' (maxSlope, azimuth or zenith)",
          arg.range);
  }
}

// CityEngine's convert(coordinate, from, to, type, x, y, z) and convert(from, to, type, float[]).
void Checker::check_convert(const Expr& expr) {
  const std::size_t count = expr.operands.size() - 1;
  if (count != 7 && count != 4) {
    error("CGA312",
          "'convert' expects 7 arguments (or 4 with a float[]), found " + std::to_string(count),
          expr.range);
    return;
  }
  const std::size_t first = count == 7 ? 2 : 1;
  const auto word = [&](std::size_t i, std::initializer_list<std::string_view> choices,
                        const char* what) {
    const std::string text = dotted_name(*expr.operands[i]);
    if (std::find(choices.begin(), choices.end(), text) == choices.end()) {
      std::string list;
      for (std::string_view c : choices) list += (list.empty() ? "" : ", ") + std::string(c);
      error("CGA315", std::string("the ") + what + " of 'convert' is one of " + list,
            expr.operands[i]->range);
    }
  };
  if (count == 7) word(1, {"x", "y", "z"}, "coordinate");
  word(first, {"scope", "pivot", "object", "world"}, "system to convert from");
  word(first + 1, {"scope", "pivot", "object", "world"}, "system to convert to");
  word(first + 2, {"pos", "orient"}, "type");
  for (std::size_t i = first + 3; i <= count; ++i) check_expr(*expr.operands[i]);
}

// CityEngine's occlusion queries: inside/overlaps/touches([intra|inter|all[, label]]).
void Checker::check_occlusion_query(const Expr& expr) {
  const std::string& name = expr.operands[0]->text;
  const std::size_t count = expr.operands.size() - 1;
  if (count > 2) {
    error("CGA312", "'" + name + "' expects at most 2 arguments, found " + std::to_string(count),
          expr.range);
    return;
  }
  const Expr& first = count >= 1 ? *expr.operands[1] : expr;
  const bool computed = count >= 1 && first.kind == ExprKind::kCall && first.operands.size() == 2 &&
                        first.operands[0]->text == "sel";
  if (computed) check_expr(*first.operands[1]);  // sel(attr): the word when derived
  if (count >= 1 && !computed) {
    const Expr& word = *expr.operands[1];
    const std::string target = word.kind == ExprKind::kString ? word.text : dotted_name(word);
    if (target != "intra" && target != "inter" && target != "all") {
      error("CGA315",
            "the target of '" + name + "' is intra, inter or all, found " +
                (target.empty() ? std::string("an expression") : "'" + target + "'"),
            expr.operands[1]->range);
    }
  }
  if (count == 2) check_expr(*expr.operands[2]);
}

bool Checker::is_uv_extent(std::string_view name) {
  return name == "du" || name == "dv" || name == "uMin" || name == "uMax" || name == "vMin" ||
         name == "vMax";
}

void Checker::check_call(const Expr& expr) {
  if (check_user_call(expr)) return;
  const Expr& callee = *expr.operands[0];
  if (cityengine() && callee.kind == ExprKind::kMember && callee.operands[0]->text == "geometry" &&
      is_uv_extent(callee.text)) {
    // geometry.du(uvSet, unitSpace | uvSpace)
    const std::size_t n = expr.operands.size() - 1;
    if (n > 2) {
      error("CGA312", "'geometry." + callee.text + "' expects at most 2 arguments", expr.range);
    }
    if (n >= 1) check_expr(*expr.operands[1]);
    if (n == 2) {
      const std::string space = dotted_name(*expr.operands[2]);
      if (space != "unitSpace" && space != "uvSpace") {
        error("CGA315", "the space of 'geometry." + callee.text + "' is unitSpace or uvSpace",
              expr.operands[2]->range);
      }
    }
    return;
  }
  if (const shape::GeometryQueryInfo* query = cityengine() ? geometry_query_of(callee) : nullptr) {
    check_geometry_call(expr, *query);
    return;
  }
  const std::size_t count = expr.operands.size() - 1;
  if (callee.kind == ExprKind::kMember) {
    const Expr& object = *callee.operands[0];
    const AttributeInfo* info =
        object.kind == ExprKind::kIdent ? find_shape_attribute(object.text, callee.text) : nullptr;
    if (!info) {
      check_member(callee);  // reports the unknown object or member
    } else if (info->args != count) {
      error("CGA312",
            "'" + object.text + "." + callee.text + "' expects " + plural(info->args, "argument") +
                ", found " + std::to_string(count),
            callee.range);
    }
  } else if (callee.kind == ExprKind::kIdent && cityengine() && callee.text == "convert") {
    check_convert(expr);
    return;
  } else if (callee.kind == ExprKind::kIdent && cityengine() &&
             (callee.text == "inside" || callee.text == "overlaps" || callee.text == "touches" ||
              callee.text == "minimumDistance")) {
    check_occlusion_query(expr);
    return;
  } else if (callee.kind == ExprKind::kIdent) {
    const FunctionInfo* info = find_function(callee.text);
    if (!info && cityengine() && contains(kUnsupportedFunctions, callee.text)) {
      error("CGA902", "CityEngine function '" + callee.text + "' is not supported", callee.range);
      // Its arguments are often words (convert(x, scope, world, pos, ...)): names only.
      for (std::size_t i = 1; i < expr.operands.size(); ++i) {
        check_expr(*expr.operands[i], ExprRole::kBareWord);
      }
      return;
    } else if (!info) {
      error("CGA321", "unknown function '" + callee.text + "'", callee.range);
    } else if (!signature_accepts(info->signature, count)) {
      error("CGA312",
            "'" + callee.text + "' expects " + arity_text(info->min_args, info->max_args) +
                " argument" + (info->max_args == 1 && info->min_args == 1 ? "" : "s") + ", found " +
                std::to_string(count),
            callee.range);
    } else {
      for (std::size_t i = 0; i < count; ++i) {
        const Expr& arg = *expr.operands[i + 1];
        const char letter = signature_letter(info->signature, count, i);
        if ((letter == 'n' && arg.kind == ExprKind::kString) ||
            (letter == 's' && arg.kind == ExprKind::kNumber)) {
          error("CGA320",
                "argument " + std::to_string(i + 1) + " of '" + callee.text + "' must be a " +
                    (letter == 'n' ? "number" : "string"),
                arg.range);
        }
      }
    }
  } else {
    error("CGA321", "only functions and Shape.occ can be called", callee.range);
  }
  const FunctionInfo* info = callee.kind == ExprKind::kIdent ? find_function(callee.text) : nullptr;
  for (std::size_t i = 1; i < expr.operands.size(); ++i) {
    const bool word = info != nullptr && signature_accepts(info->signature, count) &&
                      signature_letter(info->signature, count, i - 1) == 'w';
    check_expr(*expr.operands[i], word ? ExprRole::kBareWord : ExprRole::kValue);
  }
}

}  // namespace insula::lang::cga::detail
