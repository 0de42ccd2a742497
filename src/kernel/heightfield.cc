#include "kernel/heightfield.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace insula::kernel {
namespace {

std::uint64_t mix(std::uint64_t x) {
  // splitmix64's finaliser: every input bit reaches every output bit.
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31U);
}

// Eight unit gradients from a table, so the noise is the same bits wherever it runs (no libm).
constexpr double kHalfRoot2 = 0.70710678118654752440;
constexpr Vec2 kGradients[8] = {{1, 0},
                                {0, 1},
                                {-1, 0},
                                {0, -1},
                                {kHalfRoot2, kHalfRoot2},
                                {-kHalfRoot2, kHalfRoot2},
                                {-kHalfRoot2, -kHalfRoot2},
                                {kHalfRoot2, -kHalfRoot2}};

double fade(double t) {
  return t * t * t * (t * (t * 6 - 15) + 10);
}

// Perlin's gradient noise in [-sqrt(2)/2, sqrt(2)/2] (the bound for unit gradients in 2D).
double gradient_noise(std::uint64_t key, double x, double y) {
  const double fx = std::floor(x);
  const double fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx);
  const auto iy = static_cast<std::int64_t>(fy);
  const double u = x - fx;
  const double v = y - fy;
  const auto corner = [&](std::int64_t cx, std::int64_t cy, double ox, double oy) {
    const std::uint64_t h = mix(key ^ mix(static_cast<std::uint64_t>(cx) * 0x632be59bd9b4e019ULL ^
                                          static_cast<std::uint64_t>(cy)));
    const Vec2 g = kGradients[h & 7U];
    return g.x * ox + g.y * oy;
  };
  const double n00 = corner(ix, iy, u, v);
  const double n10 = corner(ix + 1, iy, u - 1, v);
  const double n01 = corner(ix, iy + 1, u, v - 1);
  const double n11 = corner(ix + 1, iy + 1, u - 1, v - 1);
  const double su = fade(u);
  const double sv = fade(v);
  const double a = n00 + (n10 - n00) * su;
  const double b = n01 + (n11 - n01) * su;
  return a + (b - a) * sv;
}

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// 0 inside or on the polygon, else the distance to its nearest edge.
double distance_to(const Polygon& polygon, Vec2 p) {
  if (locate(polygon, p) != PointLocation::kOutside) return 0;
  double best = std::numeric_limits<double>::infinity();
  const auto ring_distance = [&](const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      best = std::min(best, squared_distance_to_segment(p, ring[k], ring[(k + 1) % ring.size()]));
    }
  };
  ring_distance(polygon.outer);
  for (const Ring& hole : polygon.holes) ring_distance(hole);
  return std::sqrt(best);
}

struct SampleRange {
  int i0 = 0, i1 = -1, j0 = 0, j1 = -1;  // inclusive; empty when i1 < i0 or j1 < j0
};

// The samples whose points lie within `pad` of the polygon's bounds.
SampleRange samples_near(const Heightfield& f, const Polygon& polygon, double pad) {
  const Bounds2 b = bounds(polygon);
  SampleRange r;
  if (b.empty()) return r;
  r.i0 = std::max(0, static_cast<int>(std::ceil((b.min.x - pad - f.origin.x) / f.dx)));
  r.i1 = std::min(f.nx - 1, static_cast<int>(std::floor((b.max.x + pad - f.origin.x) / f.dx)));
  r.j0 = std::max(0, static_cast<int>(std::ceil((b.min.y - pad - f.origin.y) / f.dy)));
  r.j1 = std::min(f.ny - 1, static_cast<int>(std::floor((b.max.y + pad - f.origin.y) / f.dy)));
  return r;
}

bool usable(const Polygon& polygon) {
  if (polygon.outer.size() < 3) return false;
  for (const Vec2& p : polygon.outer) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  }
  return true;
}

