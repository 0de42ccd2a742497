// Attribute and flow-control nodes (graph-format.md §11 "Attributes and flow control").
#include <gtest/gtest.h>

#include <map>

#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

// Values apply in file order: a later value reads an earlier one's result, and writes replace.
TEST(FlowNodes, SetInOrder) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "a": { "type": "number", "default": 1 }, "b": { "type": "number", "default": 0 },
                    "s": { "type": "string", "default": "" } },
    "nodes": [ { "id": "e", "type": "create.entity" },
               { "id": "first", "type": "attr.set", "params": { "values": { "a": 5 } } },
               { "id": "set", "type": "attr.set",
                 "params": { "values": { "b": "= @a * 10", "a": "= @b + 1", "s": "= str(@a)" } } } ],
    "edges": [ "e.out -> first.in", "first.out -> set.in" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const EntityId e = t.at("set.out").at(0);
  EXPECT_DOUBLE_EQ(t.attribute(e, "b")->number(), 50.0);
  EXPECT_DOUBLE_EQ(t.attribute(e, "a")->number(), 51.0);
  EXPECT_EQ(t.attribute(e, "s")->text(), "51");
}

// A value of the wrong type for its attribute stops the run (G052).
TEST(FlowNodes, SetTypeError) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "n": { "type": "integer", "default": 1 } },
    "nodes": [ { "id": "e", "type": "create.entity" },
               { "id": "set", "type": "attr.set", "params": { "values": { "n": "= 1.5 * @n" } } } ],
    "edges": [ "e.out -> set.in" ])json"));
  ASSERT_FALSE(t.ok());
  EXPECT_TRUE(
      t.says("test.graph.json:4:24: error[G052]: attribute 'n' is integer; the node gives "
             "number 1.5 (node 'set')"))
      << t.errors;
}

TEST(FlowNodes, TransferFromThePairedEntity) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "h": { "type": "number", "default": 0 }, "k": { "type": "integer", "default": 9 } },
    "nodes": [ { "id": "cells", "type": "create.grid",
                 "params": { "columns": 2, "rows": 1, "cell_width": 1, "cell_depth": 1 } },
               { "id": "src", "type": "create.entity", "params": { "count": 2 }, "attributes": { "index": "k" } },
               { "id": "h", "type": "attr.set", "params": { "values": { "h": "= 3 + @k" } } },
               { "id": "take", "type": "attr.transfer", "params": { "names": ["h"] } } ],
    "edges": [ "cells.out -> take.in", "src.out -> h.in", "h.out -> take.from" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("take.out");
  ASSERT_EQ(out.size(), 2U);
  EXPECT_DOUBLE_EQ(t.attribute(out[0], "h")->number(), 3.0);
  EXPECT_DOUBLE_EQ(t.attribute(out[1], "h")->number(), 4.0);
  EXPECT_EQ(t.attribute(out[1], "k"), nullptr);  // not named: not copied
  EXPECT_EQ(t.entity(out[0]).type, EntityType::kShape);
}

TEST(FlowNodes, ConditionAndSwitch) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "i": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "e", "type": "create.entity", "params": { "count": 6 }, "attributes": { "index": "i" } },
               { "id": "odd", "type": "flow.condition", "params": { "if": "= @i % 2 == 1" } },
               { "id": "pick", "type": "flow.switch",
                 "augment": [ { "if": "= @i < 2", "out": "low" }, { "if": "= @i < 4", "out": "mid" },
                              { "if": "= @i == 0", "out": "never" } ] } ],
    "edges": [ "e.out -> odd.in", "e.out -> pick.in" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const auto ids = [&](const std::string& port) {
    std::vector<std::int64_t> out;
    for (EntityId e : t.at(port)) out.push_back(t.attribute(e, "i")->integer());
    return out;
  };
  using V = std::vector<std::int64_t>;
  EXPECT_EQ(ids("odd.true"), (V{1, 3, 5}));
  EXPECT_EQ(ids("odd.false"), (V{0, 2, 4}));
  EXPECT_EQ(ids("pick.low"), (V{0, 1}));
  EXPECT_EQ(ids("pick.mid"), (V{2, 3}));
  EXPECT_TRUE(ids("pick.never").empty());
  EXPECT_EQ(ids("pick.else"), (V{4, 5}));
}

// Weighted, from each entity's own stream: deterministic, a zero weight never chosen, all
// zero weights a W040 failure.
TEST(FlowNodes, Stochastic) {
  const auto run = [](const std::string& weights, int seed) {
    return run_text(graph_text(R"json(
      "attributes": { "i": { "type": "integer", "default": -1 } },
      "nodes": [ { "id": "e", "type": "create.entity", "params": { "count": 400 }, "attributes": { "index": "i" } },
                 { "id": "pick", "type": "flow.stochastic", "params": { "seed": )json" +
                               std::to_string(seed) + R"json( }, "augment": )json" + weights +
                               R"json( } ],
      "edges": [ "e.out -> pick.in" ])json"));
  };
  const std::string weights =
      R"([ { "weight": 1, "out": "a" }, { "weight": 0, "out": "b" }, { "weight": 3, "out": "c" } ])";
  const TestRun t = run(weights, 0);
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_TRUE(t.at("pick.b").empty());
  const std::size_t a = t.at("pick.a").size();
  EXPECT_EQ(a + t.at("pick.c").size(), 400U);
  EXPECT_GT(a, 70U);  // 100 expected; 70 is more than 5 standard deviations (8.7) below
  EXPECT_LT(a, 130U);
  const TestRun again = run(weights, 0);
  EXPECT_EQ(again.at("pick.a"), t.at("pick.a"));
  const TestRun other = run(weights, 1);
  EXPECT_NE(other.at("pick.a"), t.at("pick.a"));
  const TestRun zero = run(R"([ { "weight": 0, "out": "a" }, { "weight": 0, "out": "b" } ])", 0);
  ASSERT_TRUE(zero.ok()) << zero.errors;
  EXPECT_EQ(zero.failed("pick"), 400U);
  EXPECT_TRUE(
      zero.says("warning[W040]: node 'pick': 400 entities dropped; every branch weight is 0"))
      << zero.errors;
}

// Copies carry their number; count 0 discards (nothing failed, nothing left).
TEST(FlowNodes, Copy) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "c": { "type": "integer", "default": -1 }, "i": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "e", "type": "create.entity", "params": { "count": 2 }, "attributes": { "index": "i" } },
               { "id": "three", "type": "flow.copy", "params": { "count": "= 3 - @i" }, "attributes": { "copy": "c" } },
               { "id": "none", "type": "flow.copy", "params": { "count": 0 } } ],
    "edges": [ "e.out -> three.in", "e.out -> none.in" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  std::vector<std::pair<std::int64_t, std::int64_t>> got;
  for (EntityId e : t.at("three.out"))
    got.emplace_back(t.attribute(e, "i")->integer(), t.attribute(e, "c")->integer());
  EXPECT_EQ(got, (std::vector<std::pair<std::int64_t, std::int64_t>>{
                     {0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}}));
  EXPECT_TRUE(t.at("none.out").empty());
  EXPECT_TRUE(t.run->failed.empty());
  EXPECT_TRUE(t.run->unprocessed.empty());
  EXPECT_EQ(t.runs("none").rounds, 2U);
}

}  // namespace
}  // namespace insula::lang::graph::testing
