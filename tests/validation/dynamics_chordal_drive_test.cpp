// Polygonal action with a second sprocket as the span's far end (issue 21 validation (1);
// docs/models/dynamics.md, "A second wheel as the far end"): a drive's tight span between two
// sprockets, the driver at constant speed, the driven wheel's speed against the four-bar
// kinematics of a rigid chain over the two pitch polygons.
//
// The reference (independent of the model): with a rigid chain the tight span is a bar of n
// pitches between the driver's last seated roller A and the driven wheel's first seated roller B,
// on the two pitch polygons' upper common tangent — a four-bar linkage whose closure |AB| = n p
// gives the driven wheel's angle θ2 from the driver's θ1, n changing by one as a roller seats on
// the driver or leaves the driven wheel (the classical kinematics of the chain drive, e.g. R. C.
// Binder, Mechanics of the Roller Chain Drive, 1956 — followed for the set-up, not checked
// against that text). Known limits, checked below on the reference itself: equal wheels with a
// span of an integer number of pitches turn at a constant ratio (the four-bar a parallelogram);
// at a half-integer span the driven wheel lags half a tooth and ω2/ω1 runs between cos(π/z) and
// 1/cos(π/z), the variation 1 − min/max → sin²(π/z); over a tooth period the mean is z1/z2.
//
// The elastic four-bar (`closure` with the span's compliance; the doc's "The elastic four-bar"):
// the span's length follows its tension's once-per-tooth swing, T from the driven wheel's torque
// balance, C from the span's links and the two seat contacts in series; checked against its own
// limits (infinitely stiff: the rigid four-bar; a static stretch in closed form) and its
// compliance against the model's, measured statically.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "chordal_run.hpp"