// For every sample: the least distance to any of `polygons` (infinity beyond `pad`) and which
// polygon that is (-1 for none).
struct Nearest {
  std::vector<double> distance;
  std::vector<int> polygon;
};
Nearest nearest_polygons(const Heightfield& f, std::span<const Polygon> polygons, double pad) {
  Nearest n;
  n.distance.assign(f.z.size(), std::numeric_limits<double>::infinity());
  n.polygon.assign(f.z.size(), -1);
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    if (!usable(polygons[p])) continue;
    const SampleRange r = samples_near(f, polygons[p], pad);
    for (int j = r.j0; j <= r.j1; ++j) {
      for (int i = r.i0; i <= r.i1; ++i) {
        const double d = distance_to(polygons[p], f.point(i, j));
        const std::size_t k = static_cast<std::size_t>(j) * f.nx + i;
        if (d <= pad && d < n.distance[k]) {
          n.distance[k] = d;
          n.polygon[k] = static_cast<int>(p);
        }
      }
    }
  }
  return n;
}

// Union-find over footprints: footprints sharing a sample form one plateau.
int find(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

void level_roads(Heightfield& f, std::span<const Polygon> roads, double margin, double reach) {
  if (roads.empty()) return;
  const Nearest near = nearest_polygons(f, roads, reach + margin);
  std::vector<char> road(f.z.size(), 0);
  for (std::size_t k = 0; k < f.z.size(); ++k) road[k] = near.distance[k] <= reach ? 1 : 0;
  f.road.resize(f.cells(), 0);
  for (int j = 0; j + 1 < f.ny; ++j) {
    for (int i = 0; i + 1 < f.nx; ++i) {
      const Vec2 centre = f.point(i, j) + Vec2{f.dx / 2, f.dy / 2};
      for (const Polygon& surface : roads) {
        if (usable(surface) && locate(surface, centre) == PointLocation::kInside) {
          f.road[static_cast<std::size_t>(j) * (f.nx - 1) + i] = 1;
          break;
        }
      }
    }
  }
  // Along the road: the mean of road samples within the window.
  const double radius = std::max(2 * margin, std::max(f.dx, f.dy));
  const int ri = static_cast<int>(radius / f.dx);
  const int rj = static_cast<int>(radius / f.dy);
  std::vector<double> target(f.z.size(), 0);
  for (int j = 0; j < f.ny; ++j) {
    for (int i = 0; i < f.nx; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * f.nx + i;
      if (road[k] == 0) continue;
      double sum = 0;
      int count = 0;
      for (int b = std::max(0, j - rj); b <= std::min(f.ny - 1, j + rj); ++b) {
        for (int a = std::max(0, i - ri); a <= std::min(f.nx - 1, i + ri); ++a) {
          const std::size_t q = static_cast<std::size_t>(b) * f.nx + a;
          const double ox = (a - i) * f.dx;
          const double oy = (b - j) * f.dy;
          if (road[q] == 0 || ox * ox + oy * oy > radius * radius) continue;
          sum += f.z[q];
          ++count;
        }
      }
      target[k] = sum / count;
    }
  }
  // Around the road: towards the nearest road sample's height.
  const int mi = static_cast<int>(std::ceil((reach + margin) / f.dx));
  const int mj = static_cast<int>(std::ceil((reach + margin) / f.dy));
  std::vector<double> out = f.z;
  for (int j = 0; j < f.ny; ++j) {
    for (int i = 0; i < f.nx; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * f.nx + i;
      if (road[k] != 0) {
        out[k] = target[k];
        continue;
      }
      if (near.polygon[k] < 0 || margin <= 0) continue;
      double best = std::numeric_limits<double>::infinity();
      double height = 0;
      for (int b = std::max(0, j - mj); b <= std::min(f.ny - 1, j + mj); ++b) {
        for (int a = std::max(0, i - mi); a <= std::min(f.nx - 1, i + mi); ++a) {
          const std::size_t q = static_cast<std::size_t>(b) * f.nx + a;
          if (road[q] == 0) continue;
          const double ox = (a - i) * f.dx;
          const double oy = (b - j) * f.dy;
          if (ox * ox + oy * oy < best) {
            best = ox * ox + oy * oy;
            height = target[q];
          }
        }
      }
      if (!std::isfinite(best)) continue;
      const double t = smoothstep((near.distance[k] - reach) / margin);
      out[k] = height + (f.z[k] - height) * t;
    }
  }
  f.z = std::move(out);
}

}  // namespace

