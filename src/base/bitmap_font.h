// A small bitmap font for text drawn into images (graph textures, texture.text): printable ASCII
// (32..126) on a 5x8 dot grid, letters and digits 7 dots high in rows 0..6, descenders (g j p q y ,
// ;) reaching row 7. The glyphs are Insula's own drawing (src/base/bitmap_font.cc), in the plain
// style of 5x7 character displays; docs/graph-executor.md, "Lights and textures".
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace insula::base {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 8;
inline constexpr int kGlyphAdvance = 6;  // one empty column between characters
inline constexpr int kLineAdvance = 9;   // one empty row between lines

// The dot rows of `c`, top to bottom, bit 4 the leftmost column. Anything outside printable
// ASCII shows as a hollow box, so a missing character is visible rather than silently dropped.
std::array<std::uint8_t, kGlyphHeight> glyph(char32_t c);

// A text set in the font at one pixel per dot: `dots` row-major, 1 where a dot is set.
struct TextMask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> dots;

  bool at(int x, int y) const {
    return dots[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)] != 0;
  }
};

// `utf8` set in the font: lines split at '\n', each centred in the widest (odd leftovers go to
// the right); one glyph per code point (invalid bytes count as one each). A line of n characters
// is 6n - 1 dots wide, and L lines are 9L - 1 dots high; an empty text gives an empty mask.
TextMask text_mask(std::string_view utf8);

}  // namespace insula::base
