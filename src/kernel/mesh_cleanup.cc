#include "kernel/mesh_cleanup.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <vector>

#include "kernel/face_loops.h"

namespace insula::kernel {

namespace {

using Loop = IndexLoop;

struct Face {
  Loop loop;
  FaceTag tag;
  bool alive = true;
};

bool same_tag(const FaceTag& a, const FaceTag& b) {
  return a.semantic == b.semantic && a.material == b.material && a.face_id == b.face_id;
}

Vec3 newell(const std::vector<Vec3>& p, const Loop& loop) {
  Vec3 n;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = p[loop[i]];
    const Vec3 b = p[loop[(i + 1) % loop.size()]];
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

double area_of(const std::vector<Vec3>& p, const Loop& loop) {
  return length(newell(p, loop)) / 2;
}

// Every directed edge has exactly one opposite partner among the live faces.
bool closed(const std::vector<Face>& faces) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const Face& f : faces) {
    if (!f.alive) continue;
    for (std::size_t i = 0; i < f.loop.size(); ++i) {
      ++count[{f.loop[i], f.loop[(i + 1) % f.loop.size()]}];
    }
  }
  for (const auto& [e, n] : count) {
    const auto it = count.find({e.second, e.first});
    if (n != 1 || it == count.end() || it->second != 1) return false;
  }
  return !count.empty();
}

void drop_duplicates(std::vector<Face>& faces) {
  std::map<Loop, std::vector<std::size_t>> by_set;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    Loop key = faces[f].loop;
    std::sort(key.begin(), key.end());
    by_set[key].push_back(f);
  }
  for (auto& [key, list] : by_set) {
    if (list.size() < 2) continue;
    // Same loop twice: keep one; a loop and its reverse (a wall inside the solid): drop both.
    const auto rotated_equal = [](const Loop& a, const Loop& b) {
      if (a.size() != b.size()) return false;
      for (std::size_t shift = 0; shift < b.size(); ++shift) {
        bool same = true;
        for (std::size_t k = 0; k < a.size() && same; ++k) same = a[k] == b[(k + shift) % b.size()];
        if (same) return true;
      }
      return false;
    };
    for (std::size_t i = 0; i < list.size(); ++i) {
      Face& a = faces[list[i]];
      if (!a.alive) continue;
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        Face& b = faces[list[j]];
        if (!b.alive) continue;
        Loop reversed = b.loop;
        std::reverse(reversed.begin(), reversed.end());
        if (rotated_equal(a.loop, b.loop)) {
          b.alive = false;
        } else if (rotated_equal(a.loop, reversed)) {
          a.alive = b.alive = false;
          break;
        }
      }
    }
  }
}

// Merges pairs of live faces that share exactly one edge, have the same tag and normals within
// `cos_limit`; repeats until none is left.
void merge_coplanar(std::vector<Face>& faces, const std::vector<Vec3>& p, double cos_limit) {
  for (bool merged = true; merged;) {
    merged = false;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edge_faces;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!faces[f].alive) continue;
      const Loop& l = faces[f].loop;
      for (std::size_t i = 0; i < l.size(); ++i) {
        const std::uint32_t a = l[i];
        const std::uint32_t b = l[(i + 1) % l.size()];
        edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
      }
    }
    for (const auto& [edge, list] : edge_faces) {
      if (list.size() != 2 || list[0] == list[1]) continue;
      Face& fa = faces[list[0]];
      Face& fb = faces[list[1]];
      if (!fa.alive || !fb.alive || !same_tag(fa.tag, fb.tag)) continue;
      const Vec3 na = normalized(newell(p, fa.loop));
      const Vec3 nb = normalized(newell(p, fb.loop));
      if (dot(na, nb) < cos_limit) continue;
      std::optional<Loop> out = join_along(fa.loop, fb.loop, edge.first, edge.second);
      if (!out) continue;  // pinched, or the faces run the same way along the edge
      fa.loop = std::move(*out);
      fb.alive = false;
      merged = true;
    }
  }
}

// Drops vertices with exactly two edges that meet within the angle limit, from every loop.
void drop_collinear(std::vector<Face>& faces, const std::vector<Vec3>& p, double cos_limit) {
  std::vector<std::vector<std::uint32_t>> neighbours(p.size());
  for (const Face& f : faces) {
    if (!f.alive) continue;
    for (std::size_t i = 0; i < f.loop.size(); ++i) {
      const std::uint32_t a = f.loop[i];
      const std::uint32_t b = f.loop[(i + 1) % f.loop.size()];
      for (auto [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
        auto& n = neighbours[x];
        if (std::find(n.begin(), n.end(), y) == n.end()) n.push_back(y);
      }
    }
  }
  std::vector<char> drop(p.size(), 0);
  for (std::size_t v = 0; v < p.size(); ++v) {
    if (neighbours[v].size() != 2) continue;
    const Vec3 d1 = p[v] - p[neighbours[v][0]];
    const Vec3 d2 = p[neighbours[v][1]] - p[v];
    if (length(d1) == 0 || length(d2) == 0) continue;
    if (dot(normalized(d1), normalized(d2)) >= cos_limit) drop[v] = 1;
  }
  for (Face& f : faces) {
    if (!f.alive) continue;
    Loop kept;
    for (std::uint32_t v : f.loop) {
      if (!drop[v]) kept.push_back(v);
    }
    if (kept.size() >= 3) f.loop = std::move(kept);
  }
}

}  // namespace

Mesh cleanup(const Mesh& mesh, const CleanupOptions& options) {
  const Mesh welded = weld(mesh, std::max(options.merge_distance, 1e-9));
  const std::vector<Vec3>& p = welded.positions();
  std::vector<Face> faces;
  for (std::size_t f = 0; f < welded.face_count(); ++f) {
    const auto loop = welded.face(f);
    faces.push_back({Loop(loop.begin(), loop.end()), welded.tag(f), true});
  }
  const bool was_closed = closed(faces);
  const double angle = std::max(options.angle_degrees * std::numbers::pi / 180, 1e-6);
  const double cos_limit = std::cos(angle);
  if (options.faces) {
    std::vector<Face> before = faces;
    drop_duplicates(faces);
    const double max_area = std::max(options.max_area, 1e-12);
    for (Face& f : faces) {
      if (f.alive && area_of(p, f.loop) <= max_area) f.alive = false;
    }
    if (was_closed && !closed(faces)) {
      // Removing some of them opened the solid: drop only the duplicates, or nothing.
      faces = before;
      drop_duplicates(faces);
      if (!closed(faces)) faces = std::move(before);
    }
  }
  if (options.edges) merge_coplanar(faces, p, cos_limit);
  if (options.vertices) drop_collinear(faces, p, cos_limit);
  Mesh out;
  std::vector<std::uint32_t> remap(p.size(), UINT32_MAX);
  for (const Face& f : faces) {
    if (!f.alive) continue;
    Loop loop;
    for (std::uint32_t v : f.loop) {
      if (remap[v] == UINT32_MAX) remap[v] = out.add_vertex(p[v]);
      loop.push_back(remap[v]);
    }
    out.add_face(loop, f.tag);
  }
  return out;
}

}  // namespace insula::kernel