std::optional<Heightfield> make_heightfield(Vec2 origin, double width, double depth, double cell,
                                            double height, std::string& error) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(width) || !positive(depth)) {
    error = "a terrain needs a finite, positive width and depth";
    return std::nullopt;
  }
  if (!positive(cell)) {
    error = "a terrain's cell size must be finite and positive";
    return std::nullopt;
  }
  if (!std::isfinite(height) || !std::isfinite(origin.x) || !std::isfinite(origin.y)) {
    error = "a terrain's origin and height must be finite";
    return std::nullopt;
  }
  const double cx = std::ceil(width / cell - 1e-9);
  const double cy = std::ceil(depth / cell - 1e-9);
  if ((cx + 1) * (cy + 1) > static_cast<double>(kHeightfieldMaxSamples)) {
    error = "a terrain of " + std::to_string(static_cast<long long>(cx + 1)) + " x " +
            std::to_string(static_cast<long long>(cy + 1)) + " samples is more than " +
            std::to_string(kHeightfieldMaxSamples) + "; use a larger cell";
    return std::nullopt;
  }
  Heightfield f;
  f.origin = origin;
  f.nx = static_cast<int>(std::max(1.0, cx)) + 1;
  f.ny = static_cast<int>(std::max(1.0, cy)) + 1;
  f.dx = width / (f.nx - 1);
  f.dy = depth / (f.ny - 1);
  f.z.assign(static_cast<std::size_t>(f.nx) * f.ny, height);
  return f;
}

double height_at(const Heightfield& f, double x, double y) {
  const double u = std::clamp((x - f.origin.x) / f.dx, 0.0, static_cast<double>(f.nx - 1));
  const double v = std::clamp((y - f.origin.y) / f.dy, 0.0, static_cast<double>(f.ny - 1));
  const int i = std::min(static_cast<int>(u), f.nx - 2);
  const int j = std::min(static_cast<int>(v), f.ny - 2);
  const double s = u - i;
  const double t = v - j;
  const double a = f.at(i, j) + (f.at(i + 1, j) - f.at(i, j)) * s;
  const double b = f.at(i, j + 1) + (f.at(i + 1, j + 1) - f.at(i, j + 1)) * s;
  return a + (b - a) * t;
}

double fbm(const NoiseParams& p, double x, double y) {
  if (p.octaves <= 0 || !(p.wavelength > 0)) return 0;
  double sum = 0;
  double weights = 0;
  double weight = 1;
  double wavelength = p.wavelength;
  for (int o = 0; o < p.octaves; ++o) {
    const std::uint64_t key = mix(p.seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(o));
    sum += weight * gradient_noise(key, x / wavelength, y / wavelength);
    weights += weight;
    weight /= 2;
    wavelength /= 2;
  }
  // Each octave is within sqrt(2)/2, so the weighted mean times sqrt(2) is within 1.
  return p.amplitude * std::sqrt(2.0) * sum / weights;
}

void add_noise(Heightfield& f, const NoiseParams& params) {
  for (int j = 0; j < f.ny; ++j) {
    for (int i = 0; i < f.nx; ++i) {
      const Vec2 p = f.point(i, j);
      f.at(i, j) += fbm(params, p.x, p.y);
    }
  }
}

void smooth(Heightfield& f, int iterations) {
  std::vector<double> pass(f.z.size());
  for (int it = 0; it < iterations; ++it) {
    // Separable: rows into `pass`, then columns back into z.
    for (int j = 0; j < f.ny; ++j) {
      for (int i = 0; i < f.nx; ++i) {
        const double l = f.at(std::max(0, i - 1), j);
        const double r = f.at(std::min(f.nx - 1, i + 1), j);
        pass[static_cast<std::size_t>(j) * f.nx + i] = (l + 2 * f.at(i, j) + r) / 4;
      }
    }
    for (int j = 0; j < f.ny; ++j) {
      const std::size_t below = static_cast<std::size_t>(std::max(0, j - 1)) * f.nx;
      const std::size_t here = static_cast<std::size_t>(j) * f.nx;
      const std::size_t above = static_cast<std::size_t>(std::min(f.ny - 1, j + 1)) * f.nx;
      for (int i = 0; i < f.nx; ++i) {
        f.z[here + i] = (pass[below + i] + 2 * pass[here + i] + pass[above + i]) / 4;
      }
    }
  }
}

