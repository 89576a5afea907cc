// Seed 003 (Dolipiński, Reich, Adamowicz, Ziegler, "Wymuszone nabieganie łańcucha ogniwowego na
// koło gniazdowe"): every printed formula, transcribed with only the OCR slips undone ('1' → l,
// '2'/'s' → z in angles, the factor ω restored in eqs. 1–4), held against the validated model
// (closed forms that agree with the independent numerical solver, tests/pocketwheel/). Each
// test states whether the printed formula holds, and where it does not, what is wrong.
// The paper's figures 2–3 are not in the text, so no curve values can be read from it; its
// example parameters and conclusions are checked instead. See docs/models/pocketwheel.md.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "catena/pocketwheel/run_on.hpp"
#include "catena/pocketwheel/run_on_numeric.hpp"

namespace catena::pocketwheel {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double t = 0.064;         // [m] chain Ø18×64
constexpr double d = 0.018;         // [m]
constexpr int z = 8;                // [-]
constexpr double w = 5.0;           // [1/s] ω
constexpr double l = 0.256;         // [m] guide end
constexpr double kAgreeTol = 1e-9;  // [m, m/s, m/s²] printed formula agrees with the model
constexpr double kDisagree = 1e-3;  // [m, m/s, m/s²] a printed formula is wrong if it deviates more
constexpr double kLengthTol = 1e-12;       // [m] R against the independent closure root
constexpr double kExactLengthTol = 1e-15;  // [m] lengths of ~0.1 m by the same formula: round-off
constexpr double kExactAngleTol = 1e-15;   // [rad] an event angle that is exactly π/z
constexpr double kSeatingTol = 1e-12;      // [rad] seating angles by eqs. (29), (34) and the model
constexpr double kQuotedDegreeTol = 0.01;  // [°] angles quoted here to 0.01°

const PocketWheel kWheel{t, d, z};
const WheelGeometry kG = wheel_geometry(kWheel);
const double R = kG.pitch_radius;
const double d1 = kG.delta1;
const double d2 = kG.delta2;
const double P = 2 * kPi / z;

using Fn = std::function<double(double)>;

// Largest |printed − model| over the open interval (a, b).
double deviation(const Fn& printed, const Fn& model, double a, double b) {
  double worst = 0.0;
  for (int i = 1; i < 200; ++i) {
    const double phi = a + (b - a) * i / 200.0;
    worst = std::max(worst, std::abs(printed(phi) - model(phi)));
  }
  return worst;
}

Fn model_x(const RunOnPlan& p) {
  return [&p](double phi) { return evaluate(p, phi).x; };
}
Fn model_v(const RunOnPlan& p) {
  return [&p](double phi) { return w * evaluate(p, phi).dx; };
}
Fn model_a(const RunOnPlan& p) {
  return [&p](double phi) { return w * w * evaluate(p, phi).d2x; };
}

// The same quantities from the independent numerical solver (tests/pocketwheel/ validates it).
constexpr double kNumericVelocityTol = 1e-9;  // [m/s] its fourth-order differences, step 1e-3 rad
constexpr double kNumericAccelTol = 1e-6;     // [m/s²] the same
Fn numeric_v(const numeric::NumericPlan& p) {
  return [&p](double phi) { return w * numeric::evaluate(p, phi).dx; };
}
Fn numeric_a(const numeric::NumericPlan& p) {
  return [&p](double phi) { return w * w * numeric::evaluate(p, phi).d2x; };
}

// The printed formula's worst deviation over (a, b) with its sign: printed − model where
// |printed − model| is largest, so a test can state both how much and which way it is off.
double signed_deviation(const Fn& printed, const Fn& model, double a, double b) {
  double worst = 0.0;
  for (int i = 1; i < 200; ++i) {
    const double phi = a + (b - a) * i / 200.0;
    const double e = printed(phi) - model(phi);
    if (std::abs(e) > std::abs(worst)) worst = e;
  }
  return worst;
}

// Deviations quoted in docs/models/pocketwheel.md to three significant digits.
constexpr double kQuotedRel = 5e-3;  // [-] relative tolerance of a quoted deviation
::testing::AssertionResult IsQuoted(double value, double quoted) {
  if (std::abs(value - quoted) <= kQuotedRel * std::abs(quoted))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << value << " is not the quoted " << quoted;
}

// Root of f on [a, b] (f(a), f(b) of opposite sign) by bisection to round-off.
double bisect(const Fn& f, double a, double b) {
  const bool fa_positive = f(a) > 0;
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    ((f(m) > 0) == fa_positive ? a : b) = m;
  }
  return 0.5 * (a + b);
}

TEST(Paper003, GeometryEqs6To9AndTransverseDisplacement) {
  // Eq. (6) printed with 's' for z; the closure root (numeric::pitch_radius) confirms it.
  constexpr double kQuotedRTol = 1e-10;            // [m] R written to 10 decimals of a metre
  constexpr double kAngleSumTol = 1e-14;           // [rad] δ1 + δ2 = 2π/z: round-off
  constexpr double kQuotedDisplacementTol = 1e-8;  // [m] 5.19842 mm, one unit of its last digit
  const double half = kPi / (2 * z);
  EXPECT_NEAR(R, 0.5 * std::sqrt(std::pow(t / std::sin(half), 2) + std::pow(d / std::cos(half), 2)),
              kExactLengthTol);
  EXPECT_NEAR(R, numeric::pitch_radius(kWheel), kLengthTol);
  EXPECT_NEAR(R, 0.1642830686, kQuotedRTol);  // the example: R = 164.283 mm
  EXPECT_NEAR(d1 + d2, P, kAngleSumTol);      // eq. (9)
  EXPECT_NEAR(kG.transverse_displacement, R * (1 - std::cos(d1 / 2)), kExactLengthTol);
  EXPECT_NEAR(kG.transverse_displacement, 5.19842e-3, kQuotedDisplacementTol);
}

