// The node catalogue (§11), the entity type lattice (§10) and the positioned JSON reader.
#include <gtest/gtest.h>

#include <set>

#include "lang/graph/catalogue.h"
#include "lang/graph/json.h"
#include "shape/operation.h"
#include "test_util.h"

namespace insula::lang::graph {
namespace {

TEST(GraphCatalogue, HasEveryTypeOfTheFormatOnce) {
  std::set<std::string> names;
  for (const NodeType& t : catalogue()) EXPECT_TRUE(names.insert(t.name).second) << t.name;
  // 54 catalogue types (with `subgraph` the 55 executable types of §11, and `note`), the
  // four rule nodes Insula adds (docs/graph-executor.md, "Rule nodes") and the five terrain
  // nodes ("Terrain").
  EXPECT_EQ(names.size(), 63U);
  for (const char* name : {"create.lots", "shape.op", "path.to_shapes", "list.ungroup",
                           "query.is_oriented_to", "flow.stochastic", "texture.combine"}) {
    EXPECT_NE(find_node_type(name), nullptr) << name;
  }
}

TEST(GraphCatalogue, ShapeOperationsTakeTheRegistrysParameters) {
  std::size_t wrapped = 0;
  for (const NodeType& t : catalogue()) {
    if (t.registry_op.empty()) continue;
    ++wrapped;
    const shape::Operation* op = shape::registry().find(t.registry_op);
    ASSERT_NE(op, nullptr) << t.name;
    for (const shape::ParamDecl& d : op->params) {
      const ParamSpec* p = t.param(d.name);
      if (p == nullptr) continue;  // expressed by ports or augmentations (split sizes, comp)
      EXPECT_EQ(p->default_json.has_value(), d.default_value.has_value())
          << t.name << " " << d.name;
      EXPECT_EQ(p->min, d.min) << t.name << " " << d.name;
      EXPECT_EQ(p->choices, d.choices) << t.name << " " << d.name;
    }
  }
  EXPECT_EQ(wrapped, 11U);
  const NodeType* roof = find_node_type("shape.roof");
  ASSERT_NE(roof, nullptr);
  ASSERT_NE(roof->param("mansard_pitch"), nullptr);  // beyond §11's three: what CGA reaches
  EXPECT_EQ(*roof->param("pitch")->max, 89.0);
  EXPECT_EQ(find_node_type("shape.split")->param("sizes"), nullptr);
  EXPECT_EQ(find_node_type("shape.offset")->param("part"), nullptr);
}

TEST(GraphCatalogue, PortsAndAugmentations) {
  const NodeType* ray = find_node_type("query.ray_cast");
  ASSERT_EQ(ray->inputs.size(), 2U);
  EXPECT_EQ(ray->inputs[1].mode, PortMode::kCollective);
  EXPECT_EQ(ray->inputs[1].type, EntityType::kActor);
  EXPECT_TRUE(ray->collective());
  const NodeType* oriented = find_node_type("query.is_oriented_to");
  EXPECT_TRUE(oriented->inputs[2].optional);
  const NodeType* rect = find_node_type("create.rectangle");
  ASSERT_EQ(rect->inputs.size(), 1U);
  EXPECT_EQ(rect->inputs[0].name, "impulse");
  EXPECT_TRUE(rect->inputs[0].optional);
  EXPECT_EQ(find_node_type("attr.set")->inputs[0].mode, PortMode::kEither);
  EXPECT_TRUE(find_node_type("list.aggregate")->param("value")->per_entity);
  EXPECT_FALSE(find_node_type("list.aggregate")->param("op")->default_json.has_value());
  EXPECT_TRUE(find_node_type("shape.split")->augment("slice")->makes_ports);
  EXPECT_FALSE(find_node_type("list.order_by")->augment("criterion")->makes_ports);
  EXPECT_EQ(find_node_type("list.count")->writes, (std::vector<std::string>{"index", "count"}));
}

TEST(GraphTypes, Lattice) {
  EXPECT_TRUE(is_subtype(EntityType::kShape, EntityType::kActor));
  EXPECT_TRUE(is_subtype(EntityType::kLight, EntityType::kEntity));
  EXPECT_FALSE(is_subtype(EntityType::kTexture, EntityType::kActor));
  EXPECT_FALSE(is_subtype(EntityType::kActor, EntityType::kShape));
  EXPECT_EQ(common_supertype(EntityType::kShape, EntityType::kPath), EntityType::kActor);
  EXPECT_EQ(common_supertype(EntityType::kShape, EntityType::kGroup), EntityType::kEntity);
  EXPECT_EQ(common_supertype(EntityType::kPoint, EntityType::kPoint), EntityType::kPoint);
  EXPECT_TRUE(is_subtype(EntityType::kTerrain, EntityType::kActor));
  EXPECT_FALSE(is_subtype(EntityType::kTerrain, EntityType::kShape));
  EXPECT_EQ(common_supertype(EntityType::kTerrain, EntityType::kPath), EntityType::kActor);
  EXPECT_EQ(entity_type_named("terrain"), EntityType::kTerrain);
  EXPECT_EQ(entity_type_name(EntityType::kTerrain), "terrain");
}

TEST(GraphJson, PositionsOfValuesKeysAndStringCharacters) {
  const base::Source source("t.json",
                            "{ \"a\": [1, -2.5e3, true, null],\n  \"b\\\"c\": \"x\\u00e9\\ty\" }");
  const base::Result<JsonValue> json = parse_json(source);
  ASSERT_TRUE(json.ok());
  const JsonValue& root = json.value();
  ASSERT_EQ(root.members.size(), 2U);
  EXPECT_EQ(root.members[0].key_offset, 2U);
  const JsonValue& a = root.members[0].value;
  EXPECT_EQ(a.offset, 7U);
  EXPECT_EQ(a.items[0].offset, 8U);
  EXPECT_EQ(a.items[1].offset, 11U);
  EXPECT_EQ(a.items[1].number, -2500.0);
  EXPECT_EQ(a.items[2].offset, 19U);
  EXPECT_EQ(a.items[3].offset, 25U);
  EXPECT_EQ(root.members[1].key, "b\"c");
  EXPECT_EQ(source.locate(root.members[1].key_offset),
            (std::pair<std::uint32_t, std::uint32_t>{2, 3}));
  const JsonValue& b = root.members[1].value;
  EXPECT_EQ(b.text, "x\xC3\xA9\ty");
  // Decoded bytes 0 x, 1-2 é (written \u00e9), 3 tab (\t), 4 y.
  EXPECT_EQ(string_byte_offset(source, b, 0), b.offset + 1);
  EXPECT_EQ(string_byte_offset(source, b, 1), b.offset + 2);
  EXPECT_EQ(string_byte_offset(source, b, 3), b.offset + 8);
  EXPECT_EQ(string_byte_offset(source, b, 4), b.offset + 10);
}

TEST(GraphJson, OrderIsKeptAndDepthIsBounded) {
  const base::Source ordered("t.json", R"({"z": 1, "a": 2, "m": 3})");
  const auto json = parse_json(ordered);
  ASSERT_TRUE(json.ok());
  EXPECT_EQ(json->members[0].key, "z");
  EXPECT_EQ(json->members[2].key, "m");
  const base::Source deep("t.json", std::string(300, '[') + std::string(300, ']'));
  const auto failed = parse_json(deep);
  ASSERT_FALSE(failed.ok());
  EXPECT_EQ(base::render(failed.diagnostics()[0]),
            "t.json:1:201: error[G001]: invalid JSON: nesting deeper than 200 levels");
}

// Subgraph references are resolved against the file's folder inside the top-level folder.
TEST(GraphReader, SubgraphFilesAreReadOnceAndNamedByTheirPath) {
  std::vector<std::string> asked;
  const base::Source source("dir/top.graph.json", R"({ "format": "insula-graph", "version": 1,
    "nodes": [ { "id": "a", "type": "subgraph", "graph": "parts/p.graph.json" },
               { "id": "b", "type": "subgraph", "graph": "./parts/../parts/p.graph.json" } ] })");
  const FileReader files = [&](const std::string& path, std::string& text, std::string&) {
    asked.push_back(path);
    text = R"({ "format": "insula-graph", "version": 1, "nodes": [] })";
    return true;
  };
  const auto doc = read_graph(source, files);
  ASSERT_TRUE(doc.ok());
  EXPECT_EQ(asked, (std::vector<std::string>{"parts/p.graph.json"}));
  ASSERT_EQ(doc->graphs.size(), 2U);
  EXPECT_EQ(doc->graphs[1]->ref, "dir/parts/p.graph.json");
  EXPECT_EQ(doc->graphs[0]->nodes[1].subgraph, doc->graphs[1].get());
}

}  // namespace
}  // namespace insula::lang::graph
