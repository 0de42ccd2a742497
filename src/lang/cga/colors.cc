#include "lang/cga/colors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace insula::lang::cga {

std::string hex_color(double r, double g, double b, double a, bool alpha) {
  const auto byte = [](double v) {
    return static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
  };
  char text[16];
  if (alpha) {
    std::snprintf(text, sizeof text, "#%02x%02x%02x%02x", byte(r), byte(g), byte(b), byte(a));
  } else {
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(r), byte(g), byte(b));
  }
  return text;
}

std::string long_hex(const std::string& s) {
  if ((s.size() != 4 && s.size() != 5) || s[0] != '#') return s;
  std::string out = "#";
  for (std::size_t i = 1; i < s.size(); ++i) out.append(2, s[i]);
  return out;
}

bool valid_hex_color(const std::string& s) {
  if (s.size() != 7 && s.size() != 9) return false;
  if (s[0] != '#') return false;
  return std::all_of(s.begin() + 1, s.end(),
                     [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; });
}

std::optional<std::array<double, 4>> rgba_of_hex(const std::string& s) {
  const std::string hex = long_hex(s);
  if (!valid_hex_color(hex)) return std::nullopt;
  std::array<double, 4> c{0, 0, 0, 1};
  for (std::size_t k = 0; k * 2 + 1 < hex.size(); ++k) {
    c[k] = static_cast<double>(std::stoul(hex.substr(1 + k * 2, 2), nullptr, 16)) / 255.0;
  }
  return c;
}

std::array<double, 3> rgb_of_hsv(double h, double s, double v) {
  h = std::fmod(std::fmod(h, 360) + 360, 360) / 60;
  s = std::clamp(s, 0.0, 1.0);
  v = std::clamp(v, 0.0, 1.0);
  const double c = v * s;
  const double x = c * (1 - std::fabs(std::fmod(h, 2) - 1));
  const double m = v - c;
  const int sector = static_cast<int>(h);
  const std::array<double, 3> rgb = sector == 0   ? std::array{c, x, 0.0}
                                    : sector == 1 ? std::array{x, c, 0.0}
                                    : sector == 2 ? std::array{0.0, c, x}
                                    : sector == 3 ? std::array{0.0, x, c}
                                    : sector == 4 ? std::array{x, 0.0, c}
                                                  : std::array{c, 0.0, x};
  return {rgb[0] + m, rgb[1] + m, rgb[2] + m};
}

std::array<double, 3> hsv_of_rgb(double r, double g, double b) {
  const double max = std::max({r, g, b});
  const double min = std::min({r, g, b});
  const double d = max - min;
  double h = 0;
  if (d > 0) {
    if (max == r) {
      h = 60 * std::fmod((g - b) / d, 6);
    } else if (max == g) {
      h = 60 * ((b - r) / d + 2);
    } else {
      h = 60 * ((r - g) / d + 4);
    }
  }
  if (h < 0) h += 360;
  return {h, max > 0 ? d / max : 0, max};
}

}  // namespace insula::lang::cga

namespace insula::lang::cga {

namespace {

struct Ramp {
  std::string_view name;
  std::array<std::array<double, 3>, 3> stops;  // colours at 0, 0.5 and 1
};

// Stops chosen to read as the names say: sequential ramps through their middle colour,
// diverging ones (x to blue) through a light grey.
constexpr std::array<Ramp, 6> kRamps = {{
    {"whiteToBlack", {{{1, 1, 1}, {0.5, 0.5, 0.5}, {0, 0, 0}}}},
    {"greenToRed", {{{0, 0.7, 0}, {1, 0.85, 0}, {0.85, 0, 0}}}},
    {"yellowToRed", {{{1, 1, 0.6}, {1, 0.6, 0.1}, {0.8, 0, 0}}}},
    {"redToBlue", {{{0.8, 0.1, 0.1}, {0.95, 0.95, 0.95}, {0.1, 0.3, 0.8}}}},
    {"orangeToBlue", {{{0.95, 0.5, 0.05}, {0.95, 0.95, 0.95}, {0.1, 0.3, 0.8}}}},
    {"brownToBlue", {{{0.55, 0.3, 0.05}, {0.95, 0.95, 0.95}, {0.1, 0.3, 0.8}}}},
}};

}  // namespace

std::optional<std::string> color_ramp(const std::string& name, double value) {
  const double t = std::isfinite(value) ? std::clamp(value, 0.0, 1.0) : 0.0;
  if (name == "spectrum") {  // violet-blue at 0 through green and yellow to red at 1
    const auto [r, g, b] = rgb_of_hsv(270 * (1 - t), 1, 1);
    return hex_color(r, g, b, 1, false);
  }
  for (const Ramp& ramp : kRamps) {
    if (ramp.name != name) continue;
    const std::size_t k = t < 0.5 ? 0 : 1;
    const double u = t < 0.5 ? t * 2 : (t - 0.5) * 2;
    std::array<double, 3> c{};
    for (std::size_t i = 0; i < 3; ++i) {
      c[i] = ramp.stops[k][i] + (ramp.stops[k + 1][i] - ramp.stops[k][i]) * u;
    }
    return hex_color(c[0], c[1], c[2], 1, false);
  }
  return std::nullopt;
}

}  // namespace insula::lang::cga
