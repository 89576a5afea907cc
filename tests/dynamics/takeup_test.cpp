// The take-up (docs/models/dynamics.md, "Take-up"): an idler whose centre slides along a
// direction, pushed by a force or a spring, as one more unknown of the implicit step. Tested
// against independent numerics and closed forms: the Newton matrix's new entries against central
// finite differences of the residual; the statics of the loop against the force balance on the
// idler, 2 T sin(β/2) cos γ = F, with β the wrap from the belt path through the idler's settled
// centre; the running loop's mean span tensions either side of the idler against the same balance
// plus q v²; the energy balance with the slide's spring, force and damper; bad fields refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/layout.hpp"
#include "residual_difference.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
// 12B (ISO 606): pitch, roller diameter, inner width, mass per metre
constexpr double kPitch = 0.01905, kRoller = 0.01207, kWidth = 0.01168, kMass = 1.25;

// The example's three wheels (examples/dynamics_three_wheels.toml): a driver z = 12 at the origin,
// a driven z = 18 300 mm along +x, an idler z = 15 at (150, −175) mm on a slide along −y.
struct Loop {
  Model model;
  State state;
  std::vector<Circle> circles;
  std::vector<int> teeth{12, 18, 15};
};

Loop three_wheels(double omega, double load, double force, double stiffness, double damping,
                  double pretension = 0.0, double seat_damping = 0.0) {
  Loop l;
  const double cx[3] = {0.0, 0.3, 0.15}, cy[3] = {0.0, 0.0, -0.175};
  for (int w = 0; w < 3; ++w) {
    const Sprocket s =
        iso606_sprocket(kPitch, kRoller, kWidth, l.teeth[w], cx[w], cy[w], 2e8, seat_damping);
    l.circles.push_back({cx[w], cy[w], s.pitch_radius});
    l.model.sprockets.push_back(s);
  }
  const BeltPath path = belt_path(l.circles, 0);
  const double f = path_links(path, kPitch);
  const LoopPlacement place =
      place_loop(path, l.circles, l.teeth, static_cast<int>(std::lround(f)), kPitch);
  EXPECT_FALSE(place.s.empty());
  const double k = 5e7;
  Model m = uniform_chain(place.s.size(), true, place.spacing - pretension / k, kMass * kPitch, k,
                          100.0, false);
  m.sprockets = l.model.sprockets;
  Sprocket& driver = m.sprockets[0];
  driver.driver = true;
  driver.speed = omega;
  m.sprockets[1].inertia = 0.02;
  m.sprockets[1].load_torque = load;
  Sprocket& idler = m.sprockets[2];
  idler.inertia = 0.002;
  idler.takeup = true;
  idler.takeup_dx = 0.0;
  idler.takeup_dy = -1.0;
  idler.takeup_force = force;
  idler.takeup_stiffness = stiffness;
  idler.takeup_damping = damping;
  idler.takeup_mass = 1.0;
  l.model = m;
  l.state = loop_state(path, l.circles, place, omega * l.circles[0].radius);
  l.state.speed[0] = omega;
  return l;
}

// A Newton iterate near the step's constant-velocity predictor (step h): every node coordinate
// moved by a seeded uniform jitter within ±2e-5 m, the driven wheel's and the idler's angles and
// the slide by the given offsets.
std::vector<double> perturbed_iterate(const Loop& l, double h, unsigned seed, double driven,
                                      double idler, double slide) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-2e-5, 2e-5);
  const std::size_t n = l.model.nodes();
  std::vector<double> u(2 * n + 3);
  for (std::size_t i = 0; i < n; ++i) {
    u[2 * i] = l.state.x[i] + h * l.state.vx[i] + jitter(rng);
    u[2 * i + 1] = l.state.y[i] + h * l.state.vy[i] + jitter(rng);
  }
  u[2 * n] = l.state.angle[1] + h * l.state.speed[1] + driven;
  u[2 * n + 1] = l.state.angle[2] + h * l.state.speed[2] + idler;
  u[2 * n + 2] = l.state.slide[2] + slide;
  return u;
}

