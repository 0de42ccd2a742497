// Helpers of the graph front-end's tests: a FileReader over a folder (as the CLI's, without its
// symbolic-link checks) and the first diagnostic of reading and checking a file.
#pragma once

#include <filesystem>
#include <string>

#include "../../common/test_util.h"
#include "base/diagnostic.h"
#include "lang/graph/checker.h"
#include "lang/graph/reader.h"

namespace insula::lang::graph::testing {

inline std::filesystem::path data_dir() {
  return std::filesystem::path(INSULA_TEST_DATA) / "graph";
}

inline FileReader folder_reader(const std::filesystem::path& folder) {
  return [folder](const std::string& path, std::string& text, std::string& error) {
    if (!std::filesystem::is_regular_file(folder / path)) {
      error = "no such file";
      return false;
    }
    text = insula::test::read_file(folder / path);
    return true;
  };
}

struct Checked {
  base::Result<Document> document;
  CheckResult result;
};

// Reads `name` (a path relative to `folder`, as diagnostics will show it) and checks it.
inline Checked read_and_check(const std::filesystem::path& folder, const std::string& name) {
  const base::Source source(name, insula::test::read_file(folder / name));
  Checked out{read_graph(source, folder_reader(folder)), {}};
  if (out.document.ok()) out.result = check(out.document.value());
  return out;
}

// The first diagnostic, rendered without source lines: `file:line:col: error[CODE]: message`
// and its notes.
inline std::string first_diagnostic(const Checked& checked) {
  const auto& read = checked.document.diagnostics();
  if (!read.empty()) return base::render(read.front());
  if (!checked.result.diagnostics.empty()) return base::render(checked.result.diagnostics.front());
  return "";
}

}  // namespace insula::lang::graph::testing
