#include "lang/graph/checker.h"

#include <algorithm>
#include <functional>
#include <map>
#include <queue>
#include <set>

#include "base/format.h"
#include "lang/graph/expr.h"
#include "lang/graph/reader.h"
#include "lang/graph/value.h"

namespace insula::lang::graph {

std::optional<std::size_t> CheckedGraph::node(std::string_view id) const {
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].node->id == id) return i;
  }
  return std::nullopt;
}

namespace {

using Kind = JsonValue::Kind;

std::string suggestion(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string near = nearest(word, candidates);
  return near.empty() ? "" : " (did you mean '" + near + "'?)";
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "(none)" : out;
}

std::string shown_literal(const JsonValue& v) {
  switch (v.kind) {
    case Kind::kString:
      return "'" + v.text + "'";
    case Kind::kInteger:
    case Kind::kNumber:
      return base::shortest_number(v.number);
    case Kind::kBool:
      return v.boolean ? "true" : "false";
    default:
      return std::string(kind_name(v.kind));
  }
}

// The registry's name for a JSON literal's type, for "expects a number; got a string".
std::string literal_type(const JsonValue& v) {
  switch (v.kind) {
    case Kind::kInteger:
      return "an integer";
    case Kind::kNumber:
      return "a number";
    case Kind::kString:
      return "a string";
    case Kind::kBool:
      return "a bool";
    case Kind::kArray:
      return "a list";
    case Kind::kObject:
      return "an object";
    case Kind::kNull:
      return "null";
  }
  return "a value";
}

std::string expected_type(const ParamSpec& p) {
  switch (p.type) {
    case ValueType::kNumber:
      return "a number";
    case ValueType::kInteger:
      return "an integer";
    case ValueType::kBool:
      return "a bool";
    case ValueType::kString:
      return "a string";
    case ValueType::kVec3:
      return "a vec3 ([x, y, z])";
    case ValueType::kList:
      return "a list";
    case ValueType::kEnum: {
      std::string out = "one of ";
      for (std::size_t i = 0; i < p.choices.size(); ++i) out += (i ? ", " : "") + p.choices[i];
      return out;
    }
    case ValueType::kAny:
      return "a value";
  }
  return "a value";
}

class GraphChecker {
 public:
  GraphChecker(const Document& doc, const Graph& graph, const std::vector<CheckedGraph>& done,
               const std::map<const Graph*, std::size_t>& index_of)
      : doc_(doc), g_(graph), done_(done), index_of_(index_of) {
    out_.graph = &graph;
    notes_ = graph_notes(doc, graph);
  }

  CheckedGraph run(std::vector<base::Diagnostic>& diagnostics) {
    out_.used_as_subgraph = doc_.used_by.count(&g_) > 0;
    nodes();
    edges();
    expressions();
    infer_types();
    check_edge_types();
    gates();
    connections();
    if (!base::has_errors(diagnostics_)) {
      out_.standalone = execution_order(out_, false);
      out_.encapsulated = execution_order(out_, true);
      ways_out();
      leaves();
    }
    for (base::Diagnostic& d : diagnostics_) diagnostics.push_back(std::move(d));
    return std::move(out_);
  }

 private:
  void report(bool warning, const std::string& code, std::string message, std::size_t offset) {
    const auto [line, column] = g_.source->locate(offset);
    base::Span span = base::Span::at(g_.source->name(), line, column);
    base::Diagnostic d = warning ? base::Diagnostic::warning(code, std::move(message), span)
                                 : base::Diagnostic::error(code, std::move(message), span);
    d.notes = notes_;
    diagnostics_.push_back(std::move(d));
  }
  void error(const std::string& code, std::string message, std::size_t offset) {
    report(false, code, std::move(message), offset);
  }

  std::string describe(const CheckedNode& n) const {
    return "'" + n.node->id + "' (" + n.node->type + ")";
  }

  const CheckedGraph* subgraph_of(const Node& n) const {
    if (n.subgraph == nullptr) return nullptr;
    const auto it = index_of_.find(n.subgraph);
    if (it == index_of_.end() || it->second >= done_.size()) return nullptr;
    const CheckedGraph& c = done_[it->second];
    return c.graph == n.subgraph ? &c : nullptr;
  }

