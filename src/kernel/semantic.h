// Semantic classes of faces, after CityGML 3.0 boundary surfaces (design.md, "The shared shape
// model"). Opening parts (jamb, sill, lintel) are kept apart so exporters and renderers can tell
// them, and map to WallSurface in CityGML.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace insula::kernel {

enum class SemanticClass : std::uint8_t {
  kNone,
  kGroundSurface,
  kWallSurface,
  kRoofSurface,
  kOuterCeilingSurface,  // e.g. the soffit under a roof overhang
  kOuterFloorSurface,
  kClosureSurface,
  kFloorSurface,
  kInteriorWallSurface,
  kCeilingSurface,
  kDoor,
  kWindow,
  kJamb,
  kSill,
  kLintel,
  kStair,
};

inline constexpr int kSemanticClassCount = 16;

// "WallSurface", "RoofSurface", ...; "None" for kNone.
std::string_view semantic_name(SemanticClass semantic);
std::optional<SemanticClass> semantic_from_name(std::string_view name);
// The CityGML/CityJSON surface type this class is exported as ("WallSurface" for jamb, sill and
// lintel); empty for kNone.
std::string_view citygml_surface(SemanticClass semantic);

}  // namespace insula::kernel
