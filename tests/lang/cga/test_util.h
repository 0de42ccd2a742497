// Helpers shared by the CGA front-end tests.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "../../common/test_util.h"
#include "base/diagnostic.h"
#include "lang/cga/checker.h"
#include "lang/cga/parser.h"

namespace insula::lang::cga::testing {

inline std::filesystem::path data_dir() {
  return std::filesystem::path(INSULA_TEST_DATA) / "cga";
}

// Shared by every front-end (tests/common/test_util.h).
using insula::test::files_in;
using insula::test::read_file;

// The first diagnostic of parsing `text` as `name`, rendered without source lines; empty when
// the parse succeeded.
inline std::string first_error(const std::string& text, const std::string& name = "t.cga") {
  const base::Source source(name, text);
  const auto result = parse(source);
  if (result.ok() || result.diagnostics().empty()) return {};
  return base::render(result.diagnostics().front());
}

// The parse error, or else every diagnostic of checking `text` (as "t.cga"), one per line.
inline std::string check_text(const std::string& text) {
  const base::Source source("t.cga", text);
  base::Result<Grammar> g = parse(source);
  if (!g.ok()) return base::render(g.diagnostics().front()) + "\n";
  std::string out;
  for (const base::Diagnostic& d : check(g.value(), source).diagnostics) {
    out += base::render(d) + "\n";
  }
  return out;
}

}  // namespace insula::lang::cga::testing
