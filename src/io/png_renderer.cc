#include "io/png_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/atomic_file.h"
#include "io/render_raster.h"
#include "io/render_scene.h"
#include "io/triangulated.h"
#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "shape/part_mesh.h"

// stb_image_write's implementation lives in this translation unit only, with static linkage so it
// can never clash with another copy (tinygltf also bundles one).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace insula::io {
namespace {

constexpr int kMaxSide = 8192;
constexpr long long kMaxSamples = 1LL << 26;  // framebuffer pixels: bounds memory to ~0.7 GB
constexpr double kPlanCut = 1.2;              // meters above a floor: the usual plan cut
constexpr double kEavesClearance = 1.5;       // meters below the eaves without storey data
constexpr double kCoverClearance = 0.05;      // meters: what lies higher above a roof covers it

bool in_range(double value, double low, double high) {
  return value >= low && value <= high;  // false for NaN
}

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

kernel::Bounds3 part_bounds(const shape::Part& part) {
  kernel::Bounds3 bounds;
  for (kernel::Vec3 p : part.mesh.positions()) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) bounds.add(p);
  }
  return bounds;
}

// Cut for a building with storey parts: a plan cut above the floor of the highest storey.
double storey_cut(const shape::Building& building) {
  double floor = -std::numeric_limits<double>::infinity();
  double height = 0;
  for (const shape::Part& part : building.parts) {
    if (part.kind != shape::PartKind::kStorey) continue;
    const kernel::Bounds3 b = part_bounds(part);
    if (b.empty() || b.min.z <= floor) continue;
    floor = b.min.z;
    height = b.max.z - b.min.z;
  }
  if (std::isinf(floor)) return std::numeric_limits<double>::quiet_NaN();
  return floor + std::min(kPlanCut, height / 2);
}

// The building's triangles in plan, on a grid, for "does anything lie above this point" queries.
class Canopy {
 public:
  explicit Canopy(const shape::Building& building) {
    FaceTriangulator triangulator;
    std::vector<CornerTriangle> corners;
    for (const shape::Part& part : building.parts) {
      const kernel::Mesh& mesh = part.mesh;
      for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        corners.clear();
        const kernel::Vec3 n = kernel::face_normal(mesh, f);
        if (std::abs(n.z) < 1e-6 || !triangulator.triangulate(mesh, f, n, corners)) continue;
        const auto loop = mesh.face(f);
        for (const CornerTriangle& t : corners) {
          triangles_.push_back(
              {mesh.position(loop[t[0]]), mesh.position(loop[t[1]]), mesh.position(loop[t[2]])});
          for (const kernel::Vec3& p : triangles_.back()) bounds_.add({p.x, p.y});
        }
      }
    }
    if (triangles_.empty()) return;
    side_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(triangles_.size()))), 1, 256);
    cells_.resize(static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_));
    for (std::uint32_t i = 0; i < triangles_.size(); ++i) {
      const auto& t = triangles_[i];
      const auto [x0, y0] =
          cell(std::min({t[0].x, t[1].x, t[2].x}), std::min({t[0].y, t[1].y, t[2].y}));
      const auto [x1, y1] =
          cell(std::max({t[0].x, t[1].x, t[2].x}), std::max({t[0].y, t[1].y, t[2].y}));
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) cells_[static_cast<std::size_t>(y * side_ + x)].push_back(i);
      }
    }
  }

  // Whether some triangle covers `p` in plan (strictly inside it) more than `clearance` above it.
  bool covered(kernel::Vec3 p, double clearance) const {
    if (triangles_.empty()) return false;
    const auto [x, y] = cell(p.x, p.y);
    for (std::uint32_t i : cells_[static_cast<std::size_t>(y * side_ + x)]) {
      const auto& t = triangles_[i];
      const double area = cross2(t[0], t[1], t[2]);
      const double w0 = cross2(t[1], t[2], p) / area;
      const double w1 = cross2(t[2], t[0], p) / area;
      const double w2 = 1 - w0 - w1;
      if (!(w0 > 1e-9 && w1 > 1e-9 && w2 > 1e-9)) continue;
      if (w0 * t[0].z + w1 * t[1].z + w2 * t[2].z > p.z + clearance) return true;
    }
    return false;
  }

 private:
  static double cross2(kernel::Vec3 a, kernel::Vec3 b, kernel::Vec3 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  }
  std::pair<int, int> cell(double x, double y) const {
    const auto index = [&](double v, double lo, double hi) {
      const double f = hi > lo ? (v - lo) / (hi - lo) : 0;
      return std::clamp(static_cast<int>(f * side_), 0, side_ - 1);
    };
    return {index(x, bounds_.min.x, bounds_.max.x), index(y, bounds_.min.y, bounds_.max.y)};
  }

  std::vector<std::array<kernel::Vec3, 3>> triangles_;
  kernel::Bounds2 bounds_;
  int side_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
};

// A point well inside a face: the centroid of its largest triangle.
std::optional<kernel::Vec3> inner_point(const kernel::Mesh& mesh, std::size_t face,
                                        FaceTriangulator& triangulator,
                                        std::vector<CornerTriangle>& corners) {
  corners.clear();
  if (!triangulator.triangulate(mesh, face, kernel::face_normal(mesh, face), corners)) {
    return std::nullopt;
  }
  const auto loop = mesh.face(face);
  double best = -1;
  kernel::Vec3 centre;
  for (const CornerTriangle& t : corners) {
    const kernel::Vec3 a = mesh.position(loop[t[0]]), b = mesh.position(loop[t[1]]),
                       c = mesh.position(loop[t[2]]);
    const double area = kernel::length(kernel::cross(b - a, c - a));
    if (area > best) best = area, centre = (a + b + c) / 3.0;
  }
  return centre;
}