  // G025 and type checks of one literal against its declaration.
  void literal(const std::string& owner, const ParamSpec& spec, const ParamValue& value) {
    if (value.expression || value.value == nullptr) return;
    const JsonValue& v = *value.value;
    const std::string where = owner + ": parameter '" + spec.name + "' ";
    bool type_ok = true;
    switch (spec.type) {
      case ValueType::kNumber:
        type_ok = v.is_number();
        break;
      case ValueType::kInteger:
        type_ok = v.kind == Kind::kInteger ||
                  (v.kind == Kind::kNumber && whole_integer(v.number).has_value());
        break;
      case ValueType::kBool:
        type_ok = v.kind == Kind::kBool;
        break;
      case ValueType::kString:
        type_ok = v.kind == Kind::kString;
        break;
      case ValueType::kEnum:
        if (v.kind != Kind::kString) {
          type_ok = false;
        } else if (std::find(spec.choices.begin(), spec.choices.end(), v.text) ==
                   spec.choices.end()) {
          std::string choices;
          for (std::size_t i = 0; i < spec.choices.size(); ++i) {
            choices += (i ? ", " : "") + spec.choices[i];
          }
          error("G025", where + "must be one of " + choices + "; got '" + v.text + "'", v.offset);
          return;
        }
        break;
      case ValueType::kVec3:
        type_ok = v.kind == Kind::kArray && v.items.size() == 3 &&
                  std::all_of(v.items.begin(), v.items.end(),
                              [](const JsonValue& x) { return x.is_number(); });
        break;
      case ValueType::kList:
        type_ok = v.kind == Kind::kArray;
        break;
      case ValueType::kAny:
        break;
    }
    if (!type_ok) {
      error("G025", where + "expects " + expected_type(spec) + "; got " + literal_type(v),
            v.offset);
      return;
    }
    if (v.is_number() && (spec.type == ValueType::kNumber || spec.type == ValueType::kInteger)) {
      if (spec.min && v.number < *spec.min) {
        error(
            "G025",
            where + "must be >= " + base::shortest_number(*spec.min) + "; got " + shown_literal(v),
            v.offset);
      } else if (spec.max && v.number > *spec.max) {
        error(
            "G025",
            where + "must be <= " + base::shortest_number(*spec.max) + "; got " + shown_literal(v),
            v.offset);
      }
    }
  }

  // A node's parameters (or an augmentation's fields) against their specs: G021, G025.
  void params(const std::string& owner, const std::vector<ParamSpec>& specs,
              const std::vector<ParamValue>& values, std::size_t at, const std::string& what) {
    std::vector<std::string> names;
    for (const ParamSpec& s : specs) names.push_back(s.name);
    for (const ParamValue& v : values) {
      const auto it = std::find_if(specs.begin(), specs.end(),
                                   [&](const ParamSpec& s) { return s.name == v.name; });
      if (it == specs.end()) {
        error("G021",
              "unknown " + what + " '" + v.name + "' of " + owner + suggestion(v.name, names),
              v.name_offset);
        continue;
      }
      literal(owner, *it, v);
    }
    for (const ParamSpec& s : specs) {
      if (s.default_json) continue;
      if (std::none_of(values.begin(), values.end(),
                       [&](const ParamValue& v) { return v.name == s.name; })) {
        error("G021", owner + ": missing required " + what + " '" + s.name + "'", at);
      }
    }
  }

  void nodes() {
    std::map<std::string, std::size_t> first;
    std::vector<std::string> type_names;
    for (const NodeType& t : catalogue()) type_names.push_back(t.name);
    type_names.push_back("subgraph");
    type_names.push_back("note");
    for (std::size_t i = 0; i < g_.nodes.size(); ++i) {
      const Node& n = g_.nodes[i];
      if (const auto [it, fresh] = first.emplace(n.id, n.id_offset); !fresh) {
        error("G011",
              "duplicate node id '" + n.id + "' (first defined at line " +
                  std::to_string(g_.source->locate(it->second).first) + ")",
              n.id_offset);
        continue;
      }
      const NodeType* type = find_node_type(n.type);
      if (type == nullptr && n.type != "subgraph" && n.type != "note") {
        error("G010", "unknown node type '" + n.type + "'" + suggestion(n.type, type_names),
              n.type_offset);
        continue;
      }
      if (!n.enabled || n.type == "note") continue;
      CheckedNode c;
      c.node = &n;
      c.type = type;
      c.file_index = i;
      if (type != nullptr) {
        catalogue_node(c, *type);
      } else {
        subgraph_node(c);
      }
      port_options(c);
      c.collective = std::any_of(c.inputs.begin(), c.inputs.end(),
                                 [](const ResolvedPort& p) { return p.collective; });
      out_.nodes.push_back(std::move(c));
    }
  }

  static ResolvedPort port_of(const PortSpec& spec) {
    ResolvedPort p;
    p.name = spec.name;
    p.type = spec.type;
    p.generic = spec.generic;
    p.collective = spec.mode == PortMode::kCollective;
    p.optional = spec.optional;
    return p;
  }

