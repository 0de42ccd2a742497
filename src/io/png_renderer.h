// Insula's built-in software renderer: an axonometric (orthographic) view of a scene with flat
// Lambert shading, crease and silhouette outlines, supersampled anti-aliasing, ground shadows and a
// cutaway mode that removes everything above a cut height so rooms show from above. It needs no GPU
// and no window; docs/renderer.md describes the camera, shading and cut conventions.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "shape/scene.h"

namespace insula::io {

struct RenderOptions {
  int width = 1024;  // output pixels, 1..8192
  int height = 768;  // output pixels, 1..8192
  // Compass direction the camera looks FROM, in degrees counter-clockwise from +X (east):
  // 225 = from the south-west, 0 = from the east, 90 = from the north. Any value is accepted.
  double azimuth_deg = 225.0;
  // Angle of the viewing direction above the horizon, in degrees; 90 = straight down (plan view).
  // Clamped to [-90, 90].
  double elevation_deg = 35.0;
  // Fraction of the image size kept free around the scene on each side, in [0, 0.45].
  double margin = 0.05;
  // Cutaway: remove everything above the cut height (local Z, meters) and draw section lines
  // where faces were cut. NaN = automatic per building (see auto_cut_height).
  bool cutaway = false;
  double cut_height = std::numeric_limits<double>::quiet_NaN();
  bool outlines = true;        // dark lines on creases, silhouettes and open boundaries
  double outline_width = 1.5;  // output pixels, in [0.25, 8]
  // Angle between two faces' normals above which their shared edge is drawn, in degrees.
  double crease_angle_deg = 12.0;
  bool shadows = true;  // shadows cast on the ground plane (the lowest Z of the scene)
  // Colours are linear RGB in [0, 1], like shape::Material; the PNG is sRGB-encoded.
  std::array<float, 3> background{0.80F, 0.84F, 0.88F};
  std::array<float, 3> outline_color{0.035F, 0.035F, 0.04F};
  bool transparent_background = false;  // alpha 0 where nothing is drawn
  int supersample = 2;                  // samples per pixel along each axis, 1..4
};

// 8-bit RGBA pixels in sRGB, row-major from the top-left corner; 4 bytes per pixel.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;

  bool empty() const { return width == 0 || height == 0; }
  std::array<std::uint8_t, 4> pixel(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                           static_cast<std::size_t>(x)) *
                          4;
    return {pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]};
  }
};

// Empty when the options are usable, else a message naming the first bad option and its range.
std::string validate(const RenderOptions& options);

// Renders the scene. Faces with non-finite coordinates or degenerate loops are skipped. An empty
// scene gives a background-only image. Returns an empty Image when validate(options) fails.
// Deterministic: the same scene and options give the same pixels.
Image render(const shape::Scene& scene, const RenderOptions& options = {});

// The automatic cut height of one building, local Z in meters: the plan-cut convention of
// architecture, about 1.2 m above the floor of the top storey, so its rooms show with the roof and
// ceiling removed. The top storey is the highest part of kind kStorey; without storey parts, the
// highest upward FloorSurface below the eaves; without those, the eaves less 1.5 m, but never below
// 1.2 m above the building's base. The eaves are the lowest vertex of the roof faces open to the
// sky (nothing of the building above them; furniture tops tagged as roofs do not count), or the
// top when there is none.
// NaN for a building without geometry.
double auto_cut_height(const shape::Building& building);

// Renders the scene and writes it as a PNG file atomically (io::write_file_atomically): a failed
// write leaves no file. Returns an empty string on success, else a message naming the file.
std::string write_png(const shape::Scene& scene, const std::filesystem::path& path,
                      const RenderOptions& options = {});

// Encodes an image as PNG bytes (empty on failure or for an empty image).
std::string encode_png(const Image& image);

}  // namespace insula::io
