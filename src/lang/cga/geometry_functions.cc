#include "lang/cga/geometry_functions.h"

#include <string>

namespace insula::lang::cga {

const shape::GeometryQueryInfo* geometry_query_of(const Expr& e) {
  if (e.kind != ExprKind::kMember || dotted_name(e) != "geometry." + e.text) return nullptr;
  return shape::find_geometry_query(e.text);
}

}  // namespace insula::lang::cga