  void catalogue_node(CheckedNode& c, const NodeType& type) {
    const Node& n = *c.node;
    const std::string owner = type.name;
    for (const PortSpec& s : type.inputs) c.inputs.push_back(port_of(s));
    for (const PortSpec& s : type.outputs) c.outputs.push_back(port_of(s));
    params(owner, type.params, n.params, n.offset, "parameter");
    // Augmentations: kind, fields, and the output ports they feed.
    for (std::size_t i = 0; i < n.augment.size(); ++i) {
      const Augmentation& a = n.augment[i];
      std::vector<std::string> kinds;
      for (const AugmentSpec& s : type.augments) kinds.push_back(s.kind);
      const AugmentSpec* spec = nullptr;
      if (type.augments.empty()) {
        error("G002", "node '" + n.id + "' (" + owner + ") takes no augmentations", a.offset);
        continue;
      }
      if (a.kind.empty()) {
        if (type.augments.size() > 1) {
          error("G002",
                "node '" + n.id + "': an augmentation of " + owner +
                    " names its kind (one of: " + joined(kinds) + ")",
                a.offset);
          continue;
        }
        spec = &type.augments[0];
      } else {
        spec = type.augment(a.kind);
        if (spec == nullptr) {
          error("G002",
                "node '" + n.id + "': unknown augmentation kind '" + a.kind + "' of " + owner +
                    " (expected one of: " + joined(kinds) + ")",
                a.kind_offset);
          continue;
        }
      }
      params(owner + " " + spec->kind, spec->fields, a.fields, a.offset, "field");
      if (!spec->makes_ports) {
        if (!a.out.empty()) {
          error("G002", "node '" + n.id + "': " + spec->kind + " items feed no port", a.out_offset);
        }
        continue;
      }
      const std::string port = a.out.empty() ? spec->kind + std::to_string(i) : a.out;
      const bool shared = std::any_of(c.outputs.begin(), c.outputs.end(),
                                      [&](const ResolvedPort& p) { return p.name == port; });
      if (shared) continue;  // items sharing an `out` share one port
      ResolvedPort p;
      p.name = port;
      const bool generic = type.inputs.size() == 1 && type.inputs[0].generic;
      p.generic = generic;
      p.type = generic               ? type.inputs[0].type
               : type.inputs.empty() ? EntityType::kEntity
                                     : type.inputs[0].type;
      c.outputs.push_back(std::move(p));
    }
    // Node attribute mapping: written attributes into declared graph attributes.
    for (const AttributeMapping& m : n.attributes) {
      if (std::find(type.writes.begin(), type.writes.end(), m.node_attribute) ==
          type.writes.end()) {
        error("G020",
              "node '" + n.id + "' (" + owner + ") writes no attribute '" + m.node_attribute + "'" +
                  suggestion(m.node_attribute, type.writes) + "; it writes: " + joined(type.writes),
              m.offset);
        continue;
      }
      graph_attribute(m.to, m.to_offset);
    }
    // attr.set writes graph attributes directly.
    if (type.name == "attr.set") {
      for (const ParamValue& v : n.params) {
        if (v.name != "values" || v.expression || v.value->kind != Kind::kObject) continue;
        for (const JsonMember& m : v.value->members) graph_attribute(m.key, m.key_offset);
      }
    }
  }

  void graph_attribute(const std::string& name, std::size_t offset) {
    if (g_.attribute(name) != nullptr) return;
    std::vector<std::string> declared;
    for (const Declaration& d : g_.attributes) declared.push_back(d.name);
    error("G020", "unknown attribute '" + name + "'" + suggestion(name, declared), offset);
  }

  void subgraph_node(CheckedNode& c) {
    const Node& n = *c.node;
    const CheckedGraph* sub = subgraph_of(n);
    if (sub == nullptr) return;  // its graph failed to read (reported there)
    const Graph& sg = *sub->graph;
    const auto gate_port = [&](const Gate& gate, bool input) {
      ResolvedPort p;
      p.name = gate.name;
      bool first = true;
      for (const PortRef& r : gate.ports) {
        const auto i = sub->node(r.node);
        if (!i) continue;
        const CheckedNode& inner = sub->nodes[*i];
        const auto& ports = input ? inner.inputs : inner.outputs;
        for (const ResolvedPort& q : ports) {
          if (q.name != r.port) continue;
          p.type = first ? q.type : common_supertype(p.type, q.type);
          p.collective = q.collective;
          first = false;
        }
      }
      p.optional = true;
      return p;
    };
    for (const Gate& gate : sg.inputs) c.inputs.push_back(gate_port(gate, true));
    for (const Gate& gate : sg.outputs) c.outputs.push_back(gate_port(gate, false));
    std::vector<ParamSpec> specs;
    for (const Declaration& d : sg.parameters) {
      if (!d.is_public) continue;
      ParamSpec s;
      s.name = d.name;
      s.type = d.type;
      s.default_json = "declared";
      s.min = d.min;
      s.max = d.max;
      s.choices = d.choices;
      specs.push_back(std::move(s));
    }
    params("subgraph '" + n.id + "' (" + n.graph_ref + ")", specs, n.params, n.offset, "parameter");
    std::vector<std::string> attributes;
    for (const Declaration& d : sg.attributes) {
      if (d.is_public) attributes.push_back(d.name);
    }
    for (const AttributeMapping& m : n.attributes) {
      if (std::find(attributes.begin(), attributes.end(), m.node_attribute) == attributes.end()) {
        error("G020",
              "subgraph '" + n.id + "' (" + n.graph_ref + ") has no public attribute '" +
                  m.node_attribute + "'" + suggestion(m.node_attribute, attributes),
              m.offset);
        continue;
      }
      graph_attribute(m.to, m.to_offset);
    }
  }

