#include "kernel/convex_partition.h"

#include <algorithm>
#include <map>
#include <optional>

#include "kernel/face_loops.h"
#include "kernel/triangulate.h"

namespace insula::kernel {

namespace {

using Loop = IndexLoop;

bool convex(const std::vector<Vec2>& p, const Loop& loop, double eps) {
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 a = p[loop[i]];
    const Vec2 b = p[loop[(i + 1) % loop.size()]];
    const Vec2 c = p[loop[(i + 2) % loop.size()]];
    if (cross(b - a, c - b) < -eps) return false;
  }
  return true;
}

}  // namespace

std::vector<Ring> convex_partition(const Polygon& polygon, double max_length) {
  Triangulation t;
  if (!triangulate(polygon, t)) return {};
  const std::vector<Vec2>& p = t.vertices;
  const Bounds2 b = bounds(polygon);
  const double eps = 1e-12 * std::max({b.max.x - b.min.x, b.max.y - b.min.y, 1.0});
  std::vector<Loop> pieces;
  for (const auto& tri : t.triangles) pieces.push_back({tri[0], tri[1], tri[2]});
  std::vector<bool> alive(pieces.size(), true);
  // Two passes: long diagonals go unconditionally, then any whose removal keeps a piece convex.
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 0 && !(max_length > 0)) continue;
    for (bool merged = true; merged;) {
      merged = false;
      std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edges;
      for (std::size_t f = 0; f < pieces.size(); ++f) {
        if (!alive[f]) continue;
        const Loop& l = pieces[f];
        for (std::size_t i = 0; i < l.size(); ++i) {
          const std::uint32_t u = l[i];
          const std::uint32_t v = l[(i + 1) % l.size()];
          edges[{std::min(u, v), std::max(u, v)}].push_back(f);
        }
      }
      for (const auto& [edge, list] : edges) {
        if (list.size() != 2 || !alive[list[0]] || !alive[list[1]]) continue;
        std::optional<Loop> out =
            join_along(pieces[list[0]], pieces[list[1]], edge.first, edge.second);
        if (!out) continue;
        const Vec2 d = p[edge.first] - p[edge.second];
        const bool go = pass == 0 ? length(d) >= max_length : convex(p, *out, eps);
        if (!go) continue;
        pieces[list[0]] = std::move(*out);
        alive[list[1]] = false;
        merged = true;
      }
    }
  }
  std::vector<Ring> out;
  for (std::size_t f = 0; f < pieces.size(); ++f) {
    if (!alive[f]) continue;
    Ring ring;
    for (std::uint32_t v : pieces[f]) ring.push_back(p[v]);
    out.push_back(std::move(ring));
  }
  return out;
}

}  // namespace insula::kernel
