// The .bldg parser and moderator on good grammars: what the model holds, exactly.
#include <gtest/gtest.h>

#include "test_util.h"

namespace insula::lang::bldg {
namespace {

using testing::data_dir;
using testing::for_each_room;
using testing::parse_ok;
using testing::read_file;

TEST(BldgParser, CasaModel) {
  const Building b = parse_ok(read_file(data_dir() / "casa.bldg"), "casa.bldg");
  EXPECT_EQ(b.symbol, "house");
  EXPECT_EQ(b.name, "Casa");
  EXPECT_EQ(b.where.line, 2U);
  EXPECT_EQ(b.where.column, 1U);
  ASSERT_EQ(b.outline.outer.size(), 4U);
  EXPECT_DOUBLE_EQ(kernel::area(b.outline), 108.0);
  ASSERT_EQ(b.layout.children.size(), 2U);
  const PartNode& main = b.layout.children[0];
  ASSERT_TRUE(main.part.has_value());
  EXPECT_EQ(main.part->roof, RoofKind::kHip);
  EXPECT_DOUBLE_EQ(main.part->height, 3.0);
  EXPECT_FALSE(main.part->disposable);
  ASSERT_EQ(main.part->floors.size(), 1U);
  const Floor& ground = main.part->floors[0];
  EXPECT_EQ(ground.symbol, "ground");
  EXPECT_EQ(ground.height, 0.0);
  ASSERT_EQ(ground.layout.children.size(), 2U);
  const Division& back = ground.layout.children[0];
  EXPECT_FALSE(back.room.has_value());
  EXPECT_EQ(back.orientation, Orientation::kHorizontal);
  ASSERT_EQ(back.children.size(), 2U);
  const Room& bedroom = *back.children[1].room;
  EXPECT_EQ(bedroom.type, "bedroom");
  EXPECT_EQ(bedroom.size, SizeLabel::kBig);
  EXPECT_EQ(bedroom.walls, 4);
  EXPECT_EQ(bedroom.windows, 2);
  EXPECT_FALSE(bedroom.entrance);
  EXPECT_TRUE(ground.layout.children[1].room->entrance);
  const PartNode& front = b.layout.children[1];
  EXPECT_TRUE(front.part->disposable);
  EXPECT_EQ(front.part->roof, RoofKind::kFlat);
  ASSERT_EQ(b.transitions.size(), 3U);
  EXPECT_EQ(b.transitions[0].kind, TransitionKind::kEntrance);
  EXPECT_EQ(b.transitions[0].from, "hall");
  EXPECT_EQ(b.transitions[2].kind, TransitionKind::kDoor);
  EXPECT_EQ(b.transitions[2].from, "kitchen");
  EXPECT_EQ(b.transitions[2].to, "bedroom");
  EXPECT_EQ(b.transitions[2].where.line, 14U);
}

TEST(BldgParser, EveryGoodGrammarParses) {
  for (const auto& path : testing::files_in(data_dir(), ".bldg")) {
    SCOPED_TRACE(path.filename().string());
    const base::Source source(path.filename().string(), read_file(path));
    const auto result = parse_building(source);
    std::string all;
    for (const auto& d : result.diagnostics()) all += base::render(d, &source) + "\n";
    EXPECT_TRUE(result.ok()) << all;
    EXPECT_FALSE(base::has_errors(result.diagnostics())) << all;
  }
}

TEST(BldgParser, DomusRoomsAndRoofs) {
  const Building b = parse_ok(read_file(data_dir() / "domus.bldg"));
  int rooms = 0, entrances = 0;
  for_each_room(b.layout, [&](const Division& d) {
    ++rooms;
    entrances += d.room->entrance ? 1 : 0;
  });
  EXPECT_EQ(rooms, 13);
  EXPECT_EQ(entrances, 1);
  EXPECT_EQ(b.transitions.size(), 11U);
  const PartNode& atrium_part = b.layout.children[0].children[1];
  EXPECT_EQ(atrium_part.part->roof, RoofKind::kHoledMansard);
  EXPECT_DOUBLE_EQ(atrium_part.part->floors[0].height, 4.0);
  EXPECT_EQ(b.layout.children[0].orientation, Orientation::kHorizontal);
  EXPECT_EQ(b.layout.children[1].part->floors[0].layout.orientation, Orientation::kVertical);
}

TEST(BldgParser, TwoStoreysWithStair) {
  const Building b = parse_ok(read_file(data_dir() / "two_storey.bldg"));
  const BuildingPart& body = *b.layout.children[0].part;
  ASSERT_EQ(body.floors.size(), 2U);
  EXPECT_DOUBLE_EQ(body.floors[1].height, 2.8);
  EXPECT_EQ(body.floors[1].layout.orientation, Orientation::kHorizontal);
  // Transitions listed in the part's set are collected in order.
  ASSERT_EQ(b.transitions.size(), 7U);
  EXPECT_EQ(b.transitions[0].kind, TransitionKind::kEntrance);
  EXPECT_DOUBLE_EQ(b.transitions[0].width, 1.2);
  EXPECT_EQ(b.transitions[3].kind, TransitionKind::kStair);
  EXPECT_EQ(b.transitions[3].from, "hall");
  EXPECT_EQ(b.transitions[3].to, "landing");
}

TEST(BldgParser, ConcaveOutlineWithHoleIsNormalised) {
  const Building b = parse_ok(read_file(data_dir() / "courtyard.bldg"));
  ASSERT_EQ(b.outline.holes.size(), 1U);
  EXPECT_GT(kernel::signed_area(b.outline.outer), 0);
  EXPECT_LT(kernel::signed_area(b.outline.holes[0]), 0);  // written CCW, stored clockwise
  EXPECT_DOUBLE_EQ(kernel::area(b.outline), 30 * 20 + 12 * 4 - 60);
  bool dining = false;
  for_each_room(b.layout, [&](const Division& d) { dining |= d.room->type == "dining room"; });
  EXPECT_TRUE(dining);
}

TEST(BldgParser, GeoJsonOutlineIsLeftToTheCaller) {
  const Building b = parse_ok(read_file(data_dir() / "lot.bldg"));
  EXPECT_TRUE(b.outline.outer.empty());
  EXPECT_EQ(b.outline_file, "lots.geojson");
  EXPECT_EQ(b.outline_feature, "lot-7");
  EXPECT_EQ(b.outline_where.line, 2U);
  EXPECT_EQ(b.outline_where.column, 26U);
  EXPECT_EQ(b.layout.orientation, Orientation::kHorizontal);
}

TEST(BldgParser, CaseInsensitiveKeywordsAndDivisionSynonym) {
  const Building b = parse_ok(
      "b -> BUILDING(x, [(0,0),(4,0),(4,4),(0,4)]) : {p}\n"
      "p -> BuildingPart(hipglued, 2) : {f}\n"
      "f -> Floor(Vertical) : {r}\n"
      "r -> Division(store, BIG, 0, 0, TRUE);\n");
  EXPECT_EQ(b.name, "x");
  EXPECT_EQ(b.layout.children[0].part->roof, RoofKind::kHipGlued);
  EXPECT_EQ(b.layout.children[0].part->floors[0].layout.orientation, Orientation::kVertical);
  const Room& r = *b.layout.children[0].part->floors[0].layout.children[0].room;
  EXPECT_EQ(r.size, SizeLabel::kBig);
  EXPECT_TRUE(r.entrance);
}

TEST(BldgParser, ByteOrderMarkAndCrlfAreAccepted) {
  const Building b = parse_ok(
      "\xEF\xBB\xBF"
      "b -> building(x, [(0,0),(4,0),(4,4),(0,4)]) : {p}\r\n"
      "p -> buildingpart(Flat, 2) : {f}\r\n\tf -> floor() : {r}\r\nr -> room(a, small)\r\n");
  EXPECT_EQ(b.where.column, 4U);  // columns count bytes, the mark included
  EXPECT_EQ(b.layout.children[0].part->floors[0].where.line, 3U);
  EXPECT_EQ(b.layout.children[0].part->floors[0].where.column, 2U);
}

TEST(BldgParser, DoorIntoDisposablePartIsAWarning) {
  const base::Source source("w.bldg",
                            "b -> building(x, [(0,0),(8,0),(8,4),(0,4)]) : {p, q, d}\n"
                            "p -> buildingpart(Flat, 2) : {f}\n"
                            "f -> floor() : {r}\n"
                            "r -> room(hall, big, 0, 0, true)\n"
                            "q -> buildingpart(Flat, 0) : {g}\n"
                            "g -> floor() : {s}\n"
                            "s -> room(void, small)\n"
                            "d -> door(r, s)\n");
  const auto result = parse_building(source);
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result.diagnostics().size(), 1U);
  EXPECT_EQ(base::render(result.diagnostics()[0]),
            "w.bldg:8:1: warning[BLD240]: door 'd' leads into a disposable building part "
            "(height 0) and is ignored");
  EXPECT_EQ(result->transitions.size(), 1U);  // kept, so printing preserves the grammar
}

TEST(BldgParser, ReportsEveryErrorSorted) {
  const std::string all = testing::errors(
      "b -> building(x, [(0,0),(8,0),(8,4),(0,4)]) : {p, ghost}\n"
      "p -> buildingpart(Dome, 2) : {f}\n"
      "f -> floor() : {r, r2}\n"
      "r -> room(hall, huge)\n"
      "r2 -> room(hall, small, 2)\n"
      "lonely -> room(x, small)\n");
  EXPECT_EQ(all,
            "t.bldg:1:51: error[BLD211]: undefined symbol 'ghost'\n"
            "t.bldg:2:19: error[BLD204]: unknown roof kind 'Dome' (Flat, Pyramid, Hip, Mansard, "
            "HoledMansard, None, Gable, HipGlued)\n"
            "t.bldg:4:17: error[BLD204]: unknown size label 'huge' (small, medium or big)\n"
            "t.bldg:5:25: error[BLD205]: number of walls 2 is out of range [3, 32] (or 0 for "
            "the default)\n"
            "t.bldg:6:1: error[BLD212]: unused symbol 'lonely' (no successor set refers to it)\n");
}

TEST(BldgParser, DeepGrammarIsRejectedNotOverflowed) {
  std::string text =
      "b -> building(x, [(0,0),(8,0),(8,4),(0,4)]) : {p}\n"
      "p -> buildingpart(Flat, 2) : {f}\nf -> floor() : {d0}\n";
  const int depth = 5000;
  for (int i = 0; i < depth; ++i) {
    text +=
        testing::numbered("d", i) + " -> divisions() : {" + testing::numbered("d", i + 1) + "}\n";
  }
  text += testing::numbered("d", depth) + " -> room(x, small)\n";
  const std::string first = testing::first_error(text);
  EXPECT_NE(first.find("error[BLD216]: the tree is deeper than 256 levels"), std::string::npos)
      << first;
}

TEST(BldgParser, WideGrammarParses) {
  std::string text =
      "b -> building(x, [(0,0),(80,0),(80,40),(0,40)]) : {p}\n"
      "p -> buildingpart(Flat, 2) : {f}\nf -> floor() : {";
  const int rooms = 2000;
  for (int i = 0; i < rooms; ++i) text += (i ? ", r" : "r") + std::to_string(i);
  text += "}\n";
  for (int i = 0; i < rooms; ++i) text += testing::numbered("r", i) + " -> room(x, small)\n";
  const Building b = parse_ok(text);
  EXPECT_EQ(b.layout.children[0].part->floors[0].layout.children.size(),
            static_cast<std::size_t>(rooms));
}

}  // namespace
}  // namespace insula::lang::bldg
