// `catena loop FILE` as scripts call it: the TOML schema, json/csv/table, SI JSON with units and
// diagnostics, every input problem named by path and line with exit status 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
constexpr double kHandTol = 1e-9;     // [N] hand sums of tensions of order 1e3 (round-off only)
constexpr double kPowerTol = 1e-9;    // [W] the hand-derived power, ~9e2 W (round-off only)
constexpr double kLengthTol = 1e-12;  // [m] path positions of ~1e1 m read from the file
constexpr double kSpeedTol = 1e-12;   // [m/s] the chain speed read from the file

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "catena_loop_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// The hand-derived loop of tests/strength/loop_test.cpp (HorizontalLoopByHand), with units:
// S_slack = 1 kN; +200 N (return), ×1.05, +1000 N (carrying), ×1.02 → S_tight = 2305.2 N;
// F = 1305.2 + 0.03·3305.2 = 1404.356 N; P = F·0.5/0.8 = 877.7225 W.
const std::string kHorizontal = R"(
[loop]
speed = "30 m/min"
efficiency = 0.8
[[loop.segment]]
kind = "takeup"
pretension = "1 kN"
[[loop.segment]]
kind = "straight"
name = "return"
length = 20
chain_weight = "0.1 kN/m"
resistance = 0.1
[[loop.segment]]
kind = "turn"
name = "tail, sprocket"
factor = 1.05
[[loop.segment]]
kind = "straight"
name = "carrying"
length = "20"
chain_weight = 100
load_weight = "400 N/m"
resistance = 0.1
[[loop.segment]]
kind = "turn"
factor = 1.02
[[loop.segment]]
kind = "drive"
loss = 0.03
)";

