// Parts alike in name, kind, attributes and texture mapping merge into one (shape/alike_parts.h).
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "shape/alike_parts.h"
#include "shape/ops.h"

namespace insula::shape {
namespace {

kernel::Mesh square(double x) {
  kernel::Mesh mesh;
  mesh.add_polygon(std::vector<kernel::Vec3>{{x, 0, 0}, {x + 1, 0, 0}, {x + 1, 1, 0}, {x, 1, 0}},
                   {});
  return mesh;
}

Part part(const char* name, double x, AttributeMap attributes = {},
          PartKind kind = PartKind::kBuildingPart) {
  return Part{name, kind, std::move(attributes), square(x)};
}

TEST(AlikeParts, MergesPartsAlikeInNameKindAttributesAndUv) {
  Building b;
  b.id = "b";
  b.attributes["height"] = 12.0;
  b.parts.push_back(part("Plaster", 0, {{"color", std::string("#dccfb6")}}));
  b.parts.push_back(part("Pane", 1));
  b.parts.push_back(part("Plaster", 2, {{"color", std::string("#dccfb6")}}));
  b.parts.push_back(part("Plaster", 3, {{"color", std::string("#a65a3e")}}));  // other colour
  b.parts.push_back(part("Pane", 4, {}, PartKind::kInstallation));             // other kind
  Part mapped = part("Pane", 5);
  mapped.uv = UvMap{{0.5, 0, 0}, 0.25, {0, 0, 1}, 0};
  b.parts.push_back(mapped);  // other texture mapping
  b.parts.push_back(part("Pane", 6));
  Part instance{"Pane", PartKind::kBuildingPart, {}, {}};
  instance.instance_of = std::make_shared<const kernel::Mesh>(square(7));
  b.parts.push_back(instance);  // an instance stays its own part
  b.parts.push_back(instance);
  ASSERT_TRUE(has_alike_parts(b));

  const Building merged = merge_alike_parts(b);
  EXPECT_EQ(merged.id, "b");
  EXPECT_EQ(merged.attributes, b.attributes);
  ASSERT_EQ(merged.parts.size(), 7U);
  // In the order of each kind's first part, faces in the order of their parts.
  EXPECT_EQ(merged.parts[0].name, "Plaster");
  EXPECT_EQ(merged.parts[0].mesh.face_count(), 2U);
  EXPECT_EQ(merged.parts[0].mesh.positions()[merged.parts[0].mesh.face(1)[0]].x, 2.0);
  EXPECT_EQ(merged.parts[1].name, "Pane");
  EXPECT_EQ(merged.parts[1].mesh.face_count(), 2U);  // x = 1 and x = 6
  EXPECT_EQ(merged.parts[2].attributes.at("color"), Value(std::string("#a65a3e")));
  EXPECT_EQ(merged.parts[3].kind, PartKind::kInstallation);
  EXPECT_TRUE(merged.parts[4].uv.has_value());
  EXPECT_NE(merged.parts[5].instance_of, nullptr);
  EXPECT_NE(merged.parts[6].instance_of, nullptr);
  EXPECT_FALSE(has_alike_parts(merged));
}

TEST(AlikeParts, NothingAlikeNothingMerged) {
  Building b;
  b.parts.push_back(part("wall", 0, {{"storey", 1.0}}));
  b.parts.push_back(part("wall", 1, {{"storey", 2.0}}));
  b.parts.push_back(part("roof", 2, {{"storey", 1.0}}));
  EXPECT_FALSE(has_alike_parts(b));
  EXPECT_EQ(merge_alike_parts(b).parts.size(), 3U);
}

TEST(AlikeParts, IndexFindsOrAppends) {
  std::vector<Part> parts;
  AlikeParts alike;
  const AttributeMap red{{"color", std::string("red")}};
  EXPECT_EQ(alike.index(parts, "a", PartKind::kBuildingPart, red, std::nullopt), 0U);
  EXPECT_EQ(alike.index(parts, "b", PartKind::kBuildingPart, red, std::nullopt), 1U);
  EXPECT_EQ(alike.index(parts, "a", PartKind::kBuildingPart, red, std::nullopt), 0U);
  EXPECT_EQ(alike.index(parts, "a", PartKind::kBuildingPart, {}, std::nullopt), 2U);
  ASSERT_EQ(parts.size(), 3U);
  EXPECT_EQ(parts[1].attributes, red);
  EXPECT_TRUE(parts[0].mesh.empty());
  alike.add(parts, part("a", 0, red));
  EXPECT_EQ(parts.size(), 3U);
  EXPECT_EQ(parts[0].mesh.face_count(), 1U);
}

}  // namespace
}  // namespace insula::shape
