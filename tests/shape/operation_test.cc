#include "shape/operation.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace insula::shape {
namespace {

std::string bind_error(std::string_view op, std::vector<ArgInput> inputs) {
  const Operation* o = registry().find(op);
  EXPECT_NE(o, nullptr) << op;
  return o == nullptr ? "" : Registry::bind(*o, inputs).error;
}

TEST(Registry, DeclaresTheFirstOperations) {
  for (std::string_view name : {"extrude", "split", "repeat", "comp", "translate", "rotate",
                                "scale", "center", "roof", "insert", "offset", "setback"}) {
    const Operation* op = registry().find(name);
    ASSERT_NE(op, nullptr) << name;
    EXPECT_FALSE(op->doc.empty());
    EXPECT_TRUE(op->execute);
  }
  EXPECT_EQ(registry().find("explode"), nullptr);
}

TEST(Registry, BindsPositionalNamedAndDefaults) {
  const Operation& op = *registry().find("rotate");
  const BindResult r =
      Registry::bind(op, {{"", std::int64_t{90}}, {"pivot", std::string("center")}});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.arguments.number("x"), 90.0);  // an integer where a number is declared
  EXPECT_EQ(r.arguments.number("z"), 0.0);   // default
  EXPECT_EQ(r.arguments.string("pivot"), "center");
  const BindResult s =
      Registry::bind(*registry().find("split"), {{"", std::string("y")}, {"", 3.0}});
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(s.arguments.sizes("sizes"), (std::vector<SizeSpec>{{3, SizeMode::kAbsolute}}));
}

TEST(Registry, GenericArgumentErrors) {
  EXPECT_EQ(bind_error("extrude", {{"heigth", 2.0}}), "extrude: unknown parameter 'heigth'");
  EXPECT_EQ(bind_error("extrude", {{"", 2.0}, {"", 3.0}}),
            "extrude: too many arguments (expects at most 1)");
  EXPECT_EQ(bind_error("extrude", {{"", 2.0}, {"height", 3.0}}),
            "extrude: parameter 'height' given twice");
  EXPECT_EQ(bind_error("extrude", {{"height", std::string("tall")}}),
            "extrude: parameter 'height' expects a number; got a string");
  EXPECT_EQ(bind_error("split", {{"axis", 1.0}}),
            "split: parameter 'axis' expects one of x, y, z; got a number");
  EXPECT_EQ(bind_error("split", {{"axis", std::string("w")}}),
            "split: parameter 'axis' must be one of x, y, z; got 'w'");
  EXPECT_EQ(bind_error("extrude", {{"height", -1.0}}),
            "extrude: parameter 'height' must be >= 0; got -1");
  EXPECT_EQ(bind_error("roof", {{"pitch", 95.0}}), "roof: parameter 'pitch' must be <= 89; got 95");
  EXPECT_EQ(bind_error("extrude", {}), "extrude: missing required parameter 'height'");
  EXPECT_EQ(bind_error("split", {{"", std::string("x")}}),
            "split: missing required parameter 'sizes'");
  EXPECT_EQ(bind_error("translate", {{"x", true}}),
            "translate: parameter 'x' expects a number; got a bool");
  EXPECT_EQ(bind_error("repeat", {{"", std::string("x")}, {"size", std::nan("")}}),
            "repeat: parameter 'size' must be finite; got nan");
}

TEST(Registry, RunReportsUnknownOperationsAndLeavesTreeOnFailure) {
  ShapeTree tree;
  const ShapeId root = tree.add_root(Scope{{}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {4, 4, 0}});
  EXPECT_EQ(registry().run(tree, root, "explode", {}).error, "unknown operation 'explode'");
  // A pure scope is not a flat shape with an outline: extrude fails, and creates nothing.
  const OpResult r = registry().run(tree, root, "extrude", {{"", 3.0}});
  EXPECT_EQ(r.error, "extrude: needs a flat shape (a footprint or a face)");
  EXPECT_EQ(tree.size(), 1U);
  EXPECT_TRUE(tree[root].active);
}

// The committed page (with CGA's and Lua's spellings) is checked by
// tests/lang/frontends/operations_doc_test.cc; here, the table of spellings itself.
TEST(Registry, ReferencePageListsEachFrontEndsSpellings) {
  const FrontEndSpellings front_ends[] = {
      {"A",
       [](const Operation& op) {
         return op.name == "roof" ? std::vector<std::string>{"r|1", "r2"}
                                  : std::vector<std::string>{};
       }},
      {"B", nullptr},
  };
  const std::string page = operations_reference_markdown(front_ends);
  EXPECT_NE(page.find("| operation | A | B |\n|---|---|---|\n"), std::string::npos);
  EXPECT_NE(page.find("| `roof` | `r\\|1`<br>`r2` | - |\n"), std::string::npos);
  EXPECT_NE(page.find("| `split` | - | - |\n"), std::string::npos);
  EXPECT_EQ(operations_reference_markdown().find("Spellings by front-end"), std::string::npos);
}

TEST(SizeSpec, PrintsLikeCga) {
  EXPECT_EQ(to_string(SizeSpec{2, SizeMode::kAbsolute}), "2");
  EXPECT_EQ(to_string(SizeSpec{0.5, SizeMode::kRelative}), "'0.5");
  EXPECT_EQ(to_string(ArgValue{
                std::vector<SizeSpec>{{2, SizeMode::kAbsolute}, {1, SizeMode::kFloating}}}),
            "[2, ~1]");
}

}  // namespace
}  // namespace insula::shape
