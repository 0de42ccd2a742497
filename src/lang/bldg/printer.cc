#include "lang/bldg/printer.h"

#include <map>
#include <set>

#include "base/format.h"

namespace insula::lang::bldg {
namespace {

bool is_identifier(const std::string& text) {
  if (text.empty()) return false;
  const auto start = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  };
  if (!start(text[0])) return false;
  for (const char c : text) {
    if (!start(c) && !(c >= '0' && c <= '9')) return false;
  }
  return true;
}

std::string number(double v) {
  return v == 0 ? "0" : base::shortest_number(v);  // -0 prints as 0
}

std::string string_literal(const std::string& text) {
  return base::quoted_string(text);
}

std::string name_literal(const std::string& text) {
  return is_identifier(text) ? text : string_literal(text);
}

std::string ring_literal(const kernel::Ring& ring) {
  std::string out = "[";
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (i > 0) out += ", ";
    // Appended piece by piece: GCC 12 -O3 reports a false -Wrestrict on "(" + std::string.
    out += '(';
    out += number(ring[i].x);
    out += ", ";
    out += number(ring[i].y);
    out += ')';
  }
  return out + "]";
}

class Printer {
 public:
  explicit Printer(const Building& building) : building_(building) {}

  std::string run() {
    collect_names(building_.layout);
    name_of_building_ = claim(building_.symbol, "building");
    std::vector<std::string> set;
    for (const PartNode& child : building_.layout.children) set.push_back(claim_part(child));
    for (const Transition& t : building_.transitions) {
      transition_names_.push_back(claim(t.symbol, transition_name(t.kind)));
      set.push_back(transition_names_.back());
    }
    out_ += "# " + string_literal(building_.name) +
            ": ontology-based building grammar (seed 000; docs/bldg-language.md)\n";
    out_ += name_of_building_ + " -> building(" + string_literal(building_.name) + ", " +
            outline() + orientation_suffix(building_.layout.orientation, true) + ")" +
            set_literal(set) + "\n";
    for (const PartNode& child : building_.layout.children) print_part(child);
    for (std::size_t i = 0; i < building_.transitions.size(); ++i) {
      print_transition(building_.transitions[i], transition_names_[i]);
    }
    return out_;
  }

 private:
  // Names as written are kept when they are identifiers and unique; the others get fresh names
  // in the order of printing, so the output does not depend on anything but the model.
  void collect_names(const PartNode& node) {
    taken_.insert(node.symbol);
    if (node.part) {
      for (const Floor& floor : node.part->floors) {
        taken_.insert(floor.symbol);
        for (const Division& d : floor.layout.children) collect_names(d);
      }
    }
    for (const PartNode& child : node.children) collect_names(child);
    for (const Transition& t : building_.transitions) taken_.insert(t.symbol);
  }
  void collect_names(const Division& division) {
    taken_.insert(division.symbol);
    for (const Division& child : division.children) collect_names(child);
  }

  std::string claim(const std::string& wanted, const std::string& prefix) {
    if (is_identifier(wanted) && used_.insert(wanted).second) return wanted;
    while (true) {
      std::string fresh = prefix + std::to_string(counter_[prefix]++);
      if (taken_.count(fresh) == 0 && used_.insert(fresh).second) return fresh;
    }
  }

  // Part and division names are claimed before printing so the building's set is known; the
  // recursive printers re-derive them from these maps.
  std::string claim_part(const PartNode& node) {
    const std::string name = claim(node.symbol, node.part ? "part" : "parts");
    part_names_[&node] = name;
    return name;
  }

  std::string outline() const {
    if (!building_.outline_file.empty()) {
      return "geojson(" + string_literal(building_.outline_file) + ", " +
             string_literal(building_.outline_feature) + ")";
    }
    std::string out = ring_literal(building_.outline.outer);
    for (const kernel::Ring& hole : building_.outline.holes) out += ", " + ring_literal(hole);
    return out;
  }

  static std::string orientation_suffix(Orientation orientation, bool comma) {
    if (orientation == Orientation::kAlternate) return "";
    return std::string(comma ? ", " : "") + orientation_name(orientation);
  }

  static std::string set_literal(const std::vector<std::string>& set) {
    std::string out = " : {";
    for (std::size_t i = 0; i < set.size(); ++i) out += (i > 0 ? ", " : "") + set[i];
    return out + "}";
  }

  void print_part(const PartNode& node) {
    const std::string& name = part_names_.at(&node);
    std::vector<std::string> set;
    if (node.part) {
      for (const Floor& floor : node.part->floors) {
        floor_names_[&floor] = claim(floor.symbol, "floor");
        set.push_back(floor_names_[&floor]);
      }
      const double height = node.part->disposable ? 0.0 : node.part->height;
      out_ += name + " -> buildingpart(" + roof_name(node.part->roof) + ", " + number(height) +
              ")" + set_literal(set) + "\n";
      for (const Floor& floor : node.part->floors) print_floor(floor);
      return;
    }
    for (const PartNode& child : node.children) set.push_back(claim_part(child));
    out_ += name + " -> buildingparts(" + orientation_suffix(node.orientation, false) + ")" +
            set_literal(set) + "\n";
    for (const PartNode& child : node.children) print_part(child);
  }