  void port_options(CheckedNode& c) {
    for (const PortOptions& o : c.node->ports) {
      ResolvedPort* p = nullptr;
      bool input = false;
      for (ResolvedPort& q : c.inputs) {
        if (q.name == o.port) {
          p = &q;
          input = true;
        }
      }
      for (ResolvedPort& q : c.outputs) {
        if (p == nullptr && q.name == o.port) p = &q;
      }
      if (p == nullptr) {
        std::vector<std::string> names;
        for (const ResolvedPort& q : c.inputs) names.push_back(q.name);
        for (const ResolvedPort& q : c.outputs) names.push_back(q.name);
        error("G012",
              "node " + describe(c) + " has no port '" + o.port + "'" + suggestion(o.port, names) +
                  "; its ports are: " + joined(names),
              o.offset);
        continue;
      }
      p->blocked = o.blocked;
      if (!o.collective) continue;
      if (!input) {
        error("G015",
              "port '" + o.port + "' of " + describe(c) +
                  " is an output port; only input ports have a mode",
              o.mode_offset);
        continue;
      }
      const PortSpec* spec = c.type != nullptr ? c.type->input(o.port) : nullptr;
      if (spec == nullptr || spec->mode != PortMode::kEither) {
        if (*o.collective != p->collective) {
          error("G015",
                "port '" + o.port + "' of " + describe(c) + " is always " +
                    (p->collective ? "collective" : "single"),
                o.mode_offset);
        }
        continue;
      }
      p->collective = *o.collective;
    }
  }

  // Finds `ref` as a port of an active node; G012/G016 otherwise. `want_output` is its side.
  bool find_port(const PortRef& ref, bool want_output, const std::string& context,
                 std::size_t& node, std::size_t& port) {
    const auto i = out_.node(ref.node);
    if (!i) {
      const Node* n = g_.node(ref.node);
      if (n != nullptr && (!n->enabled || n->type == "note")) return false;  // dropped with it
      if (n != nullptr) return false;  // an unknown type, reported at the node
      std::vector<std::string> ids;
      for (const Node& m : g_.nodes) ids.push_back(m.id);
      error("G012", context + "no node '" + ref.node + "'" + suggestion(ref.node, ids), ref.offset);
      return false;
    }
    const CheckedNode& c = out_.nodes[*i];
    const auto& same = want_output ? c.outputs : c.inputs;
    const auto& other = want_output ? c.inputs : c.outputs;
    for (std::size_t k = 0; k < same.size(); ++k) {
      if (same[k].name == ref.port) {
        node = *i;
        port = k;
        return true;
      }
    }
    for (const ResolvedPort& q : other) {
      if (q.name == ref.port) {
        error(
            "G016",
            context + "'" + ref.text() + "' is an " + (want_output ? "input" : "output") + " port",
            ref.offset);
        return false;
      }
    }
    std::vector<std::string> names;
    for (const ResolvedPort& q : same) names.push_back(q.name);
    const std::string side = want_output ? "output" : "input";
    error("G012",
          context + "node " + describe(c) + " has no " + side + " port '" + ref.port + "'" +
              suggestion(ref.port, names) + "; its " + side + " ports are: " + joined(names),
          ref.offset);
    return false;
  }

