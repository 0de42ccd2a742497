#include "base/css_colours.h"

#include <gtest/gtest.h>

namespace insula::base {
namespace {

TEST(CssColours, NamesInAnyCaseWithSpaces) {
  EXPECT_EQ(css_colour("white"), 0xFFFFFFu);
  EXPECT_EQ(css_colour("aliceblue"), 0xF0F8FFu);      // the first entry
  EXPECT_EQ(css_colour("yellowgreen"), 0x9ACD32u);    // the last
  EXPECT_EQ(css_colour("Light Grey"), 0xD3D3D3u);     // as OpenStreetMap mappers write it
  EXPECT_EQ(css_colour("rebeccapurple"), 0x663399u);  // CSS Color Level 4
  EXPECT_EQ(css_colour("brick"), std::nullopt);       // a material, not a colour
  EXPECT_EQ(css_colour("#ffffff"), std::nullopt);
  EXPECT_EQ(css_colour(""), std::nullopt);
}

}  // namespace
}  // namespace insula::base
