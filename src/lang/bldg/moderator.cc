// The rules' moderator (seed 000, §3.3): "each grammar-based instruction is verified to check
// typos, i.e., unknown syntax and/or the structure (sequence conformity). Then, a structure of
// ontology-based class instances, representing a building's components, is loaded with the data
// extracted from the incoming rules". Checks, in order: functions and their parameters; symbol
// definitions and uses (undefined, unused, used twice, cycles); the ontology's structure (§4.1:
// parts hold floors, floors hold divisions, divisions are final or containers); transitions.
// Every problem is reported, at the offending token; a file with errors gives no model.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kernel/polygon.h"
#include "lang/bldg/parser.h"

namespace insula::lang::bldg {
namespace {

enum class Fn {
  kUnknown,
  kBuilding,
  kBuildingParts,
  kBuildingPart,
  kFloor,
  kDivisions,
  kRoom,
  kDoor,
  kEntrance,
  kWindow,
  kStair
};

struct FnInfo {
  const char* name;
  Fn fn;
};
constexpr FnInfo kFunctions[] = {
    {"building", Fn::kBuilding},
    {"buildingparts", Fn::kBuildingParts},
    {"buildingpart", Fn::kBuildingPart},
    {"floor", Fn::kFloor},
    {"divisions", Fn::kDivisions},
    {"room", Fn::kRoom},
    {"division", Fn::kRoom},
    {"door", Fn::kDoor},
    {"entrance", Fn::kEntrance},
    {"window", Fn::kWindow},
    {"stair", Fn::kStair},
};

std::string lower(std::string text) {
  for (char& c : text) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return text;
}

Fn function_of(const std::string& name) {
  const std::string key = lower(name);
  for (const FnInfo& info : kFunctions) {
    if (key == info.name) return info.fn;
  }
  return Fn::kUnknown;
}

bool is_transition(Fn fn) {
  return fn == Fn::kDoor || fn == Fn::kEntrance || fn == Fn::kWindow || fn == Fn::kStair;
}
bool is_part_level(Fn fn) {
  return fn == Fn::kBuildingParts || fn == Fn::kBuildingPart;
}
bool is_division_level(Fn fn) {
  return fn == Fn::kDivisions || fn == Fn::kRoom;
}
bool is_container(Fn fn) {
  return fn == Fn::kBuilding || fn == Fn::kBuildingParts || fn == Fn::kBuildingPart ||
         fn == Fn::kFloor || fn == Fn::kDivisions;
}

constexpr struct {
  const char* name;
  RoofKind kind;
} kRoofs[] = {
    {"flat", RoofKind::kFlat},
    {"pyramid", RoofKind::kPyramid},
    {"hip", RoofKind::kHip},
    {"mansard", RoofKind::kMansard},
    {"holedmansard", RoofKind::kHoledMansard},
    {"none", RoofKind::kNone},
    {"gable", RoofKind::kGable},
    {"hipglued", RoofKind::kHipGlued},
};

std::optional<Orientation> orientation_of(const std::string& word) {
  const std::string key = lower(word);
  if (key == "horizontal") return Orientation::kHorizontal;
  if (key == "vertical") return Orientation::kVertical;
  if (key == "alternate") return Orientation::kAlternate;
  return std::nullopt;
}

// One rule with its parameters read (valid ones only; errors already reported).
struct Node {
  const RuleSyntax* rule = nullptr;
  Fn fn = Fn::kUnknown;
  Orientation orientation = Orientation::kAlternate;
  double number = 0;  // part roof height, floor height, transition width
  RoofKind roof = RoofKind::kFlat;
  Room room;
  std::string building_name;
  kernel::Polygon outline;
  std::string outline_file, outline_feature;
  Location outline_where;
  std::vector<const Value*> targets;  // transition rooms, as written
  // Tree, filled by the reference checks: children in set order (defined symbols only).
  std::vector<int> children;
  int parent = -1;
  bool referenced = false;
  int storey = -1;             // rooms: floor index within the part
  bool in_disposable = false;  // rooms of a height-0 part
};

class Moderator {
 public:
  Moderator(const base::Source& source, const std::vector<RuleSyntax>& rules,
            std::vector<base::Diagnostic>& diags)
      : source_(source), rules_(rules), diags_(diags) {}

