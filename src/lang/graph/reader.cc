#include "lang/graph/reader.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <span>

#include "base/format.h"

namespace insula::lang::graph {

const Node* Graph::node(std::string_view id) const {
  for (const Node& n : nodes) {
    if (n.id == id) return &n;
  }
  return nullptr;
}

const Declaration* Graph::parameter(std::string_view wanted) const {
  for (const Declaration& d : parameters) {
    if (d.name == wanted) return &d;
  }
  return nullptr;
}

const Declaration* Graph::attribute(std::string_view wanted) const {
  for (const Declaration& d : attributes) {
    if (d.name == wanted) return &d;
  }
  return nullptr;
}

bool valid_name(std::string_view name) {
  if (name.empty()) return false;
  const auto letter = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  };
  if (!letter(name[0])) return false;
  return std::all_of(name.begin(), name.end(),
                     [&](char c) { return letter(c) || (c >= '0' && c <= '9'); });
}

std::vector<std::string> graph_notes(const Document& document, const Graph& graph) {
  std::vector<std::string> notes;
  std::set<const Graph*> seen;
  for (const Graph* g = &graph; g != nullptr && g != document.root && seen.insert(g).second;) {
    const auto it = document.used_by.find(g);
    if (it == document.used_by.end()) {
      notes.push_back("in inline graph '" + g->ref + "'");
      g = g->enclosing;
      continue;
    }
    notes.push_back("in subgraph '" + it->second.second->id + "' (" + g->ref + ")");
    g = it->second.first;
  }
  return notes;
}

namespace {

using Kind = JsonValue::Kind;

// A bound on the subgraph files one graph reaches, so a reader that always finds a file (paths
// growing into ever deeper folders) cannot keep reading.
constexpr std::size_t kMaxSubgraphFiles = 256;

constexpr const char* kTopFields[] = {"format",     "version",    "name",  "doc",   "seed",
                                      "parameters", "attributes", "nodes", "edges", "gates",
                                      "subgraphs",  "limits",     "ui"};

class Reader {
 public:
  Reader(Document& document, const FileReader& files) : doc_(document), files_(files) {}

  std::vector<base::Diagnostic>& diagnostics() { return diagnostics_; }

  // Reads a file's graph (top-level: `format` and `version` required).
  Graph* read_file(std::unique_ptr<base::Source> source, const std::string& ref,
                   const std::string& folder) {
    const base::Source& src = *source;
    doc_.sources.push_back(std::move(source));
    base::Result<JsonValue> json = parse_json(src);
    if (!json.ok()) {
      for (base::Diagnostic& d : json.diagnostics()) {
        d.notes = notes_;
        diagnostics_.push_back(std::move(d));
      }
      return nullptr;
    }
    doc_.json.push_back(std::make_unique<JsonValue>(std::move(json.value())));
    const std::size_t first_graph = doc_.graphs.size();
    Graph* g = read_graph_object(*doc_.json.back(), src, ref, nullptr, true);
    // Inline graphs of this file resolve paths from the same folder.
    for (std::size_t i = first_graph; i < doc_.graphs.size(); ++i) doc_.graphs[i]->folder = folder;
    return g;
  }

  // Resolves the subgraph nodes of every graph read so far, reading the files they name (each
  // once); then reports subgraph cycles.
  void resolve_all(const std::string& root_dir) {
    for (std::size_t i = 0; i < doc_.graphs.size(); ++i) {
      Graph& g = *doc_.graphs[i];
      for (Node& n : g.nodes) {
        if (n.type != "subgraph" || n.graph_ref.empty()) continue;
        n.subgraph = resolve(g, n, root_dir);
        if (n.subgraph != nullptr && doc_.used_by.find(n.subgraph) == doc_.used_by.end()) {
          doc_.used_by[n.subgraph] = {&g, &n};
        }
      }
    }
    report_cycles();
  }

 private:
  void error(const std::string& code, std::string message, const base::Source& src,
             std::size_t offset, std::size_t length = 1) {
    const auto [line, column] = src.locate(offset);
    base::Diagnostic d = base::Diagnostic::error(
        code, std::move(message),
        base::Span::at(src.name(), line, column, static_cast<std::uint32_t>(length)));
    d.notes = notes_;
    diagnostics_.push_back(std::move(d));
  }

