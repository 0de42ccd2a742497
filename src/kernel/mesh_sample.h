// Points on and inside a polygon mesh, for scattering (CityEngine's scatter operation: points on
// the faces, area-weighted, or inside a closed mesh). The faces are triangulated in their planes
// once; a surface point is then one binary search over the running triangle areas and two numbers
// in [0, 1). The kernel draws no random numbers itself: callers pass their own (shape/rng.h), so
// the same numbers give the same points.
#pragma once

#include <cstddef>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/vec.h"

namespace insula::kernel {

struct SurfacePoint {
  Vec3 position;
  Vec3 normal;  // the unit outward normal of the face the point lies on
  std::size_t face = 0;
};

class MeshSurface {
 public:
  // Triangulates every face of `mesh` (faces of zero area are left out).
  explicit MeshSurface(const Mesh& mesh);

  double area() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
  bool empty() const { return !(area() > 0); }

  // The point at area fraction `pick` of the surface, at (u, v) inside its triangle; uniform over
  // the surface when pick, u and v are uniform in [0, 1). Requires !empty().
  SurfacePoint at(double pick, double u, double v) const;
  // The surface point nearest to `p` (ties: the first triangle). Requires !empty().
  SurfacePoint nearest(Vec3 p) const;
  // The generalized winding number of `p` (Jacobson, Kavan, Sorkine-Hornung: "Robust
  // Inside-Outside Segmentation using Generalized Winding Numbers", SIGGRAPH 2013): the sum of
  // the solid angles of the triangles seen from p over 4 pi. About 1 inside a closed,
  // outward-oriented mesh and 0 outside, without the ray casting's trouble at edges and vertices.
  double winding_number(Vec3 p) const;

 private:
  struct Triangle {
    Vec3 a;
    Vec3 b;
    Vec3 c;
    Vec3 normal;
    std::size_t face = 0;
  };
  void add_face(const Mesh& mesh, std::size_t face);
  void add_triangle(Vec3 a, Vec3 b, Vec3 c, Vec3 normal, std::size_t face);

  std::vector<Triangle> triangles_;
  std::vector<double> cumulative_;  // running sum of the triangle areas
};

// The point of triangle abc nearest to p.
Vec3 closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c);

}  // namespace insula::kernel
