// What CityEngine's annotations say about an attribute's values (docs/cga-cityengine.md):
// `@Range(min = a, max = b)` (also the old positional `@Range(a, b)`), `@Enum(v1, v2, ...)` (also
// the old `@Range("x", "y")`), each `restricted` unless it says `restricted = false`. Used to
// check `insula build --set` and, later, by the studio's parameter panel.
#pragma once

#include <optional>
#include <string>

#include "lang/cga/ast.h"
#include "shape/value.h"

namespace insula::lang::cga {

// Why `value` is not allowed for `attr` by its annotations ("outside @Range 3 .. 30",
// "not one of @Enum \"flat\", \"hip\""), or nullopt when it is.
std::optional<std::string> annotation_violation(const AttrDecl& attr, const shape::Value& value);

}  // namespace insula::lang::cga
