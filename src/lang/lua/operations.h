// The names under which Lua reaches the shape registry's operations (bind_ops.cc), and how they
// are written, for the reference page (docs/operations.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "shape/operation.h"

namespace insula::lua {

// The global function of registry operation `name`: the name itself, or name + "Split" for a Lua
// keyword (`repeat` is repeatSplit; insula["repeat"] also works).
std::string global_name(std::string_view name);

// "roof(c, type, pitch, overhang, mansard_pitch, break_height, {name=value, ...})".
std::vector<std::string> lua_spellings(const shape::Operation& op);

}  // namespace insula::lua
