// Helpers shared by the mesh writers (OBJ, glTF, CityJSON, SVG): triangles of a planar n-gon face,
// a deterministic material table, and names safe for formats that split names at whitespace.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/triangulate.h"
#include "shape/scene.h"

namespace insula::io {

using CornerTriangle = std::array<std::uint32_t, 3>;

// Triangulates planar n-gon faces of meshes, reusing its buffers from face to face.
class FaceTriangulator {
 public:
  // Appends the triangles of face `face` of `mesh` to `triangles`, as corner positions in the
  // face's loop (0 .. n-1), each counter-clockwise around `normal`, the face's Newell normal
  // (kernel::face_normal). The face is projected to its dominant coordinate plane. A strictly
  // convex face gets the triangles kernel::triangulate's ear clipper gives it (ear at corner 0,
  // then every second remaining corner) without running it; any other face is triangulated with
  // kernel::triangulate, so concave faces come out right, and a convex face the triangulator
  // rejects falls back to a fan. Returns false and appends nothing for a degenerate face (zero
  // normal, or non-convex and rejected by the triangulator).
  bool triangulate(const kernel::Mesh& mesh, std::size_t face, kernel::Vec3 normal,
                   std::vector<CornerTriangle>& triangles);
  // The same for a face given as its corners' positions.
  bool triangulate(std::span<const kernel::Vec3> corners, kernel::Vec3 normal,
                   std::vector<CornerTriangle>& triangles);
  // The triangles of a face loop whose corners with equal `keys` are written as one point (the
  // corners rounded to one float32 or grid position), as corner positions in the loop: the loop
  // contracted (kernel::contract_loop) and each piece triangulated at the corners' `positions`.
  // A piece the triangulator rejects (rounding may make it overlap itself) is fanned instead:
  // every fan triangle follows the loop's orientation, so a closed shell stays closed.
  void triangulate_contracted(std::span<const std::uint32_t> keys,
                              std::span<const kernel::Vec3> positions, kernel::Vec3 normal,
                              std::vector<CornerTriangle>& triangles);

 private:
  template <typename Position>
  bool triangulate_corners(std::size_t n, Position position, kernel::Vec3 normal,
                           std::vector<CornerTriangle>& triangles);
  bool triangulate_ring(std::vector<CornerTriangle>& triangles);

  void triangulate_piece(std::span<const std::uint32_t> corners,
                         std::span<const kernel::Vec3> positions, kernel::Vec3 normal,
                         std::vector<CornerTriangle>& triangles);

  kernel::Polygon polygon_;
  kernel::Triangulation result_;  // a concave face's, its lists kept from face to face
  std::vector<std::uint32_t> next_;
  std::vector<std::uint32_t> prev_;
  std::vector<std::uint32_t> whole_;  // 0 .. n-1: a loop that contracts nowhere
  std::vector<kernel::Vec3> piece_;   // a piece's corners' positions
  std::vector<CornerTriangle> piece_triangles_;
};

// std::llround (halves away from zero) without its library call, which cost more than the rest
// of quantizing a vertex; `value` must be finite and below 2^62 in magnitude. The correction is
// added without a branch: which way a coordinate's fraction falls is a coin toss the branch
// predictor lost about half the time.
inline std::int64_t round_half_away(double value) {
  const auto whole = static_cast<std::int64_t>(value);     // toward zero
  const double rest = value - static_cast<double>(whole);  // exact
  return whole + static_cast<std::int64_t>(rest >= 0.5) - static_cast<std::int64_t>(rest <= -0.5);
}

// `name` with every whitespace or control character replaced by '_' (OBJ splits names at blanks);
// `fallback` when `name` is empty.
std::string safe_name(std::string_view name, std::string_view fallback);

// The materials faces of a scene show, in a fixed order: the scene's own materials used by some
// face (by id), then the default colour of each semantic class used by faces without a material
// (by class). Names are made safe and unique ("roof", "roof_2", ...).
class MaterialTable {
 public:
  // `by_class`: every face shows its semantic class's default colour (walls, roofs, windows...),
  // whatever material it was given: a view of what each face is.
  explicit MaterialTable(const shape::Scene& scene, bool by_class = false);

  // Index into materials() of the material a face with `tag` shows.
  std::uint32_t index(const kernel::FaceTag& tag) const;
  const std::vector<shape::Material>& materials() const { return materials_; }

 private:
  static constexpr std::uint32_t kNone = UINT32_MAX;
  // Class keys follow the scene materials, one per value a SemanticClass can hold.
  static constexpr std::size_t kKeysPerClass =
      std::size_t{std::numeric_limits<std::underlying_type_t<kernel::SemanticClass>>::max()} + 1;

  std::uint32_t key(const kernel::FaceTag& tag) const;

  bool by_class_ = false;
  std::size_t scene_material_count_ = 0;
  std::vector<std::uint32_t> index_by_key_;  // by key(); kNone for keys no face uses
  std::vector<shape::Material> materials_;
};

}  // namespace insula::io
