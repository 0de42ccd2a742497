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

}  // namespace insula::lang::cga
