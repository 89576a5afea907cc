// `catena sprocket` as scripts call it: the JSON contract, the drawing files, the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

constexpr double kPrintedTol = 0.5e-6;  // [m] a value printed to 0.001 mm

TEST(SprocketCli, JsonCarriesTheContractFields) {
  const CliRun r = run("sprocket --chain 12B --teeth 17 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"pitch_diameter", "root_diameter", "seat_diameter", "tip_diameter",
                          "seating_radius", "seating_angle", "flank_radius", "tooth_width",
                          "side_radius", "measurement_over_pins", "units", "diagnostics"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key :
       {"seat_diameter", "tip_diameter", "seating_radius", "seating_angle", "flank_radius"}) {
    EXPECT_TRUE(j[key].contains("min")) << key;
    EXPECT_TRUE(j[key].contains("max")) << key;
  }
  EXPECT_NEAR(j["pitch_diameter"].get<double>(), 103.674e-3, kPrintedTol);
  EXPECT_NEAR(j["root_diameter"].get<double>(), 91.604e-3, kPrintedTol);
  EXPECT_NEAR(j["tip_diameter"]["max"].get<double>(), 115.416e-3, kPrintedTol);
  EXPECT_NEAR(j["forms"]["max_gap"]["outline_tip_diameter"].get<double>(), 110.2e-3, 0.05e-3);
  EXPECT_EQ(j["units"]["pitch_diameter"], "m");
  EXPECT_EQ(j["units"]["seating_angle"], "rad");
  bool meets = false;
  for (const auto& d : j["diagnostics"])
    meets = meets || d["code"] == "sprocket.flanks_meet_below_tip";
  EXPECT_TRUE(meets);
}

TEST(SprocketCli, PitchRollerAndWidthGivenEqualTheCatalogueChain) {
  const CliRun a = run("sprocket --chain 12B --teeth 23 --format json");
  const CliRun b =
      run("sprocket --pitch 19.05mm --roller-diameter 12.07mm --inner-width 11.68mm --teeth 23 "
          "--format json");
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  // the chain's name, and pt, which --chain fills from the catalogue and a single strand does
  // not use, are the only differences
  EXPECT_DOUBLE_EQ(ja["transverse_pitch"].get<double>(), 19.46e-3);
  EXPECT_TRUE(jb["transverse_pitch"].is_null());
  for (const char* key : {"chain", "transverse_pitch"}) {
    ja.erase(key);
    jb.erase(key);
  }
  EXPECT_EQ(ja, jb);
}

TEST(SprocketCli, TableAndCsv) {
  const CliRun t = run("sprocket --chain 12B --teeth 17");
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("pitch diameter d [mm]"), std::string::npos);
  EXPECT_NE(t.out.find("103.674"), std::string::npos);
  const CliRun c = run("sprocket --chain 12B --teeth 17 --format csv");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.out.rfind("teeth,pitch_diameter,root_diameter", 0), 0u) << c.out;
}

TEST(SprocketCli, WritesTheDrawingAsSvgAndDxf) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("catena_sprocket_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const CliRun r = run("sprocket --chain 12B --teeth 17 --svg " + (dir / "s.svg").string() +
                       " --dxf " + (dir / "s.dxf").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = read_text(dir / "s.svg");
  const std::string dxf = read_text(dir / "s.dxf");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  for (const char* layer : {"OUTLINE_MIN_GAP", "OUTLINE_MAX_GAP", "PITCH_CIRCLE", "ROOT_CIRCLE"})
    EXPECT_NE(dxf.find(layer), std::string::npos) << layer;
  std::filesystem::remove_all(dir);
}

TEST(SprocketCli, RefusalsNameTheFlagAndTheRange) {
  const CliRun unknown = run("sprocket --chain 99X --teeth 17");
  EXPECT_NE(unknown.status, 0);
  EXPECT_NE(unknown.err.find("--chain"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("12B"), std::string::npos) << unknown.err;
  const CliRun few = run("sprocket --chain 12B --teeth 4");
  EXPECT_NE(few.status, 0);
  EXPECT_NE(few.err.find("--teeth"), std::string::npos) << few.err;
  EXPECT_NE(few.err.find("6 to 500"), std::string::npos) << few.err;
  const CliRun missing = run("sprocket --chain 12B");
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("--teeth"), std::string::npos) << missing.err;
}

TEST(SprocketCli, ExampleCaseEqualsTheCommandLine) {
  const CliRun c = run(std::string("run ") + CATENA_EXAMPLES_DIR + "/sprocket_12B.toml");
  ASSERT_EQ(c.status, 0) << c.err;
  const CliRun d = run("sprocket --chain 12B --teeth 17 --format json");
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_EQ(nlohmann::json::parse(c.out)["analyses"]["sprocket"], nlohmann::json::parse(d.out));
}

// The report: the sprocket's section with its drawing, and the {min, max} members of a length
// or an angle in display units (they have no unit of their own: their parent's is used).
TEST(SprocketCli, ReportShowsMinMaxInDisplayUnitsAndTheDrawing) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("catena_sprocket_report_" + std::to_string(::getpid()) + ".html");
  const CliRun r =
      run(std::string("report ") + CATENA_EXAMPLES_DIR + "/sprocket_12B.toml -o " + path.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string html = read_text(path);
  std::filesystem::remove(path);
  EXPECT_NE(html.find("<td>seat_diameter.min</td><td class=\"value\">91.1665</td><td>mm</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>seating_angle.max</td><td class=\"value\">134.706</td><td>°</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
}

}  // namespace
