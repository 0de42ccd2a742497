// The supersampled framebuffer of the PNG renderer and its primitives: z-buffered flat triangles,
// depth-tested outline strokes, a ground-shadow mask, and the box-filter downsampling to sRGB.
// Screen space: x right, y down, in framebuffer pixels (pixel centres at +0.5); depth grows away
// from the camera. Internal to io/png_renderer.cc and io/render_scene.cc.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "io/png_renderer.h"

namespace insula::io::raster {

using Rgb = std::array<float, 3>;  // linear RGB

struct ScreenPoint {
  float x = 0;
  float y = 0;
  float z = 0;  // depth along the viewing direction, meters
};

enum class Ink : std::uint8_t { kNone, kOutline, kSection };

struct Stroke {
  ScreenPoint a;
  ScreenPoint b;
  Ink ink = Ink::kOutline;
};

class Framebuffer {
 public:
  static constexpr float kEmpty = std::numeric_limits<float>::infinity();

  Framebuffer(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // Adds a flat colour of the building `owner` (1-based; 0 is the background) and returns its id
  // for fill_triangle. Where owners meet on screen lies a silhouette (docs/renderer.md,
  // "Outlines").
  std::uint32_t add_shade(Rgb colour, std::uint32_t owner);
  // Z-buffered fill: a pixel whose centre lies inside or on the triangle and is nearer than the
  // stored depth takes `shade` (edges are inclusive so shared edges leave no gaps).
  void fill_triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c,
                     std::uint32_t shade);
  // The same with a shade per pixel: shade_at(x, y) at the pixel centre (a textured face).
  void fill_triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c,
                     const std::function<std::uint32_t(float, float)>& shade_at);
  // Marks pixels whose centre lies inside or on the triangle as ground shadow (depth ignored).
  void fill_shadow(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c);
  // Draws a stroke `radius` pixels wide on each side of its centre line, where the centre line is
  // not hidden: its depth, less `bias`, is not behind the farthest surface in the 3x3 pixels
  // around it (a dilated depth test, so creases between steep faces do not flicker).
  void draw_stroke(const Stroke& stroke, float radius, float bias);

  // Averages factor x factor blocks in linear RGB and encodes to sRGB RGBA8.
  Image resolve(int factor, const RenderOptions& options) const;

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }
  // Calls visit(pixel index, depth) for every pixel whose centre lies inside or on the triangle.
  template <typename Visit>
  void scan(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c, Visit&& visit) const;
  bool visible(float x, float y, float depth) const;
  std::uint32_t owner(std::size_t i) const { return shade_[i] == 0 ? 0 : owners_[shade_[i] - 1]; }
  // Per sample, 1 within `reach` samples of a place where two owners meet (a silhouette).
  std::vector<std::uint8_t> silhouette_band(int reach) const;
  // Per sample, the opacity its ink is drawn with (empty when nothing is inked): 1 on the
  // silhouette band, else fading with the density of the other ink within `radius` output pixels.
  std::vector<float> ink_strength(int factor, int radius, int reach) const;
  void stamp(float x, float y, float radius, Ink ink);

  int width_;
  int height_;
  std::vector<float> depth_;
  std::vector<std::uint32_t> shade_;  // 0 = background, else index + 1 into shades_
  std::vector<Ink> ink_;
  std::vector<std::uint8_t> shadow_;
  std::vector<Rgb> shades_;
  std::vector<std::uint32_t> owners_;  // per shade
};

}  // namespace insula::io::raster
