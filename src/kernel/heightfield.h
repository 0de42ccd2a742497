// Terrain heightfields: a regular grid of heights over world XY, the surface behind the graph
// nodes terrain.create, terrain.noise, terrain.smooth, terrain.level and terrain.place (seed 003
// §5.1: "surface manipulation (e.g., noise, smoothing, and leveling)"; docs/graph-executor.md,
// "Terrain"). The surface between samples is bilinear for lookups; its mesh has two triangles per
// cell, whose corners are the samples, so a cell whose four corners agree is flat in both.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::kernel {

struct Heightfield {
  Vec2 origin;    // world XY of sample (0, 0)
  double dx = 1;  // spacing of samples along x and y, metres
  double dy = 1;
  int nx = 0;  // samples along x (columns) and y (rows), at least 2 each
  int ny = 0;
  std::vector<double> z;  // row by row: sample (i, j) is z[j * nx + i]
  // Cells whose centre lies inside a road levelled into the field (level()), row by row like the
  // cells; empty when no road was.
  std::vector<std::uint8_t> road;

  double& at(int i, int j) { return z[static_cast<std::size_t>(j) * nx + i]; }
  double at(int i, int j) const { return z[static_cast<std::size_t>(j) * nx + i]; }
  Vec2 point(int i, int j) const { return {origin.x + i * dx, origin.y + j * dy}; }
  double width() const { return (nx - 1) * dx; }
  double depth() const { return (ny - 1) * dy; }
  std::size_t cells() const { return static_cast<std::size_t>(nx - 1) * (ny - 1); }
};

// More samples than this is refused (about 128 MB of heights).
inline constexpr std::size_t kHeightfieldMaxSamples = std::size_t{1} << 24;

// A flat field at `height` covering width x depth metres from `origin`, with samples at most
// `cell` apart (the spacing is width / ceil(width / cell), so the extent is exact). nullopt with
// `error` for a size or cell that is not finite and positive, or too many samples.
std::optional<Heightfield> make_heightfield(Vec2 origin, double width, double depth, double cell,
                                            double height, std::string& error);

// The bilinear height at world (x, y); points outside the grid take the height at the nearest
// point of its border.
double height_at(const Heightfield& field, double x, double y);

struct NoiseParams {
  double amplitude = 1;    // the sum never leaves [-amplitude, amplitude]
  double wavelength = 50;  // of the first octave, metres
  int octaves = 4;         // each one half the wavelength and half the amplitude of the last
  std::uint64_t seed = 0;
};
// Fractal gradient noise (fBm) at world (x, y): a function of the point and the parameters only.
double fbm(const NoiseParams& params, double x, double y);
// Adds fbm() to every sample.
void add_noise(Heightfield& field, const NoiseParams& params);

// `iterations` passes of the 3x3 binomial filter (1 2 1 / 2 4 2 / 1 2 1, /16; a Gaussian of
// sigma about 0.7 cells per pass), the border clamped.
void smooth(Heightfield& field, int iterations);

// What levelling flattens. A footprint is flattened to one height: the mean of the samples under
// it (a sample is under a footprint when it lies within one cell diagonal of it, so every cell
// the footprint touches has four equal corners and the surface is exactly flat over the whole
// footprint). Footprints whose samples overlap form one plateau at their common mean (a row of
// adjoining lots becomes one terrace). Roads are flattened across but follow the terrain along:
// a road sample takes the mean of the road samples within 2 * margin of it. Around both, the
// terrain blends back to its own height over `margin` (smoothstep of the distance), roads first,
// then footprints, whose plateaus win where they meet a road; footprint blending leaves road
// samples alone.
struct Levelling {
  std::span<const Polygon> footprints;
  std::span<const Polygon> roads;
  double margin = 5;
};
// The plateau height of each footprint (its group's), in input order; a footprint with no
// sample under it (outside the grid) keeps the terrain and reports the height at its centroid.
std::vector<double> level(Heightfield& field, const Levelling& levelling);

// Two triangles per cell (the diagonal from (i, j) to (i + 1, j + 1)), counter-clockwise seen
// from above, tagged kGroundSurface with face id 0 and material `ground`, or `road` for road
// cells; vertices are the samples, row by row.
Mesh heightfield_mesh(const Heightfield& field, MaterialId ground = 0, MaterialId road = 0);

}  // namespace insula::kernel
