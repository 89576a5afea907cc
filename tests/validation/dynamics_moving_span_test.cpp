// The axially moving span (issue 21 validation (3), the moving part; docs/models/dynamics.md).
//
// A closed chain loop runs at speed v round a "stadium" of two frictionless convex arc guides of
// 0.5 m radius (no sprockets, no gravity): the straight spans between them are strings moving along
// their own length under the tension T, with the fixed ends at the guides' tangent points. Plucked,
// the transverse displacement at a fixed point of the upper span oscillates at the natural
// frequencies of the axially moving string,
//     f_n = (n / 2L) c (1 − v²/c²),   c = √(T/q)
// (e.g. C. D. Mote Jr., "Dynamic stability of axially moving materials", Shock Vib. Dig. 4 (1972)
// 2–11; J. A. Wickert, C. D. Mote Jr., J. Appl. Mech. 57 (1990) 738–744), read from the spectrum
// as in validation (3)'s stationary span (tests/dynamics/spectrum.hpp), within 2 %: modes 1, 2
// and 3 at v = c/2.
//
// A span of N links is a discrete string (beads of q l on strings of tension T): its waves
// disperse, Ω(κ) = (2c/l) sin(κl/2) in the chain's own frame, and the moving span's frequency is
// the ω at which a wave carried downstream (ω = Ω(κ₁) + vκ₁) and one running upstream
// (ω = Ω(κ₂) − vκ₂) fit the span, (κ₁ + κ₂) L = 2πn. The upstream wave is the short one (it
// crawls at c − v), so the discreteness counts about 3.5 times more than at rest (0.41 %): at 30
// links mode 3 is 1.42 % below the continuous formula (mode 2 0.63 %, mode 1 0.16 %), at 60 links
// 0.35 %. The test runs 60 links a span, checks against both the continuous formula and the
// discrete string's frequency, and checks that the latter converges to the former at second order.
// Measured (v ≈ 4.93 m/s over the record): 6.3028, 12.571, 18.786 Hz, against the continuous
// formula −0.09 %, −0.36 %, −0.74 %, against the discrete string −0.05 %, −0.21 %, −0.40 %.
// The former set-up (30 links, pluck at 1/5, probe at 0.37 L, where mode 3's envelope is 0.34)
// had mode 3 as only the fifth peak, 18.44 Hz: −2.7 % from the continuous formula (−1.3 % from
// the discrete string's); 30 links plucked and probed at 1/6 split it in two, 18.14 and 19.09 Hz.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "../dynamics/spectrum.hpp"
#include "catena/dynamics/integrator.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kFrequencyTol = 0.02;  // issue 21 (3): 2 %

// The n-th frequency [Hz] of a span of `links` beads (spacing l = span / links) moving at v under
// the wave speed c, from the lattice's dispersion Doppler-shifted into the fixed frame (above).
double discrete_moving_span_frequency(int n, int links, double span, double c, double v) {
  const double l = span / links, wave = 2.0 * kPi * n / span;  // κ₁ + κ₂
  auto omega = [&](double kappa) { return 2.0 * c / l * std::sin(0.5 * kappa * l); };
  // downstream minus upstream frequency, increasing in κ₁ from −(Ω(K) − vK) < 0 to Ω(K) + vK > 0
  auto mismatch = [&](double k1) {
    const double k2 = wave - k1;
    return (omega(k1) + v * k1) - (omega(k2) - v * k2);
  };
  double a = 0.0, b = wave;
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (a + b);
    (mismatch(m) < 0.0 ? a : b) = m;
  }
  const double k1 = 0.5 * (a + b);
  return (omega(k1) + v * k1) / (2.0 * kPi);
}