  void print_floor(const Floor& floor) {
    std::vector<std::string> set = claim_children(floor.layout);
    std::string args;
    if (floor.height != 0) args = number(floor.height);
    if (floor.layout.orientation != Orientation::kAlternate) {
      args += (args.empty() ? "" : ", ") + std::string(orientation_name(floor.layout.orientation));
    }
    out_ += floor_names_.at(&floor) + " -> floor(" + args + ")" + set_literal(set) + "\n";
    for (const Division& child : floor.layout.children) print_division(child);
  }

  std::vector<std::string> claim_children(const Division& division) {
    std::vector<std::string> set;
    for (const Division& child : division.children) {
      division_names_[&child] = claim(child.symbol, child.room ? "room" : "divisions");
      set.push_back(division_names_[&child]);
      // Transitions name a room by its written symbol, meaning its first definition (as the
      // moderator reads it); follow a renaming only when no room kept that symbol.
      if (child.room && child.symbol == division_names_[&child]) kept_.insert(child.symbol);
      if (child.room && child.symbol != division_names_[&child]) {
        renamed_.emplace(child.symbol, division_names_[&child]);
      }
    }
    return set;
  }

  void print_division(const Division& division) {
    const std::string& name = division_names_.at(&division);
    if (division.room) {
      const Room& room = *division.room;
      std::string args = name_literal(room.type) + ", " + size_name(room.size);
      if (room.walls != 0 || room.windows != 0 || room.entrance) {
        args += ", " + std::to_string(room.walls) + ", " + std::to_string(room.windows);
      }
      if (room.entrance) args += ", true";
      out_ += name + " -> room(" + args + ")\n";
      return;
    }
    const std::vector<std::string> set = claim_children(division);
    out_ += name + " -> divisions(" + orientation_suffix(division.orientation, false) + ")" +
            set_literal(set) + "\n";
    for (const Division& child : division.children) print_division(child);
  }

  std::string room_ref(const std::string& symbol) const {
    if (kept_.count(symbol)) return symbol;
    const auto it = renamed_.find(symbol);
    return it == renamed_.end() ? symbol : it->second;
  }

  void print_transition(const Transition& t, const std::string& name) {
    std::string args = room_ref(t.from);
    if (t.kind == TransitionKind::kDoor || t.kind == TransitionKind::kStair) {
      args += ", " + room_ref(t.to);
    }
    if (t.width != 0) args += ", " + number(t.width);
    out_ += name + " -> " + transition_name(t.kind) + "(" + args + ")\n";
  }

  const Building& building_;
  std::string out_;
  std::string name_of_building_;
  std::set<std::string> taken_;
  std::set<std::string> used_;
  std::map<std::string, int> counter_;
  std::map<const PartNode*, std::string> part_names_;
  std::map<const Floor*, std::string> floor_names_;
  std::map<const Division*, std::string> division_names_;
  std::multimap<std::string, std::string> renamed_;
  std::set<std::string> kept_;
  std::vector<std::string> transition_names_;
};

}  // namespace

std::string print_building(const Building& building) {
  return Printer(building).run();
}

const char* roof_name(RoofKind kind) {
  switch (kind) {
    case RoofKind::kFlat:
      return "Flat";
    case RoofKind::kPyramid:
      return "Pyramid";
    case RoofKind::kHip:
      return "Hip";
    case RoofKind::kMansard:
      return "Mansard";
    case RoofKind::kHoledMansard:
      return "HoledMansard";
    case RoofKind::kNone:
      return "None";
    case RoofKind::kGable:
      return "Gable";
    case RoofKind::kHipGlued:
      return "HipGlued";
  }
  return "Flat";
}

const char* orientation_name(Orientation orientation) {
  switch (orientation) {
    case Orientation::kHorizontal:
      return "horizontal";
    case Orientation::kVertical:
      return "vertical";
    case Orientation::kAlternate:
      return "alternate";
  }
  return "alternate";
}

const char* size_name(SizeLabel size) {
  switch (size) {
    case SizeLabel::kSmall:
      return "small";
    case SizeLabel::kMedium:
      return "medium";
    case SizeLabel::kBig:
      return "big";
  }
  return "medium";
}

const char* transition_name(TransitionKind kind) {
  switch (kind) {
    case TransitionKind::kDoor:
      return "door";
    case TransitionKind::kEntrance:
      return "entrance";
    case TransitionKind::kWindow:
      return "window";
    case TransitionKind::kStair:
      return "stair";
  }
  return "door";
}

}  // namespace insula::lang::bldg