TEST(Paper003, FreeRunOnEqs1To4And10To13HoldWithOmegaRestored) {
  const RunOnPlan p = plan_run_on(kWheel, Guide{});
  // (1)–(4) print V = R cos(...) without ω; their derivatives (10)–(13) carry ω², so V = ωR cos.
  const Fn v1 = [](double f) { return w * R * std::cos(d1 / 2 - f); };
  const Fn v2 = [](double f) { return w * R * std::cos(d2 + d1 / 2 - f); };
  const Fn vy3 = [](double f) { return w * R * std::sin(d1 / 2 - f); };
  const Fn vy4 = [](double f) { return w * R * std::sin(d2 + d1 / 2 - f); };
  const Fn p10 = [](double f) { return w * w * R * std::sin(d1 / 2 - f); };
  const Fn p11 = [](double f) { return w * w * R * std::sin(d2 + d1 / 2 - f); };
  const Fn p12 = [](double f) { return -w * w * R * std::cos(d1 / 2 - f); };
  const Fn p13 = [](double f) { return -w * w * R * std::cos(d2 + d1 / 2 - f); };
  const Fn vy = [&p](double f) { return w * evaluate(p, f).dy; };
  const Fn ay = [&p](double f) { return w * w * evaluate(p, f).d2y; };
  // The printed intervals [0, π/z], [π/z, 2π/z] are the geometric ones: the t − d link seats at
  // φ = π/z exactly (crank from +δ1/2 to −δ2/2).
  EXPECT_NEAR(p.seating_angles[1], kPi / z, kExactAngleTol);
  EXPECT_LT(deviation(v1, model_v(p), 0, P / 2), kAgreeTol);
  EXPECT_LT(deviation(v2, model_v(p), P / 2, P), kAgreeTol);
  EXPECT_LT(deviation(vy3, vy, 0, P / 2), kAgreeTol);
  EXPECT_LT(deviation(vy4, vy, P / 2, P), kAgreeTol);
  EXPECT_LT(deviation(p10, model_a(p), 0, P / 2), kAgreeTol);
  EXPECT_LT(deviation(p11, model_a(p), P / 2, P), kAgreeTol);
  EXPECT_LT(deviation(p12, ay, 0, P / 2), kAgreeTol);
  EXPECT_LT(deviation(p13, ay, P / 2, P), kAgreeTol);
}

// Chordal run-on, eqs. (14)–(25). c = cos(δ1/2); the guide is the chord line y = R c.
struct Chordal {
  double c = std::cos(d1 / 2);
  double L0 = l - t / 2 - d / 2;         // printed span of (14)–(15), (18)–(19), (22)–(23)
  double L1printed = l - t / 2 + d / 2;  // printed span of (16)–(17), (20)–(21), (24)–(25)
  double root(double L, double th) const {
    return std::sqrt(L * L - std::pow(R * (std::cos(th) - c), 2));
  }
  // (14) for θ = δ1/2 − φ and (15) for θ' = φ − δ1/2 are one formula; the same for (16)/(17).
  double x(double L, double th) const { return l - R * std::sin(th) - root(L, th); }
  double v_printed(double L, double th) const {  // (18), (20): ωR{cos θ + R[cos θ − c] sin θ / S}
    return w * R * (std::cos(th) + R * (std::cos(th) - c) * std::sin(th) / root(L, th));
  }
  double a_printed(double L, double th) const {  // (22), (24) as printed
    const double s = root(L, th);
    const double q = R * R * std::pow(std::cos(th) - c, 2);
    return w * w * R *
           (std::sin(th) -
            R / s * (std::cos(th) - std::cos(2 * th) + q * std::pow(std::sin(th), 2) / (s * s)));
  }
  double a_corrected(double L, double th) const {  // sign of the bracket, and c·cos θ for cos θ
    const double s = root(L, th);
    const double q = R * R * std::pow(std::cos(th) - c, 2);
    return w * w * R *
           (std::sin(th) +
            R / s *
                (c * std::cos(th) - std::cos(2 * th) + q * std::pow(std::sin(th), 2) / (s * s)));
  }
  // (18)–(25) are one family in their printed argument u: u = θ (the crank angle) in (18), (20),
  // (22), (24) and u = −θ in (19), (21), (23), (25). The derivative of x = l − R sin θ − S gives
  //   v = ωR{cos u + σ_v R[cos u − c] sin u / S},
  //   a = ω²R{σ_s sin u + σ_b R/S [k cos u − cos 2u + R²[cos u − c]² sin² u / S²]}
  // with σ_v = σ_s = +1 for u = θ, −1 for u = −θ, σ_b = +1 and k = c. The printings differ from
  // this in σ_v, σ_b, k and the span L only; the tests below change one at a time.
  double v_family(double L, double u, double sigma_v) const {
    return w * R * (std::cos(u) + sigma_v * R * (std::cos(u) - c) * std::sin(u) / root(L, u));
  }
  double a_family(double L, double u, double sigma_s, double sigma_b, double k) const {
    const double s = root(L, u);
    const double q = R * R * std::pow(std::cos(u) - c, 2);
    return w * w * R *
           (sigma_s * std::sin(u) +
            sigma_b * R / s *
                (k * std::cos(u) - std::cos(2 * u) + q * std::pow(std::sin(u), 2) / (s * s)));
  }
};

TEST(Paper003, ChordalRunOnFirstPhaseEqs14_15_18Hold) {
  const Chordal c;
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const double seat = p.seating_angles[1];  // the t − d link seats by geometry at 21.44°,
  EXPECT_NEAR(seat * 180 / kPi, 21.44, kQuotedDegreeTol);  // before the printed π/z = 22.5°
  EXPECT_LT(seat, kPi / z);
  EXPECT_LT(deviation([&](double f) { return c.x(c.L0, d1 / 2 - f); }, model_x(p), 0, seat),
            kAgreeTol);
  EXPECT_LT(
      deviation([&](double f) { return c.v_printed(c.L0, d1 / 2 - f); }, model_v(p), 0, d1 / 2),
      kAgreeTol);
}

