#include "lang/graph/context.h"

#include <algorithm>
#include <cmath>

#include "lang/graph/eval.h"
#include "lang/graph/properties.h"
#include "shape/rng.h"

namespace insula::lang::graph {
namespace {

// What expressions read while a node evaluates one parameter on one entity (§5).
class ContextEnv final : public EvalEnv {
 public:
  ContextEnv(ExecutionContext& context, const GraphExecution& execution, std::size_t round,
             EntityId entity, std::uint64_t stream)
      : context_(context), execution_(execution), round_(round), entity_(entity), rng_(stream) {}

  Value parameter(const std::string& name) override {
    const Graph& g = *execution_.graph().graph;
    const Declaration* d = g.parameter(name);
    return execution_.parameters()[static_cast<std::size_t>(d - g.parameters.data())];
  }
  std::optional<Value> attribute(const std::string& port, const std::string& name) override {
    EntityId e = entity_;
    if (!port.empty()) {
      const std::span<const EntityId> at = context_.input(round_, context_.input_port(port));
      e = at.empty() ? kNoEntity : at.front();
    }
    if (e == kNoEntity) return std::nullopt;
    return context_.attribute(e, name);
  }
  std::optional<Value> property(const std::string& name, std::string& error) override {
    if (entity_ == kNoEntity) {
      error = "'" + name + "()' needs a current entity and there is none";
      return std::nullopt;
    }
    return entity_property(context_.entities(), context_.tree(), entity_, name, error);
  }
  shape::Rng& rng() override { return rng_; }

