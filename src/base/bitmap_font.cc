#include "base/bitmap_font.h"

#include <algorithm>
#include <string>

namespace insula::base {
namespace {

// One glyph per printable ASCII character from ' ' (32) to '~' (126): its 8 rows left to right,
// '#' a dot, rows separated by spaces. Parsed at compile time, so a malformed row does not build.
constexpr const char* kGlyphs[] = {
    "..... ..... ..... ..... ..... ..... ..... .....",  // space
    "..#.. ..#.. ..#.. ..#.. ..#.. ..... ..#.. .....",  // !
    ".#.#. .#.#. ..... ..... ..... ..... ..... .....",  // "
    ".#.#. .#.#. ##### .#.#. ##### .#.#. .#.#. .....",  // #
    "..#.. .#### #.#.. .###. ..#.# ####. ..#.. .....",  // $
    "##... ##..# ...#. ..#.. .#... #..## ...## .....",  // %
    ".##.. #..#. #.#.. .#... #.#.# #..#. .##.# .....",  // &
    "..#.. ..#.. .#... ..... ..... ..... ..... .....",  // '
    "...#. ..#.. .#... .#... .#... ..#.. ...#. .....",  // (
    ".#... ..#.. ...#. ...#. ...#. ..#.. .#... .....",  // )
    "..... ..#.. #.#.# .###. #.#.# ..#.. ..... .....",  // *
    "..... ..#.. ..#.. ##### ..#.. ..#.. ..... .....",  // +
    "..... ..... ..... ..... ..... .##.. ..#.. .#...",  // ,
    "..... ..... ..... ##### ..... ..... ..... .....",  // -
    "..... ..... ..... ..... ..... .##.. .##.. .....",  // .
    "..... ....# ...#. ..#.. .#... #.... ..... .....",  // /
    ".###. #...# #..## #.#.# ##..# #...# .###. .....",  // 0
    "..#.. .##.. ..#.. ..#.. ..#.. ..#.. .###. .....",  // 1
    ".###. #...# ....# ...#. ..#.. .#... ##### .....",  // 2
    "##### ...#. ..#.. ...#. ....# #...# .###. .....",  // 3
    "...#. ..##. .#.#. #..#. ##### ...#. ...#. .....",  // 4
    "##### #.... ####. ....# ....# #...# .###. .....",  // 5
    "..##. .#... #.... ####. #...# #...# .###. .....",  // 6
    "##### ....# ...#. ..#.. .#... .#... .#... .....",  // 7
    ".###. #...# #...# .###. #...# #...# .###. .....",  // 8
    ".###. #...# #...# .#### ....# ...#. .##.. .....",  // 9
    "..... .##.. .##.. ..... .##.. .##.. ..... .....",  // :
    "..... .##.. .##.. ..... .##.. ..#.. .#... .....",  // ;
    "...#. ..#.. .#... #.... .#... ..#.. ...#. .....",  // <
    "..... ..... ##### ..... ##### ..... ..... .....",  // =
    ".#... ..#.. ...#. ....# ...#. ..#.. .#... .....",  // >
    ".###. #...# ....# ...#. ..#.. ..... ..#.. .....",  // ?
    ".###. #...# ....# .##.# #.#.# #.#.# .###. .....",  // @
    ".###. #...# #...# ##### #...# #...# #...# .....",  // A
    "####. #...# #...# ####. #...# #...# ####. .....",  // B
    ".###. #...# #.... #.... #.... #...# .###. .....",  // C
    "###.. #..#. #...# #...# #...# #..#. ###.. .....",  // D
    "##### #.... #.... ####. #.... #.... ##### .....",  // E
    "##### #.... #.... ####. #.... #.... #.... .....",  // F
    ".###. #...# #.... #.### #...# #...# .#### .....",  // G
    "#...# #...# #...# ##### #...# #...# #...# .....",  // H
    ".###. ..#.. ..#.. ..#.. ..#.. ..#.. .###. .....",  // I
    "..### ...#. ...#. ...#. ...#. #..#. .##.. .....",  // J
    "#...# #..#. #.#.. ##... #.#.. #..#. #...# .....",  // K
    "#.... #.... #.... #.... #.... #.... ##### .....",  // L
    "#...# ##.## #.#.# #.#.# #...# #...# #...# .....",  // M
    "#...# #...# ##..# #.#.# #..## #...# #...# .....",  // N
    ".###. #...# #...# #...# #...# #...# .###. .....",  // O
    "####. #...# #...# ####. #.... #.... #.... .....",  // P
    ".###. #...# #...# #...# #.#.# #..#. .##.# .....",  // Q
    "####. #...# #...# ####. #.#.. #..#. #...# .....",  // R
    ".#### #.... #.... .###. ....# ....# ####. .....",  // S
    "##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#.. .....",  // T
    "#...# #...# #...# #...# #...# #...# .###. .....",  // U
    "#...# #...# #...# #...# #...# .#.#. ..#.. .....",  // V
    "#...# #...# #...# #.#.# #.#.# #.#.# .#.#. .....",  // W
    "#...# #...# .#.#. ..#.. .#.#. #...# #...# .....",  // X
    "#...# #...# .#.#. ..#.. ..#.. ..#.. ..#.. .....",  // Y
    "##### ....# ...#. ..#.. .#... #.... ##### .....",  // Z
    ".###. .#... .#... .#... .#... .#... .###. .....",  // [
    "..... #.... .#... ..#.. ...#. ....# ..... .....",  // backslash
    ".###. ...#. ...#. ...#. ...#. ...#. .###. .....",  // ]
    "..#.. .#.#. #...# ..... ..... ..... ..... .....",  // ^
    "..... ..... ..... ..... ..... ..... ##### .....",  // _
    ".#... ..#.. ...#. ..... ..... ..... ..... .....",  // `
    "..... ..... .###. ....# .#### #...# .#### .....",  // a
    "#.... #.... #.##. ##..# #...# #...# ####. .....",  // b
    "..... ..... .###. #.... #.... #...# .###. .....",  // c
    "....# ....# .##.# #..## #...# #...# .#### .....",  // d
    "..... ..... .###. #...# ##### #.... .###. .....",  // e
    "..##. .#..# .#... ###.. .#... .#... .#... .....",  // f
    "..... ..... .#### #...# #...# .#### ....# .###.",  // g
    "#.... #.... #.##. ##..# #...# #...# #...# .....",  // h
    "..#.. ..... .##.. ..#.. ..#.. ..#.. .###. .....",  // i
    "...#. ..... ..##. ...#. ...#. ...#. #..#. .##..",  // j
    "#.... #.... #..#. #.#.. ##... #.#.. #..#. .....",  // k
    ".##.. ..#.. ..#.. ..#.. ..#.. ..#.. .###. .....",  // l
    "..... ..... ##.#. #.#.# #.#.# #...# #...# .....",  // m
    "..... ..... #.##. ##..# #...# #...# #...# .....",  // n
    "..... ..... .###. #...# #...# #...# .###. .....",  // o
    "..... ..... ####. #...# #...# ####. #.... #....",  // p
    "..... ..... .#### #...# #...# .#### ....# ....#",  // q
    "..... ..... #.##. ##..# #.... #.... #.... .....",  // r
    "..... ..... .#### #.... .###. ....# ####. .....",  // s
    ".#... .#... ###.. .#... .#... .#..# ..##. .....",  // t
    "..... ..... #...# #...# #...# #..## .##.# .....",  // u
    "..... ..... #...# #...# #...# .#.#. ..#.. .....",  // v
    "..... ..... #...# #...# #.#.# #.#.# .#.#. .....",  // w
    "..... ..... #...# .#.#. ..#.. .#.#. #...# .....",  // x
    "..... ..... #...# #...# #...# .#### ....# .###.",  // y
    "..... ..... ##### ...#. ..#.. .#... ##### .....",  // z
    "...#. ..#.. ..#.. .#... ..#.. ..#.. ...#. .....",  // {
    "..#.. ..#.. ..#.. ..#.. ..#.. ..#.. ..#.. .....",  // |
    ".#... ..#.. ..#.. ...#. ..#.. ..#.. .#... .....",  // }
    "..... ..... .#... #.#.# ...#. ..... ..... .....",  // ~
};

constexpr int kFirst = 32;
constexpr int kCount = 95;
static_assert(std::size(kGlyphs) == kCount);

constexpr std::size_t kRowText = kGlyphWidth + 1;  // a row and its separating space

constexpr bool well_formed(const char* text) {
  for (std::size_t i = 0; i < kGlyphHeight * kRowText - 1; ++i) {
    const char c = text[i];
    const bool separator = i % kRowText == kGlyphWidth;
    if (separator ? c != ' ' : c != '.' && c != '#') return false;
  }
  return text[kGlyphHeight * kRowText - 1] == '\0';
}

constexpr std::array<std::array<std::uint8_t, kGlyphHeight>, kCount> parse() {
  std::array<std::array<std::uint8_t, kGlyphHeight>, kCount> out{};
  for (std::size_t g = 0; g < kCount; ++g) {
    for (std::size_t row = 0; row < kGlyphHeight; ++row) {
      std::uint8_t bits = 0;
      for (std::size_t col = 0; col < kGlyphWidth; ++col) {
        bits = static_cast<std::uint8_t>(bits << 1U);
        if (kGlyphs[g][row * kRowText + col] == '#') bits |= 1U;
      }
      out[g][row] = bits;
    }
  }
  return out;
}

constexpr bool all_well_formed() {
  return std::all_of(std::begin(kGlyphs), std::end(kGlyphs), well_formed);
}
static_assert(all_well_formed(), "every glyph is 8 rows of 5 '.' or '#' separated by spaces");

constexpr auto kParsed = parse();

constexpr std::array<std::uint8_t, kGlyphHeight> kBox = {0x1F, 0x11, 0x11, 0x11,
                                                         0x11, 0x11, 0x1F, 0x00};

// Code points of `utf8`: a lead byte starts one, continuation bytes (10xxxxxx) extend it; only
// ASCII needs its value, so anything else is reported as U+FFFD.
std::vector<std::u32string> split_lines(std::string_view utf8) {
  std::vector<std::u32string> lines(1);
  for (const char byte : utf8) {
    const auto b = static_cast<unsigned char>(byte);
    if ((b & 0xC0U) == 0x80U) continue;
    if (b == '\n') {
      lines.emplace_back();
    } else {
      lines.back() += b < 0x80U ? static_cast<char32_t>(b) : U'\uFFFD';
    }
  }
  return lines;
}

int line_width(std::size_t characters) {
  return characters == 0 ? 0 : static_cast<int>(characters) * kGlyphAdvance - 1;
}

}  // namespace

std::array<std::uint8_t, kGlyphHeight> glyph(char32_t c) {
  if (c < static_cast<char32_t>(kFirst) || c >= static_cast<char32_t>(kFirst + kCount)) {
    return kBox;
  }
  return kParsed[c - kFirst];
}

TextMask text_mask(std::string_view utf8) {
  TextMask mask;
  if (utf8.empty()) return mask;
  const std::vector<std::u32string> lines = split_lines(utf8);
  for (const std::u32string& line : lines)
    mask.width = std::max(mask.width, line_width(line.size()));
  mask.height = static_cast<int>(lines.size()) * kLineAdvance - 1;
  if (mask.width == 0) return {};
  mask.dots.assign(static_cast<std::size_t>(mask.width) * static_cast<std::size_t>(mask.height), 0);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const int left = (mask.width - line_width(lines[l].size())) / 2;
    const int top = static_cast<int>(l) * kLineAdvance;
    for (std::size_t k = 0; k < lines[l].size(); ++k) {
      const std::array<std::uint8_t, kGlyphHeight> rows = glyph(lines[l][k]);
      for (int row = 0; row < kGlyphHeight; ++row) {
        for (int col = 0; col < kGlyphWidth; ++col) {
          if ((rows[static_cast<std::size_t>(row)] >> (kGlyphWidth - 1 - col) & 1U) == 0) continue;
          const int x = left + static_cast<int>(k) * kGlyphAdvance + col;
          mask.dots[static_cast<std::size_t>(top + row) * static_cast<std::size_t>(mask.width) +
                    static_cast<std::size_t>(x)] = 1;
        }
      }
    }
  }
  return mask;
}

}  // namespace insula::base