  std::optional<Building> run() {
    read_rules();
    define_symbols();
    const int axiom = find_axiom();
    link_sets();
    check_finality();
    if (axiom >= 0) walk_tree(axiom);
    report_unreached(axiom >= 0);
    check_structure();
    if (axiom >= 0) assign_storeys(axiom);
    check_transitions();
    if (axiom < 0 || base::has_errors(diags_)) return std::nullopt;
    return build(axiom);
  }

 private:
  // ---- diagnostics ----
  void error(const char* code, std::string message, Range range) {
    diags_.push_back(base::Diagnostic::error(code, std::move(message), span_of(source_, range)));
  }
  void warning(const char* code, std::string message, Range range) {
    diags_.push_back(base::Diagnostic::warning(code, std::move(message), span_of(source_, range)));
  }
  Location location(Range range) const {
    const auto [line, column] = source_.locate(range.begin);
    return Location{line, column};
  }
  static std::string quoted(const std::string& text) { return "'" + text + "'"; }

  // ---- parameters ----
  void read_rules() {
    nodes_.resize(rules_.size());
    for (std::size_t i = 0; i < rules_.size(); ++i) {
      Node& node = nodes_[i];
      node.rule = &rules_[i];
      node.fn = function_of(rules_[i].function.name);
      if (node.fn == Fn::kUnknown) {
        error("BLD201",
              "unknown function " + quoted(rules_[i].function.name) +
                  " (building, buildingparts, buildingpart, floor, divisions, room, door, "
                  "entrance, window, stair)",
              rules_[i].function.range);
        continue;
      }
      read_parameters(node);
    }
  }

  bool check_count(const RuleSyntax& rule, std::size_t min, std::size_t max, const char* what) {
    const std::size_t n = rule.args.size();
    if (n >= min && n <= max) return true;
    std::string expected = min == max       ? std::to_string(min)
                           : max == min + 1 ? std::to_string(min) + " or " + std::to_string(max)
                                            : std::to_string(min) + " to " + std::to_string(max);
    error("BLD202",
          quoted(lower(rule.function.name)) + " expects " + expected + " parameters (" + what +
              "), found " + std::to_string(n),
          rule.args_range);
    return false;
  }

  void type_error(const RuleSyntax& rule, const Value& value, const std::string& expected) {
    error("BLD203",
          "parameter of " + quoted(lower(rule.function.name)) + " must be " + expected +
              ", found " + kind_name(value),
          value.range);
  }

  static std::string kind_name(const Value& value) {
    switch (value.kind) {
      case Value::Kind::kNumber:
        return "a number";
      case Value::Kind::kString:
        return "a string";
      case Value::Kind::kIdent:
        return "the name " + quoted(value.text);
      case Value::Kind::kPoint:
        return "a point";
      case Value::Kind::kRing:
        return "a ring";
      case Value::Kind::kCall:
        return "a call of " + quoted(value.text);
    }
    return "a value";
  }

  std::optional<double> number(const RuleSyntax& rule, const Value& value, const char* what,
                               double min, double max, bool zero_ok = false) {
    if (value.kind != Value::Kind::kNumber) {
      type_error(rule, value, std::string("a number (") + what + ")");
      return std::nullopt;
    }
    const double v = value.number;
    if ((v < min || v > max) && !(zero_ok && v == 0)) {
      error("BLD205",
            std::string(what) + " " + format(v) + " is out of range [" + format(min) + ", " +
                format(max) + "]" + (zero_ok ? " (or 0 for the default)" : ""),
            value.range);
      return std::nullopt;
    }
    return v;
  }

  std::optional<int> count(const RuleSyntax& rule, const Value& value, const char* what, int min,
                           int max, bool zero_ok) {
    const auto v = number(rule, value, what, min, max, zero_ok);
    if (!v) return std::nullopt;
    if (*v != std::floor(*v)) {
      error("BLD203", std::string(what) + " must be a whole number, found " + format(*v),
            value.range);
      return std::nullopt;
    }
    return static_cast<int>(*v);
  }

  static std::string format(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
  }

  std::optional<std::string> name(const RuleSyntax& rule, const Value& value, const char* what) {
    if (value.kind != Value::Kind::kIdent && value.kind != Value::Kind::kString) {
      type_error(rule, value, std::string("a name (") + what + ")");
      return std::nullopt;
    }
    if (value.text.empty()) {
      error("BLD205", std::string(what) + " must not be empty", value.range);
      return std::nullopt;
    }
    return value.text;
  }