  // A field of the wrong JSON type: false after reporting.
  bool expect(const JsonValue& v, Kind kind, const std::string& what, const base::Source& src) {
    const bool ok = v.kind == kind || (kind == Kind::kNumber && v.kind == Kind::kInteger);
    if (!ok) {
      error("G002",
            what + " must be " + std::string(kind_name(kind)) + ", not " +
                std::string(kind_name(v.kind)),
            src, v.offset);
    }
    return ok;
  }

  // Unknown fields of `object` (G002 with the expected ones); `extensions` allows `x-...`.
  void check_fields(const JsonValue& object, std::span<const char* const> allowed,
                    const std::string& where, bool extensions, const base::Source& src) {
    std::set<std::string> seen;
    for (const JsonMember& m : object.members) {
      if (!seen.insert(m.key).second) {
        error("G002", where + "duplicate field '" + m.key + "'", src, m.key_offset);
        continue;
      }
      if (extensions && m.key.rfind("x-", 0) == 0) continue;
      if (std::find_if(allowed.begin(), allowed.end(), [&](const char* a) { return m.key == a; }) !=
          allowed.end()) {
        continue;
      }
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      error("G002", where + "unknown field '" + m.key + "' (expected one of: " + list + ")", src,
            m.key_offset);
    }
  }

  void check_name(const std::string& name, std::size_t offset, const std::string& what,
                  const base::Source& src) {
    if (!valid_name(name)) {
      error("G002",
            what + " '" + name +
                "' is not a valid name (letters, digits and '_', not starting "
                "with a digit)",
            src, offset);
    }
  }

  Graph* read_graph_object(const JsonValue& v, const base::Source& src, const std::string& ref,
                           const Graph* enclosing, bool top_level) {
    if (v.kind != Kind::kObject) {
      error("G002", "a graph must be a JSON object, not " + std::string(kind_name(v.kind)), src,
            v.offset);
      return nullptr;
    }
    doc_.graphs.push_back(std::make_unique<Graph>());
    Graph& g = *doc_.graphs.back();
    g.source = &src;
    g.ref = ref;
    g.offset = v.offset;
    g.enclosing = enclosing;
    // The version first: a newer file may have fields this reader does not know.
    const JsonValue* version = v.find("version");
    if (version != nullptr) {
      if (version->kind != Kind::kInteger || version->integer != 1) {
        std::string shown = version->kind == Kind::kString ? base::quoted_string(version->text)
                            : version->is_number()         ? base::shortest_number(version->number)
                                                           : std::string(kind_name(version->kind));
        error("G003", "unsupported format version " + shown + " (this reader knows 1)", src,
              version->offset);
        return &g;
      }
    } else if (top_level) {
      error("G002", "missing field 'version'", src, v.offset);
    }
    check_fields(v, kTopFields, "", true, src);
    if (const JsonValue* format = v.find("format")) {
      if (format->kind != Kind::kString || format->text != "insula-graph") {
        error("G002", "field 'format' must be \"insula-graph\"", src, format->offset);
      }
    } else if (top_level) {
      error("G002", "missing field 'format'", src, v.offset);
    }
    if (const JsonValue* name = v.find("name")) {
      if (expect(*name, Kind::kString, "field 'name'", src)) g.name = name->text;
    }
    if (const JsonValue* d = v.find("doc")) expect(*d, Kind::kString, "field 'doc'", src);
    if (const JsonValue* ui = v.find("ui")) expect(*ui, Kind::kObject, "field 'ui'", src);
    if (const JsonValue* seed = v.find("seed")) {
      if (seed->kind != Kind::kInteger || seed->integer < 0) {
        error("G002", "field 'seed' must be an integer >= 0", src, seed->offset);
      } else {
        g.seed = seed->integer;
      }
    }
    if (const JsonValue* p = v.find("parameters")) read_declarations(*p, src, g.parameters, true);
    if (const JsonValue* a = v.find("attributes")) read_declarations(*a, src, g.attributes, false);
    if (const JsonValue* s = v.find("subgraphs")) {
      if (expect(*s, Kind::kObject, "field 'subgraphs'", src)) {
        for (const JsonMember& m : s->members) {
          check_name(m.key, m.key_offset, "subgraph", src);
          notes_.push_back("in inline graph '#" + m.key + "'");
          const Graph* inner = read_graph_object(m.value, src, "#" + m.key, &g, false);
          notes_.pop_back();
          if (inner != nullptr) g.subgraphs.emplace_back(m.key, inner);
        }
      }
    }
    const JsonValue* nodes = v.find("nodes");
    if (nodes == nullptr) {
      error("G002", "missing field 'nodes'", src, v.offset);
    } else if (expect(*nodes, Kind::kArray, "field 'nodes'", src)) {
      for (const JsonValue& n : nodes->items) read_node(n, src, g);
    }
    if (const JsonValue* edges = v.find("edges")) {
      if (expect(*edges, Kind::kArray, "field 'edges'", src)) {
        for (const JsonValue& e : edges->items) read_edge(e, src, g);
      }
    }
    if (const JsonValue* gates = v.find("gates")) read_gates(*gates, src, g);
    if (const JsonValue* limits = v.find("limits")) read_limits(*limits, src, g.limits);
    return &g;
  }

