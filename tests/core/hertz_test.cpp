#include "catena/core/hertz.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>
#include <numbers>

namespace catena {
namespace {

TEST(Hertz, SteelOnSteelHandExample) {
  // E* = E / (2(1 − ν²)) = 210 GPa / 1.82 = 115.385 GPa; R* = 10 mm, P' = 1 MN/m:
  // p0 = √(P'E*/(πR*)) = 1.9164 GPa, b = 2P'/(π p0) = 0.33219 mm.
  const double e_star = contact_modulus(Elastic{}, Elastic{});
  EXPECT_NEAR(e_star, 210e9 / 1.82, 1.0);
  const LineContact c = line_contact(1e6, 0.01, e_star);
  EXPECT_NEAR(c.peak_pressure, 1.91643e9, 1e5);
  EXPECT_NEAR(c.half_width, 2 * 1e6 / (std::numbers::pi * c.peak_pressure), 1e-15);
}

TEST(Hertz, EllipticPressureIntegratesToTheLoad) {
  const LineContact c = line_contact(2.5e5, 0.035, 1.1e11);
  const double load = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      [&](double x) {
        return c.peak_pressure *
               std::sqrt(std::max(0.0, 1 - x * x / (c.half_width * c.half_width)));
      },
      -c.half_width, c.half_width, 10, 1e-12);
  EXPECT_NEAR(load, 2.5e5, 2.5e5 * 1e-6);
}

TEST(Hertz, ConformalRadiusLimits) {
  EXPECT_DOUBLE_EQ(conformal_radius(0.034, std::numeric_limits<double>::infinity()), 0.034);
  EXPECT_DOUBLE_EQ(conformal_radius(0.034, 0.0), 0.034);
  EXPECT_NEAR(conformal_radius(0.034, 0.0354), 0.034 * 0.0354 / 0.0014, 1e-12);  // 859.7 mm
  EXPECT_GT(conformal_radius(0.034, 0.0341), 10.0);  // R2 → R1: conformal, R* → ∞
}

}  // namespace
}  // namespace catena
