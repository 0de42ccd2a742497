// docs/operations.md is generated from the registry and the front-ends' spellings; this test
// fails when the committed page differs (regenerate with INSULA_REGENERATE=1).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lang/cga/operations.h"
#include "lang/graph/reference.h"
#include "lang/lua/operations.h"
#include "shape/operation.h"

namespace insula {
namespace {

std::string reference_page() {
  const shape::FrontEndSpellings front_ends[] = {
      {"CGA", lang::cga::cga_spellings},
      {"Lua", lua::lua_spellings},
      {"graph", lang::graph::graph_spellings},
  };
  return shape::operations_reference_markdown(front_ends);
}

TEST(OperationsReference, CommittedPageIsUpToDate) {
  const std::string path = std::string(INSULA_SOURCE_DIR) + "/docs/operations.md";
  const std::string expected = reference_page();
  if (std::getenv("INSULA_REGENERATE") != nullptr) {
    std::ofstream(path, std::ios::binary) << expected;
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), expected)
      << "docs/operations.md is out of date: run with INSULA_REGENERATE=1";
}

TEST(OperationsReference, EveryOperationHasACgaAndALuaSpelling) {
  for (const shape::Operation& op : shape::registry().operations()) {
    EXPECT_FALSE(lang::cga::cga_spellings(op).empty()) << op.name;
    EXPECT_FALSE(lua::lua_spellings(op).empty()) << op.name;
  }
  const std::string page = reference_page();
  EXPECT_NE(
      page.find("| `roof` | `roof(type, pitch, overhang, mansard_pitch, break_height, height, "
                "closed, thickness)`<br>`roofFlat(overhang, thickness, height, closed) "
                "type=flat`"),
      std::string::npos);
  EXPECT_NE(page.find("`repeatSplit(c, axis, size, {name=value, ...})`"), std::string::npos);
}

}  // namespace
}  // namespace insula