TEST(Paper003, ChordalEq19HasTheWrongSignOfItsSecondTerm) {
  // (19) repeats (18) with θ' = φ − δ1/2 in place of θ = δ1/2 − φ; sin is odd, so the second
  // term must change sign. As printed it is not the derivative of (15).
  const Chordal c;
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const Fn v19 = [&](double f) { return c.v_printed(c.L0, f - d1 / 2); };
  const double seat = p.seating_angles[1];
  EXPECT_GT(deviation(v19, model_v(p), d1 / 2, seat), kDisagree);
  const Fn v19_fixed = [&](double f) {
    const double th = f - d1 / 2;
    return w * R * (std::cos(th) - R * (std::cos(th) - c.c) * std::sin(th) / c.root(c.L0, th));
  };
  EXPECT_LT(deviation(v19_fixed, model_v(p), d1 / 2, seat), kAgreeTol);
  EXPECT_TRUE(IsQuoted(signed_deviation(v19, model_v(p), d1 / 2, seat), 3.69e-3));  // [m/s]
  const numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  EXPECT_LT(deviation(v19_fixed, numeric_v(np), d1 / 2, seat), kNumericVelocityTol);
}

TEST(Paper003, ChordalEq21HasASignErrorBesidesItsSpan) {
  // (21) repeats (20) with u = δ1/2 + φ − 2π/z = −θ in place of θ, keeping the '+' of the second
  // term: like (19) it needs '−' (sin is odd), and like (20) its span l − t/2 + d/2 is one pitch
  // too long (the corrected span is l − 3t/2 + d/2). The sine's argument is printed
  // δ1/2 + φ − π/2 (π/z): every other argument of (17), (21), (25) is δ1/2 + φ − 2π/z, so the
  // '2' of 2π/z is taken as lost (reading A); the literal π/z (reading B) is far off however
  // the rest is corrected.
  const Chordal c;
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const double L1 = c.L0 - (t - d);
  const double a = kPi / z + d2 / 2;  // the printed interval of (21): [π/z + δ2/2, 2π/z]
  // 003 eq. (21) as printed ('1' → l, '2' → z), with the sine's argument shift as a parameter:
  // v = ωR{cos(δ1/2 + φ − 2π/z) + R[cos(δ1/2 + φ − 2π/z) − cos(δ1/2)] sin(δ1/2 + φ − π/z) /
  //     √((l − t/2 + d/2)² − R²[cos(δ1/2 + φ − 2π/z) − cos(δ1/2)]²)}
  const auto v21 = [&c](double span, double sine_shift, double sigma) {
    return Fn([&c, span, sine_shift, sigma](double f) {
      const double u = d1 / 2 + f - P;
      return w * R *
             (std::cos(u) + sigma * R * (std::cos(u) - c.c) * std::sin(d1 / 2 + f - sine_shift) /
                                c.root(span, u));
    });
  };
  const Fn model = model_v(p);
  // reading A: off by 4.21 mm/s as printed, by 4.88 mm/s with only the span corrected (the sign
  // alone), by 0.671 mm/s with only the sign corrected (the span alone)
  EXPECT_TRUE(IsQuoted(signed_deviation(v21(c.L1printed, P, +1), model, a, P), 4.21e-3));
  EXPECT_TRUE(IsQuoted(signed_deviation(v21(L1, P, +1), model, a, P), 4.88e-3));
  EXPECT_TRUE(IsQuoted(signed_deviation(v21(c.L1printed, P, -1), model, a, P), 6.71e-4));
  // both corrected: the model, and the independent numerical solver
  EXPECT_LT(deviation(v21(L1, P, -1), model, a, P), kAgreeTol);
  EXPECT_LT(deviation(v21(L1, P, -1), numeric_v(np), a, P), kNumericVelocityTol);
  // reading B (π/z as printed): off by 12.2 mm/s with the span corrected, and still by 9.67 mm/s
  // with the sign corrected too: not a plausible reading
  EXPECT_TRUE(IsQuoted(signed_deviation(v21(L1, P / 2, +1), model, a, P), 1.22e-2));
  EXPECT_TRUE(IsQuoted(signed_deviation(v21(L1, P / 2, -1), model, a, P), -9.67e-3));
}

TEST(Paper003, ChordalEq22HasTheWrongSignOfItsBracketAndLosesCosHalfDelta1) {
  const Chordal c;
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  // 003 eq. (22) as printed ('1' → l), θ = δ1/2 − φ, S = √((l − t/2 − d/2)² − R²[cos θ − c]²):
  // P_x = ω²R{sin θ + −R/S [cos θ − cos 2θ + R²[cos θ − c]² sin² θ / S²]}
  const Fn a22 = [&c](double f) {
    const double th = d1 / 2 - f;
    const double s = c.root(c.L0, th);
    return w * w * R *
           (std::sin(th) +
            -R / s *
                (std::cos(th) - std::cos(2 * th) +
                 R * R * std::pow(std::cos(th) - c.c, 2) * std::pow(std::sin(th), 2) / (s * s)));
  };
  const auto a22_with = [&c](double sigma_b, double k) {
    return Fn([&c, sigma_b, k](double f) { return c.a_family(c.L0, d1 / 2 - f, +1, sigma_b, k); });
  };
  const Fn model = model_a(p);
  const double b = d1 / 2;  // the printed interval [0, δ1/2]
  EXPECT_TRUE(IsQuoted(signed_deviation(a22, model, 0, b), -0.481));                // as printed
  EXPECT_TRUE(IsQuoted(signed_deviation(a22_with(+1, 1), model, 0, b), 0.0993));    // k = c lost
  EXPECT_TRUE(IsQuoted(signed_deviation(a22_with(-1, c.c), model, 0, b), -0.385));  // the sign
  EXPECT_LT(deviation(a22_with(+1, c.c), model, 0, b), kAgreeTol);  // both corrected
  EXPECT_LT(deviation(a22_with(+1, c.c), numeric_a(np), 0, b), kNumericAccelTol);
}

