// Properties of `drive` over random drives through the registry (catena::run): no NaN, an even
// link count no shorter than the centre distance asks, the ratio, wrap angles that close the
// loop, the exact centre distance within the range it reports and near the formula, tensions
// and shaft loads consistent, the rating's margin. The 16 drives take about 0.7 s of CPU, most of
// it the exact polygon wrap's root searches (4 s, in the slow program, while each hull took every
// sprocket vertex's sine and cosine).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "catena/catena.hpp"
#include "drive_record.hpp"

namespace {

using catena::analysis::Record;
using catena::analysis::Value;
using catena::drive::testing::exact;
using catena::drive::testing::kRelTol;
using catena::drive::testing::num;

constexpr double kPi = std::numbers::pi;

TEST(DriveProperties, RandomDrives) {
  std::mt19937 rng(16);
  std::uniform_int_distribution<int> small(9, 40), extra(0, 80), chain(0, 1);
  std::uniform_real_distribution<double> pitches(25, 90), speed(20, 3000), power(0.2, 30);
  for (int trial = 0; trial < 16; ++trial) {
    const int z1 = small(rng), z2 = z1 + extra(rng);
    const std::string name = chain(rng) ? "08A" : "16A";
    const double p = name == "08A" ? 0.0127 : 0.0254;
    const double a = pitches(rng) * p, n1 = speed(rng), kw = power(rng);
    const Record r = catena::run("drive", {{"chain", name},
                                           {"teeth", std::to_string(z1) + "," + std::to_string(z2)},
                                           {"center_distance", exact(a) + " m"},
                                           {"speed", exact(n1) + " rpm"},
                                           {"power", exact(kw) + " kW"},
                                           {"service_factor", "1.3"},
                                           {"mass_per_metre", "0.7 kg/m"}});
    const Value& d = r.data;
    SCOPED_TRACE(name + " z " + std::to_string(z1) + "/" + std::to_string(z2) + " a " +
                 std::to_string(a) + " n1 " + std::to_string(n1));
    EXPECT_FALSE(d.has_non_finite());
    for (const auto& diag : r.diagnostics)
      EXPECT_NE(diag.code, "result.non_finite") << diag.message;
    const auto links = d.at("links").as_integer();
    EXPECT_EQ(links % 2, 0);
    EXPECT_GE(static_cast<double>(links), num(d, "links_exact"));
    EXPECT_LT(static_cast<double>(links), num(d, "links_exact") + 2);
    EXPECT_GE(num(d, "center_distance_formula"), a);  // more links, a longer centre distance
    EXPECT_NEAR(num(d, "speed_ratio"), static_cast<double>(z2) / z1, kRelTol);
    EXPECT_NEAR(num(d, "chain_length"), static_cast<double>(links) * p, kRelTol);
    const double c = num(d, "center_distance");
    EXPECT_NEAR(c, num(d.at("center_distance_range"), "min"), kRelTol * c);
    EXPECT_LE(c, num(d.at("center_distance_range"), "max"));
    EXPECT_LT(std::abs(c - num(d, "center_distance_formula")), 0.1 * p);
    const Value& wrap = d.at("wrap_angle");
    EXPECT_NEAR(num(wrap, "driver") + num(wrap, "driven"), 2 * kPi, kRelTol);
    EXPECT_LE(num(wrap, "driver"), kPi + kRelTol);
    const double v = num(d, "chain_speed");
    EXPECT_NEAR(v, z1 * p * n1 / 60, kRelTol * v);
    EXPECT_GT(num(d, "chordal_variation"), 0);
    EXPECT_LE(num(d, "chordal_variation"), 1 - std::cos(kPi / 9) + kRelTol);
    const Value& t = d.at("tension");
    EXPECT_NEAR(num(t, "centrifugal"), 0.7 * v * v, kRelTol * num(t, "centrifugal"));
    EXPECT_NEAR(num(t, "tight") - num(t, "slack"), kw * 1e3 / v, kRelTol * num(t, "tight"));
    const Value& s = d.at("shaft_load");
    EXPECT_NEAR(num(s, "driver"), num(s, "driven"), kRelTol * num(s, "driver"));
    EXPECT_NEAR(num(s, "driver"), kw * 1e3 / v, 1e-9 * num(s, "driver"));  // no sag tension
    const Value& g = d.at("rating");
    ASSERT_TRUE(g.is_object());
    EXPECT_NEAR(num(g, "design_power"), 1.3 * kw * 1e3, kRelTol * kw * 1e3);
    EXPECT_NEAR(num(g, "margin"), num(g, "rated_power") / num(g, "design_power"), kRelTol);
  }
}

}  // namespace