  void read_declarations(const JsonValue& v, const base::Source& src, std::vector<Declaration>& out,
                         bool parameters) {
    const std::string what = parameters ? "parameter" : "attribute";
    if (!expect(v, Kind::kObject, "field '" + what + "s'", src)) return;
    static constexpr const char* kParameterFields[] = {"type",    "default", "min",     "max",
                                                       "choices", "doc",     "section", "public"};
    static constexpr const char* kAttributeFields[] = {"type", "default", "doc", "public"};
    for (const JsonMember& m : v.members) {
      check_name(m.key, m.key_offset, what, src);
      const std::string where = what + " '" + m.key + "': ";
      if (m.value.kind != Kind::kObject) {
        error("G002", where + "must be an object, not " + std::string(kind_name(m.value.kind)), src,
              m.value.offset);
        continue;
      }
      if (parameters) {
        check_fields(m.value, kParameterFields, where, false, src);
      } else {
        check_fields(m.value, kAttributeFields, where, false, src);
      }
      Declaration d;
      d.name = m.key;
      d.offset = m.key_offset;
      const JsonValue* type = m.value.find("type");
      if (type == nullptr) {
        error("G002", where + "missing field 'type'", src, m.value.offset);
        continue;
      }
      const std::optional<ValueType> vt =
          type->kind == Kind::kString ? value_type_named(type->text) : std::nullopt;
      if (!vt || (!parameters && *vt == ValueType::kEnum)) {
        error("G002",
              where + "type must be one of: number, integer, bool, string, vec3, list" +
                  (parameters ? ", enum" : ""),
              src, type->offset);
        continue;
      }
      d.type = *vt;
      d.type_offset = type->offset;
      d.default_value = m.value.find("default");
      if (d.default_value == nullptr && parameters) {
        error("G002", where + "missing field 'default'", src, m.value.offset);
      }
      if (const JsonValue* pub = m.value.find("public")) {
        if (expect(*pub, Kind::kBool, where + "field 'public'", src)) d.is_public = pub->boolean;
      }
      for (const char* bound : {"min", "max"}) {
        if (const JsonValue* b = m.value.find(bound)) {
          if (expect(*b, Kind::kNumber, where + "field '" + bound + "'", src)) {
            (std::string(bound) == "min" ? d.min : d.max) = b->number;
          }
        }
      }
      if (const JsonValue* choices = m.value.find("choices")) {
        if (expect(*choices, Kind::kArray, where + "field 'choices'", src)) {
          for (const JsonValue& c : choices->items) {
            if (expect(c, Kind::kString, where + "a choice", src)) d.choices.push_back(c.text);
          }
        }
      } else if (d.type == ValueType::kEnum) {
        error("G002", where + "missing field 'choices' (an enum lists its choices)", src,
              m.value.offset);
      }
      out.push_back(std::move(d));
    }
  }

  // A parameter value: `=` starts an expression; {"value": "..."} is a literal string.
  ParamValue param_value(const std::string& name, std::size_t name_offset, const JsonValue& v) {
    ParamValue p{name, name_offset, &v, false};
    if (v.kind == Kind::kString && !v.text.empty() && v.text[0] == '=') p.expression = true;
    if (v.kind == Kind::kObject && v.members.size() == 1 && v.members[0].key == "value" &&
        v.members[0].value.kind == Kind::kString) {
      p.value = &v.members[0].value;
    }
    return p;
  }

