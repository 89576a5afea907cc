// Strength checks of the roller and plates (seed 000 §1.5): hand-derived diagrams, the beam's
// calculus (dM/dz = Q, ∫Q = ΔM) against finite differences and quadrature, eq. (22) against the
// integral of the arc's projection, Hertz against core/hertz, properties over random inputs
// (equilibrium, no NaN, 1/load scaling of the safety factors) and error cases.
#include "catena/strength/strength.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <string>

#include "catena/core/hertz.hpp"

namespace {

using namespace catena::strength;
constexpr double kPi = std::numbers::pi;

// Tolerances. The hand formulas below and the library do the same few operations on loads of
// ~1e4 N, lengths of ~1e-2 m and stresses of ~1e8 Pa, so they agree to round-off; the numerical
// checks (finite differences, quadrature, dense sampling) get the size of their own error.
constexpr double kForceTol = 1e-9;         // [N] plate forces, shears, ΣF of ~1e4 N: round-off
constexpr double kResultantTol = 1e-6;     // [N] |N| of ~3e4 N through a square root
constexpr double kMomentTol = 1e-9;        // [N·m] bending moments, ΣM of ~1e2 N·m: round-off
constexpr double kStartMomentTol = 1e-12;  // [N·m] M at the roller's first end: zero but round-off
constexpr double kLengthTol = 1e-12;       // [m] positions and contact widths of ~1e-2 m
constexpr double kExactLengthTol = 1e-15;  // [m] ~1e-2 m from one closed formula: round-off
constexpr double kStressTol = 1e-3;        // [Pa] hand formulas for stresses of ~1e8 Pa
constexpr double kFineStressTol = 1e-6;    // [Pa] the same stress or limit by the same formula
constexpr double kCopiedStressTol = 1e-9;  // [Pa] below one ulp of ~6e7 Pa: the value is copied
constexpr double kRatioTol = 1e-12;        // [1] safety factors, quotients of the same numbers
constexpr double kRelTol = 1e-9;           // [1] relative, closed formulas against each other
constexpr double kHertzRelTol = 1e-6;      // [1] relative, Hertz pressures written out by hand
// [N] central difference of M with h = 1 µm against Q: O(h²) truncation and round-off of M/h
constexpr double kFiniteDifferenceTol = 1e-3;
// [N·m] composite Simpson rule with 20000 intervals over Q, which has kinks at the plates' edges
constexpr double kQuadratureTol = 1e-3;
constexpr double kSamplingRelTol = 1e-6;  // [1] a dense grid misses |M|'s peak by O(h²)
// [1] the grid misses |Q|'s peak, which sits at a jump or a kink, by O(h)
constexpr double kShearSamplingRelTol = 1e-3;
constexpr double kShearSamplingTol = 1e-6;  // [N] absolute floor under kShearSamplingRelTol
// [1] per γ² in the relative chord error γ²/24: the next term of the series is ~γ⁴/1920
constexpr double kSeriesTol = 1e-3;

// A t = 125 mm class hinge: 8 mm plates, inner plates 40 mm apart (the built-in case's warp).
Input example() {
  Input in;
  in.hinge.heights = {0.0, 0.008, 0.048, 0.056};
  in.hinge.widths = {0.008, 0.008, 0.008, 0.008};
  in.hinge.pin_diameter = 0.040;
  in.hinge.plate_width = 0.090;
  in.hinge.end_distance = 0.045;
  in.loads = {30e3, 0.0, 0.0, 0.028, 0.0};  // S, S2 = 0 (N = S), θ = 0, L1, point load
  in.material = {600e6, 400e6, 0.0, 60e6, 1600e6, 1.5};
  return in;
}

const Check& find(const Result& r, const std::string& name, int layout = 0) {
  for (const Check& c : r.checks)
    if (c.name == name &&
        (layout == 0 || c.section.rfind("layout " + std::to_string(layout), 0) == 0))
      return c;
  throw std::runtime_error("no check " + name);
}

TEST(Strength, SymmetricLayoutOneMomentByHand) {
  // Layout 1, N = S at mid-height: the outer plates pull S/2 each, the tooth pushes S at
  // z = 28 mm, the inner (seated) plates carry S − N = 0. By hand: M(28 mm) = S/2 · 28 mm.
  const Input in = example();
  const LayoutLoads l = layout_loads(in, 1);
  EXPECT_DOUBLE_EQ(l.plate_force[kLowerOuter], 15e3);
  EXPECT_DOUBLE_EQ(l.plate_force[kUpperOuter], 15e3);
  EXPECT_NEAR(l.plate_force[kLowerInner], 0.0, kForceTol);
  EXPECT_NEAR(l.plate_force[kUpperInner], 0.0, kForceTol);
  const Beam b = beam(in, l);
  EXPECT_NEAR(moment(b, 0.028), 15e3 * 0.028, kMomentTol);
  // inside the lower outer plate (uniform over [-4, 4] mm): M(2 mm) = (S/2)/8 mm · (6 mm)²/2
  EXPECT_NEAR(moment(b, 0.002), 15e3 / 0.008 * 0.5 * 0.006 * 0.006, kMomentTol);
  EXPECT_NEAR(shear(b, 0.020), 15e3, kForceTol);
  EXPECT_NEAR(shear(b, 0.028, false), 15e3, kForceTol);
  EXPECT_NEAR(shear(b, 0.028, true), -15e3, kForceTol);
  const Extremes e = extremes(b);
  EXPECT_NEAR(e.moment, 420.0, kMomentTol);
  EXPECT_NEAR(e.moment_at, 0.028, kLengthTol);
  EXPECT_NEAR(e.shear, 15e3, kForceTol);
  // σ = M/W, W = π d³/32
  const Result r = assess(in);
  EXPECT_NEAR(find(r, "roller.bending", 1).stress, 420.0 / (kPi * 0.04 * 0.04 * 0.04 / 32.0),
              kStressTol);
  EXPECT_NEAR(find(r, "roller.shear", 1).stress, 4.0 / 3.0 * 15e3 / (kPi * 0.04 * 0.04 / 4.0),
              kStressTol);
}

TEST(Strength, SymmetricLayoutTwoAndStraightRunByHand) {
  Input in = example();
  // layout 2: S enters through the inner plates (z = 8, 48 mm): M(28 mm) = S/2 · 20 mm
  EXPECT_NEAR(extremes(beam(in, layout_loads(in, 2))).moment, 15e3 * 0.020, kMomentTol);
  // a straight run (N = 0): S/2 in at the outer plates, S/2 out at the inner ones; between the
  // inner plates the moment is constant S/2 · 8 mm and the shear zero
  in.loads.exit_tension = 30e3;  // N = 0
  const Beam b = beam(in, layout_loads(in, 1));
  for (double z : {0.013, 0.028, 0.040}) {
    EXPECT_NEAR(moment(b, z), 15e3 * 0.008, kMomentTol) << z;
    EXPECT_NEAR(shear(b, z), 0.0, kForceTol) << z;
  }
  EXPECT_NEAR(extremes(b).moment, 120.0, kMomentTol);
}

TEST(Strength, OffCentreToothReactionsByStatics) {
  Input in = example();
  in.loads.exit_tension = 10e3;  // N = 20 kN
  in.loads.load_height = 0.036;
  for (int layout : {1, 2}) {
    const LayoutLoads l = layout_loads(in, layout);
    // the applied loads (S, N) and the seated plates' reactions: ΣF = 0, ΣM = 0
    double f = l.tooth.force, m = l.tooth.force * in.loads.load_height;
    for (std::size_t i = 0; i < 4; ++i) {
      f += l.plate_force[i];
      m += l.plate_force[i] * in.hinge.heights[i];
    }
    EXPECT_NEAR(f, 0.0, kForceTol);
    EXPECT_NEAR(m, 0.0, kMomentTol);
    const auto [a, bb] =
        layout == 1 ? std::pair{kLowerInner, kUpperInner} : std::pair{kLowerOuter, kUpperOuter};
    EXPECT_NEAR(l.plate_force[a] + l.plate_force[bb], -in.loads.exit_tension, kForceTol);
  }
}

TEST(Strength, MomentDerivativeIsShearAndShearIntegratesToMoment) {
  Input in = example();
  in.loads = {30e3, 6e3, 0.0, 0.031, 0.010};  // N = 24 kN over 10 mm
  for (int layout : {1, 2}) {
    const Beam b = beam(in, layout_loads(in, layout));
    // finite differences of M (central, h = 1 µm) against Q, away from block boundaries
    for (double z = b.start + 0.5e-3; z < b.stop; z += 1.3e-3) {
      const double h = 1e-6;
      EXPECT_NEAR((moment(b, z + h) - moment(b, z - h)) / (2 * h), shear(b, z),
                  kFiniteDifferenceTol)
          << z;
    }
    // ∫Q dz by the composite Simpson rule over the whole roller (Q is piecewise linear and
    // continuous for distributed loads): the jump of M from end to end, which is zero, and over
    // a part of it, M(z2) − M(z1)
    auto integral = [&](double z1, double z2) {
      const int n = 20000;
      const double h = (z2 - z1) / n;
      double s = shear(b, z1) + shear(b, z2);
      for (int i = 1; i < n; ++i) s += shear(b, z1 + i * h) * (i % 2 ? 4 : 2);
      return s * h / 3;
    };
    EXPECT_NEAR(integral(b.start, 0.030), moment(b, 0.030) - moment(b, b.start), kQuadratureTol);
    EXPECT_NEAR(integral(0.003, 0.053), moment(b, 0.053) - moment(b, 0.003), kQuadratureTol);
    EXPECT_NEAR(integral(b.start, b.stop), 0.0, kQuadratureTol);
    EXPECT_NEAR(moment(b, b.start), 0.0, kStartMomentTol);
    EXPECT_NEAR(moment(b, b.stop), 0.0, kMomentTol);
    EXPECT_NEAR(shear(b, b.stop), 0.0, kForceTol);
  }
}

TEST(Strength, ExtremesAgreeWithDenseSampling) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    Input in = example();
    in.loads.exit_tension = in.loads.tension * u(rng);
    in.loads.tooth_width = 0.03 * u(rng);
    const double lo = 0.012 + 0.5 * in.loads.tooth_width, hi = 0.044 - 0.5 * in.loads.tooth_width;
    in.loads.load_height = lo + (hi - lo) * u(rng);
    for (int layout : {1, 2}) {
      const Beam b = beam(in, layout_loads(in, layout));
      const Extremes e = extremes(b);
      double m = 0.0, q = 0.0;
      for (int i = 0; i <= 200000; ++i) {
        const double z = b.start + (b.stop - b.start) * i / 200000.0;
        m = std::max(m, std::abs(moment(b, z)));
        q = std::max(q, std::abs(shear(b, z)));
      }
      EXPECT_GE(e.moment, m - kMomentTol);
      EXPECT_NEAR(e.moment, m, kSamplingRelTol * e.moment);  // the grid can miss the peak by O(h²)
      EXPECT_GE(e.shear, q - kForceTol);
      EXPECT_NEAR(e.shear, q, kShearSamplingRelTol * e.shear + kShearSamplingTol);
    }
  }
}

