// The execution model of graph-format.md §9 on small graphs: rounds, transfers, copies, blocked
// and leaf ports, cycles, limits, subgraphs and run-time diagnostics.
#include <gtest/gtest.h>

#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

std::string graph(const std::string& body) {
  return R"({"format": "insula-graph", "version": 1, )" + body + "}";
}

// §1's example: 5 faces at faces.rest, 4 floor strips at floors.out with `floor` 0..3.
TEST(Executor, FormatExample) {
  const TestRun t = run_text(graph(R"(
    "parameters": { "floor_height": { "type": "number", "default": 3, "min": 2 } },
    "attributes": { "floor": { "type": "integer", "default": -1 } },
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 20, "depth": 10 } },
      { "id": "mass", "type": "shape.extrude", "params": { "height": 12 } },
      { "id": "faces", "type": "shape.comp",
        "augment": [ { "faces": "front", "out": "facade" }, { "faces": "all", "out": "rest" } ] },
      { "id": "floors", "type": "shape.repeat", "params": { "axis": "y", "size": "= floor_height" },
        "attributes": { "index": "floor" } } ],
    "edges": [ "lot.out -> mass.in", "mass.out -> faces.in", "faces.facade -> floors.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(t.at("faces.rest").size(), 5U);
  const std::vector<EntityId> floors = t.at("floors.out");
  ASSERT_EQ(floors.size(), 4U);
  for (std::size_t i = 0; i < floors.size(); ++i) {
    EXPECT_DOUBLE_EQ(t.area(floors[i]), 60.0);
    ASSERT_NE(t.attribute(floors[i], "floor"), nullptr);
    EXPECT_EQ(t.attribute(floors[i], "floor")->integer(), static_cast<std::int64_t>(i));
  }
  // The front face's own floor attribute is never set: it reads the default.
  EXPECT_EQ(t.attribute(t.at("faces.rest").front(), "floor"), nullptr);
}

}  // namespace
}  // namespace insula::lang::graph::testing
