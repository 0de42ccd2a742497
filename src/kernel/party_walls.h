// Party walls: stretches of a footprint's edges that another footprint's edge runs along (terraced
// houses, a building:part against its neighbour part). A roof's eave must not overhang there: it
// would reach into the neighbour (kernel-roofs.md, "Party walls").
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "kernel/polygon.h"

namespace insula::kernel {

struct PartyWallTolerance {
  double distance = 0.2;    // meters between the two edges' lines (mapped neighbours rarely meet
                            // exactly outside OpenStreetMap, where they share nodes)
  double angle_deg = 3;     // between their directions
  double min_length = 0.5;  // meters of overlap along the edge: less is a corner touching
};

// A stretch [a, b] of one footprint's edge along which `neighbour`'s edge runs.
struct PartyWall {
  std::size_t footprint = 0;
  std::size_t neighbour = 0;
  Vec2 a, b;
};

// Every party wall between two different regions (each a union of polygons, all rings), both
// ways: a shared stretch gives one entry per side. Sorted by footprint, then neighbour.
std::vector<PartyWall> find_party_walls(const std::vector<std::vector<Polygon>>& regions,
                                        const PartyWallTolerance& tolerance = {});

// The stretch of edge [a, b] (as parameters along it, in meters from a) that edge [c, d] runs
// along within `tolerance`, or none.
std::optional<std::pair<double, double>> shared_stretch(Vec2 a, Vec2 b, Vec2 c, Vec2 d,
                                                        const PartyWallTolerance& tolerance = {});

// Whether edge [a, b] runs along one of `walls` (the footprint's own, in the same frame).
bool on_party_wall(Vec2 a, Vec2 b, std::span<const PartyWall> walls,
                   const PartyWallTolerance& tolerance = {});

}  // namespace insula::kernel