// The Newton matrix's entries in the take-up's row and column (and the idler's angle's, which
// now couple to it) against central differences of the residual, at a perturbed iterate with the
// idler part-way along its slide and moving, rollers in and out of their seats.
TEST(DynamicsTakeup, JacobianMatchesFiniteDifferences) {
  for (const double mu : {0.0, 0.15}) {
    Loop l = three_wheels(13.0, 10.0, 600.0, 2e4, 50.0);
    for (Sprocket& w : l.model.sprockets) w.friction = mu;
    l.state.slide[2] = 2e-5;
    l.state.slide_speed[2] = -0.01;
    const double h = 1e-4;
    Integrator integ(l.model, {.step = h, .theta = 0.6});
    const std::size_t n = l.model.nodes(), size = integ.unknowns();
    ASSERT_EQ(size, 2 * n + 3);  // two driven angles (driven, idler) and one slide
    // the slide pressing the wrapped rollers into their seats
    const std::vector<double> u = perturbed_iterate(l, h, 7, 1e-4, -1e-4, 3e-4);
    std::vector<double> r0, jac;
    integ.newton_system(l.model, l.state, u, r0, &jac);
    // the idler is in contact: the slide's row and column are not empty
    double coupling = 0.0;
    for (std::size_t i = 0; i < 2 * n; ++i) coupling += std::abs(jac[i * size + 2 * n + 2]);
    ASSERT_GT(coupling, 0.0);
    auto column = [&](std::size_t c, double eps) {
      return testing::residual_difference(integ, l.model, l.state, u, c, eps);
    };
    // the extras' columns: the slide's (new) and the two angles' (which gained the slide's row)
    for (std::size_t c = 2 * n; c < size; ++c) {
      const std::vector<double> fd = column(c, c == 2 * n + 2 ? 1e-9 : 1e-8);
      double scale = 0.0;
      for (std::size_t r = 0; r < size; ++r) scale = std::max(scale, std::abs(fd[r]));
      for (std::size_t r = 0; r < size; ++r)
        EXPECT_NEAR(jac[r * size + c], fd[r], 1e-5 * scale)
            << "mu " << mu << " row " << r << " column " << c;
    }
    // the slide's row: ∂R_s/∂u for every node coordinate
    const std::size_t rs = 2 * n + 2;
    double row_scale = 0.0;
    std::vector<double> fd_row(size);
    for (std::size_t c = 0; c < 2 * n; ++c) {
      fd_row[c] = column(c, 1e-9)[rs];
      row_scale = std::max(row_scale, std::abs(fd_row[c]));
    }
    ASSERT_GT(row_scale, 0.0);
    for (std::size_t c = 0; c < 2 * n; ++c)
      EXPECT_NEAR(jac[rs * size + c], fd_row[c], 1e-5 * row_scale)
          << "mu " << mu << " column " << c;
  }
}

