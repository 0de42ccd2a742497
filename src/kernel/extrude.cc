#include "kernel/extrude.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "kernel/triangulate.h"

namespace insula::kernel {

namespace {

bool finite(Vec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

bool finite(Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// A ring with runs of coincident vertices merged. edge_id[j] is the input edge index (counted over
// all rings) of the edge from points[j] to points[j + 1]: the edge leaving the last vertex of the
// run that points[j] stands for, so ids keep naming input edges when duplicates are dropped.
struct PreparedRing {
  std::vector<Vec2> points;
  std::vector<std::uint32_t> edge_id;
  bool reversed = false;  // wrong orientation (outer clockwise or hole counter-clockwise)
};

ExtrudeStatus prepare_ring(const Ring& ring, std::uint32_t first_edge, bool is_hole,
                           double tolerance, PreparedRing& out) {
  const std::size_t n = ring.size();
  for (Vec2 p : ring) {
    if (!finite(p)) return ExtrudeStatus::kNonFinite;
  }
  const auto same = [&](std::size_t a, std::size_t b) {
    const Vec2 d = ring[a] - ring[b];
    // A coordinate apart by more than the tolerance settles it without the square root: a
    // faithfully rounded hypot is never below either coordinate.
    if (std::abs(d.x) > tolerance || std::abs(d.y) > tolerance) return false;
    return length(d) <= tolerance;
  };
  // Start at the first vertex that begins a run (differs from its predecessor).
  std::size_t start = 0;
  while (start < n && same(start, (start + n - 1) % n)) ++start;
  if (start == n) return ExtrudeStatus::kTooFewVertices;
  out.points.reserve(n);
  out.edge_id.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (start + k) % n;
    if (k == 0 || !same(i, (i + n - 1) % n)) {
      out.points.push_back(ring[i]);
      out.edge_id.push_back(0);
    }
    out.edge_id.back() = first_edge + static_cast<std::uint32_t>(i);
  }
  if (out.points.size() < 3) return ExtrudeStatus::kTooFewVertices;
  const double signed_twice = 2 * signed_area(out.points);
  // Near zero: less than a strip of width `tolerance` along the boundary. The perimeter is bounded
  // first by the sum of |dx| + |dy| (never below it, also after rounding): when even that strip is
  // smaller than the area, the square roots are not needed.
  const std::size_t m = out.points.size();
  double perimeter_bound = 0;
  for (std::size_t j = 0; j < m; ++j) {
    const Vec2 d = out.points[(j + 1) % m] - out.points[j];
    perimeter_bound += std::abs(d.x) + std::abs(d.y);
  }
  if (std::abs(signed_twice) <= 2 * tolerance * perimeter_bound) {
    double perimeter_length = 0;
    for (std::size_t j = 0; j < m; ++j) {
      perimeter_length += length(out.points[(j + 1) % m] - out.points[j]);
    }
    if (std::abs(signed_twice) <= 2 * tolerance * perimeter_length) {
      return ExtrudeStatus::kZeroArea;
    }
  }
  out.reversed = is_hole ? signed_twice > 0 : signed_twice < 0;
  return ExtrudeStatus::kOk;
}

ExtrudeStatus prepare(const Polygon& polygon, double tolerance, std::vector<PreparedRing>& rings) {
  rings.reserve(1 + polygon.holes.size());
  std::uint32_t first_edge = 0;
  for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
    const Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
    rings.emplace_back();
    const ExtrudeStatus status = prepare_ring(ring, first_edge, r > 0, tolerance, rings.back());
    if (status != ExtrudeStatus::kOk) return status;
    first_edge += static_cast<std::uint32_t>(ring.size());
  }
  return ExtrudeStatus::kOk;
}

// The region in normalised orientation with the index of each of its vertices among the prepared
// ring vertices (outer ring first, then each hole).
void normalized_region(const std::vector<PreparedRing>& rings, Polygon& region,
                       std::vector<std::uint32_t>& ids) {
  std::uint32_t base = 0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    Ring ring = rings[r].points;
    std::vector<std::uint32_t> ring_ids(ring.size());
    for (std::uint32_t j = 0; j < ring.size(); ++j) ring_ids[j] = base + j;
    if (rings[r].reversed) {
      std::reverse(ring.begin(), ring.end());
      std::reverse(ring_ids.begin(), ring_ids.end());
    }
    (r == 0 ? region.outer : region.holes.emplace_back()) = std::move(ring);
    ids.insert(ids.end(), ring_ids.begin(), ring_ids.end());
    base += static_cast<std::uint32_t>(rings[r].points.size());
  }
}

void add_sides(Mesh& mesh, const std::vector<PreparedRing>& rings, std::uint32_t total,
               const FaceTag& side) {
  std::uint32_t base = 0;
  for (const PreparedRing& ring : rings) {
    const auto m = static_cast<std::uint32_t>(ring.points.size());
    for (std::uint32_t j = 0; j < m; ++j) {
      const std::uint32_t a = base + j;
      const std::uint32_t b = base + (j + 1) % m;
      FaceTag tag = side;
      tag.face_id = side.face_id + ring.edge_id[j];
      // Outward: the region lies left of a correctly oriented edge, so a, b, b', a' turns right.
      if (ring.reversed) {
        mesh.add_face({b, a, a + total, b + total}, tag);
      } else {
        mesh.add_face({a, b, b + total, a + total}, tag);
      }
    }
    base += m;
  }
}

// A frame on the plane of a loop: origin at its first vertex, z along its Newell normal, x along
// its first edge of non-zero length.
bool loop_frame(std::span<const Vec3> loop, double tolerance, Transform& out) {
  Vec3 area;
  for (std::size_t i = 0; i < loop.size(); ++i) area += cross(loop[i], loop[(i + 1) % loop.size()]);
  const Vec3 n = normalized(area);
  if (n == Vec3{} || !finite(n)) return false;
  for (std::size_t i = 1; i < loop.size(); ++i) {
    const Vec3 e = loop[i] - loop[0];
    const Vec3 u = normalized(e - n * dot(e, n));
    if (length(e) > tolerance && u != Vec3{}) {
      out = frame(loop[0], u, cross(n, u), n);
      return true;
    }
  }
  return false;
}

// A frame (a window's border: a convex quadrilateral with one quadrilateral hole) as the four
// quadrilaterals between them, each hole corner joined to the nearest outer one; false when one
// of the four would not be strictly convex and counter-clockwise. The quads' boundaries sum to the
// outer ring and the clockwise hole, so four convex counter-clockwise quads cover the frame once:
// a third of the triangulator's time on a district of windows, and four faces where it gave eight
// triangles.
bool add_frame_faces(Mesh& mesh, const Polygon& region, std::span<const std::uint32_t> ids,
                     bool reverse, FaceTag tag) {
  if (region.outer.size() != 4 || region.holes.size() != 1 || region.holes[0].size() != 4) {
    return false;
  }
  const Ring& outer = region.outer;
  const Ring& hole = region.holes[0];  // clockwise: corner 3 - k runs counter-clockwise
  const auto inner = [&](std::size_t k) { return (3 - k % 4) % 4; };
  std::size_t shift = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 4; ++k) {
    double sum = 0;
    for (std::size_t i = 0; i < 4; ++i)
      sum += dot(outer[i] - hole[inner(i + k)], outer[i] - hole[inner(i + k)]);
    if (sum < best) {
      best = sum;
      shift = k;
    }
  }
  std::array<std::array<std::uint32_t, 4>, 4> quads{};
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t a = inner(i + shift);
    const std::size_t b = inner(i + 1 + shift);
    const std::array<Vec2, 4> q{outer[i], outer[(i + 1) % 4], hole[b], hole[a]};
    for (std::size_t c = 0; c < 4; ++c) {
      const Vec2 e = q[(c + 1) % 4] - q[c];
      const Vec2 f = q[(c + 2) % 4] - q[(c + 1) % 4];
      const double turn = cross(e, f);  // > 1e-9 |e| |f|: a real left turn
      if (!(turn > 0 && turn * turn > 1e-18 * dot(e, e) * dot(f, f))) return false;
    }
    quads[i] = {ids[i], ids[(i + 1) % 4], ids[4 + b], ids[4 + a]};
  }
  for (auto& quad : quads) {
    if (reverse) std::reverse(quad.begin(), quad.end());
    mesh.add_face(quad, tag);
  }
  return true;
}

}  // namespace

