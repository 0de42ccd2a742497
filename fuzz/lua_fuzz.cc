// libFuzzer target for the Lua front-end (docs/lua-api.md): the bytes are a component program,
// run in the sandbox with small limits (so a loop or a huge repeat ends in a limit error within
// milliseconds) and a few in-memory OBJ assets. Beyond "no crash, no hang, no sanitizer report"
// it checks the runtime's contract on every input:
//  - Runtime::check and Runtime::run return at most one diagnostic, an error with a LUA code, a
//    message and a line inside the program (a syntax error from check is the same for run);
//  - a program that ran collects into a scene whose buildings' meshes index their own vertices.
//
// Builds as fuzz/geojson_fuzz.cc: libFuzzer with clang and INSULA_FUZZ=ON, a replay main with
// INSULA_FUZZ_REPLAY; tests/lang/lua/lua_fuzz_replay_test.cc includes it with
// INSULA_FUZZ_NO_ENTRY. fuzz/lua.dict lists the bindings' names for the mutator.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "io/obj_reader.h"
#include "lang/lua/runtime.h"
#include "shape/scene.h"

namespace insula::fuzz {

// A unit cube under the asset names of examples/lua/assets (and door01, box); any other name is
// missing.
class CubeAssets : public shape::AssetProvider {
 public:
  CubeAssets() {
    const std::string cube =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    auto mesh = io::read_obj(cube, "cube.obj");
    if (mesh.ok()) mesh_ = std::make_shared<const kernel::Mesh>(std::move(mesh.value()));
  }
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    for (const std::string_view known : {"balcony", "bed", "box", "chair", "desk", "door01", "lamp",
                                         "plant", "shelf", "sofa", "table", "wardrobe"}) {
      if (name == known) return mesh_;
    }
    error = "no asset '" + std::string(name) + "'";
    return nullptr;
  }

 private:
  std::shared_ptr<const kernel::Mesh> mesh_;
};

inline std::string check_one(const std::vector<base::Diagnostic>& diagnostics, std::size_t lines) {
  if (diagnostics.size() > 1) return "more than one diagnostic";
  for (const base::Diagnostic& d : diagnostics) {
    if (d.severity != base::Severity::kError) return "a diagnostic that is not an error";
    if (d.message.empty() || d.code.rfind("LUA", 0) != 0) return "bad code or empty message";
    if (d.span.line < 1 || d.span.line > lines + 1) return "diagnostic outside the program";
    if (base::render(d).empty()) return "empty rendering";
  }
  return {};
}

inline std::string check_scene(const shape::Scene& scene) {
  for (const shape::Building& b : scene.buildings) {
    for (const shape::Part& p : b.parts) {
      const std::size_t n = p.mesh.vertex_count();
      for (std::size_t f = 0; f < p.mesh.face_count(); ++f) {
        for (const std::uint32_t v : p.mesh.face(f)) {
          if (v >= n) return "face index out of range in part " + p.name;
        }
      }
    }
  }
  return {};
}

// Empty when the runtime kept its contract on `text`, else what broke.
inline std::string check_lua(std::string_view text) {
  const std::string owned(text);
  std::size_t lines = 1;
  for (const char c : owned) lines += c == '\n' ? 1 : 0;
  const base::Source source("fuzz.lua", owned);
  const std::vector<base::Diagnostic> syntax = lua::Runtime::check(source);
  if (std::string p = check_one(syntax, lines); !p.empty()) return "check: " + p;
  static const CubeAssets assets;
  lua::RunOptions options;
  options.seed = 7;
  options.assets = &assets;
  options.limits.instructions = 2'000'000;
  options.limits.memory_bytes = std::size_t{32} << 20;
  options.limits.call_depth = 100;
  options.limits.components = 20'000;
  lua::Runtime runtime(std::move(options));
  const std::vector<base::Diagnostic> ran = runtime.run(source);
  if (std::string p = check_one(ran, lines); !p.empty()) return "run: " + p;
  if (!syntax.empty() && (ran.empty() || base::render(ran[0]) != base::render(syntax[0]))) {
    return "run and check disagree on a syntax error";
  }
  if (!ran.empty()) return {};
  return check_scene(lua::collect_program(runtime.program()));
}

}  // namespace insula::fuzz

#ifndef INSULA_FUZZ_NO_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      insula::fuzz::check_lua(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "lua_fuzz: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
#endif

#ifdef INSULA_FUZZ_REPLAY
#define INSULA_FUZZ_REPLAY_NAME "lua_fuzz_replay"
#include "replay_main.h"
#endif