TEST(Paper003, ChordalEq23HasTheRightSignButLosesCosHalfDelta1) {
  // (23) is printed in θ' = φ − δ1/2 = −θ with '−sin θ'' and '+R/S[…]': both signs are right for
  // the argument −θ (the bracket is even in θ). Only the factor cos(δ1/2) on cos θ' is lost.
  const Chordal c;
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  // 003 eq. (23) as printed ('1' → l), θ' = φ − δ1/2, S = √((l − t/2 − d/2)² − R²[cos θ' − c]²):
  // P_x = ω²R{−sin θ' + R/S [cos θ' − cos 2θ' + R²[cos θ' − c]² sin² θ' / S²]}
  const Fn a23 = [&c](double f) {
    const double th = f - d1 / 2;
    const double s = c.root(c.L0, th);
    return w * w * R *
           (-std::sin(th) +
            R / s *
                (std::cos(th) - std::cos(2 * th) +
                 R * R * std::pow(std::cos(th) - c.c, 2) * std::pow(std::sin(th), 2) / (s * s)));
  };
  const Fn a23_fixed = [&c](double f) { return c.a_family(c.L0, f - d1 / 2, -1, +1, c.c); };
  const Fn model = model_a(p);
  const double a = d1 / 2;
  const double seat = p.seating_angles[1];  // (23) prints [δ1/2, π/z]; the phase ends at 21.44°
  EXPECT_TRUE(IsQuoted(signed_deviation(a23, model, a, seat), 0.0993));
  EXPECT_LT(deviation(a23_fixed, model, a, seat), kAgreeTol);
  EXPECT_LT(deviation(a23_fixed, numeric_a(np), a, seat), kNumericAccelTol);
}

TEST(Paper003, ChordalEq24HasTheWrongSignLosesCosHalfDelta1AndHasTheSpanOfEq16) {
  const Chordal c;
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const double L1 = c.L0 - (t - d);
  // 003 eq. (24) as printed ('1' → l, '2' → z), u = π/z + δ2/2 − φ (= θ),
  // S = √((l − t/2 + d/2)² − R²[cos u − c]²):
  // P_x = ω²R{sin u + −R/S [cos u + −cos 2u + R²[cos u − c]² sin² u / S²]}
  const Fn a24 = [&c](double f) {
    const double u = kPi / z + d2 / 2 - f;
    const double s = c.root(c.L1printed, u);
    return w * w * R *
           (std::sin(u) +
            -R / s *
                (std::cos(u) + -std::cos(2 * u) +
                 R * R * std::pow(std::cos(u) - c.c, 2) * std::pow(std::sin(u), 2) / (s * s)));
  };
  const auto a24_with = [&c](double span, double sigma_b, double k) {
    return Fn([&c, span, sigma_b, k](double f) {
      return c.a_family(span, kPi / z + d2 / 2 - f, +1, sigma_b, k);
    });
  };
  const Fn model = model_a(p);
  const double a = kPi / z;  // the printed interval [π/z, π/z + δ2/2]
  const double b = kPi / z + d2 / 2;
  EXPECT_TRUE(IsQuoted(signed_deviation(a24, model, a, b), 0.126));  // as printed
  // one defect left at a time: the span, the sign, the factor cos(δ1/2)
  EXPECT_TRUE(IsQuoted(signed_deviation(a24_with(c.L1printed, +1, c.c), model, a, b), 0.0347));
  EXPECT_TRUE(IsQuoted(signed_deviation(a24_with(L1, -1, c.c), model, a, b), 0.253));
  EXPECT_TRUE(IsQuoted(signed_deviation(a24_with(L1, +1, 1), model, a, b), 0.126));
  EXPECT_LT(deviation(a24_with(L1, +1, c.c), model, a, b), kAgreeTol);
  EXPECT_LT(deviation(a24_with(L1, +1, c.c), numeric_a(np), a, b), kNumericAccelTol);
}

TEST(Paper003, ChordalEq25HasTheRightSignButLosesCosHalfDelta1AndHasTheSpanOfEq17) {
  // (25) is printed in u = δ1/2 + φ − 2π/z = −θ with '−sin u' and '+R/S[…]': right for −θ.
  const Chordal c;
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const double L1 = c.L0 - (t - d);
  // 003 eq. (25) as printed ('1' → l, '2' → z), u = δ1/2 + φ − 2π/z,
  // S = √((l − t/2 + d/2)² − R²[cos u − c]²):
  // P_x = ω²R{−sin u + R/S [cos u + −cos 2u + R²[cos u − c]² sin² u / S²]}
  const Fn a25 = [&c](double f) {
    const double u = d1 / 2 + f - P;
    const double s = c.root(c.L1printed, u);
    return w * w * R *
           (-std::sin(u) +
            R / s *
                (std::cos(u) + -std::cos(2 * u) +
                 R * R * std::pow(std::cos(u) - c.c, 2) * std::pow(std::sin(u), 2) / (s * s)));
  };
  const auto a25_with = [&c](double span, double k) {
    return Fn([&c, span, k](double f) { return c.a_family(span, d1 / 2 + f - P, -1, +1, k); });
  };
  const Fn model = model_a(p);
  const double a = kPi / z + d2 / 2;  // the printed interval [π/z + δ2/2, 2π/z]
  EXPECT_TRUE(IsQuoted(signed_deviation(a25, model, a, P), 0.126));  // as printed
  EXPECT_TRUE(IsQuoted(signed_deviation(a25_with(c.L1printed, c.c), model, a, P), -0.0673));
  EXPECT_TRUE(IsQuoted(signed_deviation(a25_with(L1, 1), model, a, P), 0.126));
  EXPECT_LT(deviation(a25_with(L1, c.c), model, a, P), kAgreeTol);
  EXPECT_LT(deviation(a25_with(L1, c.c), numeric_a(np), a, P), kNumericAccelTol);
}

