// The node catalogue of the format (§11): one table of every node type with its ports, parameters,
// the node attributes it writes and its augmentation kinds. Shape operations take their parameters
// from the shared operation registry (shape::registry()), so a graph reaches what CGA and Lua
// reach; docs/graph-executor.md lists where the table extends the format.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/graph/types.h"

namespace insula::lang::graph {

enum class PortMode : std::uint8_t { kSingle, kCollective, kEither };

struct PortSpec {
  std::string name;
  EntityType type = EntityType::kEntity;  // a generic port's bound
  bool generic = false;                   // `T`: the arriving type (outputs: the inputs' T)
  PortMode mode = PortMode::kSingle;      // inputs only; kEither defaults to single
  bool optional = false;                  // inputs only
};

struct ParamSpec {
  std::string name;
  ValueType type = ValueType::kAny;
  std::optional<std::string> default_json;  // none: required
  std::optional<double> min;
  std::optional<double> max;
  std::vector<std::string> choices;  // kEnum
  bool per_entity = false;           // † in §11
  std::string registry_type;         // the registry's type when it has one ("size", "size list")
};

// An augmentation kind: its own fields, and whether each item feeds an output port.
struct AugmentSpec {
  std::string kind;
  std::vector<ParamSpec> fields;
  bool makes_ports = false;
};

struct NodeType {
  std::string name;
  std::string category;  // "creation", "shape", "path", "list", "query", "flow", "light",
                         // "texture", "rule", "terrain"
  std::vector<PortSpec> inputs;
  std::vector<PortSpec> outputs;  // fixed ports, before augmentation ports
  std::vector<ParamSpec> params;
  std::vector<std::string> writes;  // node attributes
  std::vector<AugmentSpec> augments;
  std::string registry_op;  // the shape operation it wraps, if any
  bool creating = false;    // has the optional `impulse:entity` input (first input)
  std::string doc;

  const PortSpec* input(std::string_view port) const;
  const PortSpec* output(std::string_view port) const;
  const ParamSpec* param(std::string_view param) const;
  const AugmentSpec* augment(std::string_view kind) const;
  // A collective node: some input port is (always) collective.
  bool collective() const;
};

// Every node type of §11 (without `subgraph` and `note`, which the checker handles), in the
// catalogue's order; built once.
std::span<const NodeType> catalogue();
const NodeType* find_node_type(std::string_view name);

}  // namespace insula::lang::graph
