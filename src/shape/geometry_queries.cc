// CityEngine's geometry.* functions (CGA reference, "geometry functions") on Insula's meshes.
#include "shape/geometry_queries.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "kernel/planar.h"

namespace insula::shape {

using kernel::Mesh;
using kernel::Vec2;
using kernel::Vec3;

namespace {

constexpr double kDegree = std::numbers::pi / 180;

constexpr std::array<GeometryQueryInfo, 14> kQueries = {{
    {"area", GeometryQuery::kArea, QueryArgument::kFaceSelector, true,
     "surface area of the faces a comp selector picks (default: all)"},
    {"volume", GeometryQuery::kVolume, QueryArgument::kNone, false,
     "volume the geometry encloses (0 when it is not closed)"},
    {"nVertices", GeometryQuery::kVertices, QueryArgument::kNone, false, "number of vertices"},
    {"nFaces", GeometryQuery::kFaces, QueryArgument::kNone, false, "number of faces"},
    {"nEdges", GeometryQuery::kEdges, QueryArgument::kNone, false,
     "number of distinct edges (faces sharing an edge count it once)"},
    {"height", GeometryQuery::kHeight, QueryArgument::kNone, false,
     "extent of the geometry along the world's vertical"},
    {"angle", GeometryQuery::kAngle, QueryArgument::kAngleType, false,
     "maxSlope (steepest face against the horizontal), azimuth (its downhill direction, clockwise "
     "from north) or zenith (90 - maxSlope), in degrees"},
    {"boundaryLength", GeometryQuery::kBoundaryLength, QueryArgument::kNone, false,
     "length of the edges that belong to one face only"},
    {"nHoles", GeometryQuery::kHoles, QueryArgument::kNone, false,
     "number of holes in the faces (a courtyard in a lot is one)"},
    {"isClosedSurface", GeometryQuery::kIsClosedSurface, QueryArgument::kNone, false,
     "true when every edge is shared by exactly two faces"},
    {"isOriented", GeometryQuery::kIsOriented, QueryArgument::kFaceSelector, false,
     "true when every face faces as the selector says (comp's face selectors, world.*, object.*)"},
    {"isConcave", GeometryQuery::kIsConcave, QueryArgument::kNone, false,
     "true when some face is not convex"},
    {"isPlanar", GeometryQuery::kIsPlanar, QueryArgument::kTolerance, false,
     "true when every face lies in one plane (normals within the tolerance, degrees)"},
    {"isRectangular", GeometryQuery::kIsRectangular, QueryArgument::kTolerance, false,
     "true for one face with four corners, each within the tolerance (degrees) of a right angle"},
}};

// A face's loop in its own plane (u, v), for the 2D tests.
std::vector<Vec2> face_in_plane(const Mesh& mesh, std::size_t face) {
  const Vec3 n = kernel::face_normal(mesh, face);
  Vec3 u;
  Vec3 v;
  Vec3 w;
  std::vector<Vec2> ring;
  const auto loop = mesh.face(face);
  if (loop.empty() ||
      !make_frame(mesh.position(loop[1 % loop.size()]) - mesh.position(loop[0]), n, u, v, w)) {
    return ring;
  }
  for (std::uint32_t i : loop) {
    const Vec3 p = mesh.position(i) - mesh.position(loop[0]);
    ring.push_back({dot(p, u), dot(p, v)});
  }
  return ring;
}

// The corners of a ring that are not straight (collinear vertices dropped).
std::vector<Vec2> corners(const std::vector<Vec2>& ring) {
  std::vector<Vec2> out;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[(i + n - 1) % n];
    const Vec2 b = ring[i];
    const Vec2 c = ring[(i + 1) % n];
    const Vec2 d1 = b - a;
    const Vec2 d2 = c - b;
    const double turn = d1.x * d2.y - d1.y * d2.x;
    if (std::fabs(turn) > 1e-9 * length(d1) * length(d2)) out.push_back(b);
  }
  return out;
}

bool rectangular(const Mesh& mesh, double tolerance) {
  if (mesh.face_count() != 1) return false;
  const std::vector<Vec2> ring = corners(face_in_plane(mesh, 0));
  if (ring.size() != 4) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec2 d1 = ring[i] - ring[(i + 3) % 4];
    const Vec2 d2 = ring[(i + 1) % 4] - ring[i];
    const double angle = std::acos(std::clamp(dot(d1, d2) / (length(d1) * length(d2)), -1.0, 1.0));
    if (std::fabs(angle - std::numbers::pi / 2) > tolerance * kDegree) return false;
  }
  return true;
}

bool planar(const Mesh& mesh, double tolerance) {
  if (mesh.face_count() == 0) return false;
  const Vec3 n0 = kernel::face_normal(mesh, 0);
  const Vec3 p0 = mesh.position(mesh.face(0)[0]);
  const double extent = std::max(length(mesh.bounds().size()), 1e-9);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Vec3 n = kernel::face_normal(mesh, f);
    if (std::acos(std::clamp(dot(n, n0), -1.0, 1.0)) > tolerance * kDegree + 1e-9) return false;
    for (std::uint32_t v : mesh.face(f)) {
      if (std::fabs(dot(mesh.position(v) - p0, n0)) >
          extent * std::sin(tolerance * kDegree) + 1e-7) {
        return false;
      }
    }
  }
  return true;
}

