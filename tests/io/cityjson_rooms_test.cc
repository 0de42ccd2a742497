// CityJSON for traversable buildings (seed 000 outputs): storeys as BuildingStorey, rooms as
// BuildingRoom with interior semantic surfaces (FloorSurface, CeilingSurface,
// InteriorWallSurface), door and window faces as Door and Window surfaces, and a closed room slab
// written as a Solid.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/cityjson_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using kernel::SemanticClass;

// The prism helper tags bottom/sides/top as ground/wall/roof; retag them as a room's slab.
kernel::Mesh slab(double x0, double x1, double z0, double z1, SemanticClass top,
                  SemanticClass bottom) {
  kernel::Mesh m = testing::prism({{x0, 0}, {x1, 0}, {x1, 4}, {x0, 4}}, z0, z1);
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    kernel::FaceTag& tag = m.tag(f);
    tag.semantic = tag.semantic == SemanticClass::kRoofSurface ? top
                   : tag.semantic == SemanticClass::kGroundSurface
                       ? bottom
                       : SemanticClass::kInteriorWallSurface;
  }
  return m;
}

shape::Scene rooms_scene() {
  shape::Scene scene;
  shape::Building b;
  b.id = "house";
  kernel::Mesh walls = testing::prism({{0, 0}, {8, 0}, {8, 0.3}, {0, 0.3}}, 0, 3);
  kernel::Mesh frame = slab(2, 3, 0, 2.1, SemanticClass::kDoor, SemanticClass::kDoor);
  for (std::size_t f = 0; f < frame.face_count(); ++f) frame.tag(f).semantic = SemanticClass::kDoor;
  walls.append(frame);
  kernel::Mesh pane = slab(5, 6, 1, 2, SemanticClass::kWindow, SemanticClass::kWindow);
  for (std::size_t f = 0; f < pane.face_count(); ++f) pane.tag(f).semantic = SemanticClass::kWindow;
  walls.append(pane);
  b.parts.push_back({"storey 0", shape::PartKind::kStorey, {{"storey", 0.0}}, walls});
  b.parts.push_back(
      {"kitchen",
       shape::PartKind::kRoom,
       {{"type", std::string("kitchen")}, {"area", 16.0}, {"storey", 0.0}},
       slab(0, 4, 0, 0.1, SemanticClass::kFloorSurface, SemanticClass::kClosureSurface)});
  kernel::Mesh hall =
      slab(4, 8, 0, 0.1, SemanticClass::kFloorSurface, SemanticClass::kClosureSurface);
  hall.append(slab(4, 8, 2.9, 3, SemanticClass::kClosureSurface, SemanticClass::kCeilingSurface));
  b.parts.push_back({"hall", shape::PartKind::kRoom, {{"type", std::string("hall")}}, hall});
  scene.buildings.push_back(std::move(b));
  return scene;
}

TEST(CityJsonRooms, StoreysAndRoomsAreTheirCityObjectTypes) {
  const nlohmann::json doc = nlohmann::json::parse(cityjson_text(rooms_scene()));
  const auto& objects = doc["CityObjects"];
  EXPECT_EQ(objects["house"]["type"], "Building");
  EXPECT_EQ(objects["house"]["children"].size(), 3U);
  EXPECT_EQ(objects["house-storey 0"]["type"], "BuildingStorey");
  EXPECT_EQ(objects["house-kitchen"]["type"], "BuildingRoom");
  EXPECT_EQ(objects["house-kitchen"]["parents"][0], "house");
  EXPECT_EQ(objects["house-kitchen"]["attributes"]["type"], "kitchen");
  EXPECT_EQ(objects["house-kitchen"]["attributes"]["area"], 16.0);
}

std::vector<std::string> surface_types(const nlohmann::json& object) {
  std::vector<std::string> out;
  for (const auto& s : object["geometry"][0]["semantics"]["surfaces"]) out.push_back(s["type"]);
  std::sort(out.begin(), out.end());
  return out;
}

TEST(CityJsonRooms, RoomsCarryInteriorSurfaces) {
  const nlohmann::json doc = nlohmann::json::parse(cityjson_text(rooms_scene()));
  const auto& kitchen = doc["CityObjects"]["house-kitchen"];
  // One closed slab: a Solid whose surfaces are the floor, its closure and the slab's edges.
  EXPECT_EQ(kitchen["geometry"][0]["type"], "Solid");
  EXPECT_EQ(surface_types(kitchen),
            (std::vector<std::string>{"ClosureSurface", "FloorSurface", "InteriorWallSurface"}));
  // Two slabs (floor and ceiling) are two shells: a MultiSurface with the ceiling too.
  const auto& hall = doc["CityObjects"]["house-hall"];
  EXPECT_EQ(hall["geometry"][0]["type"], "MultiSurface");
  EXPECT_EQ(surface_types(hall), (std::vector<std::string>{"CeilingSurface", "ClosureSurface",
                                                           "FloorSurface", "InteriorWallSurface"}));
}

TEST(CityJsonRooms, DoorAndWindowFacesAreOpeningSurfaces) {
  const nlohmann::json doc = nlohmann::json::parse(cityjson_text(rooms_scene()));
  const auto& storey = doc["CityObjects"]["house-storey 0"];
  const std::vector<std::string> types = surface_types(storey);
  EXPECT_NE(std::find(types.begin(), types.end(), "Door"), types.end());
  EXPECT_NE(std::find(types.begin(), types.end(), "Window"), types.end());
  // 6 faces of the wall, 6 of the door frame, 6 of the pane: each face has a value.
  std::size_t doors = 0;
  std::size_t windows = 0;
  const auto& surfaces = storey["geometry"][0]["semantics"]["surfaces"];
  for (const auto& v : storey["geometry"][0]["semantics"]["values"]) {
    if (v.is_null()) continue;
    const std::string type = surfaces[v.get<std::size_t>()]["type"];
    doors += type == "Door";
    windows += type == "Window";
  }
  EXPECT_EQ(doors, 6U);
  EXPECT_EQ(windows, 6U);
}

}  // namespace
}  // namespace insula::io
