#include "io/render_raster.h"

#include <algorithm>
#include <cmath>

namespace insula::io::raster {
namespace {

constexpr float kShadowStrength = 0.72F;  // ground in shadow keeps this fraction of its light
constexpr float kShadowAlpha = 0.28F;     // opacity of a shadow on a transparent background
constexpr int kDensityRadius = 3;  // output pixels around a sample, at least, for the density
// Ink density above which lines off the silhouette band fade: parallel lines 1.5 pixels wide reach
// it about 2.5 pixels apart; two lines crossing fill about 0.4 of the window.
constexpr float kCrowded = 0.6F;

// Screen coordinates in 24.8 fixed point. Edge functions are then exact integers, so two triangles
// sharing an edge agree on every pixel centre and inclusive tests leave no cracks between them.
constexpr std::int64_t kSubpixel = 256;
constexpr float kMaxCoordinate = 4.0e6F;  // pixels; keeps edge products inside int64

struct Fixed {
  std::int64_t x;
  std::int64_t y;
};

Fixed to_fixed(const ScreenPoint& p) {
  return {std::llround(p.x * kSubpixel), std::llround(p.y * kSubpixel)};
}

// Twice the signed area of (a, b, p); positive when p lies to the right of a->b on screen
// (y down), i.e. inside a triangle wound clockwise on screen.
std::int64_t edge(Fixed a, Fixed b, Fixed p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

bool usable(const ScreenPoint& p) {
  return std::abs(p.x) < kMaxCoordinate && std::abs(p.y) < kMaxCoordinate && std::isfinite(p.z);
}

// Pixel range [lo, hi] whose centres (i + 0.5) can lie within [min, max].
std::array<int, 2> pixel_span(float min, float max, int size) {
  const int lo = std::max(0, static_cast<int>(std::ceil(min - 0.5F)));
  const int hi = std::min(size - 1, static_cast<int>(std::floor(max - 0.5F)));
  return {lo, hi};
}

// Standard sRGB transfer function (IEC 61966-2-1), tabulated for speed.
class SrgbTable {
 public:
  SrgbTable() {
    for (int i = 0; i < kSize; ++i) {
      const double c = static_cast<double>(i) / (kSize - 1);
      const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
      table_[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(std::lround(s * 255.0));
    }
  }
  std::uint8_t operator()(float linear) const {
    const float c = std::clamp(linear, 0.0F, 1.0F);
    return table_[static_cast<std::size_t>(std::lround(c * (kSize - 1)))];
  }

 private:
  static constexpr int kSize = 4096;
  std::array<std::uint8_t, kSize> table_{};
};

}  // namespace

Framebuffer::Framebuffer(int width, int height)
    : width_(width),
      height_(height),
      depth_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), kEmpty),
      shade_(depth_.size(), 0),
      ink_(depth_.size(), Ink::kNone),
      shadow_(depth_.size(), 0) {}

std::uint32_t Framebuffer::add_shade(Rgb colour, std::uint32_t owner) {
  shades_.push_back(colour);
  owners_.push_back(owner);
  return static_cast<std::uint32_t>(shades_.size());
}

template <typename Visit>
void Framebuffer::scan(const ScreenPoint& a, const ScreenPoint& b0, const ScreenPoint& c0,
                       Visit&& visit) const {
  if (!usable(a) || !usable(b0) || !usable(c0)) return;
  Fixed fa = to_fixed(a), fb = to_fixed(b0), fc = to_fixed(c0);
  std::int64_t area = edge(fa, fb, fc);
  if (area == 0) return;
  const bool flip = area < 0;
  if (flip) std::swap(fb, fc), area = -area;
  const ScreenPoint& b = flip ? c0 : b0;
  const ScreenPoint& c = flip ? b0 : c0;
  const auto [x0, x1] = pixel_span(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), width_);
  const auto [y0, y1] = pixel_span(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), height_);
  // Edge functions are affine in x: step them along each row instead of re-evaluating.
  const std::int64_t d0 = -(fc.y - fb.y) * kSubpixel, d1 = -(fa.y - fc.y) * kSubpixel,
                     d2 = -(fb.y - fa.y) * kSubpixel;
  const float inv_area = 1.0F / static_cast<float>(area);
  for (int y = y0; y <= y1; ++y) {
    const Fixed p{x0 * kSubpixel + kSubpixel / 2, y * kSubpixel + kSubpixel / 2};
    std::int64_t w0 = edge(fb, fc, p), w1 = edge(fc, fa, p), w2 = edge(fa, fb, p);
    std::size_t i = index(x0, y);
    for (int x = x0; x <= x1; ++x, ++i, w0 += d0, w1 += d1, w2 += d2) {
      if ((w0 | w1 | w2) < 0) continue;
      const float z = (static_cast<float>(w0) * a.z + static_cast<float>(w1) * b.z +
                       static_cast<float>(w2) * c.z) *
                      inv_area;
      visit(i, z);
    }
  }
}

