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

TEST(Fretting, AmplitudeLoadAndFrequencyActOnlyThroughTheirProduct) {
  // Eq. (1) as printed: A, N and f enter only as the product A·N·f in the exponent, so
  // trading one against another at a constant product leaves τ unchanged, and ln τ falls
  // linearly in that product with the slope K2/Ra.
  constexpr double kLogSlopeRelTol = 1e-9;  // [1] relative, a slope from two evaluations
  const double base = latent_period(example());
  Fretting f = example();
  f.amplitude *= 4;
  f.load /= 2;
  f.frequency /= 2;
  EXPECT_NEAR(latent_period(f), base, kTimeTol);
  f = example();
  f.load *= 3;
  const Fretting e = example();
  const double slope = (std::log(latent_period(f)) - std::log(base)) /
                       (e.amplitude * e.frequency * (f.load - e.load));
  EXPECT_NEAR(slope, e.k2 / e.roughness, kLogSlopeRelTol * std::abs(e.k2 / e.roughness));
}

TEST(Fretting, LatentPeriodGrowsWithRoughness) {
  // A consequence of eq. (1) the paper does not state: with K2 < 0, τ = K1·Ra·exp(c/Ra),
  // c = K2·A·N·f < 0, has dτ/dRa = K1·exp(c/Ra)·(1 − c/Ra) > 0 — a rougher fit lasts longer
  // for any Ra. Checked over three decades of Ra.
  double previous = 0.0;
  for (double ra = 0.05e-6; ra < 50e-6; ra *= 1.25) {
    Fretting f = example();
    f.roughness = ra;
    const double tau = latent_period(f);
    EXPECT_GT(tau, previous) << ra;
    previous = tau;
  }
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
