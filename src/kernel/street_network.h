// Street networks: polylines in world XY that meet at shared vertices, and the surfaces derived
// from them, the geometry behind the graph nodes path.merge, path.to_shapes ("street to shape",
// seed 003 Fig. 10), path.buffer and path.decompose (graph-format.md §11). Decisions (ordering,
// tolerances, miter limit, dead ends, z) are in docs/street-networks.md.
//
// Planarity: merge_networks() welds near vertices and splits every crossing and T-junction, so
// that two edges of its result meet only at shared vertices. street_surfaces() merges first, then
// walks the faces of that planar graph (each half-edge continues with the next edge clockwise at
// its head, so dead ends are walked out and back) and keeps those of positive area.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::kernel {

// Vertices keep their z; edges are straight segments between two vertex indices, with a
// direction (kept by merge_networks) but no meaning attached to it. Edges whose indices are out of
// range, or that touch a vertex with a NaN or infinite coordinate, are ignored by every function
// below.
struct StreetNetwork {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 2>> edges;
};

// The default weld distance of path.merge, metres.
inline constexpr double kStreetMergeTolerance = 1e-3;
// street_surfaces() merges its input with this distance (the 2D booleans' grid) first.
inline constexpr double kStreetSurfaceTolerance = 1e-6;
// A join whose miter would reach farther than this many half-widths from the vertex is cut
// square at one half-width (turns sharper than 120 degrees); dead ends are such joins, so they
// end square, one half-width beyond the vertex. The same rule as offset()'s kMiter.
inline constexpr double kStreetMiterLimit = 2.0;

// One network from several, in the XY projection:
// - vertices with a NaN or infinite coordinate are dropped with their edges;
// - a vertex within `tolerance` (XY distance, metres; negative or NaN acts as 0) of an earlier
//   kept vertex is welded into it, which keeps its position and z;
// - an edge is split at every kept vertex within `tolerance` of its interior (T-junctions,
//   collinear overlaps) and at every proper crossing with another edge (a new vertex, welded like
//   the others, with z interpolated along the earlier of the two edges);
// - zero-length edges and repeats of an earlier edge (either direction) are dropped.
// The passes repeat until nothing changes (at most 8 times), so merging the result again changes
// nothing. Order: vertices in input order (networks, then their vertices) with crossing vertices
// after them in the order of the earlier crossing edge; edges in input order, each replaced by its
// pieces from its first vertex to its second. Isolated vertices are kept.
StreetNetwork merge_networks(std::span<const StreetNetwork> networks,
                             double tolerance = kStreetMergeTolerance);

enum class StreetStatus {
  kOk,
  kBadWidth,       // width NaN, infinite or not > 0
  kBooleanFailed,  // the 2D booleans refused (coordinates beyond kBooleanMaxExtent)
};
std::string_view to_string(StreetStatus status);

struct StreetSurfaces {
  // The union of every edge buffered by width/2: mitred joins (kStreetMiterLimit), square ends.
  // One polygon per group of overlapping buffers, normally one per connected network, with a hole
  // around each block; in boolean2d order (descending area, then lowest vertex).
  std::vector<Polygon> roads;
  // The bounded faces of the merged network minus `roads`: each face inset by width/2 with the
  // roads' joins, so roads and blocks tile the enclosed area without overlap. A face may give
  // several blocks or none; a dead end inside a face is cut out of its block. Ordered by anchor
  // (y, then x), the anchor being the leftmost of the outer ring's vertices within 1e-6 m of its
  // lowest y; each outer ring starts at its anchor and runs counter-clockwise.
  std::vector<Polygon> blocks;
  // The surfaces are flat at the lowest z of the vertices edges use (0 without edges).
  double z = 0;
  StreetStatus status = StreetStatus::kOk;  // not kOk: both lists empty
  bool ok() const { return status == StreetStatus::kOk; }
};

// Roads and blocks of `network` for a street width in metres (path.to_shapes).
StreetSurfaces street_surfaces(const StreetNetwork& network, double width);
// The roads part only, blocks left empty (path.buffer); cheaper, no face walk.
StreetSurfaces road_buffer(const StreetNetwork& network, double width);

// path.decompose: one two-vertex network per valid edge (in edge order, vertices in edge
// direction), and the vertices in order. No merging.
struct StreetParts {
  std::vector<StreetNetwork> edges;
  std::vector<Vec3> vertices;
};
StreetParts decompose(const StreetNetwork& network);

// path.grid: columns x rows vertices (counts; fewer than 1 gives an empty network), row by row
// from `origin` along +x then +y; edges for each vertex in order, to its right neighbour, then to
// the one above.
StreetNetwork grid_network(int columns, int rows, double spacing_x, double spacing_y,
                           Vec3 origin = {});

}  // namespace insula::kernel