// The eaves: the lowest vertex of the roof faces open to the sky, `top` when there is none. A
// roof-tagged face with anything of the building above it (the top of a bed or a stair step under
// the floors above, a porch roof under a balcony) is not the building's roof.
double eaves(const shape::Building& building, double top) {
  const Canopy canopy(building);
  FaceTriangulator triangulator;
  std::vector<CornerTriangle> corners;
  double low = top;
  bool any = false;
  for (const shape::Part& part : building.parts) {
    for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
      if (part.mesh.tag(f).semantic != kernel::SemanticClass::kRoofSurface) continue;
      const std::optional<kernel::Vec3> inside = inner_point(part.mesh, f, triangulator, corners);
      if (!inside || canopy.covered(*inside, kCoverClearance)) continue;
      for (std::uint32_t v : part.mesh.face(f)) {
        const double z = part.mesh.position(v).z;
        if (std::isfinite(z)) low = any ? std::min(low, z) : z, any = true;
      }
    }
  }
  return low;
}

// Highest upward floor face strictly below `below`; -inf when none.
double top_floor(const shape::Building& building, double below) {
  double best = -std::numeric_limits<double>::infinity();
  for (const shape::Part& part : building.parts) {
    for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
      if (part.mesh.tag(f).semantic != kernel::SemanticClass::kFloorSurface) continue;
      if (kernel::face_normal(part.mesh, f).z < 0.9) continue;
      const double z = part.mesh.position(part.mesh.face(f)[0]).z;
      if (std::isfinite(z) && z < below) best = std::max(best, z);
    }
  }
  return best;
}

}  // namespace

std::string validate(const RenderOptions& o) {
  if (o.width < 1 || o.width > kMaxSide) return "width must be in 1..8192";
  if (o.height < 1 || o.height > kMaxSide) return "height must be in 1..8192";
  if (o.supersample < 1 || o.supersample > 4) return "supersample must be in 1..4";
  const long long samples = 1LL * o.width * o.height * o.supersample * o.supersample;
  if (samples > kMaxSamples) return "width x height x supersample^2 must not exceed 67108864";
  if (!std::isfinite(o.azimuth_deg)) return "azimuth must be a finite number of degrees";
  if (!std::isfinite(o.elevation_deg)) return "elevation must be a finite number of degrees";
  if (!in_range(o.margin, 0.0, 0.45)) return "margin must be in 0..0.45";
  if (!in_range(o.outline_width, 0.25, 8.0)) return "outline width must be in 0.25..8 pixels";
  if (!in_range(o.crease_angle_deg, 0.0, 180.0)) return "crease angle must be in 0..180 degrees";
  if (std::isinf(o.cut_height)) return "cut height must be finite (or NaN for automatic)";
  for (const auto* colour : {&o.background, &o.outline_color}) {
    for (float c : *colour) {
      if (!in_range(c, 0.0, 1.0)) return "colours must have components in 0..1";
    }
  }
  return {};
}

double auto_cut_height(const shape::Building& building) {
  kernel::Bounds3 bounds;
  for (const shape::Part& part : building.parts) {
    const kernel::Bounds3 b = part_bounds(part);
    if (!b.empty()) bounds.add(b.min), bounds.add(b.max);
  }
  if (bounds.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (const double cut = storey_cut(building); !std::isnan(cut)) return cut;
  const double eave = eaves(building, bounds.max.z);
  if (const double floor = top_floor(building, eave - 0.5); std::isfinite(floor)) {
    return floor + std::min(kPlanCut, (eave - floor) / 2);
  }
  const double base = bounds.min.z;
  return std::max(base + std::min(kPlanCut, (eave - base) / 2), eave - kEavesClearance);
}

Image render(const shape::Scene& input, const RenderOptions& options) {
  if (!validate(options).empty()) return {};
  shape::Scene expanded;  // shared-mesh instances drawn as plain parts
  const shape::Scene& scene = shape::expand_instances(input, expanded);
  const int factor = options.supersample;
  raster::Framebuffer framebuffer(options.width * factor, options.height * factor);
  const raster::Camera camera =
      raster::fit_camera(scene, options, framebuffer.width(), framebuffer.height());
  raster::draw_scene(scene, options, camera, framebuffer);
  return framebuffer.resolve(factor, options);
}

std::string encode_png(const Image& image) {
  std::string bytes;
  if (image.empty()) return bytes;
  // Fixed compression settings keep the output byte-identical from run to run.
  const int ok = stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 4,
                                        image.pixels.data(), image.width * 4);
  if (ok == 0) bytes.clear();
  return bytes;
}

std::string write_png(const shape::Scene& scene, const std::filesystem::path& path,
                      const RenderOptions& options) {
  if (const std::string problem = validate(options); !problem.empty()) {
    return path.string() + ": cannot render: " + problem;
  }
  const std::string bytes = encode_png(render(scene, options));
  if (bytes.empty()) return path.string() + ": cannot encode the PNG image";
  return write_file_atomically(path, bytes);
}

}  // namespace insula::io
