// `catena sweep`: one analysis of a case file over a grid, as CSV.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kExamples = CATENA_EXAMPLES_DIR;
const std::string kThesis = kExamples + "/000_thesis_rolling_hinge.toml";

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, separator)) out.push_back(part);
  if (!text.empty() && text.back() == separator) out.emplace_back();
  return out;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(SweepCli, OneRowPerGridPointFirstAxisSlowestWithTheRunsOwnResults) {
  const CliRun r = run("sweep " + kThesis +
                       " --grid analyses.hinge.teeth=6:8 --grid "
                       "analyses.hinge.pin_diameter=30mm,40mm,50mm --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> lines = split(r.out, '\n');
  ASSERT_EQ(lines.size(), 1u + 9u + 1u);  // header, 3 × 3 rows, the final newline
  const std::vector<std::string> header = split(lines[0], ',');
  ASSERT_GE(header.size(), 6u);
  EXPECT_EQ(header[0], "teeth");
  EXPECT_EQ(header[1], "pin_diameter");
  EXPECT_EQ(header[2], "x_N1 [m]");
  EXPECT_EQ(header[header.size() - 3], "worst_severity");
  EXPECT_EQ(header[header.size() - 2], "worst_code");
  EXPECT_EQ(header.back(), "error");
  EXPECT_EQ(lines[1].rfind("6,30mm,", 0), 0u);
  EXPECT_EQ(lines[2].rfind("6,40mm,", 0), 0u);
  EXPECT_EQ(lines[4].rfind("7,30mm,", 0), 0u);
  EXPECT_EQ(lines[9].rfind("8,50mm,", 0), 0u);

  // teeth 8 with d 40 mm is the case itself: every scalar equals `catena run`'s, exactly
  const CliRun whole = run("run " + kThesis);
  ASSERT_EQ(whole.status, 0) << whole.err;
  const nlohmann::json hinge = nlohmann::json::parse(whole.out)["analyses"]["hinge"];
  const std::vector<std::string> row = split(lines[8], ',');
  ASSERT_EQ(row.size(), header.size());
  EXPECT_EQ(row[0] + "," + row[1], "8,40mm");
  std::size_t compared = 0;
  for (std::size_t c = 2; c + 3 < header.size(); ++c) {
    const std::string name = header[c].substr(0, header[c].find(" ["));
    const nlohmann::json* v = &hinge;
    for (const std::string& key : split(name, '.')) v = &(*v)[key];
    ASSERT_TRUE(v->is_number()) << name;
    EXPECT_EQ(std::strtod(row[c].c_str(), nullptr), v->get<double>()) << name;
    ++compared;
  }
  EXPECT_GE(compared, 15u);
  const auto& diagnostics = hinge["diagnostics"];
  ASSERT_FALSE(diagnostics.empty());
  EXPECT_EQ(row[row.size() - 3], "infeasible");
}

TEST(SweepCli, TheSameBytesOnOneTwoAndEightThreads) {
  const std::string args = "sweep " + kThesis +
                           " --grid analyses.hinge.teeth=3:20:2 --grid "
                           "'analyses.hinge.pin_diameter=30mm,35 mm,40mm,50mm' --grid "
                           "analyses.hinge.strokes=1,2 --threads ";
  const CliRun one = run(args + "1");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(split(one.out, '\n').size(), 1u + 9u * 4u * 2u + 1u);
  for (const char* threads : {"2", "8"}) {
    const CliRun many = run(args + threads);
    EXPECT_EQ(many.status, 0) << many.err;
    EXPECT_EQ(many.out, one.out) << threads << " threads";
  }
}

TEST(SweepCli, BareKeysForACaseWithOneAnalysisAndAPointThatDoesNotRun) {
  const fs::path path = fs::temp_directory_path() / "catena_sweep_one.toml";
  std::ofstream(path) << "[chain]\ntype = \"rolling-hinge\"\npin_diameter = \"40 mm\"\n"
                         "half_thickness = \"8 mm\"\n[analyses.hinge]\nplate_radius = \"15 mm\"\n";
  const fs::path out = fs::temp_directory_path() / "catena_sweep_one.csv";
  fs::remove(out);
  const CliRun r = run("sweep " + path.string() + " --grid teeth=2:4 --output " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");  // the CSV went to the file
  EXPECT_NE(r.err.find("1 of 3 points did not run"), std::string::npos) << r.err;
  const std::vector<std::string> lines = split(slurp(out), '\n');
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[1].rfind("2,,", 0), 0u) << lines[1];
  EXPECT_NE(lines[1].find(",teeth = '2': expected a whole number ≥ 3"), std::string::npos)
      << lines[1];
  EXPECT_EQ(lines[2].rfind("3,0.", 0), 0u) << lines[2];
  EXPECT_EQ(lines[3].back(), ',');  // ran: an empty error cell
  fs::remove(out);
  fs::remove(path);
}

TEST(SweepCli, EveryProblemAtOnceWithExitTwoAndNothingWritten) {
  const fs::path out = fs::temp_directory_path() / "catena_sweep_bad.csv";
  fs::remove(out);
  const CliRun r = run("sweep " + kThesis +
                       " --grid analyses.hinge.teth=6:8 --grid analyses.hinge.strokes=3:1"
                       " --grid analyses.warp.force=1kN --grid pin_diameter=30mm,,40mm"
                       " --output " +
                       out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(r.err.find("4 problems"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--grid analyses.hinge.teth = (grid): expected an input of 'hinge' (did "
                       "you mean 'teeth'?)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("'analyses.hinge.strokes=3:1': expected a range a:b with a ≤ b"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--grid analyses.warp.force = (grid): expected keys of one analysis"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("'pin_diameter=30mm,,40mm'"), std::string::npos) << r.err;

  // a shared value that can never read is named by its case path, before anything runs
  const fs::path path = fs::temp_directory_path() / "catena_sweep_unit.toml";
  std::ofstream(path) << "[chain]\ntype = \"rolling-hinge\"\npin_diameter = \"40 mm\"\n"
                         "half_thickness = \"8 kg\"\n[analyses.hinge]\nplate_radius = \"15 "
                         "mm\"\nmodulus = true\n";
  const CliRun unit = run("sweep " + path.string() + " --grid teeth=6:8");
  EXPECT_EQ(unit.status, 2);
  EXPECT_EQ(unit.out, "");
  EXPECT_NE(unit.err.find("2 problems"), std::string::npos) << unit.err;
  EXPECT_NE(unit.err.find("chain.half_thickness = '8 kg'"), std::string::npos) << unit.err;
  EXPECT_NE(unit.err.find("analyses.hinge.modulus = true"), std::string::npos) << unit.err;
  fs::remove(path);

  // several analyses in the case and bare keys: which one is meant must be said
  const CliRun which = run("sweep " + kThesis + " --grid teeth=6:8");
  EXPECT_EQ(which.status, 2);
  EXPECT_NE(which.err.find("naming one of the case's analyses (hinge, hinge-catena, hinge_sweep"),
            std::string::npos)
      << which.err;
}

TEST(SweepCli, TooManyPointsAndThreadsAreRefusedTogetherNamingTheFlags) {
  const CliRun r =
      run("sweep " + kThesis +
          " --grid analyses.hinge.teeth=1:1001 --grid analyses.hinge.plate_radius=1:1000"
          " --threads 100000");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("2 problems"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--grid = 1001000 points: expected at most 1000000 points"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--threads = 100000: expected 0 (every hardware thread) to 1024"),
            std::string::npos)
      << r.err;
}

}  // namespace
