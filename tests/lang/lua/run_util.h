// Shared by luacore's Lua tests: run a program and read its diagnostics and tree.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/lua/runtime.h"
#include "shape/query.h"

namespace insula::lua::testing {

struct Ran {
  std::unique_ptr<Runtime> runtime;
  std::vector<base::Diagnostic> diagnostics;
  std::vector<std::string> printed;

  bool ok() const { return diagnostics.empty(); }
  const shape::ShapeTree& tree() const { return runtime->tree(); }
  // `file:line:col: error[CODE]: message` of the first diagnostic ("" when none).
  std::string error() const {
    return diagnostics.empty() ? std::string() : base::render(diagnostics.front());
  }
  std::vector<shape::ShapeId> labelled(const std::string& label) const {
    std::vector<shape::ShapeId> out;
    for (shape::ShapeId id = 0; id < tree().size(); ++id) {
      if (tree().has_label(id, label)) out.push_back(id);
    }
    return out;
  }
};

inline Ran run(const std::string& code, RunOptions options = {}) {
  Ran r;
  auto* printed = &r.printed;
  options.print = [printed](const std::string& line) { printed->push_back(line); };
  r.runtime = std::make_unique<Runtime>(std::move(options));
  r.diagnostics = r.runtime->run(base::Source("test.lua", code));
  return r;
}

}  // namespace insula::lua::testing