TEST(Strength, DiagramHoldsTheJumpAtAPointLoad) {
  const Input in = example();  // the tooth is a point load at 28 mm
  const Diagram d = diagram(beam(in, layout_loads(in, 1)));
  ASSERT_EQ(d.x.size(), d.moment.size());
  ASSERT_EQ(d.x.size(), d.shear.size());
  int jumps = 0;
  for (std::size_t i = 0; i + 1 < d.x.size(); ++i) {
    EXPECT_LE(d.x[i], d.x[i + 1]);
    if (d.x[i] == d.x[i + 1]) {
      ++jumps;
      EXPECT_NEAR(d.x[i], 0.028, kExactLengthTol);
      EXPECT_NEAR(d.shear[i] - d.shear[i + 1], 30e3, kForceTol);  // Q drops by N
    }
  }
  EXPECT_EQ(jumps, 1);
  EXPECT_NEAR(d.moment.front(), 0.0, kStartMomentTol);
  EXPECT_NEAR(d.moment.back(), 0.0, kMomentTol);
}

TEST(Strength, ProjectionIsTheIntegralOfTheArcAndTendsToItsLength) {
  // eq. (22): the arc r·θ, θ ∈ [−γ/2, γ/2], projected on the plane normal to N is ∫ r cos θ dθ
  for (double gamma : {0.01, 0.3, 1.0, 2.0, kPi}) {
    const double r = 0.02;
    const int n = 10000;
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += r * std::cos(-gamma / 2 + gamma * (i + 0.5) / n) * gamma / n;
    // the midpoint rule's error bound: r γ³/(24 n²)
    EXPECT_NEAR(projection(r, gamma), s,
                r * gamma * gamma * gamma / (24.0 * n * n) + kExactLengthTol)
        << gamma;
  }
  EXPECT_NEAR(projection(0.02, kPi), 0.04, kExactLengthTol);  // the half-embraced pin: c = d
  // small γ: the chord tends to the arc length r·γ, the error ~ r γ³/24
  for (double gamma : {0.1, 0.01, 0.001}) {
    const double rel = 1.0 - projection(1.0, gamma) / gamma;
    EXPECT_NEAR(rel, gamma * gamma / 24.0, kSeriesTol * gamma * gamma) << gamma;
  }
}