  void read_node(const JsonValue& v, const base::Source& src, Graph& g) {
    static constexpr const char* kNodeFields[] = {
        "id",    "type",    "graph",           "params", "augment", "attributes",
        "ports", "enabled", "standalone_only", "label",  "doc",     "ui"};
    if (v.kind != Kind::kObject) {
      error("G002", "a node must be an object, not " + std::string(kind_name(v.kind)), src,
            v.offset);
      return;
    }
    Node n;
    n.offset = v.offset;
    const JsonValue* id = v.find("id");
    std::string where = "node: ";
    if (id == nullptr) {
      error("G002", "node: missing field 'id'", src, v.offset);
      return;
    }
    if (!expect(*id, Kind::kString, "node: field 'id'", src)) return;
    n.id = id->text;
    n.id_offset = id->offset;
    check_name(n.id, n.id_offset, "node id", src);
    where = "node '" + n.id + "': ";
    check_fields(v, kNodeFields, where, false, src);
    const JsonValue* type = v.find("type");
    if (type == nullptr) {
      error("G002", where + "missing field 'type'", src, v.offset);
      return;
    }
    if (!expect(*type, Kind::kString, where + "field 'type'", src)) return;
    n.type = type->text;
    n.type_offset = type->offset;
    const JsonValue* graph = v.find("graph");
    if (n.type == "subgraph") {
      if (graph == nullptr) {
        error("G002", where + "missing field 'graph' (a subgraph node names its graph)", src,
              v.offset);
      } else if (expect(*graph, Kind::kString, where + "field 'graph'", src)) {
        if (graph->text.empty()) {
          error("G002", where + "field 'graph' is empty", src, graph->offset);
        } else {
          n.graph_ref = graph->text;
          n.graph_offset = graph->offset;
        }
      }
    } else if (graph != nullptr) {
      error("G002", where + "field 'graph' belongs to subgraph nodes only", src, graph->offset);
    }
    if (const JsonValue* params = v.find("params")) {
      n.params_offset = params->offset;
      if (expect(*params, Kind::kObject, where + "field 'params'", src)) {
        for (const JsonMember& m : params->members) {
          check_name(m.key, m.key_offset, "parameter", src);
          n.params.push_back(param_value(m.key, m.key_offset, m.value));
        }
      }
    }
    if (const JsonValue* augment = v.find("augment")) {
      if (expect(*augment, Kind::kArray, where + "field 'augment'", src)) {
        for (const JsonValue& item : augment->items) {
          if (!expect(item, Kind::kObject, where + "an augmentation", src)) continue;
          Augmentation a;
          a.offset = item.offset;
          for (const JsonMember& m : item.members) {
            if (m.key == "kind" || m.key == "out") {
              if (!expect(m.value, Kind::kString, where + "field '" + m.key + "'", src)) continue;
              check_name(m.value.text, m.value.offset, m.key == "kind" ? "kind" : "port", src);
              (m.key == "kind" ? a.kind : a.out) = m.value.text;
              (m.key == "kind" ? a.kind_offset : a.out_offset) = m.value.offset;
            } else {
              check_name(m.key, m.key_offset, "field", src);
              a.fields.push_back(param_value(m.key, m.key_offset, m.value));
            }
          }
          n.augment.push_back(std::move(a));
        }
      }
    }
    if (const JsonValue* attributes = v.find("attributes")) {
      if (expect(*attributes, Kind::kObject, where + "field 'attributes'", src)) {
        for (const JsonMember& m : attributes->members) read_mapping(m, src, n, where);
      }
    }
    if (const JsonValue* ports = v.find("ports")) {
      if (expect(*ports, Kind::kObject, where + "field 'ports'", src)) {
        static constexpr const char* kPortFields[] = {"mode", "blocked", "doc"};
        for (const JsonMember& m : ports->members) {
          check_name(m.key, m.key_offset, "port", src);
          PortOptions o{m.key, m.key_offset, false, std::nullopt, 0};
          if (!expect(m.value, Kind::kObject, where + "port '" + m.key + "'", src)) continue;
          check_fields(m.value, kPortFields, where + "port '" + m.key + "': ", false, src);
          if (const JsonValue* b = m.value.find("blocked")) {
            if (expect(*b, Kind::kBool, where + "field 'blocked'", src)) o.blocked = b->boolean;
          }
          if (const JsonValue* mode = m.value.find("mode")) {
            if (mode->kind != Kind::kString ||
                (mode->text != "single" && mode->text != "collective")) {
              error("G002", where + "field 'mode' must be \"single\" or \"collective\"", src,
                    mode->offset);
            } else {
              o.collective = mode->text == "collective";
              o.mode_offset = mode->offset;
            }
          }
          n.ports.push_back(std::move(o));
        }
      }
    }
    for (const char* flag : {"enabled", "standalone_only"}) {
      if (const JsonValue* f = v.find(flag)) {
        if (expect(*f, Kind::kBool, where + "field '" + flag + "'", src)) {
          (std::string(flag) == "enabled" ? n.enabled : n.standalone_only) = f->boolean;
        }
      }
    }
    for (const char* text : {"label", "doc"}) {
      if (const JsonValue* t = v.find(text)) {
        expect(*t, Kind::kString, where + "field '" + text + "'", src);
      }
    }
    if (const JsonValue* ui = v.find("ui")) expect(*ui, Kind::kObject, where + "field 'ui'", src);
    g.nodes.push_back(std::move(n));
  }

