// Attributes and flow control (graph-format.md §11 "Attributes and flow control").
#include "lang/graph/nodes.h"

namespace insula::lang::graph {
namespace {

const ParamValue* given(NodeContext& c, std::string_view name) {
  for (const ParamValue& v : c.node().params) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

// Writes always replace (§7); values are applied in file order, so a later one reads an
// earlier one's result.
void set(NodeContext& c) {
  const ParamValue* values = given(c, "values");
  const std::size_t in = c.input_port("in");
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    for (EntityId e : c.input(r, in)) {
      if (values != nullptr) {
        for (const JsonMember& m : values->value->members) {
          const std::string what = "value of '" + m.key + "' in '" + c.node().id + "'";
          c.set_attribute(e, m.key, c.evaluate_json(r, m.value, ValueType::kAny, e, what));
        }
      }
      c.emit(c.output_port("out"), e);
    }
  }
}

void transfer(NodeContext& c) {
  const std::size_t from = c.input_port("from");
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId e = c.current(r);
    const EntityId source = c.input(r, from).front();
    const Value names = c.param(r, "names");
    for (const Value& name : names.list()) {
      if (name.type() != ValueType::kString || !c.declares(name.text())) {
        c.error("'names' must list declared attributes; got " + to_string(name));
      }
      c.set_attribute(e, name.text(), c.attribute(source, name.text()));
    }
    c.emit(c.output_port("out"), e);
  }
}

void condition(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId e = c.current(r);
    c.emit(c.output_port(c.param(r, "if").boolean() ? "true" : "false"), e);
  }
}

void switch_(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId e = c.current(r);
    std::size_t port = c.output_port("else");
    for (std::size_t i = 0; i < c.augment_count(); ++i) {
      if (c.field(r, i, "if", e).boolean()) {
        port = c.augment_port(i);
        break;
      }
    }
    c.emit(port, e);
  }
}

// A weighted choice from the entity's own stream (§9.9), so the choice does not depend on
// what else passes through the node.
void stochastic(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId e = c.current(r);
    std::vector<double> weights;
    for (std::size_t i = 0; i < c.augment_count(); ++i) {
      weights.push_back(c.field(r, i, "weight", e).number());
    }
    shape::Rng rng = c.rng(e, "stochastic:" + std::to_string(c.param(r, "seed").integer()));
    const std::size_t k = rng.choice(weights);
    if (k >= weights.size()) {
      c.fail(e, "every branch weight is 0");
      continue;
    }
    c.emit(c.augment_port(k), e);
  }
}

void copy(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId e = c.current(r);
    const std::int64_t count = c.param(r, "count").integer();
    for (std::int64_t i = 0; i < count; ++i) {
      const EntityId out = i == 0 ? e : c.entities().copy(e);
      c.write(out, "copy", Value(i));
      c.emit(c.output_port("out"), out);
    }
  }
}

constexpr NodeImpl kNodes[] = {
    {"attr.set", set},        {"attr.transfer", transfer},     {"flow.condition", condition},
    {"flow.switch", switch_}, {"flow.stochastic", stochastic}, {"flow.copy", copy},
};

}  // namespace

std::span<const NodeImpl> flow_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
