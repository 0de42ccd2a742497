// Shared between bind_geometry.cc and bind_geometry_elements.cc (luageom's binding files).
#pragma once

#include <vector>

#include "lang/lua/binding.h"
#include "shape/component_ops.h"

namespace insula::lua {

// A constraint from snap()/repel() or a list of them at `arg` (nil: none).
std::vector<shape::Constraint> check_constraints(lua_State* L, int arg, const char* op);
// door, window, solidGeometry, place.
void register_element_bindings(Api& api);

}  // namespace insula::lua
