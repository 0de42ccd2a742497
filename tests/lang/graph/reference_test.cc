// docs/graph-nodes.md is generated from the node catalogue; this test fails when the committed
// page differs (regenerate with INSULA_REGENERATE=1).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lang/graph/catalogue.h"
#include "lang/graph/nodes.h"
#include "lang/graph/reference.h"

namespace insula::lang::graph {
namespace {

TEST(GraphReference, CommittedPageIsUpToDate) {
  const std::string path = std::string(INSULA_SOURCE_DIR) + "/docs/graph-nodes.md";
  const std::string expected = node_reference_markdown();
  if (std::getenv("INSULA_REGENERATE") != nullptr) {
    std::ofstream(path, std::ios::binary) << expected;
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), expected)
      << "docs/graph-nodes.md is out of date: run with INSULA_REGENERATE=1";
}

TEST(GraphReference, EveryRegistryOperationIsReachable) {
  for (const shape::Operation& op : shape::registry().operations()) {
    const std::vector<std::string> spellings = graph_spellings(op);
    ASSERT_FALSE(spellings.empty());
    EXPECT_EQ(spellings.back(), "shape.op op=\"" + op.name + "\"");
  }
  EXPECT_EQ(graph_spellings(*shape::registry().find("extrude")).front(), "shape.extrude");
}

}  // namespace
}  // namespace insula::lang::graph
