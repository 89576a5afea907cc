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
// limits (infinitely stiff: the rigid four-bar; a static stretch in closed form; the arms against
// the rigid kinematics), its compliance and its tension's swing over a tooth against the model's,
// measured statically.
//
// The span's longitudinal dynamics (`dynamic_ratio`): the elastic four-bar's θ2 through a linear
// one-degree-of-freedom model of the driven wheel on the span, solved harmonic by harmonic in the
// periodic steady state; the share of the model's 0.1 m/s excess over the elastic four-bar that it
// explains, and what the rest is (`SpeedExcessIsOnlyPartlyTheSpansLongitudinalDynamics`).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
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

// Wheel w's vertex nearest its bottom at θ, its index on the wrap's side of the span's (the index
// falls towards the span on both wheels: on the driver the bottom is at 3π/2 − θ above the top,
// on the driven wheel at π/2 + θ below; at a tie, an odd wheel with a vertex at the top, the
// rounding takes the vertex past the bottom along the wrap from the span), and the arm
// (C_w − A) × û of wheel w's centre C_w about the line through A along the unit û: the centre's
// distance below the line.
int lowest_vertex(const Polygons& g, int wheel, double theta) {
  const int z = wheel == 0 ? g.z1 : g.z2;
  const double bottom = wheel == 0 ? 1.5 * kPi : -0.5 * kPi;
  return static_cast<int>(std::lround((bottom - theta) * z / (2 * kPi)));
}
double arm(const Polygons& g, int wheel, std::array<double, 2> a, double ux, double uy) {
  return ux * a[1] + uy * ((wheel == 0 ? 0.0 : g.c) - a[0]);
}

