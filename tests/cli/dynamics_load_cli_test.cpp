// `load_per_metre` on a [[dynamics.guide]] (docs/models/dynamics.md, "A conveyed load") through
// `catena dynamics`: a loaded rail adds the loads' work to the work balance (and nothing is added
// without one: the example's output keeps its fields), and every bad load is named at once — out
// of range, on an arc, without gravity — with its line and exit status 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kExample = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_conveyor.toml";

std::string example() {
  std::stringstream text;
  text << std::ifstream(kExample).rdbuf();
  return text.str();
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "catena_dynamics_load_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// `key` inserted after the n-th "[[dynamics.guide]]" line (0: the first) of `text`.
std::string with_guide_key(std::string text, int n, const std::string& key) {
  std::size_t at = 0;
  for (int k = 0; k <= n; ++k) {
    at = text.find("[[dynamics.guide]]", k == 0 ? 0 : at + 1);
    EXPECT_NE(at, std::string::npos) << n;
    if (at == std::string::npos) return text;
  }
  text.insert(text.find('\n', at) + 1, key + "\n");
  return text;
}

std::string with_dynamics_key(std::string text, const std::string& key) {
  const std::size_t at = text.find("[dynamics]\n");
  EXPECT_NE(at, std::string::npos);
  text.insert(at + 11, key + "\n");
  return text;
}

TEST(DynamicsLoadCli, LoadedRailAddsTheLoadsWorkToTheBalance) {
  const std::string balance = with_dynamics_key(example(), "work_balance = true");
  const CliRun r =
      run("dynamics " +
          write("loaded.toml", with_guide_key(balance, 0, "load_per_metre = \"2.5 kg/m\"")) +
          " --duration 0.02s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& b = j["summary"]["work_balance"];
  ASSERT_TRUE(b.contains("loads")) << b.dump();
  // the loaded chain settles onto the level rail: the load's weight works on that small sink
  EXPECT_GT(b["loads"].get<double>(), 0.0);
  const double links = b["link_dampers"], contact = b["contact_dampers"],
               numerical = b["numerical"], drift = j["summary"]["energy_drift"];
  EXPECT_NEAR(links + contact + numerical, drift, 1e-12 + 1e-9 * std::abs(drift));
  const CliRun plain =
      run("dynamics " + write("plain.toml", balance) + " --duration 0.02s --format json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const auto p = nlohmann::json::parse(plain.out);
  EXPECT_FALSE(p["summary"]["work_balance"].contains("loads"));
  // the load presses the upper run onto its rail: more friction than without it
  EXPECT_LT(j["summary"]["friction_work"].get<double>(),
            p["summary"]["friction_work"].get<double>());
}

TEST(DynamicsLoadCli, EveryBadLoadNamed) {
  std::string text = with_guide_key(example(), 0, "load_per_metre = \"-1 kg/m\"");
  text = with_guide_key(text, 1, "load_per_metre = \"3 kg/m\"");  // the upper rail's lead-in arc
  text = with_guide_key(text, 2, "load_per_metre = \"2e4 kg/m\"");
  text = with_guide_key(text, 3, "load_per_metre = \"4 m\"");
  const CliRun r = run("dynamics " + write("bad.toml", text));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  for (const char* field :
       {"dynamics.guide[0].load_per_metre (line", "dynamics.guide[1].load_per_metre (line",
        "dynamics.guide[2].load_per_metre (line", "dynamics.guide[3].load_per_metre"})
    EXPECT_NE(r.err.find(field), std::string::npos) << field << "\n" << r.err;
  EXPECT_NE(r.err.find("a straight guide"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[0, 10000] kg/m"), std::string::npos) << r.err;

  std::string weightless = example();
  const std::string gravity = "gravity = true";
  weightless.replace(weightless.find(gravity), gravity.size(), "gravity = false");
  const CliRun w = run(
      "dynamics " + write("weightless.toml", with_guide_key(weightless, 0, "load_per_metre = 2")));
  EXPECT_EQ(w.status, 2);
  EXPECT_NE(w.err.find("dynamics.guide[0].load_per_metre"), std::string::npos) << w.err;
  EXPECT_NE(w.err.find("without gravity"), std::string::npos) << w.err;
}

}  // namespace
