#include "apps/studio/drawing.h"

#include "base/diagnostic.h"
#include "lang/bldg/parser.h"
#include "lang/bldg/printer.h"

namespace insula::studio {
namespace {

namespace bldg = lang::bldg;
using Json = nlohmann::json;

Json ring_json(const kernel::Ring& ring) {
  Json points = Json::array();
  for (const kernel::Vec2& p : ring) points.push_back({p.x, p.y});
  return points;
}

Json division_json(const bldg::Division& division) {
  Json out = {{"symbol", division.symbol}};
  if (division.room) {
    const bldg::Room& room = *division.room;
    out["kind"] = "room";
    out["type"] = room.type;
    out["size"] = bldg::size_name(room.size);
    out["walls"] = room.walls;
    out["windows"] = room.windows;
    out["entrance"] = room.entrance;
    return out;
  }
  out["kind"] = "divisions";
  out["orientation"] = bldg::orientation_name(division.orientation);
  out["children"] = Json::array();
  for (const bldg::Division& child : division.children) {
    out["children"].push_back(division_json(child));
  }
  return out;
}

Json part_json(const bldg::PartNode& node) {
  Json out = {{"symbol", node.symbol}};
  if (node.part) {
    const bldg::BuildingPart& part = *node.part;
    out["kind"] = "part";
    out["roof"] = bldg::roof_name(part.roof);
    out["roof_height"] = part.disposable ? 0.0 : part.height;
    out["disposable"] = part.disposable;
    out["floors"] = Json::array();
    for (const bldg::Floor& floor : part.floors) {
      Json children = Json::array();
      for (const bldg::Division& d : floor.layout.children) children.push_back(division_json(d));
      out["floors"].push_back({{"symbol", floor.symbol},
                               {"height", floor.height},
                               {"orientation", bldg::orientation_name(floor.layout.orientation)},
                               {"children", children}});
    }
    return out;
  }
  out["kind"] = "parts";
  out["orientation"] = bldg::orientation_name(node.orientation);
  out["children"] = Json::array();
  for (const bldg::PartNode& child : node.children) out["children"].push_back(part_json(child));
  return out;
}

Json transition_json(const bldg::Transition& t) {
  return {{"symbol", t.symbol},
          {"kind", bldg::transition_name(t.kind)},
          {"from", t.from},
          {"to", t.to},
          {"width", t.width}};
}

}  // namespace

Json drawing_json(const std::string& file_name, const std::string& text) {
  const base::Source source(file_name, text);
  const base::Result<bldg::Building> parsed = bldg::parse_building(source);
  if (!parsed) {
    Json diagnostics = Json::array();
    for (const base::Diagnostic& d : parsed.diagnostics()) {
      if (d.severity == base::Severity::kError) diagnostics.push_back(base::render(d));
    }
    return {{"ok", false}, {"diagnostics", diagnostics}};
  }
  const bldg::Building& b = parsed.value();
  Json holes = Json::array();
  for (const kernel::Ring& hole : b.outline.holes) holes.push_back(ring_json(hole));
  Json transitions = Json::array();
  for (const bldg::Transition& t : b.transitions) transitions.push_back(transition_json(t));
  Json footprint = nullptr;
  if (!b.outline_file.empty()) {
    footprint = {{"file", b.outline_file}, {"feature", b.outline_feature}};
  }
  // The building's own children are its root container's (the axiom's orientation is its own).
  Json parts = part_json(b.layout);
  parts["symbol"] = b.symbol;
  return {{"ok", true},
          {"building",
           {{"symbol", b.symbol},
            {"name", b.name},
            {"outline", ring_json(b.outline.outer)},
            {"holes", holes},
            {"footprint", footprint},
            {"parts", parts},
            {"transitions", transitions}}}};
}

}  // namespace insula::studio
