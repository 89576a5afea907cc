#include "catena/io/case_file.hpp"

#include <gtest/gtest.h>

namespace catena::io {
namespace {

TEST(CaseFile, FlattensValuesInFileOrderWithPathsAndLines) {
  const CaseFile f = parse_case(
      "title = \"demo\"\n"
      "[chain]\n"
      "type = \"rolling-hinge\"\n"
      "pitch = \"125 mm\"\n"
      "[sprocket]\n"
      "teeth = 8\n"
      "poisson = 0.3\n"
      "flat = true\n"
      "[analyses.hinge]\n"
      "[analyses.contact]\n"
      "skew = \"0°42'\"\n",
      "demo.toml");
  ASSERT_EQ(f.values.size(), 7u);
  EXPECT_EQ(f.values[0].path, "title");
  EXPECT_EQ(f.values[2].path, "chain.pitch");
  EXPECT_EQ(f.values[2].text, "125 mm");
  EXPECT_EQ(f.values[2].line, 4);
  EXPECT_EQ(f.values[3].path, "sprocket.teeth");  // file order, not toml++'s sorted order
  EXPECT_EQ(f.values[3].text, "8");
  EXPECT_EQ(f.values[3].type, CaseValue::Type::kNumber);
  EXPECT_EQ(f.values[4].text, "0.3");  // the shortest spelling that reads back exactly
  EXPECT_EQ(f.values[5].type, CaseValue::Type::kBoolean);
  EXPECT_EQ(f.values[6].text, "0°42'");
  EXPECT_EQ(f.children("analyses"), (std::vector<std::string>{"hinge", "contact"}));
  ASSERT_NE(f.find("chain.type"), nullptr);
  EXPECT_EQ(f.find("chain.type")->text, "rolling-hinge");
  EXPECT_EQ(f.find("chain.wire"), nullptr);
}

TEST(CaseFile, SyntaxErrorNamesFileLineAndColumn) {
  try {
    parse_case("[chain]\npitch = \"125 mm\nteeth = 8\n", "bad.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 1u);
    EXPECT_EQ(e.issues()[0].field.rfind("bad.toml:2:", 0), 0u) << e.issues()[0].field;
    EXPECT_NE(e.issues()[0].expected.find("valid TOML"), std::string::npos);
  }
}

TEST(CaseFile, ArraysAreKeptAsOneOtherValue) {
  const CaseFile f = parse_case("[chain]\npitch = [1, 2]\n", "a.toml");
  ASSERT_EQ(f.values.size(), 1u);
  EXPECT_EQ(f.values[0].type, CaseValue::Type::kOther);
}

TEST(CaseFile, ArraysOfTablesAreFlattenedWithIndicesAndLines) {
  const CaseFile f = parse_case(
      "[loop]\n"               // 1
      "speed = \"0.5 m/s\"\n"  // 2
      "[[loop.segment]]\n"     // 3
      "kind = \"takeup\"\n"    // 4
      "[[loop.segment]]\n"     // 5
      "kind = \"straight\"\n"  // 6
      "length = 12\n",         // 7
      "loop.toml");
  ASSERT_EQ(f.values.size(), 4u);
  EXPECT_EQ(f.values[1].path, "loop.segment[0].kind");
  EXPECT_EQ(f.values[1].line, 4);
  EXPECT_EQ(f.values[3].path, "loop.segment[1].length");
  EXPECT_EQ(f.values[3].type, CaseValue::Type::kNumber);
  EXPECT_EQ(f.values[3].line, 7);
  EXPECT_EQ(f.children("loop"), (std::vector<std::string>{"segment", "segment[0]", "segment[1]"}));
  EXPECT_EQ(f.tables.front(), "loop");
}

TEST(CaseFile, DidYouMeanFindsLikelyTyposOnly) {
  const std::vector<std::string> keys = {"plate_radius", "pin_diameter", "pitch", "teeth"};
  EXPECT_EQ(did_you_mean("plate_radus", keys).value(), "plate_radius");
  EXPECT_EQ(did_you_mean("pich", keys).value(), "pitch");
  EXPECT_EQ(did_you_mean("teth", keys).value(), "teeth");
  EXPECT_FALSE(did_you_mean("modulus", keys).has_value());
  EXPECT_FALSE(did_you_mean("x", {}).has_value());
}

}  // namespace
}  // namespace catena::io
