// Reading a `.graph.json` for `insula check` and `insula build`: the graph with its subgraph
// files (read from the graph's own folder tree only), checked (lang/graph reader, catalogue,
// checker); diagnostics in subgraph files are shown against their own text.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/graph/checker.h"
#include "lang/graph/model.h"

namespace insula::cli {

struct LoadedGraph {
  std::map<std::string, base::Source> texts;  // by the name diagnostics give
  std::unique_ptr<lang::graph::Document> document;
  lang::graph::CheckResult checked;
  // Prints diagnostics against the text of the file each names.
  void print(const std::vector<base::Diagnostic>& diagnostics, bool quiet) const;
  // One diagnostic as print() shows it.
  std::string render(const base::Diagnostic& diagnostic) const;
};

// nullopt when the graph has errors (printed; warnings too unless `quiet`).
std::optional<LoadedGraph> load_graph(const base::Source& source, bool quiet);

}  // namespace insula::cli
