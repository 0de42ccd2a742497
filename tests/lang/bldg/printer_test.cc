// The grammar printer on models that did not come from a parser: generated names for empty,
// invalid or repeated symbols (transitions follow a renamed room), exact numbers, strings with
// escapes, holes, GeoJSON outlines, disposable parts.
#include <gtest/gtest.h>

#include "lang/bldg/printer.h"
#include "test_util.h"

namespace insula::lang::bldg {
namespace {

Division room(const std::string& symbol, const std::string& type, SizeLabel size) {
  Division d;
  d.symbol = symbol;
  Room r;
  r.type = type;
  r.size = size;
  d.room = r;
  return d;
}

Building small_building() {
  Building b;
  b.name = "Näme\twith \"quotes\"";
  b.outline.outer = {{-1.5, 0}, {10, 0}, {10, 0.0125}, {10, 8.25}, {-1.5, 8.25}};
  b.outline.holes = {{{2, 2}, {2, 3}, {3, 3}, {3, 2}}};
  PartNode part;
  part.symbol = "main";
  BuildingPart bp;
  bp.roof = RoofKind::kHoledMansard;
  bp.height = 2.75;
  Floor floor;
  floor.symbol = "";
  floor.layout.orientation = Orientation::kHorizontal;
  floor.layout.children.push_back(room("a", "hall", SizeLabel::kSmall));
  floor.layout.children.push_back(room("a", "kitchen", SizeLabel::kMedium));  // repeated
  floor.layout.children.push_back(room("not an id", "bath", SizeLabel::kBig));
  floor.layout.children.back().room->entrance = true;
  bp.floors.push_back(floor);
  part.part = bp;
  b.layout.children.push_back(part);
  PartNode notch;
  notch.symbol = "notch";
  BuildingPart np;
  np.disposable = true;
  np.height = 4;  // disposable wins: printed as height 0
  Floor nf;
  nf.symbol = "nf";
  nf.layout.children.push_back(room("v", "void", SizeLabel::kMedium));
  np.floors.push_back(nf);
  notch.part = np;
  b.layout.children.push_back(notch);
  Transition door;
  door.kind = TransitionKind::kDoor;
  door.from = "a";
  door.to = "not an id";
  door.width = 1.05;
  b.transitions.push_back(door);
  return b;
}

TEST(BldgPrinter, FreshNamesExactNumbersEscapes) {
  const std::string text = print_building(small_building());
  EXPECT_EQ(text,
            "# \"Näme\\twith \\\"quotes\\\"\": ontology-based building grammar (seed 000; "
            "docs/bldg-language.md)\n"
            "building0 -> building(\"Näme\\twith \\\"quotes\\\"\", [(-1.5, 0), (10, 0), (10, "
            "0.0125), (10, 8.25), (-1.5, 8.25)], [(2, 2), (2, 3), (3, 3), (3, 2)]) : {main, "
            "notch, door0}\n"
            "main -> buildingpart(HoledMansard, 2.75) : {floor0}\n"
            "floor0 -> floor(horizontal) : {a, room0, room1}\n"
            "a -> room(hall, small)\n"
            "room0 -> room(kitchen, medium)\n"
            "room1 -> room(bath, big, 0, 0, true)\n"
            "notch -> buildingpart(Flat, 0) : {nf}\n"
            "nf -> floor() : {v}\n"
            "v -> room(void, medium)\n"
            "door0 -> door(a, room1, 1.05)\n");
}

TEST(BldgPrinter, PrintedModelParsesAndIsCanonical) {
  const std::string text = print_building(small_building());
  const Building parsed = testing::parse_ok(text);
  EXPECT_EQ(parsed.name, "Näme\twith \"quotes\"");
  EXPECT_DOUBLE_EQ(parsed.outline.outer[2].y, 0.0125);
  EXPECT_TRUE(parsed.layout.children[1].part->disposable);
  EXPECT_EQ(parsed.transitions[0].to, "room1");
  EXPECT_EQ(print_building(parsed), text);
}

TEST(BldgPrinter, GeoJsonOutlineAndOrientation) {
  Building b = small_building();
  b.outline = {};
  b.outline_file = "dir/lots.geojson";
  b.outline_feature.push_back('7');  // not = "7": GCC 12 -O3 false -Wrestrict
  b.layout.orientation = Orientation::kVertical;
  const std::string text = print_building(b);
  EXPECT_NE(text.find("building(\"Näme\\twith \\\"quotes\\\"\", geojson(\"dir/lots.geojson\", "
                      "\"7\"), vertical) : {"),
            std::string::npos)
      << text;
  const Building parsed = testing::parse_ok(text);
  EXPECT_EQ(parsed.outline_feature, "7");
  EXPECT_EQ(parsed.layout.orientation, Orientation::kVertical);
}

TEST(BldgPrinter, Names) {
  EXPECT_STREQ(roof_name(RoofKind::kHipGlued), "HipGlued");
  EXPECT_STREQ(orientation_name(Orientation::kVertical), "vertical");
  EXPECT_STREQ(size_name(SizeLabel::kBig), "big");
  EXPECT_STREQ(transition_name(TransitionKind::kStair), "stair");
}

}  // namespace
}  // namespace insula::lang::bldg
