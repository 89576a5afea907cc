// `catena catalog`: list, show and search the ISO 606 catalogue.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

TEST(CatalogCli, ShowsOneChainPositionallyOrByFlag) {
  const CliRun r = run("catalog 12B --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["chain"], "12B");
  EXPECT_DOUBLE_EQ(j["pitch"].get<double>(), 19.05e-3);
  EXPECT_DOUBLE_EQ(j["roller_diameter"].get<double>(), 12.07e-3);
  EXPECT_DOUBLE_EQ(j["transverse_pitch"].get<double>(), 19.46e-3);
  EXPECT_DOUBLE_EQ(j["mass_per_metre"].get<double>(), 1.244);
  EXPECT_EQ(j["units"]["mass_per_metre"], "kg/m");
  EXPECT_NE(j["source"].get<std::string>().find("GALAXY_BS"), std::string::npos);
  const CliRun flag = run("catalog --chain 12b --format json");  // case-insensitive
  ASSERT_EQ(flag.status, 0) << flag.err;
  EXPECT_EQ(nlohmann::json::parse(flag.out), j);
  // a cell no source gives is null, not a number
  const auto a08 = nlohmann::json::parse(run("catalog 08A --format json").out);
  EXPECT_TRUE(a08["transverse_pitch"].is_null());
  // the link's axial stiffness: the A rows' (12 k lbf / p from the source's k, README
  // CALCULATORS_K: 12A 38794.33465), null on a B row
  EXPECT_TRUE(j.at("axial_stiffness").is_null());
  const auto a12 = nlohmann::json::parse(run("catalog 12A --format json").out);
  EXPECT_NEAR(a12.at("axial_stiffness").get<double>(), 12 * 38794.33465 * 4.4482216152605 / 0.01905,
              1.0);
  EXPECT_EQ(a12["units"]["axial_stiffness"], "N/m");
  EXPECT_NE(a12["source"].get<std::string>().find("CALCULATORS_K"), std::string::npos);
}

TEST(CatalogCli, ListsAndSearches) {
  const CliRun all = run("catalog --format json");
  ASSERT_EQ(all.status, 0) << all.err;
  const auto j = nlohmann::json::parse(all.out);
  EXPECT_EQ(j["chains"].size(), 18u);
  const auto b = nlohmann::json::parse(run("catalog --search b --format json").out);
  EXPECT_EQ(b["chains"].size(), 10u);  // 05B … 32B
  for (const auto& c : b["chains"]) EXPECT_EQ(c["chain"].get<std::string>().back(), 'B');
  const CliRun table = run("catalog");
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("19.46"), std::string::npos);
  EXPECT_NE(table.out.find("—"), std::string::npos);  // an empty cell
  const CliRun csv = run("catalog --search 12 --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("chain,pitch,roller_diameter", 0), 0u);
  EXPECT_NE(csv.out.find("\n12A,"), std::string::npos);
  EXPECT_NE(csv.out.find("\n12B,"), std::string::npos);
}

TEST(CatalogCli, UnknownChainListsTheCatalogue) {
  const CliRun r = run("catalog 99X");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--chain"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("32B"), std::string::npos) << r.err;
}

}  // namespace
