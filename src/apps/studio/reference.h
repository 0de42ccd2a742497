// What the studio's editor shows on hover (issue 15, "hover help for operations and node types
// from the registry"): every shape operation of the shared registry with its parameters, and
// every graph node type of the catalogue with its ports, as JSON for `GET /api/reference`.
#pragma once

#include <nlohmann/json.hpp>

namespace insula::studio {

nlohmann::json reference_json();

}  // namespace insula::studio
