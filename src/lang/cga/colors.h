// Colours as CGA writes them: "#rrggbb" (and CityEngine's "#rgb", "#rrggbbaa"), and CityEngine's
// colour functions (colorRGBToHex, colorHSVToHex, colorHexToR ... colorHexToO).
#pragma once

#include <array>
#include <optional>
#include <string>

namespace insula::lang::cga {

// "#rrggbb" ("#rrggbbaa" with `alpha`) of components in [0, 1] (clamped).
std::string hex_color(double r, double g, double b, double a, bool alpha);
// "#rgb" and "#rgba" (CSS's short forms, which CityEngine files use) as "#rrggbb[aa]".
std::string long_hex(const std::string& s);
bool valid_hex_color(const std::string& s);
// r, g, b, opacity in [0, 1] of "#rrggbb[aa]" (or a short form); nullopt when not a colour.
std::optional<std::array<double, 4>> rgba_of_hex(const std::string& s);
// HSV (h in degrees, s and v in [0, 1]) to RGB and back (h in [0, 360)).
std::array<double, 3> rgb_of_hsv(double h, double s, double v);
std::array<double, 3> hsv_of_rgb(double r, double g, double b);
// CityEngine's colorRamp(gradient, value): "#rrggbb" at `value` (clamped to [0, 1]) along the
// named ramp; nullopt for an unknown name. The ramps' stops are Insula's (CityEngine's are
// shown only as pictures): two or three colours, linear in RGB; spectrum runs the hue.
std::optional<std::string> color_ramp(const std::string& name, double value);

}  // namespace insula::lang::cga