  void read_mapping(const JsonMember& m, const base::Source& src, Node& n,
                    const std::string& where) {
    check_name(m.key, m.key_offset, "attribute", src);
    AttributeMapping a;
    a.node_attribute = m.key;
    a.offset = m.key_offset;
    const JsonValue* to = &m.value;
    if (m.value.kind == Kind::kObject) {
      static constexpr const char* kMappingFields[] = {"to", "direction"};
      check_fields(m.value, kMappingFields, where + "attribute '" + m.key + "': ", false, src);
      to = m.value.find("to");
      if (to == nullptr) {
        error("G002", where + "attribute '" + m.key + "': missing field 'to'", src, m.value.offset);
        return;
      }
      if (const JsonValue* d = m.value.find("direction")) {
        if (d->kind == Kind::kString &&
            (d->text == "in" || d->text == "out" || d->text == "inout")) {
          a.direction = d->text == "in"    ? Direction::kIn
                        : d->text == "out" ? Direction::kOut
                                           : Direction::kInOut;
        } else {
          error("G002", where + "field 'direction' must be \"in\", \"out\" or \"inout\"", src,
                d->offset);
        }
      }
    }
    if (!expect(*to, Kind::kString, where + "attribute '" + m.key + "'", src)) return;
    check_name(to->text, to->offset, "attribute", src);
    a.to = to->text;
    a.to_offset = to->offset;
    n.attributes.push_back(std::move(a));
  }

  // "node.port" inside the string `v`, from decoded byte `at`; false when malformed.
  bool port_ref(const base::Source& src, const JsonValue& v, std::string_view text, std::size_t at,
                PortRef& out) {
    const std::size_t dot = text.find('.');
    if (dot == std::string_view::npos) return false;
    out.node = std::string(text.substr(0, dot));
    out.port = std::string(text.substr(dot + 1));
    out.offset = string_byte_offset(src, v, at);
    return valid_name(out.node) && valid_name(out.port);
  }