// With the seats' discrete gradient (docs/models/dynamics.md, "Sprockets: the discrete
// gradient"), where a roller's gaps at the step's ends are taken relative to the idler's sliding
// centre at the slide's start and iterate: every column of the Newton matrix against central
// differences of the residual at θ = ½, seats damped (800 N·s/m), frictionless and with μ = 0.15,
// at the iterate above (the slide pressing the wrapped rollers into their seats). It is the
// discrete gradient's matrix: it differs from the θ point's at the same iterate.
TEST(DynamicsTakeup, DiscreteGradientJacobianMatchesFiniteDifferences) {
  const double h = 1e-4;
  for (const double mu : {0.0, 0.15}) {
    std::vector<double> jac_theta;
    for (const bool gradient : {false, true}) {
      Loop l = three_wheels(13.0, 10.0, 600.0, 2e4, 50.0, 0.0, 800.0);
      for (Sprocket& w : l.model.sprockets) {
        w.friction = mu;
        w.discrete_gradient = gradient;
      }
      l.state.slide[2] = 2e-5;
      l.state.slide_speed[2] = -0.01;
      Integrator integ(l.model, {.step = h, .theta = 0.5});
      const std::size_t n = l.model.nodes();
      ASSERT_EQ(integ.unknowns(), 2 * n + 3);
      const std::vector<double> u = perturbed_iterate(l, h, 7, 1e-4, -1e-4, 3e-4);
      std::vector<double> r0, jac;
      integ.newton_system(l.model, l.state, u, r0, &jac);
      if (!gradient) {
        jac_theta = jac;
        continue;
      }
      const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
          integ, l.model, l.state, u, jac, jac_theta,
          [n](std::size_t c) { return c < 2 * n ? 1e-10 : (c == 2 * n + 2 ? 1e-9 : 1e-8); }, 1e-5);
      std::printf(
          "take-up with the seats' discrete gradient (theta 0.5, mu %.2f): worst |J - FD| / "
          "column scale %.2e\n",
          mu, d.worst);
      EXPECT_GT(d.differs, 1e-3 * d.scale);
    }
  }
}
// With the seats' contact damping (the damper's rate turns with the roller's position about the
// wheel, a non-symmetric term that also reaches the driven wheel's and the take-up's rows and
// columns): the whole Newton matrix, every column, against central differences of the residual,
// at a perturbed iterate with the wheels turning, the idler moving and rollers in and out of
// their seats, with and without seat friction.
TEST(DynamicsTakeup, JacobianWithSeatDampingMatchesFiniteDifferences) {
  for (const double mu : {0.0, 0.15}) {
    Loop l = three_wheels(13.0, 10.0, 600.0, 2e4, 50.0, 0.0, 5e3);
    for (Sprocket& w : l.model.sprockets) w.friction = mu;
    l.state.slide[2] = 2e-5;
    l.state.slide_speed[2] = -0.01;
    const double h = 1e-4;
    Integrator integ(l.model, {.step = h, .theta = 0.6});
    const std::size_t n = l.model.nodes(), size = integ.unknowns();
    ASSERT_EQ(size, 2 * n + 3);
    const std::vector<double> u = perturbed_iterate(l, h, 11, 1e-4, -1e-4, 3e-4);
    std::vector<double> r0, jac;
    integ.newton_system(l.model, l.state, u, r0, &jac);
    double worst = 0.0;
    for (std::size_t c = 0; c < size; ++c) {
      const double eps = c >= 2 * n && c < 2 * n + 2 ? 1e-8 : 1e-9;
      const std::vector<double> fd =
          testing::residual_difference(integ, l.model, l.state, u, c, eps);
      double scale = 0.0;
      for (std::size_t r = 0; r < size; ++r) scale = std::max(scale, std::abs(fd[r]));
      for (std::size_t r = 0; r < size; ++r) {
        worst = std::max(worst, std::abs(jac[r * size + c] - fd[r]) / scale);
        EXPECT_NEAR(jac[r * size + c], fd[r], 1e-5 * scale)
            << "mu " << mu << " row " << r << " column " << c;
      }
    }
    std::printf("seat damping 5e3 N s/m, mu %.2f: worst |J - FD| / column scale %.2e\n", mu, worst);
  }
}

// The wrap and the slide's angle to the wrap's bisector from the belt path with the idler at
// `centre_y`: the force balance along the slide e = −y, T e·(d_out − d_in) = −F, as
// T = F / (2 sin(β/2) cos γ).
double closed_form_tension(const Loop& l, double force, double idler_y) {
  std::vector<Circle> c = l.circles;
  c[2].y = idler_y;
  const BeltPath path = belt_path(c, 0);
  for (std::size_t k = 0; k < path.pieces.size(); ++k) {
    const PathPiece& arc = path.pieces[k];
    if (!arc.arc || arc.wheel != 2) continue;
    // along the arc the chain's direction turns from the arriving span's to the leaving span's:
    // d_in = perp(n(from)), d_out = perp(n(to)), with perp(n) = (−sin, cos)
    const double din_y = std::cos(arc.from), dout_y = std::cos(arc.to);
    const double along = -(dout_y - din_y);  // e·(d_out − d_in) with e = −y
    return -force / along;
  }
  return NAN;
}

