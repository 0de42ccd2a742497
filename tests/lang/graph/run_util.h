// Running graphs written inline in tests: read (subgraph files from tests/data/graph), check and
// run a JSON text, with the diagnostics rendered and the result entities at hand.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lang/graph/executor.h"
#include "lang/graph/properties.h"
#include "test_util.h"

namespace insula::lang::graph::testing {

struct TestRun {
  std::unique_ptr<base::Source> source;
  std::unique_ptr<Document> document;
  CheckResult checked;
  std::unique_ptr<RunResult> run;
  std::string errors;  // every error and warning, rendered, one per line

  bool ok() const { return run != nullptr && run->ok; }
  // The result entities that left `port` ("node.port"), in order.
  std::vector<EntityId> at(const std::string& port) const {
    std::vector<EntityId> out;
    for (const ResultEntity& r : run->results) {
      if (r.port == port) out.push_back(r.entity);
    }
    return out;
  }
  double area(EntityId e) const { return measure(run->entities, run->tree, e).area; }
  double volume(EntityId e) const { return measure(run->entities, run->tree, e).volume; }
  shape::Scope scope(EntityId e) const { return *entity_scope(run->entities, run->tree, e); }
  const Entity& entity(EntityId e) const { return run->entities[e]; }
  // The node's execution counts (zero when it never ran).
  NodeRuns runs(const std::string& id) const {
    for (const auto& [node, n] : run->node_runs) {
      if (node == id) return n;
    }
    return {};
  }
  std::uint64_t failed(const std::string& node) const {
    const auto it = run->failed.find(node);
    return it == run->failed.end() ? 0 : it->second;
  }
  bool says(const std::string& text) const { return errors.find(text) != std::string::npos; }
  // The value of top-level attribute `name` stored on the entity or an ancestor, or null.
  const Value* attribute(EntityId e, const std::string& name) const {
    for (const auto& [key, n] : run->attribute_names) {
      if (n == name) return run->entities.attribute(e, key);
    }
    return nullptr;
  }
};

// A top-level graph of format version 1 around `body` (its members without braces).
inline std::string graph_text(const std::string& body) {
  return R"({"format": "insula-graph", "version": 1, )" + body + "}";
}

inline TestRun run_text(const std::string& json, RunOptions options = {}) {
  TestRun t;
  t.source = std::make_unique<base::Source>("test.graph.json", json);
  base::Result<Document> document = read_graph(*t.source, folder_reader(data_dir()));
  for (const base::Diagnostic& d : document.diagnostics()) t.errors += base::render(d) + "\n";
  if (!document.ok()) return t;
  t.document = std::make_unique<Document>(std::move(document.value()));
  t.checked = check(*t.document);
  for (const base::Diagnostic& d : t.checked.diagnostics) t.errors += base::render(d) + "\n";
  if (!t.checked.ok) return t;
  t.run = std::make_unique<RunResult>(run_graph(*t.document, t.checked, options));
  for (const base::Diagnostic& d : t.run->diagnostics) t.errors += base::render(d) + "\n";
  return t;
}

}  // namespace insula::lang::graph::testing