  void read_edge(const JsonValue& v, const base::Source& src, Graph& g) {
    Edge e;
    e.offset = v.offset;
    if (v.kind == Kind::kString) {
      const std::string& t = v.text;
      const std::size_t arrow = t.find("->");
      const auto trim = [&t](std::size_t begin, std::size_t end) {
        while (begin < end && (t[begin] == ' ' || t[begin] == '\t')) ++begin;
        while (end > begin && (t[end - 1] == ' ' || t[end - 1] == '\t')) --end;
        return std::pair{begin, end};
      };
      bool ok = arrow != std::string::npos;
      if (ok) {
        const auto [fb, fe] = trim(0, arrow);
        const auto [tb, te] = trim(arrow + 2, t.size());
        ok = port_ref(src, v, std::string_view(t).substr(fb, fe - fb), fb, e.from) &&
             port_ref(src, v, std::string_view(t).substr(tb, te - tb), tb, e.to);
      }
      if (!ok) {
        error("G002", "edge '" + t + "' is not written 'node.port -> node.port'", src, v.offset);
        return;
      }
    } else if (v.kind == Kind::kObject) {
      static constexpr const char* kEdgeFields[] = {"from", "to", "enabled", "doc", "ui"};
      check_fields(v, kEdgeFields, "edge: ", false, src);
      for (const char* end : {"from", "to"}) {
        const JsonValue* r = v.find(end);
        if (r == nullptr) {
          error("G002", std::string("edge: missing field '") + end + "'", src, v.offset);
          return;
        }
        PortRef& ref = std::string(end) == "from" ? e.from : e.to;
        if (r->kind != Kind::kString || !port_ref(src, *r, r->text, 0, ref)) {
          error("G002", std::string("edge: field '") + end + "' must be 'node.port'", src,
                r->offset);
          return;
        }
      }
      if (const JsonValue* en = v.find("enabled")) {
        if (expect(*en, Kind::kBool, "edge: field 'enabled'", src)) e.enabled = en->boolean;
      }
    } else {
      error("G002", "an edge must be a string or an object, not " + std::string(kind_name(v.kind)),
            src, v.offset);
      return;
    }
    g.edges.push_back(std::move(e));
  }

  void read_gates(const JsonValue& v, const base::Source& src, Graph& g) {
    if (!expect(v, Kind::kObject, "field 'gates'", src)) return;
    static constexpr const char* kGateFields[] = {"inputs", "outputs"};
    check_fields(v, kGateFields, "gates: ", false, src);
    for (const char* side : {"inputs", "outputs"}) {
      const JsonValue* map = v.find(side);
      if (map == nullptr) continue;
      if (!expect(*map, Kind::kObject, std::string("gates: field '") + side + "'", src)) continue;
      for (const JsonMember& m : map->members) {
        check_name(m.key, m.key_offset, "gate", src);
        Gate gate{m.key, m.key_offset, {}};
        const auto add = [&](const JsonValue& r) {
          PortRef ref;
          if (r.kind != Kind::kString || !port_ref(src, r, r.text, 0, ref)) {
            error("G002", "gate '" + m.key + "': ports are written 'node.port'", src, r.offset);
            return;
          }
          gate.ports.push_back(std::move(ref));
        };
        if (m.value.kind == Kind::kArray) {
          if (m.value.items.empty()) {
            error("G002", "gate '" + m.key + "': an empty list of ports", src, m.value.offset);
          }
          for (const JsonValue& r : m.value.items) add(r);
        } else {
          add(m.value);
        }
        (std::string(side) == "inputs" ? g.inputs : g.outputs).push_back(std::move(gate));
      }
    }
  }

  void read_limits(const JsonValue& v, const base::Source& src, Limits& limits) {
    if (!expect(v, Kind::kObject, "field 'limits'", src)) return;
    static constexpr const char* kLimitFields[] = {"max_rounds", "max_entities",
                                                   "max_subgraph_depth"};
    check_fields(v, kLimitFields, "limits: ", false, src);
    for (const JsonMember& m : v.members) {
      if (m.value.kind != Kind::kInteger || m.value.integer < 1) {
        error("G002", "limits: field '" + m.key + "' must be an integer >= 1", src, m.value.offset);
        continue;
      }
      if (m.key == "max_rounds") limits.max_rounds = m.value.integer;
      if (m.key == "max_entities") limits.max_entities = m.value.integer;
      if (m.key == "max_subgraph_depth") limits.max_subgraph_depth = m.value.integer;
    }
  }

