#include "catena/contact/roller_tooth.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>
#include <numbers>
#include <numeric>
#include <random>

namespace catena::contact {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kArcmin = kPi / 10800.0;

// Tolerances
constexpr double kRelTol = 1e-9;           // [1] relative, loads and pressures by two formulas
constexpr double kRoundOffRelTol = 1e-12;  // [1] relative, round-off of a few operations
constexpr double kFactorTol = 1e-12;       // [1] load factors of order 1-5 by hand
constexpr double kHertzRelTol = 1e-6;      // [1] relative, the slice model's peak against Hertz
constexpr double kLengthTol = 1e-12;       // [m] loaded lengths of ~1e-2 m
// [1] relative: 201 slices against 3201; the peak is at the roller's end and the loaded length
// where the gap closes, so both converge fast
constexpr double kMeshRelTol = 1e-4;

// 12B-like roller on a concave flank, steel on steel.
RollerTooth example(Profile profile = Profile::kConcave) {
  RollerTooth c;
  c.roller_diameter = 12.07e-3;
  c.roller_length = 11.68e-3;
  c.tooth_radius = 15.56e-3;
  c.profile = profile;
  return c;
}

TEST(RollerTooth, PaperConstant0418IsHertzForSteelOnSteel) {
  // σ = √(P'E*/(πρ)) with E* = E/(2(1 − ν²)): √(1/(2π(1 − 0.09))) = 0.41820 for ν = 0.3.
  constexpr double kPrintedTol = 3e-4;     // [1] the paper prints 3 digits: 0.418 for 0.41820
  constexpr double kPrintedRelTol = 5e-4;  // [1] relative, the same 0.418/0.41820 = 1 − 4.9e-4
  EXPECT_NEAR(std::sqrt(1.0 / (2 * kPi * (1 - 0.09))), 0.418, kPrintedTol);
  const RollerTooth c = example();
  const double q = 1000.0;
  const double paper = paper_stress(q, 210e9, c.roller_length, reduced_radius(c));
  EXPECT_NEAR(paper / hertz(c, q).peak_pressure, 1.0, kPrintedRelTol);
}

TEST(RollerTooth, ReducedRadiusIsTheRelativeCurvature) {
  constexpr double kCurvatureTol = 1e-9;  // [1/m] curvatures of ~1e2 1/m: round-off
  const RollerTooth cc = example(Profile::kConcave), cv = example(Profile::kConvex);
  EXPECT_NEAR(1 / reduced_radius(cc), 2 / cc.roller_diameter - 1 / cc.tooth_radius, kCurvatureTol);
  EXPECT_NEAR(1 / reduced_radius(cv), 2 / cv.roller_diameter + 1 / cv.tooth_radius, kCurvatureTol);
}

TEST(RollerTooth, HertzPressureReproducesTheSurfaceCurvatureNumerically) {
  // Independent check of the closed form: the surface slope under the elliptical pressure of
  // the half-space (plane strain), du/dx = −(2/(πE*)) PV∫ p(s)/(x − s) ds, must equal −x/ρ
  // inside the contact. The principal value is taken by subtracting the singular part.
  // [1] relative to the slope scale b/ρ: Gauss-Kronrod to 1e-12 of a square-root integrand
  constexpr double kSlopeRelTol = 1e-6;
  const RollerTooth c = example();
  const HertzResult h = hertz(c, 2000.0);
  const double e_star = contact_modulus(c.roller, c.tooth), rho = reduced_radius(c),
               b = h.half_width;
  for (double xi : {-0.813, -0.291, 0.137, 0.533, 0.917}) {  // off the quadrature nodes
    auto p = [&](double t) { return h.peak_pressure * std::sqrt(std::max(0.0, 1 - t * t)); };
    const double regular = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
        [&](double t) { return (p(t) - p(xi)) / (xi - t); }, -1.0, 1.0, 12, 1e-12);
    const double pv =
        regular + p(xi) * std::log((1 + xi) / (1 - xi));  // ∫ dt/(x − t), x in units of b
    const double slope = -2.0 / (kPi * e_star) * pv;      // t and x scaled by b cancel
    EXPECT_NEAR(slope, -xi * b / rho, kSlopeRelTol * b / rho) << xi;
  }
}