TEST(Strength, ShearFactorMatchesJourawskiOnTheNeutralAxis) {
  // τ = Q·S/(I·t) at the neutral axis of an annulus: S = (2/3)(ro³ − ri³), I = π(ro⁴ − ri⁴)/4,
  // t = 2(ro − ri); compared with k·Q/A
  for (double ri : {0.0, 0.002, 0.01, 0.019}) {
    const double ro = 0.02;
    const double tau = (2.0 / 3.0) * (ro * ro * ro - ri * ri * ri) /
                       (kPi * (ro * ro * ro * ro - ri * ri * ri * ri) / 4.0 * 2.0 * (ro - ri));
    const double a = kPi * (ro * ro - ri * ri);
    EXPECT_NEAR(shear_factor(2 * ro, 2 * ri) / a, tau, kRelTol * tau) << ri;
  }
  EXPECT_DOUBLE_EQ(shear_factor(0.04, 0.0), 4.0 / 3.0);
}

TEST(Strength, SlidingContactIsEquation23) {
  Input in = example();
  in.hinge.contact_angle = 2.0;
  const Result r = assess(in);
  // most loaded plate: 15 kN on 8 mm; c = d sin(1), p = N/(c B)
  EXPECT_NEAR(r.contact.force, 15e3, kForceTol);
  EXPECT_NEAR(r.contact.c, 0.04 * std::sin(1.0), kExactLengthTol);
  EXPECT_NEAR(r.contact.p, 15e3 / (0.04 * std::sin(1.0) * 0.008), kStressTol);
  EXPECT_FALSE(r.contact.hertz);
  EXPECT_NEAR(find(r, "hinge.pressure").stress, r.contact.p, kCopiedStressTol);
}

