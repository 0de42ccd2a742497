// Private to the Lua front-end's own files (runtime.cc, binding.cc, bind_*.cc of luacore): handle
// types for faces and regions, component sets, and the registration entry points.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "lang/lua/binding.h"

namespace insula::lua {

// Set by connect() on the component it placed elsewhere (seed 001 §3.4.2: the source is moved);
// collect_program leaves such parts out.
inline constexpr const char* kConnectedAttribute = "insula_connected";

// Metatables, the component cache and every binding family; then `insula` and the globals.
void open_bindings(lua_State* L);
// print(): one line to Program::print.
void print_line(lua_State* L, const char* text, std::size_t length);

// A face of a component's boundary (seed 001 §3.1.1), as fquery returns it.
struct FaceRef {
  shape::ShapeId id = shape::kNoShape;
  std::uint32_t face = 0;
};
inline constexpr const char* kFaceMeta = "insula.Face";
void push_face(lua_State* L, FaceRef face);
std::optional<FaceRef> to_face(lua_State* L, int arg);

// A region of a component (seed 001 §3.1.2), as region() and rquery return it.
struct RegionRef {
  shape::ShapeId id = shape::kNoShape;
  std::uint32_t index = 0;
};
inline constexpr const char* kRegionMeta = "insula.Region";
void push_region(lua_State* L, RegionRef region);
std::optional<RegionRef> to_region(lua_State* L, int arg);

// Arrays of faces or regions (plain tables).
template <typename T, typename Push>
int push_array(lua_State* L, const std::vector<T>& items, Push push) {
  lua_createtable(L, static_cast<int>(items.size()), 0);
  for (std::size_t i = 0; i < items.size(); ++i) {
    push(L, items[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

void register_component_bindings(Api& api);  // bind_core.cc
void register_query_bindings(Api& api);      // bind_query.cc
void register_ops_bindings(Api& api);        // bind_ops.cc
void register_region_bindings(Api& api);     // bind_region.cc

}  // namespace insula::lua
