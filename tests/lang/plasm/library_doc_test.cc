// docs/plasm-library.md is generated from the builtin table; this test fails when the committed
// page differs (regenerate with INSULA_REGENERATE=1).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lang/plasm/builtins.h"

namespace insula::lang::plasm {
namespace {

TEST(PlasmLibraryReference, CommittedPageIsUpToDate) {
  const std::string path = std::string(INSULA_SOURCE_DIR) + "/docs/plasm-library.md";
  const std::string expected = library_reference_markdown();
  if (std::getenv("INSULA_REGENERATE") != nullptr)
    std::ofstream(path, std::ios::binary) << expected;
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), expected)
      << "docs/plasm-library.md is out of date: run with INSULA_REGENERATE=1";
}

TEST(PlasmLibraryReference, EveryBuiltinHasARow) {
  const std::string page = library_reference_markdown();
  for (const Builtin& b : builtins())
    EXPECT_NE(page.find("| `" + std::string(b.name) + "` |"), std::string::npos) << b.name;
  // The checker checks the length of TRUNCONE's sequence; the page says so.
  EXPECT_NE(page.find("| `TRUNCONE` | a sequence of 3 | TRUNCONE:<r1, r2, h>:n"),
            std::string::npos);
}

}  // namespace
}  // namespace insula::lang::plasm
