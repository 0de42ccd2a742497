// The lookups and signature helpers of builtins.h (the table shared by checker, compiler and
// derivation). These were static_asserts in the header, which GCC rejects under
// -fsanitize=undefined (the table loops are then not constant expressions), so they run here.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "lang/cga/builtins.h"

namespace insula::lang::cga {
namespace {

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
  for (const OperationInfo& op : kOperations) {
    EXPECT_TRUE(ops.insert(std::string(op.name)).second) << op.name;
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