namespace catena::dynamics {
namespace {

using chordal::simulated_profile;
using chordal::variation_of;
constexpr double kPi = std::numbers::pi;

// The two pitch polygons: radii, centre distance (driven wheel at (c, 0)), pitch [m], teeth; and
// the play of the span's end rollers in their seats (`seat_play`; 0: the rollers at the seat
// centres, the rigid chain's classical four-bar).
struct Polygons {
  double r1, r2, c, p;
  int z1, z2;
  double play = 0.0;  // [m] the two end rollers' shifts along the span, towards each other
  // The elastic span (below, `closure`; `elastic` sets it): its end-to-end compliance C [m/N]
  // (0: the rigid chain), the tension T1 at which its links are p long and the slack tail's
  // tension T2 [N]
  double compliance = 0.0;
  double tight = 0.0, slack = 0.0;
};

// Wheel w's vertex i (any integer) at θ + 2π i/z on its pitch circle.
std::array<double, 2> vertex(const Polygons& g, int wheel, double theta, int i) {
  const int z = wheel == 0 ? g.z1 : g.z2;
  const double r = wheel == 0 ? g.r1 : g.r2, a = theta + 2 * kPi * i / z;
  return {(wheel == 0 ? 0.0 : g.c) + r * std::cos(a), r * std::sin(a)};
}

// The upper common tangent at (θ1, θ2): the driver's vertex i and the driven's vertex j with the
// neighbours of both on or below the line from the first to the second (for convex polygons, every
// vertex then is), and its length. Searched within two vertices of those nearest the top: the
// tangent's tilt, asin((R2 − R1)/C), is under a tooth in every case here.
struct Tangent {
  int i = 0, j = 0;
  double length = NAN;
};
Tangent upper_tangent(const Polygons& g, double t1, double t2) {
  const int i0 = static_cast<int>(std::lround((kPi / 2 - t1) * g.z1 / (2 * kPi)));
  const int j0 = static_cast<int>(std::lround((kPi / 2 - t2) * g.z2 / (2 * kPi)));
  for (int i = i0 - 2; i <= i0 + 2; ++i) {
    const auto a = vertex(g, 0, t1, i);
    for (int j = j0 - 2; j <= j0 + 2; ++j) {
      const auto b = vertex(g, 1, t2, j);
      const double ux = b[0] - a[0], uy = b[1] - a[1];
      auto below = [&](std::array<double, 2> v) {
        return ux * (v[1] - a[1]) - uy * (v[0] - a[0]) <= 1e-12;
      };
      if (below(vertex(g, 0, t1, i - 1)) && below(vertex(g, 0, t1, i + 1)) &&
          below(vertex(g, 1, t2, j - 1)) && below(vertex(g, 1, t2, j + 1)))
        return {i, j, std::hypot(ux, uy)};
    }
  }
  ADD_FAILURE() << "no upper common tangent at " << t1 << ", " << t2;
  return {};
}

// The four-bar's closure f = |AB| − play − n p (the rollers' centres on the line AB, the end
// rollers `play` in from their seats' centres together). A seated roller keeps its vertex, so the
// span's link count is n = i − j + k, k fixed by the start (on both wheels the vertex index falls
// towards the span and rises away from it). f is continuous through the seat switches — a roller
// seats on the driver as A, A', B come in line: n and |AB| drop by one and p; one leaves the driven
// wheel as A, B, B' come in line: both grow — and falls as θ2 grows (B moves towards A), by p a
// tooth.
//
// The elastic span (g.compliance = C > 0; the doc's "The elastic four-bar"): the links are p long
// at T1 and the span stretches by C (T − T1), so f = |AB| − play − n p − C (T − T1). C is the
// end-to-end compliance of the span's links and the two end rollers' seat contacts in series,
// C = n̄/k + 2/k_c, with n̄ the tangent's length in pitches — the span's mean link count, held
// through the tooth: with n itself f would jump by (T − T1)/k at every seat switch, where the link
// that seats or leaves still carries most of the span's tension (the model's static compliance
// is 6–12 % over C: `ModelStaticStretchIsTheSpansCompliance`). T is the driven wheel's torque
// balance, quasi-static: the span pulls B along the line AB at the arm d2, the driven centre's
// distance below the line; the slack tail, pulled along −x at T2 from the wheel's lowest vertex,
// at the arm d2s, that vertex's depth below the centre; the load is (T1 − T2) R2, so
// T d2 − T2 d2s = (T1 − T2) R2. T swings once a tooth by about (T1 + T2)(1 − cos(π/z2)) (T1 R2/d2,
// and at odd z2 the tail's arm in the opposite phase). Left out: the inertia torque J_eff θ̈2
// (0.5–1.2 % of the swing in the cases here) and so the wheel's torsional ring. C → 0 is the
// rigid four-bar; C T1 ≪ p keeps f monotone in θ2.
double closure(const Polygons& g, double t1, double t2, int k) {
  const Tangent t = upper_tangent(g, t1, t2);
  double stretch = 0.0;
  if (g.compliance > 0) {
    const auto a = vertex(g, 0, t1, t.i), b = vertex(g, 1, t2, t.j);
    const double ux = (b[0] - a[0]) / t.length, uy = (b[1] - a[1]) / t.length;
    const double arm = ux * a[1] + uy * (g.c - a[0]);  // d2: (C2 − A) × û
    double low = 0.0;                                  // d2s / R2
    for (int j = 0; j < g.z2; ++j) low = std::max(low, -std::sin(t2 + 2 * kPi * j / g.z2));
    const double tension = ((g.tight - g.slack) * g.r2 + g.slack * g.r2 * low) / arm;
    stretch = g.compliance * (tension - g.tight);
  }
  return t.length - g.play - (t.i - t.j + k) * g.p - stretch;
}

// θ2 with f(θ1, θ2) = 0 by bisection, bracketed from half a driven tooth either side of `guess`
double driven_angle(const Polygons& g, double t1, int k, double guess) {
  const double tooth = 2 * kPi / g.z2;
  double lo = guess - 0.5 * tooth, hi = guess + 0.5 * tooth;
  for (int it = 0; it < 4 && !(closure(g, t1, lo, k) > 0); ++it) lo -= tooth;
  for (int it = 0; it < 4 && !(closure(g, t1, hi, k) < 0); ++it) hi += tooth;
  if (!(closure(g, t1, lo, k) > 0 && closure(g, t1, hi, k) < 0)) {
    ADD_FAILURE() << "no closure within four teeth of " << guess;
    return NAN;
  }
  for (int it = 0; it < 200 && hi - lo > 1e-14; ++it) {
    const double mid = 0.5 * (lo + hi);
    (closure(g, t1, mid, k) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The reference's mean ω2/ω1 over `bins` equal bins of the driver's tooth phase (phase 0: a
// driver vertex at the top, θ1 = π/2 mod 2π/z1), exactly Δθ2/Δθ1 over each bin; shifted by
// `shift` of a tooth (the checks that the comparison can fail).
std::vector<double> kinematic_ratio(const Polygons& g, int k, int bins, double shift = 0.0) {
  const double tooth = 2 * kPi / g.z1, start = kPi / 2 + shift * tooth;
  std::vector<double> out;
  double prev = driven_angle(g, start, k, kPi / 2);
  for (int b = 1; b <= bins; ++b) {
    const double t2 = driven_angle(g, start + tooth * b / bins, k, prev);
    out.push_back((t2 - prev) / (tooth / bins));
    prev = t2;
  }
  return out;
}

// The set-up. The tight span's tension T1 is set by one rule (below, `tight_off_harmonics`), the
// driven wheel's load torque (T1 − T2) R2 asks for it.
struct FarWheel {
  int driver_teeth = 17;       // z1
  int driven_teeth = 17;       // z2
  double centre = 20.0;        // [pitches] the centre distance
  double pitch = 0.01905;      // [m] 12B
  double roller = 0.01207;     // [m] d1
  double width = 0.01168;      // [m] b1
  double node_mass = 0.0238;   // [kg] 1.25 kg/m
  double stiffness = 5e7;      // [N/m] per link
  double damping = 2000.0;     // [N·s/m] per link
  double tight = 0.0;          // [N] T1
  double slack = 50.0;         // [N] T2, the slack side's constant tension at both cut ends
  double inertia = 0.002;      // [kg·m²] the driven wheel
  double chain_speed = 0.05;   // [m/s]
  double seat_friction = 0.3;  // μ
  double contact = 2e8;        // [N/m] k_c, the seats' contact stiffness
  double settle = 0.1;         // [s]
  int periods = 8;             // tooth periods measured after the settling time
  double step = 1e-4;          // [s]
};

Polygons polygons(const FarWheel& d) {
  return {0.5 * d.pitch / std::sin(kPi / d.driver_teeth),
          0.5 * d.pitch / std::sin(kPi / d.driven_teeth),
          d.centre * d.pitch,
          d.pitch,
          d.driver_teeth,
          d.driven_teeth};
}

// The end rollers' play in their seats, both ends together [m]. A roller of radius r in a seating
// arc of radius r_i ≥ r (ISO 606), pulled along the span's direction û, rests where the contact's
// normal is along the pull: its centre at the seat's centre + (r_i − r) û. The driver's end roller
// A is pulled towards B and the driven wheel's B towards A, so both centres lie on the line AB,
// (r_i − r) in from their vertices. The seats' dimensions are the model's (iso606_sprocket).
double seat_play(const FarWheel& d) {
  auto gap = [&](int teeth) {
    const Sprocket w = iso606_sprocket(d.pitch, d.roller, d.width, teeth, 0.0, 0.0, 1.0, 0.0);
    return w.seat_radius - w.roller_radius;
  };
  return gap(d.driver_teeth) + gap(d.driven_teeth);
}

// the span's length between the pitch circles' tangent points [m]
double tangent_length(const Polygons& g) {
  return std::sqrt(g.c * g.c - (g.r2 - g.r1) * (g.r2 - g.r1));
}

// the polygons with the elastic span of the set-up (`closure`)
Polygons elastic(const FarWheel& d, Polygons g) {
  g.compliance = tangent_length(g) / g.p / d.stiffness + 2 / d.contact;
  g.tight = d.tight;
  g.slack = d.slack;
  return g;
}

// k: the span's link count at the start (A at the top), the tangent's length in pitches rounded
// down
int count_constant(const Polygons& g) {
  return static_cast<int>(std::floor(tangent_length(g) / g.p));
}

// T1 such that the tight span's first transverse mode (a string fixed at the two wheels, f_n =
// n c/2L, c = √(T1/q)) is f1 = 4.75 tooth frequencies (v/p): between the 4th and 5th tooth
// harmonics, so that f1, f2, f3 = 4.75, 9.5, 14.25 v/p each lie a quarter of the tooth frequency
// from the nearest harmonic, the free span's modes off every harmonic as the far end on rails
// places them (dynamics_chordal_slow_test.cpp, there 3.75). The instance matters: 3.75 and 5.75
// meet the same criterion and fail (the doc's "A second wheel as the far end"). The polygons move
// the span's ends across at the tooth frequency; at f1 = 5 v/p (T1 = 500 N at 0.1 m/s and 20
// pitches) the swing resonates with the 5th harmonic and the driven speed carries its
// foreshortening at 2 f1, growing over the run (measured with J = 0.01 kg·m²: the speed's
// standard deviation 0.5 % of its mean at 0.5 s, 3 % at 2 s).
FarWheel tight_off_harmonics(FarWheel d) {
  const double wave = 2 * 4.75 * d.chain_speed * tangent_length(polygons(d)) / d.pitch;
  d.tight = d.node_mass / d.pitch * wave * wave;
  return d;
}

// The model: the two ISO 606 wheels (clearance seats with μ, contacts as in the drive's
// validation), the driver at constant ω1, the driven wheel with inertia and a load torque. The
// chain is open: the slack span is cut and its two ends pulled apart at T2 (Model::loads) — a
// constant-tension take-up, so that the slack side's length changes take nothing from the tight
// span, which the four-bar assumes; no gravity. Laid at the reference's start (θ1 = π/2, θ2 from
// the closure), the tight span straight from A to B, each wheel wrapped to its vertex nearest the
// bottom and a straight tail on from there. `run` returns the driver's tooth phase and ω2/ω1 at
// every step after the settling time (chordal::Result's phase and span). `lay` builds the model and
// its start, with the nodes of the span's end rollers A (on the driver) and B (on the driven
// wheel); the chain's tails are long enough for `duration`.
struct Laid {
  Model model;
  State state;
  std::size_t a = 0, b = 0;
};
Laid lay(const FarWheel& d, int k, double duration) {
  const Polygons g = polygons(d);
  const double omega1 = d.chain_speed / g.r1, v = d.chain_speed;
  const double rest = d.pitch - d.tight / d.stiffness;  // the tight span's links at p
  const double t1 = kPi / 2, t2 = driven_angle(g, t1, k, kPi / 2);
  const double h = 1e-6;  // the driven wheel's start speed: the reference's ratio there
  const double omega2 = omega1 * (driven_angle(g, t1 + h, k, t2) - t2) / h;
  const Tangent tan = upper_tangent(g, t1, t2);
  const int n = tan.i - tan.j + k;
  const int tail = static_cast<int>(std::ceil(duration * v / d.pitch)) + 3;
  std::vector<std::array<double, 4>> nodes;  // x, y, vx, vy from the driver's cut end
  auto seated = [&](int wheel, double theta, double omega, int i) {
    const auto q = vertex(g, wheel, theta, i);
    const double cx = wheel == 0 ? 0.0 : g.c;
    return std::array<double, 4>{q[0], q[1], -omega * q[1], omega * (q[0] - cx)};
  };
  const int bottom1 = static_cast<int>(std::lround((1.5 * kPi - t1) * g.z1 / (2 * kPi)));
  const auto b1 = vertex(g, 0, t1, bottom1);
  for (int q = 3; q >= 1; --q) nodes.push_back({b1[0] + q * rest, b1[1], v, 0.0});
  for (int i = bottom1; i >= tan.i; --i) nodes.push_back(seated(0, t1, omega1, i));
  Laid out;
  out.a = nodes.size() - 1;
  out.b = out.a + static_cast<std::size_t>(n);
  const auto a = seated(0, t1, omega1, tan.i), b = seated(1, t2, omega2, tan.j);
  for (int q = 1; q < n; ++q) {
    const double s = static_cast<double>(q) / n;
    std::array<double, 4> p{};
    for (int c = 0; c < 4; ++c) p[c] = a[c] + s * (b[c] - a[c]);
    nodes.push_back(p);
  }
  const int bottom2 = static_cast<int>(std::lround((-0.5 * kPi - t2) * g.z2 / (2 * kPi)));
  for (int j = tan.j; j >= bottom2; --j) nodes.push_back(seated(1, t2, omega2, j));
  const auto b2 = vertex(g, 1, t2, bottom2);
  for (int q = 1; q <= tail; ++q) nodes.push_back({b2[0] - q * rest, b2[1], v, 0.0});

  const std::size_t count = nodes.size();
  out.model = uniform_chain(count, false, rest, d.node_mass, d.stiffness, d.damping, false);
  Sprocket w1 =
      iso606_sprocket(d.pitch, d.roller, d.width, d.driver_teeth, 0.0, 0.0, d.contact, 800.0);
  w1.driver = true;
  w1.speed = omega1;
  w1.friction = d.seat_friction;
  Sprocket w2 =
      iso606_sprocket(d.pitch, d.roller, d.width, d.driven_teeth, g.c, 0.0, d.contact, 800.0);
  w2.inertia = d.inertia;
  w2.load_torque = (d.tight - d.slack) * g.r2;
  w2.friction = d.seat_friction;
  out.model.sprockets = {w1, w2};
  out.model.loads = {{.node = 0, .fx = d.slack, .fy = 0.0},
                     {.node = count - 1, .fx = -d.slack, .fy = 0.0}};
  State& s = out.state;
  s = State(count, 2);
  for (std::size_t i = 0; i < count; ++i) {
    s.x[i] = nodes[i][0];
    s.y[i] = nodes[i][1];
    s.vx[i] = nodes[i][2];
    s.vy[i] = nodes[i][3];
  }
  s.angle = {t1, t2};
  s.speed = {omega1, omega2};
  return out;
}

chordal::Result run(const FarWheel& d, int k) {
  const Polygons g = polygons(d);
  const double omega1 = d.chain_speed / g.r1, v = d.chain_speed;
  const double duration = d.settle + d.periods * d.pitch / v;
  Laid laid = lay(d, k, duration);
  Model& model = laid.model;
  State& s = laid.state;
  // the driver's cut end, pulled along the bottom towards the driven wheel, must not reach its
  // teeth within the run (at 0.05 m/s, 12/25 at 20 p: about 4.9 s; the run is 3.15 s)
  const double reach = contact_reach(model.sprockets[1]);
  Integrator integ(model, {.step = d.step, .theta = 0.6});
  chordal::Result out;
  const double tooth = 2 * kPi / d.driver_teeth;
  const int steps = static_cast<int>(std::lround(duration / d.step));
  for (int q = 0; q < steps; ++q) {
    if (!integ.step(model, s).converged) {
      ADD_FAILURE() << "step " << q << " did not converge";
      out.converged = false;
      break;
    }
    if (std::hypot(s.x[0] - g.c, s.y[0]) < reach) {
      ADD_FAILURE() << "the driver's cut end reaches the driven wheel's teeth at " << s.time
                    << " s: shorten the run";
      out.converged = false;
      break;
    }
    if (s.time < d.settle) continue;
    double ph = std::fmod(s.angle[0] - kPi / 2, tooth) / tooth;
    if (ph < 0) ph += 1;
    out.phase.push_back(ph);
    out.span.push_back(s.speed[1] / omega1);
  }
  return out;
}

// the largest |a − b| over the bins
double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0.0;
  for (std::size_t q = 0; q < a.size(); ++q) worst = std::max(worst, std::abs(a[q] - b[q]));
  return worst;
}

// The reference against its known limits (the header): the parallelogram's constant ratio, the
// half-integer span's sin²(π/z) (the ratio is continuous at a seat switch, its slope jumps: the
// extremes are kinks, and 2000 bins' means flatten them by about 7e-4 of the variation; the
// span's tilt takes about 5e-5), and the mean z1/z2 (a tooth of the driver turns the driven wheel
// by a tooth).
TEST(DynamicsChordalDrive, FourBarReferenceHasTheKnownLimits) {
  for (int z : {9, 17, 25}) {
    FarWheel d;
    d.driver_teeth = d.driven_teeth = z;
    const Polygons whole = polygons(d);
    const std::vector<double> parallel = kinematic_ratio(whole, count_constant(whole), 40);
    EXPECT_LT(variation_of(parallel), 1e-9) << "z " << z;
    d.centre = 20.5;
    const Polygons half = polygons(d);
    const double var = variation_of(kinematic_ratio(half, count_constant(half), 2000));
    const double s = std::sin(kPi / z);
    std::printf("z %d: half-integer span %.6f, sin^2(pi/z) %.6f\n", z, var, s * s);
    EXPECT_NEAR(var / (s * s), 1.0, 0.005) << "z " << z;
  }
  FarWheel d;
  d.driver_teeth = 12;
  d.driven_teeth = 25;
  const Polygons g = polygons(d);
  const std::vector<double> ratio = kinematic_ratio(g, count_constant(g), 40);
  double mean = 0.0;
  for (const double r : ratio) mean += r / 40;
  EXPECT_NEAR(mean, 12.0 / 25.0, 1e-9);
}

// Validation (1) with a second wheel as the far end: the driven wheel's speed ω2/ω1, averaged
// synchronously over 20, 40, 80 bins of the driver's tooth phase, against the four-bar's bin means
// (kinematic_ratio) with the end rollers' seat play (seat_play), at z1 = z2 = 17 with the span 20
// pitches (nearly a parallelogram: near-constant ratio), 20.25 (where the variation is most
// sensitive to the span) and 20.5 (the largest variation, sin²(π/z) = 0.0338 unbinned, stationary
// in the span), z1 = 12, z2 = 25 and the speed-up drive 25/12 at 20 pitches (no closed form: the
// four-bar only). 0.05 m/s (why, and the measured table: the doc's "A second wheel as the far
// end"). Tolerances: where the four-bar varies, its variation 1 − min/max within validation (1)'s
// 2 % and every bin within 5 % of its range (max − min) — the profile's shape and phase; at the
// integer span of equal wheels the driven wheel's variation under a tenth of the half-integer
// span's, sin²(π/z). Three known misses are asserted as such (sign and size; `miss`, the largest
// excess allowed): 17/17 at 20.75 pitches is over the four-bar by up to 2.1 %, 12/25 at 20.5 by
// up to 2.3 %, and 9/9 at 20.5 rings at 80 bins (7.5 % over). What would fail: the single wheel's
// form (the level span's, binned; 1 − cos(π/z) unbinned) and the four-bar half a tooth off — each
// checked below to lie outside the tolerance it replaces.
TEST(DynamicsChordalDrive, DrivenSpeedFollowsTheFourBar) {
  constexpr double kTol = 0.02, kShape = 0.05, kParallel = 0.1;
  struct Case {
    int z1, z2;
    double centre;
    double miss = 0.0;    // a known miss: the variation over the four-bar's by more than kTol at
                          // some bin count, by at most `miss`, and never under it by kTol
    int shape_bins = 80;  // the largest bin count whose shape is asserted
  };
  // 25/12's 80-bin shape is not converged in the step (4.5 % of the range at 1e-4 s, 9.3 % at
  // 5e-5 s: the bins after the driven wheel's seat switch)
  const std::vector<Case> cases = {
      {17, 17, 20.0},          {17, 17, 20.25},       {17, 17, 20.5},       {12, 25, 20.0},
      {25, 12, 20.0, 0.0, 40}, {17, 17, 20.75, 0.04}, {12, 25, 20.5, 0.04}, {9, 9, 20.5, 0.1}};
  for (const Case c : cases) {
    FarWheel d;
    d.driver_teeth = c.z1;
    d.driven_teeth = c.z2;
    d.centre = c.centre;
    d = tight_off_harmonics(d);
    // the rule gives T1 ∝ v²: at a lower speed the "tight" span would be slacker than the cut
    // slack side
    ASSERT_GT(d.tight, d.slack) << "T1 under T2 at " << d.chain_speed << " m/s";
    Polygons g = polygons(d);
    g.play = seat_play(d);
    const int k = count_constant(g);
    const chordal::Result r = run(d, k);
    ASSERT_TRUE(r.converged) << c.z1 << "/" << c.z2 << " at " << c.centre;
    const double half = std::pow(std::sin(kPi / c.z1), 2);
    const bool parallel = c.z1 == c.z2 && c.centre == std::floor(c.centre);
    double over = -1.0;  // the largest var / four-bar − 1 over the bin counts
    for (int bins : {20, 40, 80}) {
      const std::vector<double> kin = kinematic_ratio(g, k, bins), sim = simulated_profile(r, bins);
      const std::vector<double> shifted = kinematic_ratio(g, k, bins, 0.5);
      const double range =
          *std::max_element(kin.begin(), kin.end()) - *std::min_element(kin.begin(), kin.end());
      const double var = variation_of(sim), four_bar = variation_of(kin);
      const double single = chordal::binned_variation(c.z1, bins);
      double mean = 0.0;
      for (const double v : sim) mean += v / bins;
      std::printf(
          "z %d/%d, %.2f p, T1 %.1f N, %d bins: driven %.5f, four-bar %.5f (%.4f), single wheel "
          "%.5f; largest difference %.2e (%.4f of the range), half a tooth off %.2e; mean %.6f "
          "(z1/z2 %.6f)\n",
          c.z1, c.z2, c.centre, d.tight, bins, var, four_bar, var / four_bar, single,
          largest_difference(sim, kin), parallel ? NAN : largest_difference(sim, kin) / range,
          largest_difference(sim, shifted), mean, double(c.z1) / c.z2);
      const std::string where = std::to_string(c.z1) + "/" + std::to_string(c.z2) + " at " +
                                std::to_string(c.centre) + " p, " + std::to_string(bins) + " bins";
      EXPECT_NEAR(mean * c.z2 / c.z1, 1.0, 1e-4) << where;
      // the single wheel's form would fail
      EXPECT_GT(std::abs(var / single - 1), kTol) << where;
      if (parallel) {
        EXPECT_LT(var, kParallel * half) << where;
        EXPECT_GT(single, kParallel * half) << where;
        continue;
      }
      over = std::max(over, var / four_bar - 1);
      // half a tooth off would fail
      EXPECT_GT(largest_difference(sim, shifted), kShape * range) << where;
      if (c.miss > 0) {
        EXPECT_GT(var / four_bar - 1, -kTol) << where;
        EXPECT_LT(var / four_bar - 1, c.miss) << where;
        continue;
      }
      EXPECT_NEAR(var / four_bar, 1.0, kTol) << where;
      if (bins <= c.shape_bins) {
        EXPECT_LT(largest_difference(sim, kin), kShape * range) << where;
      }
    }
    // still a miss: when it passes, it belongs with the cases above (and out of the doc's list)
    if (c.miss > 0) {
      EXPECT_GT(over, kTol) << c.z1 << "/" << c.z2 << " at " << c.centre << " p";
    }
  }
}

TEST(DynamicsChordalDrive, ElasticFourBarHasItsLimits) {
  for (const auto& [z1, z2, centre] : std::vector<std::tuple<int, int, double>>{
           {17, 17, 20.25}, {17, 17, 20.75}, {12, 25, 20.5}, {25, 12, 20.0}}) {
    FarWheel d;
    d.driver_teeth = z1;
    d.driven_teeth = z2;
    d.centre = centre;
    d.chain_speed = 0.1;
    d = tight_off_harmonics(d);
    Polygons g = polygons(d);
    g.play = seat_play(d);
    const int k = count_constant(g);
    // infinitely stiff: the rigid four-bar
    d.stiffness = d.contact = 1e18;
    const std::vector<double> rigid = kinematic_ratio(g, k, 40);
    EXPECT_LT(largest_difference(kinematic_ratio(elastic(d, g), k, 40), rigid), 1e-9)
        << z1 << "/" << z2 << " at " << centre << " p";
    // and as set up it differs: the span's stretch moves the ratio by a percent of the range
    d.stiffness = FarWheel{}.stiffness;
    d.contact = FarWheel{}.contact;
    const double range = *std::max_element(rigid.begin(), rigid.end()) -
                         *std::min_element(rigid.begin(), rigid.end());
    EXPECT_GT(largest_difference(kinematic_ratio(elastic(d, g), k, 40), rigid), 0.005 * range)
        << z1 << "/" << z2 << " at " << centre << " p";
  }
  // The static stretch in closed form: equal wheels at an integer span, A on the driver's top
  // vertex (θ1 = π/2). With B on the driven wheel's top vertex the span is level and n p = C long;
  // turned by δ, |AB| = C − R δ + O(δ²) and the arm d2 = R + O(δ); the lowest vertex of an odd
  // wheel lies half a tooth off the bottom, d2s = R cos(π/z), so T = T1 − T2 (1 − cos(π/z)) and
  // the closure gives δ = −C_s (T − T1)/R = C_s T2 (1 − cos(π/z))/R, C_s = n/k + 2/k_c: the span
  // shorter than n p, the driven wheel ahead of the rigid four-bar's π/2.
  for (int z : {9, 17, 25}) {
    FarWheel d;
    d.driver_teeth = d.driven_teeth = z;
    d.tight = 485.0;
    const Polygons g = elastic(d, polygons(d));
    const int k = count_constant(g);
    const Tangent t = upper_tangent(g, kPi / 2, kPi / 2);
    ASSERT_EQ(t.i - t.j + k, 20) << "z " << z;
    const double cs = 20 / d.stiffness + 2 / d.contact;
    const double delta = cs * d.slack * (1 - std::cos(kPi / z)) / g.r2;
    const double got = driven_angle(g, kPi / 2, k, kPi / 2) - kPi / 2;
    std::printf("z %d: static turn %.6e rad, closed form %.6e\n", z, got, delta);
    EXPECT_NEAR(got / delta, 1.0, 1e-3) << "z " << z;
  }
}

// The model's own end-to-end compliance, measured statically: the driver held (ω1 = 0), the driven
// wheel's load torque stepped from (T1 − T2) R2 to (T1 + 10 N − T2) R2, each run 0.4 s from the
// lay (A on the driver's top vertex; the closure moves by under 1 % of the step's stretch from
// 0.4 to 1.2 s); the stretch is the rigid four-bar's closure f = |AB| − play − n p at the settled
// θ2 (the span's length beyond the rigid one's, its ends included). At the two tensions the
// comparisons run at (the rule's T1 at 0.05 and 0.1 m/s, 17/17 at 20.75 pitches, n = 21 links at
// the lay): the span's own links stretch as n/k; the whole is over the reference's compliance
// C = n̄/k + 2/k_c (`elastic`, n̄ = 20.75) by 6–10 % (4.50e-7 and 4.65e-7 m/N against 4.25e-7;
// 4.47–4.76e-7 over the tooth's phases, probed), and the two ends, the whole less the links,
// take more than their contacts' 2/k_c (their wrap links share the step: 2.8e-8 and 4.4e-8 m/N
// against 1e-8) — the parts the reference leaves out, within 15 % of it.
TEST(DynamicsChordalDrive, ModelStaticStretchIsTheSpansCompliance) {
  for (double speed : {0.05, 0.1}) {
    FarWheel d;
    d.centre = 20.75;
    d.chain_speed = speed;
    d = tight_off_harmonics(d);
    Polygons g = polygons(d);
    g.play = seat_play(d);
    const int k = count_constant(g);
    std::array<double, 2> stretch{}, links{};
    std::size_t n = 0;
    for (int q = 0; q < 2; ++q) {
      Laid l = lay(d, k, 0.1);
      n = l.b - l.a;
      l.model.sprockets[0].speed = 0.0;
      l.model.sprockets[1].load_torque = (d.tight + 10.0 * q - d.slack) * g.r2;
      std::fill(l.state.vx.begin(), l.state.vx.end(), 0.0);
      std::fill(l.state.vy.begin(), l.state.vy.end(), 0.0);
      l.state.speed = {0.0, 0.0};
      Integrator integ(l.model, {.step = d.step, .theta = 0.6});
      for (int s = 0; s < 4000; ++s) ASSERT_TRUE(integ.step(l.model, l.state).converged);
      stretch[q] = closure(g, l.state.angle[0], l.state.angle[1], k);
      for (std::size_t i = l.a; i < l.b; ++i) {
        links[q] += std::hypot(l.state.x[i + 1] - l.state.x[i], l.state.y[i + 1] - l.state.y[i]);
      }
    }
    const double model = (stretch[1] - stretch[0]) / 10.0, span = (links[1] - links[0]) / 10.0;
    const double links_only = static_cast<double>(n) / d.stiffness;
    const double reference = elastic(d, g).compliance;
    std::printf(
        "T1 %.1f N, n %zu: the model's compliance %.4e m/N (its span's links %.4e, n/k "
        "%.4e; the ends %.4e, 2/k_c %.4e), the reference's %.4e: %.4f\n",
        d.tight, n, model, span, links_only, model - span, 2 / d.contact, reference,
        model / reference);
    EXPECT_NEAR(span / links_only, 1.0, 0.02) << speed;
    EXPECT_GT(model - span, 2 / d.contact) << speed;
    EXPECT_GT(model / reference, 1.0) << speed;
    EXPECT_LT(model / reference, 1.15) << speed;
  }
}

// The driven wheel's speed against the elastic four-bar (`closure` with the span's compliance):
// the cases the rigid four-bar misses by more than 2 % that it brings within 2 % — the variation
// at every bin count listed, and every bin within 5 % of the range up to `shape_bins` (the finer
// profiles' shapes move with the step: at 5e-5 s 9/9's 40-bin shape goes from 3.7 to 5.9 % of the
// range, 17/17's 80-bin ones from 2.3 and 3.9 to 4.4 and 4.8 %; the variations move by under
// 0.7 %). 17/17 at 20.75 pitches at 0.05 m/s (rigid: 2.1 % over); at 0.1 m/s 17/17 at 20.5
// pitches (rigid: 2.2–3.2 % over), and at 20 and 40 bins 17/17 at 20.25 pitches (rigid: 5.6 %
// under at 20 bins) and 9/9 at 20.5 pitches (rigid: 2.2, 2.6 % over) — at 80 bins these two are
// 3.9 and 5.4 % over the elastic four-bar: the torsional ring after the switches, which the
// reference leaves out. Asserted for each: the rigid four-bar misses.
TEST(DynamicsChordalDrive, DrivenSpeedFollowsTheElasticFourBar) {
  constexpr double kTol = 0.02, kShape = 0.05;
  struct Case {
    int z1, z2;
    double centre, speed;
    std::vector<int> bins;
    int shape_bins;  // the largest bin count whose shape is asserted
  };
  const std::vector<Case> cases = {{17, 17, 20.75, 0.05, {20, 40, 80}, 40},
                                   {17, 17, 20.5, 0.1, {20, 40, 80}, 40},
                                   {17, 17, 20.25, 0.1, {20, 40}, 40},
                                   {9, 9, 20.5, 0.1, {20, 40}, 20}};
  for (const Case& c : cases) {
    FarWheel d;
    d.driver_teeth = c.z1;
    d.driven_teeth = c.z2;
    d.centre = c.centre;
    d.chain_speed = c.speed;
    d = tight_off_harmonics(d);
    Polygons g = polygons(d);
    g.play = seat_play(d);
    const Polygons ge = elastic(d, g);
    const int k = count_constant(g);
    const chordal::Result r = run(d, k);
    const std::string name = std::to_string(c.z1) + "/" + std::to_string(c.z2) + " at " +
                             std::to_string(c.centre) + " p, " + std::to_string(c.speed) + " m/s";
    ASSERT_TRUE(r.converged) << name;
    double rigid_off = 0.0;  // the largest |var / rigid four-bar − 1| over the bin counts
    for (int bins : c.bins) {
      const std::vector<double> sim = simulated_profile(r, bins),
                                kel = kinematic_ratio(ge, k, bins);
      const std::vector<double> kin = kinematic_ratio(g, k, bins);
      const double range =
          *std::max_element(kel.begin(), kel.end()) - *std::min_element(kel.begin(), kel.end());
      const double var = variation_of(sim);
      std::printf(
          "%s, T1 %.1f N, %d bins: driven / elastic four-bar %.4f (rigid %.4f); largest "
          "difference %.4f of the range (rigid %.4f)\n",
          name.c_str(), d.tight, bins, var / variation_of(kel), var / variation_of(kin),
          largest_difference(sim, kel) / range, largest_difference(sim, kin) / range);
      EXPECT_NEAR(var / variation_of(kel), 1.0, kTol) << name << ", " << bins << " bins";
      if (bins <= c.shape_bins) {
        EXPECT_LT(largest_difference(sim, kel), kShape * range) << name << ", " << bins << " bins";
      }
      rigid_off = std::max(rigid_off, std::abs(var / variation_of(kin) - 1));
    }
    EXPECT_GT(rigid_off, kTol) << name << ": the rigid four-bar passes too";
  }
}

}  // namespace
}  // namespace catena::dynamics
