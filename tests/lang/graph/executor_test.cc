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

namespace insula::lang::graph::testing {
namespace {

// A subdivision cycle (§3.5): halves until small enough; the count after the cycle runs once,
// on every piece (§9.3 rule (a)).
const char* kSubdivide = R"(
    "attributes": { "n": { "type": "integer", "default": -1 }, "of": { "type": "integer" } },
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 64, "depth": 64 } },
      { "id": "check", "type": "flow.condition", "params": { "if": "= area() > 100" } },
      { "id": "cut", "type": "shape.split", "params": { "axis": "x" },
        "augment": [ { "size": "'0.5", "out": "piece" }, { "size": "'0.5", "out": "piece" } ] },
      { "id": "number", "type": "list.count", "attributes": { "index": "n", "count": "of" } } ],
    "edges": [ "lot.out -> check.in", "check.true -> cut.in", "cut.piece -> check.in",
               "check.false -> number.in" ])";

TEST(Executor, CountAfterASubdivisionCycleRunsOnce) {
  const TestRun t = run_text(graph(kSubdivide));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> pieces = t.at("number.out");
  ASSERT_EQ(pieces.size(), 64U);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    EXPECT_DOUBLE_EQ(t.area(pieces[i]), 64.0);
    EXPECT_EQ(t.attribute(pieces[i], "n")->integer(), static_cast<std::int64_t>(i));
    EXPECT_EQ(t.attribute(pieces[i], "of")->integer(), 64);
  }
  const auto runs = [&](const std::string& id) {
    for (const auto& [node, n] : t.run->node_runs) {
      if (node == id) return n;
    }
    return NodeRuns{};
  };
  EXPECT_EQ(runs("number").executions, 1U);
  EXPECT_EQ(runs("number").rounds, 1U);
  EXPECT_EQ(runs("cut").rounds, 63U);     // 1 + 2 + ... + 32 splits
  EXPECT_EQ(runs("check").rounds, 127U);  // every piece is checked once
  ASSERT_EQ(t.run->cyclic_edges.size(), 1U);
  EXPECT_EQ(t.run->cyclic_edges[0], "cut.piece -> check.in");
}

TEST(Executor, MaxRoundsNamesTheCycle) {
  std::string body = kSubdivide;
  body += R"(, "limits": { "max_rounds": 50 })";
  const TestRun t = run_text(graph(body));
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.errors.find("error[G050]: graph did not finish within max_rounds = 50 node rounds; "
                          "entities still circulate in the cycle check -> cut -> check"),
            std::string::npos)
      << t.errors;
}

TEST(Executor, MaxEntities) {
  std::string body = kSubdivide;
  body += R"(, "limits": { "max_entities": 20 })";
  const TestRun t = run_text(graph(body));
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.errors.find("error[G051]: more than max_entities = 20 live entities"),
            std::string::npos)
      << t.errors;
}

