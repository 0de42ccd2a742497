// Automatic texture coordinates (seed 001 §3.6: "When using the solidGeometry operation, a surface
// parameterization is automatically generated for the geometry"): a planar projection per face,
// u along the face's horizontal direction and v up the face (world z up), in meters divided by the
// texture size, so bricks and tiles keep their size and line up across coplanar faces.
#pragma once

#include "kernel/vec.h"

namespace insula::kernel {

// Texture coordinates of point `p` on a face with unit normal `normal`; `scale` meters per
// texture repeat (> 0). Horizontal faces use world x and y.
Vec2 planar_uv(Vec3 p, Vec3 normal, double scale);

}  // namespace insula::kernel
