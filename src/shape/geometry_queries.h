// Measures and tests of a shape's geometry (CityEngine's geometry.* functions; any front-end may
// ask them): the mesh is in scope coordinates, `scope` takes it to the world (Z up) where a query
// needs the world's vertical (height, slope, azimuth).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "kernel/mesh.h"
#include "shape/ops.h"
#include "shape/scope.h"

namespace insula::shape {

enum class GeometryQuery : std::uint8_t {
  kArea,             // area(selector = all): faces the selector picks (comp's face selectors)
  kVolume,           // volume(): enclosed volume, 0 when not closed
  kVertices,         // nVertices()
  kFaces,            // nFaces()
  kEdges,            // nEdges(): distinct edges after welding
  kHeight,           // height(): extent along the world's vertical
  kAngle,            // angle(maxSlope | azimuth | zenith), degrees
  kBoundaryLength,   // boundaryLength(): edges of one face only
  kHoles,            // nHoles(): holes in the faces (a flat shape's outline's)
  kIsClosedSurface,  // isClosedSurface(): every edge shared by exactly two faces
  kIsOriented,       // isOriented(selector): every face picked by the face selector
  kIsConcave,        // isConcave(): some face is not convex
  kIsPlanar,         // isPlanar(tolerance degrees): every face in one plane
  kIsRectangular,    // isRectangular(tolerance degrees): one face, four right angles
};

// The argument a query takes besides the geometry.
enum class QueryArgument : std::uint8_t { kNone, kFaceSelector, kAngleType, kTolerance };

struct GeometryQueryInfo {
  std::string_view name;  // CityEngine's name, without "geometry."
  GeometryQuery query;
  QueryArgument argument;
  bool optional_argument;
  std::string_view doc;
};
std::span<const GeometryQueryInfo> geometry_queries();
// Whether the query is a test (CityEngine returns a bool: isClosedSurface, isConcave, ...).
inline bool is_test(GeometryQuery query) {
  return query >= GeometryQuery::kIsClosedSurface;
}
const GeometryQueryInfo* find_geometry_query(std::string_view name);

enum class AngleType : std::uint8_t { kMaxSlope, kAzimuth, kZenith };
std::optional<AngleType> angle_type_named(std::string_view name);

// The option of a face selector argument (area, isOriented): comp's face selectors and `surface`
// (all) as their FaceSelector; the world.*/object.* frame words (street.* read as object.*) from
// kFrameOption on. nullopt for any other word (the roof edge classes among them).
inline constexpr std::uint8_t kFrameOption = 64;
std::optional<std::uint8_t> face_option_named(std::string_view word);

// What the query answers (numbers; tests 1 or 0). `option` is the face option or AngleType the
// query takes, `tolerance` its degrees, `object` the object frame's scope (null: the world's),
// `outline` a flat shape's outline (its holes are the faces' holes: the mesh has none).
double geometry_query(const kernel::Mesh& mesh, const Scope& scope, GeometryQuery query,
                      std::uint8_t option, double tolerance, const Scope* object = nullptr,
                      const kernel::Polygon* outline = nullptr);

}  // namespace insula::shape