TEST(RollerTooth, MaxShearDepthAndValueFromTheFlamantSolution) {
  // Stresses on the axis below the contact by integrating Flamant's point-load solution over the
  // Hertz pressure; the principal shear (σx − σz)/2 peaks at 0.786 b with 0.300 p0.
  // [1] relative: the depth of a flat maximum, found by a search over quadratures (the library's
  // 0.786 b is 2e-4 off the exact 0.78615 b)
  constexpr double kDepthRelTol = 3e-3;
  // [1] relative: the library's 0.300 p0 is 3 digits of the exact 0.30028 p0 (9.4e-4 off)
  constexpr double kPeakRelTol = 1e-3;
  const RollerTooth c = example();
  const HertzResult h = hertz(c, 2000.0);
  const double b = h.half_width, p0 = h.peak_pressure;
  auto shear = [&](double z) {
    auto p = [&](double s) { return p0 * std::sqrt(std::max(0.0, 1 - s * s / (b * b))); };
    auto integral = [&](auto f) {
      return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, -b, b, 12, 1e-12);
    };
    const double sz = -2 * z * z * z / kPi *
                      integral([&](double s) { return p(s) / std::pow(s * s + z * z, 2); });
    const double sx = -2 * z / kPi *
                      integral([&](double s) { return p(s) * s * s / std::pow(s * s + z * z, 2); });
    return -(sx - sz) / 2;  // minimised below: maximum of (σx − σz)/2 in magnitude
  };
  const auto [z, neg] = boost::math::tools::brent_find_minima(
      [&](double zz) { return -std::abs(shear(zz)); }, 0.2 * b, 2 * b, 40);
  EXPECT_NEAR(h.max_shear_depth / z, 1.0, kDepthRelTol);
  EXPECT_NEAR(h.max_shear / -neg, 1.0, kPeakRelTol);
  // and the pressure integrates to the load per length
  const double carried = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      [&](double s) { return p0 * std::sqrt(std::max(0.0, 1 - s * s / (b * b))); }, -b, b, 12,
      1e-12);
  EXPECT_NEAR(carried, 2000.0 / c.roller_length, kRelTol * carried);
}

TEST(RollerTooth, SkewLoadFactorOfThePaper) {
  constexpr double kPrintedArcminTol = 0.01;  // [arcmin] 41.96′, one unit of the 2nd decimal
  constexpr double kLargeFactorTol = 1e-9;    // [1] the factor 68.9 at 3°26′
  EXPECT_EQ(skew_gamma(19.05e-3).value(), 0.0016);
  EXPECT_EQ(skew_gamma(12.7e-3).value(), 0.0023);
  EXPECT_FALSE(skew_gamma(31.75e-3).has_value());  // no extrapolation
  EXPECT_NEAR(skew_from_gauge(0.155e-3, 12.7e-3) / kArcmin, 41.96, kPrintedArcminTol);  // ≈ 0°42′
  // 0 → 50′ for a 19.05 mm chain: Q_n/Q_nom = 1 + 0.0016·50² = 5, the stress × √5 = 2.24
  EXPECT_NEAR(load_factor(0.0016, 50 * kArcmin), 5.0, kFactorTol);
  // the measured range 0°42′…3°26′ (held to the doc's printed 3.82 … 68.9 in
  // contact_paper_test.cpp: ContactPaper.MeasuredSkewRangeGivesTheDocsLoadAndStressFactors)
  EXPECT_NEAR(load_factor(0.0016, 42 * kArcmin), 1 + 0.0016 * 42 * 42, kFactorTol);
  EXPECT_NEAR(load_factor(0.0016, 206 * kArcmin), 1 + 0.0016 * 206 * 206, kLargeFactorTol);
  EXPECT_NEAR(load_factor(0.0016, 50 * kArcmin, 0.65), 1 + 0.0016 * 32.5 * 32.5, kFactorTol);
}

