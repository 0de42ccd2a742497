// List operation nodes (graph-format.md §11 "List operations"): collective, order-keeping unless
// they sort, node attributes through the mapping.
#include <gtest/gtest.h>

#include <algorithm>

#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

// Six cells 1 x (1 + i) with `g` = i % 3 (0 1 2 0 1 2), then `nodes` fed by `cells.out`.
std::string six(const std::string& nodes, const std::string& edges,
                const std::string& attributes = "") {
  return graph_text(R"(
    "attributes": { "g": { "type": "integer", "default": -1 }, "i": { "type": "integer", "default": -1 },
                    "n": { "type": "integer", "default": -1 } )" +
                    attributes + R"( },
    "nodes": [
      { "id": "grid", "type": "create.grid",
        "params": { "columns": 6, "rows": 1, "cell_width": 1, "cell_depth": 1 },
        "attributes": { "index": "i" } },
      { "id": "cells", "type": "actor.scale", "params": { "y": "= 1 + @i" } },
      { "id": "mod", "type": "attr.set", "params": { "values": { "g": "= @i % 3" } } }, )" +
                    nodes + R"( ],
    "edges": [ "grid.out -> cells.in", "cells.out -> mod.in", )" +
                    edges + "]");
}

std::vector<std::int64_t> ints(const TestRun& t, const std::string& port, const std::string& name) {
  std::vector<std::int64_t> out;
  for (EntityId e : t.at(port)) out.push_back(t.attribute(e, name)->integer());
  return out;
}

using V = std::vector<std::int64_t>;

