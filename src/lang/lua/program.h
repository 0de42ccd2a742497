// The state of one running Lua component program, without the Lua headers (so the CLI and tests
// can hold a Runtime without seeing lua.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shape/operation.h"
#include "shape/rng.h"
#include "shape/shape_tree.h"

namespace insula::lua {

// The state of one running program, reachable from any lua_State of it through program(L).
struct Program {
  shape::ShapeTree tree;
  // OBJ assets by name (build_lua.cc: io's OBJ reader restricted to the --assets folders); null
  // when the program may read no assets ("componentFromFile: no asset folders given").
  const shape::AssetProvider* assets = nullptr;
  // The program's random stream (math.random, and any random choice a binding makes that is not
  // tied to one component: e.g. connect() without a position; seed 001 §3.4.2). Seeded by --seed.
  shape::Rng rng{0};
  std::string file;  // the program's file name, as printed in diagnostics
  // Every operation a binding ran, for the report ("operations", as in seed 001 §5's table).
  std::uint64_t operations = 0;
  // Set when a limit stopped the program: pcall cannot catch it (the runtime re-raises
  // `stop_message`). Bindings that hit a limit call stop() (runtime.cc).
  bool stopped = false;
  void* runtime = nullptr;  // the runtime's private state (runtime.cc)
  // Where print() writes one line (null: nowhere).
  std::function<void(const std::string&)> print;
  std::string stop_message;
  std::size_t max_components = static_cast<std::size_t>(-1);  // Limits::components
  // Per-family state for bindings that remember facts beyond the tree (e.g. openings to cut at
  // solidGeometry time), keyed by family name; see extension<T>().
  std::vector<std::pair<std::string, std::shared_ptr<void>>> extensions;

  explicit Program(std::uint64_t seed) : tree(seed), rng(shape::mix64(seed ^ 0x1u)) {}
  // The state of family `name`, default-constructed on first use.
  template <typename T>
  T& extension(std::string_view name) {
    for (auto& [key, value] : extensions) {
      if (key == name) return *static_cast<T*>(value.get());
    }
    auto value = std::make_shared<T>();
    T& ref = *value;
    extensions.emplace_back(std::string(name), std::move(value));
    return ref;
  }
};

}  // namespace insula::lua
