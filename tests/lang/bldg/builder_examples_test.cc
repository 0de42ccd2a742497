// Every example of examples/bldg/ through the whole pipeline (parse_building -> make_floor_plan ->
// build_building): every part closed and outward, no builder warning, one room part per room of
// the plan, and a golden summary per example (tests/data/bldg/examples/<stem>.txt: counts, room
// clear-floor areas, parts; regenerate with INSULA_UPDATE_GOLDEN=1).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "kernel/mesh.h"
#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/parser.h"
#include "test_util.h"

namespace insula::lang::bldg {
namespace {

std::filesystem::path examples_dir() {
  return std::filesystem::path(INSULA_SOURCE_DIR) / "examples" / "bldg";
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string summary(const BuildResult& r) {
  const BuildStats& s = r.stats;
  std::string out = "building " + r.building.id + "\n";
  out += "storeys " + std::to_string(s.storeys) + " rooms " + std::to_string(s.rooms) + " walls " +
         std::to_string(s.walls) + " doors " + std::to_string(s.doors) + " entrances " +
         std::to_string(s.entrances) + " windows " + std::to_string(s.windows) + " stairs " +
         std::to_string(s.stairs) + " roofs " + std::to_string(s.roofs) + "\n";
  out +=
      "vertices " + std::to_string(s.vertices) + " triangles " + std::to_string(s.triangles) + "\n";
  for (const shape::Part& p : r.building.parts) {
    const kernel::MeshCheck c = kernel::check(p.mesh);
    out += "part '" + p.name + "' faces " + std::to_string(p.mesh.face_count()) + " shells " +
           std::to_string(c.components) + " volume " + fixed(kernel::volume(p.mesh), 2);
    if (p.kind == shape::PartKind::kRoom) {
      out += " area " + fixed(std::get<double>(p.attributes.at("area")), 2);
    }
    out += "\n";
  }
  return out;
}

void expect_golden(const std::string& name, const std::string& text) {
  const std::filesystem::path path = testing::data_dir() / "examples" / (name + ".txt");
  if (std::getenv("INSULA_UPDATE_GOLDEN") != nullptr) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return;
  }
  EXPECT_EQ(testing::read_file(path), text)
      << "golden " << path << " (INSULA_UPDATE_GOLDEN=1 regenerates it)";
}

struct Built {
  FloorPlan plan;
  BuildResult result;
};

// parse_building -> make_floor_plan -> build_building with the default rules; nothing (and a test
// failure) when a stage fails.
std::optional<Built> build_source(const base::Source& source) {
  const base::Result<Building> building = parse_building(source);
  if (!building.ok()) {
    ADD_FAILURE() << source.name() << " does not parse";
    return std::nullopt;
  }
  const Restrictions rules;
  const base::Result<FloorPlan> plan = make_floor_plan(building.value(), rules);
  if (!plan.ok()) {
    ADD_FAILURE() << source.name() << " has no floor plan";
    return std::nullopt;
  }
  BuildResult result = build_building(building.value(), plan.value(), rules);
  return Built{plan.value(), std::move(result)};
}

TEST(BuilderExamples, BuildClosedAndMatchTheirGoldens) {
  const auto files = testing::files_in(examples_dir(), ".bldg");
  ASSERT_GE(files.size(), 9U);
  for (const std::filesystem::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::optional<Built> built =
        build_source(base::Source(file.string(), testing::read_file(file)));
    ASSERT_TRUE(built.has_value());
    const FloorPlan* plan = &built->plan;
    const BuildResult& r = built->result;
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    std::size_t rooms = 0;
    for (const PlanStorey& s : plan->storeys) rooms += s.rooms.size();
    EXPECT_EQ(r.stats.rooms, rooms);
    EXPECT_EQ(r.building.plans.size(), plan->storeys.size());
    for (const shape::Part& p : r.building.parts) {
      const kernel::MeshCheck c = kernel::check(p.mesh);
      EXPECT_TRUE(c.closed && c.oriented && c.non_manifold_edges == 0) << p.name;
      EXPECT_GT(kernel::volume(p.mesh), 0) << p.name;
    }
    expect_golden(file.stem().string(), summary(r));
  }
}

// An L-shaped lot (20 x 20 m less its north-east quarter, 300 m²) under every example: walls stay
// on the lot's axes, the rooms share the whole storey (no dead zone), their clear floors add up to
// the storey less its walls, every room is reachable, and doors keep the absolute default widths.
TEST(BuilderExamples, OnAnLShapedLot) {
  const kernel::Polygon lot{{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}}, {}};
  const Restrictions rules;
  for (const std::filesystem::path& file : testing::files_in(examples_dir(), ".bldg")) {
    SCOPED_TRACE(file.string());
    const base::Source source(file.string(), testing::read_file(file));
    base::Result<Building> building = parse_building(source);
    ASSERT_TRUE(building.ok());
    building.value().outline = lot;
    const base::Result<FloorPlan> plan = make_floor_plan(building.value(), rules);
    ASSERT_TRUE(plan.ok());
    const BuildResult built = build_building(building.value(), plan.value(), rules);
    EXPECT_TRUE(built.warnings.empty()) << built.warnings.front();
    EXPECT_TRUE(plan->unreachable_rooms.empty()) << plan->unreachable_rooms.front().reason;
    for (const PlanStorey& s : plan->storeys) {
      SCOPED_TRACE("storey " + std::to_string(s.level));
      EXPECT_TRUE(s.dead_zones.empty()) << s.dead_zones.front().reason;
      double storey_area = 0;
      for (const PlanPart& part : plan->parts)
        if (part.storeys > s.level) storey_area += kernel::area(part.outline);
      double rooms_area = 0;
      for (const PlanRoom& room : s.rooms) {
        rooms_area += kernel::area(room.cell);
        const std::size_t n = room.cell.outer.size();
        for (std::size_t i = 0; i < n; ++i) {
          const kernel::Vec2 d = room.cell.outer[(i + 1) % n] - room.cell.outer[i];
          EXPECT_TRUE(std::abs(d.x) < 1e-6 || std::abs(d.y) < 1e-6)
              << room.symbol << " has a wall across the axes at (" << room.cell.outer[i].x << ", "
              << room.cell.outer[i].y << ")";
        }
      }
      EXPECT_NEAR(rooms_area, storey_area, 1e-6 * storey_area);
      // Clear floors: each cell less the outer walls inside it and half of each inner wall; the
      // corners where walls overlap or stop short stay within 2 m² on the storey.
      double walls_area = 0;
      for (const PlanWall& w : s.walls) walls_area += kernel::length(w.b - w.a) * w.thickness;
      double clear = 0;
      for (const shape::Part& p : built.building.parts) {
        if (p.kind != shape::PartKind::kRoom) continue;
        if (std::get<double>(p.attributes.at("storey")) != s.level) continue;
        clear += std::get<double>(p.attributes.at("area"));
      }
      EXPECT_NEAR(clear, storey_area - walls_area, 2.0);
      // A door is as wide as its transition says, else 0.9 m; an entrance 1.0 m.
      const auto stated = [&](const PlanDoor& d, double otherwise) {
        for (const Transition& t : building->transitions)
          if (!d.symbol.empty() && t.symbol == d.symbol && t.width > 0) return t.width;
        return otherwise;
      };
      for (const PlanDoor& d : s.doors) EXPECT_EQ(d.width, stated(d, 0.9)) << d.symbol;
      for (const PlanDoor& d : s.entrances) EXPECT_EQ(d.width, stated(d, 1.0)) << d.symbol;
    }
  }
}

// A square house with a Gable roof gets a gable, not a hip (issue 12 item 6): the roof solid has
// two slopes, and its ridge runs parallel to the outline's first edge (along x).
TEST(BuilderExamples, SquareGableHouseHasTwoSlopes) {
  const std::optional<Built> built = build_source(base::Source(
      "square.bldg", R"(house -> building("Square", [(0, 0), (9, 0), (9, 9), (0, 9)]) : {body}
body -> buildingpart(Gable, 3) : {ground, e}
ground -> floor(3, horizontal) : {hall, living}
hall -> room(hall, small, 4, 1)
living -> room(living, big, 4, 2)
e -> entrance(hall, 1.2)
)"));
  ASSERT_TRUE(built.has_value());
  const BuildResult& r = built->result;
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  int slopes = 0;
  double ridge_y_min = 1e300, ridge_y_max = -1e300;
  for (const shape::Part& p : r.building.parts) {
    if (p.name.rfind("roof", 0) != 0) continue;
    const kernel::MeshCheck c = kernel::check(p.mesh);
    EXPECT_TRUE(c.closed && c.oriented && c.non_manifold_edges == 0) << p.name;
    for (std::size_t f = 0; f < p.mesh.face_count(); ++f) {
      if (p.mesh.tag(f).semantic == kernel::SemanticClass::kRoofSurface &&
          kernel::face_normal(p.mesh, f).z > 0.1) {
        ++slopes;
      }
    }
    for (const kernel::Vec3& v : p.mesh.positions()) {
      if (std::abs(v.z - p.mesh.bounds().max.z) > 1e-9) continue;
      ridge_y_min = std::min(ridge_y_min, v.y);
      ridge_y_max = std::max(ridge_y_max, v.y);
    }
  }
  EXPECT_EQ(slopes, 2);
  EXPECT_NEAR(ridge_y_min, ridge_y_max, 1e-9);  // a ridge along x
}

}  // namespace
}  // namespace insula::lang::bldg
