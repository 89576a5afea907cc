// `catena dynamics` in a case file: the case's chain.type and dynamics.wheel agree (docs/models/
// dynamics.md, "Chain type and wheel"; docs/cli.md). A round-link chain without wheel = "pocket"
// and a roller chain with it are refused, naming dynamics.wheel and what it must be; the accepted
// combinations run; `catena dynamics FILE` on a file with only a [dynamics] table is unchanged,
// and --chain-type applies the same check on the command line; a whole case file's chain.type
// is checked by `catena dynamics` too.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kPocket = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_pocketwheel.toml";
const std::string kRoller = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_12B.toml";

// `example` with each line starting `from` replaced by `to` (an empty `to` drops the line), the
// run shortened to 10 ms; every replacement must hit.
std::string edited(const std::string& example, const std::string& name,
                   std::vector<std::pair<std::string, std::string>> edits) {
  std::string s = read_text(example);
  edits.push_back({"duration = ", "duration = \"0.01 s\""});
  for (const auto& [from, to] : edits) {
    const std::size_t at = s.find("\n" + from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) continue;
    const std::size_t end = s.find("\n", at + 1);
    s.replace(at + 1, end - at - (to.empty() ? 0 : 1), to);
  }
  const fs::path dir = fs::temp_directory_path() / "catena_dynamics_chain_type_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << s;
  return path.string();
}

bool has(const CliRun& r, const std::string& text) { return r.err.find(text) != std::string::npos; }

TEST(DynamicsChainTypeCli, RoundLinkWithoutPocketWheelIsRefusedNamingTheWheel) {
  const std::string file = edited(kPocket, "round_link_no_wheel.toml", {{"wheel = ", ""}});
  const CliRun r = run("run " + file);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(has(r,
                  "dynamics.wheel = (missing): expected \"pocket\" with chain.type = "
                  "\"round-link\""))
      << r.err;
}

TEST(DynamicsChainTypeCli, RoundLinkWithIso606WheelIsRefusedNamingTheWheel) {
  const std::string file =
      edited(kPocket, "round_link_iso606.toml", {{"wheel = ", "wheel = \"iso606\""}});
  const CliRun r = run("run " + file);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(has(r,
                  "dynamics.wheel (line 15) = 'iso606': expected \"pocket\" with chain.type = "
                  "\"round-link\""))
      << r.err;
}

TEST(DynamicsChainTypeCli, RollerChainWithPocketWheelIsRefusedNamingTheWheel) {
  // the pocket example's [dynamics] table as it is, under a roller chain's type
  const std::string file =
      edited(kPocket, "roller_pocket.toml", {{"type = ", "type = \"roller-iso606\""}});
  const CliRun r = run("run " + file);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(has(r,
                  "dynamics.wheel (line 15) = 'pocket': expected \"iso606\" or omitted with "
                  "chain.type = \"roller-iso606\""))
      << r.err;
  // the only problem: the table itself is a valid pocket-wheel table
  EXPECT_TRUE(has(r, "catena: invalid input:\n")) << r.err;
}

TEST(DynamicsChainTypeCli, CatalogueChainWithPocketWheelIsRefused) {
  // chain = "12B" names a roller chain: with wheel = "pocket" the catalogue key is refused
  const std::string file =
      edited(kRoller, "catalogue_pocket.toml", {{"links = ", "links = 32\nwheel = \"pocket\""}});
  const CliRun r = run("run " + file);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(has(r, "dynamics.chain (line 13) = '12B': expected no chain with wheel = \"pocket\""))
      << r.err;
  EXPECT_TRUE(has(r,
                  "dynamics.wheel (line 15) = 'pocket': expected \"iso606\" or omitted with "
                  "chain.type = \"roller-iso606\""))
      << r.err;
}

TEST(DynamicsChainTypeCli, AcceptedCombinationsRun) {
  // round-link + pocket (the example); roller-iso606 + the default wheel; + wheel = "iso606"
  for (const std::string& file :
       {edited(kPocket, "round_link_pocket.toml", {}), edited(kRoller, "roller_default.toml", {}),
        edited(kRoller, "roller_iso606.toml", {{"links = ", "links = 32\nwheel = \"iso606\""}})}) {
    const CliRun r = run("run " + file);
    EXPECT_EQ(r.status, 0) << file << "\n" << r.err;
  }
}

TEST(DynamicsChainTypeCli, CommandLineReadsOnlyTheDynamicsTableUnlessTold) {
  // a file with only a [dynamics] table runs as before (no chain type: no check)
  const std::string file =
      edited(kPocket, "only_dynamics.toml",
             {{"[chain]", ""}, {"type = ", ""}, {"pitch = \"64", ""}, {"wire = ", ""}});
  const CliRun plain = run("dynamics " + file + " --format json");
  EXPECT_EQ(plain.status, 0) << plain.err;
  // --chain-type applies the case file's check on the command line
  const CliRun told = run("dynamics " + file + " --chain-type roller-iso606");
  EXPECT_EQ(told.status, 2) << told.err;
  EXPECT_TRUE(has(told, "dynamics.wheel (line 11) = 'pocket': expected \"iso606\" or omitted"))
      << told.err;
  const CliRun agrees = run("dynamics " + file + " --chain-type round-link --format json");
  EXPECT_EQ(agrees.status, 0) << agrees.err;
  // the same run (the wall-clock fields aside)
  const std::size_t from = plain.out.find("\"energy_drift\"");
  ASSERT_NE(from, std::string::npos);
  EXPECT_EQ(agrees.out.substr(agrees.out.find("\"energy_drift\"")), plain.out.substr(from));
  EXPECT_EQ(agrees.out.substr(0, agrees.out.find("\"wall_time\"")),
            plain.out.substr(0, plain.out.find("\"wall_time\"")));
}

TEST(DynamicsChainTypeCli, CommandLineReadsTheCaseFilesChainType) {
  // a whole case file: its chain.type is checked as `catena run` checks it
  const std::string roller_on_pocket =
      edited(kPocket, "roller_on_pocket.toml", {{"type = ", "type = \"roller-iso606\""}});
  const CliRun refused = run("dynamics " + roller_on_pocket);
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_TRUE(has(refused, "dynamics.wheel (line 15) = 'pocket': expected \"iso606\" or omitted"))
      << refused.err;
  EXPECT_EQ(refused.status, run("run " + roller_on_pocket).status);
  // a type the command does not take names chain.type and the types it takes
  const CliRun unknown = run(
      "dynamics " + edited(kPocket, "hinge_type.toml", {{"type = ", "type = \"rolling-hinge\""}}));
  EXPECT_EQ(unknown.status, 2) << unknown.err;
  EXPECT_TRUE(has(unknown,
                  "chain.type (line 10) = 'rolling-hinge': expected a chain type "
                  "'dynamics' takes: roller-iso606, round-link"))
      << unknown.err;
  // the flag wins over the file's type (the file's is then not read, even one not taken)
  const CliRun flag = run("dynamics " + roller_on_pocket + " --chain-type round-link");
  EXPECT_EQ(flag.status, 0) << flag.err;
  const CliRun over_unknown =
      run("dynamics " +
          edited(kPocket, "hinge_type_told.toml", {{"type = ", "type = \"rolling-hinge\""}}) +
          " --chain-type round-link");
  EXPECT_EQ(over_unknown.status, 0) << over_unknown.err;
  // the example itself (round-link on pocket wheels) runs
  EXPECT_EQ(run("dynamics " + edited(kPocket, "agrees.toml", {})).status, 0);
}

}  // namespace
