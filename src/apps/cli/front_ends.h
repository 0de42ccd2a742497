// Entry points of the language front-ends behind `insula build` and `insula check`, one source file
// each (build_<front-end>.cc, check_<front-end>.cc), chosen by the input's extension.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "apps/cli/build_command.h"
#include "base/diagnostic.h"

namespace insula::cli {

// `insula build`: exit code (exit_codes.h); diagnostics already printed.
int build_cga(const BuildOptions& options);
int build_bldg(const BuildOptions& options);
int build_lua(const BuildOptions& options);
int build_plasm(const BuildOptions& options);
int build_graph(const BuildOptions& options);

// `insula check`: a one-line summary of what was checked, or nullopt when the input has errors
// (diagnostics already printed; warnings too unless `quiet`).
std::optional<std::string> check_cga(const base::Source& source, bool quiet);
// The same with `insula check --start SYMBOL` (empty: the grammar's own start symbol) and
// `--workspace DIR` (where imports and assets named "/Project/..." are found; empty: default).
std::optional<std::string> check_cga(const base::Source& source, bool quiet,
                                     const std::string& start, const std::string& workspace);
std::optional<std::string> check_bldg(const base::Source& source, bool quiet);
std::optional<std::string> check_lua(const base::Source& source, bool quiet);
std::optional<std::string> check_plasm(const base::Source& source, bool quiet);
std::optional<std::string> check_graph(const base::Source& source, bool quiet);

// Prints diagnostics rendered against `source` to stderr (warnings and notes only when !quiet).
void print_diagnostics(const std::vector<base::Diagnostic>& diagnostics, const base::Source& source,
                       bool quiet);

}  // namespace insula::cli