  std::optional<Orientation> orientation(const RuleSyntax& rule, const Value& value) {
    if (value.kind != Value::Kind::kIdent) {
      type_error(rule, value, "an orientation (horizontal, vertical or alternate)");
      return std::nullopt;
    }
    const auto o = orientation_of(value.text);
    if (!o) {
      error("BLD204",
            "unknown orientation " + quoted(value.text) + " (horizontal, vertical or alternate)",
            value.range);
    }
    return o;
  }

  void read_parameters(Node& node) {
    const RuleSyntax& rule = *node.rule;
    switch (node.fn) {
      case Fn::kBuilding:
        return read_building(node);
      case Fn::kBuildingParts:
      case Fn::kDivisions:
        if (check_count(rule, 0, 1, "[orientation]") && !rule.args.empty()) {
          node.orientation = orientation(rule, rule.args[0]).value_or(Orientation::kAlternate);
        }
        return;
      case Fn::kBuildingPart:
        return read_part(node);
      case Fn::kFloor:
        return read_floor(node);
      case Fn::kRoom:
        return read_room(node);
      case Fn::kDoor:
      case Fn::kStair:
        return read_transition(node, 2);
      case Fn::kEntrance:
      case Fn::kWindow:
        return read_transition(node, 1);
      case Fn::kUnknown:
        return;
    }
  }

  void read_part(Node& node) {
    const RuleSyntax& rule = *node.rule;
    if (!check_count(rule, 2, 2, "roof, height")) return;
    const Value& roof = rule.args[0];
    if (roof.kind != Value::Kind::kIdent) {
      type_error(rule, roof, "a roof kind");
    } else {
      bool found = false;
      for (const auto& entry : kRoofs) {
        if (lower(roof.text) == entry.name) {
          node.roof = entry.kind;
          found = true;
        }
      }
      if (!found) {
        error("BLD204",
              "unknown roof kind " + quoted(roof.text) +
                  " (Flat, Pyramid, Hip, Mansard, HoledMansard, None, Gable, HipGlued)",
              roof.range);
      }
    }
    node.number = number(rule, rule.args[1], "roof height", 0, 100).value_or(0);
  }

  void read_floor(Node& node) {
    const RuleSyntax& rule = *node.rule;
    if (!check_count(rule, 0, 2, "[height], [orientation]")) return;
    std::size_t i = 0;
    if (i < rule.args.size() && rule.args[i].kind != Value::Kind::kIdent) {
      node.number = number(rule, rule.args[i], "storey height", 2, 20, true).value_or(0);
      ++i;
    }
    if (i < rule.args.size()) {
      node.orientation = orientation(rule, rule.args[i]).value_or(Orientation::kAlternate);
      ++i;
    }
    if (i < rule.args.size()) type_error(rule, rule.args[i], "an orientation");
  }

  void read_room(Node& node) {
    const RuleSyntax& rule = *node.rule;
    if (!check_count(rule, 2, 5, "type, size, [walls], [windows], [entrance]")) return;
    node.room.type = name(rule, rule.args[0], "room type").value_or("");
    const Value& size = rule.args[1];
    if (size.kind != Value::Kind::kIdent) {
      type_error(rule, size, "a size label (small, medium or big)");
    } else {
      const std::string key = lower(size.text);
      if (key == "small") {
        node.room.size = SizeLabel::kSmall;
      } else if (key == "medium") {
        node.room.size = SizeLabel::kMedium;
      } else if (key == "big") {
        node.room.size = SizeLabel::kBig;
      } else {
        error("BLD204", "unknown size label " + quoted(size.text) + " (small, medium or big)",
              size.range);
      }
    }
    if (rule.args.size() > 2) {
      const auto walls = count(rule, rule.args[2], "number of walls", 3, 32, true);
      if (walls) node.room.walls = *walls;
    }
    if (rule.args.size() > 3) {
      node.room.windows = count(rule, rule.args[3], "number of windows", 0, 32, false).value_or(0);
    }
    if (rule.args.size() > 4) {
      const Value& flag = rule.args[4];
      const std::string key = flag.kind == Value::Kind::kIdent ? lower(flag.text) : "";
      if (key == "true" || key == "false") {
        node.room.entrance = key == "true";
      } else {
        type_error(rule, flag, "true or false (entrance)");
      }
    }
  }