TEST(Strength, RollingContactIsHertzAndEquation23IsItsMean) {
  Input in = example();
  in.hinge.kind = HingeKind::kRolling;
  in.hinge.r1 = 0.034;
  in.hinge.r2 = 0.0354;
  const Result r = assess(in);
  ASSERT_TRUE(r.contact.hertz);
  // against core/hertz and against Johnson's formulas written out here
  const catena::Elastic steel{210e9, 0.3};
  const double rstar = 0.034 * 0.0354 / (0.0354 - 0.034);
  const double estar = 210e9 / (2 * (1 - 0.09));
  const double load = 15e3 / 0.008;
  const auto lc = catena::line_contact(load, catena::conformal_radius(0.034, 0.0354),
                                       catena::contact_modulus(steel, steel));
  EXPECT_NEAR(r.contact.peak, lc.peak_pressure, kFineStressTol);
  EXPECT_NEAR(r.contact.peak, std::sqrt(load * estar / (kPi * rstar)),
              kHertzRelTol * r.contact.peak);
  EXPECT_NEAR(r.contact.half_width, std::sqrt(4 * load * rstar / (kPi * estar)), kLengthTol);
  // (22) on the Hertz arc: c = 2b; (23): p = N/(2bB) = π/4 p0, the mean pressure
  EXPECT_NEAR(r.contact.c, 2 * r.contact.half_width, kLengthTol);
  EXPECT_NEAR(r.contact.p, kPi / 4 * r.contact.peak, kHertzRelTol * r.contact.peak);
  EXPECT_NEAR(find(r, "hinge.contact").stress, r.contact.peak, kFineStressTol);
}