TEST(Paper003, ChordalSecondPhaseEqs16_17UseASpanOnePitchTooLong) {
  // After the t − d link seats, the span from the new crank to the same guided point is
  // L0 − (t − d) = l − 3t/2 + d/2; (16)–(17) print l − t/2 + d/2, one pitch t longer, and switch
  // at π/z instead of at the geometric seating. With the printed span x jumps at the switch.
  const Chordal c;
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const double seat = p.seating_angles[1];
  const double L1 = c.L0 - (t - d);
  EXPECT_NEAR(p.phases[1].span, L1, kExactLengthTol);
  const double th_switch = kPi / z + d2 / 2 - kPi / z;  // crank angle of (16) at φ = π/z
  const double jump = c.x(c.L1printed, th_switch) - c.x(c.L0, d1 / 2 - kPi / z);
  EXPECT_GT(std::abs(jump), 0.5 * t) << "printed x jumps by " << jump << " m at phi = pi/z";
  // With the geometric span and the crank angle of (16) the model's second phase is reproduced:
  const Fn x16_fixed = [&](double f) { return c.x(L1, kPi / z + d2 / 2 - f); };
  EXPECT_LT(deviation(x16_fixed, model_x(p), seat, P), kAgreeTol);
  const Fn x16_printed = [&](double f) { return c.x(c.L1printed, kPi / z + d2 / 2 - f); };
  EXPECT_GT(deviation(x16_printed, model_x(p), seat, P), 0.5 * t);
  // velocities of (20) with the geometric span hold; with the printed span they do not
  const Fn v20_fixed = [&](double f) { return c.v_printed(L1, kPi / z + d2 / 2 - f); };
  const Fn v20_printed = [&](double f) { return c.v_printed(c.L1printed, kPi / z + d2 / 2 - f); };
  EXPECT_LT(deviation(v20_fixed, model_v(p), seat, kPi / z + d2 / 2), kAgreeTol);
  EXPECT_TRUE(
      IsQuoted(signed_deviation(v20_printed, model_v(p), seat, kPi / z + d2 / 2), -6.69e-4));
}

// Tangential run-on, eqs. (26)–(43). H = R.
struct Tangential {
  static double root(double L, double th) {
    return std::sqrt(L * L - std::pow(R * (1 - std::cos(th)), 2));
  }
  // x = l − R sin θ − S for the crank at θ (26: θ = −φ, 30: δ1 − φ, 31: −(δ2 + φ − 2π/z), 35: 2π/z
  // − φ)
  static double x(double L, double th) { return l - R * std::sin(th) - root(L, th); }
  static double v(double L, double th) {  // (37), (39): ωR[cos θ − R(1 − cos θ) sin θ / S]
    return w * R * (std::cos(th) - R * (1 - std::cos(th)) * std::sin(th) / root(L, th));
  }
  static double a_printed(double L, double th) {  // (41), (43) as printed
    const double s = root(L, th);
    const double q = R * R * std::pow(1 - std::cos(th), 2);
    return w * w * R *
           (std::sin(th) -
            R / s * (std::cos(th) - std::cos(2 * th) + q * std::pow(std::sin(th), 2) / (s * s)));
  }
  // (40)–(43) as one family in the printed argument u (c = 1): σ_s = +1 for u = θ, −1 for u = −θ;
  // the derivative needs σ_b = +1 for both.
  static double a_family(double L, double u, double sigma_s, double sigma_b) {
    const double s = root(L, u);
    const double q = R * R * std::pow(1 - std::cos(u), 2);
    return w * w * R *
           (sigma_s * std::sin(u) +
            sigma_b * R / s *
                (std::cos(u) - std::cos(2 * u) + q * std::pow(std::sin(u), 2) / (s * s)));
  }
  static double a40(double L, double f) {  // (40) as printed, argument φ
    const double s = root(L, f);
    const double q = R * R * std::pow(1 - std::cos(f), 2);
    return w * w * R *
           (-std::sin(f) +
            R / s * (std::cos(f) - std::cos(2 * f) + q * std::pow(std::sin(f), 2) / (s * s)));
  }
  // (29)/(34): seating angle from sin ξ = (R/L)(1 − cos(δ/2 + ξ)), φ_g = base + ξ
  static double seating(double base, double L, double delta) {
    const double s = std::sin(delta / 2);
    return base + 2 * std::atan((L - R * s - std::sqrt(L * L - 2 * R * L * s)) /
                                (2 * R * std::pow(std::cos(delta / 4), 2)));
  }
};

TEST(Paper003, TangentialSeatingAnglesEq29And34HoldWithTheGeometricSpans) {
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider});
  ASSERT_EQ(p.seating_angles.size(), 2u);
  // (29) as printed (with l for '1')
  EXPECT_NEAR(Tangential::seating(d1 / 2, l, d1), p.seating_angles[0], kSeatingTol);
  // (34) prints the span as (1 − d); the bar from the first seated joint is l − (t + d)
  EXPECT_NEAR(Tangential::seating(P - d2 / 2, l - t - d, d2), p.seating_angles[1], kSeatingTol);
  EXPECT_GT(std::abs(Tangential::seating(P - d2 / 2, l - d, d2) - p.seating_angles[1]), 1e-3);
  // (34) as printed, span (l − d): 37.38°, 0.185° early
  EXPECT_TRUE(IsQuoted(
      (Tangential::seating(P - d2 / 2, l - d, d2) - p.seating_angles[1]) * 180 / kPi, -0.185));
  // and (33) prints cos(−δ2/2 + ξ2); the geometry (and (34) itself) need cos(δ2/2 + ξ2)
  constexpr double kSineTol = 1e-12;  // [1] both sides of eq. (33) at the model's seating
  const double xi2 = p.seating_angles[1] - (P - d2 / 2);
  EXPECT_NEAR(std::sin(xi2), R / (l - t - d) * (1 - std::cos(d2 / 2 + xi2)), kSineTol);
  EXPECT_GT(std::abs(std::sin(xi2) - R / (l - t - d) * (1 - std::cos(-d2 / 2 + xi2))), 1e-4);
  EXPECT_NEAR(p.seating_angles[0] * 180 / kPi, 15.85, kQuotedDegreeTol);
  EXPECT_NEAR(p.seating_angles[1] * 180 / kPi, 37.57, kQuotedDegreeTol);
}

