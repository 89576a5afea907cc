// Size parameters beyond their caps (issue 18): each reproducer of the issue exits 2 at once,
// naming the flag, the value, the estimated time and memory and the cap; --allow-large lifts the
// cap (on the command line, in a case file), and a value at the cap still runs.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_run.hpp"

namespace {

struct Case {
  const char* name;
  const char* args;
  const char* flag;
  const char* value;
  const char* cap;
};

class CapsCli : public testing::TestWithParam<Case> {};

constexpr const char* kRing =
    "ring --inner-radius 4.72 --outer-radius 10 --thickness 1 --E-r 10GPa --E-phi 40GPa --G 4GPa "
    "--nu-phi-r 0.28 --gap 0.02";

TEST_P(CapsCli, AboveTheCapIsRefusedQuicklyNamingFlagValueEstimateAndCap) {
  const Case& c = GetParam();
  const auto start = std::chrono::steady_clock::now();
  const CliRun r = run(c.args);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_LT(seconds, 10.0);
  EXPECT_NE(r.err.find(std::string(c.flag) + " = '" + c.value + "'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(std::string("at most ") + c.cap + " (estimated "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(" s and "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" MB"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--allow-large"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

INSTANTIATE_TEST_SUITE_P(
    Issue18, CapsCli,
    testing::Values(
        Case{"ring_nodes",
             "ring --inner-radius 4.72 --outer-radius 10 --thickness 1 --E-r 10GPa --E-phi 40GPa "
             "--G 4GPa --nu-phi-r 0.28 --gap 0.02 --method sweep --nodes 2000000",
             "--nodes", "2000000", "20000"},
        Case{"ring_harmonics",
             "ring --inner-radius 4.72 --outer-radius 10 --thickness 1 --E-r 10GPa --E-phi 40GPa "
             "--G 4GPa --nu-phi-r 0.28 --gap 0.02 --method sweep --harmonics 200000",
             "--harmonics", "200000", "20000"},
        Case{"engagement_points",
             "engagement --hinge sliding --pitch 125 --teeth 8 --tension 1kN --points 1000000000",
             "--points", "1000000000", "100000"},
        Case{"pocketwheel_points",
             "pocketwheel --pitch 64 --wire 18 --teeth 8 --omega 5 --points 1000000000", "--points",
             "1000000000", "100000"},
        Case{"hinge_points",
             "hinge --pin-diameter 40 --half-thickness 8 --teeth 8 --plate-radius 34 "
             "--points 1000000000",
             "--points", "1000000000", "100000"},
        Case{"hinge_sweep_count",
             "hinge sweep --pin-diameter 40 --half-thickness 8 --teeth 8 --count 1000000",
             "--count", "1000000", "40000"},
        Case{"ring_capacity_harmonics",
             "ring capacity --alpha 0.42 --sum-sigma-r 0.2662 --k-max 4.173 "
             "--fibre-strength 2500MPa --load 10kN --harmonics 300000",
             "--harmonics", "300000", "20000"},
        // --teeth sets work too: the whole wrap seats ~z/2 rollers; a wheel of z pockets
        // (measured: engagement 10⁹ teeth and pocketwheel 10⁶ did not finish in 30 s)
        Case{"engagement_teeth",
             "engagement --hinge sliding --pitch 125 --teeth 1000000000 --tension 1kN", "--teeth",
             "1000000000", "100000"},
        Case{"pocketwheel_teeth", "pocketwheel --pitch 64 --wire 18 --teeth 1000000 --omega 5",
             "--teeth", "1000000", "10000"}),
    [](const testing::TestParamInfo<Case>& p) { return std::string(p.param.name); });

TEST(CapsCli, TeethAtTheCapRunAndAboveNeedAllowLarge) {
  EXPECT_EQ(run("engagement --hinge sliding --pitch 125 --teeth 100000 --tension 1kN --format "
                "json >/dev/null")
                .status,
            0);
  EXPECT_EQ(
      run("pocketwheel --pitch 64 --wire 18 --teeth 100 --omega 5 --points 3 --format json").status,
      0);
  const CliRun above =
      run("engagement --hinge sliding --pitch 125 --teeth 100001 --tension 1kN "
          "--points 3 --format json");
  EXPECT_EQ(above.status, 2);
  EXPECT_NE(above.err.find("--teeth = '100001': expected at most 100000"), std::string::npos)
      << above.err;
  EXPECT_EQ(run("engagement --hinge sliding --pitch 125 --teeth 100001 --tension 1kN --points 3 "
                "--allow-large --format json >/dev/null")
                .status,
            0);
}

TEST(CapsCli, TheEstimateGrowsWithTheValue) {
  // 10⁹ points of a pocket wheel: 65 µs and 850 B each, so about 65 000 s and 850 000 MB
  const CliRun r = run("pocketwheel --pitch 64 --wire 18 --teeth 8 --omega 5 --points 1000000000");
  EXPECT_NE(r.err.find("estimated 65000 s and 850000 MB; at the cap 6.5 s and 85 MB"),
            std::string::npos)
      << r.err;
}

TEST(CapsCli, AValueAtTheCapRunsAndOneAboveNeedsAllowLarge) {
  const std::string ring = std::string(kRing) + " --format json";
  EXPECT_EQ(run("hinge sweep --pin-diameter 40 --half-thickness 8 --teeth 8 --count 40001").status,
            2);
  const CliRun small =
      run("hinge sweep --pin-diameter 40 --half-thickness 8 --teeth 8 --count "
          "3 --allow-large --format json");
  EXPECT_EQ(small.status, 0) << small.err;
  // --allow-large lifts the cap: a size above it runs (small enough for a test)
  const CliRun allowed =
      run("engagement --hinge sliding --pitch 125 --teeth 8 --tension 1kN --points 100001 "
          "--allow-large --format json");
  EXPECT_EQ(allowed.status, 0) << allowed.err;
  const CliRun refused =
      run("engagement --hinge sliding --pitch 125 --teeth 8 --tension 1kN --points 100001 "
          "--format json");
  EXPECT_EQ(refused.status, 2) << refused.err;
  const CliRun at_cap =
      run("engagement --hinge sliding --pitch 125 --teeth 8 --tension 1kN --points 100000 "
          "--format json");
  EXPECT_EQ(at_cap.status, 0) << at_cap.err;
  EXPECT_EQ(run(ring).status, 0);
}

TEST(CapsCli, ACaseFileTakesAllowLargeInItsAnalysisTable) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("catena_caps_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string head =
      "title = \"caps\"\n[chain]\ntype = \"sliding-hinge\"\npitch = \"125 mm\"\n"
      "[sprocket]\nteeth = 8\n[loads]\ntension = \"1 kN\"\n[analyses.engagement]\n"
      "points = 100001\n";
  {
    std::ofstream(dir / "over.toml") << head;
    std::ofstream(dir / "allowed.toml") << head << "allow_large = true\n";
    std::ofstream(dir / "bad.toml") << head << "allow_large = \"maybe\"\n";
  }
  const CliRun over = run("run " + (dir / "over.toml").string());
  EXPECT_EQ(over.status, 2) << over.err;
  EXPECT_NE(over.err.find("analyses.engagement.points = '100001': expected at most 100000"),
            std::string::npos)
      << over.err;
  const CliRun allowed = run("run " + (dir / "allowed.toml").string());
  EXPECT_EQ(allowed.status, 0) << allowed.err;
  const CliRun bad = run("run " + (dir / "bad.toml").string());
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_NE(bad.err.find("analyses.engagement.allow_large"), std::string::npos) << bad.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
