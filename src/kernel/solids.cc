#include "kernel/solids.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/boolean2d.h"
#include "kernel/extrude.h"

namespace insula::kernel {
namespace {

// Six quads over a box's corners, corner (i, j, k) being i + 2j + 4k: outward for a right-handed
// (u, v, w).
constexpr std::array<std::uint32_t, 24> kBoxFaces{
    0, 2, 3, 1,  // k = 0
    4, 5, 7, 6,  // k = 1
    0, 1, 5, 4,  // j = 0
    2, 6, 7, 3,  // j = 1
    0, 4, 6, 2,  // i = 0
    1, 3, 7, 5,  // i = 1
};

// A box's eight corners, corner (i, j, k) at i + 2j + 4k; a left-handed (u, v, w) is turned
// right-handed first, from the opposite w face. Inlined: frames and footers make most of a
// building's boxes.
[[gnu::always_inline]] inline void write_box_corners(Vec3* corners, Vec3 origin, Vec3 u, Vec3 v,
                                                     Vec3 w) {
  if (dot(cross(u, v), w) < 0) {
    origin = origin + w;
    w = -w;
  }
  const std::array<Vec3, 2> us{u * 0.0, u};
  const std::array<Vec3, 2> vs{v * 0.0, v};
  const std::array<Vec3, 2> ws{w * 0.0, w};
  const std::array<Vec3, 2> along_u{origin + us[0], origin + us[1]};
  const std::array<Vec3, 4> along_uv{along_u[0] + vs[0], along_u[1] + vs[0], along_u[0] + vs[1],
                                     along_u[1] + vs[1]};
  for (int k = 0; k < 2; ++k) {
    for (int ij = 0; ij < 4; ++ij) corners[4 * k + ij] = along_uv[ij] + ws[k];
  }
}

}  // namespace

void add_box(Mesh& mesh, Vec3 origin, Vec3 u, Vec3 v, Vec3 w, FaceTag tag) {
  std::vector<Vec3>& positions = mesh.positions();
  const auto base = static_cast<std::uint32_t>(positions.size());
  positions.resize(base + std::size_t{8});
  write_box_corners(positions.data() + base, origin, u, v, w);
  mesh.add_faces(kBoxFaces, 4, base, tag);
}

void add_boxes(Mesh& mesh, std::span<const BoxEdges> boxes, FaceTag tag) {
  std::vector<Vec3>& positions = mesh.positions();
  const std::size_t first = positions.size();
  positions.resize(first + 8 * boxes.size());
  const Mesh::FaceSlots slots = mesh.add_face_slots(6 * boxes.size(), 24 * boxes.size());
  std::uint32_t* index = slots.indices.data();
  std::uint32_t end = slots.first_index;
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const BoxEdges& box = boxes[b];
    const auto base = static_cast<std::uint32_t>(first + 8 * b);
    write_box_corners(positions.data() + base, box.origin, box.u, box.v, box.w);
    for (const std::uint32_t corner : kBoxFaces) *index++ = base + corner;
    for (std::size_t f = 0; f < 6; ++f) {
      slots.ends[6 * b + f] = end += 4;
      slots.tags[6 * b + f] = tag;
    }
  }
}

bool add_prism(Mesh& mesh, const Polygon& polygon, double z0, double z1, const PrismTags& tags) {
  ExtrudeOptions options;
  options.bottom = tags.bottom;
  options.top = tags.top;
  options.side = tags.side;
  options.tolerance = 1e-6;
  const std::size_t first = mesh.face_count();
  if (extrude_between_append(mesh, polygon, z0, z1, options) != ExtrudeStatus::kOk) return false;
  // A slab's sides are one surface to the caller: one face id, not one per edge.
  for (std::size_t f = first; f < mesh.face_count(); ++f) {
    FaceTag& tag = mesh.tag(f);
    if (tag.semantic == tags.side.semantic && tag.material == tags.side.material) {
      tag.face_id = tags.side.face_id;
    }
  }
  return true;
}

std::size_t add_slab(Mesh& mesh, std::span<const Polygon> region, std::span<const Polygon> openings,
                     double z0, double z1, const PrismTags& tags) {
  std::vector<Polygon> cut;
  if (!openings.empty()) {
    BooleanResult r = subtract(std::vector<Polygon>(region.begin(), region.end()),
                               std::vector<Polygon>(openings.begin(), openings.end()));
    if (r.ok()) {
      cut = std::move(r.polygons);
      region = cut;
    }
  }
  std::size_t added = 0;
  for (const Polygon& p : region) added += add_prism(mesh, p, z0, z1, tags) ? 1 : 0;
  return added;
}

int stair_steps(double rise, double max_rise) {
  if (!(rise > 0) || !(max_rise > 0)) return 1;
  return std::max(1, static_cast<int>(std::ceil(rise / max_rise)));
}

bool add_staircase(Mesh& mesh, const StairSpec& spec, FaceTag tag) {
  if (spec.steps < 1 || !(spec.run > 0) || !(spec.rise > 0) || !(spec.width > 0)) return false;
  // The profile in the vertical plane through the flight's right edge, climbing along `dir`:
  // (0, 0), (0, r), (d, r), (d, 2r), ... (n d, n r), (n d, 0).
  const Vec2 side = perp(spec.dir);
  const Vec2 right = spec.foot - side * (spec.width / 2);
  const auto p = [&](double along, double up) {
    return lift(right + spec.dir * along, spec.z0 + up);
  };
  std::vector<Vec3> loop;
  loop.reserve(2 * static_cast<std::size_t>(spec.steps) + 2);
  loop.push_back(p(0, 0));
  for (int i = 0; i < spec.steps; ++i) {
    loop.push_back(p(i * spec.run, (i + 1) * spec.rise));
    loop.push_back(p((i + 1) * spec.run, (i + 1) * spec.rise));
  }
  loop.push_back(p(spec.steps * spec.run, 0));
  // extrude_loop grows the solid along the loop's normal: orient the loop so that it points
  // across the flight, towards its left edge.
  const Vec3 normal = cross(loop[1] - loop[0], loop.back() - loop[0]);
  if (dot(normal, lift(side, 0)) < 0) std::reverse(loop.begin(), loop.end());
  ExtrudeOptions options;
  options.bottom = tag;
  options.top = tag;
  options.side = tag;
  const ExtrudeResult solid = extrude_loop(loop, spec.width, options);
  if (!solid.ok()) return false;
  mesh.append(solid.mesh);
  return true;
}

}  // namespace insula::kernel
