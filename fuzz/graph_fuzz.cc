// libFuzzer target for the graph front-end (docs/graph-executor.md): the positioned JSON reader,
// the .graph.json reader, the checker and the executor (under small limits).
// For any bytes (read as a top-level graph whose subgraph files all hold the same bytes):
//   - read_graph() fails with at least one error, every diagnostic positioned (or naming its file
//     only for a failed subgraph file) with a G or W code, or succeeds with no error;
//   - check() is ok exactly when it reports no error, every diagnostic positioned and coded;
//   - when ok, every graph's two execution orders hold each active node once, indices are a
//     permutation, and a cyclic edge stays inside its strongly connected component;
//   - a run is ok exactly when it reports no error, every diagnostic positioned and coded, each
//     result entity once;
//   - a second read, check and run give the same diagnostics, order dump and result counts.
// Builds as fuzz/plasm_fuzz.cc: libFuzzer with clang and INSULA_FUZZ=ON, a replay main with
// INSULA_FUZZ_REPLAY; tests/lang/graph/graph_fuzz_replay_test.cc includes it with
// INSULA_FUZZ_NO_ENTRY.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "lang/graph/checker.h"
#include "lang/graph/executor.h"
#include "lang/graph/reader.h"

namespace insula::fuzz {

inline std::string graph_diagnostics_problem(const std::vector<base::Diagnostic>& diagnostics) {
  for (const base::Diagnostic& d : diagnostics) {
    if (d.message.empty()) return "empty diagnostic message";
    if (d.span.line == 0 || d.span.column == 0)
      return "diagnostic without a position: " + d.message;
    if (d.code.empty() || (d.code[0] != 'G' && d.code[0] != 'W'))
      return "unexpected diagnostic code " + d.code;
  }
  return {};
}

inline std::string order_problem(const lang::graph::CheckedGraph& g,
                                 const lang::graph::ExecutionOrder& order, bool encapsulated) {
  std::size_t active = 0;
  for (const lang::graph::CheckedNode& n : g.nodes) {
    if (!encapsulated || !n.node->standalone_only) ++active;
  }
  if (order.order.size() != active) return "an execution order misses or repeats a node";
  std::vector<bool> seen(g.nodes.size(), false);
  for (std::size_t i = 0; i < order.order.size(); ++i) {
    const std::size_t k = order.order[i];
    if (k >= g.nodes.size() || seen[k]) return "an execution order repeats a node";
    seen[k] = true;
    if (order.index[k] != i) return "execution indices disagree with the order";
  }
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    if (order.cyclic[e] &&
        order.component[g.edges[e].from_node] != order.component[g.edges[e].to_node])
      return "a cyclic edge leaves its component";
  }
  return {};
}

// A run under small limits: ok exactly when it reports no error, every diagnostic positioned
// and coded, every result entity once; the transcript gets its diagnostics and result counts.
inline std::string run_problem(const lang::graph::Document& document,
                               const lang::graph::CheckResult& checked, std::string& transcript) {
  lang::graph::RunOptions options;
  options.limits_cap = lang::graph::Limits{2000, 2000, 8};
  const lang::graph::RunResult run = lang::graph::run_graph(document, checked, options);
  for (const base::Diagnostic& d : run.diagnostics) transcript += base::render(d) + "\n";
  if (run.ok == base::has_errors(run.diagnostics)) return "run ok disagrees with its errors";
  if (const std::string p = graph_diagnostics_problem(run.diagnostics); !p.empty()) return p;
  std::vector<bool> seen(run.entities.size(), false);
  for (const lang::graph::ResultEntity& r : run.results) {
    if (r.entity >= seen.size() || seen[r.entity]) return "a result entity twice or unknown";
    seen[r.entity] = true;
  }
  transcript += std::to_string(run.results.size()) + " results, " +
                std::to_string(run.entities.size()) + " entities\n";
  return {};
}

// One read and check: the problem found, and the text that a second run must repeat.
inline std::string read_and_check(std::string_view bytes, std::string& transcript) {
  const base::Source source("fuzz.graph.json", std::string(bytes));
  const std::string text(bytes);
  const lang::graph::FileReader files = [&text](const std::string&, std::string& out,
                                                std::string&) {
    out = text;
    return true;
  };
  const base::Result<lang::graph::Document> doc = lang::graph::read_graph(source, files);
  for (const base::Diagnostic& d : doc.diagnostics()) transcript += base::render(d) + "\n";
  if (doc.ok() == base::has_errors(doc.diagnostics())) return "read ok disagrees with its errors";
  if (const std::string p = graph_diagnostics_problem(doc.diagnostics()); !p.empty()) return p;
  if (!doc.ok()) return {};
  const lang::graph::CheckResult checked = lang::graph::check(doc.value());
  for (const base::Diagnostic& d : checked.diagnostics) transcript += base::render(d) + "\n";
  if (checked.ok == base::has_errors(checked.diagnostics))
    return "check ok disagrees with its errors";
  if (const std::string p = graph_diagnostics_problem(checked.diagnostics); !p.empty()) return p;
  if (!checked.ok) return {};
  for (const lang::graph::CheckedGraph& g : checked.graphs) {
    if (const std::string p = order_problem(g, g.standalone, false); !p.empty()) return p;
    if (const std::string p = order_problem(g, g.encapsulated, true); !p.empty()) return p;
  }
  transcript += lang::graph::dump_order(doc.value(), checked);
  return run_problem(doc.value(), checked, transcript);
}

// Empty when every contract above holds for `bytes`, else what broke.
inline std::string check_graph(std::string_view bytes) {
  std::string first;
  if (const std::string p = read_and_check(bytes, first); !p.empty()) return p;
  std::string second;
  read_and_check(bytes, second);
  return first == second ? "" : "a second read and check differ";
}

}  // namespace insula::fuzz

#ifndef INSULA_FUZZ_NO_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      insula::fuzz::check_graph(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "graph_fuzz: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
#endif

#ifdef INSULA_FUZZ_REPLAY
#define INSULA_FUZZ_REPLAY_NAME "graph_fuzz_replay"
#define INSULA_FUZZ_REPLAY_RECURSIVE  // the test data nests its bad-input catalog
#include "replay_main.h"
#endif