  void read_transition(Node& node, std::size_t rooms) {
    const RuleSyntax& rule = *node.rule;
    if (!check_count(rule, rooms, rooms + 1,
                     rooms == 2 ? "room, room, [width]" : "room, [width]")) {
      return;
    }
    for (std::size_t i = 0; i < rooms; ++i) {
      if (rule.args[i].kind != Value::Kind::kIdent) {
        type_error(rule, rule.args[i], "a room symbol");
      } else {
        node.targets.push_back(&rule.args[i]);
      }
    }
    if (rule.args.size() > rooms) {
      node.number = number(rule, rule.args[rooms], "width", 0.3, 20, true).value_or(0);
    }
  }

  void read_building(Node& node) {
    const RuleSyntax& rule = *node.rule;
    if (rule.args.size() < 2) {
      error("BLD202",
            "'building' expects a name and an outline (a ring or geojson(file, feature)), found " +
                std::to_string(rule.args.size()),
            rule.args_range);
      return;
    }
    node.building_name = name(rule, rule.args[0], "building name").value_or("");
    std::size_t end = rule.args.size();
    if (end > 2 && rule.args.back().kind == Value::Kind::kIdent) {
      node.orientation = orientation(rule, rule.args.back()).value_or(Orientation::kAlternate);
      --end;
    }
    const Value& first = rule.args[1];
    node.outline_where = location(first.range);
    if (first.kind == Value::Kind::kCall) {
      read_geojson(node, first);
      for (std::size_t i = 2; i < end; ++i) {
        type_error(rule, rule.args[i], "an orientation (a geojson outline takes no holes)");
      }
      return;
    }
    bool rings_ok = true;
    for (std::size_t i = 1; i < end; ++i) {
      const Value& ring = rule.args[i];
      if (ring.kind != Value::Kind::kRing) {
        type_error(rule, ring,
                   i == 1 ? "an outline ring [(x, y), ...] or geojson(file, feature)"
                          : "a hole ring [(x, y), ...]");
        rings_ok = false;
        continue;
      }
      if (ring.ring.size() < 3) {
        error("BLD206",
              "invalid outline: a ring needs at least 3 points, found " +
                  std::to_string(ring.ring.size()),
              ring.range);
        rings_ok = false;
        continue;
      }
      if (i == 1) {
        node.outline.outer = ring.ring;
      } else {
        node.outline.holes.push_back(ring.ring);
      }
    }
    if (rings_ok) check_outline(node, rule);
  }

  void read_geojson(Node& node, const Value& call) {
    const RuleSyntax& rule = *node.rule;
    if (lower(call.text) != "geojson") {
      error("BLD201", "unknown function " + quoted(call.text) + " in an outline (geojson)",
            call.range);
      return;
    }
    if (call.args.size() != 2) {
      error("BLD202",
            "'geojson' expects 2 parameters (file, feature), found " +
                std::to_string(call.args.size()),
            call.range);
      return;
    }
    const Value& file = call.args[0];
    if (file.kind != Value::Kind::kString || file.text.empty()) {
      type_error(rule, file, "a file name string");
    } else {
      node.outline_file = file.text;
    }
    const Value& feature = call.args[1];
    if (feature.kind == Value::Kind::kNumber && feature.number == std::floor(feature.number)) {
      node.outline_feature = format(feature.number);
    } else if ((feature.kind == Value::Kind::kString || feature.kind == Value::Kind::kIdent) &&
               !feature.text.empty()) {
      node.outline_feature = feature.text;
    } else {
      type_error(rule, feature, "a feature id (string or whole number)");
    }
  }

  // The constraint polygon must be usable by the subdivision (§3.2): positive area, no crossing
  // edges, holes inside. Orientation is normalised; collinear vertices are kept as written.
  void check_outline(Node& node, const RuleSyntax& rule) {
    kernel::normalize(node.outline);
    for (const kernel::PolygonIssue& issue : kernel::validate(node.outline)) {
      if (issue.kind == kernel::PolygonIssueKind::kCollinearVertex ||
          issue.kind == kernel::PolygonIssueKind::kWrongOrientation) {
        continue;
      }
      std::string message = issue.message;
      const std::size_t removed = message.rfind(" (removed)");
      if (removed != std::string::npos) message.resize(removed);
      const std::size_t arg = 1 + static_cast<std::size_t>(std::max(0, issue.ring));
      const Range range = arg < rule.args.size() ? rule.args[arg].range : rule.args_range;
      error("BLD206", "invalid outline: " + message, range);
      return;
    }
  }

