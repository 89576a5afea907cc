// `catena sweep`: one analysis of a case file over a grid, as CSV.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../read_text.hpp"
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
  const std::vector<std::string> lines = split(read_text(out), '\n');
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

// The CSV's rows as cells, the header first.
std::vector<std::vector<std::string>> cells(const std::string& csv) {
  std::vector<std::vector<std::string>> out;
  for (const std::string& line : split(csv, '\n')) {
    if (!line.empty()) out.push_back(split(line, ','));
  }
  return out;
}

// The value at a sweep column's dotted path; a key may hold dots itself (life_hours."1.5").
const nlohmann::json* at_path(const nlohmann::json& json, const std::string& path) {
  if (json.is_object()) {
    for (const auto& [key, value] : json.items()) {
      if (path == key) return &value;
      if (path.size() > key.size() && path.compare(0, key.size(), key) == 0 &&
          path[key.size()] == '.') {
        if (const nlohmann::json* found = at_path(value, path.substr(key.size() + 1))) return found;
      }
    }
  }
  return nullptr;
}

// Every result column of `row` (after the `inputs` swept ones) equals the JSON's number at its
// path, exactly; the run's wall-clock measurements (wall_time, real_time_factor) are not
// compared. Returns how many were compared.
std::size_t expect_row_equals(const std::vector<std::string>& header,
                              const std::vector<std::string>& row, std::size_t inputs,
                              const nlohmann::json& json) {
  std::size_t compared = 0;
  EXPECT_EQ(row.size(), header.size());
  for (std::size_t c = inputs; c + 3 < header.size() && c < row.size(); ++c) {
    const std::string name = header[c].substr(0, header[c].find(" ["));
    if (name == "summary.wall_time" || name == "summary.real_time_factor") continue;
    const nlohmann::json* v = at_path(json, name);
    if (v != nullptr && v->is_null()) {  // an absent optional result: an empty cell
      EXPECT_EQ(row[c], "") << name;
      continue;
    }
    if (v == nullptr || !v->is_number()) {
      ADD_FAILURE() << name << " is not a number of the run";
      continue;
    }
    EXPECT_EQ(std::strtod(row[c].c_str(), nullptr), v->get<double>()) << name;
    ++compared;
  }
  EXPECT_EQ(row[row.size() - 1], "");  // it ran
  return compared;
}

// The same CSV without the wall-clock columns (they measure this run's time, nothing else).
std::string without_wall_clock(const std::string& csv) {
  const auto rows = cells(csv);
  std::string out;
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      const std::string& name = rows.front()[c];
      if (name.rfind("summary.wall_time", 0) == 0 || name.rfind("summary.real_time_factor", 0) == 0)
        continue;
      out += row[c] + ",";
    }
    out += "\n";
  }
  return out;
}

// A dynamics case's [dynamics] table reaches every point, and the grid varies a value in it
// (the driven wheel's load torque) beside the analysis' own --duration: each row equals
// `catena dynamics` on a file with that value, and 1 and 2 threads give the same CSV.
TEST(SweepCli, ADynamicsSweepTakesTheCasesTableAndVariesAValueInIt) {
  const std::string drive = kExamples + "/dynamics_12B.toml";
  const std::string args = "sweep " + drive +
                           " --grid 'dynamics.sprocket[1].load_torque=5,10' --grid duration=4ms,6ms"
                           " --threads ";
  const CliRun one = run(args + "1");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(one.err, "");
  const auto rows = cells(one.out);
  ASSERT_EQ(rows.size(), 1u + 4u);
  EXPECT_EQ(rows[0][0], "dynamics.sprocket[1].load_torque");
  EXPECT_EQ(rows[0][1], "duration");
  const std::string text = read_text(drive);
  const std::string torque = "load_torque = 10 ";
  ASSERT_NE(text.find(torque), std::string::npos);
  const fs::path light = fs::temp_directory_path() / "catena_sweep_dynamics_5.toml";
  {
    std::string edited = text;
    edited.replace(edited.find(torque), torque.size(), "load_torque = 5 ");
    std::ofstream(light) << edited;
  }
  std::vector<double> drift;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const std::string& file = rows[r][0] == "5" ? light.string() : drive;
    const CliRun alone = run("dynamics " + file + " --duration " + rows[r][1] + " --format json");
    ASSERT_EQ(alone.status, 0) << alone.err;
    // 9 of the run's scalars, then the summary's window (4) and its means and extremes: 2
    // sprockets × 2, 2 spans × 3 (+ 2 natural frequencies)
    EXPECT_EQ(expect_row_equals(rows[0], rows[r], 2, nlohmann::json::parse(alone.out)), 27u) << r;
    drift.push_back(std::strtod(rows[r][2 + 9].c_str(), nullptr));
  }
  EXPECT_EQ(rows[0][2 + 9], "summary.energy_drift [J]");
  for (const char* column :
       {"summary.window_start [s]", "summary.sprocket_1.mean_speed [rad/s]",
        "summary.sprocket_1.mean_torque [N m]", "summary.span_0.mean_tension [N]",
        "summary.span_0.max_tension [N]", "summary.span_1.min_tension [N]",
        "summary.span_1.transverse_frequency [Hz]", "summary.span_0.longitudinal_frequency [Hz]"})
    EXPECT_NE(std::find(rows[0].begin(), rows[0].end(), column), rows[0].end()) << column;
  EXPECT_NE(drift[0], drift[2]);    // the load torque changed the run
  EXPECT_EQ(rows[1][2 + 5], "40");  // summary.steps: 4 ms of 0.1 ms steps
  EXPECT_EQ(rows[2][2 + 5], "60");
  const CliRun two = run(args + "2");
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(without_wall_clock(two.out), without_wall_clock(one.out));
  fs::remove(light);
}

