// The stochastic generator (seed 000, §4.3) on 1,000 seeded buildings of every shape: each one
// passes the moderator, prints and parses back, has one entrance, reaches every room from it
// through doors, honours the part and room counts and the room list, and is reproducible.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "lang/bldg/printer.h"
#include "lang/bldg/stochastic.h"
#include "test_util.h"

namespace insula::lang::bldg {
namespace {

using testing::for_each_room;

struct Census {
  int real_parts = 0;
  int disposable_parts = 0;
  std::vector<int> rooms_per_real_part;
  std::map<std::string, const Room*> rooms;  // non-disposable rooms by symbol
  std::multiset<std::string> types;
};

void count(const PartNode& node, Census& census) {
  if (node.part) {
    (node.part->disposable ? census.disposable_parts : census.real_parts) += 1;
    int rooms = 0;
    for (const Floor& floor : node.part->floors) {
      for_each_room(floor.layout, [&](const Division& d) {
        ++rooms;
        if (!node.part->disposable) {
          census.rooms[d.symbol] = &*d.room;
          census.types.insert(d.room->type);
        }
      });
    }
    if (!node.part->disposable) census.rooms_per_real_part.push_back(rooms);
  }
  for (const PartNode& child : node.children) count(child, census);
}

// Rooms reached from the entrances through doors (both directions).
std::set<std::string> reached(const Building& b) {
  std::map<std::string, std::vector<std::string>> graph;
  std::vector<std::string> stack;
  for (const Transition& t : b.transitions) {
    if (t.kind == TransitionKind::kEntrance) stack.push_back(t.from);
    if (t.kind == TransitionKind::kDoor) {
      graph[t.from].push_back(t.to);
      graph[t.to].push_back(t.from);
    }
  }
  std::set<std::string> seen(stack.begin(), stack.end());
  while (!stack.empty()) {
    const std::string room = stack.back();
    stack.pop_back();
    for (const std::string& next : graph[room]) {
      if (seen.insert(next).second) stack.push_back(next);
    }
  }
  return seen;
}

int priority_of(const std::string& type) {
  static const std::set<std::string> kPublic = {"hall",     "living",     "atrium", "lobby",
                                                "corridor", "vestibule",  "shop",   "taberna",
                                                "fauces",   "peristylium"};
  static const std::set<std::string> kService = {"kitchen", "dining",  "culina",  "triclinium",
                                                 "pantry",  "storage", "laundry", "tablinum"};
  return kPublic.count(type) ? 0 : kService.count(type) ? 1 : 2;
}

TEST(BldgStochastic, ThousandBuildingsAreValidReachableAndRoundTrip) {
  const RandomShape shapes[] = {RandomShape::kConvex, RandomShape::kL, RandomShape::kU,
                                RandomShape::kT, RandomShape::kH};
  const int expected_disposable[] = {0, 1, 1, 2, 2};
  const int minimum_parts[] = {1, 2, 3, 2, 3};
  for (int i = 0; i < 1000; ++i) {
    RandomSpec spec;
    spec.shape = shapes[i % 5];
    spec.parts = (i / 5) % 6;  // 0 = random
    spec.rooms_min = 1 + (i % 7);
    spec.rooms_max = spec.rooms_min + (i % 5);
    const Building b = random_building(spec, batch_seed(42, static_cast<std::uint64_t>(i)));
    SCOPED_TRACE("building " + std::to_string(i));
    Census census;
    count(b.layout, census);
    EXPECT_EQ(census.disposable_parts, expected_disposable[i % 5]);
    if (spec.parts > 0) {
      EXPECT_EQ(census.real_parts, std::max(spec.parts, minimum_parts[i % 5]));
    } else {
      EXPECT_GE(census.real_parts, minimum_parts[i % 5]);
      EXPECT_LE(census.real_parts, minimum_parts[i % 5] + 2);
    }
    for (const int rooms : census.rooms_per_real_part) {
      EXPECT_GE(rooms, spec.rooms_min);
      EXPECT_LE(rooms, spec.rooms_max);
    }
    // One entrance, on a room of the highest priority present.
    int entrances = 0, best = 3;
    for (const auto& [symbol, room] : census.rooms) best = std::min(best, priority_of(room->type));
    for (const Transition& t : b.transitions) {
      if (t.kind != TransitionKind::kEntrance) continue;
      ++entrances;
      ASSERT_TRUE(census.rooms.count(t.from)) << t.from;
      EXPECT_EQ(priority_of(census.rooms.at(t.from)->type), best);
    }
    EXPECT_EQ(entrances, 1);
    // Doors state their width (1 m, entrances 1.2 m) instead of the perimeter-based default.
    for (const Transition& t : b.transitions) {
      EXPECT_DOUBLE_EQ(t.width, t.kind == TransitionKind::kEntrance ? 1.2 : 1.0);
    }
    // Every real room reachable; no door into a disposable part.
    const std::set<std::string> seen = reached(b);
    for (const auto& [symbol, room] : census.rooms) EXPECT_TRUE(seen.count(symbol)) << symbol;
    EXPECT_EQ(seen.size(), census.rooms.size());
    // The moderator accepts it and the grammar text is canonical.
    const std::string text = print_building(b);
    const base::Source source("random.bldg", text);
    const auto parsed = parse_building(source);
    ASSERT_TRUE(parsed.ok()) << testing::errors(text) << text;
    EXPECT_TRUE(parsed.diagnostics().empty()) << testing::errors(text);
    EXPECT_EQ(print_building(parsed.value()), text);
    EXPECT_GT(kernel::area(parsed->outline), 0);
  }
}

TEST(BldgStochastic, SameSeedSameBuildingOtherSeedOtherBuilding) {
  RandomSpec spec;
  spec.shape = RandomShape::kU;
  const std::string a = print_building(random_building(spec, 7));
  EXPECT_EQ(print_building(random_building(spec, 7)), a);
  EXPECT_NE(print_building(random_building(spec, 8)), a);
  EXPECT_NE(batch_seed(1, 0), batch_seed(1, 1));
  EXPECT_NE(batch_seed(1, 0), batch_seed(2, 0));
}

TEST(BldgStochastic, RoomListIsTheProgram) {
  RandomSpec spec;
  spec.shape = RandomShape::kL;
  spec.room_types = {"kitchen", "bedroom", "bedroom", "living", "bathroom", "dining room"};
  const Building b = random_building(spec, 3);
  Census census;
  count(b.layout, census);
  EXPECT_EQ(census.types,
            std::multiset<std::string>(spec.room_types.begin(), spec.room_types.end()));
  // The living room is the only public room: the entrance is there.
  for (const Transition& t : b.transitions) {
    if (t.kind == TransitionKind::kEntrance) {
      EXPECT_EQ(census.rooms.at(t.from)->type, "living");
    }
  }
  // "dining room" is not an identifier: the printer quotes the type, the symbol is sanitised.
  EXPECT_NE(print_building(b).find("room(\"dining room\""), std::string::npos);
}

TEST(BldgStochastic, ShortRoomListIsRepeatedToFillTheParts) {
  RandomSpec spec;
  spec.shape = RandomShape::kH;
  spec.parts = 4;
  spec.room_types = {"hall", "kitchen"};
  Census census;
  count(random_building(spec, 11).layout, census);
  EXPECT_EQ(census.real_parts, 4);
  EXPECT_EQ(census.types.size(), 4U);
  EXPECT_EQ(census.types.count("hall"), 2U);
}

TEST(BldgStochastic, ShapeNames) {
  RandomShape shape{};
  EXPECT_TRUE(parse_random_shape("u", shape));
  EXPECT_EQ(shape, RandomShape::kU);
  EXPECT_TRUE(parse_random_shape("Convex", shape));
  EXPECT_EQ(shape, RandomShape::kConvex);
  EXPECT_FALSE(parse_random_shape("Z", shape));
  EXPECT_STREQ(random_shape_name(RandomShape::kH), "H");
}

}  // namespace
}  // namespace insula::lang::bldg
