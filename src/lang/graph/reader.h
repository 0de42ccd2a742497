// Reading `.graph.json` (docs/graph-executor.md, "Reading"): JSON with positions (json.h), the
// structure of §2-§8 (G001-G003 and G002's field checks, names), inline subgraphs (`#name`,
// innermost first) and subgraph files (G031, G032). The language layer reads no files itself:
// the app passes a FileReader.
#pragma once

#include <functional>
#include <string>

#include "base/diagnostic.h"
#include "lang/graph/model.h"

namespace insula::lang::graph {

// Fills `text` with the file at `path` (relative to the top-level graph's folder, normalized, never
// leading out of it), or returns false with `error` set to why not ("no such file").
using FileReader =
    std::function<bool(const std::string& path, std::string& text, std::string& error)>;

// Reads the graph in `source` and everything it reaches. Fails when any diagnostic is an error;
// every diagnostic names the file it is in, with notes naming the subgraph node that brought it.
base::Result<Document> read_graph(const base::Source& source, const FileReader& files);

// The notes that say where a graph is used: "in subgraph 'houseA' (parts/house.graph.json)",
// outermost last.
std::vector<std::string> graph_notes(const Document& document, const Graph& graph);

// True when `name` matches [A-Za-z_][A-Za-z0-9_]*.
bool valid_name(std::string_view name);

}  // namespace insula::lang::graph
