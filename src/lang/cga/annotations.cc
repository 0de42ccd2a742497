#include "lang/cga/annotations.h"

#include <cmath>

#include "base/format.h"

namespace insula::lang::cga {
namespace {

// A literal argument: a number (a negated one too), a string or a boolean.
std::optional<shape::Value> literal(const Expr& e) {
  switch (e.kind) {
    case ExprKind::kNumber:
      return shape::Value{e.number};
    case ExprKind::kString:
      return shape::Value{e.text};
    case ExprKind::kBool:
      return shape::Value{e.boolean};
    case ExprKind::kUnary:
      if (e.unary_op == UnaryOp::kNegate && e.operands[0]->kind == ExprKind::kNumber) {
        return shape::Value{-e.operands[0]->number};
      }
      return std::nullopt;
    default:
      return std::nullopt;
  }
}

std::string shown(const shape::Value& v) {
  if (const auto* d = std::get_if<double>(&v)) return base::shortest_number(*d);
  if (const auto* s = std::get_if<std::string>(&v)) return base::quoted_string(*s);
  return shape::to_string(v);
}

bool restricted(const Annotation& a) {
  for (std::size_t i = 0; i < a.args.size(); ++i) {
    if (a.keys[i] != "restricted") continue;
    const std::optional<shape::Value> v = literal(*a.args[i]);
    if (v && std::holds_alternative<bool>(*v)) return std::get<bool>(*v);
  }
  return true;
}

// @Range with numbers: [min, max] (either may be missing).
std::optional<std::string> range_violation(const Annotation& a, double x) {
  std::optional<double> lo, hi;
  std::size_t positional = 0;
  for (std::size_t i = 0; i < a.args.size(); ++i) {
    const std::optional<shape::Value> v = literal(*a.args[i]);
    if (!v || !std::holds_alternative<double>(*v)) continue;
    const double d = std::get<double>(*v);
    if (a.keys[i] == "min" || (a.keys[i].empty() && positional == 0)) lo = d;
    if (a.keys[i] == "max" || (a.keys[i].empty() && positional == 1)) hi = d;
    if (a.keys[i].empty()) ++positional;
  }
  if ((lo && x < *lo) || (hi && x > *hi)) {
    return "outside @Range " + (lo ? base::shortest_number(*lo) : std::string("-inf")) + " .. " +
           (hi ? base::shortest_number(*hi) : std::string("inf"));
  }
  return std::nullopt;
}

// @Enum(...) or @Range("a", "b", ...): one of the positional values.
std::optional<std::string> enum_violation(const Annotation& a, const shape::Value& value) {
  std::string list;
  for (std::size_t i = 0; i < a.args.size(); ++i) {
    if (!a.keys[i].empty()) continue;
    const std::optional<shape::Value> v = literal(*a.args[i]);
    if (!v) return std::nullopt;  // computed choices: not checked here
    const bool same = std::holds_alternative<double>(*v) && std::holds_alternative<double>(value)
                          ? std::fabs(std::get<double>(*v) - std::get<double>(value)) < 1e-12
                          : *v == value;
    if (same) return std::nullopt;
    if (!list.empty()) list += ", ";
    list += shown(*v);
  }
  if (list.empty()) return std::nullopt;
  return "not one of @" + a.name + " " + list;
}

bool has_string_argument(const Annotation& a) {
  for (const ExprPtr& arg : a.args) {
    if (arg->kind == ExprKind::kString) return true;
  }
  return false;
}

}  // namespace

std::optional<std::string> annotation_violation(const AttrDecl& attr, const shape::Value& value) {
  for (const Annotation& a : attr.annotations) {
    if (!restricted(a)) continue;
    std::optional<std::string> why;
    if (a.name == "Enum" || (a.name == "Range" && has_string_argument(a))) {
      why = enum_violation(a, value);
    } else if (a.name == "Range" && std::holds_alternative<double>(value)) {
      why = range_violation(a, std::get<double>(value));
    }
    if (why) return why;
  }
  return std::nullopt;
}

}  // namespace insula::lang::cga
