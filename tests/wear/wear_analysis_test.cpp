// `wear` as an analysis: the comparison of the two hinges (compare_wear_coefficient) in the
// record and its report chart.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "catena/catena.hpp"
#include "catena/io/record.hpp"
#include "catena/io/report.hpp"
#include "catena/wear/wear.hpp"

namespace {

using Inputs = std::vector<std::pair<std::string, std::string>>;

Inputs rolling_bench() {
  return {{"hinge", "rolling"},    {"pitch", "125mm"},           {"teeth", "8"},
          {"strokes", "2"},        {"tension", "3.5kN"},         {"speed", "0.34"},
          {"loop_length", "10m"},  {"wear_coefficient", "1e-4"}, {"contact_length", "24mm"},
          {"friction", "0.15"},    {"pin_diameter", "40mm"},     {"half_thickness", "8mm"},
          {"plate_radius", "15mm"}};
}

const catena::analysis::Chart* only_chart(const catena::analysis::Record& r) {
  EXPECT_EQ(r.charts.size(), 1u);
  return r.charts.empty() ? nullptr : &r.charts.front();
}

// The other hinge is the model's own sliding hinge with the given k (checked against a run of
// it alone), charted beside the rolling one with the retirement limits as horizontal lines.
TEST(WearCompare, BothChainsOnOneChartWithTheLimits) {
  Inputs in = rolling_bench();
  in.emplace_back("compare_wear_coefficient", "2e-4");
  const catena::analysis::Record r = catena::run("wear", in);
  ASSERT_TRUE(r.data.contains("compare"));
  const auto& c = r.data.at("compare");
  EXPECT_EQ(c.at("hinge").as_string(), "sliding");
  EXPECT_EQ(c.at("wear_coefficient").as_number(), 2e-4);

  // the sliding chain alone, with its own k
  const catena::analysis::Record alone = catena::run("wear", {{"hinge", "sliding"},
                                                              {"pitch", "125mm"},
                                                              {"teeth", "8"},
                                                              {"strokes", "2"},
                                                              {"tension", "3.5kN"},
                                                              {"speed", "0.34"},
                                                              {"loop_length", "10m"},
                                                              {"wear_coefficient", "2e-4"},
                                                              {"contact_length", "24mm"},
                                                              {"friction", "0.15"}});
  EXPECT_EQ(c.at("elongation").at("hours").numbers(),
            alone.data.at("elongation").at("hours").numbers());
  EXPECT_EQ(c.at("elongation").at("percent").numbers(),
            alone.data.at("elongation").at("percent").numbers());
  for (const char* key : {"1.5", "2", "3"})
    EXPECT_EQ(c.at("life_hours").at(key).as_number(),
              alone.data.at("life_hours").at(key).as_number())
        << key;
  // the ratio of the new chains' pitch extension per pass, sliding over rolling
  const double sl = alone.data.at("sliding_per_pass").at("roller_depth").as_number() +
                    alone.data.at("sliding_per_pass").at("plate_depth").as_number();
  const double ro = r.data.at("sliding_per_pass").at("roller_depth").as_number() +
                    r.data.at("sliding_per_pass").at("plate_depth").as_number();
  EXPECT_NEAR(c.at("sliding_to_rolling").at("pitch_extension").as_number(), sl / ro,
              1e-12 * sl / ro);

  const auto* chart = only_chart(r);
  ASSERT_NE(chart, nullptr);
  ASSERT_EQ(chart->traces.size(), 5u);
  EXPECT_EQ(chart->traces[0].name, "sliding");
  EXPECT_EQ(chart->traces[1].name, "rolling");
  EXPECT_EQ(chart->traces[0].y, c.at("elongation").at("percent").numbers());
  EXPECT_EQ(chart->traces[1].y, r.data.at("elongation").at("percent").numbers());
  const double longest = std::max(chart->traces[0].x.back(), chart->traces[1].x.back());
  const std::vector<std::pair<std::string, double>> limits = {
      {"limit 1.5 %", 1.5}, {"limit 2 %", 2.0}, {"limit 3 %", 3.0}};
  for (std::size_t i = 0; i < limits.size(); ++i) {
    const auto& t = chart->traces[2 + i];
    EXPECT_EQ(t.name, limits[i].first);
    EXPECT_EQ(t.x, (std::vector<double>{0.0, longest}));
    EXPECT_EQ(t.y, (std::vector<double>{limits[i].second, limits[i].second}));
  }

  // the report section carries both traces and the limits
  catena::io::Report report;
  report.title = "t";
  report.case_name = "c";
  report.case_hash = std::string(64, '0');
  report.version = "0";
  report.sections = {catena::io::report_section(r, "wear", "Wear", "")};
  const std::string html = catena::io::to_html(report, "");
  for (const char* name : {"\"name\":\"sliding\"", "\"name\":\"rolling\"", "\"name\":\"limit 3 %\"",
                           "Elongation of the sliding- and the rolling-hinge chain"})
    EXPECT_NE(html.find(name), std::string::npos) << name;
}

// Without it the record is as before: one chain, one trace; a sliding case compares with the
// rolling hinge, whose geometry it then needs (named, every missing key at once).
TEST(WearCompare, OnlyWhenAskedAndTheOtherHingeNeedsItsGeometry) {
  const catena::analysis::Record r = catena::run("wear", rolling_bench());
  EXPECT_FALSE(r.data.contains("compare"));
  const auto* chart = only_chart(r);
  ASSERT_NE(chart, nullptr);
  ASSERT_EQ(chart->traces.size(), 1u);
  EXPECT_EQ(chart->traces[0].name, "rolling");

  const Inputs sliding = {{"hinge", "sliding"},
                          {"pitch", "125mm"},
                          {"teeth", "8"},
                          {"strokes", "2"},
                          {"tension", "3.5kN"},
                          {"speed", "0.34"},
                          {"loop_length", "10m"},
                          {"wear_coefficient", "1e-4"},
                          {"contact_length", "24mm"},
                          {"friction", "0.15"},
                          {"compare_wear_coefficient", "3"}};
  try {
    catena::run("wear", sliding);
    FAIL() << "expected InputError";
  } catch (const catena::InputError& e) {
    std::string fields;
    for (const auto& i : e.issues()) fields += i.field + ";";
    for (const char* key : {"pin_diameter;", "half_thickness;", "plate_radius;"})
      EXPECT_NE(fields.find(key), std::string::npos) << key << " in " << fields;
  }
  Inputs with = sliding;
  with.back().second = "3";  // k out of (0, 1): named as the compare key
  with.emplace_back("pin_diameter", "40mm");
  with.emplace_back("half_thickness", "8mm");
  with.emplace_back("plate_radius", "15mm");
  try {
    catena::run("wear", with);
    FAIL() << "expected InputError";
  } catch (const catena::InputError& e) {
    ASSERT_FALSE(e.issues().empty());
    EXPECT_EQ(e.issues().front().field, "compare_wear_coefficient");
  }
  with.back() = {"plate_radius", "15mm"};
  with[10].second = "1e-4";
  const catena::analysis::Record both = catena::run("wear", with);
  EXPECT_EQ(both.data.at("compare").at("hinge").as_string(), "rolling");
  const auto* c = only_chart(both);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->traces[0].name, "sliding");
  EXPECT_EQ(c->traces[1].name, "rolling");
}

}  // namespace
