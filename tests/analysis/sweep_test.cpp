#include "catena/sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "catena/catena.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/record.hpp"

namespace catena {
namespace {

// The hinge of the thesis' example case with a plate radius inside R1max for every pin swept.
const InputSet kBase = {{"half_thickness", "8 mm"},     {"plate_radius", "15 mm"},
                        {"tension", "29.4 kN"},         {"contact_length", "24 mm"},
                        {"allowable_shear", "120 MPa"}, {"allowable_contact", "1600 MPa"},
                        {"friction", "0.15"},           {"pin_diameter", "40 mm"}};

SweepRequest hinge_grid() {
  SweepRequest r;
  r.analysis = "hinge";
  r.base = kBase;
  // teeth = 2 is below the model's z ≥ 3: those points must fail alone.
  r.grid = {{"teeth", {"2", "6", "8", "12", "20"}},
            {"pin_diameter", {"30mm", "40 mm", "50mm"}},
            {"strokes", {"1", "2"}}};
  return r;
}

std::vector<std::string> json_of(const SweepResult& result) {
  std::vector<std::string> out;
  for (const SweepPoint& p : result.points)
    out.push_back(p.ok() ? io::to_json(p.record->data) : "error: " + p.error);
  return out;
}

TEST(Sweep, GridOrderIsTheCartesianProductFirstAxisSlowest) {
  const std::vector<InputSet> points = sweep_points(hinge_grid());
  ASSERT_EQ(points.size(), 5u * 3u * 2u);
  EXPECT_EQ(points[0], (InputSet{{"teeth", "2"}, {"pin_diameter", "30mm"}, {"strokes", "1"}}));
  EXPECT_EQ(points[1], (InputSet{{"teeth", "2"}, {"pin_diameter", "30mm"}, {"strokes", "2"}}));
  EXPECT_EQ(points[2], (InputSet{{"teeth", "2"}, {"pin_diameter", "40 mm"}, {"strokes", "1"}}));
  EXPECT_EQ(points[6], (InputSet{{"teeth", "6"}, {"pin_diameter", "30mm"}, {"strokes", "1"}}));
  EXPECT_EQ(points.back(), (InputSet{{"teeth", "20"}, {"pin_diameter", "50mm"}, {"strokes", "2"}}));
  const SweepResult result = sweep(hinge_grid(), {.threads = 3});
  ASSERT_EQ(result.points.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(result.points[i].inputs, points[i]);
  EXPECT_EQ(result.keys, (std::vector<std::string>{"teeth", "pin_diameter", "strokes"}));
}

TEST(Sweep, IdenticalBitForBitOnOneTwoAndEightThreads) {
  const SweepResult one = sweep(hinge_grid(), {.threads = 1});
  const std::vector<std::string> reference = json_of(one);
  for (unsigned threads : {2u, 8u}) {
    for (int repeat = 0; repeat < 3; ++repeat) {
      const SweepResult many = sweep(hinge_grid(), {.threads = threads});
      EXPECT_EQ(json_of(many), reference) << threads << " threads";
      EXPECT_EQ(sweep_csv(sweep_table(many)), sweep_csv(sweep_table(one))) << threads;
    }
  }
}

TEST(Sweep, EqualsCatenaRunPointByPoint) {
  const SweepRequest request = hinge_grid();
  const SweepResult result = sweep(request, {.threads = 4});
  std::size_t failed = 0;
  for (const SweepPoint& p : result.points) {
    InputSet inputs = request.base;
    for (const auto& [key, text] : p.inputs) {
      bool replaced = false;
      for (auto& kv : inputs) {
        if (kv.first == key) {
          kv.second = text;
          replaced = true;
        }
      }
      if (!replaced) inputs.emplace_back(key, text);
    }
    try {
      const analysis::Record direct = run("hinge", inputs);
      ASSERT_TRUE(p.ok()) << p.error;
      EXPECT_EQ(io::to_json(p.record->data), io::to_json(direct.data));
    } catch (const InputError& e) {
      ++failed;
      EXPECT_FALSE(p.ok());
      EXPECT_EQ(p.error, e.what());
    }
  }
  EXPECT_EQ(failed, 3u * 2u);  // every teeth = 2 point, and only those
}

TEST(Sweep, APointThatFailsToBindKeepsItsErrorAndTheRestRun) {
  SweepRequest request;
  request.analysis = "hinge";
  request.base = kBase;
  request.points = {{{"teeth", "8"}},
                    {{"teeth", "eight"}},
                    {{"teeth", "9"}, {"strokes", "0"}},
                    {{"teeth", "10"}}};
  const SweepResult result = sweep(request, {.threads = 2});
  ASSERT_EQ(result.points.size(), 4u);
  EXPECT_TRUE(result.points[0].ok());
  EXPECT_TRUE(result.points[3].ok());
  ASSERT_FALSE(result.points[1].ok());
  EXPECT_NE(result.points[1].error.find("teeth = 'eight'"), std::string::npos)
      << result.points[1].error;
  ASSERT_EQ(result.points[2].issues.size(), 1u);
  EXPECT_EQ(result.points[2].issues[0].field, "strokes");
  EXPECT_FALSE(result.points[1].record.has_value());
  EXPECT_EQ(result.keys, (std::vector<std::string>{"teeth", "strokes"}));
}

TEST(Sweep, KeysThatCanNeverBindAreRefusedUpFrontAllAtOnce) {
  SweepRequest request = hinge_grid();
  request.base.emplace_back("tooth_count", "8");
  request.grid.push_back({"pin_diamter", {"30mm"}});
  request.grid.push_back({"strokes", {}});
  try {
    sweep(request);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    ASSERT_EQ(e.issues().size(), 4u) << what;
    EXPECT_EQ(e.issues()[0].field, "tooth_count");
    EXPECT_EQ(e.issues()[1].field, "pin_diamter");
    EXPECT_NE(what.find("did you mean 'pin_diameter'"), std::string::npos) << what;
    EXPECT_EQ(e.issues()[2].field, "strokes");  // swept twice
    EXPECT_EQ(e.issues()[3].field, "strokes");  // no values
  }
  // a shared value that does not read fails up front, unless every point replaces it
  request = hinge_grid();
  request.base.emplace_back("modulus", "210 parsec");
  request.base[0].second = "8 furlongs per fortnight";
  try {
    sweep_points(request);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 2u) << e.what();
    EXPECT_EQ(e.issues()[0].field, "half_thickness");
    EXPECT_EQ(e.issues()[1].field, "modulus");
  }
  request = hinge_grid();
  request.base[7].second = "40 kg";  // pin_diameter: every point sets its own
  EXPECT_EQ(sweep_points(request).size(), 30u);
  EXPECT_THROW(sweep({.analysis = "hinj", .base = {}, .grid = {{"teeth", {"8"}}}, .points = {}}),
               InputError);
  EXPECT_THROW(sweep({.analysis = "hinge", .base = kBase, .grid = {}, .points = {}}), InputError);
}

TEST(Sweep, ProgressIsReportedOnTheCallingThreadEndingAtTheTotal) {
  std::vector<std::size_t> seen;
  const auto caller = std::this_thread::get_id();
  bool elsewhere = false;
  SweepOptions options;
  options.threads = 2;
  options.progress = [&](std::size_t done, std::size_t total) {
    EXPECT_EQ(total, 30u);
    elsewhere = elsewhere || std::this_thread::get_id() != caller;
    seen.push_back(done);
  };
  sweep(hinge_grid(), options);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 30u);
  EXPECT_FALSE(elsewhere);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_GT(seen[i], seen[i - 1]);
}

TEST(Sweep, TableColumnsAreInputsThenScalarResultsWithUnitsThenWorstDiagnostic) {
  const SweepResult result =
      sweep(hinge_grid(), {.threads = 2, .progress = {}, .keep_records = false});
  EXPECT_FALSE(result.points[6].record.has_value());
  const SweepTable table = sweep_table(result);
  ASSERT_EQ(table.rows(), 30u);
  ASSERT_EQ(table.inputs.size(), 3u);
  EXPECT_EQ(table.inputs[0].name, "teeth");
  EXPECT_EQ(table.inputs[1].values[2], "40 mm");
  std::vector<std::string> names;
  for (const auto& c : table.results) names.push_back(c.name + "|" + c.unit);
  const auto has = [&](const std::string& n) {
    return std::find(names.begin(), names.end(), n) != names.end();
  };
  EXPECT_TRUE(has("R1_max|m"));
  EXPECT_TRUE(has("shear_stress|Pa"));
  EXPECT_TRUE(has("step1.R1_max|m"));  // nested: dotted path, unit of its key
  EXPECT_FALSE(has("R2_from_eq6|"));   // a boolean is not a number
  for (const std::string& n : names) EXPECT_EQ(n.find("pitch_change.phi"), std::string::npos);
  EXPECT_FALSE(has("model|"));
  // row 6 (teeth 6, d 30 mm, m 1) against the hinge run alone
  InputSet inputs = kBase;
  inputs[7].second = "30mm";
  inputs.emplace_back("teeth", "6");
  inputs.emplace_back("strokes", "1");
  const analysis::Record direct = run("hinge", inputs);
  for (const auto& c : table.results) {
    if (c.name == "R1_max") {
      EXPECT_EQ(c.values[6], direct.data.at("R1_max").as_number());
    }
    EXPECT_TRUE(std::isnan(c.values[0])) << c.name;  // teeth 2 did not run
  }
  const auto worst = worst_diagnostic(direct.diagnostics);
  ASSERT_TRUE(worst.has_value());
  EXPECT_EQ(table.severity.values[6], to_string(worst->severity));
  EXPECT_EQ(table.code.values[6], worst->code);
  EXPECT_EQ(table.error.values[6], "");
  EXPECT_NE(table.error.values[0].find("teeth"), std::string::npos);

  const std::string csv = sweep_csv(table);
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header.rfind("teeth,pin_diameter,strokes,x_N1 [m],", 0), 0u) << header;
  EXPECT_NE(header.find(",R1_max [m],"), std::string::npos);
  const std::string tail = ",worst_severity,worst_code,error";
  ASSERT_GT(header.size(), tail.size());
  EXPECT_EQ(header.substr(header.size() - tail.size()), tail);
  std::size_t lines = 0;
  for (char ch : csv) lines += ch == '\n';
  EXPECT_EQ(lines, 31u);
  // the error cell is the point's problems on one line
  EXPECT_EQ(table.error.values[0], "teeth = '2': expected a whole number ≥ 3");
}