// Mean tension of the links wholly on the straight spans either side of the idler.
void span_tensions(const Loop& l, const State& s, double& left, double& right) {
  std::vector<double> t(l.model.links());
  link_tensions(l.model, s, t);
  const double ix = l.circles[2].x, iy = l.circles[2].y + s.slide[2] * -1.0;
  const double reach = l.circles[2].radius + 0.6 * kPitch;
  double sum[2] = {0, 0};
  int count[2] = {0, 0};
  const std::size_t n = s.nodes();
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t b = (j + 1) % n;
    const double mx = 0.5 * (s.x[j] + s.x[b]), my = 0.5 * (s.y[j] + s.y[b]);
    // a span link below the driver/driven centres' line, off the idler and the other wheels
    if (my > -0.05 || std::hypot(mx - ix, my - iy) < reach) continue;
    if (std::hypot(mx - l.circles[0].x, my - l.circles[0].y) < l.circles[0].radius + kPitch)
      continue;
    if (std::hypot(mx - l.circles[1].x, my - l.circles[1].y) < l.circles[1].radius + kPitch)
      continue;
    const int side = mx < ix ? 0 : 1;
    sum[side] += t[j];
    ++count[side];
  }
  left = count[0] ? sum[0] / count[0] : NAN;
  right = count[1] ? sum[1] / count[1] : NAN;
}

// With hinge friction the Newton matrix is block-pentadiagonal: the dense verification matrix
// (newton_system) holds its far blocks too, every node column against central differences of the
// residual, the take-up's borders included.
TEST(DynamicsTakeup, JacobianWithHingeFrictionMatchesFiniteDifferences) {
  Loop l = three_wheels(13.0, 10.0, 600.0, 2e4, 50.0);
  l.model.hinge.arm = 0.003;  // sliding hinges, 12B's pin (μ 0.1 × ~6 mm diameter is ~0.3 mm)
  l.model.hinge.rate_band = 5.0;
  const double h = 1e-4;
  Integrator integ(l.model, {.step = h, .theta = 0.6});
  const std::size_t n = l.model.nodes(), size = integ.unknowns();
  const std::vector<double> u = perturbed_iterate(l, h, 11, 0.0, 0.0, 1e-4);
  std::vector<double> r0, jac;
  integ.newton_system(l.model, l.state, u, r0, &jac);
  double far = 0.0;  // the far blocks are there: node 2's rows in node 0's columns
  for (std::size_t a = 0; a < 2; ++a)
    for (std::size_t b = 0; b < 2; ++b) far += std::abs(jac[(4 + a) * size + b]);
  ASSERT_GT(far, 0.0);
  for (std::size_t c = 0; c < 2 * n; ++c) {
    const std::vector<double> fd =
        testing::residual_difference(integ, l.model, l.state, u, c, 1e-9);
    double scale = 0.0;
    for (std::size_t r = 0; r < size; ++r) scale = std::max(scale, std::abs(fd[r]));
    for (std::size_t r = 0; r < size; ++r)
      EXPECT_NEAR(jac[r * size + c], fd[r], 1e-5 * scale) << "row " << r << " column " << c;
  }
}