// Divergence copies; a blocked output port discards; a blocked input port discards on arrival.
TEST(Executor, DivergenceAndBlockedPorts) {
  const TestRun t = run_text(graph(R"(
    "nodes": [
      { "id": "cells", "type": "create.grid",
        "params": { "columns": 3, "rows": 2, "cell_width": 10, "cell_depth": 5 } },
      { "id": "big", "type": "flow.condition", "params": { "if": "= pos().x > 10" },
        "ports": { "false": { "blocked": true } } },
      { "id": "a", "type": "shape.extrude", "params": { "height": 2 } },
      { "id": "b", "type": "shape.extrude", "params": { "height": 4 },
        "ports": { "in": { "blocked": true } } },
      { "id": "c", "type": "flow.copy", "params": { "count": 2 } } ],
    "edges": [ "cells.out -> big.in", "big.true -> a.in", "big.true -> b.in", "big.true -> c.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  // Cell centres at x = 5, 15, 25 in two rows: four pass.
  EXPECT_EQ(t.at("a.out").size(), 4U);
  for (EntityId e : t.at("a.out")) EXPECT_DOUBLE_EQ(t.volume(e), 100.0);
  EXPECT_EQ(t.at("c.out").size(), 8U);
  EXPECT_EQ(t.run->blocked.at("big.false"), 2U);
  EXPECT_EQ(t.run->blocked.at("b.in"), 4U);
  EXPECT_TRUE(t.at("b.out").empty());
}

// Two single ports are paired by arrival order; leftovers are W010.
TEST(Executor, UnprocessedEntitiesAreReported) {
  const TestRun t = run_text(graph(R"(
    "attributes": { "h": { "type": "number", "default": 0 } },
    "nodes": [
      { "id": "three", "type": "create.grid",
        "params": { "columns": 3, "rows": 1, "cell_width": 1, "cell_depth": 1 } },
      { "id": "two", "type": "create.entity", "params": { "count": 2 } },
      { "id": "take", "type": "attr.transfer", "params": { "names": ["h"] } } ],
    "edges": [ "three.out -> take.in", "two.out -> take.from" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(t.at("take.out").size(), 2U);
  EXPECT_EQ(t.run->unprocessed.at("take.in"), 1U);
  EXPECT_NE(t.errors.find("warning[W010]: 1 entity left unprocessed at 'take.in'"),
            std::string::npos)
      << t.errors;
}

// An expression error stops the run at the offending character of the file.
TEST(Executor, ExpressionErrorPointsIntoTheFile) {
  const std::string text = graph(R"json(
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
      { "id": "mass", "type": "shape.extrude", "params": { "height": "= 3 / (area() - 100)" } } ],
    "edges": [ "lot.out -> mass.in" ])json");
  const TestRun t = run_text(text);
  ASSERT_FALSE(t.ok());
  const std::size_t slash = text.find("/ (area");
  const base::Source source("test.graph.json", text);
  const auto [line, column] = source.locate(slash);
  EXPECT_NE(t.errors.find("test.graph.json:" + std::to_string(line) + ":" + std::to_string(column) +
                          ": error[G052]: division by zero"),
            std::string::npos)
      << t.errors;
}

// --set overrides a parameter, checked against its declaration.
TEST(Executor, SetOverridesParameters) {
  const std::string body = R"(
    "parameters": { "h": { "type": "number", "default": 3, "min": 1 } },
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
      { "id": "mass", "type": "shape.extrude", "params": { "height": "= h" } } ],
    "edges": [ "lot.out -> mass.in" ])";
  RunOptions options;
  options.sets = {{"h", "7"}};
  TestRun t = run_text(graph(body), options);
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_DOUBLE_EQ(t.volume(t.at("mass.out").front()), 700.0);
  options.sets = {{"h", "0.5"}};
  t = run_text(graph(body), options);
  EXPECT_NE(t.errors.find("error[G025]: parameter 'h' must be >= 1; got 0.5"), std::string::npos)
      << t.errors;
  options.sets = {{"hh", "2"}};
  t = run_text(graph(body), options);
  EXPECT_NE(t.errors.find("error[G021]: unknown graph parameter 'hh' (did you mean 'h'?)"),
            std::string::npos)
      << t.errors;
}

// The same seed gives the same random values; another seed others.
TEST(Executor, RandomnessFollowsTheSeed) {
  const std::string body = R"json(
    "attributes": { "r": { "type": "number", "default": 0 } },
    "nodes": [
      { "id": "cells", "type": "create.grid",
        "params": { "columns": 4, "rows": 1, "cell_width": 1, "cell_depth": 1 } },
      { "id": "roll", "type": "attr.set", "params": { "values": { "r": "= rand()" } } } ],
    "edges": [ "cells.out -> roll.in" ])json";
  const auto values = [&](std::uint64_t seed) {
    RunOptions options;
    options.seed = seed;
    const TestRun t = run_text(graph(body), options);
    std::vector<double> out;
    for (EntityId e : t.at("roll.out")) out.push_back(t.attribute(e, "r")->number());
    return out;
  };
  const std::vector<double> a = values(1);
  ASSERT_EQ(a.size(), 4U);
  EXPECT_EQ(a, values(1));
  EXPECT_NE(a, values(2));
  EXPECT_NE(a[0], a[1]);
}

}  // namespace
}  // namespace insula::lang::graph::testing