  // §5: every expression parses (G023), names declared things (G020, G021), reads the entity only
  // where there is one (G022), and has types that fit its operators and its parameter (G024).
  void expression(const CheckedNode& c, const ParamValue& v, std::optional<ValueType> wanted,
                  bool per_entity) {
    if (!v.expression) return;
    const std::string text = v.value->text.substr(1);
    const auto file_offset = [&](std::size_t at) {
      return string_byte_offset(*g_.source, *v.value, 1 + at);
    };
    ExprError err;
    const std::optional<Expr> parsed = parse_expression(text, err);
    if (!parsed) {
      error(err.code, err.message, file_offset(err.at));
      return;
    }
    ExprScope scope;
    scope.attribute = [this](const std::string& name) -> std::optional<ValueType> {
      const Declaration* d = g_.attribute(name);
      return d == nullptr ? std::nullopt : std::optional<ValueType>(d->type);
    };
    scope.parameter = [this](const std::string& name) -> std::optional<ValueType> {
      const Declaration* d = g_.parameter(name);
      return d == nullptr ? std::nullopt : std::optional<ValueType>(d->type);
    };
    scope.input_port = [&c](const std::string& port) {
      return std::any_of(c.inputs.begin(), c.inputs.end(),
                         [&](const ResolvedPort& p) { return p.name == port; });
    };
    for (const Declaration& d : g_.attributes) scope.attributes.push_back(d.name);
    for (const Declaration& d : g_.parameters) scope.parameters.push_back(d.name);
    const std::string param = "parameter '" + v.name + "' of " + describe(c);
    const bool has_entity =
        std::any_of(c.inputs.begin(), c.inputs.end(),
                    [](const ResolvedPort& p) { return !p.edges.empty() || p.gate; });
    if (!has_entity) {
      scope.entity_readable = false;
      scope.not_readable_because =
          param + " has no current entity (no input port is connected) and";
    } else if (c.collective && !per_entity) {
      scope.entity_readable = false;
      scope.not_readable_because = param + " is evaluated once per execution and";
    }
    const std::optional<ValueType> t = check_expression(*parsed, text, scope, err);
    if (!t) {
      error(err.code, err.message, file_offset(err.at));
      return;
    }
    if (!wanted || *wanted == ValueType::kAny || *t == ValueType::kAny || *t == *wanted) return;
    const bool numeric = *t == ValueType::kNumber || *t == ValueType::kInteger;
    if (numeric && (*wanted == ValueType::kNumber || *wanted == ValueType::kInteger)) return;
    if (*t == ValueType::kString && *wanted == ValueType::kEnum) return;
    error("G024",
          param + " needs " + expected_of(*wanted) + "; '=" + text + "' gives " + expected_of(*t),
          file_offset(0));
  }

  static std::string expected_of(ValueType t) {
    return t == ValueType::kInteger ? "an integer"
           : t == ValueType::kEnum  ? "a string"
                                    : "a " + std::string(value_type_name(t));
  }

  void expressions() {
    for (const CheckedNode& c : out_.nodes) {
      const Node& n = *c.node;
      if (c.type == nullptr) {
        for (const ParamValue& v : n.params) {
          const Declaration* d = n.subgraph != nullptr ? n.subgraph->parameter(v.name) : nullptr;
          expression(c, v, d ? std::optional<ValueType>(d->type) : std::nullopt, false);
        }
        continue;
      }
      for (const ParamValue& v : n.params) {
        const ParamSpec* spec = c.type->param(v.name);
        if (spec == nullptr) continue;
        expression(
            c, v, spec->registry_type.empty() ? std::optional<ValueType>(spec->type) : std::nullopt,
            spec->per_entity);
        // attr.set: each value is a literal or an expression of the attribute's type.
        if (c.type->name == "attr.set" && v.name == "values" && !v.expression &&
            v.value->kind == Kind::kObject) {
          for (const JsonMember& m : v.value->members) {
            const Declaration* d = g_.attribute(m.key);
            const ParamValue inner{
                m.key, m.key_offset, &m.value,
                m.value.kind == Kind::kString && !m.value.text.empty() && m.value.text[0] == '='};
            expression(c, inner, d ? std::optional<ValueType>(d->type) : std::nullopt, true);
          }
        }
      }
      for (std::size_t i = 0; i < n.augment.size(); ++i) {
        const Augmentation& a = n.augment[i];
        const AugmentSpec* spec = a.kind.empty() && c.type->augments.size() == 1
                                      ? &c.type->augments[0]
                                      : c.type->augment(a.kind);
        if (spec == nullptr) continue;
        for (const ParamValue& v : a.fields) {
          const auto it = std::find_if(spec->fields.begin(), spec->fields.end(),
                                       [&](const ParamSpec& f) { return f.name == v.name; });
          if (it == spec->fields.end()) continue;
          expression(c, v, std::optional<ValueType>(it->type), it->per_entity);
        }
      }
    }
  }

  void edges() {
    std::set<std::pair<std::string, std::string>> seen;
    for (const Edge& e : g_.edges) {
      if (!e.enabled) continue;
      const std::string context = "edge '" + e.text() + "': ";
      CheckedEdge c;
      c.edge = &e;
      if (!find_port(e.from, true, context, c.from_node, c.from_port)) continue;
      if (!find_port(e.to, false, context, c.to_node, c.to_port)) continue;
      if (!seen.emplace(e.from.text(), e.to.text()).second) {
        error("G017", "duplicate edge '" + e.text() + "'", e.offset);
        continue;
      }
      const std::size_t index = out_.edges.size();
      out_.nodes[c.from_node].outputs[c.from_port].edges.push_back(index);
      out_.nodes[c.to_node].inputs[c.to_port].edges.push_back(index);
      out_.edges.push_back(c);
    }
  }

  // The type an output port carries: a generic port's inferred T, else its own type.
  EntityType carried(const CheckedNode& n, const ResolvedPort& p) const {
    return p.generic && n.generic ? *n.generic : p.type;
  }

