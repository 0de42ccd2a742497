#include "kernel/semantic.h"

#include <array>

namespace insula::kernel {
namespace {

constexpr std::array<std::string_view, kSemanticClassCount> kNames = {"None",
                                                                      "GroundSurface",
                                                                      "WallSurface",
                                                                      "RoofSurface",
                                                                      "OuterCeilingSurface",
                                                                      "OuterFloorSurface",
                                                                      "ClosureSurface",
                                                                      "FloorSurface",
                                                                      "InteriorWallSurface",
                                                                      "CeilingSurface",
                                                                      "Door",
                                                                      "Window",
                                                                      "Jamb",
                                                                      "Sill",
                                                                      "Lintel",
                                                                      "Stair"};

}  // namespace

std::string_view semantic_name(SemanticClass semantic) {
  return kNames[static_cast<std::size_t>(semantic)];
}

std::optional<SemanticClass> semantic_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == name) return static_cast<SemanticClass>(i);
  }
  return std::nullopt;
}

std::string_view citygml_surface(SemanticClass semantic) {
  switch (semantic) {
    case SemanticClass::kNone:
      return {};
    case SemanticClass::kJamb:
    case SemanticClass::kSill:
    case SemanticClass::kLintel:
      return "WallSurface";
    case SemanticClass::kStair:
      return "FloorSurface";
    default:
      return semantic_name(semantic);
  }
}

}  // namespace insula::kernel
