#include "lang/graph/catalogue.h"

#include <algorithm>
#include <sstream>

#include "base/format.h"
#include "shape/operation.h"

namespace insula::lang::graph {

const PortSpec* NodeType::input(std::string_view port) const {
  for (const PortSpec& p : inputs) {
    if (p.name == port) return &p;
  }
  return nullptr;
}

const PortSpec* NodeType::output(std::string_view port) const {
  for (const PortSpec& p : outputs) {
    if (p.name == port) return &p;
  }
  return nullptr;
}

const ParamSpec* NodeType::param(std::string_view wanted) const {
  for (const ParamSpec& p : params) {
    if (p.name == wanted) return &p;
  }
  return nullptr;
}

const AugmentSpec* NodeType::augment(std::string_view kind) const {
  for (const AugmentSpec& a : augments) {
    if (a.kind == kind) return &a;
  }
  return nullptr;
}

bool NodeType::collective() const {
  return std::any_of(inputs.begin(), inputs.end(),
                     [](const PortSpec& p) { return p.mode == PortMode::kCollective; });
}

namespace {

// Ports written as in §11: "in:shape target:actor? -> out:T". An input's type may be `T` (generic,
// bound `entity`) or `T<actor`; suffix `*` collective, `^` single or collective, `?` optional.
void parse_ports(NodeType& type, std::string_view text) {
  std::istringstream in{std::string(text)};
  std::string word;
  bool outputs = false;
  while (in >> word) {
    if (word == "->") {
      outputs = true;
      continue;
    }
    PortSpec port;
    const std::size_t colon = word.find(':');
    port.name = word.substr(0, colon);
    std::string kind = word.substr(colon + 1);
    while (!kind.empty() && (kind.back() == '*' || kind.back() == '?' || kind.back() == '^')) {
      if (kind.back() == '*') port.mode = PortMode::kCollective;
      if (kind.back() == '^') port.mode = PortMode::kEither;
      if (kind.back() == '?') port.optional = true;
      kind.pop_back();
    }
    if (kind.rfind("T", 0) == 0) {
      port.generic = true;
      port.type = kind.size() > 2 ? *entity_type_named(kind.substr(2)) : EntityType::kEntity;
    } else {
      port.type = *entity_type_named(kind);
    }
    (outputs ? type.outputs : type.inputs).push_back(std::move(port));
  }
}

// Parameters: "name:type[=default][>=min][<=max][!]" separated by ';'; `!` marks per-entity (†);
// an enum is "enum(a|b|c)"; a default is JSON text.
std::vector<ParamSpec> parse_params(std::string_view text) {
  std::vector<ParamSpec> out;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find(';', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string item(text.substr(begin, end - begin));
    begin = end + 1;
    while (!item.empty() && item.front() == ' ') item.erase(0, 1);
    if (item.empty()) continue;
    ParamSpec p;
    if (item.back() == '!') {
      p.per_entity = true;
      item.pop_back();
    }
    const std::size_t colon = item.find(':');
    p.name = item.substr(0, colon);
    std::string rest = item.substr(colon + 1);
    const auto cut = [&rest](const std::string& marker) -> std::optional<std::string> {
      const std::size_t at = rest.find(marker);
      if (at == std::string::npos) return std::nullopt;
      std::size_t stop = rest.size();
      for (const char* other : {"=", ">=", "<="}) {
        const std::size_t next = rest.find(other, at + marker.size());
        if (next != std::string::npos && std::string(other) != marker) stop = std::min(stop, next);
      }
      std::string value = rest.substr(at + marker.size(), stop - at - marker.size());
      rest.erase(at, stop - at);
      return value;
    };
    if (const auto max = cut("<=")) p.max = std::stod(*max);
    if (const auto min = cut(">=")) p.min = std::stod(*min);
    if (const std::size_t eq = rest.find('='); eq != std::string::npos) {
      p.default_json = rest.substr(eq + 1);
      rest.erase(eq);
    }
    if (rest.rfind("enum(", 0) == 0) {
      p.type = ValueType::kEnum;
      std::string choices = rest.substr(5, rest.size() - 6);
      std::size_t from = 0;
      while (from <= choices.size()) {
        std::size_t bar = choices.find('|', from);
        if (bar == std::string::npos) bar = choices.size();
        p.choices.push_back(choices.substr(from, bar - from));
        from = bar + 1;
      }
    } else {
      p.type = *value_type_named(rest == "any" ? "list" : rest);
      if (rest == "any") p.type = ValueType::kAny;
    }
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<std::string> words(std::string_view text) {
  std::istringstream in{std::string(text)};
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// The registry operation's parameters as graph parameters, leaving out those the graph expresses
// with ports or augmentations (`except`).
std::vector<ParamSpec> registry_params(const shape::Operation& op,
                                       const std::vector<std::string>& except) {
  std::vector<ParamSpec> out;
  for (const shape::ParamDecl& d : op.params) {
    if (std::find(except.begin(), except.end(), d.name) != except.end()) continue;
    ParamSpec p;
    p.name = d.name;
    p.min = d.min;
    p.max = d.max;
    p.choices = d.choices;
    switch (d.type) {
      case shape::ParamType::kNumber:
        p.type = ValueType::kNumber;
        break;
      case shape::ParamType::kInteger:
        p.type = ValueType::kInteger;
        break;
      case shape::ParamType::kString:
        p.type = ValueType::kString;
        break;
      case shape::ParamType::kBool:
        p.type = ValueType::kBool;
        break;
      case shape::ParamType::kEnum:
        p.type = ValueType::kEnum;
        break;
      case shape::ParamType::kSize:
      case shape::ParamType::kSizeList:
        p.type = ValueType::kAny;
        p.registry_type = std::string(shape::param_type_name(d.type));
        break;
    }
    if (d.default_value) {
      const std::string shown = shape::to_string(*d.default_value);
      switch (p.type) {
        case ValueType::kNumber:
        case ValueType::kInteger:
          p.default_json = shown;
          break;
        case ValueType::kBool:
          p.default_json = std::get<bool>(*d.default_value) ? "true" : "false";
          break;
        default:
          p.default_json = base::quoted_string(shown);
          break;
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}

struct Row {
  const char* name;
  const char* category;
  const char* ports;
  const char* params;
  const char* writes;
  const char* registry_op;  // "" or "extrude" or "split-sizes" (op, then excluded parameters)
  const char* doc;
};

// §11, in its order. Every creating node also gets `impulse:entity?` (added below).
constexpr Row kRows[] = {
    {"create.rectangle", "creation", "-> out:shape",
     "width:number>=0; depth:number>=0; origin:vec3=[0,0,0]", "", "", "flat rectangle"},
    {"create.circle", "creation", "-> out:shape",
     "radius:number>=0; segments:integer=32>=3; center:vec3=[0,0,0]", "", "", "regular polygon"},
    {"create.polygon", "creation", "-> out:shape", "vertices:list", "", "", "polygon"},
    {"create.grid", "creation", "-> out:shape",
     "columns:integer>=1; rows:integer>=1; cell_width:number>=0; cell_depth:number>=0; "
     "gap:number=0>=0; origin:vec3=[0,0,0]",
     "index ix iy", "", "rectangles row by row"},
    {"create.points", "creation", "-> out:point", "points:list", "index", "", "points"},
    {"create.entity", "creation", "-> out:entity", "count:integer=1>=0", "index", "",
     "empty carriers"},
    {"create.lots", "creation", "-> out:shape", "file:string=\"\"", "index", "",
     "one flat shape per footprint polygon (GeoJSON, .osm, .osm.pbf)"},
    {"shape.extrude", "shape", "in:shape -> out:shape", "", "", "extrude", "registry extrude"},
    {"shape.split", "shape", "in:shape ->", "", "index count", "split sizes",
     "registry split; one port per slice"},
    {"shape.repeat", "shape", "in:shape -> out:shape", "", "index count", "repeat",
     "registry repeat"},
    {"shape.comp", "shape", "in:shape ->", "", "index count face", "comp type select",
     "registry comp(faces); one port per selection"},
    {"shape.offset", "shape", "in:shape -> inside:shape border:shape", "", "", "offset part",
     "registry offset"},
    {"shape.setback", "shape", "in:shape -> strip:shape rest:shape", "", "", "setback",
     "registry setback"},
    {"shape.roof", "shape", "in:shape -> out:shape", "", "", "roof", "registry roof"},
    {"shape.insert", "shape", "in:shape -> out:shape", "", "", "insert", "registry insert"},
    {"shape.fit_scope", "shape", "in:shape target:actor -> out:shape",
     "axes:enum(x|y|z|xy|xz|yz|xyz)=\"xyz\"", "", "", "fit-to-scope"},
    {"shape.merge", "shape", "in:shape* -> out:shape", "", "", "", "merging"},
    {"shape.unify", "shape", "in:shape -> out:shape", "tolerance:number=0.001>=0", "", "",
     "unification"},
    {"shape.adjacency_merge", "shape", "in:shape* -> out:shape", "tolerance:number=0.001>=0", "",
     "", "adjacency merge"},
    {"shape.set_material", "shape", "in:shape -> out:shape",
     "material:string; color:vec3=[0.8,0.8,0.8]", "", "", "face material"},
    {"shape.set_texture", "shape", "in:shape texture:texture -> out:shape", "", "", "",
     "procedural material"},
    {"shape.op", "shape", "in:shape -> out:shape", "op:string; args:any={}", "index count", "",
     "any registry operation by name"},
    {"actor.translate", "shape", "in:T<actor -> out:T", "space:enum(scope|world)=\"scope\"", "",
     "translate", "registry translate"},
    {"actor.rotate", "shape", "in:T<actor -> out:T", "", "", "rotate", "registry rotate"},
    {"actor.scale", "shape", "in:T<actor -> out:T", "", "", "scale", "registry scale"},
    {"path.create", "path", "-> out:path", "points:list; closed:bool=false", "", "",
     "a polyline network"},
    {"path.grid", "path", "-> out:path",
     "columns:integer>=1; rows:integer>=1; spacing_x:number>=0; spacing_y:number>=0; "
     "origin:vec3=[0,0,0]",
     "", "", "grid network"},
    {"path.to_shapes", "path", "in:path -> roads:shape blocks:shape", "width:number=10>=0", "index",
     "", "street to shape"},
    {"path.buffer", "path", "in:path -> out:shape", "width:number>=0", "", "", "buffer"},
    {"path.merge", "path", "in:path* -> out:path", "tolerance:number=0.001>=0", "", "",
     "one network"},
    {"path.decompose", "path", "in:path -> edges:path vertices:point", "", "index", "",
     "sub-entities as entities"},
    {"list.count", "list", "in:T* -> out:T", "", "index count", "", "count"},
    {"list.amount_filter", "list", "in:T* -> taken:T rest:T",
     "start:integer=0>=0; amount:integer=1>=0; by:list=[]!", "", "", "amount filter"},
    {"list.order_by", "list", "in:T* -> out:T", "", "", "", "order by"},
    {"list.reverse", "list", "in:T* -> out:T", "", "", "", "reverse"},
    {"list.shuffle", "list", "in:T* -> out:T", "seed:integer=0", "", "", "shuffle"},
    {"list.aggregate", "list", "in:T* -> out:T",
     "value:any!; op:enum(sum|average|min|max|count); by:list=[]!", "result", "", "aggregator"},
    {"list.group", "list", "in:T* -> out:group", "by:list=[]!", "size", "", "group"},
    {"list.ungroup", "list", "in:group -> out:entity", "", "", "", "ungroup"},
    {"query.kmeans", "query", "in:T<actor* -> out:T",
     "k:integer>=1; position:vec3=\"= pos()\"!; max_iterations:integer=100>=1", "cluster center",
     "", "cluster (k-means)"},
    {"query.ray_cast", "query",
     "sources:shape* targets:actor* -> sources:shape hit:actor miss:actor",
     "axis:enum(+x|-x|+y|-y|+z|-z)=\"+z\"; max_distance:number=1e9>=0",
     "hit hit_position hit_distance", "", "ray cast"},
    {"query.occlusion", "query", "shapes:shape* occluders:shape* -> occluded:shape visible:shape",
     "distance:number=10>=0; threshold:number=0.5>=0<=1", "occlusion", "", "occlusion query"},
    {"query.is_oriented_to", "query",
     "shapes:shape* streets:path* occluders:shape*? -> oriented:shape other:shape",
     "tolerance:number=45>=0<=180", "oriented", "", "is oriented to"},
    {"query.distance", "query", "in:T<actor* targets:actor* -> out:T", "", "distance nearest", "",
     "distance to targets"},
    {"attr.set", "flow", "in:T^ -> out:T", "values:any={}", "", "", "sets graph attributes"},
    {"attr.transfer", "flow", "in:T from:entity -> out:T", "names:list", "", "",
     "copies attributes"},
    {"flow.condition", "flow", "in:T -> true:T false:T", "if:bool", "", "", "condition"},
    {"flow.switch", "flow", "in:T -> else:T", "", "", "", "first true case wins"},
    {"flow.stochastic", "flow", "in:T ->", "seed:integer=0", "", "", "weighted choice"},
    {"flow.copy", "flow", "in:T -> out:T", "count:integer=1>=0", "copy", "", "copies"},
    {"light.create", "light", "in:actor -> out:light",
     "position:vec3=\"= vec(sx()/2, sy()/2, sz()/2)\"; kind:enum(point|spot)=\"point\"; "
     "intensity:number=100>=0; color:vec3=[1,1,0.8]; range:number=0>=0",
     "", "", "light sources"},
    {"texture.text", "texture", "-> out:texture",
     "text:string; name:string=\"text\"; width:integer=256>=1; height:integer=128>=1; "
     "size:number=64>=0; color:vec3=[0,0,0]; background:vec3=[1,1,1]",
     "", "", "text on image"},
    {"texture.invert", "texture", "in:texture -> out:texture", "", "", "", "invert"},
    {"texture.combine", "texture", "a:texture b:texture -> out:texture",
     "op:enum(add|subtract|multiply)", "", "", "combine"},
    // Extensions of the format (docs/graph-executor.md, "Rule nodes"): another front-end's
    // program run on each shape, so CGA, .bldg, Lua and PLaSM work inside graphs.
    {"rule.cga", "rule", "in:shape -> out:shape", "file:string; start:string=\"\"", "", "",
     "derives a CGA rule file from the shape's footprint (the lot)"},
    {"rule.bldg", "rule", "in:shape -> out:shape", "file:string", "", "",
     "builds a .bldg grammar on the shape's footprint"},
    {"rule.lua", "rule", "in:shape -> out:shape", "file:string", "", "",
     "runs a Lua program on the shape's footprint"},
    {"rule.plasm", "rule", "in:shape -> out:shape", "file:string", "", "",
     "a PLaSM expression FILE.psm#EXPRESSION fitted into the shape's scope"},
    // Extensions of the format (docs/graph-executor.md, "Terrain"): the surfaces of seed 003
    // §5.1 (noise, smoothing, levelling) as a `terrain` entity, and actors placed on it.
    {"terrain.create", "terrain", "-> out:terrain",
     "width:number>=0; depth:number>=0; cell:number=2>=0; origin:vec3=[0,0,0]; height:number=0", "",
     "", "a flat heightfield of width x depth metres, samples at most `cell` apart"},
    {"terrain.noise", "terrain", "in:terrain -> out:terrain",
     "amplitude:number>=0; wavelength:number>=0; octaves:integer=4>=1<=16; seed:integer=0", "", "",
     "adds fractal gradient noise (within +-amplitude; each octave half the last)"},
    {"terrain.smooth", "terrain", "in:terrain -> out:terrain", "iterations:integer=1>=0<=1000", "",
     "", "binomial 3x3 smoothing passes"},
    {"terrain.level", "terrain", "in:terrain* shapes:shape*? roads:shape*? -> out:terrain",
     "margin:number=5>=0", "", "",
     "flat under each footprint (its mean height), roads flat across, blended over `margin`"},
    {"terrain.place", "terrain", "in:T<actor* terrain:terrain* -> out:T", "", "", "",
     "shapes onto the terrain at their footprint's centroid; path vertices, points, lights"},
};

std::vector<NodeType> build() {
  std::vector<NodeType> out;
  for (const Row& row : kRows) {
    NodeType t;
    t.name = row.name;
    t.category = row.category;
    t.doc = row.doc;
    parse_ports(t, row.ports);
    // Creating nodes: no input port of their own (texture.text creates too).
    t.creating = t.inputs.empty();
    if (t.creating) {
      t.inputs.insert(t.inputs.begin(),
                      PortSpec{"impulse", EntityType::kEntity, false, PortMode::kSingle, true});
    }
    const std::vector<std::string> op = words(row.registry_op);
    if (!op.empty()) {
      t.registry_op = op[0];
      const shape::Operation* registered = shape::registry().find(op[0]);
      if (registered != nullptr) {
        t.params = registry_params(*registered, {op.begin() + 1, op.end()});
      }
    }
    for (ParamSpec& p : parse_params(row.params)) t.params.push_back(std::move(p));
    t.writes = words(row.writes);
    out.push_back(std::move(t));
  }
  const auto find = [&out](std::string_view name) -> NodeType& {
    return *std::find_if(out.begin(), out.end(), [&](const NodeType& t) { return t.name == name; });
  };
  find("shape.split").augments = {{"slice", parse_params("size:any"), true}};
  find("shape.comp").augments = {
      {"select", parse_params("faces:enum(front|back|left|right|top|bottom|side|all)"), true}};
  find("list.order_by").augments = {
      {"criterion", parse_params("value:any!; descending:bool=false"), false}};
  find("flow.switch").augments = {{"case", parse_params("if:bool"), true}};
  find("flow.stochastic").augments = {{"branch", parse_params("weight:number>=0"), true}};
  return out;
}

}  // namespace

std::span<const NodeType> catalogue() {
  static const std::vector<NodeType> kTable = build();
  return kTable;
}

const NodeType* find_node_type(std::string_view name) {
  for (const NodeType& t : catalogue()) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

}  // namespace insula::lang::graph