TEST(Strength, PlateSectionsByHand) {
  Input in = example();
  in.hinge.stress_concentration = 2.0;
  in.hinge.hole_diameter = 0.041;
  in.material.plate_ultimate = 700e6;
  const Result r = assess(in);
  // the largest plate force is S/2 = 15 kN on an 8 mm plate
  EXPECT_NEAR(find(r, "plate.tension").stress, 2.0 * 15e3 / ((0.090 - 0.041) * 0.008), kStressTol);
  EXPECT_NEAR(find(r, "plate.tension_ultimate").safety_factor,
              700e6 / find(r, "plate.tension").stress, kRatioTol);
  EXPECT_NEAR(find(r, "plate.shear_out").stress, 15e3 / (2 * (0.045 - 0.0205) * 0.008), kStressTol);
  EXPECT_NEAR(find(r, "plate.shear_out").allowable, 400e6 / std::sqrt(3.0), kStressTol);
  EXPECT_NEAR(find(r, "plate.bearing").stress, 15e3 / (0.041 * 0.008), kStressTol);
}

TEST(Strength, FailingChecksGetDiagnosticsWithTheLimit) {
  Input in = example();
  in.material.roller_yield = 80e6;  // σ_b = 66.8 MPa in layout 1: n = 1.2 < 1.5
  const Result r = assess(in);
  const Check& c = find(r, "roller.bending", 1);
  EXPECT_FALSE(c.ok);
  EXPECT_NEAR(c.safety_factor, 80e6 / c.stress, kRatioTol);
  int found = 0;
  for (const auto& d : r.diagnostics)
    if (d.code == "strength.roller.bending") {
      ++found;
      EXPECT_EQ(d.severity, catena::Diagnostic::Severity::kInfeasible);
      EXPECT_NEAR(d.limit, 80e6 / 1.5, kFineStressTol);
      EXPECT_GT(d.value, d.limit);
    }
  EXPECT_EQ(found, 1);  // layout 2 (σ = 47.7 MPa, n = 1.68) passes
  for (const Check& k : r.checks)
    if (k.ok) {
      for (const auto& d : r.diagnostics)
        EXPECT_FALSE(d.code == "strength." + k.name && d.value == k.stress) << k.name;
    }
}

