// `insula check FILE.graph.json`: reads a procedural content graph with its subgraph files (read
// from the graph's own folder tree only) and checks it (lang/graph: reader, catalogue, checker);
// diagnostics in subgraph files are shown against their own text. `insula build` on a graph says
// that the executor is not there yet.
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "apps/cli/asset_folders.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/input_file.h"
#include "apps/cli/progress.h"
#include "apps/cli/warnings.h"
#include "lang/graph/checker.h"
#include "lang/graph/reader.h"

namespace insula::cli {

std::optional<std::string> check_graph(const base::Source& source, bool quiet) {
  namespace fs = std::filesystem;
  const fs::path own = fs::path(source.name()).parent_path();
  const std::string folder = own.empty() ? "." : own.string();
  std::map<std::string, base::Source> texts;  // by the name diagnostics give
  texts.emplace(source.name(), source);
  const lang::graph::FileReader files = [&](const std::string& path, std::string& text,
                                            std::string& error) {
    std::string why;
    const std::optional<fs::path> found = find_in_folders({folder}, path, path, why);
    if (!found) {
      error = fs::exists(own / path) ? "it leads outside the graph's folder" : "no such file";
      return false;
    }
    const std::optional<std::string> bytes = read_input_file(found->string());
    if (!bytes) {
      error = read_failure_reason(found->string());
      return false;
    }
    text = *bytes;
    const std::string shown = (own / path).lexically_normal().generic_string();
    texts.emplace(shown, base::Source(shown, text));
    return true;
  };
  const auto print = [&](const std::vector<base::Diagnostic>& diagnostics) {
    for (const base::Diagnostic& d : diagnostics) {
      const auto it = texts.find(d.span.file);
      const std::string text = base::render(d, it == texts.end() ? nullptr : &it->second);
      if (d.severity == base::Severity::kError) {
        clear_progress_line();
        std::fprintf(stderr, "%s\n", text.c_str());
      } else {
        emit_warning(d.code, text, quiet);
      }
    }
  };
  const base::Result<lang::graph::Document> document = lang::graph::read_graph(source, files);
  print(document.diagnostics());
  if (!document.ok()) return std::nullopt;
  const lang::graph::CheckResult checked = lang::graph::check(document.value());
  print(checked.diagnostics);
  if (!checked.ok) return std::nullopt;
  std::size_t nodes = 0;
  std::size_t edges = 0;
  std::size_t cyclic = 0;
  for (const lang::graph::CheckedGraph& g : checked.graphs) {
    nodes += g.nodes.size();
    edges += g.edges.size();
    for (bool c : g.standalone.cyclic) cyclic += c ? 1 : 0;
  }
  const auto plural = [](std::size_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
  };
  return plural(checked.graphs.size(), "graph") + ", " + plural(nodes, "node") + ", " +
         plural(edges, "edge") + ", " + plural(cyclic, "cyclic edge");
}

int build_graph(const BuildOptions& options) {
  std::fprintf(stderr,
               "insula: %s: building graphs needs the graph executor, which comes in a later "
               "stage; `insula check %s` reads and checks the graph now\n",
               options.input.c_str(), options.input.c_str());
  return kExitInput;
}

}  // namespace insula::cli