TEST(Sweep, CsvNumbersReadBackExactlyAndAbsentCellsAreEmpty) {
  SweepTable table;
  table.inputs = {{"k", {"a,b", "say \"x\""}}};
  table.results = {{"v", "m", {0.1 + 0.2, NAN}}};
  table.severity.values = {"warning", ""};
  table.code.values = {"c", ""};
  table.error.values = {"", "line\nbreak"};
  EXPECT_EQ(sweep_csv(table),
            "k,v [m],worst_severity,worst_code,error\n"
            "\"a,b\",0.30000000000000004,warning,c,\n"
            "\"say \"\"x\"\"\",,,,\"line\nbreak\"\n");
}

TEST(Sweep, AxesParseRangesStepsAndListsWithUnits) {
  std::vector<Issue> issues;
  auto a = parse_axis("teeth=6:9", "--grid", issues);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->key, "teeth");
  EXPECT_EQ(a->values, (std::vector<std::string>{"6", "7", "8", "9"}));
  a = parse_axis("teeth=6:20:5", "--grid", issues);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->values, (std::vector<std::string>{"6", "11", "16"}));
  a = parse_axis("pin_diameter=30mm, 40 mm,50mm", "--grid", issues);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->values, (std::vector<std::string>{"30mm", "40 mm", "50mm"}));
  a = parse_axis("teeth=8", "--grid", issues);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->values, (std::vector<std::string>{"8"}));
  EXPECT_TRUE(issues.empty());
  for (const char* bad : {"teeth", "=6:9", "teeth=9:6", "teeth=6:9:0", "teeth=6.5:9", "teeth=a:b",
                          "teeth=6:9:1:2", "d=30mm,,40mm", "d="}) {
    std::vector<Issue> one;
    EXPECT_FALSE(parse_axis(bad, "--grid", one)) << bad;
    ASSERT_EQ(one.size(), 1u) << bad;
    EXPECT_EQ(one[0].field, "--grid");
  }
}