namespace insula::lang::graph::testing {
namespace {

// One inline subgraph used twice in a row (§8): parameters per use, attributes mapped in and
// out, the subgraph's own attributes gone when its entities leave, its standalone_only test
// source dropped, node runs keyed by the subgraph node.
TEST(Executor, SubgraphUsedTwiceScopesItsAttributes) {
  const TestRun t = run_text(graph(R"json(
    "attributes": { "total": { "type": "number", "default": 0 } },
    "subgraphs": {
      "step": {
        "parameters": { "h": { "type": "number", "default": 5 } },
        "attributes": { "height": { "type": "number", "default": 0 },
                        "tmp": { "type": "number", "default": 0, "public": false } },
        "gates": { "inputs": { "In": "mark.in" }, "outputs": { "Out": "mark.out" } },
        "nodes": [
          { "id": "test", "type": "create.rectangle", "params": { "width": 1, "depth": 1 },
            "standalone_only": true },
          { "id": "mark", "type": "attr.set",
            "params": { "values": { "tmp": "= @tmp + 1", "height": "= @height + h + @tmp * 100" } } } ],
        "edges": [ "test.out -> mark.in" ] } },
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
      { "id": "A", "type": "subgraph", "graph": "#step", "params": { "h": 3 },
        "attributes": { "height": "total" } },
      { "id": "B", "type": "subgraph", "graph": "#step", "params": { "h": 4 },
        "attributes": { "height": "total" } } ],
    "edges": [ "lot.out -> A.In", "A.Out -> B.In" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("B.Out");
  ASSERT_EQ(out.size(), 1U);
  EXPECT_DOUBLE_EQ(t.attribute(out[0], "total")->number(), 207.0);  // 3 + 100, then 4 + 100
  bool a_mark = false;
  for (const auto& [node, n] : t.run->node_runs)
    a_mark = a_mark || (node == "A/mark" && n.rounds == 1);
  EXPECT_TRUE(a_mark);
}

TEST(Executor, SubgraphNestingLimit) {
  const TestRun t = run_text(graph(R"json(
    "limits": { "max_subgraph_depth": 1 },
    "subgraphs": {
      "outer": {
        "gates": { "inputs": { "In": "inner.In" }, "outputs": { "Out": "inner.Out" } },
        "subgraphs": {
          "inner": {
            "gates": { "inputs": { "In": "pass.in" }, "outputs": { "Out": "pass.out" } },
            "nodes": [ { "id": "pass", "type": "flow.copy" } ] } },
        "nodes": [ { "id": "inner", "type": "subgraph", "graph": "#inner" } ] } },
    "nodes": [
      { "id": "lot", "type": "create.entity" },
      { "id": "wrap", "type": "subgraph", "graph": "#outer" } ],
    "edges": [ "lot.out -> wrap.In" ])json"));
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.errors.find("error[G053]: subgraph nesting deeper than max_subgraph_depth = 1"),
            std::string::npos)
      << t.errors;
  EXPECT_NE(t.errors.find("note: in subgraph 'wrap' (#outer)"), std::string::npos) << t.errors;
}

}  // namespace
}  // namespace insula::lang::graph::testing

namespace insula::lang::graph::testing {
namespace {

// §4: an entity output into a shape input is accepted at check time; a non-shape arriving stops
// the run with G052.
TEST(Executor, NarrowerInputChecksArrivals) {
  const TestRun t = run_text(graph(R"json(
    "nodes": [
      { "id": "carrier", "type": "create.entity" },
      { "id": "groups", "type": "list.group" },
      { "id": "members", "type": "list.ungroup" },
      { "id": "mass", "type": "shape.extrude", "params": { "height": 3 } } ],
    "edges": [ "carrier.out -> groups.in", "groups.out -> members.in", "members.out -> mass.in" ])json"));
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.errors.find("error[G052]: 'mass.in' accepts shape entities; an entity arrived from "
                          "'members.out'"),
            std::string::npos)
      << t.errors;
}

}  // namespace
}  // namespace insula::lang::graph::testing
