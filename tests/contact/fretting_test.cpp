#include "catena/contact/fretting.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena::contact {
namespace {

constexpr double kTimeTol = 1e-9;  // [s] latent periods of ~6e2 s: round-off

Fretting example() { return {0.8e-6, 5e-6, 2000.0, 20.0, 1e9, -1e-6}; }

TEST(Fretting, Eq1HandValue) {
  // τ = K1·Ra·exp(K2·A·N·f/Ra) = 1e9·0.8e-6·exp(−1e-6·5e-6·2000·20/0.8e-6) = 800·e^(−0.25)
  EXPECT_NEAR(latent_period(example()), 800.0 * std::exp(-0.25), kTimeTol);
}

TEST(Fretting, LatentPeriodFallsWithAmplitudeLoadAndFrequency) {
  const double base = latent_period(example());
  Fretting f = example();
  f.amplitude *= 2;
  EXPECT_LT(latent_period(f), base);
  f = example();
  f.load *= 2;
  EXPECT_LT(latent_period(f), base);
  f = example();
  f.frequency *= 2;
  EXPECT_LT(latent_period(f), base);
}

TEST(Fretting, ANonNegativeK2IsRejected) {
  Fretting f = example();
  f.k2 = 1e-6;
  const auto issues = validate(f);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "k2");
  f.k2 = 0.0;
  EXPECT_THROW(latent_period(f), InputError);
  f = example();
  f.roughness = 0;
  f.k1 = -1;
  EXPECT_EQ(validate(f).size(), 2u);
}

}  // namespace
}  // namespace catena::contact
