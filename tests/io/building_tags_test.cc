// The form of a building from S3DB tags and register attributes: heights with units, levels,
// roof shapes and heights, parts, colours, and where each value came from.
#include "io/building_tags.h"

#include <gtest/gtest.h>

#include <cmath>

namespace insula::io {
namespace {

using shape::AttributeMap;

// A roof that rises 4 m at any pitch over any footprint.
double rise_4(const std::string& /*roof*/, double /*pitch*/) {
  return 4.0;
}

BuildingForm form_of(const AttributeMap& properties, std::vector<TagWarning>& warnings,
                     const BuildingTagOptions& options = {}) {
  return read_building_form(PropertyRow::of(properties), options, rise_4, warnings);
}

BuildingForm form_of(const AttributeMap& properties, const BuildingTagOptions& options = {}) {
  std::vector<TagWarning> warnings;
  return form_of(properties, warnings, options);
}

TEST(ParseLength, MetersFeetAndInches) {
  EXPECT_DOUBLE_EQ(*parse_length("12"), 12.0);
  EXPECT_DOUBLE_EQ(*parse_length(" 12.5 m"), 12.5);
  EXPECT_DOUBLE_EQ(*parse_length("12m"), 12.0);
  EXPECT_DOUBLE_EQ(*parse_length("3,5"), 3.5);
  EXPECT_NEAR(*parse_length("40 ft"), 12.192, 1e-12);
  EXPECT_NEAR(*parse_length("12'6\""), 12 * 0.3048 + 6 * 0.0254, 1e-12);
  EXPECT_NEAR(*parse_length("12' 6\""), 12 * 0.3048 + 6 * 0.0254, 1e-12);
  EXPECT_NEAR(*parse_length("12 ft 6 in"), 12 * 0.3048 + 6 * 0.0254, 1e-12);
  for (const char* bad : {"", "tall", "-5", "12 m 3", "12;15", "12 furlongs", "1.2.3", "m"}) {
    EXPECT_FALSE(parse_length(bad).has_value()) << bad;
  }
}

TEST(IdentifierSpelling, TagNamesAsAttrNames) {
  EXPECT_EQ(base::identifier_spelling("building:levels"), "building_levels");
  EXPECT_TRUE(base::spells_identifier("building:levels", "building_levels"));
  EXPECT_TRUE(base::spells_identifier("roof:colour", "roof_colour"));
  EXPECT_TRUE(base::spells_identifier("height", "height"));
  EXPECT_FALSE(base::spells_identifier("building:levels", "building_level"));
  EXPECT_FALSE(base::spells_identifier("building_levels", "building:levels"));
  EXPECT_FALSE(base::spells_identifier("roof-shape", "roof_shapes"));
}

TEST(ParseDirection, DegreesAndCompassPoints) {
  EXPECT_DOUBLE_EQ(*parse_direction("135"), 135.0);
  EXPECT_DOUBLE_EQ(*parse_direction("N"), 0.0);
  EXPECT_DOUBLE_EQ(*parse_direction("ssw"), 202.5);
  EXPECT_DOUBLE_EQ(*parse_direction("450"), 90.0);
  EXPECT_FALSE(parse_direction("up").has_value());
}

TEST(ParseColour, HexAndCssNames) {
  const std::array<float, 3> white = *parse_colour("white");
  EXPECT_FLOAT_EQ(white[0], 1.0F);
  EXPECT_EQ(*parse_colour("#fff"), white);
  EXPECT_EQ(*parse_colour("#FFFFFF"), white);
  const std::array<float, 3> red = *parse_colour("Red");
  EXPECT_FLOAT_EQ(red[0], 1.0F);
  EXPECT_FLOAT_EQ(red[1], 0.0F);
  // sRGB 0x80 is linear 0.2158.
  EXPECT_NEAR((*parse_colour("grey"))[0], 0.2158F, 1e-4);
  EXPECT_EQ(*parse_colour("light grey"), *parse_colour("lightgrey"));
  EXPECT_FALSE(parse_colour("#12345").has_value());
  EXPECT_FALSE(parse_colour("blurple").has_value());
  EXPECT_TRUE(material_colour("brick").has_value());
  EXPECT_FALSE(material_colour("unobtainium").has_value());
}

TEST(S3dbRoofName, EveryDocumentedShape) {
  const std::vector<std::pair<const char*, const char*>> names = {
      {"flat", "flat"},       {"skillion", "shed"},
      {"gabled", "gable"},    {"half-hipped", "half_hipped"},
      {"hipped", "hip"},      {"pyramidal", "pyramid"},
      {"gambrel", "gambrel"}, {"mansard", "mansard"},
      {"dome", "dome"},       {"onion", "onion"},
      {"round", "round"},     {"saltbox", "saltbox"}};
  for (const auto& [s3db, kernel] : names) EXPECT_EQ(s3db_roof_name(s3db), kernel) << s3db;
  EXPECT_FALSE(s3db_roof_name("zigzag").has_value());
}

// The example: height=12, roof:shape=gabled, roof:height=3 is 12 m high with its eaves at
// 9 m.
TEST(BuildingForm, HeightIsTheTopOfTheRoof) {
  const BuildingForm form = form_of(
      {{"building", "house"}, {"height", "12"}, {"roof:shape", "gabled"}, {"roof:height", "3"}});
  EXPECT_TRUE(form.osm);
  EXPECT_EQ(form.roof, "gable");
  EXPECT_DOUBLE_EQ(form.eave, 9.0);
  EXPECT_DOUBLE_EQ(*form.roof_height, 3.0);
  EXPECT_EQ(form.height_source, ValueSource::kTag);
  EXPECT_EQ(form.roof_source, ValueSource::kTag);
}

TEST(BuildingForm, HeightWithoutRoofHeightTakesThePitchedRise) {
  const BuildingForm form =
      form_of({{"building", "yes"}, {"height", "14 m"}, {"roof:shape", "hipped"}});
  EXPECT_DOUBLE_EQ(form.eave, 10.0);  // 14 - the roof's 4 m rise
  // A roof never takes more than half a building given by its total height.
  const BuildingForm low =
      form_of({{"building", "yes"}, {"height", "6"}, {"roof:shape", "hipped"}});
  EXPECT_DOUBLE_EQ(low.eave, 3.0);
}

TEST(BuildingForm, OsmWithoutRoofShapeIsFlatUnlessTheCommandLineSaysOtherwise) {
  EXPECT_EQ(form_of({{"building", "yes"}, {"height", "9"}}).roof, "flat");
  EXPECT_DOUBLE_EQ(form_of({{"building", "yes"}, {"height", "9"}}).eave, 9.0);
  BuildingTagOptions options;
  options.roof = "gable";
  const BuildingForm form = form_of({{"building", "yes"}, {"height", "9"}}, options);
  EXPECT_EQ(form.roof, "gable");
  EXPECT_EQ(form.roof_source, ValueSource::kOption);
  EXPECT_DOUBLE_EQ(form.eave, 5.0);
}

TEST(BuildingForm, LevelsTimesStoreyHeight) {
  const BuildingForm form = form_of({{"building", "yes"},
                                     {"building:levels", "4"},
                                     {"roof:shape", "gabled"},
                                     {"roof:levels", 1.0}});
  EXPECT_DOUBLE_EQ(form.eave, 12.0);
  EXPECT_DOUBLE_EQ(*form.roof_height, 3.0);
  EXPECT_EQ(form.height_source, ValueSource::kLevels);
  BuildingTagOptions options;
  options.storey_height = 2.5;
  EXPECT_DOUBLE_EQ(form_of({{"building", "yes"}, {"building:levels", 4.0}}, options).eave, 10.0);
}

TEST(BuildingForm, MinHeightAndMinLevelLiftTheBase) {
  const BuildingForm part =
      form_of({{"building:part", "yes"}, {"min_height", "5"}, {"height", "20"}});
  EXPECT_TRUE(part.is_part);
  EXPECT_DOUBLE_EQ(part.base, 5.0);
  EXPECT_DOUBLE_EQ(part.eave, 20.0);
  const BuildingForm levels =
      form_of({{"building:part", "yes"}, {"building:min_level", "2"}, {"building:levels", "5"}});
  EXPECT_DOUBLE_EQ(levels.base, 6.0);
  EXPECT_DOUBLE_EQ(levels.eave, 15.0);
}

TEST(BuildingForm, BuildingRoofHasNoWalls) {
  EXPECT_FALSE(form_of({{"building", "roof"}, {"height", "3"}}).walls);
  EXPECT_TRUE(form_of({{"building", "yes"}, {"height", "3"}}).walls);
}

TEST(BuildingForm, RoofDirectionOrientationAndAngle) {
  const BuildingForm form = form_of({{"building", "yes"},
                                     {"roof:shape", "skillion"},
                                     {"roof:direction", "SE"},
                                     {"roof:orientation", "across"},
                                     {"roof:angle", "20"}});
  EXPECT_EQ(form.roof, "shed");
  EXPECT_DOUBLE_EQ(*form.direction_deg, 135.0);
  EXPECT_EQ(form.orientation, RoofOrientation::kAcross);
  EXPECT_DOUBLE_EQ(form.pitch_deg, 20.0);
}

TEST(BuildingForm, ColoursAndMaterials) {
  const BuildingForm form = form_of(
      {{"building", "yes"}, {"building:colour", "#a0522d"}, {"roof:material", "roof_tiles"}});
  ASSERT_TRUE(form.wall_colour && form.roof_colour);
  EXPECT_EQ(form.wall_colour_name, "#a0522d");
  EXPECT_EQ(form.roof_colour_name, "roof_tiles");
}

TEST(BuildingForm, UnreadableValuesWarnOnceAndFallBack) {
  std::vector<TagWarning> warnings;
  const BuildingForm form = form_of({{"building", "yes"},
                                     {"height", "tall"},
                                     {"roof:shape", "zigzag"},
                                     {"building:colour", "blurple"}},
                                    warnings);
  EXPECT_DOUBLE_EQ(form.eave, 10.0);
  EXPECT_EQ(form.height_source, ValueSource::kDefault);
  EXPECT_EQ(form.roof, "flat");
  ASSERT_EQ(warnings.size(), 3U);
  EXPECT_EQ(warnings[0].code, "MAS003");
  EXPECT_EQ(warnings[0].text, "unknown roof:shape='zigzag'; using flat");
  EXPECT_EQ(warnings[1].code, "MAS002");
  EXPECT_EQ(warnings[1].text, "height='tall' is not a length in (0, 1000) m; using 10 m");
  EXPECT_EQ(warnings[2].code, "MAS006");
}

TEST(BuildingForm, RegisterAttributes) {
  BuildingTagOptions options;
  options.height_attr = "hoehe";
  options.levels_attr = "Floors";
  // A register's height attribute is the wall height; its roof is the --roof default.
  const BuildingForm tall = form_of({{"hoehe", 8.5}}, options);
  EXPECT_FALSE(tall.osm);
  EXPECT_DOUBLE_EQ(tall.eave, 8.5);
  EXPECT_EQ(tall.height_source, ValueSource::kAttribute);
  EXPECT_EQ(tall.roof, "hip");
  const BuildingForm floors = form_of({{"Floors", 3.0}}, options);
  EXPECT_DOUBLE_EQ(floors.eave, 9.0);
  EXPECT_EQ(floors.height_source, ValueSource::kLevels);
  // Zero floors: a warning and the default height.
  std::vector<TagWarning> warnings;
  const BuildingForm zero = form_of({{"Floors", 0.0}}, warnings, options);
  EXPECT_DOUBLE_EQ(zero.eave, 10.0);
  EXPECT_EQ(zero.height_source, ValueSource::kDefault);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_EQ(warnings[0].code, "MAS007");
  EXPECT_EQ(warnings[0].text, "Floors='0' is not a level count above 0; using 10 m");
}

// A register's roof at a pitch nobody gave rises at most as high as its walls (docs/cli.md); a
// pitch from the data or the command line, a roof height or a flat roof is left as it is.
TEST(BuildingForm, DefaultPitchRoofRisesAtMostTheWallHeight) {
  BuildingTagOptions options;
  options.height_attr = "hoehe";
  const BuildingForm walls = form_of({{"hoehe", 8.5}}, options);
  ASSERT_TRUE(walls.roof_height_limit);
  EXPECT_DOUBLE_EQ(*walls.roof_height_limit, 8.5);
  EXPECT_FALSE(form_of({{"hoehe", 8.5}, {"pitch", 40.0}}, options).roof_height_limit);
  BuildingTagOptions pitched = options;
  pitched.pitch_deg = 45;
  pitched.pitch_given = true;
  EXPECT_FALSE(form_of({{"hoehe", 8.5}}, pitched).roof_height_limit);
  BuildingTagOptions flat = options;
  flat.default_roof = "flat";
  EXPECT_FALSE(form_of({{"hoehe", 8.5}}, flat).roof_height_limit);
  // S3DB: a total height already split the building; a roof height given is kept.
  EXPECT_FALSE(
      form_of({{"building", "yes"}, {"height", "12"}, {"roof:shape", "hipped"}}).roof_height_limit);
  EXPECT_FALSE(form_of({{"building", "yes"},
                        {"building:levels", "2"},
                        {"roof:shape", "hipped"},
                        {"roof:height", "3"}})
                   .roof_height_limit);
}

// --height-unit: a register's bare numbers in feet (NYC's heightroof of a 458.5 ft tower);
// texts with a unit and OpenStreetMap's meters keep theirs.
TEST(BuildingForm, HeightUnitScalesARegistersBareNumbers) {
  BuildingTagOptions feet;
  feet.height_attr = "heightroof";
  feet.length_unit = 0.3048;
  EXPECT_NEAR(form_of({{"heightroof", 458.5}}, feet).eave, 139.7508, 1e-9);
  EXPECT_NEAR(form_of({{"heightroof", "458.5"}}, feet).eave, 139.7508, 1e-9);
  EXPECT_NEAR(form_of({{"heightroof", "12 m"}}, feet).eave, 12, 1e-12);
  BuildingTagOptions osm_feet;
  osm_feet.length_unit = 0.3048;
  EXPECT_NEAR(form_of({{"building", "yes"}, {"height", "12"}}, osm_feet).eave, 12, 1e-12);
}

// Microsoft's building footprints write "height": -1 where the height is unknown: no height given
// (MAS001 says it was -1), where any other negative height stays a height that cannot be read.
TEST(BuildingForm, HeightMinusOneIsNoHeight) {
  std::vector<TagWarning> warnings;
  const BuildingForm msft = form_of({{"height", -1.0}, {"confidence", -1.0}}, warnings);
  EXPECT_DOUBLE_EQ(msft.eave, 10.0);
  EXPECT_EQ(msft.height_source, ValueSource::kDefault);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_EQ(warnings[0].code, "MAS001");
  EXPECT_EQ(warnings[0].text, "'height' is -1 (unknown); using 10 m");
  BuildingTagOptions floors;
  floors.levels_attr = "floors";
  EXPECT_DOUBLE_EQ(form_of({{"height", "-1"}, {"floors", 2.0}}, floors).eave, 6.0);
  warnings.clear();
  form_of({{"height", -2.0}}, warnings);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_EQ(warnings[0].code, "MAS002");
  EXPECT_EQ(warnings[0].text, "height='-2' is not a length in (0, 1000) m; using 10 m");
  warnings.clear();
  form_of({{"building", "yes"}, {"height", "-1"}}, warnings);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_EQ(warnings[0].text, "'height' is -1 (unknown) and no building:levels tag; using 10 m");
}

// MAS001 names the properties that look like the register's height column.
TEST(BuildingForm, NoHeightNamesCandidateColumns) {
  const auto mas001 = [](const AttributeMap& properties) {
    std::vector<TagWarning> warnings;
    form_of(properties, warnings);
    return warnings.size() == 1 && warnings[0].code == "MAS001" ? warnings[0].text : "";
  };
  EXPECT_EQ(mas001({{"hauteur", 12.0}, {"nom", "mairie"}}),
            "no 'height' property; this feature has 'hauteur' (use --height-attr hauteur); "
            "using 10 m");
  EXPECT_EQ(mas001({{"HEIGHT", 9.0}, {"h_dak", 11.0}, {"approx_hgt", 3.0}, {"insula:height", 4.0}}),
            "no 'height' property; this feature has 'HEIGHT', 'approx_hgt' and 'h_dak' (name one "
            "with --height-attr); using 10 m");
  EXPECT_EQ(mas001({{"Measured_Height_m", 7.0}, {"H\xC3\xB6he", std::monostate{}}}),
            "no 'height' property; this feature has 'Measured_Height_m' (use --height-attr "
            "Measured_Height_m); using 10 m");
  EXPECT_EQ(mas001({{"name", "barn"}, {"heights", std::monostate{}}}),
            "no 'height' property; using 10 m");
}

TEST(BuildingForm, RoofTallerThanTheBuildingIsCapped) {
  std::vector<TagWarning> warnings;
  const BuildingForm form = form_of(
      {{"building", "yes"}, {"height", "5"}, {"roof:shape", "gabled"}, {"roof:height", "8"}},
      warnings);
  EXPECT_NEAR(form.eave, 0.1, 1e-12);
  EXPECT_NEAR(*form.roof_height, 4.9, 1e-12);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_EQ(warnings[0].code, "MAS008");
}

}  // namespace
}  // namespace insula::io