bool add_region_faces(Mesh& mesh, const Polygon& region, std::span<const std::uint32_t> ids,
                      bool reverse, FaceTag tag) {
  std::size_t total = region.outer.size();
  for (const Ring& hole : region.holes) total += hole.size();
  if (ids.size() != total || region.outer.size() < 3) return false;
  if (region.holes.empty()) {
    std::vector<std::uint32_t> loop(ids.begin(), ids.end());
    if (reverse) std::reverse(loop.begin(), loop.end());
    mesh.add_face(loop, tag);
    return true;
  }
  if (add_frame_faces(mesh, region, ids, reverse, tag)) return true;
  Triangulation triangulation;
  if (!triangulate(region, triangulation) || triangulation.vertices.size() != total) return false;
  // Orientation from the total signed area, so (near) degenerate triangles follow the rest.
  double twice_area = 0;
  for (const auto& t : triangulation.triangles) {
    if (t[0] >= total || t[1] >= total || t[2] >= total) return false;
    const Vec2 a = triangulation.vertices[t[0]];
    twice_area += cross(triangulation.vertices[t[1]] - a, triangulation.vertices[t[2]] - a);
  }
  const bool flip = (twice_area < 0) != reverse;
  for (const auto& t : triangulation.triangles) {
    if (flip) {
      mesh.add_face({ids[t[0]], ids[t[2]], ids[t[1]]}, tag);
    } else {
      mesh.add_face({ids[t[0]], ids[t[1]], ids[t[2]]}, tag);
    }
  }
  return true;
}