TEST(Paper003, TangentialEq33AsPrintedSeatsTheSecondLinkTooEarly) {
  // 003 eq. (33) as printed ('1' → l): sin ξ2 = R/(l − d) [1 − cos(−δ2/2 + ξ2)], solved for ξ2 and
  // put into (32), φ_g2 = 2π/z − δ2/2 + ξ2 (which holds). Two defects: the span (l − d) for
  // l − t − d, and −δ2/2 for +δ2/2. Each alone moves the seating by more than 0.1°.
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider});
  const auto phi_g2_deg = [](double span, double sign) {
    const Fn f = [span, sign](double xi) {
      return std::sin(xi) - R / span * (1 - std::cos(sign * d2 / 2 + xi));
    };
    return (P - d2 / 2 + bisect(f, 0.0, 1.0)) * 180 / kPi;  // ξ2 in (0, 1 rad): one sign change
  };
  const double model_deg = p.seating_angles[1] * 180 / kPi;          // 37.57°
  constexpr double kSeatingDegTol = 1e-10;                           // [°] bisection to round-off
  EXPECT_TRUE(IsQuoted(phi_g2_deg(l - d, -1) - model_deg, -0.262));  // as printed
  EXPECT_TRUE(IsQuoted(phi_g2_deg(l - t - d, -1) - model_deg, -0.145));  // the sign alone
  EXPECT_TRUE(IsQuoted(phi_g2_deg(l - d, +1) - model_deg, -0.185));      // the span alone
  EXPECT_NEAR(phi_g2_deg(l - t - d, +1), model_deg, kSeatingDegTol);     // both corrected
}

TEST(Paper003, TangentialPositionsEqs26_30_31HoldAnd35NeedsTwoCorrections) {
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider});
  const double g1 = p.seating_angles[0];
  const double g2 = p.seating_angles[1];
  const Fn x26 = [](double f) {
    return l + R * std::sin(f) - std::sqrt(l * l - R * R * std::pow(1 - std::cos(f), 2));
  };
  EXPECT_LT(deviation(x26, model_x(p), 0, g1), kAgreeTol);
  const Fn x30 = [](double f) { return Tangential::x(l - t - d, d1 - f); };
  const Fn x31 = [](double f) { return Tangential::x(l - t - d, -(d2 + f - P)); };
  EXPECT_LT(deviation(x30, model_x(p), g1, d1), kAgreeTol);
  EXPECT_LT(deviation(x31, model_x(p), d1, g2), kAgreeTol);
  // (30), (31) as printed, span (l − d): one pitch too long, x off by 64.0 mm
  const Fn x30_printed = [](double f) { return Tangential::x(l - d, d1 - f); };
  const Fn x31_printed = [](double f) {
    return l + R * std::sin(d2 + f - P) - Tangential::root(l - d, d2 + f - P);
  };
  EXPECT_TRUE(IsQuoted(signed_deviation(x30_printed, model_x(p), g1, d1), -0.0640));  // [m]
  EXPECT_TRUE(IsQuoted(signed_deviation(x31_printed, model_x(p), d1, g2), -0.0640));  // [m]
  // (35) as printed: span (l − t) and '+' under the root. Geometry: span l − 2t, '−'.
  const Fn x35_printed = [](double f) {
    return l - R * std::sin(P - f) -
           std::sqrt(std::pow(l - t, 2) + R * R * std::pow(1 - std::cos(P - f), 2));
  };
  const Fn x35_fixed = [](double f) { return Tangential::x(l - 2 * t, P - f); };
  EXPECT_LT(deviation(x35_fixed, model_x(p), g2, P), kAgreeTol);
  EXPECT_GT(deviation(x35_printed, model_x(p), g2, P), 0.5 * t);
  EXPECT_TRUE(IsQuoted(signed_deviation(x35_printed, model_x(p), g2, P), -0.0640));  // [m]
  // one defect left at a time: the '+' (span corrected) costs 14.6 µm; the span (sign corrected)
  // 64.0 mm
  const auto x35_with = [](double span, double sign) {
    return Fn([span, sign](double f) {
      return l - R * std::sin(P - f) -
             std::sqrt(span * span + sign * R * R * std::pow(1 - std::cos(P - f), 2));
    });
  };
  EXPECT_TRUE(IsQuoted(signed_deviation(x35_with(l - 2 * t, +1), model_x(p), g2, P), -1.46e-5));
  EXPECT_TRUE(IsQuoted(signed_deviation(x35_with(l - t, -1), model_x(p), g2, P), -0.0640));
  EXPECT_NEAR(x35_fixed(P), 2 * t, kExactLengthTol);  // the strand advances two pitches per period
}

