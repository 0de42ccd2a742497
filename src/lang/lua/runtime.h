// Runs a Lua 5.4 component program (seed 001 §3.2: "a program composed of a series of
// statements", each pairing a query with operations) in a sandbox, growing a ShapeTree.
//
// Sandbox: the program is untrusted input. It sees only the base library without dofile,
// loadfile and bytecode loading (`load` is text-only), string (without string.dump), table, math
// (math.random and math.randomseed on the program's seeded generator) and utf8: no os, io,
// package, require, debug or coroutine. Assets (OBJ files) come only through the AssetProvider the
// caller plugs in (build_lua.cc restricts it to the --assets folders).
//
// Limits (docs/lua-api.md, "Limits"): instructions (a count hook), Lua heap memory (a capped
// allocator), call depth (a call/return hook) and components in the tree. Reaching one stops the
// program with `file:line:col: error[LUA1xx]: <limit> limit of N reached`; pcall cannot catch it.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/polygon.h"
#include "lang/lua/program.h"
#include "shape/operation.h"
#include "shape/scene.h"
#include "shape/value.h"

struct lua_State;

namespace insula::lua {

struct Limits {
  std::uint64_t instructions = 500'000'000;           // Lua VM instructions (about 5 s)
  std::size_t memory_bytes = std::size_t{512} << 20;  // Lua heap (geometry is not counted)
  int call_depth = 200;                               // nested Lua and C function calls
  std::size_t components = 5'000'000;                 // shapes in the tree
};

struct RunOptions {
  std::uint64_t seed = 0;
  Limits limits;
  const shape::AssetProvider* assets = nullptr;
  // --set name=value: the global table `params` (params.name), read by insula.param().
  std::vector<std::pair<std::string, shape::Value>> params;
  // A lot to build on (a graph's rule.lua node): a flat root from this footprint (local meters,
  // scope x along its first edge) in the global `lot` before the program runs; none: the
  // program makes its own roots.
  std::optional<kernel::Polygon> lot;
  // Where print() goes (one call per printed line, without the newline); null: discarded.
  std::function<void(const std::string&)> print;
};

// Statistics of a finished run.
struct RunStats {
  std::uint64_t instructions = 0;  // Lua VM instructions, rounded up to the next 100
  std::size_t peak_memory = 0;     // Lua heap bytes
  std::uint64_t operations = 0;    // operations run by bindings
};

class Runtime {
 public:
  explicit Runtime(RunOptions options);
  ~Runtime();
  Runtime(const Runtime&) = delete;
  Runtime& operator=(const Runtime&) = delete;

  // Compiles without running: syntax errors as diagnostics (code LUA001).
  static std::vector<base::Diagnostic> check(const base::Source& source);

  // Compiles and runs the program. On failure the returned diagnostics hold one error (the tree
  // keeps what was built up to then, for tests; build_lua.cc writes nothing).
  std::vector<base::Diagnostic> run(const base::Source& source);

  Program& program() { return *program_; }
  const shape::ShapeTree& tree() const { return program_->tree; }
  RunStats stats() const;
  lua_State* state() const { return L_; }

  struct Guard;  // allocator and hook state (runtime.cc)

 private:
  std::unique_ptr<Guard> guard_;  // allocator and hook state (before L_: destroyed last)
  std::unique_ptr<Program> program_;
  lua_State* L_ = nullptr;
  RunOptions options_;
};

// The export scene of a finished program (shape::collect over the leaves), without the asset
// templates that componentFromFile created only to be connected elsewhere.
shape::Scene collect_program(const Program& program);

}  // namespace insula::lua