TEST(LoopCli, JsonCarriesTheContractFieldsInSi) {
  const CliRun r = run("loop " + write("h.toml", kHorizontal) + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& points = j["points"];
  ASSERT_EQ(points.size(), 12u);  // start and end of 6 segments
  for (const auto& p : points)
    for (const char* k : {"segment", "name", "kind", "s", "tension"})
      EXPECT_TRUE(p.contains(k)) << k;
  EXPECT_EQ(points[2]["name"], "return");
  EXPECT_EQ(points[3]["kind"], "straight");
  EXPECT_NEAR(points[3]["s"].get<double>(), 20.0, kLengthTol);  // bare length: metres
  EXPECT_NEAR(points[7]["s"].get<double>(), 40.0, kLengthTol);  // "20" (a string) too
  EXPECT_NEAR(points[3]["tension"].get<double>(), 1200.0, kHandTol);
  EXPECT_NEAR(points[9]["tension"].get<double>(), 2305.2, kHandTol);
  EXPECT_NEAR(j["max_tension"].get<double>(), 2305.2, kHandTol);
  EXPECT_EQ(j["max_tension_at"]["segment"], 4);
  EXPECT_NEAR(j["min_tension"].get<double>(), 1000.0, kHandTol);
  EXPECT_NEAR(j["drive_force"].get<double>(), 1404.356, kHandTol);
  EXPECT_NEAR(j["power"].get<double>(), 877.7225, kPowerTol);
  EXPECT_NEAR(j["speed"].get<double>(), 0.5, kSpeedTol);
  EXPECT_TRUE(j["diagnostics"].is_array());
  EXPECT_EQ(j["units"]["tension"], "N");
  EXPECT_EQ(j["units"]["s"], "m");
  EXPECT_EQ(j["units"]["power"], "W");
}

TEST(LoopCli, CsvIsThePointsTableAndTableIsReadable) {
  const std::string file = write("h.toml", kHorizontal);
  const CliRun csv = run("loop " + file + " --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("segment,name,kind,at,s,tension\n", 0), 0u);
  EXPECT_EQ(std::count(csv.out.begin(), csv.out.end(), '\n'), 13);
  EXPECT_NE(csv.out.find("2,\"tail, sprocket\",turn,end,20,1260\n"), std::string::npos) << csv.out;
  const CliRun table = run("loop " + file);
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("drive force"), std::string::npos);
  EXPECT_NE(table.out.find("S out [kN]"), std::string::npos);
  // -o writes the file and nothing to stdout
  const std::string out = (fs::temp_directory_path() / "catena_loop_cli_test" / "o.csv").string();
  const CliRun o = run("loop " + file + " --format csv -o " + out);
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(o.out.empty());
  const std::string written = read_text(out);
  EXPECT_EQ(written, csv.out);
}

TEST(LoopCli, DiagnosticsCarryTheirLimits) {
  std::string text = kHorizontal;
  text.replace(text.find("efficiency = 0.8"), 16,
               "efficiency = 0.8\nmin_tension = \"1.1 kN\"\nallowable_tension = \"2 kN\"");
  const CliRun r = run("loop " + write("d.toml", text) + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;  // a design finding is not an input error
  const auto j = nlohmann::json::parse(r.out);
  std::map<std::string, nlohmann::json> by_code;
  for (const auto& d : j["diagnostics"]) by_code[d["code"].get<std::string>()] = d;
  ASSERT_TRUE(by_code.count("loop.below_min_tension")) << r.out;
  EXPECT_EQ(by_code["loop.below_min_tension"]["limit"].get<double>(), 1100.0);
  ASSERT_TRUE(by_code.count("loop.over_allowable_tension")) << r.out;
  EXPECT_EQ(by_code["loop.over_allowable_tension"]["limit"].get<double>(), 2000.0);
  EXPECT_EQ(by_code["loop.over_allowable_tension"]["severity"], "infeasible");
}

TEST(LoopCli, EveryProblemIsListedWithPathAndLineAndExitTwo) {
  const std::string bad = R"([loop]
speed = "0.3 rpm"
efficency = 0.85
[[loop.segment]]
kind = "straight"
length = "-5 m"
chain_weight = "30 kg/m"
resistance = 0.1
factor = 1.05
[[loop.segment]]
kind = "turn"
factor = 0.95
[[loop.segment]]
kind = "drvie"
[[loop.segment]]
kind = "takeup"
)";
  const CliRun r = run("loop " + write("bad.toml", bad) + " --format json");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  for (const char* fragment :
       {"loop.speed (line 2)", "did you mean 'efficiency'", "loop.efficiency = (missing)",
        "loop.segment[0].length (line 6)", "loop.segment[0].chain_weight (line 7)", "kgf/m",
        "loop.segment[0].factor (line 9)", "a key of a straight segment",
        "loop.segment[1].factor (line 12)", "k ≥ 1", "loop.segment[2].kind (line 14)",
        "did you mean 'drive'", "loop.segment[3].pretension (line 16) = (missing)"})
    EXPECT_NE(r.err.find(fragment), std::string::npos) << fragment << "\n" << r.err;
}

TEST(LoopCli, DriveAndTakeUpCountsAndMissingTable) {
  const CliRun none = run("loop " + write("none.toml", "[chain]\ntype = \"x\"\n"));
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("loop = (missing)"), std::string::npos) << none.err;
  const CliRun two = run("loop " + write("two.toml", R"([loop]
speed = 1
efficiency = 1
[[loop.segment]]
kind = "drive"
[[loop.segment]]
kind = "takeup"
pretension = 100
[[loop.segment]]
kind = "drive"
)"));
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find("loop.segment = 2 drives"), std::string::npos) << two.err;
  EXPECT_NE(two.err.find("loop.segment[0].kind (line 5)"), std::string::npos) << two.err;
  const CliRun single = run("loop " + write("single.toml", R"([loop]
speed = 1
efficiency = 1
[loop.segment]
kind = "drive"
)"));
  EXPECT_EQ(single.status, 2);
  EXPECT_NE(single.err.find("[[loop.segment]]"), std::string::npos) << single.err;
  const CliRun missing = run("loop /nonexistent/loop.toml");
  EXPECT_EQ(missing.status, 2);
}

TEST(LoopCli, CaseFileRunsTheLoopAndNamesItsLines) {
  // a case file's loop runs through `catena run`; its errors name the case file's path and line
  const std::string good =
      "[chain]\ntype = \"sliding-hinge\"\n" + kHorizontal + "\n[analyses.loop]\n";
  const CliRun r = run("run " + write("case.toml", good));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["analyses"]["loop"]["drive_force"].get<double>(), 1404.356, kHandTol);
  std::string bad = good;
  bad.replace(bad.find("length = 20\n"), 12, "length = \"20 kg\"\n");
  const CliRun e = run("run " + write("case_bad.toml", bad));
  EXPECT_EQ(e.status, 2);
  EXPECT_NE(e.err.find("loop.segment[1].length (line 13)"), std::string::npos) << e.err;
  // [analyses.loop] takes no options: the loop is the [loop] table
  std::string option = good + "speed = 1\n";
  const CliRun o = run("run " + write("case_option.toml", option));
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("analyses.loop.speed"), std::string::npos) << o.err;
}

}  // namespace

// The report's loop section gives its lengths in one unit, the metres of its segment table and
// chart (it once showed 90000 mm beside s in m), and its tensions in the table's kN.
TEST(LoopCli, ReportShowsLengthsInMetresAndTensionsInKilonewtons) {
  const std::string out =
      (std::filesystem::temp_directory_path() / "catena_loop_cli_report.html").string();
  const CliRun r = run("report " + std::string(CATENA_EXAMPLES_DIR) + "/000_loop.toml -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string page = read_text(out);
  for (const char* row :
       {"<td>Loop length L</td><td class=\"value\">90</td><td>m</td>",
        "<td>… at path length s</td><td class=\"value\">90</td><td>m</td>",
        "<td>Greatest tension S max</td><td class=\"value\">12.7771</td><td>kN</td>",
        "<th>s start [m]</th>"})
    EXPECT_NE(page.find(row), std::string::npos) << row;
  EXPECT_EQ(page.find("<td>mm</td>"), std::string::npos);
  std::filesystem::remove(out);
}