std::vector<double> level(Heightfield& f, const Levelling& l) {
  const double margin = std::isfinite(l.margin) ? std::max(0.0, l.margin) : 0.0;
  const double reach = std::hypot(f.dx, f.dy) * (1 + 1e-9);
  level_roads(f, l.roads, margin, reach);

  const std::span<const Polygon> fp = l.footprints;
  std::vector<double> plateau(fp.size());
  for (std::size_t p = 0; p < fp.size(); ++p) {
    const Vec2 c = usable(fp[p]) ? centroid(fp[p]) : Vec2{};
    plateau[p] = height_at(f, c.x, c.y);
  }
  if (fp.empty()) return plateau;
  const Nearest near = nearest_polygons(f, fp, reach + margin);
  // Plateaus: footprints that claim a common sample are one group.
  std::vector<int> group(fp.size());
  std::iota(group.begin(), group.end(), 0);
  std::vector<int> owner(f.z.size(), -1);
  for (std::size_t p = 0; p < fp.size(); ++p) {
    if (!usable(fp[p])) continue;
    const SampleRange r = samples_near(f, fp[p], reach);
    for (int j = r.j0; j <= r.j1; ++j) {
      for (int i = r.i0; i <= r.i1; ++i) {
        const std::size_t k = static_cast<std::size_t>(j) * f.nx + i;
        if (distance_to(fp[p], f.point(i, j)) > reach) continue;
        if (owner[k] < 0) {
          owner[k] = static_cast<int>(p);
        } else {
          group[find(group, owner[k])] = find(group, static_cast<int>(p));
        }
      }
    }
  }
  std::vector<double> sum(fp.size(), 0);
  std::vector<std::size_t> count(fp.size(), 0);
  for (std::size_t k = 0; k < f.z.size(); ++k) {
    if (owner[k] < 0) continue;
    const int g = find(group, owner[k]);
    sum[g] += f.z[k];
    ++count[g];
  }
  std::vector<double> target(fp.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t p = 0; p < fp.size(); ++p) {
    const int g = find(group, static_cast<int>(p));
    if (count[g] == 0) continue;
    target[p] = sum[g] / static_cast<double>(count[g]);
    plateau[p] = target[p];
  }
  // Road samples (within reach of a road) keep the road's levelling outside the plateaus.
  const Nearest roads = nearest_polygons(f, l.roads, reach);
  for (std::size_t k = 0; k < f.z.size(); ++k) {
    if (owner[k] >= 0) {
      f.z[k] = target[owner[k]];
    } else if (near.polygon[k] >= 0 && roads.polygon[k] < 0 && margin > 0) {
      const double t = target[near.polygon[k]];
      if (std::isnan(t)) continue;
      f.z[k] = t + (f.z[k] - t) * smoothstep((near.distance[k] - reach) / margin);
    }
  }
  return plateau;
}

Mesh heightfield_mesh(const Heightfield& f, MaterialId ground, MaterialId road) {
  Mesh mesh;
  if (f.nx < 2 || f.ny < 2) return mesh;
  const std::size_t cells = f.cells();
  mesh.reserve(f.z.size(), 2 * cells, 6 * cells);
  for (int j = 0; j < f.ny; ++j) {
    for (int i = 0; i < f.nx; ++i) {
      const Vec2 p = f.point(i, j);
      mesh.add_vertex({p.x, p.y, f.at(i, j)});
    }
  }
  const auto nx = static_cast<std::uint32_t>(f.nx);
  std::size_t cell = 0;
  for (std::uint32_t j = 0; j + 1 < static_cast<std::uint32_t>(f.ny); ++j) {
    for (std::uint32_t i = 0; i + 1 < nx; ++i, ++cell) {
      const bool on_road = !f.road.empty() && f.road[cell] != 0;
      const FaceTag tag{SemanticClass::kGroundSurface, on_road ? road : ground, 0};
      const std::uint32_t a = j * nx + i;
      mesh.add_face({a, a + 1, a + nx + 1}, tag);
      mesh.add_face({a, a + nx + 1, a + nx}, tag);
    }
  }
  return mesh;
}

}  // namespace insula::kernel
