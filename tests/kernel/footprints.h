// Footprints shared by the kernel's roof and mass tests.
#pragma once

#include <cmath>

#include "kernel/polygon.h"

namespace insula::kernel::testing_footprints {

// A regular n-gon of circumradius r about the origin, counter-clockwise.
inline Polygon circle(int n, double r) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / n;
    p.outer.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

}  // namespace insula::kernel::testing_footprints