TEST(Sweep, PointsAndThreadsAreBoundedAndNamedTogether) {
  // 1001 × 1000 points: one more row than the cap of 10⁶, refused before any point is made
  SweepRequest request = hinge_grid();
  std::vector<std::string> many(1000, "8");
  request.grid = {{"teeth", std::vector<std::string>(1001, "8")}, {"strokes", many}};
  try {
    sweep(request, {.threads = 5000, .progress = {}, .keep_records = false});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 2u) << e.what();
    EXPECT_EQ(e.issues()[0].field, "grid");
    EXPECT_EQ(e.issues()[0].value, "1001000 points");
    EXPECT_NE(e.issues()[0].expected.find("at most 1000000 points"), std::string::npos);
    EXPECT_EQ(e.issues()[1].field, "threads");
    EXPECT_EQ(e.issues()[1].expected, "0 (every hardware thread) to 1024");
  }
  // at the caps: the thread count alone is fine
  request = hinge_grid();
  EXPECT_EQ(sweep(request, {.threads = 1024, .progress = {}, .keep_records = false}).points.size(),
            30u);
}

// A 12B drive of 3 ms (examples/dynamics_12B.toml, shortened), its driven wheel's load torque
// given.
std::string drive_toml(const std::string& load_torque) {
  return "[dynamics]\nchain = \"12B\"\nlinks = 32\naxial_stiffness = \"5e7 N/m\"\n"
         "axial_damping = 100\npretension = \"950 N\"\ncontact_stiffness = \"2e8 N/m\"\n"
         "contact_damping = 800\nduration = \"3 ms\"\nstep = \"0.1 ms\"\ntheta = 0.6\n"
         "[[dynamics.sprocket]]\nteeth = 12\nrole = \"driver\"\nspeed = \"13 rad/s\"\n"
         "[[dynamics.sprocket]]\nteeth = 12\nrole = \"driven\"\ninertia = 0.01\nload_torque = " +
         load_torque + "\n";
}

