// Mesh cleanup after CityEngine's cleanupGeometry: merge close vertices, drop duplicate and
// degenerate faces, merge coplanar neighbours and drop collinear vertices, without opening a mesh
// that was closed.
#pragma once

#include "kernel/mesh.h"

namespace insula::kernel {

struct CleanupOptions {
  double merge_distance = 1e-7;  // vertices closer than this are merged
  double angle_degrees = 0;      // collinear / coplanar within this angle (0: exactly, 1e-6 rad)
  double max_area = 0;           // faces with at most this area are degenerate (0: 1e-12 m²)
  bool faces = true;             // duplicate and degenerate faces
  bool edges = true;             // edges between coplanar faces of the same tag
  bool vertices = true;          // collinear vertices between two edges
};

// The cleaned mesh; a mesh that was closed stays closed (a face whose removal would open it is
// kept).
Mesh cleanup(const Mesh& mesh, const CleanupOptions& options);

}  // namespace insula::kernel