std::string_view extrude_status_message(ExtrudeStatus status) {
  switch (status) {
    case ExtrudeStatus::kOk:
      return "ok";
    case ExtrudeStatus::kInvalidHeight:
      return "the extrusion height must be finite and positive";
    case ExtrudeStatus::kNonFinite:
      return "a coordinate is not finite";
    case ExtrudeStatus::kTooFewVertices:
      return "a ring has fewer than 3 distinct vertices";
    case ExtrudeStatus::kZeroArea:
      return "a ring encloses zero area";
    case ExtrudeStatus::kTriangulationFailed:
      return "a cap with holes could not be triangulated (rings crossing?)";
    case ExtrudeStatus::kDegenerateFace:
      return "the face has no well-defined plane";
  }
  return "unknown extrude status";
}

ExtrudeResult extrude(const Polygon& footprint, double z0, double height,
                      const ExtrudeOptions& options) {
  ExtrudeResult result;
  if (!std::isfinite(z0) || !std::isfinite(height) || !(height > 0)) {
    result.status = std::isfinite(z0) ? ExtrudeStatus::kInvalidHeight : ExtrudeStatus::kNonFinite;
    return result;
  }
  std::vector<PreparedRing> rings;
  result.status = prepare(footprint, std::max(options.tolerance, 0.0), rings);
  if (!result.ok()) return result;
  std::uint32_t total = 0;
  for (const PreparedRing& ring : rings) total += static_cast<std::uint32_t>(ring.points.size());
  Mesh& mesh = result.mesh;
  mesh.reserve(2 * total, total + 2, 6 * total);
  for (double z : {z0, z0 + height}) {
    for (const PreparedRing& ring : rings) {
      for (Vec2 p : ring.points) mesh.add_vertex(lift(p, z));
    }
  }
  Polygon region;
  std::vector<std::uint32_t> bottom_ids;
  normalized_region(rings, region, bottom_ids);
  std::vector<std::uint32_t> top_ids = bottom_ids;
  for (std::uint32_t& id : top_ids) id += total;
  if (!add_region_faces(mesh, region, bottom_ids, true, options.bottom) ||
      !add_region_faces(mesh, region, top_ids, false, options.top)) {
    return {ExtrudeStatus::kTriangulationFailed, {}};
  }
  add_sides(mesh, rings, total, options.side);
  return result;
}

ExtrudeResult extrude_between(const Polygon& footprint, double z_bottom, double z_top,
                              const ExtrudeOptions& options) {
  if (!std::isfinite(z_bottom) || !std::isfinite(z_top)) return {ExtrudeStatus::kNonFinite, {}};
  return extrude(footprint, z_bottom, z_top - z_bottom, options);
}

