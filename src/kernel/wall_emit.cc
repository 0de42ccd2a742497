// Mesh emission of a wall (wall_detail.h): front pieces, back pieces, one quad per boundary edge.
#include <array>
#include <cstdint>
#include <vector>

#include "kernel/wall_detail.h"

namespace insula::kernel::wall_detail {

// A left-handed frame gets every loop reversed as it is written, so the faces stay outward. The
// loops are written straight into the mesh's face slots: a storey's walls go into one mesh.
void emit(const Boundary& b, const std::vector<std::uint32_t>& loops,
          const std::vector<std::uint32_t>& offsets, const WallSpec& spec, const WallFrame& frame,
          Mesh& mesh) {
  const auto n = static_cast<std::uint32_t>(b.points.size());
  const auto base = static_cast<std::uint32_t>(mesh.vertex_count());
  const std::size_t pieces = offsets.size() - 1;
  const bool flip = dot(cross(frame.u_axis, frame.v_axis), frame.normal) < 0;
  // Front vertices, then back vertices: frame.map(u, v, thickness) and frame.map(u, v, 0), in
  // WallFrame::map's order of sums, so a wall's vertices do not depend on how it is built.
  std::vector<Vec3>& positions = mesh.positions();
  positions.resize(base + 2 * std::size_t{n});
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec2 p = b.points[i];
    const Vec3 in_plane = frame.origin + frame.u_axis * p.x + frame.v_axis * p.y;
    positions[base + i] = in_plane + frame.normal * spec.thickness;
    positions[base + n + i] = in_plane + frame.normal * 0.0;
  }
  // Front pieces, back pieces (reversed, on the back vertices), then one quad per boundary edge.
  const Mesh::FaceSlots slots = mesh.add_face_slots(2 * pieces + n, 2 * loops.size() + 4 * n);
  std::uint32_t* out = slots.indices.data();
  std::size_t face = 0;
  const auto close_face = [&](const FaceTag& tag) {
    slots.ends[face] = slots.first_index + static_cast<std::uint32_t>(out - slots.indices.data());
    slots.tags[face++] = tag;
  };
  const auto write_pieces = [&](bool reversed, std::uint32_t shift, const FaceTag& tag) {
    for (std::size_t f = 0; f < pieces; ++f) {
      const std::uint32_t* first = loops.data() + offsets[f];
      const std::uint32_t* last = loops.data() + offsets[f + 1];
      if (reversed) {
        while (last != first) *out++ = *--last + shift;
      } else {
        while (first != last) *out++ = *first++ + shift;
      }
      close_face(tag);
    }
  };
  write_pieces(flip, base, spec.tags.front);
  write_pieces(!flip, base + n, spec.tags.back);
  // The side quads: (i, n + i, n + j, j) for the edge i -> j, its two ends swapped when flipped;
  // tags looked up by edge kind (in EdgeKind order).
  const std::array<const FaceTag*, 6> kind_tags{&spec.tags.top,  &spec.tags.bottom,
                                                &spec.tags.end,  &spec.tags.jamb,
                                                &spec.tags.sill, &spec.tags.lintel};
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = b.next[i];
    const std::uint32_t first = base + (flip ? j : i);
    const std::uint32_t second = base + (flip ? i : j);
    out[0] = first, out[1] = first + n, out[2] = second + n, out[3] = second;
    out += 4;
    close_face(*kind_tags[static_cast<std::size_t>(b.kind[i])]);
  }
}

}  // namespace insula::kernel::wall_detail