TEST(Paper003, TangentialVelocitiesEqs36To39HoldWithTheGeometricSpans) {
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider});
  const double g1 = p.seating_angles[0];
  const double g2 = p.seating_angles[1];
  const Fn v36 = [](double f) {
    return w * R * (std::cos(f) + R * (1 - std::cos(f)) * std::sin(f) / Tangential::root(l, f));
  };
  EXPECT_LT(deviation(v36, model_v(p), 0, g1), kAgreeTol);
  EXPECT_LT(
      deviation([](double f) { return Tangential::v(l - t - d, d1 - f); }, model_v(p), g1, d1),
      kAgreeTol);
  // (38) is (37) in the argument ψ = −θ: cos ψ + R(1 − cos ψ) sin ψ / S; printed span (l − t)
  const Fn v38 = [](double f) {
    const double psi = d2 + f - P;
    return w * R *
           (std::cos(psi) +
            R * (1 - std::cos(psi)) * std::sin(psi) / Tangential::root(l - t - d, psi));
  };
  EXPECT_LT(deviation(v38, model_v(p), d1, g2), kAgreeTol);
  EXPECT_LT(deviation([](double f) { return Tangential::v(l - 2 * t, P - f); }, model_v(p), g2, P),
            kAgreeTol);
  EXPECT_GT(deviation([](double f) { return Tangential::v(l - t, P - f); }, model_v(p), g2, P),
            1e-6);
  // (38), (39) as printed, span (l − t): −0.123 and +0.376 mm/s
  const Fn v38_printed = [](double f) {
    const double psi = d2 + f - P;
    return w * R *
           (std::cos(psi) + R * (1 - std::cos(psi)) * std::sin(psi) / Tangential::root(l - t, psi));
  };
  EXPECT_TRUE(IsQuoted(signed_deviation(v38_printed, model_v(p), d1, g2), -1.23e-4));  // [m/s]
  EXPECT_TRUE(IsQuoted(
      signed_deviation([](double f) { return Tangential::v(l - t, P - f); }, model_v(p), g2, P),
      3.76e-4));  // [m/s]
}

TEST(Paper003, TangentialAccelerationsEq40And42HoldEqs41And43HaveTheWrongSign) {
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider});
  const double g1 = p.seating_angles[0];
  const double g2 = p.seating_angles[1];
  EXPECT_LT(deviation([](double f) { return Tangential::a40(l, f); }, model_a(p), 0, g1),
            kAgreeTol);
  // (42) is (40)'s form in ψ = δ2 + φ − 2π/z with the span l − t − d (printed (1 − d))
  EXPECT_LT(deviation([](double f) { return Tangential::a40(l - t - d, d2 + f - P); }, model_a(p),
                      d1, g2),
            kAgreeTol);
  // (42) as printed, span (l − d): −0.0351 m/s²
  EXPECT_TRUE(IsQuoted(signed_deviation([](double f) { return Tangential::a40(l - d, d2 + f - P); },
                                        model_a(p), d1, g2),
                       -0.0351));
  // (41), (43): the bracket enters with '−'; the derivative of (37), (39) needs '+'
  const Fn a41 = [](double f) { return Tangential::a_printed(l - t - d, d1 - f); };
  const Fn a41_fixed = [](double f) {
    return 2 * w * w * R * std::sin(d1 - f) - Tangential::a_printed(l - t - d, d1 - f);
  };
  EXPECT_GT(deviation(a41, model_a(p), g1, d1), 0.1);
  EXPECT_TRUE(IsQuoted(signed_deviation(a41, model_a(p), g1, d1), -0.586));  // [m/s²]
  EXPECT_LT(deviation(a41_fixed, model_a(p), g1, d1), kAgreeTol);
  const numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider});
  EXPECT_LT(deviation(a41_fixed, numeric_a(np), g1, d1), kNumericAccelTol);
}

TEST(Paper003, TangentialEq43HasTheWrongSignAndASpanOnePitchTooLong) {
  // 003 eq. (43) as printed ('1' → l, the root's closing bracket put back after the square),
  // u = 2π/z − φ (= θ), S = √((l − t)² − R²[1 − cos u]²):
  // P_x = ω²R{sin u − R/S [cos u + −cos 2u + R²[1 − cos u]² sin² u / S²]}
  // After the two links of the period have seated the span is l − (t + d) − (t − d) = l − 2t.
  const RunOnPlan p = plan_run_on(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider});
  const numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider});
  const double g2 = p.seating_angles[1];
  const Fn a43 = [](double f) {
    const double u = P - f;
    const double s = Tangential::root(l - t, u);
    return w * w * R *
           (std::sin(u) -
            R / s *
                (std::cos(u) + -std::cos(2 * u) +
                 R * R * std::pow(1 - std::cos(u), 2) * std::pow(std::sin(u), 2) / (s * s)));
  };
  const auto a43_with = [](double span, double sigma_b) {
    return Fn([span, sigma_b](double f) { return Tangential::a_family(span, P - f, +1, sigma_b); });
  };
  const Fn model = model_a(p);
  EXPECT_TRUE(IsQuoted(signed_deviation(a43, model, g2, P), -0.218));  // as printed
  EXPECT_TRUE(IsQuoted(signed_deviation(a43_with(l - 2 * t, -1), model, g2, P), -0.262));  // sign
  EXPECT_TRUE(IsQuoted(signed_deviation(a43_with(l - t, +1), model, g2, P), -0.0436));     // span
  EXPECT_LT(deviation(a43_with(l - 2 * t, +1), model, g2, P), kAgreeTol);
  EXPECT_LT(deviation(a43_with(l - 2 * t, +1), numeric_a(np), g2, P), kNumericAccelTol);
}

// The paper's conclusions (§3.2 end, §4), checked on the validated curves of its example.
struct Example {
  RunOnResult free, chordal, tangential;
  Example() {
    const Sampling s{w, 4001, std::nullopt};
    free = run_on(kWheel, Guide{}, s);
    chordal = run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider}, s);
    tangential = run_on(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kSlider}, s);
  }
};

double end_jump(const RunOnResult& r) {  // a(2π/z⁺) − a(2π/z⁻): the change at the period's end
  const RunOnPlan& p = r.plan;
  return w * w * (evaluate(p, P).d2x - evaluate_phase(p, p.phases.size() - 1, P).d2x);
}

