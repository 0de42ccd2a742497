// CityEngine's `geometry.*` functions as CGA spells them: `geometry.area(top)`,
// `geometry.angle(maxSlope)`, `geometry.isRectangular(10)`. The measures themselves are the shape
// layer's (shape/geometry_queries.h), so every front-end answers them alike.
#pragma once

#include <optional>
#include <string_view>

#include "lang/cga/ast.h"
#include "shape/geometry_queries.h"
#include "shape/ops.h"

namespace insula::lang::cga {

// The query `e` names when it is `geometry.<name>` (a member, or a call's callee); else null.
const shape::GeometryQueryInfo* geometry_query_of(const Expr& e);

}  // namespace insula::lang::cga
