// Slots for doors and windows (plan_openings.h, seed 000 §3.3): a slot keeps its clearance from the
// openings already on its wall line, and find_slot through an OpeningIndex (the doors and windows
// stages) finds exactly the slot the scan of every opening finds, while openings are appended.
// One room's boundary pieces equal those the storey-wide listing gives it.
#include "lang/bldg/plan_openings.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "lang/bldg/stochastic.h"

namespace insula::lang::bldg {
namespace {

using kernel::Vec2;
using plan::OpeningIndex;
using plan::Slot;

PlanDoor door_at(Vec2 a, Vec2 b) {
  PlanDoor d;
  d.a = a;
  d.b = b;
  d.center = (a + b) * 0.5;
  return d;
}

PlanWindow window_at(Vec2 a, Vec2 b) {
  PlanWindow w;
  w.a = a;
  w.b = b;
  w.center = (a + b) * 0.5;
  return w;
}

void expect_same(const std::optional<Slot>& x, const std::optional<Slot>& y) {
  ASSERT_EQ(x.has_value(), y.has_value());
  if (!x) return;
  EXPECT_EQ(x->a.x, y->a.x);
  EXPECT_EQ(x->a.y, y->a.y);
  EXPECT_EQ(x->b.x, y->b.x);
  EXPECT_EQ(x->b.y, y->b.y);
  EXPECT_EQ(x->center.x, y->center.x);
  EXPECT_EQ(x->center.y, y->center.y);
}

TEST(PlanOpenings, SlotKeepsClearFromTheOpeningsOnItsLine) {
  PlanStorey storey;
  // A door on the wall's line at [4, 5] and one 1 mm beside the line (on another wall, ignored):
  // the slot of 1 m with 0.2 m clearance nearest the middle (5) starts at 5 + 0.2.
  storey.doors.push_back(door_at({4, 0}, {5, 0}));
  storey.doors.push_back(door_at({5.2, 0.001}, {6.2, 0.001}));
  OpeningIndex index(storey);
  for (const std::optional<Slot>& slot : {plan::find_slot(storey, {0, 0}, {10, 0}, 1, 0.2),
                                          plan::find_slot(index, {0, 0}, {10, 0}, 1, 0.2)}) {
    ASSERT_TRUE(slot.has_value());
    EXPECT_DOUBLE_EQ(slot->a.x, 5.2);
    EXPECT_DOUBLE_EQ(slot->b.x, 6.2);
    EXPECT_DOUBLE_EQ(slot->center.x, 5.7);
    EXPECT_EQ(slot->a.y, 0);
  }
  // A window appended after the index was built leaves 0.2 m beside the door on the right: the
  // slot moves left of the first door, ending 0.2 m before it.
  storey.windows.push_back(window_at({9.8, 0}, {5.6, 0}));
  for (const std::optional<Slot>& slot : {plan::find_slot(storey, {0, 0}, {10, 0}, 1, 0.2),
                                          plan::find_slot(index, {0, 0}, {10, 0}, 1, 0.2)}) {
    ASSERT_TRUE(slot.has_value());
    EXPECT_DOUBLE_EQ(slot->a.x, 2.8);
    EXPECT_DOUBLE_EQ(slot->b.x, 3.8);
  }
  // Vertical wall: the openings above lie across it, none on it.
  expect_same(plan::find_slot(storey, {5, -3}, {5, 3}, 1, 0.2),
              plan::find_slot(index, {5, -3}, {5, 3}, 1, 0.2));
  EXPECT_EQ(plan::find_slot(index, {5, -3}, {5, 3}, 1, 0.2)->center.y, 0);
}

// Random storeys of openings on a few horizontal, vertical and oblique lines (some a fraction of
// the 0.1 mm line tolerance off, some just past it), appended one by one between queries along
// those lines: the indexed search gives the scan's slot bits every time, also after the lists are
// cut short (the index lists them again).
TEST(PlanOpenings, IndexedSlotsEqualScannedSlots) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const double offsets[] = {0, 3e-5, -6e-5, 9.9e-5, -1.01e-4, 1.5e-4, -2.5e-4, 1e-3};
  int compared = 0;
  int found = 0;
  for (int it = 0; it < 60; ++it) {
    PlanStorey storey;
    OpeningIndex index(storey);
    const double base_x = 100 * (u(rng) - 0.5);
    const double base_y = 100 * (u(rng) - 0.5);
    auto line_point = [&](int line, double s, double off) -> Vec2 {
      switch (line % 3) {
        case 0:  // horizontal
          return {base_x + s, base_y + line + off};
        case 1:  // vertical
          return {base_x + line + off, base_y + s};
        default:  // oblique
          return {base_x + s * 0.6 + off, base_y + line + s * 0.8};
      }
    };
    for (int step = 0; step < 80; ++step) {
      const int line = static_cast<int>(u(rng) * 6);
      const double s = 20 * u(rng);
      const double w = 0.6 + u(rng);
      const Vec2 a = line_point(line, s, offsets[static_cast<int>(u(rng) * 8)]);
      const Vec2 b = line_point(line, s + w, offsets[static_cast<int>(u(rng) * 8)]);
      const double kind = u(rng);
      if (kind < 0.3) {
        storey.doors.push_back(door_at(a, b));
      } else if (kind < 0.4) {
        storey.entrances.push_back(door_at(b, a));
      } else {
        storey.windows.push_back(window_at(a, b));
      }
      if (step == 50) storey.windows.resize(storey.windows.size() / 2);
      for (int q = 0; q < 3; ++q) {
        const int qline = static_cast<int>(u(rng) * 6);
        const double s0 = 10 * u(rng);
        const Vec2 p = line_point(qline, s0, 0);
        const Vec2 e = line_point(qline, s0 + 3 + 10 * u(rng), 0);
        const double prefer = u(rng) < 0.5 ? -1 : 5 * u(rng);
        const std::optional<Slot> scanned = plan::find_slot(storey, p, e, 0.9, 0.2, {}, prefer);
        expect_same(scanned, plan::find_slot(index, p, e, 0.9, 0.2, {}, prefer));
        ++compared;
        if (scanned) ++found;
      }
    }
  }
  EXPECT_EQ(compared, 60 * 80 * 3);
  // Both outcomes occur: walls with room left and walls filled up.
  EXPECT_GT(found, compared / 10);
  EXPECT_LT(found, compared);
}

// room_pieces (one room, its neighbours found by a scan of every box) lists what StoreyCells
// (the storey's touching lists) lists for that room, piece for piece, on generated plans with
// several parts, storeys and dead zones; open_air_pieces likewise for both routes.
TEST(PlanOpenings, RoomPiecesEqualTheStoreyCellsPieces) {
  const RandomShape shapes[] = {RandomShape::kConvex, RandomShape::kL, RandomShape::kU,
                                RandomShape::kT, RandomShape::kH};
  int rooms = 0;
  int shared = 0;
  for (int i = 0; i < 10; ++i) {
    RandomSpec spec;
    spec.shape = shapes[i % 5];
    spec.parts = 1 + i % 4;
    spec.rooms_min = 3;
    spec.rooms_max = 9;
    const Building building = random_building(spec, batch_seed(41, static_cast<std::uint64_t>(i)));
    const base::Result<FloorPlan> plan = make_floor_plan(building, Restrictions{});
    ASSERT_TRUE(plan.ok());
    for (const PlanStorey& storey : plan.value().storeys) {
      const plan::StoreyCells cells(storey);
      for (int r = 0; r < static_cast<int>(storey.rooms.size()); ++r) {
        const std::vector<plan::EdgePiece> alone = plan::room_pieces(storey, r);
        const std::vector<plan::EdgePiece>& listed = cells.pieces(r);
        ASSERT_EQ(alone.size(), listed.size());
        for (std::size_t k = 0; k < alone.size(); ++k) {
          EXPECT_EQ(alone[k].a.x, listed[k].a.x);
          EXPECT_EQ(alone[k].a.y, listed[k].a.y);
          EXPECT_EQ(alone[k].b.x, listed[k].b.x);
          EXPECT_EQ(alone[k].b.y, listed[k].b.y);
          EXPECT_EQ(alone[k].other, listed[k].other);
          if (alone[k].other >= 0) ++shared;
        }
        EXPECT_EQ(plan::open_air_pieces(storey, r, plan.value().footprint).size(),
                  plan::open_air_pieces(storey, cells, r, plan.value().footprint).size());
        ++rooms;
      }
    }
  }
  EXPECT_GT(rooms, 50);
  EXPECT_GT(shared, rooms);  // rooms have neighbours: the lists are not all exterior
}

}  // namespace
}  // namespace insula::lang::bldg
