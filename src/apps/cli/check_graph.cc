// `insula check FILE.graph.json` (graph_input.h reads and checks it).
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "apps/cli/asset_folders.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/graph_input.h"
#include "apps/cli/input_file.h"
#include "apps/cli/progress.h"
#include "apps/cli/warnings.h"
#include "lang/graph/checker.h"
#include "lang/graph/reader.h"

namespace insula::cli {

std::optional<LoadedGraph> load_graph(const base::Source& source, bool quiet) {
  namespace fs = std::filesystem;
  const fs::path own = fs::path(source.name()).parent_path();
  const std::string folder = own.empty() ? "." : own.string();
  LoadedGraph loaded;
  loaded.texts.emplace(source.name(), source);
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
    loaded.texts.emplace(shown, base::Source(shown, text));
    return true;
  };
  base::Result<lang::graph::Document> document = lang::graph::read_graph(source, files);
  loaded.print(document.diagnostics(), quiet);
  if (!document.ok()) return std::nullopt;
  loaded.document = std::make_unique<lang::graph::Document>(std::move(document.value()));
  loaded.checked = lang::graph::check(*loaded.document);
  loaded.print(loaded.checked.diagnostics, quiet);
  if (!loaded.checked.ok) return std::nullopt;
  return loaded;
}

std::string LoadedGraph::render(const base::Diagnostic& diagnostic) const {
  const auto it = texts.find(diagnostic.span.file);
  return base::render(diagnostic, it == texts.end() ? nullptr : &it->second);
}

void LoadedGraph::print(const std::vector<base::Diagnostic>& diagnostics, bool quiet) const {
  for (const base::Diagnostic& d : diagnostics) {
    const std::string text = render(d);
    if (d.severity == base::Severity::kError) {
      clear_progress_line();
      std::fprintf(stderr, "%s\n", text.c_str());
    } else {
      emit_warning(d.code, text, quiet);
    }
  }
}

std::optional<std::string> check_graph(const base::Source& source, bool quiet) {
  const std::optional<LoadedGraph> loaded = load_graph(source, quiet);
  if (!loaded) return std::nullopt;
  const lang::graph::CheckResult& checked = loaded->checked;
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

}  // namespace insula::cli
