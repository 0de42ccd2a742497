#include "shape/uv_map.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>

namespace insula::shape {

std::vector<std::string> uv_attributes() {
  constexpr int kUvSets = 10;  // CityEngine's uv sets 0..9
  std::vector<std::string> names{std::string(kColormapAttribute)};
  for (int set = 0; set < kUvSets; ++set) {
    names.push_back(uv_set_attribute(set));
    names.push_back(uv_projection_attribute(set));
  }
  return names;
}

UvMap UvMap::then(double a, double b, double c, double d, double e, double f) const {
  UvMap out;
  out.du = du * a + dv * b;
  out.u0 = a * u0 + b * v0 + c;
  out.dv = du * d + dv * e;
  out.v0 = d * u0 + e * v0 + f;
  return out;
}

UvMap UvMap::moved(const kernel::Transform& t) const {
  // t(p) = R p + t.t with R's columns t.x, t.y, t.z orthonormal: the map of q is this map's of
  // R^T (q - t.t), so each gradient turns by R and the constant loses its value at t.t.
  const auto turn = [&](kernel::Vec3 g) { return t.x * g.x + t.y * g.y + t.z * g.z; };
  UvMap out;
  out.du = turn(du);
  out.u0 = u0 - dot(out.du, t.t);
  out.dv = turn(dv);
  out.v0 = v0 - dot(out.dv, t.t);
  return out;
}

std::string uv_set_attribute(int set) {
  return "#uv" + std::to_string(set);
}

std::string uv_projection_attribute(int set) {
  return "#uv" + std::to_string(set) + ".projection";
}

std::string encode(const UvMap& map) {
  const std::array<double, 8> v = {map.du.x, map.du.y, map.du.z, map.u0,
                                   map.dv.x, map.dv.y, map.dv.z, map.v0};
  std::string out;
  char buffer[32];
  for (double x : v) {
    const int n = std::snprintf(buffer, sizeof buffer, "%.17g", x);
    if (!out.empty()) out += ' ';
    out.append(buffer, static_cast<std::size_t>(n));
  }
  return out;
}

std::optional<UvMap> decode_uv_map(const Value& value) {
  const auto* text = std::get_if<std::string>(&value);
  if (text == nullptr || text->empty()) return std::nullopt;
  std::array<double, 8> v{};
  const char* p = text->data();
  const char* end = p + text->size();
  for (double& x : v) {
    while (p < end && *p == ' ') ++p;
    const auto [next, ec] = std::from_chars(p, end, x);
    if (ec != std::errc()) return std::nullopt;
    p = next;
  }
  if (p != end) return std::nullopt;
  return UvMap{{v[0], v[1], v[2]}, v[3], {v[4], v[5], v[6]}, v[7]};
}

std::optional<UvRange> uv_range(const UvMap& map, std::span<const kernel::Vec3> world_points) {
  if (world_points.empty()) return std::nullopt;
  UvRange r{map.at(world_points.front()), map.at(world_points.front())};
  for (const kernel::Vec3& p : world_points) {
    const kernel::Vec2 t = map.at(p);
    r.min = {std::min(r.min.x, t.x), std::min(r.min.y, t.y)};
    r.max = {std::max(r.max.x, t.x), std::max(r.max.y, t.y)};
  }
  return r;
}

}  // namespace insula::shape