TEST(DynamicsMovingSpan, DiscreteSpanConvergesToTheContinuousFormula) {
  // the reference itself: at v = 0 the beaded string's 2(c/l) sin(nπ/2N) / 2π exactly, and at
  // v = c/2 the gap to (n/2L) c (1 − v²/c²) falls 4× per doubling of the links (second order)
  const double span = 0.6, c = 10.0;
  for (int m = 1; m <= 3; ++m) {
    const double beads = 2.0 * c * 30 / span * std::sin(m * kPi / 60.0) / (2.0 * kPi);
    EXPECT_NEAR(discrete_moving_span_frequency(m, 30, span, c, 0.0) / beads, 1.0, 1e-12);
  }
  const double v = 0.5 * c, continuous = 3.0 * c / (2.0 * span) * (1.0 - v * v / (c * c));
  std::vector<double> gap;
  for (const int links : {30, 60, 120, 240}) {
    gap.push_back(1.0 - discrete_moving_span_frequency(3, links, span, c, v) / continuous);
  }
  EXPECT_NEAR(gap[0], 0.0142, 0.0001);  // mode 3 at 30 links: 1.42 % low
  EXPECT_NEAR(gap[1], 0.0035, 0.0001);  // at 60 links: 0.35 % low
  for (std::size_t i = 1; i < gap.size(); ++i) EXPECT_NEAR(gap[i - 1] / gap[i], 4.0, 0.1);
}

