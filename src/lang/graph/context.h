// The NodeContext of one node execution (internal to the executor): parameter and expression
// evaluation (§5), entity creation with the seeds of §9.9, node attribute mapping (§7) and
// failures (W040). Parameters are evaluated on the executor's thread only.
#pragma once

#include <vector>

#include "lang/graph/execution.h"
#include "lang/graph/node_context.h"

namespace insula::lang::graph {

class ExecutionContext final : public NodeContext {
 public:
  ExecutionContext(GraphExecution& execution, std::size_t node, const Rounds& rounds,
                   std::vector<std::vector<EntityId>>& outputs);

  std::size_t rounds() const override { return rounds_.count; }
  std::span<const EntityId> input(std::size_t round, std::size_t port) const override {
    return rounds_.at(round, port);
  }
  std::size_t input_port(std::string_view name) const override;
  bool connected(std::size_t port) const override { return execution_.connected(node_, port); }
  EntityId current(std::size_t round) const override;

  Value param(std::size_t round, std::string_view name) override;
  Value param_on(std::size_t round, std::string_view name, EntityId entity) override;
  bool has_param(std::string_view name) const override;
  std::size_t augment_count() const override { return checked_.node->augment.size(); }
  std::string_view augment_kind(std::size_t item) const override {
    const std::string& kind = checked_.node->augment[item].kind;
    return kind.empty() ? std::string_view(checked_.type->augments.front().kind) : kind;
  }
  Value field(std::size_t round, std::size_t item, std::string_view name, EntityId entity) override;
  bool has_field(std::size_t item, std::string_view name) const override;
  Value evaluate_json(std::size_t round, const JsonValue& value, ValueType type, EntityId entity,
                      const std::string& what) override;
  const Node& node() const override { return *checked_.node; }
  const CheckedNode& checked() const override { return checked_; }

  std::size_t output_port(std::string_view name) const override;
  std::size_t augment_port(std::size_t item) const override;
  void emit(std::size_t port, EntityId entity) override { outputs_[port].push_back(entity); }

  EntityStore& entities() override { return state_.out.entities; }
  shape::ShapeTree& tree() override { return state_.out.tree; }
  EntityId create(std::size_t round, EntityType type, std::uint32_t position) override;
  void write(EntityId entity, std::string_view name, const Value& value) override;
  void set_attribute(EntityId entity, std::string_view name, const Value& value) override;
  Value attribute(EntityId entity, std::string_view name) override;
  std::vector<std::pair<std::string, Value>> stored_attributes(EntityId entity) override;
  std::uint16_t material(const std::string& name, std::array<float, 4> rgba) override;
  std::uint16_t textured_material(const std::shared_ptr<const Texture>& texture) override;
  void fail(EntityId entity, const std::string& message) override;
  [[noreturn]] void error(const std::string& message) override;
  void warning(const std::string& code, const std::string& message) override;
  void record_lot(EntityId entity, std::string id) override;
  std::optional<ValueType> declared_type(std::string_view name) const override {
    const Declaration* d = execution_.graph().graph->attribute(name);
    return d != nullptr ? std::optional<ValueType>(d->type) : std::nullopt;
  }
  shape::Rng rng(EntityId entity, std::string_view stream) const override;
  const RunOptions& options() const override { return state_.options; }
  std::uint64_t graph_seed() const override { return state_.out.seed; }

  // Evaluates `value` (a literal or an expression) as `spec` says, on `entity` in `round`.
  Value evaluate(const ParamValue& value, const ParamSpec& spec, std::size_t round, EntityId entity,
                 const std::string& what);

 private:
  const ParamValue* given(std::string_view name) const;
  Value default_of(const ParamSpec& spec, std::size_t round, EntityId entity,
                   const std::string& what);
  Value expression(const ParsedExpression& parsed, const Graph& graph, std::size_t round,
                   EntityId entity, std::string_view param);
  Value typed(Value value, const ParamSpec& spec, const std::string& what, std::size_t offset);

  GraphExecution& execution_;
  RunState& state_;
  std::size_t node_;
  const CheckedNode& checked_;
  const Rounds& rounds_;
  std::vector<std::vector<EntityId>>& outputs_;
};

// The value an entity sees for a declared attribute when it never set it (§7).
Value declared_default(const Declaration& declaration, RunState& state);

// FNV-1a of a name: stable across platforms, for the seeds of §9.9.
std::uint64_t name_hash(std::string_view name);

}  // namespace insula::lang::graph
