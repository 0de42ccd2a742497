#include "shape/query.h"

#include <gtest/gtest.h>

namespace insula::shape {
namespace {

// root (building) -> floor0 (floor), floor1 (floor, corridor) -> room (room)
struct Fixture {
  ShapeTree tree;
  ShapeId root, floor0, floor1, room;
  Fixture() {
    root = tree.add_root(Scope{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {10, 6, 8}});
    floor0 = tree.add_child(root, Scope{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {10, 3, 8}});
    floor1 = tree.add_child(root, Scope{{0, 3, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {10, 3, 8}});
    room = tree.add_child(floor1, Scope{{0, 3, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {4, 3, 8}});
    tree.add_label(root, "building");
    tree.add_label(floor0, "floor");
    tree.add_label(floor1, "floor");
    tree.add_label(floor1, "corridor");
    tree.add_label(room, "living space");
    tree.set_attribute(root, "level", 0.0);
    tree.set_attribute(floor1, "level", 1.0);
    tree.set_attribute(root, "style", std::string("brick"));
    tree.deactivate(root);
  }
};

std::vector<ShapeId> run(const Fixture& f, std::string_view text, QuerySet set = QuerySet::kAll) {
  auto expr = LabelExpr::parse(text);
  EXPECT_TRUE(expr.ok()) << text;
  return expr.ok() ? query(f.tree, expr.value(), set) : std::vector<ShapeId>{};
}

TEST(Query, LabelExpressions) {
  Fixture f;
  EXPECT_EQ(run(f, "floor"), (std::vector<ShapeId>{f.floor0, f.floor1}));
  EXPECT_EQ(run(f, "floor and not corridor"), (std::vector<ShapeId>{f.floor0}));
  EXPECT_EQ(run(f, "building or \"living space\""), (std::vector<ShapeId>{f.root, f.room}));
  EXPECT_EQ(run(f, "not (floor or building)"), (std::vector<ShapeId>{f.room}));
  EXPECT_EQ(run(f, "not not floor and corridor"), (std::vector<ShapeId>{f.floor1}));
  EXPECT_EQ(run(f, "building or floor", QuerySet::kActive),
            (std::vector<ShapeId>{f.floor0, f.floor1}));
  EXPECT_EQ(run(f, "unknown"), (std::vector<ShapeId>{}));
  auto expr = LabelExpr::parse("a or b and not c");
  ASSERT_TRUE(expr.ok());
  EXPECT_EQ(expr->to_string(), "(a or (b and (not c)))");
  auto subtree_only = LabelExpr::parse("floor or \"living space\"");
  EXPECT_EQ(query(f.tree, subtree_only.value(), QuerySet::kAll, f.floor1),
            (std::vector<ShapeId>{f.floor1, f.room}));
}

TEST(Query, LabelSyntaxErrorsCarryColumns) {
  auto bad = LabelExpr::parse("room and", "rules.lua");
  ASSERT_FALSE(bad.ok());
  const base::Diagnostic& d = bad.diagnostics().front();
  EXPECT_EQ(d.code, "Q001");
  EXPECT_EQ(d.message, "expected a label or '(', found end of query");
  EXPECT_EQ(d.span.file, "rules.lua");
  EXPECT_EQ(d.span.column, 9U);
  EXPECT_EQ(LabelExpr::parse("(room").diagnostics().front().message,
            "expected ')', found end of query");
  EXPECT_EQ(LabelExpr::parse("room corridor").diagnostics().front().message,
            "expected 'and', 'or' or end of query, found 'corridor'");
  EXPECT_EQ(LabelExpr::parse("room and \"open").diagnostics().front().message,
            "expected a label or '(', found '\"open'");
  EXPECT_EQ(LabelExpr::parse("").diagnostics().front().message,
            "expected a label or '(', found end of query");
}

TEST(Query, AttributeTests) {
  Fixture f;
  auto level = AttributeTest::parse("level >= 1");
  ASSERT_TRUE(level.ok());
  EXPECT_EQ(query(f.tree, level.value()), (std::vector<ShapeId>{f.floor1, f.room}));
  auto style = AttributeTest::parse("style == \"brick\"");
  ASSERT_TRUE(style.ok());
  EXPECT_EQ(query(f.tree, style.value()).size(), 4U);  // inherited by everyone
  auto missing = AttributeTest::parse("height != 3");
  EXPECT_EQ(query(f.tree, missing.value()).size(), 4U);
  auto bad = AttributeTest::parse("level = 1");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.diagnostics().front().code, "Q002");
  EXPECT_EQ(bad.diagnostics().front().message, "expected one of == != < <= > >=, found '='");
  EXPECT_EQ(AttributeTest::parse("level == 1x").diagnostics().front().message,
            "expected a number, true, false or a quoted string, found '1x'");
}

TEST(Query, DescendantsAndProximity) {
  Fixture f;
  EXPECT_EQ(descendants(f.tree, f.root), (std::vector<ShapeId>{f.floor0, f.floor1, f.room}));
  EXPECT_EQ(descendants(f.tree, f.room), (std::vector<ShapeId>{}));
  // Centres: floor0 (5,1.5,4), floor1 (5,4.5,4), room (2,4.5,4), root (5,3,4).
  EXPECT_EQ(within_distance(f.tree, f.floor0, 1.6, f.tree.all()), (std::vector<ShapeId>{f.root}));
  EXPECT_EQ(within_distance(f.tree, f.floor0, 3.1, f.tree.all()),
            (std::vector<ShapeId>{f.root, f.floor1}));
}

TEST(Query, OcclusionOfVolumesAndFaces) {
  Fixture f;
  // The room fills 4/10 of floor1; floor0 does not overlap floor1 (they only touch).
  EXPECT_NEAR(occlusion(f.tree, f.floor1, {f.room}), 0.4, 1e-12);
  EXPECT_NEAR(occlusion(f.tree, f.floor1, {f.floor0}), 0.0, 1e-12);
  EXPECT_NEAR(occlusion(f.tree, f.root, {f.floor0, f.room}), 0.5 + 0.2, 1e-12);
  // A wall face in the plane x = 4 (z = +x): touched over its whole area by the room on one side.
  const ShapeId wall =
      f.tree.add_child(f.room, Scope{{4, 3, 8}, {0, 0, -1}, {0, 1, 0}, {1, 0, 0}, {8, 3, 0}});
  EXPECT_NEAR(occlusion(f.tree, wall, {f.room}), 1.0, 1e-12);
  // floor0 lies below the wall's y range: it does not cover it.
  EXPECT_NEAR(occlusion(f.tree, wall, {f.floor0}), 0.0, 1e-12);
}

}  // namespace
}  // namespace insula::shape
