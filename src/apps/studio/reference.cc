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

// A node parameter as the graph editor's panel needs it: type, default (none: required), range,
// choices, whether it may read the current entity.
nlohmann::json param_json(const lang::graph::ParamSpec& p) {
  nlohmann::json out = {{"name", p.name},
                        {"type", std::string(lang::graph::value_type_name(p.type))},
                        {"per_entity", p.per_entity}};
  if (p.default_json) out["default"] = nlohmann::json::parse(*p.default_json, nullptr, false);
  if (p.min) out["min"] = *p.min;
  if (p.max) out["max"] = *p.max;
  if (!p.choices.empty()) out["choices"] = p.choices;
  return out;
}

nlohmann::json augments_json(const std::vector<lang::graph::AugmentSpec>& augments) {
  nlohmann::json out = nlohmann::json::array();
  for (const lang::graph::AugmentSpec& a : augments) {
    nlohmann::json fields = nlohmann::json::array();
    for (const lang::graph::ParamSpec& f : a.fields) fields.push_back(param_json(f));
    out.push_back(
        {{"kind", a.kind}, {"fields", std::move(fields)}, {"makes_ports", a.makes_ports}});
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
    for (const lang::graph::ParamSpec& p : type.params) params.push_back(param_json(p));
    nodes.push_back({{"name", type.name},
                     {"category", type.category},
                     {"doc", type.doc},
                     {"inputs", ports_json(type.inputs)},
                     {"outputs", ports_json(type.outputs)},
                     {"params", std::move(params)},
                     {"writes", type.writes},
                     {"augments", augments_json(type.augments)}});
  }
  return {{"operations", std::move(operations)}, {"nodes", std::move(nodes)}};
}

}  // namespace insula::studio
