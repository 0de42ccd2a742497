#include "kernel/skeleton_faces.h"

#include <algorithm>
#include <utility>

namespace insula::kernel {

bool assemble_skeleton_faces(const std::vector<SkeletonArc>& arcs, Skeleton& out) {
  constexpr std::uint32_t kUsed = 0xffffffffU;
  const std::uint32_t n = out.contour_count;
  // Per face, its arcs directed as the face's counter-clockwise loop runs: an arc has the face of
  // its left edge on its left.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> sides(n);
  for (const SkeletonArc& a : arcs) {
    if (a.from == a.to) continue;
    if (a.left >= n || a.right >= n) return false;
    sides[a.left].push_back({a.from, a.to});
    sides[a.right].push_back({a.to, a.from});
  }
  out.face_indices.clear();
  out.face_offsets.assign(1, 0);
  for (std::uint32_t e = 0; e < n; ++e) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>>& side = sides[e];
    out.face_indices.push_back(e);
    std::uint32_t at = out.next_contour(e);
    std::size_t used = 0;
    while (at != e) {
      out.face_indices.push_back(at);
      auto it = std::find_if(side.begin(), side.end(), [at](auto a) { return a.first == at; });
      if (it == side.end() || ++used > side.size()) return false;
      if (std::find_if(it + 1, side.end(), [at](auto a) { return a.first == at; }) != side.end())
        return false;  // two ways on: not a simple face
      at = it->second;
      it->first = kUsed;
    }
    if (used != side.size()) return false;
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_indices.size()));
  }
  return true;
}

}  // namespace insula::kernel
