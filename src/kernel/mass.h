// The closed LOD2 building shell, "the thing users see first": a footprint extruded to its walls
// and capped by a roof (roof.h), as one closed, outward-oriented, watertight mesh with shared
// vertices and no T-junctions (issue 2, "The first job").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/roof.h"

namespace insula::kernel {

struct MassSpec {
  // Height (meters, > 0) above ground_z at which the roof surface passes over the footprint's
  // edges (the low edge of a shed): the eave height. With overhang, pitched walls stop lower, under
  // the soffit, by overhang * tan(pitch); flat and shed walls by the fascia.
  double wall_height = 10;
  RoofType roof = RoofType::kHip;
  double pitch_deg = 30;  // see RoofSpec::pitch_deg
  double overhang = 0;    // meters, >= 0
  double ground_z = 0;    // height of the ground face
  double mansard_pitch_deg = 70;
  double mansard_break_height = 2.5;
  int shed_edge = -1;
  double fascia = 0.25;
  std::optional<double> height = std::nullopt;             // see RoofSpec::height
  std::optional<double> height_limit = std::nullopt;       // see RoofSpec::height_limit
  std::optional<double> direction_deg = std::nullopt;      // see RoofSpec::direction_deg
  RidgeOrientation orientation = RidgeOrientation::kAuto;  // see RoofSpec::orientation
  std::vector<PartyWall> party_walls;                      // see RoofSpec::party_walls
  // false: S3DB building=roof, a roof on posts without walls: the roof as a closed solid (its
  // surface, gable ends and a flat underside at the eave; flat and shed roofs a slab 0.25 m thick
  // under their surface) and a 0.25 m square post from the ground up to it under each outer-ring
  // corner, each post its own closed shell in the same mesh.
  bool walls = true;
};

enum class MassStatus : std::uint8_t {
  kOk,
  kFallback,  // built, with another roof type or without overhang; see message
  kFailed,    // nothing built; see message
};

struct MassResult {
  Mesh mesh;  // empty when kFailed
  MassStatus status = MassStatus::kFailed;
  RoofType roof = RoofType::kFlat;  // the roof type actually built
  std::string message;              // empty when kOk
};

// One closed shell over `footprint` (any orientation; duplicate and collinear vertices are
// removed and self-intersections rejected with a message, see polygon.h repair): ground face(s)
// (GroundSurface), one wall face per footprint edge (WallSurface; a gable wall is one face with its
// gable), soffits (OuterCeilingSurface) and the roof. Face ids: 0 for the ground, then one per
// roof face, then one per wall. Never throws.
MassResult build_mass(const Polygon& footprint, const MassSpec& spec);

}  // namespace insula::kernel