void Framebuffer::fill_triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c,
                                std::uint32_t shade) {
  scan(a, b, c, [&](std::size_t i, float z) {
    if (z < depth_[i]) {
      depth_[i] = z;
      shade_[i] = shade;
    }
  });
}

void Framebuffer::fill_triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c,
                                const std::function<std::uint32_t(float, float)>& shade_at) {
  scan(a, b, c, [&](std::size_t i, float z) {
    if (z < depth_[i]) {
      depth_[i] = z;
      const auto x = static_cast<float>(i % static_cast<std::size_t>(width_)) + 0.5F;
      const auto y = static_cast<float>(i / static_cast<std::size_t>(width_)) + 0.5F;
      shade_[i] = shade_at(x, y);
    }
  });
}

void Framebuffer::fill_shadow(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c) {
  scan(a, b, c, [&](std::size_t i, float) { shadow_[i] = 1; });
}

bool Framebuffer::visible(float x, float y, float depth) const {
  const int cx = static_cast<int>(std::floor(x));
  const int cy = static_cast<int>(std::floor(y));
  float farthest = -kEmpty;
  for (int yy = std::max(0, cy - 1); yy <= std::min(height_ - 1, cy + 1); ++yy) {
    for (int xx = std::max(0, cx - 1); xx <= std::min(width_ - 1, cx + 1); ++xx) {
      farthest = std::max(farthest, depth_[index(xx, yy)]);
    }
  }
  return depth <= farthest;
}

void Framebuffer::stamp(float x, float y, float radius, Ink ink) {
  const auto [x0, x1] = pixel_span(x - radius, x + radius, width_);
  const auto [y0, y1] = pixel_span(y - radius, y + radius, height_);
  const float r2 = radius * radius;
  for (int py = y0; py <= y1; ++py) {
    const float dy = static_cast<float>(py) + 0.5F - y;
    for (int px = x0; px <= x1; ++px) {
      const float dx = static_cast<float>(px) + 0.5F - x;
      if (dx * dx + dy * dy > r2) continue;
      Ink& cell = ink_[index(px, py)];
      cell = std::max(cell, ink);
    }
  }
}

void Framebuffer::draw_stroke(const Stroke& stroke, float radius, float bias) {
  const float dx = stroke.b.x - stroke.a.x;
  const float dy = stroke.b.y - stroke.a.y;
  const float length = std::hypot(dx, dy);
  if (!std::isfinite(length)) return;
  // Two samples per pixel along the centre line keep the stamped discs overlapping.
  const int steps = std::max(1, static_cast<int>(std::ceil(length * 2.0F)));
  const float margin = radius + 1.0F;
  for (int s = 0; s <= steps; ++s) {
    const float t = static_cast<float>(s) / static_cast<float>(steps);
    const float x = stroke.a.x + t * dx;
    const float y = stroke.a.y + t * dy;
    if (x < -margin || y < -margin || x > static_cast<float>(width_) + margin ||
        y > static_cast<float>(height_) + margin) {
      continue;
    }
    const float z = stroke.a.z + t * (stroke.b.z - stroke.a.z);
    if (visible(x, y, z - bias)) stamp(x, y, radius, stroke.ink);
  }
}

std::vector<std::uint8_t> Framebuffer::silhouette_band(int reach) const {
  // First the samples beside a sample of another owner, then a square dilation by `reach`: a row
  // pass into `rows`, a column pass back into `band`.
  std::vector<std::uint8_t> band(ink_.size(), 0);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const std::uint32_t here = owner(index(x, y));
      if (x + 1 < width_ && owner(index(x + 1, y)) != here) {
        band[index(x, y)] = band[index(x + 1, y)] = 1;
      }
      if (y + 1 < height_ && owner(index(x, y + 1)) != here) {
        band[index(x, y)] = band[index(x, y + 1)] = 1;
      }
    }
  }
  std::vector<std::uint8_t> rows(ink_.size(), 0);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      if (band[index(x, y)] == 0) continue;
      const int x0 = std::max(0, x - reach), x1 = std::min(width_ - 1, x + reach);
      std::fill(rows.begin() + static_cast<std::ptrdiff_t>(index(x0, y)),
                rows.begin() + static_cast<std::ptrdiff_t>(index(x1, y)) + 1, 1);
    }
  }
  std::fill(band.begin(), band.end(), 0);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      if (rows[index(x, y)] == 0) continue;
      for (int yy = std::max(0, y - reach); yy <= std::min(height_ - 1, y + reach); ++yy) {
        band[index(x, yy)] = 1;
      }
    }
  }
  return band;
}

