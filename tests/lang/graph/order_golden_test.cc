// Golden dumps of §9 steps 2-3 (cyclic edges, execution indices, strongly connected components)
// for the examples in examples/graph/ and a few test graphs; every example checks clean.
#include <gtest/gtest.h>

#include "test_util.h"

namespace insula::lang::graph {
namespace {

std::string dumped(const std::filesystem::path& folder, const std::string& name) {
  const auto checked = testing::read_and_check(folder, name);
  EXPECT_TRUE(checked.document.ok()) << testing::first_diagnostic(checked);
  if (!checked.document.ok()) return "";
  EXPECT_TRUE(checked.result.ok) << testing::first_diagnostic(checked);
  for (const base::Diagnostic& d : checked.result.diagnostics) ADD_FAILURE() << base::render(d);
  return dump_order(checked.document.value(), checked.result);
}

TEST(GraphOrder, ExamplesCheckCleanAndKeepTheirOrder) {
  const std::filesystem::path examples =
      std::filesystem::path(INSULA_SOURCE_DIR) / "examples/graph";
  for (const char* name : {"footprint_tiles.graph.json", "lot_subdivision.graph.json",
                           "street_houses.graph.json", "parts/house.graph.json"}) {
    SCOPED_TRACE(name);
    std::string golden = name;
    golden = golden.substr(golden.rfind('/') + 1);
    insula::test::expect_golden(testing::data_dir() / "golden" / (golden + ".order"),
                                dumped(examples, name));
  }
}

TEST(GraphOrder, TestGraphsKeepTheirOrder) {
  for (const char* name : {"two_cycles.graph.json", "self_loop.graph.json"}) {
    SCOPED_TRACE(name);
    insula::test::expect_golden(testing::data_dir() / "golden" / (std::string(name) + ".order"),
                                dumped(testing::data_dir(), name));
  }
}

// The count after a subdivision loop comes after every node of the loop (rule (a) of §9.3),
// although the plain topological order of the paper could put it between them.
TEST(GraphOrder, CountAfterALoopComesAfterTheWholeLoop) {
  const auto checked = testing::read_and_check(
      std::filesystem::path(INSULA_SOURCE_DIR) / "examples/graph", "lot_subdivision.graph.json");
  ASSERT_TRUE(checked.result.ok);
  const CheckedGraph& g = checked.result.graphs.front();
  const ExecutionOrder& order = g.standalone;
  const std::size_t count = *g.node("number");
  for (const char* looped : {"check", "cut"}) {
    const std::size_t k = *g.node(looped);
    EXPECT_TRUE(order.in_cycle[k]);
    EXPECT_LT(order.index[k], order.index[count]) << looped;
  }
  EXPECT_FALSE(order.in_cycle[count]);
  std::size_t cyclic = 0;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    if (order.cyclic[e]) {
      ++cyclic;
      EXPECT_EQ(g.edges[e].edge->text(), "cut.piece -> check.in");
    }
  }
  EXPECT_EQ(cyclic, 1U);
}

// standalone_only nodes are left out when the graph runs inside a subgraph node.
TEST(GraphOrder, EncapsulatedOrderDropsStandaloneSources) {
  const auto checked = testing::read_and_check(
      std::filesystem::path(INSULA_SOURCE_DIR) / "examples/graph", "street_houses.graph.json");
  ASSERT_TRUE(checked.result.ok);
  std::size_t house = 0;
  while (checked.document->graphs[house]->ref != "parts/house.graph.json") ++house;
  const CheckedGraph& g = checked.result.graphs[house];
  EXPECT_TRUE(g.used_as_subgraph);
  EXPECT_EQ(g.standalone.order.size(), 4U);
  EXPECT_EQ(g.encapsulated.order.size(), 3U);
  // The subgraph node's ports are the gates, typed from the ports inside.
  const CheckedGraph& top = checked.result.graphs[0];
  const CheckedNode& low = top.nodes[*top.node("low")];
  ASSERT_EQ(low.inputs.size(), 1U);
  EXPECT_EQ(low.inputs[0].name, "Lot");
  EXPECT_EQ(low.inputs[0].type, EntityType::kShape);
  ASSERT_EQ(low.outputs.size(), 2U);
  EXPECT_EQ(low.outputs[1].name, "Walls");
}

}  // namespace
}  // namespace insula::lang::graph
