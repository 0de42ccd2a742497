// What a node implementation sees of one execution of its node (graph-format.md §9.4): the
// rounds' input entities, its parameters evaluated on demand (per round or per entity, §5), its
// output ports, node attributes (written through the node's mapping, §7), entity creation with
// the seeds of §9.9, and failures (W040). Implementations live in nodes_<family>.cc, one function
// per node type (nodes.h); the executor (executor.cc) owns the queues and transfers.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/graph/checker.h"
#include "lang/graph/entity.h"
#include "lang/graph/value.h"
#include "shape/operation.h"
#include "shape/shape_tree.h"

namespace insula::lang::graph {

struct RunOptions;

class NodeContext {
 public:
  virtual ~NodeContext() = default;

  // --- inputs
  virtual std::size_t rounds() const = 0;
  // The entities at input port `port` (index into CheckedNode::inputs) in `round`: one for a
  // single port, the whole queue for a collective one, none for an unconnected optional port.
  virtual std::span<const EntityId> input(std::size_t round, std::size_t port) const = 0;
  // The index of input port `name` (a programming error when absent: catalogue names only).
  virtual std::size_t input_port(std::string_view name) const = 0;
  virtual bool connected(std::size_t port) const = 0;
  // The round's current entity (§5): the first input port's entity, or kNoEntity.
  virtual EntityId current(std::size_t round) const = 0;

  // --- parameters (the node's value, else the catalogue default; converted to the declared
  // type; an evaluation error stops the run with G052 at the expression)
  // A per-round parameter, with the round's current entity.
  virtual Value param(std::size_t round, std::string_view name) = 0;
  // A per-entity parameter (†) evaluated on `entity`.
  virtual Value param_on(std::size_t round, std::string_view name, EntityId entity) = 0;
  virtual bool has_param(std::string_view name) const = 0;  // given in the file
  // Augmentation items (in order) and their fields, evaluated like parameters; a field the item
  // does not give takes the kind's default.
  virtual std::size_t augment_count() const = 0;
  virtual std::string_view augment_kind(std::size_t item) const = 0;
  virtual Value field(std::size_t round, std::size_t item, std::string_view name,
                      EntityId entity) = 0;
  virtual bool has_field(std::size_t item, std::string_view name) const = 0;
  // A JSON value of the node's (an entry of attr.set's `values`) evaluated like a parameter of
  // `type` on `entity`: an expression when it is a string starting with `=`.
  virtual Value evaluate_json(std::size_t round, const JsonValue& value, ValueType type,
                              EntityId entity, const std::string& what) = 0;
  // `attr.set`'s values: attribute names in file order, evaluated one by one.
  virtual const Node& node() const = 0;
  virtual const CheckedNode& checked() const = 0;

  // --- outputs
  // The index of output port `name` (catalogue port or augmentation port).
  virtual std::size_t output_port(std::string_view name) const = 0;
  // The output port fed by augmentation item `item`.
  virtual std::size_t augment_port(std::size_t item) const = 0;
  // Appends `entity` to output port `port` (production order = call order).
  virtual void emit(std::size_t port, EntityId entity) = 0;

  // --- entities
  virtual EntityStore& entities() = 0;
  virtual shape::ShapeTree& tree() = 0;
  // A new entity made in `round` at `position` among that round's creations (§9.9); with an
  // impulse entity this round it descends from it (and inherits its attributes).
  virtual EntityId create(std::size_t round, EntityType type, std::uint32_t position) = 0;
  // Writes node attribute `name` on `entity` when the node maps it to a graph attribute
  // (discarded otherwise, §7).
  virtual void write(EntityId entity, std::string_view name, const Value& value) = 0;
  // Sets graph attribute `name` (attr.set).
  virtual void set_attribute(EntityId entity, std::string_view name, const Value& value) = 0;
  // The graph's declared attributes that `entity` or an ancestor set (defaults are not stored),
  // in declaration order.
  virtual std::vector<std::pair<std::string, Value>> stored_attributes(EntityId entity) = 0;
  // The value of graph attribute `name` seen by `entity` (its default when never set).
  virtual Value attribute(EntityId entity, std::string_view name) = 0;
  // The index of a run-wide material (created on first use).
  virtual std::uint16_t material(const std::string& name, std::array<float, 4> rgba) = 0;
  // A material named after a texture that shows it (shape.set_texture).
  virtual std::uint16_t textured_material(const std::shared_ptr<const Texture>& texture) = 0;
  // An operation failed on `entity` (W040): it is dropped and counted.
  virtual void fail(EntityId entity, const std::string& message) = 0;
  // A run-time warning at the node (W030), reported once per distinct message.
  virtual void warning(const std::string& code, const std::string& message) = 0;
  // Marks `entity` as made for the lot `id` (create.lots; RunResult::lots).
  virtual void record_lot(EntityId entity, std::string id) = 0;
  // Whether the node's graph declares attribute `name`.
  bool declares(std::string_view name) const { return declared_type(name).has_value(); }
  // The type the node's graph declares attribute `name` with, if it does.
  virtual std::optional<ValueType> declared_type(std::string_view name) const = 0;
  // Stops the run with G052 at the node (a run-time type error).
  [[noreturn]] virtual void error(const std::string& message) = 0;
  // The node's random stream for `entity` and stream name (§9.9).
  virtual shape::Rng rng(EntityId entity, std::string_view stream) const = 0;
  virtual const RunOptions& options() const = 0;
  virtual std::uint64_t graph_seed() const = 0;
};

}  // namespace insula::lang::graph