  // ---- symbols ----
  void define_symbols() {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const SymbolRef& symbol = nodes_[i].rule->symbol;
      const auto [it, inserted] = symbols_.emplace(symbol.name, static_cast<int>(i));
      if (!inserted) {
        duplicates_.push_back(static_cast<int>(i));
        const Location first = location(nodes_[it->second].rule->symbol.range);
        error("BLD210",
              "symbol " + quoted(symbol.name) + " is already defined at line " +
                  std::to_string(first.line),
              symbol.range);
      }
    }
  }

  int lookup(const std::string& name) const {
    const auto it = symbols_.find(name);
    return it == symbols_.end() ? -1 : it->second;
  }

  int find_axiom() {
    int axiom = -1;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (nodes_[i].fn != Fn::kBuilding) continue;
      if (axiom < 0) {
        axiom = static_cast<int>(i);
      } else {
        error("BLD215",
              "a second building axiom " + quoted(nodes_[i].rule->symbol.name) +
                  " (a file describes one building)",
              nodes_[i].rule->function.range);
      }
    }
    if (axiom < 0) {
      const Range range = rules_.empty() ? Range{0, 0} : rules_.front().range;
      error("BLD215", "no building axiom: one rule must be 'symbol -> building(name, outline)'",
            range);
    }
    return axiom;
  }