TEST(ListNodes, Count) {
  const TestRun t = run_text(six(R"({ "id": "c", "type": "list.count",
                                      "attributes": { "index": "n", "count": "g" } })",
                                 R"("mod.out -> c.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(ints(t, "c.out", "n"), (V{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(ints(t, "c.out", "g"), (V{6, 6, 6, 6, 6, 6}));
  EXPECT_EQ(t.runs("c").executions, 1U);
}

TEST(ListNodes, AmountFilterWithAndWithoutBy) {
  const TestRun t = run_text(six(R"({ "id": "mid", "type": "list.amount_filter",
                                      "params": { "start": 1, "amount": 2 } },
                                    { "id": "first", "type": "list.amount_filter",
                                      "params": { "by": "= [@g]" } })",
                                 R"("mod.out -> mid.in", "mod.out -> first.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(ints(t, "mid.taken", "i"), (V{1, 2}));
  EXPECT_EQ(ints(t, "mid.rest", "i"), (V{0, 3, 4, 5}));
  EXPECT_EQ(ints(t, "first.taken", "i"), (V{0, 1, 2}));  // the first of each group
  EXPECT_EQ(ints(t, "first.rest", "i"), (V{3, 4, 5}));
}

// `g` descending, then area ascending; equal keys keep their arrival order.
TEST(ListNodes, OrderByTwoCriteriaStable) {
  const TestRun t = run_text(six(R"({ "id": "sort", "type": "list.order_by",
                                      "augment": [ { "value": "= @g", "descending": true },
                                                   { "value": "= -area() " } ] },
                                    { "id": "keep", "type": "list.order_by",
                                      "augment": [ { "value": "= @g" } ] })",
                                 R"("mod.out -> sort.in", "mod.out -> keep.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(ints(t, "sort.out", "i"), (V{5, 2, 4, 1, 3, 0}));
  EXPECT_EQ(ints(t, "keep.out", "i"), (V{0, 3, 1, 4, 2, 5}));
}

TEST(ListNodes, Reverse) {
  const TestRun t =
      run_text(six(R"({ "id": "r", "type": "list.reverse" })", R"("mod.out -> r.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(ints(t, "r.out", "i"), (V{5, 4, 3, 2, 1, 0}));
}

// A permutation, the same for the same seeds, another for another `seed`.
TEST(ListNodes, ShuffleIsADeterministicPermutation) {
  const auto order = [](int seed, std::uint64_t graph_seed) {
    RunOptions options;
    options.seed = graph_seed;
    const TestRun t = run_text(graph_text(R"(
      "attributes": { "i": { "type": "integer", "default": -1 } },
      "nodes": [ { "id": "e", "type": "create.entity", "params": { "count": 20 }, "attributes": { "index": "i" } },
                 { "id": "mix", "type": "list.shuffle", "params": { "seed": )" +
                                          std::to_string(seed) + R"( } } ],
      "edges": [ "e.out -> mix.in" ])"),
                               options);
    EXPECT_TRUE(t.ok()) << t.errors;
    return ints(t, "mix.out", "i");
  };
  const V a = order(0, 0);
  V sorted = a;
  std::sort(sorted.begin(), sorted.end());
  V identity(20);
  for (std::size_t k = 0; k < 20; ++k) identity[k] = static_cast<std::int64_t>(k);
  EXPECT_EQ(sorted, identity);
  EXPECT_NE(a, identity);
  EXPECT_EQ(a, order(0, 0));
  EXPECT_NE(a, order(1, 0));
  EXPECT_NE(a, order(0, 1));
}

TEST(ListNodes, AggregateOperationsAndGroups) {
  const std::string attrs = R"(, "r": { "type": "number", "default": 0 },
                               "k": { "type": "integer", "default": 0 },
                               "c": { "type": "vec3", "default": [0, 0, 0] })";
  const TestRun t = run_text(
      six(R"({ "id": "sum", "type": "list.aggregate", "params": { "value": "= @i", "op": "sum" },
               "attributes": { "result": "k" } },
             { "id": "avg", "type": "list.aggregate", "params": { "value": "= area() ", "op": "average", "by": "= [@g]" },
               "attributes": { "result": "r" } },
             { "id": "min", "type": "list.aggregate", "params": { "value": "= area() ", "op": "min", "by": "= [@g]" },
               "attributes": { "result": "r" } },
             { "id": "max", "type": "list.aggregate", "params": { "value": "= @i", "op": "max", "by": "= [@g == 0]" },
               "attributes": { "result": "k" } },
             { "id": "count", "type": "list.aggregate", "params": { "value": 0, "op": "count", "by": "= [@g > 0]" },
               "attributes": { "result": "k" } },
             { "id": "mid", "type": "list.aggregate", "params": { "value": "= pos() ", "op": "average" },
               "attributes": { "result": "c" } })",
          R"("mod.out -> sum.in", "mod.out -> avg.in", "mod.out -> min.in", "mod.out -> max.in",
             "mod.out -> count.in", "mod.out -> mid.in")",
          attrs));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(ints(t, "sum.out", "k"), (V{15, 15, 15, 15, 15, 15}));
  EXPECT_EQ(t.attribute(t.at("sum.out")[0], "k")->type(), ValueType::kInteger);
  std::vector<double> avg;
  for (EntityId e : t.at("avg.out")) avg.push_back(t.attribute(e, "r")->number());
  EXPECT_EQ(avg, (std::vector<double>{2.5, 3.5, 4.5, 2.5, 3.5, 4.5}));  // areas 1..6 by i % 3
  std::vector<double> min;
  for (EntityId e : t.at("min.out")) min.push_back(t.attribute(e, "r")->number());
  EXPECT_EQ(min, (std::vector<double>{1, 2, 3, 1, 2, 3}));
  EXPECT_EQ(ints(t, "max.out", "k"), (V{3, 5, 5, 3, 5, 5}));
  EXPECT_EQ(ints(t, "count.out", "k"), (V{2, 4, 4, 2, 4, 4}));
  // Centres (i + 0.5, (1 + i) / 2): the average of i is 2.5, of 1 + i 3.5.
  const kernel::Vec3 c = t.attribute(t.at("mid.out").at(0), "c")->vec();
  EXPECT_NEAR(c.x, 3.0, 1e-12);
  EXPECT_NEAR(c.y, 1.75, 1e-12);
}

// Integers are summed and compared exactly, past a double's 2^53; an overflow is G052.
TEST(ListNodes, AggregateIntegersExactly) {
  const std::string big =
      R"(, "big": { "type": "integer", "default": 0 }, "low": { "type": "integer", "default": 0 })";
  TestRun t = run_text(six(R"({ "id": "sum", "type": "list.aggregate",
                                "params": { "value": "= 9007199254740992 + @i", "op": "sum" },
                                "attributes": { "result": "big" } },
                              { "id": "min", "type": "list.aggregate",
                                "params": { "value": "= 9007199254740993 - @i * 2", "op": "min" },
                                "attributes": { "result": "low" } })",
                           R"("mod.out -> sum.in", "mod.out -> min.in")", big));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(t.attribute(t.at("sum.out").at(0), "big")->integer(), 54043195528445967);
  EXPECT_EQ(t.attribute(t.at("min.out").at(0), "low")->integer(), 9007199254740983);
  t = run_text(six(R"({ "id": "sum", "type": "list.aggregate",
                        "params": { "value": "= 4611686018427387904 + @i", "op": "sum" },
                        "attributes": { "result": "big" } })",
                   R"("mod.out -> sum.in")", big));
  ASSERT_FALSE(t.ok());
  EXPECT_TRUE(t.says("error[G052]: integer overflow in the sum of 'value' (node 'sum')"))
      << t.errors;
}

