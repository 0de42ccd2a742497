#include "lang/cga/ast.h"

namespace insula::lang::cga {

std::string dotted_name(const Expr& expr) {
  if (expr.kind == ExprKind::kIdent) return expr.text;
  if (expr.kind != ExprKind::kMember) return "";
  std::string object = dotted_name(*expr.operands[0]);
  if (object.empty()) return "";
  object += '.';
  object += expr.text;
  return object;
}

ExprPtr clone(const Expr& expr) {
  auto copy = std::make_unique<Expr>();
  copy->kind = expr.kind;
  copy->range = expr.range;
  copy->number = expr.number;
  copy->boolean = expr.boolean;
  copy->text = expr.text;
  copy->unary_op = expr.unary_op;
  copy->binary_op = expr.binary_op;
  copy->elementwise = expr.elementwise;
  for (const ExprPtr& operand : expr.operands) copy->operands.push_back(clone(*operand));
  return copy;
}

}  // namespace insula::lang::cga