// The record as JSON without the run's wall-clock measurements (they time this run only).
std::string without_wall_clock(analysis::Value data) {
  data["summary"]["wall_time"] = 0.0;
  data["summary"]["real_time_factor"] = 0.0;
  return io::to_json(data);
}

// A table given as values reaches every point, an axis may vary a value inside it, and each point
// is the run of a file holding that value, series and all, on 1 and 2 threads alike.
TEST(Sweep, TablesReachEveryPointAndAnAxisMayVaryAValueInside) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "catena_sweep_tables";
  fs::create_directories(dir);
  const fs::path ten = dir / "ten.toml", five = dir / "five.toml";
  std::ofstream(ten) << drive_toml("10");
  std::ofstream(five) << drive_toml("5");
  const analysis::Parameter& table = *find_analysis("dynamics")->parameter("dynamics");
  const io::RawInput raw = io::table_input(io::read_case(ten.string()), table);
  SweepRequest r;
  r.analysis = "dynamics";
  r.tables = {{raw.key, raw.table, raw.tables, raw.source}};
  r.grid = {{"dynamics.sprocket[1].load_torque", {"5", "10"}}, {"step", {"0.1ms", "0.05 ms"}}};
  SweepOptions one;
  one.threads = 1;
  const SweepResult a = sweep(r, one);
  SweepOptions two;
  two.threads = 2;
  const SweepResult b = sweep(r, two);
  ASSERT_EQ(a.points.size(), 4u);
  ASSERT_EQ(b.points.size(), 4u);
  EXPECT_EQ(a.keys, (std::vector<std::string>{"dynamics.sprocket[1].load_torque", "step"}));
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    ASSERT_TRUE(a.points[i].ok()) << a.points[i].error;
    ASSERT_TRUE(b.points[i].ok()) << b.points[i].error;
    const auto& in = a.points[i].inputs;
    const fs::path& file = in[0].second == "5" ? five : ten;
    const analysis::Record alone =
        run("dynamics", {{"dynamics", file.string()}, {"step", in[1].second}});
    EXPECT_EQ(without_wall_clock(a.points[i].record->data), without_wall_clock(alone.data)) << i;
    EXPECT_EQ(without_wall_clock(b.points[i].record->data), without_wall_clock(alone.data)) << i;
  }
  // the torque reached the run: the driven wheel's mean torque differs
  EXPECT_NE(io::to_json(a.points[0].record->data.at("sprocket")),
            io::to_json(a.points[2].record->data.at("sprocket")));

  // refused before anything runs: a row the table lacks, a table the analysis does not take, a
  // table given twice
  SweepRequest bad = r;
  bad.grid = {{"dynamics.sprocket[2].load_torque", {"5"}}};
  bad.tables.push_back({"loop", {}, {}, ""});
  bad.tables.push_back(bad.tables.front());
  try {
    sweep_points(bad);
    ADD_FAILURE() << "not refused";
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 3u) << e.what();
    EXPECT_EQ(e.issues()[0].field, "loop");
    EXPECT_EQ(e.issues()[0].expected, "a table parameter of 'dynamics' (dynamics)");
    EXPECT_EQ(e.issues()[1].field, "dynamics");
    EXPECT_EQ(e.issues()[1].expected, "one value of the table (it is given twice)");
    EXPECT_EQ(e.issues()[2].field, "dynamics.sprocket[2].load_torque");
  }
  fs::remove_all(dir);
}