ExtrudeStatus extrude_between_append(Mesh& mesh, const Polygon& footprint, double z_bottom,
                                     double z_top, const ExtrudeOptions& options) {
  if (!std::isfinite(z_bottom) || !std::isfinite(z_top)) return ExtrudeStatus::kNonFinite;
  const double height = z_top - z_bottom;
  if (!std::isfinite(height) || !(height > 0)) return ExtrudeStatus::kInvalidHeight;
  if (!footprint.holes.empty()) {
    // A cap with holes is triangulated, which may fail after the bottom cap went in: build apart
    // and append so that a failure leaves `mesh` untouched.
    ExtrudeResult prism = extrude(footprint, z_bottom, height, options);
    if (prism.ok()) mesh.append(prism.mesh);
    return prism.status;
  }
  // One ring (prepare() on the outer ring alone): the same vertices, caps and sides as extrude(),
  // shifted by the vertices already in `mesh`. An n-gon cap cannot fail, so nothing needs undoing.
  PreparedRing ring;
  const ExtrudeStatus status =
      prepare_ring(footprint.outer, 0, false, std::max(options.tolerance, 0.0), ring);
  if (status != ExtrudeStatus::kOk) return status;
  const auto total = static_cast<std::uint32_t>(ring.points.size());
  const auto base = static_cast<std::uint32_t>(mesh.vertex_count());
  for (double z : {z_bottom, z_bottom + height}) {
    for (Vec2 p : ring.points) mesh.add_vertex(lift(p, z));
  }
  // The caps' vertex loop: on the stack for the usual few-sided slab.
  constexpr std::size_t kStackLoop = 32;
  std::array<std::uint32_t, kStackLoop> small;
  std::vector<std::uint32_t> large;
  if (total > kStackLoop) large.resize(total);
  const std::span<std::uint32_t> loop =
      total > kStackLoop ? std::span<std::uint32_t>(large) : std::span(small).first(total);
  // normalized_region() reverses a clockwise outer ring; the bottom cap runs reversed again.
  for (std::uint32_t j = 0; j < total; ++j) {
    const std::uint32_t k = ring.reversed ? total - 1 - j : j;
    loop[j] = base + k;
  }
  std::reverse(loop.begin(), loop.end());
  mesh.add_face(loop, options.bottom);
  std::reverse(loop.begin(), loop.end());
  for (std::uint32_t& id : loop) id += total;
  mesh.add_face(loop, options.top);
  for (std::uint32_t j = 0; j < total; ++j) {
    const std::uint32_t a = base + j;
    const std::uint32_t b = base + (j + 1) % total;
    FaceTag tag = options.side;
    tag.face_id = options.side.face_id + ring.edge_id[j];
    if (ring.reversed) {
      mesh.add_face({b, a, a + total, b + total}, tag);
    } else {
      mesh.add_face({a, b, b + total, a + total}, tag);
    }
  }
  return ExtrudeStatus::kOk;
}

ExtrudeResult extrude_planar(const Polygon& local, const Transform& plane, double distance,
                             const ExtrudeOptions& options) {
  if (!std::isfinite(distance)) return {ExtrudeStatus::kNonFinite, {}};
  if (distance == 0) return {ExtrudeStatus::kInvalidHeight, {}};
  if (!inverse(plane)) return {ExtrudeStatus::kDegenerateFace, {}};
  ExtrudeResult result;
  if (distance > 0) {
    result = extrude(local, 0, distance, options);
  } else {
    // Behind the plane: the cap in the plane is geometrically the top one but keeps the bottom tag.
    ExtrudeOptions swapped = options;
    std::swap(swapped.bottom, swapped.top);
    result = extrude(local, distance, -distance, swapped);
  }
  if (result.ok()) transform_mesh(result.mesh, plane);
  return result;
}

ExtrudeResult extrude_loop(std::span<const Vec3> loop, double distance,
                           const ExtrudeOptions& options) {
  for (Vec3 p : loop) {
    if (!finite(p)) return {ExtrudeStatus::kNonFinite, {}};
  }
  Transform plane;
  if (loop.size() < 3 || !loop_frame(loop, std::max(options.tolerance, 0.0), plane)) {
    return {ExtrudeStatus::kDegenerateFace, {}};
  }
  Polygon local;
  for (Vec3 p : loop) {
    const Vec3 offset = p - plane.t;
    local.outer.push_back({dot(offset, plane.x), dot(offset, plane.y)});
  }
  return extrude_planar(local, plane, distance, options);
}

ExtrudeResult extrude_face(const Mesh& mesh, std::size_t face, double distance,
                           const ExtrudeOptions& options) {
  if (face >= mesh.face_count()) return {ExtrudeStatus::kDegenerateFace, {}};
  std::vector<Vec3> loop;
  for (std::uint32_t v : mesh.face(face)) loop.push_back(mesh.position(v));
  return extrude_loop(loop, distance, options);
}

}  // namespace insula::kernel