  // Resolves every successor set; the tree edges are the first use of each symbol.
  void link_sets() {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      for (const SymbolRef& ref : nodes_[i].rule->set) {
        const int child = lookup(ref.name);
        if (child < 0) {
          error("BLD211", "undefined symbol " + quoted(ref.name), ref.range);
          continue;
        }
        edges_.push_back(Edge{static_cast<int>(i), child, &ref});
        nodes_[static_cast<std::size_t>(child)].referenced = true;
      }
    }
    std::stable_sort(edges_.begin(), edges_.end(),
                     [](const Edge& a, const Edge& b) { return a.from < b.from; });
  }

  void check_finality() {
    for (const Node& node : nodes_) {
      const RuleSyntax& rule = *node.rule;
      if (node.fn == Fn::kRoom || is_transition(node.fn)) {
        if (rule.has_set) {
          error("BLD207",
                quoted(rule.symbol.name) + " is a " +
                    (node.fn == Fn::kRoom ? "room" : "transition") +
                    ", a final symbol: it takes no successors",
                rule.set_range);
        }
      } else if (is_container(node.fn) && node.fn != Fn::kBuildingPart && rule.set.empty()) {
        error("BLD207",
              quoted(rule.symbol.name) + " needs successors: ': {symbol, ...}' after " +
                  quoted(lower(rule.function.name) + "(...)"),
              rule.has_set ? rule.set_range : rule.args_range);
      }
    }
  }

  // Depth-first from `root` with an explicit stack (grammars may be deep): the first edge into a
  // white node is a tree edge, an edge into a node on the stack a cycle, any other edge into a
  // visited node a second use.
  void visit_from(int root) {
    struct Frame {
      int node;
      std::size_t next;
    };
    std::vector<Frame> stack{{root, 0}};
    color_[static_cast<std::size_t>(root)] = 1;
    while (!stack.empty()) {
      Frame& frame = stack.back();
      const auto [begin, end] = edges_of(frame.node);
      if (begin + frame.next >= end) {
        color_[static_cast<std::size_t>(frame.node)] = 2;
        stack.pop_back();
        continue;
      }
      const Edge& edge = edges_[begin + frame.next++];
      const auto child = static_cast<std::size_t>(edge.to);
      if (color_[child] == 1) {
        error("BLD213",
              "cycle: " + quoted(edge.ref->name) + " is among its own successors (through " +
                  quoted(nodes_[static_cast<std::size_t>(edge.from)].rule->symbol.name) + ")",
              edge.ref->range);
      } else if (color_[child] == 2) {
        if (nodes_[child].fn == Fn::kBuilding) {
          error("BLD220", "the building axiom " + quoted(edge.ref->name) + " cannot be a successor",
                edge.ref->range);
        } else {
          // A node reached first as the root of a detached subtree, or cut off below the depth
          // limit, has no parent to name.
          const int parent = nodes_[child].parent;
          error("BLD214",
                "symbol " + quoted(edge.ref->name) + " is already used" +
                    (parent >= 0
                         ? " in the set of " +
                               quoted(nodes_[static_cast<std::size_t>(parent)].rule->symbol.name)
                         : std::string(" in another set")) +
                    " (each symbol is used once: the rules form a tree)",
                edge.ref->range);
        }
      } else if (stack.size() > kMaxDepth) {
        error("BLD216", "the tree is deeper than " + std::to_string(kMaxDepth) + " levels",
              edge.ref->range);
        color_[child] = 2;
      } else {
        nodes_[child].parent = frame.node;
        nodes_[static_cast<std::size_t>(frame.node)].children.push_back(edge.to);
        color_[child] = 1;
        stack.push_back(Frame{edge.to, 0});
      }
    }
  }

  std::pair<std::size_t, std::size_t> edges_of(int node) const {
    const auto lo = std::lower_bound(edges_.begin(), edges_.end(), node,
                                     [](const Edge& e, int n) { return e.from < n; });
    const auto hi = std::upper_bound(edges_.begin(), edges_.end(), node,
                                     [](int n, const Edge& e) { return n < e.from; });
    return {static_cast<std::size_t>(lo - edges_.begin()),
            static_cast<std::size_t>(hi - edges_.begin())};
  }

  void walk_tree(int axiom) {
    color_.assign(nodes_.size(), 0);
    visit_from(axiom);
  }

  // Rules the axiom does not reach: each unused subtree is reported once, at its root; rules that
  // only refer to each other in a ring are reported as a cycle.
  void report_unreached(bool has_axiom) {
    color_.resize(nodes_.size(), 0);
    // A second definition is reported as such; without an axiom everything would be unused.
    for (const int d : duplicates_) color_[static_cast<std::size_t>(d)] = 2;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (color_[i] != 0 || nodes_[i].referenced) continue;
      if (nodes_[i].fn != Fn::kBuilding && has_axiom) {
        error("BLD212",
              "unused symbol " + quoted(nodes_[i].rule->symbol.name) +
                  " (no successor set refers to it)",
              nodes_[i].rule->symbol.range);
      }
      visit_from(static_cast<int>(i));
    }
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (color_[i] == 0) visit_from(static_cast<int>(i));
    }
  }

  // §4.1: the building holds parts and transitions, a part holds floors, a floor holds divisions.
  void check_structure() {
    for (const Node& parent : nodes_) {
      for (const int c : parent.children) {
        const Node& child = nodes_[static_cast<std::size_t>(c)];
        if (child.fn == Fn::kUnknown || parent.fn == Fn::kUnknown || is_transition(child.fn)) {
          continue;
        }
        const std::string message = misplacement(parent.fn, child.fn, child.rule->symbol.name);
        if (!message.empty()) error("BLD220", message, ref_to(parent, c));
      }
      const bool needs_child = is_container(parent.fn) && parent.fn != Fn::kBuildingPart;
      if (needs_child && !parent.children.empty() &&
          std::all_of(parent.children.begin(), parent.children.end(), [&](int c) {
            return is_transition(nodes_[static_cast<std::size_t>(c)].fn);
          })) {
        error("BLD207",
              quoted(parent.rule->symbol.name) + " holds only transitions; it needs " +
                  (parent.fn == Fn::kBuilding || parent.fn == Fn::kBuildingParts ? "a building part"
                                                                                 : "a division"),
              parent.rule->set_range);
      }
      if (parent.fn == Fn::kBuildingPart && parent.rule->has_set == false) {
        error("BLD221",
              "building part " + quoted(parent.rule->symbol.name) +
                  " has no floors: ': {floor, ...}' after 'buildingpart(...)'",
              parent.rule->args_range);
      } else if (parent.fn == Fn::kBuildingPart &&
                 std::none_of(parent.children.begin(), parent.children.end(), [&](int c) {
                   return nodes_[static_cast<std::size_t>(c)].fn == Fn::kFloor;
                 })) {
        error("BLD221", "building part " + quoted(parent.rule->symbol.name) + " has no floors",
              parent.rule->has_set ? parent.rule->set_range : parent.rule->args_range);
      }
    }
  }

  Range ref_to(const Node& parent, int child) const {
    for (const SymbolRef& ref : parent.rule->set) {
      if (lookup(ref.name) == child) return ref.range;
    }
    return parent.rule->range;
  }

  static std::string misplacement(Fn parent, Fn child, const std::string& name) {
    const std::string q = quoted(name);
    const bool part_parent = parent == Fn::kBuilding || parent == Fn::kBuildingParts;
    if (part_parent) {
      if (is_part_level(child)) return {};
      if (child == Fn::kFloor) return "floor " + q + " is outside a building part";
      return "division " + q + " is outside a floor (divisions belong to a floor)";
    }
    if (parent == Fn::kBuildingPart) {
      if (child == Fn::kFloor) return {};
      if (is_part_level(child)) {
        return "building part " + q +
               " cannot be inside the final building part (use "
               "'buildingparts' for a container)";
      }
      return "division " + q + " is outside a floor (a building part holds floors)";
    }
    // Floors and division containers.
    if (is_division_level(child)) return {};
    if (child == Fn::kFloor) return "floor " + q + " is inside a floor or division";
    return "building part " + q + " cannot be inside a floor or division";
  }

  // ---- transitions ----
  void assign_storeys(int axiom) {
    std::vector<std::pair<int, std::pair<int, bool>>> stack{{axiom, {-1, false}}};
    while (!stack.empty()) {
      const auto [index, state] = stack.back();
      stack.pop_back();
      Node& node = nodes_[static_cast<std::size_t>(index)];
      int storey = state.first;
      bool disposable = state.second;
      if (node.fn == Fn::kRoom) {
        node.storey = storey;
        node.in_disposable = disposable;
      }
      if (node.fn == Fn::kBuildingPart) disposable = node.number == 0;
      int floor_index = 0;
      for (const int c : node.children) {
        const Fn fn = nodes_[static_cast<std::size_t>(c)].fn;
        const int child_storey = fn == Fn::kFloor ? floor_index++ : storey;
        stack.push_back({c, {child_storey, disposable}});
      }
    }
  }

  void check_transitions() {
    for (Node& node : nodes_) {
      if (!is_transition(node.fn)) continue;
      std::vector<const Node*> rooms;
      for (const Value* target : node.targets) {
        const int index = lookup(target->text);
        if (index < 0) {
          error("BLD230",
                "transition " + quoted(node.rule->symbol.name) + " names unknown division " +
                    quoted(target->text),
                target->range);
          continue;
        }
        const Node& room = nodes_[static_cast<std::size_t>(index)];
        if (room.fn != Fn::kRoom) {
          if (room.fn != Fn::kUnknown) {
            error("BLD231",
                  "transition " + quoted(node.rule->symbol.name) + " names " +
                      quoted(target->text) + ", which is not a room",
                  target->range);
          }
          continue;
        }
        rooms.push_back(&room);
      }
      if (rooms.size() == 2 && node.targets.size() == 2) check_pair(node, *rooms[0], *rooms[1]);
    }
  }

  void check_pair(const Node& node, const Node& a, const Node& b) {
    const Range where = node.targets[1]->range;
    if (&a == &b) {
      error("BLD232",
            std::string(node.fn == Fn::kDoor ? "door " : "stair ") +
                quoted(node.rule->symbol.name) + " connects room " + quoted(a.rule->symbol.name) +
                " with itself",
            where);
      return;
    }
    if (a.storey < 0 || b.storey < 0) return;  // rooms outside the tree: reported already
    if (node.fn == Fn::kDoor && a.storey != b.storey) {
      error("BLD233",
            "door " + quoted(node.rule->symbol.name) + " joins rooms on storeys " +
                std::to_string(a.storey) + " and " + std::to_string(b.storey) +
                " (use 'stair' between storeys)",
            where);
    } else if (node.fn == Fn::kStair && b.storey != a.storey + 1) {
      error("BLD233",
            "stair " + quoted(node.rule->symbol.name) + " must go one storey up, from storey " +
                std::to_string(a.storey) + " to " + std::to_string(a.storey + 1) + ", but " +
                quoted(b.rule->symbol.name) + " is on storey " + std::to_string(b.storey),
            where);
    } else if (node.fn == Fn::kDoor && (a.in_disposable || b.in_disposable)) {
      warning("BLD240",
              "door " + quoted(node.rule->symbol.name) +
                  " leads into a disposable building part (height 0) and is ignored",
              node.rule->symbol.range);
    }
  }

  // ---- the model ----
  Building build(int axiom) {
    const Node& root = nodes_[static_cast<std::size_t>(axiom)];
    Building building;
    building.symbol = root.rule->symbol.name;
    building.name = root.building_name;
    building.where = location(root.rule->symbol.range);
    building.outline = root.outline;
    building.outline_file = root.outline_file;
    building.outline_feature = root.outline_feature;
    building.outline_where = root.outline_where;
    building.layout = part_node(root, building);
    building.layout.orientation = root.orientation;
    return building;
  }

  PartNode part_node(const Node& node, Building& building) {
    PartNode out;
    out.symbol = node.rule->symbol.name;
    out.where = location(node.rule->symbol.range);
    out.orientation = node.orientation;
    if (node.fn == Fn::kBuildingPart) {
      BuildingPart part;
      part.roof = node.roof;
      part.height = node.number;
      part.disposable = node.number == 0;
      out.part = part;
    }
    for (const int c : node.children) {
      const Node& child = nodes_[static_cast<std::size_t>(c)];
      if (is_transition(child.fn)) {
        building.transitions.push_back(transition(child));
      } else if (child.fn == Fn::kFloor) {
        out.part->floors.push_back(floor(child, building));
      } else {
        out.children.push_back(part_node(child, building));
      }
    }
    return out;
  }

  Floor floor(const Node& node, Building& building) {
    Floor out;
    out.symbol = node.rule->symbol.name;
    out.where = location(node.rule->symbol.range);
    out.height = node.number;
    out.layout = division(node, building);
    return out;
  }

  Division division(const Node& node, Building& building) {
    Division out;
    out.symbol = node.rule->symbol.name;
    out.where = location(node.rule->symbol.range);
    out.orientation = node.orientation;
    if (node.fn == Fn::kRoom) out.room = node.room;
    for (const int c : node.children) {
      const Node& child = nodes_[static_cast<std::size_t>(c)];
      if (is_transition(child.fn)) {
        building.transitions.push_back(transition(child));
      } else {
        out.children.push_back(division(child, building));
      }
    }
    return out;
  }

  Transition transition(const Node& node) const {
    Transition out;
    out.symbol = node.rule->symbol.name;
    out.where = location(node.rule->symbol.range);
    out.kind = node.fn == Fn::kDoor       ? TransitionKind::kDoor
               : node.fn == Fn::kEntrance ? TransitionKind::kEntrance
               : node.fn == Fn::kWindow   ? TransitionKind::kWindow
                                          : TransitionKind::kStair;
    out.from = node.targets.at(0)->text;
    if (node.targets.size() > 1) out.to = node.targets[1]->text;
    out.width = node.number;
    return out;
  }

  static constexpr std::size_t kMaxDepth = 256;

  struct Edge {
    int from;
    int to;
    const SymbolRef* ref;
  };

  const base::Source& source_;
  const std::vector<RuleSyntax>& rules_;
  std::vector<base::Diagnostic>& diags_;
  std::vector<Node> nodes_;
  std::map<std::string, int> symbols_;
  std::vector<Edge> edges_;
  std::vector<int> duplicates_;  // rules whose symbol was defined before
  std::vector<int> color_;       // 0 unvisited, 1 on the stack, 2 done
};

}  // namespace