// Statics: the driver held, no load, the idler pushed down by a constant force (then by a
// spring with a preload) settles where the span tensions balance it.
TEST(DynamicsTakeup, StaticTensionBalancesTheTakeupForce) {
  for (const double stiffness : {0.0, 2e5}) {
    const double force = 800.0;
    Loop l = three_wheels(0.0, 0.0, force, stiffness, 2000.0);
    l.model.drag = 20.0;  // settle the chain's transverse motion too
    Integrator integ(l.model, {.step = 2e-4, .theta = 1.0});
    for (int k = 0; k < 2500; ++k) ASSERT_TRUE(integ.step(l.model, l.state).converged) << k;
    EXPECT_LT(std::abs(l.state.slide_speed[2]), 1e-6);
    EXPECT_GT(l.state.slide[2], 0.0);  // the idler moved down, taking up the stretch
    const double pushed = force - stiffness * l.state.slide[2];
    const double closed = closed_form_tension(l, pushed, l.circles[2].y - l.state.slide[2]);
    double left = 0.0, right = 0.0;
    span_tensions(l, l.state, left, right);
    EXPECT_NEAR(left, closed, 0.01 * closed) << "k_t " << stiffness;
    EXPECT_NEAR(right, closed, 0.01 * closed) << "k_t " << stiffness;
    // and the chain's force on the idler along the slide is the take-up's
    EXPECT_NEAR(-integ.applied_slide_force()[2], pushed, 1e-3 * pushed);
  }
}

// Running: the driver at 13 rad/s against a 10 N m load, the idler on the slack side. Over the
// last 0.2 s the mean tension of the spans either side of the idler is the balance's, plus the
// chain's centrifugal q v² (the wrapped chain presses on the wheel with T − q v²).
TEST(DynamicsTakeup, RunningSlackTensionIsTheTakeupBalance) {
  const double force = 600.0, omega = 13.0;
  Loop l = three_wheels(omega, 10.0, force, 0.0, 500.0, 0.0);
  l.model.axial_damping = 200.0;
  Integrator integ(l.model, {.step = 1e-4, .theta = 0.6});
  double left = 0.0, right = 0.0, slide = 0.0;
  int samples = 0;
  const int steps = 6000, window = 2000;
  for (int k = 0; k < steps; ++k) {
    ASSERT_TRUE(integ.step(l.model, l.state).converged) << k;
    if (k < steps - window) continue;
    double a = 0.0, b = 0.0;
    span_tensions(l, l.state, a, b);
    left += a;
    right += b;
    slide += l.state.slide[2];
    ++samples;
  }
  left /= samples;
  right /= samples;
  slide /= samples;
  const double v = omega * l.circles[0].radius;
  const double closed = closed_form_tension(l, force, l.circles[2].y - slide) + kMass * v * v;
  EXPECT_NEAR(left, closed, 0.01 * closed);
  EXPECT_NEAR(right, closed, 0.01 * closed);
}

// Energy: frictionless, undamped links and seats, the θ = ½ step; the idler released moving on a
// spring with a preload and a damper. The change of the total energy (with the slide's kinetic,
// spring and force-potential terms) equals the take-up damper's work up to the seat contacts'
// numerical work (their penalty is taken at the θ point, not by a discrete gradient:
// docs/models/dynamics.md, "Work balance"), which falls faster than h² as the step is halved and
// is then a small fraction of the damper's work. A missing or wrong slide term would leave a
// remainder that does not fall with h.
double left_over(double h, double& damper) {
  Loop l = three_wheels(0.0, 0.0, 100.0, 1e4, 300.0, 0.0);
  l.model.axial_damping = 0.0;
  l.state.slide_speed[2] = 0.01;
  Integrator integ(l.model, {.step = h, .max_iterations = 60, .theta = 0.5});
  const double e0 = energy(l.model, l.state).total();
  for (int k = 0; k < static_cast<int>(std::lround(0.08 / h)); ++k)
    if (!integ.step(l.model, l.state).converged) return NAN;
  const double e1 = energy(l.model, l.state).total();
  damper = l.state.takeup_damper_work;
  return e1 - e0 - damper - l.state.damper_work - l.state.contact_damping_work;
}