// Groups in order of first appearance with their size and the values their members share;
// ungrouping gives the members in order, with the group's later attributes.
TEST(ListNodes, GroupAndUngroup) {
  const TestRun t =
      run_text(six(R"({ "id": "by", "type": "list.group", "params": { "by": "= [@g]" },
                                      "attributes": { "size": "n" } },
                                    { "id": "mark", "type": "attr.set", "params": { "values": { "n": "= @n * 10" } } },
                                    { "id": "flat", "type": "list.ungroup" })",
                   R"("mod.out -> by.in", "by.out -> mark.in", "mark.out -> flat.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> members = t.at("flat.out");
  EXPECT_EQ(ints(t, "flat.out", "i"), (V{0, 3, 1, 4, 2, 5}));
  EXPECT_EQ(ints(t, "flat.out", "n"), (V{20, 20, 20, 20, 20, 20}));
  EXPECT_EQ(ints(t, "flat.out", "g"), (V{0, 0, 1, 1, 2, 2}));
  EXPECT_EQ(t.entity(members[0]).type, EntityType::kShape);
}

// A group's members leave as entities; one that is not a shape reaching a shape input is G052.
TEST(ListNodes, UngroupedPointIntoAShapeInput) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "p", "type": "create.points", "params": { "points": [[1, 2, 3]] } },
               { "id": "all", "type": "list.group" },
               { "id": "flat", "type": "list.ungroup" },
               { "id": "mass", "type": "shape.extrude", "params": { "height": 1 } } ],
    "edges": [ "p.out -> all.in", "all.out -> flat.in", "flat.out -> mass.in" ])"));
  ASSERT_FALSE(t.ok());
  EXPECT_TRUE(
      t.says("error[G052]: 'mass.in' accepts shape entities; a point entity arrived from "
             "'flat.out'"))
      << t.errors;
  // shape.comp would read the missing shape: the arrival check stops the run first.
  const TestRun comp = run_text(graph_text(R"(
    "nodes": [ { "id": "p", "type": "create.points", "params": { "points": [[1, 2, 3]] } },
               { "id": "all", "type": "list.group" },
               { "id": "flat", "type": "list.ungroup" },
               { "id": "faces", "type": "shape.comp", "augment": [ { "faces": "all" } ] } ],
    "edges": [ "p.out -> all.in", "all.out -> flat.in", "flat.out -> faces.in" ])"));
  EXPECT_TRUE(
      comp.says("error[G052]: 'faces.in' accepts shape entities; a point entity arrived "
                "from 'flat.out'"))
      << comp.errors;
}

}  // namespace
}  // namespace insula::lang::graph::testing
