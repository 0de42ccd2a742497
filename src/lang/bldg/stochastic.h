// Stochastic building generation (seed 000, §4.3): "arranges the rooms (or divisions) by
// priorities, sets up the connected divisions' graph, and randomly arranges them in a treemap-like
// node structure", which is then a Building model like one parsed from a .bldg file (and printed
// as grammar text by print_building, so a generated building can be edited and rebuilt).
//
// Shapes L, U, T and H are made with the fake-concave technique (§3.2): the outline is a
// rectangle and disposable building parts (height 0) cut the notches. The outline is sized from
// the room count. Same spec and seed give the same building, on every platform (no std::
// distributions, no unordered containers).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lang/bldg/model.h"

namespace insula::lang::bldg {

enum class RandomShape : std::uint8_t { kConvex, kL, kU, kT, kH };

struct RandomSpec {
  RandomShape shape = RandomShape::kConvex;
  // Non-disposable building parts; 0 = random in [the shape's minimum, the minimum + 2]. The
  // minimum is 1 for convex, 2 for L and T, 3 for U and H; smaller values are raised to it.
  int parts = 0;
  // Rooms per non-disposable building part, inclusive (Table 2 uses [3-7] ... [11-15]).
  int rooms_min = 3;
  int rooms_max = 7;
  // Room types to draw from, e.g. {"kitchen", "bedroom"}; empty = a default domestic program.
  // Types are placed by priority: public rooms (atrium, hall, living, ...) at the entrance,
  // then service rooms (kitchen, dining, ...), then private rooms (bedroom, bath, ...).
  std::vector<std::string> room_types;
  std::string name = "building";  // Building::name
};

// Parses "L", "U", "T", "H", "convex" (any case); false when unknown.
bool parse_random_shape(const std::string& text, RandomShape& shape);
const char* random_shape_name(RandomShape shape);

// One building. Guarantees (tested on 1,000 seeds): the model passes the moderator (printing it
// and parsing the text gives it back); every non-disposable room is connected to the entrance
// room by doors (a spanning tree over rooms that share a wall in the nominal treemap layout,
// plus a few extra doors); exactly one entrance; containers carry explicit orientations.
Building random_building(const RandomSpec& spec, std::uint64_t seed);

// The seed of building `index` of a batch started with `seed` (splitmix64 of both), so that
// buildings of one batch are independent and `--count` does not change the earlier ones.
std::uint64_t batch_seed(std::uint64_t seed, std::uint64_t index);

}  // namespace insula::lang::bldg
