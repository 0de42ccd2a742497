// Component selectors on edges and vertices (CityEngine's comp(e) and comp(v) take the same
// direction selectors as faces, plus the roof edge classes eave, hip, valley and ridge; see
// docs/operations-cityengine.md for how Insula decides each class).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "shape/ops.h"

namespace insula::shape {

using kernel::Mesh;
using kernel::Vec3;

namespace {

// An edge is horizontal when its rise is below this fraction of its length: roofs are exact up to
// rounding, and a shallow hip (a 15 degree roof's hip rises about 10.7 degrees) must stay a hip.
constexpr double kFlatEdge = 1e-4;
// How far (meters) a face's centre must lie from the edge to count as above or below it.
constexpr double kSide = 1e-7;

Vec3 centroid(const Mesh& mesh, std::uint32_t face) {
  Vec3 sum;
  const auto loop = mesh.face(face);
  for (std::uint32_t v : loop) sum += mesh.position(v);
  return sum / static_cast<double>(loop.size());
}

// A roof plane faces up but is neither flat nor a wall.
bool roof_plane(Vec3 n) {
  return n.y > 1e-3 && n.y < 1 - 1e-9;
}

FaceSelector roof_class(const Mesh& mesh, const MeshEdge& edge) {
  const Vec3 a = mesh.position(edge.a);
  const Vec3 d = mesh.position(edge.b) - a;
  const bool horizontal = std::fabs(d.y) <= kFlatEdge * length(d);
  if (edge.faces.size() == 2) {
    const Vec3 n0 = kernel::face_normal(mesh, edge.faces[0]);
    const Vec3 n1 = kernel::face_normal(mesh, edge.faces[1]);
    if (roof_plane(n0) && roof_plane(n1)) {
      const Vec3 c0 = centroid(mesh, edge.faces[0]);
      const Vec3 c1 = centroid(mesh, edge.faces[1]);
      const bool convex = dot(c1 - a, n0) < 0;
      if (!horizontal) return convex ? FaceSelector::kHip : FaceSelector::kValley;
      if (!convex) return FaceSelector::kValley;
      if (c0.y < a.y - kSide && c1.y < a.y - kSide) return FaceSelector::kRidge;
      return FaceSelector::kAll;  // a break between two planes of one slope (mansard)
    }
  }
  if (!horizontal) return FaceSelector::kAll;
  // An eave: the low edge of a roof plane, its other side a wall, the roof's underside or nothing.
  std::size_t above = 0;
  for (std::uint32_t f : edge.faces) {
    const bool plane = roof_plane(kernel::face_normal(mesh, f));
    if (plane && centroid(mesh, f).y > a.y + kSide) {
      ++above;
    } else if (plane) {
      return FaceSelector::kAll;
    }
  }
  return above == 1 ? FaceSelector::kEave : FaceSelector::kAll;
}

bool roof_selector(FaceSelector selector) {
  return selector == FaceSelector::kEave || selector == FaceSelector::kHip ||
         selector == FaceSelector::kValley || selector == FaceSelector::kRidge;
}

bool direction_matches(FaceSelector selector, Vec3 normal_sum, bool border) {
  if (selector == FaceSelector::kBorder) return border;
  if (selector == FaceSelector::kInside) return !border;
  if (roof_selector(selector)) return false;
  const double len = length(normal_sum);
  return selector == FaceSelector::kAll ||
         (len > 1e-12 && face_matches(selector, normal_sum / len));
}

}  // namespace

std::optional<FaceSelector> face_selector_named(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, FaceSelector>, 18> kNames = {{
      {"front", FaceSelector::kFront},
      {"back", FaceSelector::kBack},
      {"left", FaceSelector::kLeft},
      {"right", FaceSelector::kRight},
      {"top", FaceSelector::kTop},
      {"bottom", FaceSelector::kBottom},
      {"side", FaceSelector::kSide},
      {"all", FaceSelector::kAll},
      {"vertical", FaceSelector::kVertical},
      {"horizontal", FaceSelector::kHorizontal},
      {"aslant", FaceSelector::kAslant},
      {"nutant", FaceSelector::kNutant},
      {"border", FaceSelector::kBorder},
      {"inside", FaceSelector::kInside},
      {"eave", FaceSelector::kEave},
      {"hip", FaceSelector::kHip},
      {"valley", FaceSelector::kValley},
      {"ridge", FaceSelector::kRidge},
  }};
  for (const auto& [word, selector] : kNames) {
    if (word == name) return selector;
  }
  return std::nullopt;
}

std::vector<MeshEdge> mesh_edges(const Mesh& welded) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> faces_of;
  for (std::size_t f = 0; f < welded.face_count(); ++f) {
    const auto loop = welded.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = loop[i];
      const std::uint32_t b = loop[(i + 1) % loop.size()];
      faces_of[{std::min(a, b), std::max(a, b)}].push_back(static_cast<std::uint32_t>(f));
    }
  }
  std::vector<MeshEdge> edges;
  edges.reserve(faces_of.size());
  for (auto& [ends, faces] : faces_of) edges.push_back({ends.first, ends.second, std::move(faces)});
  return edges;
}

std::vector<bool> select_edges(const Mesh& welded, std::span<const MeshEdge> edges,
                               FaceSelector selector) {
  std::vector<bool> selected(edges.size(), false);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (roof_selector(selector)) {
      selected[e] = roof_class(welded, edges[e]) == selector;
      continue;
    }
    Vec3 normal_sum;
    for (std::uint32_t f : edges[e].faces) normal_sum += kernel::face_normal(welded, f);
    selected[e] = direction_matches(selector, normal_sum, edges[e].faces.size() == 1);
  }
  return selected;
}

std::vector<bool> select_vertices(const Mesh& welded, FaceSelector selector) {
  std::vector<Vec3> normal_sum(welded.vertex_count());
  for (std::size_t f = 0; f < welded.face_count(); ++f) {
    const Vec3 n = kernel::face_normal(welded, f);
    for (std::uint32_t v : welded.face(f)) normal_sum[v] += n;
  }
  std::vector<bool> border(welded.vertex_count(), false);
  for (const MeshEdge& edge : mesh_edges(welded)) {
    if (edge.faces.size() == 1) border[edge.a] = border[edge.b] = true;
  }
  std::vector<bool> selected(welded.vertex_count(), false);
  for (std::size_t v = 0; v < welded.vertex_count(); ++v) {
    selected[v] = direction_matches(selector, normal_sum[v], border[v]);
  }
  return selected;
}

}  // namespace insula::shape