  // G013's fixed point: each generic node's T is the common supertype of what reaches its
  // generic inputs; T flows on through generic outputs, around cycles too.
  void infer_types() {
    for (bool changed = true; changed;) {
      changed = false;
      for (CheckedNode& n : out_.nodes) {
        std::optional<EntityType> t = n.generic;
        for (const ResolvedPort& in : n.inputs) {
          if (!in.generic) continue;
          for (std::size_t e : in.edges) {
            const CheckedEdge& edge = out_.edges[e];
            const CheckedNode& from = out_.nodes[edge.from_node];
            const ResolvedPort& port = from.outputs[edge.from_port];
            if (port.generic && !from.generic) continue;  // nothing known yet
            const EntityType arriving = carried(from, port);
            t = t ? common_supertype(*t, arriving) : arriving;
          }
        }
        if (t != n.generic) {
          n.generic = t;
          changed = true;
        }
      }
    }
    for (CheckedNode& n : out_.nodes) {
      for (ResolvedPort& p : n.outputs) p.type = carried(n, p);
    }
  }

  void check_edge_types() {
    for (const CheckedEdge& e : out_.edges) {
      const CheckedNode& from = out_.nodes[e.from_node];
      const CheckedNode& to = out_.nodes[e.to_node];
      const EntityType t = from.outputs[e.from_port].type;
      const ResolvedPort& in = to.inputs[e.to_port];
      // A generic input accepts what its bound accepts; the narrower case is checked per entity
      // at run time (G052).
      if (is_subtype(t, in.type) || is_subtype(in.type, t)) continue;
      error("G013",
            "edge '" + e.edge->text() + "': '" + e.edge->from.text() + "' carries " +
                std::string(entity_type_name(t)) + " entities but '" + e.edge->to.text() + "' (" +
                to.node->type + ") accepts " + std::string(entity_type_name(in.type)) + " entities",
            e.edge->offset);
    }
  }

  void gates() {
    for (int side = 0; side < 2; ++side) {
      const bool input = side == 0;
      for (const Gate& gate : input ? g_.inputs : g_.outputs) {
        std::optional<bool> collective;
        std::optional<EntityType> type;
        std::string first_ref;
        for (const PortRef& r : gate.ports) {
          std::size_t node = 0;
          std::size_t port = 0;
          if (!find_port(r, !input, "gate '" + gate.name + "': ", node, port)) continue;
          ResolvedPort& p = input ? out_.nodes[node].inputs[port] : out_.nodes[node].outputs[port];
          p.gate = true;
          if (!input) continue;
          const char* mode = p.collective ? "collective" : "single";
          if (collective && *collective != p.collective) {
            error("G030",
                  "gate '" + gate.name + "': ports '" + first_ref + "' (" +
                      (*collective ? "collective" : "single") + ") and '" + r.text() + "' (" +
                      mode + ") disagree",
                  r.offset);
            continue;
          }
          if (type && *type != p.type) {
            error("G030",
                  "gate '" + gate.name + "': ports '" + first_ref + "' (" +
                      std::string(entity_type_name(*type)) + ") and '" + r.text() + "' (" +
                      std::string(entity_type_name(p.type)) + ") accept different types",
                  r.offset);
            continue;
          }
          collective = p.collective;
          type = p.type;
          if (first_ref.empty()) first_ref = r.text();
        }
      }
    }
  }

  // G014: every required input port has an edge or an input gate.
  void connections() {
    for (const CheckedNode& n : out_.nodes) {
      for (const ResolvedPort& p : n.inputs) {
        if (p.optional || !p.edges.empty() || p.gate) continue;
        error("G014", "required input port '" + n.node->id + "." + p.name + "' is not connected",
              n.node->id_offset);
      }
    }
  }

  // W001: a cycle none of whose nodes has an edge out of it, a leaf port or an output gate.
  void ways_out() {
    const ExecutionOrder& order = out_.standalone;
    std::map<std::size_t, std::vector<std::size_t>> members;
    for (std::size_t k : order.order) {
      if (order.in_cycle[k]) members[order.component[k]].push_back(k);
    }
    for (const auto& [component, nodes] : members) {
      bool way_out = false;
      for (std::size_t k : nodes) {
        for (const ResolvedPort& p : out_.nodes[k].outputs) {
          if (p.gate || (p.edges.empty() && !p.blocked)) way_out = true;
          for (std::size_t e : p.edges) {
            if (order.component[out_.edges[e].to_node] != component) way_out = true;
          }
        }
      }
      if (way_out) continue;
      std::string cycle;
      for (std::size_t k : nodes) cycle += out_.nodes[k].node->id + " -> ";
      cycle += out_.nodes[nodes.front()].node->id;
      report(true, "W001",
             "cycle " + cycle + " has no way out: entities entering it can never leave",
             out_.nodes[nodes.front()].node->id_offset);
    }
  }

