// The compact property table of footprints: every kind of value comes back as it went in, a key set
// twice keeps its later value, rows stay apart, and a row becomes the map a building carries.
#include "io/property_table.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace insula::io {
namespace {

using shape::AttributeMap;
using shape::Value;

TEST(PropertyTable, ValuesComeBackAsTheyWentIn) {
  PropertyTable table;
  const std::size_t row = table.add_row();
  table.set(row, "height", 12.5);
  table.set(row, "listed", true);
  table.set(row, "note", std::monostate{});
  table.set_text(row, "name", std::string("Hall\0with a zero byte", 21));
  table.set(row, "use", Value(std::string("office")));
  EXPECT_EQ(table.size(row), 5u);
  EXPECT_EQ(table.find(row, "height"), Value(12.5));
  EXPECT_EQ(table.find(row, "listed"), Value(true));
  EXPECT_EQ(table.find(row, "note"), Value(std::monostate{}));
  EXPECT_EQ(table.find(row, "name"), Value(std::string("Hall\0with a zero byte", 21)));
  EXPECT_EQ(table.find(row, "use"), Value(std::string("office")));
  EXPECT_FALSE(table.find(row, "roof").has_value());
}

TEST(PropertyTable, ALaterValueOfAKeyWins) {
  PropertyTable table;
  const std::size_t row = table.add_row();
  table.set_text(row, "roof", "gable");
  table.set(row, "roof", 3.0);
  table.set_text(row, "height", "12");
  table.set_text(row, "height", "15 m");
  EXPECT_EQ(table.size(row), 2u);
  EXPECT_EQ(table.map(row), (AttributeMap{{"height", std::string("15 m")}, {"roof", 3.0}}));
}

TEST(PropertyTable, RowsShareKeysButNotValues) {
  PropertyTable table;
  const std::size_t first = table.add_row();
  table.set_text(first, "use", "office");
  table.set(first, "height", 9.0);
  const std::size_t empty = table.add_row();
  const std::size_t third = table.add_row();
  table.set(third, "height", 20.0);
  EXPECT_EQ(table.rows(), 3u);
  EXPECT_EQ(table.map(first), (AttributeMap{{"height", 9.0}, {"use", std::string("office")}}));
  EXPECT_TRUE(table.map(empty).empty());
  EXPECT_EQ(table.map(third), (AttributeMap{{"height", 20.0}}));
  EXPECT_FALSE(table.find(third, "use").has_value());
  // Rows are written in order: an earlier row is closed.
  EXPECT_THROW(table.set(first, "use", 1.0), std::logic_error);
}

TEST(PropertyRow, OfAMapAndEmpty) {
  const AttributeMap map{{"a", 1.0}, {"b", std::string("x")}, {"c", false}};
  const PropertyRow row = PropertyRow::of(map);
  EXPECT_EQ(row.size(), 3u);
  EXPECT_EQ(row.map(), map);
  EXPECT_EQ(row.find("b"), Value(std::string("x")));
  const PropertyRow none;
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(none.map().empty());
  EXPECT_FALSE(none.find("a").has_value());
}

}  // namespace
}  // namespace insula::io
