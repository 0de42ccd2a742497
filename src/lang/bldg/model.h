// The checked building model of the ontology-based building grammar (seed 000, §3.1 and §4.1): the
// "structure of ontology-based class instances" that the rules' moderator (§3.3) loads from a
// .bldg file and that the floor-plan engine (§3.2-3.4) and the 3D builder consume. The stochastic
// generator (§4.3) produces the same structure, and the grammar printer turns it back into text,
// so a generated building can be edited and rebuilt.
//
// Ontology (§4.1): a building is made of containers of building parts or final building parts;
// each final part holds at least one floor; each floor holds divisions, which are containers of
// divisions or final rooms; transitions (doors, entrance doors, windows, stairs) connect divisions
// with each other and with the exterior; each part has its own roof.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kernel/polygon.h"

namespace insula::lang::bldg {

// Where a symbol was defined in the .bldg source (1-based; 0 when generated).
struct Location {
  std::uint32_t line = 0;
  std::uint32_t column = 0;
};

// The arrangement axis of a container's children (§3.2, Eq. 1): horizontal = side by side along
// the container's x axis, vertical = stacked along its y axis. The axis alternates per depth when a
// container does not state its own.
enum class Orientation : std::uint8_t { kHorizontal, kVertical, kAlternate };

// §4.1 and §4.6. HipGlued parts in contact share one straight-skeleton roof; None leaves the part
// open (a courtyard wall ring, a ruin).
enum class RoofKind : std::uint8_t {
  kFlat,
  kPyramid,
  kHip,
  kMansard,
  kHoledMansard,
  kNone,
  kGable,
  kHipGlued
};

// Size labels of divisions (§3.3): each grows by its restriction-rule growth factor.
enum class SizeLabel : std::uint8_t { kSmall, kMedium, kBig };

// A final room (a Division with no decomposition).
struct Room {
  std::string type;  // free room type: "kitchen", "bedroom", "atrium", "corridor", ...
  SizeLabel size = SizeLabel::kMedium;
  int walls = 0;  // requested number of delimiting walls (§3.4); 0 = as the subdivision gives
  int windows = 0;
  bool entrance = false;  // an entrance door from the exterior
};

// A division: a final room (room set, no children) or a container of divisions.
struct Division {
  std::string symbol;
  Location where;
  Orientation orientation = Orientation::kAlternate;  // containers only
  std::optional<Room> room;
  std::vector<Division> children;
};

// A storey of a final building part. Floors of one part are stacked in order, level 0 first.
struct Floor {
  std::string symbol;
  Location where;
  double height = 0;  // storey height in meters; 0 = the restriction rules' storey height
  Division layout;    // root container of the floor's divisions
};

// A building part (final: `part` set) or a container of building parts.
struct BuildingPart {
  RoofKind roof = RoofKind::kFlat;
  double height = 0;  // roof height in meters (ridge above the top storey); see `disposable`
  // Height 0 in the grammar marks a disposable part (§3.2, "fake-concave"): it takes part in the
  // subdivision and is removed afterwards, leaving a notch or a hole in the plan.
  bool disposable = false;
  std::vector<Floor> floors;
};

struct PartNode {
  std::string symbol;
  Location where;
  Orientation orientation = Orientation::kAlternate;  // containers only
  std::optional<BuildingPart> part;
  std::vector<PartNode> children;
};

enum class TransitionKind : std::uint8_t {
  kDoor,      // between two rooms (also across building parts)
  kEntrance,  // from the exterior into a room
  kWindow,    // in an exterior wall of a room
  kStair,     // from a room to a room on the next storey up
};

struct Transition {
  std::string symbol;
  Location where;
  TransitionKind kind = TransitionKind::kDoor;
  std::string from;  // room symbol
  std::string to;    // room symbol; empty for entrances and windows
  double width = 0;  // meters; 0 = from the restriction rules
};

// The building axiom: its outline and the tree of parts, floors and divisions.
struct Building {
  std::string symbol;
  std::string name;
  Location where;
  // Outline in meters, counter-clockwise outer ring, optional holes; convex or concave.
  kernel::Polygon outline;
  // When the outline comes from a GeoJSON feature instead of inline coordinates: the file (as
  // written, relative to the .bldg file) and the feature id. The front-end cannot read files
  // (design.md, "Layers"), so the command line fills `outline` before the floor plan is made.
  std::string outline_file;
  std::string outline_feature;
  Location outline_where;
  PartNode layout;  // root container of building parts
  std::vector<Transition> transitions;
};

// Restriction rules (§3.3): every tunable of the floor-plan engine and the 3D builder, read from
// their own file; the defaults are documented in docs/bldg-language.md.
struct Restrictions {
  double initial_weight = 0.001;                   // Fig. 3: starting weight of every room
  std::array<double, 3> growth = {1.5, 2.0, 2.5};  // per SizeLabel (small, medium, big)
  double step = 0.01;                              // Eq. 5: rectangle scaling step
  // Default widths of doors between rooms and of entrance doors (m), unless a transition states
  // one. door_width_fraction > 0 brings back the paper's rule (§3.3): a default door is that
  // fraction of its layout's perimeter, at least door_min_width (entrances at least
  // entrance_width).
  double door_width = 0.9;
  double entrance_width = 1.0;
  double door_width_fraction = 0;
  double door_min_width = 0.9;
  double door_height = 2.1;
  double borrow_limit = 0.25;  // max fraction of a room's weight lent away
  // Rooms that fit (docs/bldg-floorplan.md): a room's cell must hold min_room_area m² and a disc
  // of diameter min_room_width m; a room below either is merged into a neighbour or dropped.
  double min_room_area = 2.0;
  double min_room_width = 1.0;
  double outer_wall_thickness = 0.3;
  double inner_wall_thickness = 0.12;
  double storey_height = 3.0;
  double window_width = 1.2;
  double window_height = 1.2;
  double window_sill = 0.9;
  double base_height = 0.3;    // building base (plinth) below the ground floor
  double footer_height = 0.1;  // room footers (skirting) along inner walls
  double stair_width = 1.0;
  std::vector<std::pair<std::string, std::array<float, 4>>> colors;  // semantic class -> rgba
};

}  // namespace insula::lang::bldg