TEST(Strength, PropertyRandomInputs) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    Input in = example();
    double z = 0.0;
    for (std::size_t i = 0; i < 4; ++i) {
      in.hinge.widths[i] = 0.002 + 0.02 * u(rng);
      const double gap = i == 2 ? 0.005 + 0.1 * u(rng) : 0.01 * u(rng);
      z += (i == 0 ? 0.0 : 0.5 * in.hinge.widths[i - 1] + 0.5 * in.hinge.widths[i] + gap);
      in.hinge.heights[i] = z - 0.05;
    }
    in.hinge.kind = u(rng) < 0.5 ? HingeKind::kSliding : HingeKind::kRolling;
    in.hinge.pin_diameter = 0.005 + 0.06 * u(rng);
    in.hinge.bore = u(rng) < 0.5 ? 0.0 : 0.9 * in.hinge.pin_diameter * u(rng);
    in.hinge.plate_width = in.hinge.pin_diameter * (1.2 + 2 * u(rng));
    in.hinge.end_distance = in.hinge.pin_diameter * (0.6 + u(rng));
    in.hinge.r1 = 0.005 + 0.05 * u(rng);
    in.hinge.r2 = in.hinge.r1 * (1.001 + 0.5 * u(rng));
    in.hinge.contact_angle = kPi * (0.01 + 0.99 * u(rng));
    in.loads.tension = std::pow(10.0, 2 + 4 * u(rng));
    in.loads.exit_tension = in.loads.tension * u(rng);
    in.loads.link_angle = u(rng) < 0.5 ? 0.0 : 3.1 * u(rng);
    const double glo = in.hinge.heights[1] + 0.5 * in.hinge.widths[1];
    const double ghi = in.hinge.heights[2] - 0.5 * in.hinge.widths[2];
    in.loads.tooth_width = (ghi - glo) * u(rng);
    in.loads.load_height =
        glo + 0.5 * in.loads.tooth_width + (ghi - glo - in.loads.tooth_width) * u(rng);
    ASSERT_TRUE(validate(in).empty()) << trial;
    const Result r = assess(in);
    const double scale = in.loads.tension;
    const double arm = in.hinge.heights[3] - in.hinge.heights[0] + in.hinge.widths[3];
    for (const LayoutResult& lr : r.layouts) {
      EXPECT_LE(lr.force_residual, kRelTol * scale) << trial;
      EXPECT_LE(lr.moment_residual, kRelTol * scale * (arm + 0.05)) << trial;
      for (int component : {0, 1}) {
        const Beam b = beam(in, lr.loads, component);
        EXPECT_LE(std::abs(moment(b, b.stop)), kRelTol * scale * arm) << trial;
        EXPECT_LE(std::abs(shear(b, b.stop)), kRelTol * scale) << trial;
      }
      for (double v : lr.diagram.moment) ASSERT_TRUE(std::isfinite(v));
      for (double v : lr.diagram.shear) ASSERT_TRUE(std::isfinite(v));
    }
    for (const Check& c : r.checks) {
      ASSERT_TRUE(std::isfinite(c.stress)) << c.name;
      ASSERT_TRUE(c.safety_factor > 0) << c.name;
    }
    // doubling the loads halves every safety factor (Hertz: by √2)
    Input twice = in;
    twice.loads.tension *= 2;
    twice.loads.exit_tension *= 2;
    const Result r2 = assess(twice);
    ASSERT_EQ(r2.checks.size(), r.checks.size());
    for (std::size_t i = 0; i < r.checks.size(); ++i) {
      if (!std::isfinite(r.checks[i].safety_factor)) continue;
      const double ratio = r.checks[i].name == "hinge.contact" ? std::sqrt(2.0) : 2.0;
      EXPECT_NEAR(r.checks[i].safety_factor / r2.checks[i].safety_factor, ratio, kRelTol * ratio)
          << r.checks[i].name << " " << trial;
    }
  }
}

TEST(Strength, PlanarLinksBalanceAndTheResultantByHand) {
  // the seated link pulls at θ = 60°: N = −(S x̂ + S2 û), |N|² = S² + S2² − 2 S S2 cos θ
  Input in = example();
  in.loads.exit_tension = 12.7e3;
  in.loads.link_angle = kPi / 3;
  const auto n = tooth_force(in.loads);
  EXPECT_NEAR(std::hypot(n[0], n[1]),
              std::sqrt(30e3 * 30e3 + 12.7e3 * 12.7e3 - 2 * 30e3 * 12.7e3 * 0.5), kResultantTol);
  const LayoutLoads l = layout_loads(in, 1);
  // symmetric, tooth at mid-height: each seated (inner) plate pulls S2/2 along û
  EXPECT_NEAR(l.plate_force[kLowerInner], -0.5 * 12.7e3 * 0.5, kForceTol);
  EXPECT_NEAR(l.plate_force_y[kUpperInner], 0.5 * 12.7e3 * std::sin(kPi / 3), kForceTol);
  const Beam bx = beam(in, l, 0), by = beam(in, l, 1);
  // M at the tooth: S/2 x̂ at 28 mm arm and S2/2 û at 20 mm arm
  const double mx = 15e3 * 0.028 - 0.5 * 12.7e3 * 0.5 * 0.020;
  const double my = 0.5 * 12.7e3 * std::sin(kPi / 3) * 0.020;
  EXPECT_NEAR(moment(bx, 0.028), mx, kMomentTol);
  EXPECT_NEAR(moment(by, 0.028), my, kMomentTol);
  // the resultant's maximum against dense sampling
  const Extremes e = extremes(bx, by);
  double m = 0, q = 0;
  for (int i = 0; i <= 200000; ++i) {
    const double z = bx.start + (bx.stop - bx.start) * i / 200000.0;
    m = std::max(m, std::hypot(moment(bx, z), moment(by, z)));
    q = std::max(q, std::hypot(shear(bx, z), shear(by, z)));
  }
  EXPECT_NEAR(e.moment, m, kSamplingRelTol * m);
  EXPECT_GE(e.moment, std::hypot(mx, my) - kMomentTol);
  EXPECT_NEAR(e.shear, q, kShearSamplingRelTol * q);
  const Result r = assess(in);
  ASSERT_TRUE(r.layouts[0].planar);
  EXPECT_NEAR(find(r, "roller.bending", 1).stress, e.moment / (kPi * 0.04 * 0.04 * 0.04 / 32.0),
              kFineStressTol);
  EXPECT_EQ(r.layouts[0].diagram.moment_y.size(), r.layouts[0].diagram.x.size());
}