TEST(Paper003, ConclusionAboutTheEndOfThePeriod) {
  // "Free run-on has the most abrupt change of sign of the acceleration at the end of the period;
  // it is smaller for chordal run-on; tangential run-on has no change of sign there, only a drop
  // of the acceleration to zero."
  constexpr double kJumpTol = 1e-12;       // [m/s²] the free jump of ~2 m/s² in closed form
  constexpr double kZeroAccelTol = 1e-15;  // [m/s²] the tangential acceleration at 2π/z, zero
  constexpr double kEndJumpTol = 1e-5;     // [m/s²] what is left of the jump (~1 m/s² scale)
  const Example e;
  const double free_jump = end_jump(e.free);
  const double chordal_jump = end_jump(e.chordal);
  EXPECT_NEAR(free_jump, 2 * w * w * R * std::sin(d1 / 2), kJumpTol);  // −1.025 → +1.025 m/s²
  EXPECT_LT(std::abs(chordal_jump), std::abs(free_jump));              // 1.997 < 2.050 m/s²
  const RunOnPlan& tp = e.tangential.plan;
  const double a_before = w * w * evaluate_phase(tp, tp.phases.size() - 1, P - 1e-6).d2x;
  EXPECT_GE(a_before, 0.0);  // no change of sign ...
  EXPECT_NEAR(w * w * evaluate(tp, P).d2x, 0.0,
              kZeroAccelTol);  // ... the acceleration drops to zero
  EXPECT_NEAR(end_jump(e.tangential), 0.0, kEndJumpTol);
}

TEST(Paper003, ConclusionThatTangentialRunOnHasTheSmallestExtremesDoesNotHold) {
  // "Tangential run-on also has the smallest extreme accelerations." On the corrected model of
  // the paper's example (l = 256 mm) it does not: the jumps move from the period's end to the
  // seatings inside the period, where the inclined span adds to the crank's acceleration.
  constexpr double kSampledPeakTol = 1e-9;  // [m/s²] the free peak sits on a sample (φ = 0)
  constexpr double kQuotedAccelTol = 1e-4;  // [m/s²] peaks quoted to 4 decimals
  constexpr double kRangeTol = 1e-3;        // [m/s²] slack on "no smaller" for sampled ranges
  const Example e;
  auto peak = [](const RunOnResult& r) { return std::max(-r.extremes.ax_min, r.extremes.ax_max); };
  EXPECT_NEAR(peak(e.free), w * w * R * std::sin(d1 / 2), kSampledPeakTol);  // 1.025 m/s²
  EXPECT_NEAR(peak(e.chordal), 1.2205, kQuotedAccelTol);
  EXPECT_NEAR(peak(e.tangential), 1.2233, kQuotedAccelTol);
  EXPECT_GT(peak(e.tangential), peak(e.chordal));
  EXPECT_GT(peak(e.chordal), peak(e.free));
  // the range a_max − a_min is also no smaller for tangential than for free run-on
  EXPECT_GE(e.tangential.extremes.ax_max - e.tangential.extremes.ax_min,
            e.free.extremes.ax_max - e.free.extremes.ax_min - kRangeTol);
}

TEST(Paper003, ConclusionThatChordalRunOnHasTheSmallerEndJumpDependsOnTheSpanReading) {
  // "The abrupt change of sign at the end of the period is smaller for chordal run-on" (than the
  // free one's 2ω²R sin(δ1/2) = 2.050 m/s²). It holds only in the slider reading with the guided
  // point re-chosen at each period start; it fails when the same chain point is followed across
  // the boundary, and in the pivot reading.
  constexpr double kQuotedJumpTol = 1e-3;  // [m/s²] jumps and limits quoted to 3 decimals
  const Sampling s{w, 33, std::nullopt};
  const double free_jump = end_jump(run_on(kWheel, Guide{}, s));
  EXPECT_NEAR(free_jump, 2.050, kQuotedJumpTol);
  // slider, reset at the period start: −0.776 → +1.220 m/s²
  const RunOnPlan slider =
      plan_run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const double a_end = w * w * evaluate_phase(slider, slider.phases.size() - 1, P).d2x;
  EXPECT_NEAR(a_end, -0.776, kQuotedJumpTol);
  EXPECT_NEAR(w * w * evaluate(slider, 0).d2x - a_end, 1.997, kQuotedJumpTol);
  // slider, the same chain point: after the t + d link seats at 2π/z the bar from the new crank
  // (at θ = δ1/2 again) to the old guided point is two pitches shorter than the reset one.
  const Chordal c;
  const double a_same_point = c.a_corrected(c.L0 - 2 * t, d1 / 2);  // eq. (22) corrected
  EXPECT_NEAR(a_same_point, 1.508, kQuotedJumpTol);
  // ... the same from the independent numerical solver with that span
  numeric::NumericPlan np =
      numeric::plan(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  np.phases[0].span -= 2 * t;
  EXPECT_NEAR(w * w * numeric::evaluate_phase(np, 0, 0.0).d2x, a_same_point, kNumericAccelTol);
  EXPECT_GT(a_same_point - a_end, free_jump);  // 2.284 > 2.050 m/s²
  // pivot: −0.8835 → +1.2205 m/s²
  const double pivot_jump =
      end_jump(run_on(kWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kPivot}, s));
  EXPECT_NEAR(pivot_jump, 2.104, kQuotedJumpTol);
  EXPECT_GT(pivot_jump, free_jump);
}

TEST(Paper003, ConclusionThatTangentialRunOnHasTheSmallestExtremesFailsInThePivotReadingToo) {
  // Conclusion 2 of §4 (tangential run-on is the most favourable for inertial loads, which are
  // −M·a_x) read with the pivot span: its peak |a_x| 1.2175 m/s² is still above free run-on's
  // 1.025 m/s².
  constexpr double kQuotedAccelTol = 1e-4;  // [m/s²] peaks quoted to 4 decimals
  const Sampling s{w, 33, std::nullopt};
  const RunOnResult free = run_on(kWheel, Guide{}, s);
  const RunOnResult tangential =
      run_on(kWheel, Guide{GuideKind::kTangential, 0, l, SpanModel::kPivot}, s);
  auto peak = [](const RunOnResult& r) { return std::max(-r.extremes.ax_min, r.extremes.ax_max); };
  EXPECT_NEAR(peak(tangential), 1.2175, kQuotedAccelTol);
  EXPECT_GT(peak(tangential), peak(free));
}

}  // namespace
}  // namespace catena::pocketwheel