 private:
  ExecutionContext& context_;
  const GraphExecution& execution_;
  std::size_t round_;
  EntityId entity_;
  shape::Rng rng_;
};

const ParamValue* find_value(const std::vector<ParamValue>& values, std::string_view name) {
  for (const ParamValue& v : values) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

// Catalogue defaults are JSON text ("30", "\"hip\"", "[0,0,0]", "\"= pos()\"").
const JsonValue& default_json(RunState& state, const std::string& text) {
  state.default_sources.push_back(std::make_unique<base::Source>("<default>", text));
  base::Result<JsonValue> parsed = parse_json(*state.default_sources.back());
  state.default_json.push_back(
      std::make_unique<JsonValue>(parsed.ok() ? std::move(parsed.value()) : JsonValue{}));
  return *state.default_json.back();
}

std::string type_text(const Value& v) {
  return std::string(value_type_name(v.type()));
}

}  // namespace

std::uint64_t name_hash(std::string_view name) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

Value declared_default(const Declaration& d, RunState& state) {
  if (d.default_value != nullptr) {
    auto it = state.literals.find(d.default_value);
    if (it == state.literals.end()) {
      std::optional<Value> v = value_from_json(*d.default_value, d.type);
      it = state.literals.emplace(d.default_value, v ? *v : Value()).first;
    }
    return it->second;
  }
  switch (d.type) {
    case ValueType::kInteger:
      return Value(std::int64_t{0});
    case ValueType::kBool:
      return Value(false);
    case ValueType::kString:
    case ValueType::kEnum:
      return Value(std::string());
    case ValueType::kVec3:
      return Value(kernel::Vec3{});
    case ValueType::kList:
      return Value(ValueList{});
    default:
      return Value(0.0);
  }
}

ExecutionContext::ExecutionContext(GraphExecution& execution, std::size_t node,
                                   const Rounds& rounds,
                                   std::vector<std::vector<EntityId>>& outputs)
    : execution_(execution),
      state_(execution.state()),
      node_(node),
      checked_(execution.graph().nodes[node]),
      rounds_(rounds),
      outputs_(outputs) {}

std::size_t ExecutionContext::input_port(std::string_view name) const {
  for (std::size_t p = 0; p < checked_.inputs.size(); ++p) {
    if (checked_.inputs[p].name == name) return p;
  }
  return checked_.inputs.size();
}

std::size_t ExecutionContext::output_port(std::string_view name) const {
  for (std::size_t p = 0; p < checked_.outputs.size(); ++p) {
    if (checked_.outputs[p].name == name) return p;
  }
  return checked_.outputs.size();
}

std::size_t ExecutionContext::augment_port(std::size_t item) const {
  return output_port(checked_.node->augment[item].out);
}

EntityId ExecutionContext::current(std::size_t round) const {
  for (std::size_t p = 0; p < checked_.inputs.size(); ++p) {
    const std::span<const EntityId> at = rounds_.at(round, p);
    if (!at.empty()) return at.front();
    if (connected(p)) return kNoEntity;
  }
  return kNoEntity;
}

const ParamValue* ExecutionContext::given(std::string_view name) const {
  return find_value(checked_.node->params, name);
}

bool ExecutionContext::has_param(std::string_view name) const {
  return given(name) != nullptr;
}

bool ExecutionContext::has_field(std::size_t item, std::string_view name) const {
  return find_value(checked_.node->augment[item].fields, name) != nullptr;
}

Value ExecutionContext::param(std::size_t round, std::string_view name) {
  return param_on(round, name, current(round));
}

Value ExecutionContext::param_on(std::size_t round, std::string_view name, EntityId entity) {
  const std::string what = "parameter '" + std::string(name) + "' of '" + checked_.node->id +
                           "' (" + checked_.node->type + ")";
  const ParamSpec* spec = checked_.type->param(name);
  const ParamValue* value = given(name);
  if (value != nullptr) return evaluate(*value, *spec, round, entity, what);
  return default_of(*spec, round, entity, what);
}

Value ExecutionContext::field(std::size_t round, std::size_t item, std::string_view name,
                              EntityId entity) {
  const Augmentation& a = checked_.node->augment[item];
  // A node type with one augmentation kind lets items omit `kind`.
  const AugmentSpec* kind =
      a.kind.empty() ? &checked_.type->augments.front() : checked_.type->augment(a.kind);
  const ParamSpec* spec = nullptr;
  for (const ParamSpec& f : kind->fields) {
    if (f.name == name) spec = &f;
  }
  const std::string what = "field '" + std::string(name) + "' of augmentation " +
                           std::to_string(item) + " of '" + checked_.node->id + "'";
  const ParamValue* value = find_value(a.fields, name);
  if (value != nullptr) return evaluate(*value, *spec, round, entity, what);
  return default_of(*spec, round, entity, what);
}

Value ExecutionContext::evaluate_json(std::size_t round, const JsonValue& value, ValueType type,
                                      EntityId entity, const std::string& what) {
  ParamValue v;
  v.value = &value;
  v.name = what;
  const JsonValue* literal = value.kind == JsonValue::Kind::kObject && value.members.size() == 1 &&
                                     value.members[0].key == "value"
                                 ? &value.members[0].value
                                 : nullptr;
  if (literal != nullptr) v.value = literal;
  v.expression = literal == nullptr && value.kind == JsonValue::Kind::kString &&
                 !value.text.empty() && value.text[0] == '=';
  ParamSpec spec;
  spec.type = type;
  return evaluate(v, spec, round, entity, what);
}

Value ExecutionContext::default_of(const ParamSpec& spec, std::size_t round, EntityId entity,
                                   const std::string& what) {
  const std::string key = checked_.node->type + "." + spec.name;
  if (const auto it = state_.catalogue_defaults.find(key); it != state_.catalogue_defaults.end()) {
    return it->second;
  }
  const JsonValue& json = default_json(state_, spec.default_json.value_or("null"));
  if (json.kind == JsonValue::Kind::kString && !json.text.empty() && json.text[0] == '=') {
    auto it = state_.default_expressions.find(key);
    if (it == state_.default_expressions.end()) {
      ExprError error;
      std::optional<Expr> parsed = parse_expression(std::string_view(json.text).substr(1), error);
      it = state_.default_expressions.emplace(key, ParsedExpression{*parsed, &json, 1}).first;
    }
    return typed(expression(it->second, *execution_.graph().graph, round, entity, spec.name), spec,
                 what, checked_.node->offset);
  }
  std::optional<Value> v = value_from_json(json, spec.type);
  const Value value = v ? *v : Value();
  state_.catalogue_defaults.emplace(key, value);
  return value;
}

Value ExecutionContext::evaluate(const ParamValue& value, const ParamSpec& spec, std::size_t round,
                                 EntityId entity, const std::string& what) {
  const JsonValue& json = *value.value;
  if (!value.expression) {
    auto it = state_.literals.find(&json);
    if (it == state_.literals.end()) {
      std::optional<Value> v = value_from_json(json, spec.type);
      it = state_.literals.emplace(&json, v ? *v : Value()).first;
    }
    return typed(it->second, spec, what, json.offset);
  }
  auto it = state_.expressions.find(&json);
  if (it == state_.expressions.end()) {
    ExprError error;
    std::optional<Expr> parsed = parse_expression(std::string_view(json.text).substr(1), error);
    it = state_.expressions.emplace(&json, ParsedExpression{*parsed, &json, 1}).first;
  }
  return typed(expression(it->second, *execution_.graph().graph, round, entity, value.name), spec,
               what, json.offset);
}

Value ExecutionContext::expression(const ParsedExpression& parsed, const Graph& graph,
                                   std::size_t round, EntityId entity, std::string_view param) {
  const std::uint64_t seed = entity == kNoEntity ? state_.out.seed : entities()[entity].seed;
  const std::uint64_t stream = shape::mix64(
      seed ^ shape::mix64(name_hash(checked_.node->id) ^ shape::mix64(name_hash(param))));
  ContextEnv env(*this, execution_, round, entity, stream);
  EvalError error;
  std::optional<Value> v = graph::evaluate(parsed.expr, env, error);
  if (!v) {
    const std::size_t offset =
        graph.source != nullptr && parsed.string->offset < graph.source->text().size()
            ? string_byte_offset(*graph.source, *parsed.string, parsed.skip + error.at)
            : checked_.node->offset;
    throw RunError{"G052", error.message + " (node '" + checked_.node->id + "')", &graph, offset,
                   execution_.notes()};
  }
  return *v;
}

Value ExecutionContext::typed(Value value, const ParamSpec& spec, const std::string& what,
                              std::size_t offset) {
  if (!spec.registry_type.empty() || spec.type == ValueType::kAny) return value;
  std::optional<Value> v = convert(value, spec.type);
  if (!v) {
    throw RunError{"G052",
                   what + " needs " + std::string(value_type_name(spec.type)) + "; got " +
                       type_text(value) + " " + to_string(value),
                   execution_.graph().graph, offset, execution_.notes()};
  }
  if (v->is_number()) {
    const double x = v->number();
    const auto out_of_range = [&](const char* op, double bound) {
      throw RunError{
          "G052",
          what + " must be " + op + " " + to_string(Value(bound)) + "; got " + to_string(*v),
          execution_.graph().graph, offset, execution_.notes()};
    };
    if (spec.min && x < *spec.min) out_of_range(">=", *spec.min);
    if (spec.max && x > *spec.max) out_of_range("<=", *spec.max);
  }
  if (spec.type == ValueType::kEnum && !spec.choices.empty() &&
      std::find(spec.choices.begin(), spec.choices.end(), v->text()) == spec.choices.end()) {
    std::string list;
    for (const std::string& c : spec.choices) list += (list.empty() ? "" : ", ") + c;
    throw RunError{"G052", what + " must be one of " + list + "; got '" + v->text() + "'",
                   execution_.graph().graph, offset, execution_.notes()};
  }
  return *v;
}

EntityId ExecutionContext::create(std::size_t round, EntityType type, std::uint32_t position) {
  const std::size_t impulse = input_port("impulse");
  if (impulse < checked_.inputs.size()) {
    const std::span<const EntityId> at = rounds_.at(round, impulse);
    if (!at.empty()) return entities().derive(at.front(), type);
  }
  // §9.9: the graph seed, the node id, the round and the position (and the subgraph execution,
  // so a source inside a subgraph differs from round to round of its node).
  std::uint64_t seed = shape::mix64(state_.out.seed ^ name_hash(checked_.node->id));
  seed = shape::child_seed(seed, static_cast<std::uint32_t>(execution_.execution()));
  seed = shape::child_seed(seed, static_cast<std::uint32_t>(round));
  seed = shape::child_seed(seed, position);
  return entities().create(type, seed);
}

void ExecutionContext::write(EntityId entity, std::string_view name, const Value& value) {
  for (const AttributeMapping& m : checked_.node->attributes) {
    if (m.node_attribute == name) set_attribute(entity, m.to, value);
  }
}

void ExecutionContext::set_attribute(EntityId entity, std::string_view name, const Value& value) {
  const Graph& g = *execution_.graph().graph;
  const Declaration* d = g.attribute(name);
  if (d == nullptr) return;
  std::optional<Value> v = convert(value, d->type);
  if (!v) {
    error("attribute '" + std::string(name) + "' is " + std::string(value_type_name(d->type)) +
          "; the node gives " + type_text(value) + " " + to_string(value));
  }
  entities().set_attribute(entity, execution_.attribute_key(std::string(name)), std::move(*v));
}

Value ExecutionContext::attribute(EntityId entity, std::string_view name) {
  const Graph& g = *execution_.graph().graph;
  const Declaration* d = g.attribute(name);
  const Value* v = entities().attribute(entity, execution_.attribute_key(std::string(name)));
  return v != nullptr ? *v : declared_default(*d, state_);
}

std::vector<std::pair<std::string, Value>> ExecutionContext::stored_attributes(EntityId entity) {
  std::vector<std::pair<std::string, Value>> out;
  for (const Declaration& d : execution_.graph().graph->attributes) {
    const Value* v = entities().attribute(entity, execution_.attribute_key(d.name));
    if (v != nullptr) out.emplace_back(d.name, *v);
  }
  return out;
}

std::uint16_t ExecutionContext::material(const std::string& name, std::array<float, 4> rgba) {
  std::vector<shape::Material>& materials = state_.out.materials;
  for (std::size_t i = 1; i < materials.size(); ++i) {
    if (materials[i].name == name) return static_cast<std::uint16_t>(i);
  }
  materials.push_back({name, rgba});
  return static_cast<std::uint16_t>(materials.size() - 1);
}

// One material per texture image (texture.text's default name is shared by every sign, and
// each sign shows its own text): named after the texture, numbered when the name repeats.
std::uint16_t ExecutionContext::textured_material(const std::shared_ptr<const Texture>& texture) {
  for (const auto& [m, t] : state_.out.textures) {
    if (t == texture) return m;
  }
  std::string name = "texture_" + texture->name;
  for (std::size_t k = 2; std::any_of(state_.out.materials.begin(), state_.out.materials.end(),
                                      [&](const shape::Material& m) { return m.name == name; });
       ++k) {
    name = "texture_" + texture->name + "_" + std::to_string(k);
  }
  state_.out.materials.push_back({name, {1, 1, 1, 1}});
  const auto m = static_cast<std::uint16_t>(state_.out.materials.size() - 1);
  state_.out.textures[m] = texture;
  return m;
}

void ExecutionContext::fail(EntityId /*entity*/, const std::string& message) {
  const std::string who = execution_.prefix() + checked_.node->id;
  auto [it, added] =
      state_.failures.try_emplace(who, 0,
                                  RunError{"W040", message, execution_.graph().graph,
                                           checked_.node->id_offset, execution_.notes()});
  if (added) state_.failure_order.push_back(who);
  ++it->second.first;
  ++state_.out.failed[who];
}

void ExecutionContext::warning(const std::string& code, const std::string& message) {
  if (!state_.warned.insert(code + message).second) return;
  state_.warnings.push_back(RunError{code, message + " (node '" + checked_.node->id + "')",
                                     execution_.graph().graph, checked_.node->id_offset,
                                     execution_.notes()});
}

void ExecutionContext::record_lot(EntityId entity, std::string id) {
  state_.out.lots.emplace(entity, std::move(id));
}

void ExecutionContext::error(const std::string& message) {
  throw RunError{"G052", message + " (node '" + checked_.node->id + "')", execution_.graph().graph,
                 checked_.node->id_offset, execution_.notes()};
}

shape::Rng ExecutionContext::rng(EntityId entity, std::string_view stream) const {
  const std::uint64_t seed =
      entity == kNoEntity ? state_.out.seed : state_.out.entities[entity].seed;
  return shape::Rng(shape::mix64(
      seed ^ shape::mix64(name_hash(checked_.node->id) ^ shape::mix64(name_hash(stream)))));
}

}  // namespace insula::lang::graph