base::Result<Building> parse_building(const base::Source& source) {
  SyntaxOutput syntax = parse_rules(source);
  std::vector<base::Diagnostic> diags = std::move(syntax.diagnostics);
  std::optional<Building> building;
  // A file with syntax errors is still moderated (the rules that parsed), so one run reports
  // the structure problems too; symbols of rules that failed to parse would all look undefined,
  // so undefined-symbol reports are dropped then.
  const bool syntax_errors = base::has_errors(diags);
  {
    std::vector<base::Diagnostic> checks;
    building = Moderator(source, syntax.rules, checks).run();
    for (base::Diagnostic& d : checks) {
      // With syntax errors rules are missing: keep only the checks of the rules that parsed
      // (functions, parameters, outlines, duplicate symbols), not the structure ones.
      if (syntax_errors && d.code > "BLD210") continue;
      diags.push_back(std::move(d));
    }
  }
  std::stable_sort(diags.begin(), diags.end(), [](const auto& a, const auto& b) {
    return std::pair(a.span.line, a.span.column) < std::pair(b.span.line, b.span.column);
  });
  if (diags.size() > static_cast<std::size_t>(kMaxErrors)) {
    const base::Span last = diags[kMaxErrors - 1].span;
    diags.resize(kMaxErrors);
    diags.push_back(base::Diagnostic::error("BLD108", "too many errors; giving up", last));
  }
  if (syntax_errors || !building || base::has_errors(diags)) {
    return base::Result<Building>::failure(std::move(diags));
  }
  return base::Result<Building>(std::move(*building), std::move(diags));
}

}  // namespace insula::lang::bldg