TEST(SliceModel, AlignedRollerIsHertzAndLoadIsConserved) {
  constexpr double kLineLoadRelTol = 1e-8;  // [1] relative, the aligned roller's slice loads
  const RollerTooth c = example();
  const SliceResult aligned = slice_model(c, 3000.0, 0.0);
  for (double q : aligned.q) EXPECT_NEAR(q, 3000.0 / c.roller_length, kLineLoadRelTol * q);
  EXPECT_NEAR(aligned.stress_peak, hertz(c, 3000.0).peak_pressure,
              kHertzRelTol * aligned.stress_peak);
  EXPECT_NEAR(aligned.loaded_length, c.roller_length, kLengthTol);
  double previous_peak = aligned.stress_peak, previous_length = aligned.loaded_length;
  for (double arcmin : {5.0, 20.0, 42.0, 100.0, 206.0}) {
    const SliceResult r = slice_model(c, 3000.0, arcmin * kArcmin);
    EXPECT_NEAR(r.load_sum, 3000.0, kRelTol * 3000.0) << arcmin;
    EXPECT_GE(r.stress_peak, previous_peak);
    EXPECT_LE(r.loaded_length, previous_length + kLengthTol);
    EXPECT_GE(r.q.front(), r.q.back());  // the gap opens towards +s
    previous_peak = r.stress_peak;
    previous_length = r.loaded_length;
  }
}

TEST(SliceModel, PeakAndLoadedLengthConvergeWithTheMesh) {
  // The peak is evaluated at the roller's end and the loaded length where the gap closes, so
  // the default 201 slices agree with a 16× finer mesh to better than 1e-4, and the error falls
  // as the mesh is refined.
  const RollerTooth c = example();
  for (double arcmin : {10.0, 50.0, 206.0}) {
    const SliceResult fine = slice_model(c, 1000.0, arcmin * kArcmin, SliceOptions{3201});
    double previous_error = 1.0;
    for (int n : {51, 201, 801}) {
      const SliceResult r = slice_model(c, 1000.0, arcmin * kArcmin, SliceOptions{n});
      const double error = std::abs(r.stress_peak / fine.stress_peak - 1);
      EXPECT_LT(error, previous_error) << arcmin << "′, " << n << " slices";
      if (n >= 201) {
        EXPECT_LT(error, kMeshRelTol) << arcmin << "′";
        EXPECT_NEAR(r.loaded_length, fine.loaded_length, kMeshRelTol * c.roller_length) << arcmin;
      }
      previous_error = error;
    }
  }
}

TEST(SliceModel, ComplianceIsMonotone) {
  const RollerTooth c = example();
  double previous = 0.0;
  for (double q = 1e3; q < 1e7; q *= 1.5) {
    const double d = slice_approach(c, q);
    EXPECT_GT(d, previous);
    previous = d;
  }
}

TEST(SliceModel, RandomInputsStayFinite) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 60; ++i) {
    RollerTooth c = example(u(rng) < 0.5 ? Profile::kConcave : Profile::kConvex);
    c.roller_diameter = 5e-3 + 20e-3 * u(rng);
    c.tooth_radius = c.roller_diameter * (0.6 + 2 * u(rng));
    c.roller_length = 3e-3 + 20e-3 * u(rng);
    const double load = 100 + 1e4 * u(rng);
    const SliceResult r = slice_model(c, load, 240 * kArcmin * u(rng), SliceOptions{51});
    EXPECT_NEAR(r.load_sum, load, kRelTol * load);
    ASSERT_TRUE(std::isfinite(r.stress_peak) && std::isfinite(r.approach));
    EXPECT_GT(r.loaded_length, 0.0);
    EXPECT_LE(r.loaded_length, c.roller_length * (1 + kRoundOffRelTol));
    const double summed = std::accumulate(r.q.begin(), r.q.end(), 0.0) * c.roller_length / 51;
    EXPECT_NEAR(r.load_sum, summed, kRelTol * load);
    // skew only concentrates the load: never below the aligned Hertz stress
    EXPECT_GE(r.stress_peak, hertz(c, load).peak_pressure * (1 - kRelTol));
  }
}

TEST(RollerTooth, InvalidInputIsReported) {
  RollerTooth c = example();
  c.tooth_radius = 5e-3;  // concave flank tighter than the roller
  EXPECT_EQ(validate(c).size(), 1u);
  c.roller.poisson = 0.7;
  c.roller_length = -1;
  EXPECT_EQ(validate(c).size(), 2u);
  c = example();
  c.roller.modulus = c.tooth.modulus = -1;  // one bad constant shared by both: one problem
  ASSERT_EQ(validate(c).size(), 1u);
  EXPECT_EQ(validate(c)[0].field, "modulus");
  c = example();
  c.tooth.poisson = 0.5;
  ASSERT_EQ(validate(c).size(), 1u);
  EXPECT_EQ(validate(c)[0].field, "tooth_poisson");
  EXPECT_THROW(slice_model(example(), -1.0, 0.0), InputError);
}

}  // namespace
}  // namespace catena::contact