  // W020: inside a subgraph, leaf ports that are no output gate drop what reaches them.
  void leaves() {
    if (!out_.used_as_subgraph) return;
    const auto user = doc_.used_by.find(&g_);
    const std::string name = user->second.second->id;
    for (const CheckedNode& n : out_.nodes) {
      if (n.node->standalone_only) continue;
      for (const ResolvedPort& p : n.outputs) {
        if (!p.edges.empty() || p.blocked || p.gate) continue;
        report(true, "W020",
               "subgraph '" + name + "': leaf port '" + n.node->id + "." + p.name +
                   "' is not an output gate; its entities are dropped",
               n.node->id_offset);
      }
    }
  }

  const Document& doc_;
  const Graph& g_;
  const std::vector<CheckedGraph>& done_;
  const std::map<const Graph*, std::size_t>& index_of_;
  CheckedGraph out_;
  std::vector<base::Diagnostic> diagnostics_;
  std::vector<std::string> notes_;
};

}  // namespace

ExecutionOrder execution_order(const CheckedGraph& graph, bool encapsulated) {
  const std::size_t n = graph.nodes.size();
  std::vector<bool> active(n, true);
  if (encapsulated) {
    for (std::size_t i = 0; i < n; ++i) active[i] = !graph.nodes[i].node->standalone_only;
  }
  std::vector<std::vector<std::size_t>> out_edges(n);
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    const CheckedEdge& edge = graph.edges[e];
    if (active[edge.from_node] && active[edge.to_node]) out_edges[edge.from_node].push_back(e);
  }
  ExecutionOrder order;
  order.cyclic.assign(graph.edges.size(), false);
  // Step 2: depth-first from every node in file order; each edge is examined once, and an edge
  // into a node on the current path is cyclic.
  {
    std::vector<bool> examined(graph.edges.size(), false);
    std::vector<bool> on_path(n, false);
    struct Frame {
      std::size_t node;
      std::size_t next;
    };
    for (std::size_t start = 0; start < n; ++start) {
      if (!active[start]) continue;
      std::vector<Frame> stack{{start, 0}};
      on_path[start] = true;
      while (!stack.empty()) {
        Frame& f = stack.back();
        if (f.next == out_edges[f.node].size()) {
          on_path[f.node] = false;
          stack.pop_back();
          continue;
        }
        const std::size_t e = out_edges[f.node][f.next++];
        if (examined[e]) continue;
        examined[e] = true;
        const std::size_t to = graph.edges[e].to_node;
        if (on_path[to]) {
          order.cyclic[e] = true;
        } else {
          on_path[to] = true;
          stack.push_back({to, 0});
        }
      }
    }
  }
  // Strongly connected components (Tarjan, iterative), numbered afterwards by first node.
  std::vector<std::size_t> comp(n, SIZE_MAX);
  {
    std::vector<std::size_t> low(n, 0);
    std::vector<std::size_t> num(n, SIZE_MAX);
    std::vector<bool> on_stack(n, false);
    std::vector<std::size_t> stack;
    std::size_t counter = 0;
    std::size_t components = 0;
    struct Frame {
      std::size_t node;
      std::size_t next;
    };
    for (std::size_t s = 0; s < n; ++s) {
      if (!active[s] || num[s] != SIZE_MAX) continue;
      std::vector<Frame> frames{{s, 0}};
      num[s] = low[s] = counter++;
      stack.push_back(s);
      on_stack[s] = true;
      while (!frames.empty()) {
        Frame& f = frames.back();
        if (f.next < out_edges[f.node].size()) {
          const std::size_t to = graph.edges[out_edges[f.node][f.next++]].to_node;
          if (num[to] == SIZE_MAX) {
            num[to] = low[to] = counter++;
            stack.push_back(to);
            on_stack[to] = true;
            frames.push_back({to, 0});
          } else if (on_stack[to]) {
            low[f.node] = std::min(low[f.node], num[to]);
          }
          continue;
        }
        const std::size_t v = f.node;
        frames.pop_back();
        if (!frames.empty()) low[frames.back().node] = std::min(low[frames.back().node], low[v]);
        if (low[v] == num[v]) {
          for (;;) {
            const std::size_t w = stack.back();
            stack.pop_back();
            on_stack[w] = false;
            comp[w] = components;
            if (w == v) break;
          }
          ++components;
        }
      }
    }
  }
  order.component = comp;
  order.in_cycle.assign(n, false);
  std::map<std::size_t, std::vector<std::size_t>> members;  // component -> nodes in file order
  for (std::size_t i = 0; i < n; ++i) {
    if (active[i]) members[comp[i]].push_back(i);
  }
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    const CheckedEdge& edge = graph.edges[e];
    if (!active[edge.from_node] || !active[edge.to_node]) continue;
    if (comp[edge.from_node] == comp[edge.to_node]) {
      order.in_cycle[edge.from_node] = order.in_cycle[edge.to_node] = true;
    }
  }
  // Step 3: components in topological order (ready ones by their first node in the file), and
  // inside each, its nodes topologically without the cyclic edges (ready ones by file order).
  std::map<std::size_t, std::size_t> waiting;  // component -> edges from other components
  for (const auto& [c, nodes] : members) waiting[c] = 0;
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    const CheckedEdge& edge = graph.edges[e];
    if (!active[edge.from_node] || !active[edge.to_node]) continue;
    if (comp[edge.from_node] != comp[edge.to_node]) ++waiting[comp[edge.to_node]];
  }
  using Ready = std::priority_queue<std::size_t, std::vector<std::size_t>, std::greater<>>;
  Ready ready;  // by first node's file index
  std::map<std::size_t, std::size_t> by_first;
  for (const auto& [c, nodes] : members) {
    by_first[nodes.front()] = c;
    if (waiting[c] == 0) ready.push(nodes.front());
  }
  order.index.assign(n, SIZE_MAX);
  while (!ready.empty()) {
    const std::size_t c = by_first[ready.top()];
    ready.pop();
    const std::vector<std::size_t>& nodes = members[c];
    std::map<std::size_t, std::size_t> inner_waiting;
    for (std::size_t v : nodes) inner_waiting[v] = 0;
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
      const CheckedEdge& edge = graph.edges[e];
      if (order.cyclic[e] || !active[edge.from_node] || !active[edge.to_node]) continue;
      if (comp[edge.from_node] == c && comp[edge.to_node] == c) ++inner_waiting[edge.to_node];
    }
    std::set<std::size_t> pending(nodes.begin(), nodes.end());
    while (!pending.empty()) {
      std::size_t next = *pending.begin();  // fallback: the earliest in the file
      for (std::size_t v : pending) {
        if (inner_waiting[v] == 0) {
          next = v;
          break;
        }
      }
      pending.erase(next);
      order.index[next] = order.order.size();
      order.order.push_back(next);
      for (std::size_t e : out_edges[next]) {
        const std::size_t to = graph.edges[e].to_node;
        if (order.cyclic[e]) continue;
        if (comp[to] == c) {
          if (inner_waiting[to] > 0) --inner_waiting[to];
        } else if (--waiting[comp[to]] == 0) {
          ready.push(members[comp[to]].front());
        }
      }
    }
  }
  return order;
}