TEST(DynamicsTakeup, EnergyBalanceClosesWithTheSlidesWork) {
  double damper_coarse = 0.0, damper_fine = 0.0;
  const double coarse = left_over(2e-5, damper_coarse);
  const double fine = left_over(1e-5, damper_fine);
  ASSERT_TRUE(std::isfinite(coarse) && std::isfinite(fine));
  EXPECT_LT(damper_fine, 0.0);
  EXPECT_NEAR(damper_fine, damper_coarse, 0.15 * std::abs(damper_fine));
  EXPECT_LT(std::abs(fine), 0.25 * std::abs(coarse)) << coarse << " -> " << fine;
  EXPECT_LT(std::abs(fine), 0.25 * std::abs(damper_fine)) << fine << " vs " << damper_fine;
}

TEST(DynamicsTakeup, BadFieldsAreRefusedTogether) {
  Loop l = three_wheels(13.0, 10.0, 600.0, 0.0, 0.0);
  Sprocket& w = l.model.sprockets[2];
  w.takeup_dx = 0.5;  // not a unit vector
  w.takeup_stiffness = -1.0;
  w.takeup_damping = NAN;
  w.takeup_mass = 0.0;
  w.takeup_force = INFINITY;
  l.model.sprockets[0].takeup = true;  // on the driver
  l.model.sprockets[0].takeup_dx = 1.0;
  l.model.sprockets[0].takeup_mass = 1.0;
  const std::vector<Issue> issues = validate(l.model);
  std::vector<std::string> fields;
  for (const Issue& i : issues) fields.push_back(i.field);
  for (const char* f : {"sprocket[2].takeup_direction", "sprocket[2].takeup_stiffness",
                        "sprocket[2].takeup_damping", "sprocket[2].takeup_mass",
                        "sprocket[2].takeup_force", "sprocket[0].takeup"})
    EXPECT_NE(std::find(fields.begin(), fields.end(), f), fields.end()) << f;
  // a slide on a wheel without a take-up is refused in the state
  State s = l.state;
  s.slide[1] = 1e-3;
  bool slide_issue = false;
  for (const Issue& i : validate(three_wheels(13.0, 10.0, 600.0, 0.0, 0.0).model, s))
    slide_issue = slide_issue || i.field == "state.slide[1]";
  EXPECT_TRUE(slide_issue);
}

// The end stop's law (slide_stop) against its own definition: the force is minus the derivative
// of its energy (central differences, with the damper off), its stiffness and damping the
// derivatives of the force, it pushes toward the travel from either end and never pulls, and it
// is zero within the travel.
TEST(DynamicsTakeup, EndStopLawIsConsistent) {
  Sprocket w = three_wheels(13.0, 0.0, 600.0, 0.0, 0.0).model.sprockets[2];
  w.takeup_travel_min = -2e-3;
  w.takeup_travel_max = 1e-3;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> depth(0.0, 4.0 * w.contact_smoothing);
  std::uniform_real_distribution<double> speed(-0.05, 0.05);
  for (int trial = 0; trial < 200; ++trial) {
    const bool far = trial % 2 == 0;  // past travel_max (else before travel_min)
    const double g = depth(rng), v = speed(rng);
    const double s = far ? w.takeup_travel_max + g : w.takeup_travel_min - g;
    w.contact_damping = 0.0;
    const SlideStop elastic = slide_stop(w, s, 0.0);
    EXPECT_NEAR(elastic.penetration, g, 1e-15);
    const double eps = 1e-10;
    const double dE =
        (slide_stop(w, s + eps, 0.0).energy - slide_stop(w, s - eps, 0.0).energy) / (2 * eps);
    EXPECT_NEAR(elastic.force, -dE, 1e-5 * std::max(1.0, std::abs(elastic.force))) << g;
    EXPECT_EQ(elastic.force > 0.0, !far);  // toward the travel
    w.contact_damping = 800.0;
    const SlideStop st = slide_stop(w, s, v);
    if (st.force == 0.0) {  // separating fast enough: no pull
      EXPECT_EQ(st.stiffness, 0.0);
      continue;
    }
    EXPECT_EQ(st.force > 0.0, !far);
    const double ks =
        -(slide_stop(w, s + eps, v).force - slide_stop(w, s - eps, v).force) / (2 * eps);
    const double cs = -(slide_stop(w, s, v + 1e-7).force - slide_stop(w, s, v - 1e-7).force) / 2e-7;
    EXPECT_NEAR(st.stiffness, ks, 1e-5 * std::abs(ks) + 1e-3) << g << " " << v;
    EXPECT_NEAR(st.damping, cs, 1e-6 * std::abs(cs) + 1e-9) << g << " " << v;
    EXPECT_LE(st.damping_power, 0.0);
  }
  // within the travel: nothing
  for (const double s : {-2e-3, -1e-3, 0.0, 1e-3}) {
    const SlideStop st = slide_stop(w, s, 0.3);
    EXPECT_EQ(st.force, 0.0);
    EXPECT_EQ(st.energy, 0.0);
    EXPECT_EQ(st.penetration, 0.0);
  }
}

