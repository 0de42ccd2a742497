#include "apps/studio/reference.h"

#include <string>

#include "lang/graph/catalogue.h"
#include "lang/graph/types.h"
#include "shape/operation.h"

namespace insula::studio {

namespace {

nlohmann::json operation_json(const shape::Operation& op) {
  nlohmann::json params = nlohmann::json::array();
  for (const shape::ParamDecl& p : op.params) {
    nlohmann::json param = {
        {"name", p.name}, {"type", std::string(shape::param_type_name(p.type))}, {"doc", p.doc}};
    if (p.default_value) param["default"] = shape::to_string(*p.default_value);
    if (!p.choices.empty()) param["choices"] = p.choices;
    params.push_back(std::move(param));
  }
  return {{"name", op.name}, {"doc", op.doc}, {"params", std::move(params)}};
}

nlohmann::json ports_json(const std::vector<lang::graph::PortSpec>& ports) {
  nlohmann::json out = nlohmann::json::array();
  for (const lang::graph::PortSpec& p : ports) {
    out.push_back({{"name", p.name},
                   {"type", p.generic ? std::string("T")
                                      : std::string(lang::graph::entity_type_name(p.type))},
                   {"collective", p.mode == lang::graph::PortMode::kCollective}});
  }
  return out;
}

}  // namespace

nlohmann::json reference_json() {
  nlohmann::json operations = nlohmann::json::array();
  for (const shape::Operation& op : shape::registry().operations()) {
    operations.push_back(operation_json(op));
  }
  nlohmann::json nodes = nlohmann::json::array();
  for (const lang::graph::NodeType& type : lang::graph::catalogue()) {
    nlohmann::json params = nlohmann::json::array();
    for (const lang::graph::ParamSpec& p : type.params) params.push_back(p.name);
    nodes.push_back({{"name", type.name},
                     {"category", type.category},
                     {"doc", type.doc},
                     {"inputs", ports_json(type.inputs)},
                     {"outputs", ports_json(type.outputs)},
                     {"params", std::move(params)}});
  }
  return {{"operations", std::move(operations)}, {"nodes", std::move(nodes)}};
}

}  // namespace insula::studio