// A dynamics sweep whose points add up to more than the total work cap (2e9 link-steps) is
// refused with exit 2 before anything runs, nothing written, naming the limit and the estimate;
// a sweep under it runs (the test above).
TEST(SweepCli, ADynamicsSweepOverTheTotalWorkCapIsRefused) {
  const std::string drive = kExamples + "/dynamics_12B.toml";
  const fs::path out = fs::temp_directory_path() / "catena_sweep_total_work.csv";
  fs::remove(out);
  const CliRun r = run("sweep " + drive +
                       " --grid 'dynamics.sprocket[1].load_torque=1:42' --grid duration=150s" +
                       " --grid dynamics.output_interval=1ms -o " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(r.err.find("--grid = 42 points, 2.016e+09 link-steps in all: expected at most 2e+09 "
                       "link-steps in one sweep (40 runs at the per-run cap of 5e+07"),
            std::string::npos)
      << r.err;
  const CliRun under = run("sweep " + drive + " --grid duration=2ms,3ms");
  EXPECT_EQ(under.status, 0) << under.err;
  EXPECT_EQ(cells(under.out).size(), 3u);
}

// The loop analysis (its one input is the [loop] table) and wear with tension_source = "loop"
// (which reads [loop] beside its own table) sweep too: the row of the case's own values equals
// `catena run`, the others differ.
TEST(SweepCli, LoopAndWearWithTheLoopsTensionsSweep) {
  const std::string loop = kExamples + "/000_loop.toml";
  const CliRun r = run("sweep " + loop + " --grid 'loop.segment[2].pretension=2kN,3kN'");
  ASSERT_EQ(r.status, 0) << r.err;
  auto rows = cells(r.out);
  ASSERT_EQ(rows.size(), 3u);
  const CliRun whole = run("run " + loop);
  ASSERT_EQ(whole.status, 0) << whole.err;
  const nlohmann::json tree = nlohmann::json::parse(whole.out)["analyses"];
  EXPECT_GE(expect_row_equals(rows[0], rows[2], 1, tree["loop"]), 10u);
  EXPECT_EQ(rows[0][3], "max_tension [N]");
  EXPECT_LT(std::strtod(rows[1][3].c_str(), nullptr), std::strtod(rows[2][3].c_str(), nullptr));

  const std::string wear = kExamples + "/000_wear_loop.toml";
  const CliRun w = run("sweep " + wear +
                       " --grid analyses.wear.wear_coefficient=1e-4,2e-4 --grid "
                       "'loop.segment[2].pretension=3kN,4kN' --threads 2");
  ASSERT_EQ(w.status, 0) << w.err;
  rows = cells(w.out);
  ASSERT_EQ(rows.size(), 5u);
  const CliRun wear_run = run("run " + wear);
  ASSERT_EQ(wear_run.status, 0) << wear_run.err;
  EXPECT_GE(expect_row_equals(rows[0], rows[1], 2,
                              nlohmann::json::parse(wear_run.out)["analyses"]["wear"]),
            10u);
  EXPECT_NE(rows[2], rows[1]);  // more pretension: other tensions, other wear
}

// Paths into the table are checked before anything runs: a row the file does not have, a
// table the analysis does not read; a key the table does not take is its point's error, as
// `catena dynamics` words it.
TEST(SweepCli, TablePathsNameWhatTheCaseHas) {
  const std::string drive = kExamples + "/dynamics_12B.toml";
  const CliRun r =
      run("sweep " + drive + " --grid 'dynamics.sprocket[2].load_torque=5' --grid 'loop.speed=1'" +
          " --grid dynamics.sprocket.teeth=12");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("3 problems"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--grid dynamics.sprocket.teeth = (grid): expected a value of the "
                       "[dynamics] table"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--grid dynamics.sprocket[2].load_torque = (grid): expected a value of "
                       "the [dynamics] table: dynamics.<key> or <row>.<key> with a row of the "
                       "file (dynamics.sprocket[0], dynamics.sprocket[1])"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--grid = 'loop.speed=1': expected an input of the analysis: a key, "
                       "analyses.<name>.<key> or a value of its table (dynamics.<key>)"),
            std::string::npos)
      << r.err;

  const CliRun typo =
      run("sweep " + drive + " --grid 'dynamics.sprocket[1].load_tork=5' --grid duration=1ms");
  ASSERT_EQ(typo.status, 0) << typo.err;
  EXPECT_NE(typo.out.find("dynamics.sprocket[1].load_tork (line 0) = 5: expected a key of a "
                          "sprocket: teeth, role, speed, inertia, load_torque"),
            std::string::npos)
      << typo.out;
  EXPECT_NE(typo.err.find("1 of 1 points did not run"), std::string::npos) << typo.err;

  // a case without the [dynamics] table: every point says so, as `catena run` does
  const fs::path path = fs::temp_directory_path() / "catena_sweep_no_table.toml";
  std::ofstream(path) << "[chain]\ntype = \"roller-iso606\"\ndesignation = \"12B\"\n"
                         "[analyses.dynamics]\n";
  const CliRun none = run("sweep " + path.string() + " --grid duration=1ms,2ms");
  EXPECT_EQ(none.status, 0);
  EXPECT_NE(none.out.find("1ms,,,\"dynamics = (missing): expected a [dynamics] table"),
            std::string::npos)
      << none.out;
  EXPECT_NE(none.err.find("2 of 2 points did not run"), std::string::npos) << none.err;
  fs::remove(path);
}

}  // namespace