CheckResult check(const Document& document) {
  CheckResult result;
  // Subgraphs before the graphs that use them (their gates become node ports).
  std::map<const Graph*, std::size_t> index_of;
  for (std::size_t i = 0; i < document.graphs.size(); ++i) {
    index_of[document.graphs[i].get()] = i;
  }
  result.graphs.resize(document.graphs.size());
  std::vector<std::vector<base::Diagnostic>> per_graph(document.graphs.size());
  std::vector<int> state(document.graphs.size(), 0);
  const std::function<void(std::size_t)> visit = [&](std::size_t i) {
    if (state[i] != 0) return;
    state[i] = 1;
    for (const Node& n : document.graphs[i]->nodes) {
      if (n.subgraph != nullptr) visit(index_of[n.subgraph]);
    }
    GraphChecker checker(document, *document.graphs[i], result.graphs, index_of);
    result.graphs[i] = checker.run(per_graph[i]);
    state[i] = 2;
  };
  for (std::size_t i = 0; i < document.graphs.size(); ++i) visit(i);
  for (auto& diagnostics : per_graph) {
    for (base::Diagnostic& d : diagnostics) result.diagnostics.push_back(std::move(d));
  }
  result.ok = !base::has_errors(result.diagnostics);
  return result;
}

std::string dump_order(const Document& document, const CheckResult& result) {
  std::string out;
  for (std::size_t g = 0; g < result.graphs.size(); ++g) {
    const CheckedGraph& c = result.graphs[g];
    const bool inside = c.used_as_subgraph && document.graphs[g].get() != document.root;
    const ExecutionOrder& order = inside ? c.encapsulated : c.standalone;
    out += "graph " + document.graphs[g]->ref + (inside ? " (encapsulated)" : "") + "\n";
    for (std::size_t k : order.order) {
      const CheckedNode& n = c.nodes[k];
      out += "  " + std::to_string(order.index[k]) + " " + n.node->id + " (" + n.node->type + ")" +
             (n.collective ? " collective" : "") + (order.in_cycle[k] ? " in-cycle" : "") + "\n";
    }
    for (std::size_t e = 0; e < c.edges.size(); ++e) {
      if (order.cyclic[e]) out += "  cyclic " + c.edges[e].edge->text() + "\n";
    }
  }
  return out;
}

}  // namespace insula::lang::graph