// Which faces a face option (face_option_named) picks.
std::vector<bool> picked_faces(const Mesh& mesh, std::uint8_t option, const Scope& scope,
                               const Scope* object) {
  std::vector<bool> picked(mesh.face_count(), false);
  if (option >= kFrameOption) {
    const std::vector<std::string> words = frame_selector_words();
    const std::optional<FrameSelector> frame =
        frame_selector_named(words[std::min<std::size_t>(option - kFrameOption, words.size() - 1)]);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      picked[f] = face_matches_in_frame(
          *frame, scope.direction_to_world(kernel::face_normal(mesh, f)), object);
    }
    return picked;
  }
  const auto selector = static_cast<FaceSelector>(option);
  const bool by_border = selector == FaceSelector::kBorder || selector == FaceSelector::kInside;
  const std::vector<bool> border = by_border ? border_faces(mesh) : std::vector<bool>();
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    picked[f] = by_border ? (f < border.size() && border[f] == (selector == FaceSelector::kBorder))
                          : face_matches(selector, kernel::face_normal(mesh, f));
  }
  return picked;
}

// The steepest face's slope against the horizontal (degrees) and the azimuth it falls towards.
std::pair<double, double> steepest(const Mesh& mesh, const Scope& scope) {
  double slope = 0;
  double azimuth = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (kernel::face_area(mesh, f) <= 0) continue;
    const Vec3 n = scope.direction_to_world(kernel::face_normal(mesh, f));
    const double angle = std::acos(std::clamp(std::fabs(n.z), 0.0, 1.0)) / kDegree;
    if (angle <= slope) continue;
    slope = angle;
    // Downhill is the normal's horizontal part for a face facing up (x east, y north).
    const double east = n.z >= 0 ? n.x : -n.x;
    const double north = n.z >= 0 ? n.y : -n.y;
    azimuth = std::fmod(std::atan2(east, north) / kDegree + 360, 360);
  }
  return {slope, azimuth};
}

double edge_measure(const Mesh& mesh, GeometryQuery query) {
  const Mesh welded = kernel::weld(mesh);
  const std::vector<MeshEdge> edges = mesh_edges(welded);
  if (query == GeometryQuery::kEdges) return static_cast<double>(edges.size());
  if (query == GeometryQuery::kIsClosedSurface) {
    return !edges.empty() && std::all_of(edges.begin(), edges.end(),
                                         [](const MeshEdge& e) { return e.faces.size() == 2; })
               ? 1
               : 0;
  }
  double border = 0;
  for (const MeshEdge& e : edges) {
    if (e.faces.size() == 1) border += length(welded.position(e.b) - welded.position(e.a));
  }
  return border;
}

}  // namespace

std::span<const GeometryQueryInfo> geometry_queries() {
  return kQueries;
}

const GeometryQueryInfo* find_geometry_query(std::string_view name) {
  for (const GeometryQueryInfo& q : kQueries) {
    if (q.name == name) return &q;
  }
  return nullptr;
}

std::optional<AngleType> angle_type_named(std::string_view name) {
  if (name == "maxSlope") return AngleType::kMaxSlope;
  if (name == "azimuth") return AngleType::kAzimuth;
  if (name == "zenith") return AngleType::kZenith;
  return std::nullopt;
}

std::optional<std::uint8_t> face_option_named(std::string_view word) {
  if (word == "surface") return static_cast<std::uint8_t>(FaceSelector::kAll);
  // Without street data CityEngine reads street.* as the initial shape's own sides.
  const std::string frame_word =
      word.starts_with("street.") ? "object." + std::string(word.substr(7)) : std::string(word);
  const std::vector<std::string> words = frame_selector_words();
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (words[i] == frame_word) return static_cast<std::uint8_t>(kFrameOption + i);
  }
  const std::optional<FaceSelector> selector = face_selector_named(word);
  if (!selector || *selector >= FaceSelector::kEave) return std::nullopt;
  return static_cast<std::uint8_t>(*selector);
}

double geometry_query(const Mesh& mesh, const Scope& scope, GeometryQuery query,
                      std::uint8_t option, double tolerance, const Scope* object,
                      const kernel::Polygon* outline) {
  switch (query) {
    case GeometryQuery::kHoles:
      return outline != nullptr ? static_cast<double>(outline->holes.size()) : 0;
    case GeometryQuery::kArea: {
      const std::vector<bool> picked = picked_faces(mesh, option, scope, object);
      double sum = 0;
      for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        if (picked[f]) sum += kernel::face_area(mesh, f);
      }
      return sum;
    }
    case GeometryQuery::kVolume:
      return std::fabs(kernel::volume(mesh));
    case GeometryQuery::kVertices:
      return static_cast<double>(mesh.vertex_count());
    case GeometryQuery::kFaces:
      return static_cast<double>(mesh.face_count());
    case GeometryQuery::kHeight: {
      if (mesh.face_count() == 0) return 0;
      return mesh_to_world(mesh, scope).bounds().size().z;
    }
    case GeometryQuery::kAngle: {
      const auto [slope, azimuth] = steepest(mesh, scope);
      const auto type = static_cast<AngleType>(option);
      return type == AngleType::kMaxSlope ? slope
             : type == AngleType::kZenith ? 90 - slope
                                          : azimuth;
    }
    case GeometryQuery::kIsConcave:
      for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        if (!kernel::is_convex(face_in_plane(mesh, f), kernel::Winding::kEither, 1e-12)) return 1;
      }
      return 0;
    case GeometryQuery::kIsOriented: {
      const std::vector<bool> picked = picked_faces(mesh, option, scope, object);
      return !picked.empty() && std::all_of(picked.begin(), picked.end(), [](bool b) { return b; })
                 ? 1
                 : 0;
    }
    case GeometryQuery::kIsPlanar:
      return planar(mesh, tolerance) ? 1 : 0;
    case GeometryQuery::kIsRectangular:
      return rectangular(mesh, tolerance) ? 1 : 0;
    case GeometryQuery::kEdges:
    case GeometryQuery::kBoundaryLength:
    case GeometryQuery::kIsClosedSurface:
      return edge_measure(mesh, query);
  }
  return 0;
}

}  // namespace insula::shape
