#include "catena/core/hertz.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>
#include <numbers>

namespace catena {
namespace {

constexpr double kModulusTol = 1.0;   // [Pa] E* ≈ 1.15e11 Pa by hand: ~1e-11 relative
constexpr double kLengthTol = 1e-15;  // [m] the half-width b ≈ 3e-4 m by hand: round-off
constexpr double kRadiusTol = 1e-12;  // [m] the conformal radius R* ≈ 0.86 m by hand: round-off

TEST(Hertz, SteelOnSteelHandExample) {
  // E* = E / (2(1 − ν²)) = 210 GPa / 1.82 = 115.385 GPa; R* = 10 mm, P' = 1 MN/m:
  // p0 = √(P'E*/(πR*)) = 1.9164 GPa, b = 2P'/(π p0) = 0.33219 mm.
  const double e_star = contact_modulus(Elastic{}, Elastic{});
  EXPECT_NEAR(e_star, 210e9 / 1.82, kModulusTol);
  constexpr double kPrintedPressureTol = 1e5;  // [Pa] p0 = 1.9164 GPa: a unit of its last digit
  const LineContact c = line_contact(1e6, 0.01, e_star);
  EXPECT_NEAR(c.peak_pressure, 1.91643e9, kPrintedPressureTol);
  EXPECT_NEAR(c.half_width, 2 * 1e6 / (std::numbers::pi * c.peak_pressure), kLengthTol);
}

TEST(Hertz, EllipticPressureIntegratesToTheLoad) {
  // [1] relative: Gauss-Kronrod over a pressure with square-root zeros at both ends
  constexpr double kQuadratureRelTol = 1e-6;
  const LineContact c = line_contact(2.5e5, 0.035, 1.1e11);
  const double load = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      [&](double x) {
        return c.peak_pressure *
               std::sqrt(std::max(0.0, 1 - x * x / (c.half_width * c.half_width)));
      },
      -c.half_width, c.half_width, 10, 1e-12);
  EXPECT_NEAR(load, 2.5e5, 2.5e5 * kQuadratureRelTol);
}

TEST(Hertz, ConformalRadiusLimits) {
  EXPECT_DOUBLE_EQ(conformal_radius(0.034, std::numeric_limits<double>::infinity()), 0.034);
  EXPECT_DOUBLE_EQ(conformal_radius(0.034, 0.0), 0.034);
  EXPECT_NEAR(conformal_radius(0.034, 0.0354), 0.034 * 0.0354 / 0.0014, kRadiusTol);  // 859.7 mm
  EXPECT_GT(conformal_radius(0.034, 0.0341), 10.0);  // R2 → R1: conformal, R* → ∞
}

}  // namespace
}  // namespace catena