// Explicit points that give the table as its file and name a value inside it (what Python's
// catena.sweep sends): share_table_files reads the file once and each point runs as the file
// holding its value; points naming different files, or one without the file, are refused, and
// a request that never looks inside the table is left alone.
TEST(Sweep, PointsNamingAValueInsideTheirTablesFileShareIt) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "catena_sweep_share";
  fs::create_directories(dir);
  const fs::path ten = dir / "ten.toml", five = dir / "five.toml";
  std::ofstream(ten) << drive_toml("10");
  std::ofstream(five) << drive_toml("5");
  SweepRequest r;
  r.analysis = "dynamics";
  r.base = {{"dynamics", ten.string()}};
  r.points = {{{"dynamics.sprocket[1].load_torque", "5"}},
              {{"dynamics.sprocket[1].load_torque", "10"}, {"dynamics", ten.string()}}};
  std::vector<Issue> issues;
  share_table_files(r, issues);
  ASSERT_TRUE(issues.empty()) << issues.front().expected;
  ASSERT_EQ(r.tables.size(), 1u);
  EXPECT_EQ(r.tables[0].key, "dynamics");
  EXPECT_TRUE(r.base.empty());
  ASSERT_EQ(r.points[1].size(), 1u);
  const SweepResult got = sweep(r, {.threads = 1});
  ASSERT_EQ(got.points.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_TRUE(got.points[i].ok()) << got.points[i].error;
    const analysis::Record alone = run("dynamics", {{"dynamics", (i == 0 ? five : ten).string()}});
    EXPECT_EQ(without_wall_clock(got.points[i].record->data), without_wall_clock(alone.data)) << i;
  }

  // two files, and a point without any: refused, naming the table's key
  for (const InputSet& second : {InputSet{{"dynamics", five.string()}}, InputSet{}}) {
    SweepRequest two;
    two.analysis = "dynamics";
    two.points = {{{"dynamics", ten.string()}, {"dynamics.duration", "2ms"}}, second};
    std::vector<Issue> found;
    share_table_files(two, found);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].field, "dynamics");
    EXPECT_EQ(found[0].value, second.empty() ? "(missing)" : "a different file in some points");
    EXPECT_TRUE(two.tables.empty());
  }
  // a file that does not read
  SweepRequest missing;
  missing.analysis = "dynamics";
  missing.points = {{{"dynamics", (dir / "none.toml").string()}, {"dynamics.duration", "2ms"}}};
  std::vector<Issue> unread;
  share_table_files(missing, unread);
  ASSERT_FALSE(unread.empty());
  EXPECT_EQ(unread[0].field, "dynamics");
  // nothing inside the table: the file stays a point's value
  SweepRequest plain;
  plain.analysis = "dynamics";
  plain.points = {{{"dynamics", ten.string()}, {"duration", "2ms"}}};
  std::vector<Issue> none;
  share_table_files(plain, none);
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(plain.tables.empty());
  EXPECT_EQ(plain.points[0].size(), 2u);
  fs::remove_all(dir);
}

