// The drawing tool's reading of a .bldg text (seed 000 §3.6; docs/studio.md "Drawing"): the
// building as the real parser and moderator read it, as JSON, so the page's tool shows exactly
// the tree the command line builds (comments, rule order, spelling and case do not matter).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace insula::studio {

// {"ok": true, "building": {...}} or {"ok": false, "diagnostics": ["file:line:col: error..."]}.
// The building: name, orientation, outline (outer ring), holes, footprint ({file, feature} or
// null), parts (the tree of part containers and building parts, each floor with its tree of
// division containers and rooms, every node with its symbol) and transitions.
nlohmann::json drawing_json(const std::string& file_name, const std::string& text);

}  // namespace insula::studio
