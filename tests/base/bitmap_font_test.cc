// The bitmap font (base/bitmap_font.h): glyph rows, the box for characters it lacks, and the
// layout of lines in a text mask.
#include "base/bitmap_font.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace insula::base {
namespace {

std::string row_text(const TextMask& m, int y) {
  std::string out;
  for (int x = 0; x < m.width; ++x) out += m.at(x, y) ? '#' : '.';
  return out;
}

TEST(BitmapFont, GlyphRows) {
  const std::array<std::uint8_t, 8> a = {0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11, 0x00};
  EXPECT_EQ(glyph(U'A'), a);
  const std::array<std::uint8_t, 8> space{};
  EXPECT_EQ(glyph(U' '), space);
  // Descenders use the last row.
  EXPECT_NE(glyph(U'g')[7], 0);
  EXPECT_EQ(glyph(U'a')[7], 0);
}

TEST(BitmapFont, EveryPrintableCharacterButSpaceHasDotsAndDiffers) {
  for (char32_t c = 33; c < 127; ++c) {
    const auto g = glyph(c);
    EXPECT_TRUE(std::any_of(g.begin(), g.end(), [](std::uint8_t r) { return r != 0; }))
        << static_cast<int>(c);
    for (char32_t d = 33; d < c; ++d)
      EXPECT_NE(glyph(d), g) << static_cast<int>(c) << " " << static_cast<int>(d);
  }
}

TEST(BitmapFont, CharactersOutsideAsciiShowAsABox) {
  EXPECT_EQ(glyph(U'\t'), glyph(U'\u00e9'));
  EXPECT_EQ(glyph(127), glyph(U'\u00e9'));
  const TextMask m = text_mask("\xc3\xa9");  // one code point, two bytes
  EXPECT_EQ(m.width, 5);
  EXPECT_EQ(row_text(m, 0), "#####");
  EXPECT_EQ(row_text(m, 3), "#...#");
}

TEST(BitmapFont, LinesAreCentredInTheWidest) {
  const TextMask m = text_mask("AB\nI");
  EXPECT_EQ(m.width, 11);
  EXPECT_EQ(m.height, 17);
  EXPECT_EQ(row_text(m, 0), ".###..####.");
  EXPECT_EQ(row_text(m, 8), "...........");  // the gap between the lines
  EXPECT_EQ(row_text(m, 9), "....###....");  // 'I' centred: 3 columns on each side
  EXPECT_EQ(text_mask("").width, 0);
  EXPECT_EQ(text_mask("").dots.size(), 0U);
}

}  // namespace
}  // namespace insula::base