namespace insula::io {
namespace {

// Overture Maps buildings (docs/osm-buildings.md, "Overture Maps"): recognised by their `names`
// object or `sources` array (nested values arrive as JSON text) or a property only Overture names
// so; their underscore names read as the S3DB tags, `height` the top of the roof.
TEST(BuildingForm, OvertureNamesReadAsS3db) {
  const BuildingForm gable = form_of({{"names", std::string("{\"primary\":\"Dom\"}")},
                                      {"height", 12.0},
                                      {"roof_shape", std::string("gabled")},
                                      {"roof_height", 3.0},
                                      {"facade_color", std::string("#ff0000")},
                                      {"roof_material", std::string("slate")}});
  EXPECT_TRUE(gable.osm);
  EXPECT_EQ(gable.roof, "gable");
  EXPECT_EQ(gable.roof_source, ValueSource::kTag);
  EXPECT_DOUBLE_EQ(gable.eave, 9.0);
  ASSERT_TRUE(gable.wall_colour.has_value());
  EXPECT_FLOAT_EQ((*gable.wall_colour)[0], 1.0F);
  EXPECT_TRUE(gable.roof_colour.has_value());
  // Only a height, as most Overture buildings: the top of a flat roof, not walls under a hip.
  const BuildingForm plain = form_of({{"names", std::string("{}")}, {"height", 8.6}});
  EXPECT_EQ(plain.roof, "flat");
  EXPECT_DOUBLE_EQ(plain.eave, 8.6);
  // Floors from num_floors, the base from min_floor; a building_part names its building.
  const BuildingForm part = form_of({{"sources", std::string("[{\"dataset\":\"OpenStreetMap\"}]")},
                                     {"num_floors", 4.0},
                                     {"min_floor", 1.0},
                                     {"building_id", std::string("08b1")}});
  EXPECT_TRUE(part.is_part);
  EXPECT_DOUBLE_EQ(part.base, 3.0);
  EXPECT_DOUBLE_EQ(part.eave, 12.0);
  EXPECT_EQ(part.height_source, ValueSource::kLevels);
  // A warning names the property the data has.
  std::vector<TagWarning> warnings;
  form_of({{"roof_shape", std::string("zigzag")}}, warnings);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].text.find("roof_shape='zigzag'"), std::string::npos) << warnings[0].text;
  // A register's plain `height` stays the wall height.
  EXPECT_DOUBLE_EQ(form_of({{"height", 8.6}}).eave, 8.6);
  EXPECT_EQ(form_of({{"height", 8.6}}).roof, "hip");
  EXPECT_EQ(*s3db_roof_name("spherical"), "dome");
}

}  // namespace
}  // namespace insula::io
