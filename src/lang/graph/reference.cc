#include "lang/graph/reference.h"

#include "lang/graph/catalogue.h"

namespace insula::lang::graph {
namespace {

std::string port_text(const PortSpec& p, bool input) {
  std::string text = "`" + p.name + "`: ";
  text += p.generic ? "T" : std::string(entity_type_name(p.type));
  if (p.generic && p.type != EntityType::kEntity) {
    text += " (a " + std::string(entity_type_name(p.type)) + ")";
  }
  if (input && p.mode == PortMode::kCollective) text += ", collective";
  if (input && p.mode == PortMode::kEither) text += ", single or collective";
  if (input && p.optional) text += ", optional";
  return text;
}

std::string param_text(const ParamSpec& p) {
  std::string text = "`" + p.name + "`: ";
  text += p.registry_type.empty() ? std::string(value_type_name(p.type)) : p.registry_type;
  if (!p.choices.empty()) {
    text += " (";
    for (std::size_t i = 0; i < p.choices.size(); ++i) text += (i > 0 ? " | " : "") + p.choices[i];
    text += ")";
  }
  const auto bound = [](double v) {
    std::string t = std::to_string(v);
    t.erase(t.find_last_not_of('0') + 1);
    if (!t.empty() && t.back() == '.') t.pop_back();
    return t;
  };
  if (p.min) text += " >= " + bound(*p.min);
  if (p.max) text += " <= " + bound(*p.max);
  text += p.default_json ? " = `" + *p.default_json + "`" : " (required)";
  if (p.per_entity) text += ", per entity";
  return text;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : "<br>") + s;
  return out.empty() ? "-" : out;
}

}  // namespace

std::string node_reference_markdown() {
  std::string out =
      "# Graph node reference\n\n"
      "Generated from the node catalogue (`src/lang/graph/catalogue.cc`) by\n"
      "`insula::lang::graph::node_reference_markdown()`; `tests/lang/graph/reference_test.cc` "
      "fails\nwhen this file differs. Regenerate with `INSULA_REGENERATE=1 "
      "build/tests/lang/test_lang_graph_reference_test`.\n\n"
      "The format is `../shared/docs/graph-format.md` (§11 for the semantics of each type); how\n"
      "it maps to code is docs/graph-executor.md. Ports marked T take the type of what arrives;\n"
      "parameters marked per entity are evaluated for every entity of a collective list.\n"
      "Shape operations take the registry's parameters (docs/operations.md).\n";
  std::string family;
  for (const NodeType& t : catalogue()) {
    if (t.category != family) {
      family = t.category;
      out += "\n## " + family + "\n";
    }
    out += "\n### `" + t.name + "`\n\n" + t.doc +
           (t.registry_op.empty() ? "" : " (registry `" + t.registry_op + "`)") + ".\n\n";
    std::vector<std::string> inputs;
    for (const PortSpec& p : t.inputs) inputs.push_back(port_text(p, true));
    std::vector<std::string> outputs;
    for (const PortSpec& p : t.outputs) outputs.push_back(port_text(p, false));
    std::vector<std::string> params;
    for (const ParamSpec& p : t.params) params.push_back(param_text(p));
    std::vector<std::string> augments;
    for (const AugmentSpec& a : t.augments) {
      std::string text = "`" + a.kind + "`" + (a.makes_ports ? " (one port per `out`)" : "") + ": ";
      for (std::size_t i = 0; i < a.fields.size(); ++i) {
        text += (i > 0 ? "; " : "") + param_text(a.fields[i]);
      }
      augments.push_back(text);
    }
    std::vector<std::string> writes;
    for (const std::string& w : t.writes) writes.push_back("`" + w + "`");
    out += "| inputs | outputs | parameters | augmentations | writes |\n|---|---|---|---|---|\n";
    out += "| " + join(inputs) + " | " + join(outputs) + " | " + join(params) + " | " +
           join(augments) + " | " + join(writes) + " |\n";
  }
  return out;
}

std::vector<std::string> graph_spellings(const shape::Operation& op) {
  std::vector<std::string> out;
  for (const NodeType& t : catalogue()) {
    if (t.registry_op == op.name) out.push_back(t.name);
  }
  out.push_back("shape.op op=\"" + op.name + "\"");
  return out;
}

}  // namespace insula::lang::graph
