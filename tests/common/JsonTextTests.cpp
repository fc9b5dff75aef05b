// The app's one JSON layout (common/JsonText.h): scene files and rt probe's answers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "common/JsonText.h"

namespace rt {
namespace {

using Json = nlohmann::ordered_json;

TEST(JsonTextTests, jsonNumber) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an integral double becomes an integer
  EXPECT_TRUE(jsonNumber(2.0).is_number_integer());
  EXPECT_EQ(jsonNumber(-2.0).get<std::int64_t>(), -2);
  // TC02: a fraction stays a double
  EXPECT_TRUE(jsonNumber(0.5).is_number_float());
  EXPECT_EQ(jsonNumber(0.5).get<double>(), 0.5);
  // TC03: NaN and the infinities become null
  EXPECT_TRUE(jsonNumber(std::nan("")).is_null());
  EXPECT_TRUE(jsonNumber(-std::numeric_limits<double>::infinity()).is_null());
  // =============== Boundary Values Tests ==================
  // TC11: -0 stays a double with its sign; 0 is the integer 0
  EXPECT_TRUE(jsonNumber(-0.0).is_number_float());
  EXPECT_TRUE(std::signbit(jsonNumber(-0.0).get<double>()));
  EXPECT_TRUE(jsonNumber(0.0).is_number_integer());
  // TC12: integers are exact below 2^53; 2^53 itself stays a double
  EXPECT_TRUE(jsonNumber(9007199254740991.0).is_number_integer());
  EXPECT_TRUE(jsonNumber(9007199254740992.0).is_number_float());
  // TC13: jsonTriple is three of them
  EXPECT_EQ(jsonTriple(Double3(1, 0.5, -2)).dump(), "[1,0.5,-2]");
}

TEST(JsonTextTests, formatJsonLayout) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the document one member per line, short values on one line, a list of objects one
  // object per line, empty containers as [] and {}, a final newline
  const Json doc = {{"ray", {{"origin", {0, 0, 1}}, {"direction", {0, 0, -1}}}},
                    {"hits", Json::array({{{"t", 1}}, {{"t", 2}}})},
                    {"none", Json::array()},
                    {"empty", Json::object()}};
  EXPECT_EQ(formatJson(doc),
            "{\n"
            "  \"ray\": {\"origin\": [0, 0, 1], \"direction\": [0, 0, -1]},\n"
            "  \"hits\": [\n"
            "    {\"t\": 1},\n"
            "    {\"t\": 2}\n"
            "  ],\n"
            "  \"none\": [],\n"
            "  \"empty\": {}\n"
            "}\n");
  // TC02: the document is broken into lines even when it would fit on one
  EXPECT_EQ(formatJson(Json{{"a", 1}}), "{\n  \"a\": 1\n}\n");
  // TC03: a scalar document is one line
  EXPECT_EQ(formatJson(Json(3)), "3\n");
  // TC04: strings and keys escaped as JSON requires
  EXPECT_EQ(formatJson(Json{{"name \"A\"", "tab\there\n"}}),
            "{\n  \"name \\\"A\\\"\": \"tab\\there\\n\"\n}\n");

  // =============== Boundary Values Tests ==================
  // TC11: a value that ends exactly at column 100 stays on one line: 2 spaces, "k": (5
  // characters), then ["x...x"] of 89 + 4 characters
  const std::string fits(89, 'x');
  EXPECT_EQ(formatJson(Json{{"k", {fits}}}), "{\n  \"k\": [\"" + fits + "\"]\n}\n");
  // TC12: one character more breaks it
  const std::string over(90, 'x');
  EXPECT_EQ(formatJson(Json{{"k", {over}}}), "{\n  \"k\": [\n    \"" + over + "\"\n  ]\n}\n");
}

TEST(JsonTextTests, formatJsonNumbers) {
  const auto text = [](const Json& value) { return formatJson(Json::array({value})); };
  // ============ Equivalence Partitions Tests ==============
  // TC01: the shortest form that reads back to the same double
  EXPECT_EQ(text(0.1), "[\n  0.1\n]\n");
  EXPECT_EQ(text(0.1 + 0.2), "[\n  0.30000000000000004\n]\n");
  EXPECT_EQ(text(1e-7), "[\n  1e-07\n]\n");
  // TC02: where nlohmann's own writer (Grisu2) is not the shortest: 1e23 is
  // 9.999999999999999e+22 there
  EXPECT_EQ(text(1e23), "[\n  1e+23\n]\n");
  // TC03: an integral double without a fraction
  EXPECT_EQ(text(2.0), "[\n  2\n]\n");
  // TC04: integers as integers
  EXPECT_EQ(text(-17), "[\n  -17\n]\n");
  // TC05: printf's %g notation: fixed down to 1e-4, exponent below
  EXPECT_EQ(text(0.0005), "[\n  0.0005\n]\n");
  EXPECT_EQ(text(0.00005), "[\n  5e-05\n]\n");
  // TC06: NaN and infinity as null
  EXPECT_EQ(text(std::numeric_limits<double>::infinity()), "[\n  null\n]\n");
  // =============== Boundary Values Tests ==================
  // TC11: -0 as -0.0, which reads back as -0
  EXPECT_EQ(text(-0.0), "[\n  -0.0\n]\n");
  EXPECT_TRUE(std::signbit(Json::parse("-0.0").get<double>()));
  // TC12: the smallest and the largest double
  EXPECT_EQ(text(std::numeric_limits<double>::denorm_min()), "[\n  5e-324\n]\n");
  EXPECT_EQ(text(std::numeric_limits<double>::max()), "[\n  1.7976931348623157e+308\n]\n");
}

}  // namespace
}  // namespace rt
