// Properties of `drive select` through the registry (catena::run): the candidates sorted and
// sufficient, none left out. Those of `drive` over random drives are the slow program's
// (drive_random_test.cpp).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "catena/catena.hpp"
#include "catena/contact/chain_catalog.hpp"
#include "catena/drive/rating.hpp"
#include "drive_record.hpp"

namespace {

using catena::analysis::Record;
using catena::analysis::Value;
using catena::drive::testing::exact;
using catena::drive::testing::kRelTol;
using catena::drive::testing::num;

TEST(DriveProperties, SelectListsSufficientChainsSmallestPitchFirst) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> speed(50, 3000), power(0.5, 60);
  for (int trial = 0; trial < 10; ++trial) {
    const double n1 = speed(rng), kw = power(rng);
    const Record r = catena::run("drive_select", {{"power", exact(kw) + " kW"},
                                                  {"speed", exact(n1) + " rpm"},
                                                  {"ratio", "3"},
                                                  {"service_factor", "1.5"}});
    const Value& list = r.data.at("candidates");
    double previous_pitch = 0;
    int previous_strands = 0;
    for (const Value& c : list.as_array()) {
      EXPECT_GE(num(c, "margin"), 1.0);
      EXPECT_NEAR(num(c, "rated_power") / (kw * 1e3 * 1.5), num(c, "margin"), kRelTol);
      const double pitch = num(c, "pitch");
      const auto strands = static_cast<int>(c.at("strands").as_integer());
      EXPECT_TRUE(pitch > previous_pitch ||
                  (pitch == previous_pitch && strands > previous_strands));
      EXPECT_LE(strands, 3);
      previous_pitch = pitch;
      previous_strands = strands;
    }
    // none left out: every rated chain and strand count with margin ≥ 1 is listed
    std::size_t expected = 0;
    for (const std::string& name : catena::contact::iso606_names()) {
      const auto number = catena::drive::ansi_number(name);
      if (!number) continue;
      const auto chain = catena::contact::iso606_chain(name);
      for (int k = 1; k <= 3; ++k)
        expected += catena::drive::rate(*catena::drive::ansi_constants(*number), chain->pitch, 17,
                                        n1, k, kw * 1e3, 1.5)
                        .margin >= 1;
    }
    EXPECT_EQ(list.size(), expected);
  }
}

}  // namespace