// A sweep's total work (steps × links summed over its points, Analysis::work_of) is capped at
// kSweepWorkCaps per-run caps, 2e9 link-steps for dynamics, before anything runs: 42 points of
// 150 s on 32 links (4.8e7 link-steps each, under the per-run cap of 5e7) are 2.016e9, over it;
// 41 are 1.968e9, under it. A point over the per-run cap (1000 s) is its own error and adds no
// work; allow_large on every point lifts the total cap as it lifts each point's.
TEST(Sweep, ADynamicsSweepsTotalWorkIsCappedBeforeAnythingRuns) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "catena_sweep_work";
  fs::create_directories(dir);
  const fs::path file = dir / "drive.toml";
  std::ofstream(file) << drive_toml("10");
  const analysis::Parameter& table = *find_analysis("dynamics")->parameter("dynamics");
  const io::RawInput raw = io::table_input(io::read_case(file.string()), table);
  auto request = [&](int points) {
    SweepRequest r;
    r.analysis = "dynamics";
    r.tables = {{raw.key, raw.table, raw.tables, raw.source}};
    std::vector<std::string> torques;
    for (int i = 1; i <= points; ++i) torques.push_back(std::to_string(i));
    // (the output interval keeps the series under the 200 000 samples a run may hold)
    r.grid = {{"dynamics.sprocket[1].load_torque", torques},
              {"duration", {"150s", "1000s"}},
              {"dynamics.output_interval", {"1 ms"}}};
    return r;
  };
  try {
    sweep_points(request(42));
    ADD_FAILURE() << "not refused";
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 1u) << e.what();
    EXPECT_EQ(e.issues()[0].field, "grid");
    EXPECT_EQ(e.issues()[0].value, "84 points, 2.016e+09 link-steps in all");
    EXPECT_NE(e.issues()[0].expected.find("at most 2e+09 link-steps in one sweep"),
              std::string::npos)
        << e.what();
    EXPECT_NE(e.issues()[0].expected.find("allow_large = true in [analyses.dynamics]"),
              std::string::npos)
        << e.what();
  }
  // sweep() refuses it too, before any point runs (a run would take minutes)
  EXPECT_THROW(sweep(request(42), {.threads = 1, .progress = {}, .keep_records = false}),
               InputError);
  EXPECT_EQ(sweep_points(request(41)).size(), 82u);
  SweepRequest large = request(42);
  large.base.emplace_back(std::string(analysis::kAllowLarge), "true");
  EXPECT_EQ(sweep_points(large).size(), 84u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace catena