TEST(Strength, PlanarExtremesAgreeWithDenseSampling) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    Input in = example();
    in.loads.exit_tension = in.loads.tension * u(rng);
    in.loads.link_angle = 3.1 * u(rng);
    in.loads.tooth_width = 0.03 * u(rng);
    const double lo = 0.012 + 0.5 * in.loads.tooth_width, hi = 0.044 - 0.5 * in.loads.tooth_width;
    in.loads.load_height = lo + (hi - lo) * u(rng);
    for (int layout : {1, 2}) {
      const LayoutLoads l = layout_loads(in, layout);
      const Beam bx = beam(in, l, 0), by = beam(in, l, 1);
      const Extremes e = extremes(bx, by);
      double m = 0.0;
      for (int i = 0; i <= 100000; ++i) {
        const double z = bx.start + (bx.stop - bx.start) * i / 100000.0;
        m = std::max(m, std::hypot(moment(bx, z), moment(by, z)));
      }
      EXPECT_GE(e.moment, m - kMomentTol) << trial;
      EXPECT_NEAR(e.moment, m, kSamplingRelTol * e.moment) << trial;
    }
  }
}

TEST(Strength, ValidateListsEveryProblem) {
  Input in = example();
  in.hinge.hole_diameter = 0.1;  // larger than the plate width 90 mm
  in.hinge.end_distance = 0.02;  // less than the hole radius
  in.hinge.widths[1] = 0.02;     // the lower inner plate overlaps the lower outer one
  in.hinge.bore = 0.05;          // larger than d
  in.loads.exit_tension = -1.0;  // negative
  in.loads.link_angle = 4.0;     // beyond 180°
  in.loads.load_height = 0.05;   // not between the inner plates
  in.material.roller_yield = -1;
  in.material.allowable_pressure = 0;  // a sliding hinge needs it
  in.material.required = NAN;
  const auto issues = validate(in);
  std::set<std::string> fields;
  for (const auto& i : issues) fields.insert(i.field);
  for (const char* f :
       {"hole_diameter", "end_distance", "heights", "bore", "exit_tension", "link_angle",
        "load_height", "roller_yield", "allowable_pressure", "safety_factor"})
    EXPECT_TRUE(fields.count(f)) << f;
  EXPECT_THROW(assess(in), catena::InputError);
  // the tooth pushes: S2 cos θ ≤ S
  Input pull = example();
  pull.loads.exit_tension = 40e3;
  const auto pi = validate(pull);
  ASSERT_EQ(pi.size(), 1u);
  EXPECT_EQ(pi[0].field, "exit_tension");
  pull.loads.link_angle = kPi / 2;  // now the tooth takes it sideways: valid
  EXPECT_TRUE(validate(pull).empty());
  // a rolling hinge needs R2 > R1 and [σ_H]
  Input roll = example();
  roll.hinge.kind = HingeKind::kRolling;
  roll.hinge.r1 = 0.034;
  roll.hinge.r2 = 0.030;
  const auto ri = validate(roll);
  std::set<std::string> rf;
  for (const auto& i : ri) rf.insert(i.field);
  EXPECT_TRUE(rf.count("roller_radius"));
  EXPECT_FALSE(rf.count("allowable_pressure"));
  roll.material.allowable_contact = 0;
  roll.hinge.r2 = 0.0354;
  const auto rc = validate(roll);
  ASSERT_EQ(rc.size(), 1u);
  EXPECT_EQ(rc[0].field, "allowable_contact");
}

}  // namespace
