// CGA's operations as operations.h builds them from the shape registry and the alias table
// (arity, signatures, selectors, fixed arguments), and the lookups and signature helpers of
// functions.h. The latter were static_asserts, which GCC rejects under -fsanitize=undefined (the
// table loops are then not constant expressions), so they run here.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "lang/cga/functions.h"
#include "lang/cga/operations.h"
#include "shape/operation.h"

namespace insula::lang::cga {
namespace {

// Arity and argument kinds come from the registry's parameters in the alias's positional order.
TEST(CgaOperations, SignaturesFollowTheRegistry) {
  const auto sig = [](std::string_view name) { return find_operation(name)->signature; };
  EXPECT_EQ(sig("BS"), "az+");
  EXPECT_EQ(sig("RR"), "az");
  EXPECT_EQ(sig("CS"), "cn*");
  EXPECT_EQ(sig("T"), "nnn");
  EXPECT_EQ(sig("S"), "zzz");
  EXPECT_EQ(sig("Rx"), "n");
  EXPECT_EQ(sig("I"), "s");
  EXPECT_EQ(sig("extrude"), "n");
  EXPECT_EQ(sig("split"), "a");
  EXPECT_EQ(sig("offset"), "n|ns");
  EXPECT_EQ(sig("setback"), "n");
  EXPECT_EQ(sig("roofHip"), "n|nn|nnn|nnnb|nnnbn");  // then height, closed, thickness
  EXPECT_EQ(sig("roofMansard"), "n|nn|nnn|nnnn|nnnnn|nnnnnb|nnnnnbn");
  EXPECT_EQ(sig("roofFlat"), "|n|nn|nnn|nnnb");  // overhang, thickness (as .bldg Flat)
  EXPECT_EQ(sig("primitiveCube"), "|n|nn|nnn");  // width, height, depth (0: fill the scope)
  EXPECT_EQ(sig("color"), "s|nnn|nnnn");
  // A registry operation under its own name: every parameter, the required ones first.
  EXPECT_EQ(sig("roof"), "|s|sn|snn|snnn|snnnn|snnnnn|snnnnnb|snnnnnbn");
  EXPECT_EQ(sig("slice"), "sn|sns");
  EXPECT_EQ(find_operation("BS")->max_args, kUnbounded);
  EXPECT_EQ(find_operation("roofMansard")->max_args, 7);
}

TEST(CgaOperations, ArgumentsMapOntoRegistryParameters) {
  const OperationInfo* mansard = find_operation("roofMansard");
  ASSERT_NE(mansard, nullptr);
  ASSERT_EQ(mansard->op, shape::registry().find("roof"));
  EXPECT_EQ(mansard->param_of(1)->name, "mansard_pitch");
  EXPECT_EQ(mansard->param_of(3)->name, "overhang");
  EXPECT_EQ(mansard->param_of(4)->name, "height");
  EXPECT_EQ(mansard->param_of(7), nullptr);
  const OperationInfo* flat = find_operation("roofFlat");
  EXPECT_EQ(flat->param_of(0)->name, "overhang");
  EXPECT_EQ(flat->param_of(1)->name, "thickness");
  ASSERT_EQ(mansard->fixed.size(), 1U);
  EXPECT_EQ(mansard->fixed[0].name, "type");
  EXPECT_EQ(std::get<std::string>(mansard->fixed[0].value), "mansard");
  const OperationInfo* cs = find_operation("CS");
  EXPECT_EQ(cs->param_of(0)->name, "type");
  EXPECT_EQ(cs->param_of(1), nullptr);  // the component indices are CGA's own
  EXPECT_EQ(cs->param_of(7), nullptr);
  EXPECT_EQ(find_operation("BS")->param_of(5)->name, "sizes");
  EXPECT_EQ(find_operation("color")->op, nullptr);
}

TEST(CgaOperations, SelectorsAreTheRegistryChoices) {
  using V = std::vector<std::string>;
  EXPECT_EQ(find_operation("comp")->selectors,
            (V{"front",        "back",         "left",          "right",         "top",
               "bottom",       "side",         "all",           "vertical",      "horizontal",
               "aslant",       "nutant",       "border",        "inside",        "eave",
               "hip",          "valley",       "ridge",         "object.front",  "object.back",
               "object.left",  "object.right", "object.top",    "object.bottom", "object.side",
               "world.north",  "world.south",  "world.east",    "world.west",    "world.up",
               "world.down",   "world.side",   "street.front",  "street.back",   "street.left",
               "street.right", "street.top",   "street.bottom", "street.side"}));
  EXPECT_EQ(find_operation("shapeU")->selectors, (V{"shape", "remainder"}));
  EXPECT_TRUE(find_operation("innerRectangle")->selectors_are_pieces);
  EXPECT_EQ(
      find_operation("setback")->selectors,
      (V{"front",      "back",         "left",        "right",       "side",         "all",
         "street",     "remainder",    "world.north", "world.south", "world.east",   "world.west",
         "world.side", "object.front", "object.back", "object.left", "object.right", "object.side",
         "streetSide", "noStreetSide", "uv.left",     "uv.right",    "uv.bottom",    "uv.top"}));
  EXPECT_EQ(find_operation("offset")->selectors, (V{"inside", "border"}));
  EXPECT_TRUE(find_operation("offset")->selectors_are_pieces);
  EXPECT_TRUE(is_selector(*find_operation("CS"), "side"));
  EXPECT_FALSE(is_selector(*find_operation("CS"), "street"));
}

TEST(CgaOperations, EveryRegistryOperationIsReachable) {
  for (const shape::Operation& op : shape::registry().operations()) {
    const OperationInfo* info = find_operation(op.name);
    ASSERT_NE(info, nullptr) << op.name;
    EXPECT_EQ(info->op, &op) << op.name;
  }
}

TEST(CgaBuiltins, FindOperation) {
  ASSERT_NE(find_operation("roofHip"), nullptr);
  EXPECT_EQ(find_operation("roofHip")->name, "roofHip");
  ASSERT_NE(find_operation("BS"), nullptr);
  EXPECT_EQ(find_operation("BS")->kind, OpKind::kSplit);
  EXPECT_EQ(find_operation("RR")->kind, OpKind::kRepeat);
  EXPECT_EQ(find_operation("nope"), nullptr);
  EXPECT_EQ(find_operation("bs"), nullptr);  // names are case-sensitive
}

TEST(CgaBuiltins, NamesAreUnique) {
  std::set<std::string> ops;
  for (const OperationInfo& op : operations()) {
    EXPECT_TRUE(ops.insert(op.name).second) << op.name;
    EXPECT_EQ(find_operation(op.name), &op);
  }
  std::set<std::string> fns;
  for (const FunctionInfo& fn : kFunctions) {
    EXPECT_TRUE(fns.insert(std::string(fn.name)).second) << fn.name;
    EXPECT_EQ(find_function(fn.name), &fn);
  }
}

TEST(CgaBuiltins, ShapeAttributes) {
  EXPECT_NE(find_shape_attribute("Scope", "sx"), nullptr);
  EXPECT_NE(find_shape_attribute("split", "index"), nullptr);
  EXPECT_EQ(find_shape_attribute("Lot", "sx"), nullptr);
  EXPECT_EQ(find_shape_attribute("Shape", "sw"), nullptr);
  EXPECT_TRUE(is_shape_object("comp"));
  EXPECT_FALSE(is_shape_object("Comp"));
}

TEST(CgaBuiltins, SignatureAccepts) {
  EXPECT_TRUE(signature_accepts("s|nnn|nnnn", 3));
  EXPECT_FALSE(signature_accepts("s|nnn|nnnn", 2));
  EXPECT_TRUE(signature_accepts("s|nnn|nnnn", 1));
  EXPECT_TRUE(signature_accepts("s|nnn|nnnn", 4));
  EXPECT_FALSE(signature_accepts("s|nnn|nnnn", 5));
  EXPECT_TRUE(signature_accepts("az+", 2));
  EXPECT_TRUE(signature_accepts("az+", 9));
  EXPECT_FALSE(signature_accepts("az+", 1));
  EXPECT_TRUE(signature_accepts("cn*", 1));
  EXPECT_TRUE(signature_accepts("cn*", 4));
  EXPECT_FALSE(signature_accepts("cn*", 0));
  EXPECT_TRUE(signature_accepts("", 0));
  EXPECT_FALSE(signature_accepts("", 1));
}

TEST(CgaBuiltins, SignatureLetter) {
  EXPECT_EQ(signature_letter("az+", 5, 0), 'a');
  EXPECT_EQ(signature_letter("az+", 5, 4), 'z');
  EXPECT_EQ(signature_letter("|n|nn", 2, 1), 'n');
  EXPECT_EQ(signature_letter("s|nnn|nnnn", 1, 0), 's');
  EXPECT_EQ(signature_letter("s|nnn|nnnn", 3, 2), 'n');
  EXPECT_EQ(signature_letter("s|nnn|nnnn", 2, 0), '\0');
}

}  // namespace
}  // namespace insula::lang::cga
