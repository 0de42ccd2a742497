// Which graphs a city can run a few lots at a time (lang/graph/per_lot.h): one create.lots reading
// --lot, every node fed from it, none relating entities to each other.
#include "lang/graph/per_lot.h"

#include <gtest/gtest.h>

#include <string>

#include "run_util.h"
#include "test_util.h"

namespace insula::lang::graph::testing {
namespace {

// The obstacle per_lot_obstacle finds in a graph of `nodes` and `edges` (JSON members' text).
std::string obstacle(const std::string& nodes, const std::string& edges) {
  const base::Source source("test.graph.json", graph_text(R"("nodes": [ )" + nodes +
                                                          R"( ], "edges": [ )" + edges + " ]"));
  base::Result<Document> document = read_graph(source, folder_reader(data_dir()));
  EXPECT_TRUE(document.ok());
  if (!document.ok()) return "unreadable";
  const CheckResult checked = check(document.value());
  std::string errors;
  for (const base::Diagnostic& d : checked.diagnostics) errors += base::render(d) + "\n";
  EXPECT_TRUE(checked.ok) << errors;
  return per_lot_obstacle(checked);
}

constexpr const char* kLots = R"({ "id": "lots", "type": "create.lots" })";
constexpr const char* kMass =
    R"({ "id": "mass", "type": "shape.extrude", "params": { "height": 9 } })";

TEST(PerLot, AChainFromTheLotsIsPerLot) {
  EXPECT_EQ(obstacle(std::string(kLots) + ", " + kMass + R"(,
      { "id": "faces", "type": "shape.comp",
        "augment": [ { "faces": "top", "out": "top" }, { "faces": "side", "out": "walls" } ] },
      { "id": "roof", "type": "shape.roof", "params": { "type": "hip", "pitch": 30 } },
      { "id": "pick", "type": "flow.stochastic", "augment": [ { "weight": 1 }, { "weight": 2 } ] })",
                     R"("lots.out -> mass.in", "mass.out -> faces.in", "faces.top -> roof.in",
                        "faces.walls -> pick.in")"),
            "");
}

TEST(PerLot, WhatRelatesLotsOrMakesEntitiesIsNot) {
  EXPECT_EQ(obstacle(std::string(R"({ "id": "r", "type": "create.rectangle",
                                        "params": { "width": 9, "depth": 9 } }, )") +
                         kMass,
                     R"("r.out -> mass.in")"),
            "no create.lots node");
  EXPECT_EQ(obstacle(std::string(kLots) + R"(, { "id": "more", "type": "create.lots" })", ""),
            "more than one create.lots node");
  EXPECT_EQ(
      obstacle(R"({ "id": "lots", "type": "create.lots", "params": { "file": "a.geojson" } })", ""),
      "node 'lots' (create.lots) reads its own file, not --lot");
  EXPECT_EQ(obstacle(std::string(kLots) + R"(, { "id": "n", "type": "list.count" })",
                     R"("lots.out -> n.in")"),
            "node 'n' (list.count) is a list node");
  EXPECT_EQ(obstacle(std::string(kLots) + R"(, { "id": "ground", "type": "create.rectangle",
                                                 "params": { "width": 9, "depth": 9 } })",
                     ""),
            "node 'ground' (create.rectangle) is a creation node");
  EXPECT_EQ(
      obstacle(
          std::string(kLots) + ", " + kMass + R"(, { "id": "see", "type": "query.occlusion" })",
          R"("lots.out -> mass.in", "mass.out -> see.shapes", "mass.out -> see.occluders")"),
      "node 'see' (query.occlusion) is a query node");
  EXPECT_EQ(obstacle(std::string(kLots) + R"(, { "id": "lamp", "type": "light.create" })",
                     R"("lots.out -> lamp.in")"),
            "node 'lamp' (light.create) makes lights, which 3D Tiles do not carry");
}

}  // namespace
}  // namespace insula::lang::graph::testing
