// JsonStream writes the bytes nlohmann::json::dump() prints for the same document (the writers'
// golden files depend on it): numbers, string escapes, empty containers, compact and indented.
#include "io/json_stream.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace insula::io {
namespace {

using nlohmann::json;

// Writes `doc` through JsonStream (keys in the object's own, sorted, order).
void stream(JsonStream& out, const json& doc) {
  switch (doc.type()) {
    case json::value_t::object:
      out.begin_object();
      for (const auto& [name, value] : doc.items()) {
        out.key(name);
        stream(out, value);
      }
      out.end_object();
      return;
    case json::value_t::array:
      out.begin_array();
      for (const json& value : doc) stream(out, value);
      out.end_array();
      return;
    case json::value_t::string:
      out.string(doc.get<std::string>());
      return;
    case json::value_t::boolean:
      out.boolean(doc.get<bool>());
      return;
    case json::value_t::number_integer:
      out.integer(doc.get<std::int64_t>());
      return;
    case json::value_t::number_unsigned:
      out.integer(doc.get<std::uint64_t>());
      return;
    case json::value_t::number_float:
      out.number(doc.get<double>());
      return;
    default:
      out.null();
      return;
  }
}

std::string streamed(const json& doc, int indent) {
  std::string text;
  JsonStream out(text, indent);
  stream(out, doc);
  return text;
}

json sample() {
  return {{"numbers",
           {0.0, -0.0, 3.0, 0.1, 1e-7, 1.5e300, -2.5e-300, 0.001, 455000.25, 5428000.0,
            static_cast<double>(0.3F), 123456789012345.0, 1234567890123456789.0}},
          {"integers", {0, -1, 42, std::numeric_limits<std::int64_t>::min()}},
          {"big", std::numeric_limits<std::uint64_t>::max()},
          {"strings",
           {"", "plain", "quote \" backslash \\ slash /", "\b\f\n\r\t",
            std::string("\x01\x1f\x7f", 3), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8f\xa0"}},
          {"empty", {{"array", json::array()}, {"object", json::object()}}},
          {"flags", {true, false, nullptr}},
          {"Zebra", {{"b", 1}, {"a", {1, {2, 3}}}}}};
}

TEST(JsonStream, CompactTextMatchesNlohmann) {
  const json doc = sample();
  EXPECT_EQ(streamed(doc, -1), doc.dump());
}

TEST(JsonStream, IndentedTextMatchesNlohmann) {
  const json doc = sample();
  EXPECT_EQ(streamed(doc, 1), doc.dump(1));
  EXPECT_EQ(streamed(doc, 4), doc.dump(4));
}

TEST(JsonStream, NonFiniteNumbersAreNull) {
  std::string text;
  JsonStream out(text);
  out.begin_array().number(std::nan("")).number(std::numeric_limits<double>::infinity());
  out.end_array();
  EXPECT_EQ(text, "[null,null]");
}

TEST(JsonStream, IllFormedUtf8BecomesReplacementCharacter) {
  std::string text;
  append_json_escaped(text, "a\xe9z \xc0\xaf \xed\xa0\x80 ok\xc3\xa9");
  EXPECT_EQ(text,
            "a\xef\xbf\xbdz \xef\xbf\xbd\xef\xbf\xbd \xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd "
            "ok\xc3\xa9");
}

TEST(JsonStream, AttributesInsertTheExtraMemberInSortedPlace) {
  std::string text;
  JsonStream out(text);
  const shape::AttributeMap attributes{{"a", 1.0}, {"z", std::string("x")}, {"n", shape::Value{}}};
  out.begin_array()
      .attributes(attributes, "kind", "Room")
      .attributes({{"kind", true}}, "kind", "X");
  out.attributes({}, "kind", "Room").end_array();
  EXPECT_EQ(text, R"([{"a":1,"kind":"Room","n":null,"z":"x"},{"kind":true},{"kind":"Room"}])");
}

TEST(JsonStream, AnAttributesWholeNumberIsAnInteger) {
  std::string text;
  JsonStream out(text);
  out.begin_array();
  for (double v :
       {1810.0, -3.0, 0.0, 2.5, 9007199254740991.0, 9007199254740992.0, 1e300, std::nan("")}) {
    out.value(v);
  }
  out.number(1810.0).end_array();  // geometry numbers keep nlohmann's layout
  EXPECT_EQ(text, "[1810,-3,0,2.5,9007199254740991,9.007199254740992e+15,1e+300,null,1810.0]");
}

}  // namespace
}  // namespace insula::io
