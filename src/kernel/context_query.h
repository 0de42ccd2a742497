// Context-aware queries of procedural content graphs (seed 003, §4.4-§4.5 and §6.1; the graph
// format's `query.*` nodes, docs/graph-format.md §11): pure functions over plain geometry that the
// graph executor wraps as nodes. Each takes every source and every target at once, so it can
// build one spatial index over the targets ("this node can organize and optimize the verification
// internally using spatial data structures", seed 003, §4.5). docs/context-queries.md records the
// decisions, the acceleration structures and their cost.
//
// Every query but k-means takes a SkipPredicate: skip(source, target) true means the pair is not
// considered at all (the executor skips an entity's own ancestors and descendants, graph format
// §9.10). An empty predicate skips nothing. Ties between equally near targets go to the lower
// target index, so results do not depend on the order the indices visit candidates.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/solids.h"
#include "kernel/vec.h"

namespace insula::kernel {

using SkipPredicate = std::function<bool(std::size_t source, std::size_t target)>;

// ---- Clustering (seed 003, §4.4, Fig. 7) ----

struct KMeansResult {
  std::vector<int> cluster;   // per point, in [0, centers.size())
  std::vector<Vec3> centers;  // the mean of each cluster's points (see kmeans)
  int iterations = 0;         // assignment passes made, including the one that changed nothing
};

// Lloyd's k-means. The initial centroids are the first k points (the paper picks "the first
// entities as source for the initial cluster centroids", so callers shuffle for randomness); k
// larger than the number of points acts as that number, and k < 1 gives no centers and no
// assignments. Each pass assigns every point to its nearest center (squared distance; a tie goes to
// the lower cluster index), then moves each center to the mean of its points, summed in point
// order; a cluster left without points keeps its center. Stops after a pass that changes no
// assignment or after max_iterations passes (at least 1), so `centers` are always the means of
// the returned assignment (or the kept centroid of an empty cluster).
KMeansResult kmeans(std::span<const Vec3> points, int k, int max_iterations);

// ---- Ray casting (seed 003, §4.5, Fig. 8 "ray cast") ----

struct Ray {
  Vec3 origin;
  Vec3 direction;  // normalised on use; a zero direction hits nothing
  double max_distance = 1e9;
};

struct RayHit {
  int target = -1;  // -1: no hit
  Vec3 position;
  double distance = -1;
};

struct RayCastResult {
  std::vector<RayHit> hits;      // per ray
  std::vector<bool> target_hit;  // per target: some ray's nearest hit is on it
  std::size_t face_tests = 0;    // ray-face tests made, a measure of the index's work
};

// For each ray, the nearest point at distance 0 <= t <= max_distance on a face of any target
// mesh (world space; faces count from both sides, so a ray leaving a box hits its far face). A ray
// grazing a face edge-on does not hit it. Faces are tested as planar polygons (plane, then
// even-odd point-in-polygon in the projection that drops the normal's largest axis), so concave
// faces need no triangulation. Index: a bounding volume hierarchy over every face of every target
// (median split of face centres along the widest axis, four faces per leaf), traversed near child
// first and pruned by the nearest hit so far: about log(F) node visits per ray for F faces.
RayCastResult ray_cast(std::span<const Ray> rays, std::span<const Mesh> targets,
                       const SkipPredicate& skip = {});

// ---- Occlusion query (seed 003, §6.1; Müller et al. 2006's occlusion test) ----

// A flat region in 3D: the union of `loops` (hole-free polygons in one plane, such as the faces
// of a mesh that share a face id) and its outward normal (normalised on use). The plane is taken
// through the first vertex of the first loop.
struct FlatShape {
  std::vector<std::vector<Vec3>> loops;
  Vec3 normal;
};

// Per shape, the fraction of its area covered by the occluder boxes in front of it: the part of
// each box strictly in front of the shape's plane and at most `distance` from it along the normal,
// projected onto the plane; all projections united (overlaps count once), intersected with the
// shape, area over the shape's area. Computed exactly with the 2D booleans (to their 1e-6 m grid).
// A box that only touches the plane (zero thickness in front of it) does not occlude; a shape of
// zero area gets 0. Index: a uniform grid over the boxes' bounds, queried with the bounds of the
// shape's slab.
std::vector<double> occlusion(std::span<const FlatShape> shapes,
                              std::span<const BoxEdges> occluders, double distance,
                              const SkipPredicate& skip = {});

// ---- "Is oriented to" (seed 003, §4.5, Fig. 1), in the ground plane ----

// A vertical-ish face seen from above: the XY midpoint of its bottom edge and its outward normal.
struct OrientedFace {
  Vec2 base;
  Vec3 normal;
};

struct StreetSegment {
  Vec2 a;
  Vec2 b;
};

// Per face, whether the face sees a street: whether the street points within `tolerance` degrees
// (clamped to [0, 90]) of its horizontal normal seen from `base`, no farther than `max_distance`,
// on sight lines from `base` that cross no occluder footprint's interior, span a positive angle
// seen from `base`. So a street seen only along one sight line (a single point in the cone, a
// street lying on a sight line, a gap of zero width between two footprints) does not count, and
// tolerance 0 never passes. Faces whose normal lies within 45 degrees of vertical (roofs, floors)
// never are. Exact, not sampled: each street segment is clipped to the tolerance wedge and the disc
// of radius max_distance; along the clipped piece the visibility changes only where a sight line
// passes an occluder vertex or the street crosses an occluder edge, so one point between each two
// consecutive such events decides the stretch. Index: uniform grids over the street segments' and
// the footprints' bounds; streets are searched in sectors of doubling radius, ending early once
// the footprints within the radius hide the whole wedge. skip(face, occluder) leaves an occluder
// out for that face.
std::vector<bool> is_oriented_to(std::span<const OrientedFace> faces,
                                 std::span<const StreetSegment> streets,
                                 std::span<const Polygon> occluders, double tolerance,
                                 double max_distance = 1e9, const SkipPredicate& skip = {});

// ---- Ground-plane distance (seed 003, §4.5, Fig. 1 levels of detail) ----

// An entity's geometry projected to XY: polygon regions (holes allowed), points and segments.
struct Footprint {
  std::vector<Polygon> polygons;
  std::vector<Vec2> points;
  std::vector<StreetSegment> segments;
};

struct NearestTarget {
  int target = -1;  // -1 when every target is skipped or empty
  double distance = -1;
};

// Per entity, the least XY distance between its geometry and a target's (0 when they overlap or
// one lies inside the other's polygons) and that target. Index: a uniform grid over the targets'
// bounds, searched in growing boxes around the entity until a candidate is found, then once more
// within the best distance.
std::vector<NearestTarget> nearest_targets(std::span<const Footprint> entities,
                                           std::span<const Footprint> targets,
                                           const SkipPredicate& skip = {});

}  // namespace insula::kernel