// Ink strength per sample (docs/renderer.md, "Outlines"). Ink on the silhouette band is drawn at
// full strength, so every outlined building shows its outline whatever lies inside it. Other
// ink fades where it crowds: its density is the fraction of the square window `radius` output
// pixels around the sample inked off the band (a summed-area table); above kCrowded the strength
// falls as (kCrowded / density)^2, so lines packed closer than the pixels (a 200-storey tower's
// floor lines) become a light hatch instead of a black bar.
std::vector<float> Framebuffer::ink_strength(int factor, int radius, int reach) const {
  std::vector<float> strength;
  if (std::none_of(ink_.begin(), ink_.end(), [](Ink ink) { return ink != Ink::kNone; })) {
    return strength;
  }
  const std::vector<std::uint8_t> band = silhouette_band(reach);
  const std::size_t w = static_cast<std::size_t>(width_) + 1;
  std::vector<std::uint32_t> sum(w * (static_cast<std::size_t>(height_) + 1), 0);
  for (int y = 0; y < height_; ++y) {
    std::uint32_t row = 0;
    for (int x = 0; x < width_; ++x) {
      row += ink_[index(x, y)] != Ink::kNone && band[index(x, y)] == 0 ? 1U : 0U;
      sum[(static_cast<std::size_t>(y) + 1) * w + static_cast<std::size_t>(x) + 1] =
          sum[static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x) + 1] + row;
    }
  }
  const int r = radius * factor;
  strength.assign(ink_.size(), 1.0F);
  for (int y = 0; y < height_; ++y) {
    const int y0 = std::max(0, y - r), y1 = std::min(height_, y + r + 1);
    for (int x = 0; x < width_; ++x) {
      if (ink_[index(x, y)] == Ink::kNone || band[index(x, y)] != 0) continue;
      const int x0 = std::max(0, x - r), x1 = std::min(width_, x + r + 1);
      const auto at = [&](int xx, int yy) {
        return sum[static_cast<std::size_t>(yy) * w + static_cast<std::size_t>(xx)];
      };
      const auto inked = static_cast<float>(at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0));
      const float density = inked / static_cast<float>((x1 - x0) * (y1 - y0));
      if (density > kCrowded) strength[index(x, y)] = (kCrowded / density) * (kCrowded / density);
    }
  }
  return strength;
}

Image Framebuffer::resolve(int factor, const RenderOptions& options) const {
  static const SrgbTable srgb;
  // The window grows with the line width, so an isolated line fills about a fifth of it.
  const int radius =
      std::max(kDensityRadius, static_cast<int>(std::ceil(2 * options.outline_width)));
  // The band reaches as far into a building as its silhouette strokes: their half width, plus
  // half a sample from the edge to the centre of the sample beside it.
  const int reach = static_cast<int>(std::ceil(options.outline_width * factor / 2.0 + 0.5));
  const std::vector<float> strength = ink_strength(factor, radius, reach);
  Image image;
  image.width = width_ / factor;
  image.height = height_ / factor;
  image.pixels.resize(static_cast<std::size_t>(image.width) *
                      static_cast<std::size_t>(image.height) * 4);
  const Rgb& background = options.background;
  const Rgb& outline = options.outline_color;
  const bool transparent = options.transparent_background;
  const float samples = static_cast<float>(factor * factor);
  std::uint8_t* out = image.pixels.data();
  for (int oy = 0; oy < image.height; ++oy) {
    for (int ox = 0; ox < image.width; ++ox, out += 4) {
      // Premultiplied accumulation so a transparent background blends correctly.
      float r = 0, g = 0, b = 0, alpha = 0;
      for (int sy = 0; sy < factor; ++sy) {
        std::size_t i = index(ox * factor, oy * factor + sy);
        for (int sx = 0; sx < factor; ++sx, ++i) {
          const Rgb* colour = &background;
          float a = transparent ? 0.0F : 1.0F;
          float light = 1.0F;
          if (shade_[i] != 0) {
            colour = &shades_[shade_[i] - 1];
            a = 1.0F;
          } else if (shadow_[i] != 0) {
            light = transparent ? 0.0F : kShadowStrength;
            a = transparent ? kShadowAlpha : 1.0F;
          }
          // Ink over what lies under it, by its strength (premultiplied).
          const float s = ink_[i] == Ink::kNone ? 0.0F : strength[i];
          const float under = (1.0F - s) * light * a;
          r += (*colour)[0] * under + outline[0] * s;
          g += (*colour)[1] * under + outline[1] * s;
          b += (*colour)[2] * under + outline[2] * s;
          alpha += (1.0F - s) * a + s;
        }
      }
      const float inv = alpha > 0 ? 1.0F / alpha : 0.0F;
      out[0] = srgb(r * inv);
      out[1] = srgb(g * inv);
      out[2] = srgb(b * inv);
      out[3] = static_cast<std::uint8_t>(std::lround(alpha / samples * 255.0F));
    }
  }
  return image;
}

}  // namespace insula::io::raster