// The span's tension T at (θ1, θ2) from the driven wheel's quasi-static torque balance (`closure`
// below): T d2 − T2 d2s = (T1 − T2) R2, d2 the arm of the driven centre about the line AB, d2s the
// depth of its lowest vertex, where the slack tail leaves along −x; t the upper tangent there.
double span_tension(const Polygons& g, double t1, double t2, const Tangent& t) {
  const auto a = vertex(g, 0, t1, t.i), b = vertex(g, 1, t2, t.j);
  const double d2 = arm(g, 1, a, (b[0] - a[0]) / t.length, (b[1] - a[1]) / t.length);
  const double low = -vertex(g, 1, t2, lowest_vertex(g, 1, t2))[1];  // d2s
  return ((g.tight - g.slack) * g.r2 + g.slack * low) / d2;
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
// is 5–12 % over C: `ModelStaticStretchIsTheSpansCompliance`). T is the driven wheel's torque
// balance, quasi-static (`span_tension`): the span pulls B along the line AB at the arm d2, the
// driven centre's distance below the line; the slack tail, pulled along −x at T2 from the wheel's
// lowest vertex, at the arm d2s, that vertex's depth below the centre; the load is (T1 − T2) R2,
// so T d2 − T2 d2s = (T1 − T2) R2. With equal wheels and a level span T swings once a tooth by
// about (T1 + T2)(1 − cos(π/z2)) (T1 R2/d2, and at odd z2 the tail's arm in the opposite phase);
// where the span tilts, the tilt shifts the tail's phase against the T1 term's (12/25 at 20.5
// pitches at 0.05 m/s: the tail takes 24 % off the swing; 25/12, 2–4 %). The tail's term is not
// confirmed by the model (`ModelStaticSwingFollowsTheTensionLaw`: without it the static swing's
// ratio is 1.31 at 485.5 N and 0.97 at 121.4 N, with it 1.19 and 0.69; the shape at 121.4 N is
// off either way). Left out: the inertia torque J_eff θ̈2 (0.5–1.2 % of the swing in the cases
// here) and so the wheel's torsional ring. C → 0 is the rigid four-bar; C T1 ≪ p keeps f
// monotone in θ2.
double closure(const Polygons& g, double t1, double t2, int k) {
  const Tangent t = upper_tangent(g, t1, t2);
  const double stretch =
      g.compliance > 0 ? g.compliance * (span_tension(g, t1, t2, t) - g.tight) : 0;
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
  // the tight span held straight after every step (`hold_straight`)
  bool hold_transverse = false;
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

// The set-up of a drive (z1/z2, the centre distance [pitches], the chain's speed [m/s]) with T1 by
// the rule above, its polygons with the seat play and the link count k at the start
struct Drive {
  FarWheel d;
  Polygons g;
  int k = 0;
};
Drive set_up(int z1, int z2, double centre, double speed) {
  Drive out;
  out.d.driver_teeth = z1;
  out.d.driven_teeth = z2;
  out.d.centre = centre;
  out.d.chain_speed = speed;
  out.d = tight_off_harmonics(out.d);
  out.g = polygons(out.d);
  out.g.play = seat_play(out.d);
  out.k = count_constant(out.g);
  return out;
}

// the run's length from the lay [s] (`run`): the settling time and the measured tooth periods
double run_duration(const FarWheel& d) { return d.settle + d.periods * d.pitch / d.chain_speed; }

// the links of each of the chain's straight tails (`lay`) for a run of `duration` [s]
int tail_links(const FarWheel& d, double duration) {
  return static_cast<int>(std::ceil(duration * d.chain_speed / d.pitch)) + 3;
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
// wheel); the chain's tails are long enough for `duration`; `phase` [teeth] lays it that far on
// (θ1 = π/2 + phase 2π/z1; the static scans).
struct Laid {
  Model model;
  State state;
  std::size_t a = 0, b = 0;
};
Laid lay(const FarWheel& d, int k, double duration, double phase = 0.0) {
  const Polygons g = polygons(d);
  const double omega1 = d.chain_speed / g.r1, v = d.chain_speed;
  const double rest = d.pitch - d.tight / d.stiffness;  // the tight span's links at p
  const double t1 = kPi / 2 + phase * 2 * kPi / d.driver_teeth;
  const double t2 = driven_angle(g, t1, k, kPi / 2 + phase * 2 * kPi / d.driven_teeth);
  const double h = 1e-6;  // the driven wheel's start speed: the reference's ratio there
  const double omega2 = omega1 * (driven_angle(g, t1 + h, k, t2) - t2) / h;
  const Tangent tan = upper_tangent(g, t1, t2);
  const int n = tan.i - tan.j + k;
  const int tail = tail_links(d, duration);
  std::vector<std::array<double, 4>> nodes;  // x, y, vx, vy from the driver's cut end
  auto seated = [&](int wheel, double theta, double omega, int i) {
    const auto q = vertex(g, wheel, theta, i);
    const double cx = wheel == 0 ? 0.0 : g.c;
    return std::array<double, 4>{q[0], q[1], -omega * q[1], omega * (q[0] - cx)};
  };
  const int bottom1 = lowest_vertex(g, 0, t1);
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
  const int bottom2 = lowest_vertex(g, 1, t2);
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

// The tight span's quasi-static transverse state: its nodes between the driver's last seated
// roller A and the driven wheel's first B put on the line AB, their speeds across it the ends'
// interpolated along it, the speeds along it kept (as chordal::Chordal::hold_transverse does for
// the single wheel). A and B: the last node within 0.3 mm of the driver's pitch circle on its upper
// half and the first after it within 0.3 mm of the driven wheel's (chordal::run's test for a
// seated roller).
void hold_straight(const Polygons& g, State& s) {
  const std::size_t n = s.x.size();
  std::size_t a = n, b = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (s.y[i] > 0 && std::hypot(s.x[i], s.y[i]) < g.r1 + 3e-4) a = i;
  }
  for (std::size_t i = a + 1; i < n && b == n; ++i) {
    if (s.y[i] > 0 && std::hypot(s.x[i] - g.c, s.y[i]) < g.r2 + 3e-4) b = i;
  }
  if (a == n || b == n) {
    ADD_FAILURE() << "no span to hold";
    return;
  }
  const double length = std::hypot(s.x[b] - s.x[a], s.y[b] - s.y[a]);
  const double ux = (s.x[b] - s.x[a]) / length, uy = (s.y[b] - s.y[a]) / length;
  const double wa = ux * s.vy[a] - uy * s.vx[a], wb = ux * s.vy[b] - uy * s.vx[b];
  for (std::size_t i = a + 1; i < b; ++i) {
    const double t = (s.x[i] - s.x[a]) * ux + (s.y[i] - s.y[a]) * uy;
    const double along = s.vx[i] * ux + s.vy[i] * uy, across = wa + (wb - wa) * t / length;
    s.x[i] = s.x[a] + t * ux;
    s.y[i] = s.y[a] + t * uy;
    s.vx[i] = along * ux - across * uy;
    s.vy[i] = along * uy + across * ux;
  }
}

chordal::Result run(const FarWheel& d, int k) {
  const Polygons g = polygons(d);
  const double omega1 = d.chain_speed / g.r1;
  const double duration = run_duration(d);
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
    if (d.hold_transverse) hold_straight(g, s);
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
// excess allowed): 17/17 at 20.75 pitches is over the four-bar by up to 2.1 % (against the elastic
// four-bar within 2 %: `DrivenSpeedFollowsTheElasticFourBar`), 12/25 at 20.5 by up to 2.3 %, and
// 9/9 at 20.5 rings at 80 bins (7.5 % over). What would fail: the single wheel's form (the level
// span's, binned; 1 − cos(π/z) unbinned) and the four-bar half a tooth off — each checked below
// to lie outside the tolerance it replaces.
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
    const auto [d, g, k] = set_up(c.z1, c.z2, c.centre, FarWheel{}.chain_speed);
    // the rule gives T1 ∝ v²: at a lower speed the "tight" span would be slacker than the cut
    // slack side
    ASSERT_GT(d.tight, d.slack) << "T1 under T2 at " << d.chain_speed << " m/s";
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
    auto [d, g, k] = set_up(z1, z2, centre, 0.1);
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
  // turned by δ, |AB| = C − R δ + O(δ²) and the arm d2 = R + O(δ²); the lowest vertex of an odd
  // wheel lies half a tooth off the bottom, turned by δ towards it: d2s = R cos(π/z − δ) =
  // R (cos(π/z) + δ sin(π/z)) + O(δ²), so T − T1 = −T2 (1 − cos(π/z)) + T2 δ sin(π/z), and the
  // closure R δ = −C_s (T − T1) gives δ = C_s T2 (1 − cos(π/z)) / (R + C_s T2 sin(π/z)),
  // C_s = n/k + 2/k_c: the span shorter than n p, the driven wheel ahead of the rigid four-bar's
  // π/2 (the reference within 1.4e-7 of it at z = 9, 1e-8 at 17 and 25: the O(δ²) terms). At this
  // lay d2 = R: the tension's main term T1 R2/d2 does not enter; the identity below checks d2.
  for (int z : {9, 17, 25}) {
    FarWheel d;
    d.driver_teeth = d.driven_teeth = z;
    d.tight = 485.0;
    const Polygons g = elastic(d, polygons(d));
    const int k = count_constant(g);
    const Tangent t = upper_tangent(g, kPi / 2, kPi / 2);
    ASSERT_EQ(t.i - t.j + k, 20) << "z " << z;
    const double cs = 20 / d.stiffness + 2 / d.contact, swing = cs * d.slack;
    const double delta = swing * (1 - std::cos(kPi / z)) / (g.r2 + swing * std::sin(kPi / z));
    const double got = driven_angle(g, kPi / 2, k, kPi / 2) - kPi / 2;
    std::printf("z %d: static turn %.9e rad, closed form %.9e\n", z, got, delta);
    EXPECT_NEAR(got / delta, 1.0, 1e-6) << "z " << z;
  }
  // The arms d1, d2 (`arm`, the one `span_tension` takes d2 from) against the rigid four-bar's
  // kinematics: the bar AB keeps its length, so A's and B's velocities have equal components along
  // it, ω1 d1 = ω2 d2, and ω2/ω1 = d1/d2 — between seat switches, with the span tilted (unequal
  // wheels; equal ones off the parallelogram). ω2/ω1 by central differences of the closure's θ2
  // (h = 1e-6 rad: 1e-8 of the ratio from the bisection's 1e-14 rad).
  for (const auto& [z1, z2, centre] : std::vector<std::tuple<int, int, double>>{
           {17, 17, 20.25}, {17, 17, 20.75}, {12, 25, 20.5}, {25, 12, 20.0}}) {
    const auto [d, g, k] = set_up(z1, z2, centre, 0.1);
    const double h = 1e-6, tooth = 2 * kPi / z1;
    int checked = 0;
    double guess = kPi / 2;
    for (int q = 0; q < 8; ++q) {
      const double t1 = kPi / 2 + (q + 0.37) / 8 * tooth;
      const double t2 = driven_angle(g, t1, k, guess);
      guess = t2;
      const Tangent t = upper_tangent(g, t1, t2);
      const double lo = driven_angle(g, t1 - h, k, t2), hi = driven_angle(g, t1 + h, k, t2);
      const Tangent tl = upper_tangent(g, t1 - h, lo), th = upper_tangent(g, t1 + h, hi);
      if (tl.i != t.i || th.i != t.i || tl.j != t.j || th.j != t.j) continue;  // a seat switch
      const auto a = vertex(g, 0, t1, t.i), b = vertex(g, 1, t2, t.j);
      const double ux = (b[0] - a[0]) / t.length, uy = (b[1] - a[1]) / t.length;
      const double ratio = (hi - lo) / (2 * h), arms = arm(g, 0, a, ux, uy) / arm(g, 1, a, ux, uy);
      EXPECT_NEAR(ratio / arms, 1.0, 1e-6)
          << z1 << "/" << z2 << " at " << centre << " p, phase " << (q + 0.37) / 8;
      ++checked;
    }
    EXPECT_GE(checked, 6) << z1 << "/" << z2 << " at " << centre << " p";
  }
}

// The model held still: laid at `phase` of a tooth (`lay`), the driver held (ω1 = 0), the driven
// wheel's load torque (T1 + extra − T2) R2, at rest from the lay and run 0.4 s (4000 steps); the
// settled angles, the span's links' total length and their count n at the lay.
struct Settled {
  double t1 = NAN, t2 = NAN, links = 0.0;
  std::size_t n = 0;
};
Settled settle_held(const FarWheel& d, int k, double phase, double extra) {
  Laid l = lay(d, k, 0.1, phase);
  l.model.sprockets[0].speed = 0.0;
  l.model.sprockets[1].load_torque = (d.tight + extra - d.slack) * polygons(d).r2;
  std::fill(l.state.vx.begin(), l.state.vx.end(), 0.0);
  std::fill(l.state.vy.begin(), l.state.vy.end(), 0.0);
  l.state.speed = {0.0, 0.0};
  Integrator integ(l.model, {.step = d.step, .theta = 0.6});
  Settled out;
  for (int s = 0; s < 4000; ++s) {
    if (!integ.step(l.model, l.state).converged) {
      ADD_FAILURE() << "step " << s << " did not converge at phase " << phase;
      return out;
    }
  }
  out.t1 = l.state.angle[0];
  out.t2 = l.state.angle[1];
  out.n = l.b - l.a;
  for (std::size_t i = l.a; i < l.b; ++i) {
    out.links += std::hypot(l.state.x[i + 1] - l.state.x[i], l.state.y[i + 1] - l.state.y[i]);
  }
  return out;
}

// The model's own end-to-end compliance, measured statically (`settle_held`): the load torque
// stepped from (T1 − T2) R2 to (T1 + 10 N − T2) R2, A on the driver's top vertex (the closure
// moves by under 1 % of the step's stretch from 0.4 to 1.2 s); the stretch is the rigid four-bar's
// closure f = |AB| − play − n p at the settled θ2 (the span's length beyond the rigid one's, its
// ends included), over the span's tension step, 10 N R2/d2 = 10.044 N by the reference's torque
// balance at the settled angles (`span_tension`). At the two tensions the comparisons run at (the
// rule's T1 at 0.05 and 0.1 m/s, 17/17 at 20.75 pitches, n = 21 links at the lay): the span's own
// links stretch as n/k (0.9975 and 1.0001 of it, asserted within 0.35 %: 0.10 % to spare at
// 121.4 N; over 10 N instead of the tension step they are 1.0045 at 485.5 N, which fails); the
// whole is over the reference's compliance C = n̄/k + 2/k_c (`elastic`, n̄ = 20.75) by 5–9 %
// (4.48e-7 and 4.63e-7 m/N against 4.25e-7; 4.47–4.76e-7 over the tooth's phases, probed over
// 10 N, so 5–12 %), and the two ends, the whole less the links, take more than their contacts'
// 2/k_c (their wrap links share the step: 2.8e-8 and 4.4e-8 m/N against 1e-8) — the parts the
// reference leaves out, within 15 % of it.
TEST(DynamicsChordalDrive, ModelStaticStretchIsTheSpansCompliance) {
  for (double speed : {0.05, 0.1}) {
    const auto [d, g, k] = set_up(17, 17, 20.75, speed);
    const Settled low = settle_held(d, k, 0.0, 0.0), high = settle_held(d, k, 0.0, 10.0);
    // the span's tension step: the load's 10 N R2 over the arm d2 at the settled angles
    Polygons ge = elastic(d, g);
    const Tangent t = upper_tangent(ge, high.t1, high.t2);
    const double before = span_tension(ge, high.t1, high.t2, t);
    ge.tight += 10.0;
    const double step = span_tension(ge, high.t1, high.t2, t) - before;
    const double model = (closure(g, high.t1, high.t2, k) - closure(g, low.t1, low.t2, k)) / step;
    const double span = (high.links - low.links) / step;
    const double links_only = static_cast<double>(high.n) / d.stiffness;
    const double reference = elastic(d, g).compliance;
    std::printf(
        "T1 %.1f N, n %zu, tension step %.4f N: the model's compliance %.4e m/N (its span's links "
        "%.4e, n/k %.4e; the ends %.4e, 2/k_c %.4e), the reference's %.4e: %.4f\n",
        d.tight, high.n, step, model, span, links_only, model - span, 2 / d.contact, reference,
        model / reference);
    EXPECT_NEAR(span / links_only, 1.0, 0.0035) << speed;
    EXPECT_GT(model - span, 2 / d.contact) << speed;
    EXPECT_GT(model / reference, 1.0) << speed;
    EXPECT_LT(model / reference, 1.15) << speed;
  }
}

// The tension law against the model: the static stretch over a driver's tooth. 17/17 at 20.75
// pitches laid at 20 phases of the tooth, the driver held and the load (T1 − T2) R2 fixed
// (`settle_held`); the model's stretch is the rigid four-bar's closure f = |AB| − play − n p at the
// settled angles, the reference's C (T − T1) at the same angles (`span_tension`, `elastic`).
// Compared over the tooth, each less its mean (the model's mean holds the ends' static stretch
// under T1, which the reference leaves out): the ratio of their peak-to-peak swings and the shape,
// the largest difference from the reference scaled by that ratio, as a fraction of the model's
// swing; and the phases of the extremes. At 485.5 N (the rule's T1 at 0.1 m/s) the model swings
// 1.191 times the reference's 3.88 µm, in the same shape (0.076 of the swing) with its extremes
// at the same phases (0.25 and 0.75 of the tooth): asserted within 1.19 ± 0.05, 0.1 and one phase
// (without the tail's term, the probes' T1 R2/d2, the reference swings 3.53 µm and the ratio is
// 1.31; with C × 1.5, 0.79; with the sign of d2's tilt term flipped, 0.57). The band is the
// measured ratio's, not a derived one. The 1.19 is measured, not derived: the reference leaves out
// what makes the model's static swing 19 % larger. At 121.4 N (0.05 m/s) it is a known miss,
// asserted as such: the model swings 0.690 times the reference's 1.24 µm, its shape 0.40 of the
// swing off and its minimum at half the tooth against the reference's quarter (not resolved; when
// it fits, it belongs with 485.5 N).
TEST(DynamicsChordalDrive, ModelStaticSwingFollowsTheTensionLaw) {
  constexpr int kPhases = 20;
  for (double speed : {0.05, 0.1}) {
    const auto [d, g, k] = set_up(17, 17, 20.75, speed);
    const Polygons ge = elastic(d, g);
    std::vector<double> model, reference;
    for (int q = 0; q < kPhases; ++q) {
      const Settled s = settle_held(d, k, static_cast<double>(q) / kPhases, 0.0);
      model.push_back(closure(g, s.t1, s.t2, k));
      reference.push_back(ge.compliance *
                          (span_tension(ge, s.t1, s.t2, upper_tangent(ge, s.t1, s.t2)) - d.tight));
    }
    auto centred = [](std::vector<double> v) {
      double mean = 0.0;
      for (const double x : v) mean += x / static_cast<double>(v.size());
      for (double& x : v) x -= mean;
      return v;
    };
    auto swing = [](const std::vector<double>& v) {
      return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
    };
    const std::vector<double> m = centred(model), r = centred(reference);
    const double ratio = swing(m) / swing(r);
    std::vector<double> scaled;
    for (const double x : r) scaled.push_back(ratio * x);
    const double shape = largest_difference(m, scaled) / swing(m);
    std::printf(
        "T1 %.1f N: the model's static swing %.3f um, the reference's %.3f um: %.3f; shape "
        "%.3f of the swing\n",
        d.tight, 1e6 * swing(m), 1e6 * swing(r), ratio, shape);
    for (int q = 0; q < kPhases; ++q) std::printf("  %2d %+.4f %+.4f\n", q, 1e6 * m[q], 1e6 * r[q]);
    auto at = [](const std::vector<double>& v, bool largest) {
      const auto e =
          largest ? std::max_element(v.begin(), v.end()) : std::min_element(v.begin(), v.end());
      return static_cast<int>(e - v.begin());
    };
    const int off =
        std::max(std::abs(at(m, true) - at(r, true)), std::abs(at(m, false) - at(r, false)));
    if (speed == 0.1) {
      EXPECT_NEAR(ratio, 1.19, 0.05);
      EXPECT_LT(shape, 0.1);
      EXPECT_LE(off, 1) << "phases apart (of " << kPhases << ")";
    } else {  // the known miss
      EXPECT_LT(ratio, 0.85);
      EXPECT_GT(shape, 0.2);
    }
  }
}

// The driven wheel's speed against the elastic four-bar (`closure` with the span's compliance):
// the cases the rigid four-bar misses by more than 2 % that it brings within 2 % — the variation
// at every bin count listed, and every bin within 5 % of the range up to `shape_bins` (the finer
// profiles' shapes move with the step: at 5e-5 s 9/9's 40-bin shape goes from 3.7 to 5.9 % of the
// range, 17/17's 80-bin ones from 2.3 and 3.9 to 4.4 and 4.8 %; the variations move by under
// 0.7 %). 17/17 at 20.75 pitches at 0.05 m/s (rigid: 2.1 % over); at 0.1 m/s 17/17 at 20.5
// pitches (rigid: 2.2–3.2 % over), and at 20 and 40 bins 17/17 at 20.25 pitches (rigid: 5.6 %
// under at 20 bins; at 40 bins the rigid one passes too, 0.998, and the elastic one is 1.017) and
// 9/9 at 20.5 pitches (rigid: 2.2, 2.6 % over) — at 80 bins these two are 3.9 and 5.4 % over the
// elastic four-bar, attributed to the torsional ring after the switches, which the reference
// leaves out (not shown: a one-degree-of-freedom model of the ring took 0.5–4 % off). Asserted for
// each: the rigid four-bar misses. What this test can tell: the variations pass for C from about
// 0.95 to 1.75 times the reference's and without the tail's term in T; the first case for C from
// 0.25 to 3 times (its rigid miss is 0.12 % beyond the 2 %), and it runs at 121.4 N, where the
// model's static swing does not follow the reference (`ModelStaticSwingFollowsTheTensionLaw`):
// it does not discriminate the stretch. C is pinned by `ModelStaticStretchIsTheSpansCompliance`,
// the tension law by `ModelStaticSwingFollowsTheTensionLaw`. Margins: 17/17 at 20.25 pitches at
// 40 bins is 1.0174 against the 2 % (0.26 % to spare, under the step's 0.7 %: 1.018 at 5e-5 s),
// and the first case's rigid miss has 0.12 % to spare; an integrator change may flip either for
// reasons that are not the reference's.
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
    const auto [d, g, k] = set_up(c.z1, c.z2, c.centre, c.speed);
    const Polygons ge = elastic(d, g);
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

// The span's longitudinal dynamics with the driven wheel: the elastic four-bar is quasi-static,
// the model's span and wheel have mass. Their linear model, solved independently of the model: the
// driven wheel (J_eff) on the span as a spring of the elastic four-bar's compliance C with the
// links' damping in series (c/n̄), its far end moved by the elastic four-bar's θ2 (a base
// excitation). In the arc x = R2 θ2 at the driven pitch radius, M ẍ + c ẋ + x/C = c ẋ_q + x_q/C
// with M = J_eff/R2² and x_q the quasi-static reference's; the arm d2 is taken as R2 (d2 runs over
// R2 [cos(π/z2), 1] in a tooth: R2/d2 within 1.7 % for z2 = 17 and 3.4 % for 12, on the tooth's
// mean 0.6 and 1.1 %, so M varies by up to 7 % over 25/12's tooth, not modelled). The dashpot's lag
// on the quasi-static stretch rate (c Ḟ/K) is left out: it is under 1 % of the stretch's term for
// the harmonics that matter, and it is what makes the massless limit the reference. J_eff = J + m
// R2² (z2/2 + 1 + tail + n̄/3): the wheel, the rollers wrapped on it and the tail's links, which
// move with it, and a third of the span's (Rayleigh's for a spring's own mass; the span's own first
// longitudinal mode, fixed at both ends, is at p √(k/m)/2L ≈ 1.1 kHz, five times the wheel's). The
// same J_eff as the probes' one-degree-of-freedom time-domain model (the doc's "The elastic
// four-bar").
struct Oscillator {
  double stiffness = 0.0;  // [N/m] 1/C
  double mass = 0.0;       // [kg] J_eff/R2²
  double damping = 0.0;    // [N·s/m]
};
Oscillator span_and_wheel(const FarWheel& d, const Polygons& ge) {
  const double nbar = tangent_length(ge) / ge.p;
  const double links = d.driven_teeth / 2.0 + 1 + tail_links(d, run_duration(d)) + nbar / 3;
  return {1 / ge.compliance, d.inertia / (ge.r2 * ge.r2) + links * d.node_mass, d.damping / nbar};
}

// x/x_q at the angular frequency w [rad/s]: (K + icw)/(K − M w² + icw)
std::complex<double> transmitted(const Oscillator& o, double w) {
  const std::complex<double> spring(o.stiffness, o.damping * w);
  return spring / (spring - o.mass * w * w);
}

// a periodic signal sampled at N equal steps of its period, its harmonic h (frequency h w0 [rad/s])
// multiplied by `transmitted` (a discrete Fourier transform and its inverse; harmonics to N/2)
std::vector<double> transmitted_signal(const std::vector<double>& x, const Oscillator& o,
                                       double w0) {
  const std::size_t n = x.size();
  std::vector<double> out(n, 0.0);
  for (std::size_t h = 0; 2 * h <= n; ++h) {
    std::complex<double> c = 0.0;
    for (std::size_t s = 0; s < n; ++s) {
      c += x[s] * std::polar(1.0, -2 * kPi * static_cast<double>(h * s) / static_cast<double>(n));
    }
    c *= transmitted(o, static_cast<double>(h) * w0) / static_cast<double>(n);
    const double both = h == 0 || 2 * h == n ? 1.0 : 2.0;  // h and −h
    for (std::size_t s = 0; s < n; ++s) {
      out[s] += both * std::real(c * std::polar(1.0, 2 * kPi * static_cast<double>(h * s) /
                                                         static_cast<double>(n)));
    }
  }
  return out;
}

// The elastic four-bar with the span's longitudinal dynamics: its θ2 at kSamples equal steps of the
// driver's tooth (phase 0 as `kinematic_ratio`'s), less the mean rotation (z1/z2 of the driver's),
// periodic over the tooth, through `transmitted` at the tooth's frequency ω1 z1 (ω1 = v/r1) and its
// harmonics in the periodic steady state; the mean ω2/ω1 over `bins` equal bins (bins divides
// kSamples), exactly Δθ2/Δθ1 as `kinematic_ratio`.
constexpr int kSamples = 480;
std::vector<double> dynamic_ratio(const FarWheel& d, const Polygons& ge, int k, int bins,
                                  const Oscillator& o) {
  const double tooth = 2 * kPi / ge.z1, mean = static_cast<double>(ge.z1) / ge.z2;
  std::vector<double> x(kSamples);
  const double start = driven_angle(ge, kPi / 2, k, kPi / 2);
  double prev = start;
  for (int s = 1; s <= kSamples; ++s) {
    prev = driven_angle(ge, kPi / 2 + tooth * s / kSamples, k, prev);
    x[s % kSamples] = prev - start - mean * tooth * s / kSamples;
  }
  EXPECT_LT(std::abs(x[0]), 1e-9) << "not periodic over the tooth";
  x[0] = 0.0;
  const std::vector<double> y = transmitted_signal(x, o, d.chain_speed / ge.r1 * ge.z1);
  const int per = kSamples / bins;
  EXPECT_EQ(per * bins, kSamples) << bins << " bins";
  std::vector<double> out;
  for (int b = 0; b < bins; ++b) {
    const double dy = y[((b + 1) * per) % kSamples] - y[b * per];
    out.push_back(mean + dy / (tooth / bins));
  }
  return out;
}

// The elastic four-bar's variation with the span's longitudinal dynamics (`dynamic_ratio`) over its
// own, less 1, at `bins` bins (the polygons with the seat play, as `excess`)
double dynamic_excess(const FarWheel& d, int k, int bins) {
  Polygons g = polygons(d);
  g.play = seat_play(d);
  const Polygons ge = elastic(d, g);
  return variation_of(dynamic_ratio(d, ge, k, bins, span_and_wheel(d, ge))) /
             variation_of(kinematic_ratio(ge, k, bins)) -
         1;
}

// The harmonic solution against its own limits and an independent solution:
// * a single harmonic (h = 3 of 64 samples) comes out as the closed form: at a resonance
//   (M = K/w²) with cw = K, (K + icw)/(icw) = 1 − i, the gain √2 and the phase −π/4 (a lag);
//   undamped at w/ω_n = 0.4, 1/(1 − 0.16);
// * a kinked periodic signal (a triangle rising over 0.3 of the period, falling over the rest)
//   through an oscillator with ω_n = 3.5 w0 and ζ = 0.1 matches the same equation integrated in
//   time by RK4 (in w = ẋ − (c/M) x_q, so that the input's rate is not needed), started at rest and
//   run for 12 periods (the transient falls by e^{−ζ ω_n t} ≈ 5e-12), within 1e-4 of the
//   triangle's unit amplitude at 960 samples (measured 1.8e-5, and 7.2e-5 at 480: as 1/N², the
//   kinks' high harmonics aliased onto the resonant low ones);
// * without mass it is the elastic four-bar itself, within 1e-10 over 20, 40 and 80 bins (the
//   transform's round trip and the binning from the samples);
// * with links 4× stiffer (17/17 at 20.75 p, 0.1 m/s, 20 bins) the dynamics' excess falls with
//   f_L², (204.8/395.9)² = 0.268: within 0.2–0.35 of its value at k (measured 0.27).
TEST(DynamicsChordalDrive, SpanDynamicsReferenceHasItsLimits) {
  constexpr int kN = 64;
  constexpr double kW0 = 10.0;
  const Oscillator damped{
      .stiffness = 1e6, .mass = 1e6 / (3 * kW0) / (3 * kW0), .damping = 1e6 / (3 * kW0)};
  // undamped, off every harmonic: ω_n = 2.5 w0
  const Oscillator o{.stiffness = 1e6, .mass = 1e6 / (2.5 * kW0) / (2.5 * kW0), .damping = 0.0};
  std::vector<double> x(kN);
  for (int s = 0; s < kN; ++s) x[s] = std::cos(2 * kPi * 3 * s / kN + 0.4);
  const std::vector<double> y = transmitted_signal(x, damped, kW0);
  const std::complex<double> gain = transmitted(damped, 3 * kW0);
  EXPECT_NEAR(std::abs(gain), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(std::arg(gain), -kPi / 4, 1e-12);
  for (int s = 0; s < kN; ++s) {
    EXPECT_NEAR(y[s], std::sqrt(2.0) * std::cos(2 * kPi * 3 * s / kN + 0.4 - kPi / 4), 1e-12) << s;
  }
  // undamped: 1/(1 − (w/ω_n)²) at h = 1, w/ω_n = 0.4
  for (int s = 0; s < kN; ++s) x[s] = std::sin(2 * kPi * s / kN);
  const std::vector<double> y2 = transmitted_signal(x, o, kW0);
  for (int s = 0; s < kN; ++s) EXPECT_NEAR(y2[s], x[s] / (1 - 0.16), 1e-12) << s;
  // a kinked periodic signal against RK4
  {
    constexpr int kTri = 960, kSub = 4, kPeriods = 12;
    constexpr double kRise = 0.3;
    const double wn = 3.5 * kW0, stiffness = 1e6, mass = stiffness / (wn * wn);
    const Oscillator tri{
        .stiffness = stiffness, .mass = mass, .damping = 2 * 0.1 * std::sqrt(stiffness * mass)};
    const double period = 2 * kPi / kW0, dt = period / (kTri * kSub);
    const auto input = [&](double t) {
      const double u = t / period - std::floor(t / period);
      return u < kRise ? -1 + 2 * u / kRise : 1 - 2 * (u - kRise) / (1 - kRise);
    };
    std::vector<double> xt(kTri);
    for (int s = 0; s < kTri; ++s) xt[s] = input(period * s / kTri);
    const std::vector<double> yt = transmitted_signal(xt, tri, kW0);
    const double cm = tri.damping / tri.mass;
    // x' = w + (c/M) x_q, w' = (K (x_q − x) − c x')/M
    const auto rate = [&](double t, double at, double w) {
      const double q = input(t), dx = w + cm * q;
      return std::array<double, 2>{dx, (tri.stiffness * (q - at) - tri.damping * dx) / tri.mass};
    };
    double xs = 0.0, ws = -cm * input(0.0), worst = 0.0;
    for (int n = 0; n < kPeriods * kTri * kSub; ++n) {
      const double t = n * dt;
      const auto k1 = rate(t, xs, ws);
      const auto k2 = rate(t + dt / 2, xs + dt / 2 * k1[0], ws + dt / 2 * k1[1]);
      const auto k3 = rate(t + dt / 2, xs + dt / 2 * k2[0], ws + dt / 2 * k2[1]);
      const auto k4 = rate(t + dt, xs + dt * k3[0], ws + dt * k3[1]);
      xs += dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
      ws += dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
      const int step = n + 1;
      if (step > (kPeriods - 1) * kTri * kSub && step % kSub == 0) {
        worst = std::max(worst, std::abs(xs - yt[(step / kSub) % kTri]));
      }
    }
    std::printf("a triangle through the harmonic solution against RK4: largest difference %.2e\n",
                worst);
    EXPECT_LT(worst, 1e-4);
  }
  // without mass: the elastic four-bar, over 20, 40 and 80 bins
  for (const auto& [z1, z2, centre] : {std::tuple{17, 17, 20.75}, std::tuple{25, 12, 20.0}}) {
    const auto [d, g, k] = set_up(z1, z2, centre, 0.1);
    const Polygons ge = elastic(d, g);
    Oscillator still = span_and_wheel(d, ge);
    still.mass = 0.0;
    for (int bins : {20, 40, 80}) {
      EXPECT_LT(
          largest_difference(dynamic_ratio(d, ge, k, bins, still), kinematic_ratio(ge, k, bins)),
          1e-10)
          << z1 << "/" << z2 << ", " << bins << " bins";
    }
  }
  // with links 4× stiffer: f_L² (0.268)
  {
    const auto [d, g, k] = set_up(17, 17, 20.75, 0.1);
    FarWheel stiff = d;
    stiff.stiffness *= 4;
    const double at_k = dynamic_excess(d, k, 20), at_4k = dynamic_excess(stiff, k, 20);
    std::printf("17/17 at 20.75 p, 0.1 m/s, 20 bins: the dynamics' excess %.4f at k, %.4f at 4k\n",
                at_k, at_4k);
    EXPECT_GT(at_4k, 0.2 * at_k);
    EXPECT_LT(at_4k, 0.35 * at_k);
  }
}

// The model's variation over the elastic four-bar's less 1, and the same for the four-bar with the
// span's longitudinal dynamics (`dynamic_ratio`), at each bin count: one run of the model.
struct Excess {
  std::vector<double> model, dynamic;
};
Excess excess(const FarWheel& d, int k, const std::vector<int>& bins) {
  Polygons g = polygons(d);
  g.play = seat_play(d);
  const Polygons ge = elastic(d, g);
  const chordal::Result r = run(d, k);
  EXPECT_TRUE(r.converged);
  Excess out;
  for (int b : bins) {
    const double ve = variation_of(kinematic_ratio(ge, k, b));
    out.model.push_back(variation_of(simulated_profile(r, b)) / ve - 1);
    out.dynamic.push_back(dynamic_excess(d, k, b));
  }
  return out;
}

// What the 0.1 m/s excess over the elastic four-bar is (the doc's "The elastic four-bar", "The
// excess at 0.1 m/s"). The hypothesis: the span's longitudinal dynamics with the driven wheel
// (`dynamic_ratio`), driven at the tooth's frequency f_z = v z1 sin(π/z1)/(π p) (5.22 Hz) and its
// harmonics, the quasi-static response amplified by 1/(1 − (h f_z/f_L)²): f_L = 205 Hz for 17/17
// (J_eff 0.0038 kg·m², ζ = 0.026), 172 Hz for 25/12 ((f_z/f_L)² = 6.5e-4 and 9.2e-4; the
// resonance at the 39th and 33rd harmonic). Measured (20, 40 bins): it takes 0.4, 0.8 % off 17/17
// at 20.75 pitches' 3.6, 3.5 % (a share of 0.11, 0.22; the model is still 3.2, 2.7 % over it) and
// 1.7, 2.0 % off 25/12's 3.9, 4.3 % (0.44, 0.47).
//
// The rest, for 17/17 with T1 held (485.5 N), at 20 bins only: the excess is 1.59 % at 0.025 m/s
// and 3.62 % at 0.1 m/s; the part that grows with the speed, 2.03 %, stays with links 4× stiffer
// (1.95 %: −0.71 % and 1.24 %), and with the span held straight (`hold_straight`, which also fixes
// the end links' direction at A and B) it is gone: held 1.61 % at 0.1 m/s, 1.60 % at 0.025 m/s.
// At 40 and 80 bins neither holds, so the rest is not identified: the speed's part is 2.28, 3.01 %
// at k and 1.65, −0.53 % at 4k (it falls with k), and the held runs keep 1.01, 3.31 % of it (the
// free runs' 2.28, 3.01 %; of the held 1.01 % at 40 bins the longitudinal dynamics give 0.71 %).
// What falls with k at 20 bins is the quasi-static excess (1.59, 0.13, −0.71 % at k, 2k, 4k at
// 0.025 m/s; the static swing's 1.19, `ModelStaticSwingFollowsTheTensionLaw`).
//
// Claims (each able to fail for a physical reason): the longitudinal dynamics add to the elastic
// four-bar (dynamic > 0) and explain less than the model's excess (share < 1), both set-ups at 20
// and 40 bins; 17/17 stays over the dynamic reference by more than 2 %; at 20 bins the speed's part
// is over 1.5 %, with 4k over 0.75 of it (the longitudinal dynamics would give 1/4, f_L²), and the
// hold takes at least 3/4 of it away (held fast within 0.25 of it of held slow). Regression pins
// (bands set around single measured values, not physics; they move if the model's excess does):
// the shares within 0.05–0.3 (17/17) and 0.3–0.6 (25/12). At 5e-5 s (halved) it passes: 17/17
// 3.69, 3.48 % (shares 0.11, 0.22), 25/12 4.18, 4.78 % (0.41, 0.42); at 20 bins slow 1.56 %, 4k's
// speed part 2.00 %, held 1.60 % and held slow 1.58 %; at 80 bins the speed's part 3.29 % at k,
// −0.51 % at 4k, held 3.42 %. Seven runs of the model.
TEST(DynamicsChordalDrive, SpeedExcessIsOnlyPartlyTheSpansLongitudinalDynamics) {
  const std::vector<int> bins = {20, 40, 80};
  const auto claims = [&bins](const Excess& e, const char* name) {
    for (std::size_t q = 0; q < 2; ++q) {
      EXPECT_GT(e.dynamic[q], 0.0) << name << ", " << bins[q] << " bins";
      EXPECT_LT(e.dynamic[q], e.model[q]) << name << ", " << bins[q] << " bins";
    }
  };
  // The longitudinal dynamics' share of the excess at 20 and 40 bins, printed and pinned in
  // [low, high] (regression pins, above).
  const auto shares = [&bins](const Excess& e, const char* name, double low, double high) {
    for (std::size_t q = 0; q < 2; ++q) {
      const double share = e.dynamic[q] / e.model[q];
      std::printf(
          "%s, 0.1 m/s, %d bins: over the elastic four-bar %.4f, its longitudinal "
          "dynamics %.4f, share %.2f\n",
          name, bins[q], e.model[q], e.dynamic[q], share);
      EXPECT_GT(share, low) << "regression pin, " << name << ", " << bins[q] << " bins";
      EXPECT_LT(share, high) << "regression pin, " << name << ", " << bins[q] << " bins";
    }
  };
  {
    const auto [d, g, k] = set_up(25, 12, 20.0, 0.1);
    const Excess e = excess(d, k, bins);
    claims(e, "25/12");
    shares(e, "25/12 at 20 p", 0.3, 0.6);
  }
  const auto [fast, g, k] = set_up(17, 17, 20.75, 0.1);
  FarWheel slow = fast;  // T1 held at the 0.1 m/s rule's
  slow.chain_speed = 0.025;
  slow.periods = 4;
  FarWheel stiff = fast, stiff_slow = slow, held = fast, held_slow = slow;
  stiff.stiffness *= 4;
  stiff_slow.stiffness *= 4;
  held.hold_transverse = true;
  held_slow.hold_transverse = true;
  const Excess e = excess(fast, k, bins), e_slow = excess(slow, k, bins),
               e_stiff = excess(stiff, k, bins), e_stiff_slow = excess(stiff_slow, k, bins),
               e_held = excess(held, k, bins), e_held_slow = excess(held_slow, k, bins);
  claims(e, "17/17");
  shares(e, "17/17 at 20.75 p", 0.05, 0.3);
  for (std::size_t q = 0; q < 2; ++q)
    EXPECT_GT((1 + e.model[q]) / (1 + e.dynamic[q]) - 1, 0.02) << bins[q] << " bins";
  for (std::size_t q = 0; q < bins.size(); ++q) {
    std::printf(
        "17/17 at 20.75 p, %d bins, T1 %.1f N, 0.025 and 0.1 m/s: %.4f, %.4f; links 4x stiffer "
        "%.4f, %.4f; the span held straight %.4f, %.4f; longitudinal dynamics at 0.1 m/s %.4f, "
        "4x stiffer %.4f\n",
        bins[q], fast.tight, e_slow.model[q], e.model[q], e_stiff_slow.model[q], e_stiff.model[q],
        e_held_slow.model[q], e_held.model[q], e.dynamic[q], e_stiff.dynamic[q]);
  }
  const double speed = e.model[0] - e_slow.model[0];
  const double speed_stiff = e_stiff.model[0] - e_stiff_slow.model[0];
  EXPECT_GT(speed, 0.015);
  EXPECT_GT(speed_stiff, 0.75 * speed);
  EXPECT_NEAR(e_held.model[0], e_held_slow.model[0], 0.25 * speed);
}

}  // namespace
}  // namespace catena::dynamics