// The Newton matrix's slide entries with an end stop pressed (either end, the damper on) against
// central differences of the residual: the stop's stiffness hθk and damping c join the slide's
// own entry, nothing else.
TEST(DynamicsTakeup, EndStopJacobianMatchesFiniteDifferences) {
  for (const double past : {1.0, -1.0}) {
    Loop l = three_wheels(13.0, 10.0, 600.0, 0.0, 50.0);
    Sprocket& idler = l.model.sprockets[2];
    idler.contact_damping = 800.0;
    idler.takeup_travel_max = 1e-4;
    idler.takeup_travel_min = -1e-4;
    l.state.slide[2] = 0.9e-4 * past;
    l.state.slide_speed[2] = 0.01 * past;
    const double h = 1e-4;
    Integrator integ(l.model, {.step = h, .theta = 0.6});
    const std::size_t n = l.model.nodes(), size = integ.unknowns();
    std::vector<double> u(size);
    for (std::size_t i = 0; i < n; ++i) {
      u[2 * i] = l.state.x[i] + h * l.state.vx[i];
      u[2 * i + 1] = l.state.y[i] + h * l.state.vy[i];
    }
    u[2 * n] = l.state.angle[1] + h * l.state.speed[1];
    u[2 * n + 1] = l.state.angle[2] + h * l.state.speed[2];
    const std::size_t rs = 2 * n + 2;
    u[rs] = past * 1.3e-4;  // its θ point 2.2e-5 past the end: beyond the smoothing ε
    std::vector<double> r0, jac;
    integ.newton_system(l.model, l.state, u, r0, &jac);
    const double fd = testing::residual_difference(integ, l.model, l.state, u, rs, 1e-10)[rs];
    EXPECT_NEAR(jac[rs * size + rs], fd, 1e-6 * std::abs(fd)) << past;
    // the stop is what dominates the entry: h θ k_c + c_c against the slide's m/(hθ) + c_t
    EXPECT_GT(jac[rs * size + rs], 0.5 * h * 0.6 * idler.contact_stiffness) << past;
    // and the stop pushes the slide back: R_s = −h F_stop + … is positive past travel_max
    Loop free = l;
    free.model.sprockets[2].takeup_travel_max = INFINITY;
    free.model.sprockets[2].takeup_travel_min = -INFINITY;
    Integrator integ_free(free.model, {.step = h, .theta = 0.6});
    std::vector<double> r_free;
    integ_free.newton_system(free.model, free.state, u, r_free, nullptr);
    const double th_point = 0.4 * l.state.slide[2] + 0.6 * u[rs];
    const SlideStop st = slide_stop(idler, th_point, (u[rs] - l.state.slide[2]) / h);
    EXPECT_NEAR(r0[rs] - r_free[rs], -h * st.force, 1e-9 * std::abs(h * st.force)) << past;
  }
}

}  // namespace
}  // namespace catena::dynamics
