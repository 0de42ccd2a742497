// Scene traversal of the PNG renderer: the fitted axonometric camera, shading, triangulation of
// the n-gon faces, cutaway clipping and outline edge classification, all drawn into a
// raster::Framebuffer. Internal to io/png_renderer.cc.
#pragma once

#include "io/png_renderer.h"
#include "io/render_raster.h"
#include "kernel/vec.h"
#include "shape/scene.h"

namespace insula::io::raster {

// Orthographic camera: world point p maps to screen x = (p.right - u0) * scale + width / 2,
// y = height / 2 - (p.up - v0) * scale, depth = p.forward - depth0.
struct Camera {
  kernel::Vec3 right;
  kernel::Vec3 up;
  kernel::Vec3 forward;  // the viewing direction (from the camera into the scene)
  double scale = 1;      // framebuffer pixels per meter
  double u0 = 0;
  double v0 = 0;
  double depth0 = 0;
  double half_width = 0;
  double half_height = 0;

  ScreenPoint project(kernel::Vec3 p) const {
    return {static_cast<float>((kernel::dot(p, right) - u0) * scale + half_width),
            static_cast<float>(half_height - (kernel::dot(p, up) - v0) * scale),
            static_cast<float>(kernel::dot(p, forward) - depth0)};
  }
};

// The camera looking from options.azimuth_deg / elevation_deg, fitted so every finite vertex of
// the scene lies inside a width x height framebuffer less the margin.
Camera fit_camera(const shape::Scene& scene, const RenderOptions& options, int width, int height);

// Draws every part of every building: faces, then ground shadows' mask, then outline strokes.
void draw_scene(const shape::Scene& scene, const RenderOptions& options, const Camera& camera,
                Framebuffer& framebuffer);

}  // namespace insula::io::raster