TEST(DynamicsMovingSpan, TransverseModesOfAnAxiallyMovingSpan) {
  const double q = 1.0, tension = 100.0, c = std::sqrt(tension / q);  // c = 10 m/s
  const double v = 0.5 * c;                                           // v/c = ½: factor 0.75
  const double rail = 0.5, roller = 0.005, bend = rail + roller;      // centres' arc radius
  const double k = 1e6;
  constexpr int kSpanLinks = 60;       // the discrete string 0.35 % off at mode 3 (above)
  const double l = 0.01;               // stretched link length (node spacing)
  const double span = kSpanLinks * l;  // L, tangent point to tangent point
  // nodes round the arcs: the arc of radius `bend` in chords of length l
  const double dphi = 2.0 * std::asin(0.5 * l / bend);
  const int arc_links = static_cast<int>(std::lround(kPi / dphi));
  const double bend_fit = 0.5 * l / std::sin(0.5 * kPi / arc_links);  // an exact half polygon
  const std::size_t n = static_cast<std::size_t>(2 * kSpanLinks + 2 * arc_links);
  Model model = uniform_chain(n, true, l - tension / k, q * l, k, 0.0, false);
  for (const double cx : {0.0, span}) {
    Guide g;
    g.kind = Guide::Kind::kArc;
    g.centre_x = cx;
    g.radius = bend_fit - roller;
    // each arc runs 30° on past both tangent points, under the spans: a roller of a span that
    // swings below the tangent line meets the circle gradually, not an arc's sharp end
    g.start_angle = (cx == 0.0 ? kPi / 2 : -kPi / 2) - kPi / 6;
    g.end_angle = g.start_angle + kPi + kPi / 3;
    g.roller_radius = roller;
    g.contact_stiffness = 1e7;
    g.contact_damping = 0.0;
    model.guides.push_back(g);
  }
  // counter-clockwise: the lower span +x, round the right arc, the upper span −x, round the left
  State s(n, 0);
  std::size_t i = 0;
  auto put = [&](double x, double y, double tx, double ty) {
    s.x[i] = x;
    s.y[i] = y;
    s.vx[i] = v * tx;
    s.vy[i] = v * ty;
    ++i;
  };
  for (int j = 0; j < kSpanLinks; ++j) put(j * l, -bend_fit, 1.0, 0.0);
  for (int j = 0; j < arc_links; ++j) {
    const double a = -kPi / 2 + j * kPi / arc_links;
    put(span + bend_fit * std::cos(a), bend_fit * std::sin(a), -std::sin(a), std::cos(a));
  }
  for (int j = 0; j < kSpanLinks; ++j) put(span - j * l, bend_fit, -1.0, 0.0);
  for (int j = 0; j < arc_links; ++j) {
    const double a = kPi / 2 + j * kPi / arc_links;
    put(bend_fit * std::cos(a), bend_fit * std::sin(a), -std::sin(a), std::cos(a));
  }
  ASSERT_EQ(i, n);
  // the pluck: the upper span's nodes displaced outwards in a triangle peaking at 1/6 of it, where
  // mode 3 has its crest (on the string at rest a triangle at a gives mode n a share sin(nπa)/n²:
  // mode 3 gets 0.22 of mode 1's at a = 1/6, 0.18 at 1/5)
  const double amplitude = 1e-3 * span, pluck = span / 6.0;
  for (std::size_t j = 0; j < n; ++j) {
    if (!(s.y[j] > 0.0) || s.x[j] <= 0.0 || s.x[j] >= span) continue;
    const double x = s.x[j];
    s.y[j] += x < pluck ? amplitude * x / pluck : amplitude * (span - x) / (span - pluck);
  }
  ASSERT_TRUE(validate(model, s).empty());
  const double h = 5e-4;
  Integrator integ(model, {.step = h, .theta = 0.6});
  // the upper span's height at a fixed x (the chain's polyline there), as it runs past: at 1/6 of
  // the span too, mode 3's crest (the moving string's modes have fixed envelopes |sin(nπx/L)|)
  const double probe = span / 6.0;
  std::vector<double> signal;
  double speed_sum = 0.0;  // the loop's speed, measured at node 0, over the recording
  for (int step = 0; step < 8000; ++step) {
    ASSERT_TRUE(integ.step(model, s).converged) << step;
    speed_sum += std::hypot(s.vx[0], s.vy[0]);
    double y = NAN;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t e = (j + 1) % n;
      if (!(s.y[j] > 0.0 && s.y[e] > 0.0)) continue;
      const double x0 = s.x[j], x1 = s.x[e];
      if ((x0 - probe) * (x1 - probe) > 0.0 || x0 == x1) continue;
      y = s.y[j] + (probe - x0) / (x1 - x0) * (s.y[e] - s.y[j]);
      break;
    }
    ASSERT_TRUE(std::isfinite(y)) << step;
    signal.push_back(y - bend_fit);
  }
  // The loop is not driven: each roller running onto an arc meets it at the chord's angle
  // (l/R = 0.02 rad) and the θ-method takes a little of that impact, so the loop slows by about
  // 3 % over the 4 s (with contact damping it stopped within seconds on small arcs). The formula
  // takes the speed measured over the recording.
  const double speed = speed_sum / static_cast<double>(signal.size());
  EXPECT_NEAR(speed / v, 1.0, 0.05);
  const double f1 = c / (2.0 * span) * (1.0 - speed * speed / (c * c));
  // the three strongest peaks up to 4.5 f1: modes 1, 2, 3 (the next, at 1.09 f1 and 0.73 of mode
  // 3's height, is not the span's: not identified, every set-up tried showed it at 1.09 f1)
  const std::vector<double> peaks = testing::spectral_peaks(signal, h, 1.0, 4.5 * f1, 3);
  ASSERT_EQ(peaks.size(), 3u);
  for (int m = 1; m <= 3; ++m) {
    const double discrete = discrete_moving_span_frequency(m, kSpanLinks, span, c, speed);
    EXPECT_NEAR(peaks[m - 1] / (m * f1), 1.0, kFrequencyTol)
        << "mode " << m << ": " << peaks[m - 1] << " Hz against the continuous " << m * f1;
    EXPECT_NEAR(peaks[m - 1] / discrete, 1.0, kFrequencyTol)
        << "mode " << m << ": " << peaks[m - 1] << " Hz against the discrete " << discrete;
  }
  // and not the stationary span's: the speed's factor 1 − v²/c² ≈ 0.76 shows
  EXPECT_LT(peaks[0], 0.9 * c / (2.0 * span));
}

}  // namespace
}  // namespace catena::dynamics
