#include "lang/cga/geometry_functions.h"

#include <string>

namespace insula::lang::cga {

const shape::GeometryQueryInfo* geometry_query_of(const Expr& e) {
  if (e.kind != ExprKind::kMember || dotted_name(e) != "geometry." + e.text) return nullptr;
  return shape::find_geometry_query(e.text);
}

std::optional<shape::FaceSelector> geometry_face_selector(std::string_view word) {
  if (word == "surface") return shape::FaceSelector::kAll;
  const std::optional<shape::FaceSelector> selector = shape::face_selector_named(word);
  if (!selector || *selector >= shape::FaceSelector::kEave) return std::nullopt;
  return selector;
}

}  // namespace insula::lang::cga