  const Graph* resolve(const Graph& g, const Node& n, const std::string& root_dir) {
    const base::Source& src = *g.source;
    notes_ = graph_notes(doc_, g);
    if (n.graph_ref[0] == '#') {
      const std::string wanted = n.graph_ref.substr(1);
      // Innermost first: the graph's own inline graphs, then its enclosing graphs'.
      for (const Graph* scope = &g; scope != nullptr; scope = scope->enclosing) {
        for (const auto& [name, inner] : scope->subgraphs) {
          if (name == wanted) return inner;
        }
      }
      error("G031", "no inline subgraph '" + n.graph_ref + "' (define it under 'subgraphs')", src,
            n.graph_offset);
      return nullptr;
    }
    // Relative to the folder of the file the node is in, walked component by component from the
    // top-level graph's folder: a path that steps above it is refused, however the top-level
    // file was named on the command line.
    std::vector<std::string> parts;
    for (const auto& part : std::filesystem::path(g.folder)) {
      if (!part.empty() && part != ".") parts.push_back(part.string());
    }
    bool outside = std::filesystem::path(n.graph_ref).is_absolute();
    for (const auto& part : std::filesystem::path(n.graph_ref)) {
      const std::string p = part.string();
      if (p.empty() || p == "." || p == "/") continue;
      if (p != "..") {
        parts.push_back(p);
      } else if (parts.empty()) {
        outside = true;
      } else {
        parts.pop_back();
      }
    }
    if (outside || parts.empty()) {
      error("G031",
            "cannot read subgraph '" + n.graph_ref + "': it leads outside the graph's folder", src,
            n.graph_offset);
      return nullptr;
    }
    std::string key;
    for (const std::string& p : parts) key += (key.empty() ? "" : "/") + p;
    if (const auto it = files_read_.find(key); it != files_read_.end()) return it->second;
    if (files_read_.size() >= kMaxSubgraphFiles) {
      error("G031",
            "cannot read subgraph '" + n.graph_ref + "': more than " +
                std::to_string(kMaxSubgraphFiles) + " subgraph files",
            src, n.graph_offset);
      return nullptr;
    }
    std::string text;
    std::string why;
    if (!files_ || !files_(key, text, why)) {
      error("G031",
            "cannot read subgraph '" + n.graph_ref + "': " + (why.empty() ? "no file reader" : why),
            src, n.graph_offset);
      files_read_[key] = nullptr;
      return nullptr;
    }
    const std::string shown =
        (std::filesystem::path(root_dir) / key).lexically_normal().generic_string();
    notes_.insert(notes_.begin(), "in subgraph '" + n.id + "' (" + shown + ")");
    Graph* read = read_file(std::make_unique<base::Source>(shown, std::move(text)), shown,
                            std::filesystem::path(key).parent_path().generic_string());
    notes_.clear();
    files_read_[key] = read;
    return read;
  }

  // G032: a graph that includes itself; reported once per cycle, at the node that closes it.
  void report_cycles() {
    std::map<const Graph*, int> state;  // 1 on the path, 2 done
    std::vector<std::pair<const Graph*, const Node*>> path;
    const std::function<void(const Graph*)> visit = [&](const Graph* g) {
      state[g] = 1;
      for (const Node& n : g->nodes) {
        if (n.subgraph == nullptr) continue;
        if (state[n.subgraph] == 1) {
          // The cycle: the graph named again, the references leading from it back to itself.
          std::string chain = n.subgraph->ref;
          bool on = false;
          for (const auto& [pg, pn] : path) {
            on = on || pg == n.subgraph;
            if (on) chain += " -> " + pn->graph_ref;
          }
          chain += " -> " + n.graph_ref;
          notes_ = graph_notes(doc_, *g);
          error("G032", "subgraph cycle: " + chain, *g->source, n.graph_offset);
          notes_.clear();
          continue;
        }
        if (state[n.subgraph] == 0) {
          path.emplace_back(g, &n);
          visit(n.subgraph);
          path.pop_back();
        }
      }
      state[g] = 2;
    };
    for (const auto& g : doc_.graphs) {
      if (state[g.get()] == 0) visit(g.get());
    }
  }

  Document& doc_;
  const FileReader& files_;
  std::vector<base::Diagnostic> diagnostics_;
  std::vector<std::string> notes_;
  std::map<std::string, const Graph*> files_read_;
};

}  // namespace

base::Result<Document> read_graph(const base::Source& source, const FileReader& files) {
  Document doc;
  Reader reader(doc, files);
  const Graph* root = reader.read_file(std::make_unique<base::Source>(source.name(), source.text()),
                                       source.name(), "");
  doc.root = root;
  if (root != nullptr && !base::has_errors(reader.diagnostics())) {
    reader.resolve_all(std::filesystem::path(source.name()).parent_path().string());
  }
  std::vector<base::Diagnostic> diagnostics = std::move(reader.diagnostics());
  if (root == nullptr || base::has_errors(diagnostics)) {
    return base::Result<Document>::failure(std::move(diagnostics));
  }
  return base::Result<Document>(std::move(doc), std::move(diagnostics));
}

}  // namespace insula::lang::graph
