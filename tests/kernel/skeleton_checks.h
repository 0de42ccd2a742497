// Checks of a Skeleton's invariants (kernel/skeleton.h) shared by the skeleton tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "kernel/polygon.h"
#include "kernel/skeleton.h"

namespace insula::kernel::testing_skeleton {

inline Ring face_ring(const Skeleton& s, std::size_t e) {
  Ring ring;
  for (std::uint32_t v : s.face(e)) ring.push_back(s.vertices[v].position);
  return ring;
}

// Every face starts with its contour edge and runs counter-clockwise, every face vertex lies at
// its time above the face's edge line (tolerance relative to the roof's height and to the
// outline's distance from the origin), and the faces tile the polygon.
inline void expect_valid(const Polygon& polygon, const Skeleton& s, const std::string& what) {
  ASSERT_EQ(s.face_count(), s.contour_count) << what;
  double height = 0, far = 0;
  for (Vec2 p : polygon.outer) far = std::max({far, std::abs(p.x), std::abs(p.y)});
  for (const SkeletonVertex& v : s.vertices) height = std::max(height, v.time);
  const double tolerance = 1e-9 * std::max(height, 1e-300) + 1e-13 * far;
  const double polygon_area = area(polygon);
  double total = 0;
  for (std::uint32_t e = 0; e < s.contour_count; ++e) {
    const auto face = s.face(e);
    ASSERT_GE(face.size(), 3U) << what;
    EXPECT_EQ(face[0], e) << what;
    EXPECT_EQ(face[1], s.next_contour(e)) << what;
    const Vec2 a = s.vertices[e].position;
    const Vec2 d = normalized(s.vertices[s.next_contour(e)].position - a);
    for (std::uint32_t v : face) {
      EXPECT_NEAR(cross(d, s.vertices[v].position - a), s.vertices[v].time, tolerance)
          << what << " face " << e;
    }
    const double face_area = signed_area(face_ring(s, e));
    EXPECT_GT(face_area, 0) << what << " face " << e;
    total += face_area;
  }
  EXPECT_NEAR(total, polygon_area, 1e-9 * polygon_area) << what;
}

// `ours` is `reference` (CGAL's general builder) face by face: the same roof height and every
// face's area alike, within the rounding both builders carry.
inline void expect_matches(const Polygon& polygon, const Skeleton& ours, const Skeleton& reference,
                           const std::string& what) {
  const double polygon_area = area(polygon);
  // Far from the origin the input coordinates themselves carry an ulp of the largest coordinate
  // (2e-9 at 1e7), and both builders round their nodes to it: times may differ by a few such
  // ulps and face areas by a few ulps times the face's perimeter, beyond the relative tolerances.
  double far = 0;
  for (Vec2 v : polygon.outer) far = std::max({far, std::abs(v.x), std::abs(v.y)});
  const double ulp = 4 * std::numeric_limits<double>::epsilon() * far;
  EXPECT_NEAR(ours.max_time(), reference.max_time(), 1e-9 * reference.max_time() + ulp) << what;
  ASSERT_EQ(ours.contour_count, reference.contour_count) << what;
  int wrong_faces = 0;
  for (std::uint32_t e = 0; e < ours.contour_count; ++e) {
    const double a = signed_area(face_ring(ours, e));
    const double b = signed_area(face_ring(reference, e));
    const Ring ring = face_ring(reference, e);
    double face_perimeter = 0;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      face_perimeter += length(ring[(k + 1) % ring.size()] - ring[k]);
    }
    if (!(std::abs(a - b) <= 1e-7 * polygon_area + ulp * face_perimeter)) {
      if (++wrong_faces <= 3) {
        ADD_FAILURE() << what << " face " << e << ": area " << a << ", CGAL " << b;
      }
    }
  }
  EXPECT_EQ(wrong_faces, 0) << what;
}

}  // namespace insula::kernel::testing_skeleton
