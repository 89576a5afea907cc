// Hinge friction in a running drive (issue 21; docs/models/dynamics.md, "Hinges").
//
// Closed form: in a steady drive over two equal sprockets every hinge articulates by 2π/z as it
// enters a wheel and straightens by 2π/z as it leaves, each time under its span's tension; the
// wrapped links turn with the wheel and the spans' links run straight. So the hinges dissipate
//     P = e (2π/z) (z ω/2π) [driven: T_tight + T_slack; driver: T_slack + T_tight]
//       = 2 e ω (T_tight + T_slack)
// (e the friction arm μ r, ω the driver's speed), and the driver's mean torque at the same load
// rises by P/ω = 2 e (T_tight + T_slack).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "../dynamics/period_mean.hpp"
#include "catena/dynamics/integrator.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

struct HingeDriveRun {
  std::vector<double> time, tight, slack, driver_torque, hinge_power, engaging_power;
  // per step, over the engaging zone's hinges: Σ |Δβ|/h, Σ T_span |Δβ|/h (T_span the mid-span
  // tension of the hinge's side: tight above the centres, slack below) and Σ e F |Δβ|/h (F the
  // pin load: Coulomb's torque at the hinge's own load, no rate band)
  std::vector<double> turn_rate, span_turn, coulomb_power;
  // the same two sums split by which link holds the hinge's pin (the outer link, pin_link_side,
  // whatever the run's rule): [0] the link on the span's side (its midpoint the farther from the
  // nearest wheel's centre), [1] the link on the wheel's side
  std::vector<double> held_span_turn[2], held_coulomb_power[2];
  // and by the side: [0] the tight span's (above the centres), [1] the slack span's
  std::vector<double> side_engaging_power[2], side_span_turn[2], side_coulomb_power[2];
  // per step, the hinges' power within kZones[z] pitches of a span's end, and over every hinge
  // the power of those turning slowly, |ω| < 2 ω_ε (inside the rate band and its edge)
  std::vector<double> zone_power[5], slow_power;
  double mean_iterations = 0.0;
  double mean_factorizations = 0.0;  // the fresh Newton matrices factored a step
  int max_iterations = 0;
  bool converged = true;
};

// The drive of validation (6) (tests/validation/dynamics_drive_test.cpp): 12B, z = 12, 10 pitches
// between the centres, driver at 13 rad/s, driven J = 0.01 kg m², load 10 N·m.
constexpr int kTeeth = 12, kSpan = 10;
constexpr double kPitch = 0.01905, kOmega = 13.0;
// the engaging zone's radii tried, in pitches (the tests' zone is kZones[1] = 1.5)
constexpr double kZones[5] = {1.0, 1.5, 2.0, 2.5, 3.0};

// `stick` > 0: the hinges' stick law with k_t = `stick` [N·m/rad] (no damper; "Hinges: sticking").
Model drive_model(double arm, double band, bool tooth_tip = false,
                  PinLoad pin_load = PinLoad::kMean, double stick = 0.0) {
  constexpr double roller = 0.01207, width = 0.01168;
  const std::size_t n = static_cast<std::size_t>(kTeeth + 2 * kSpan);
  Model model = uniform_chain(n, true, kPitch * (1.0 - 1e-3), 0.0238, 5e7, 100.0, false);
  Sprocket a = iso606_sprocket(kPitch, roller, width, kTeeth, 0.0, 0.0, 2e8, 800.0);
  a.driver = true;
  a.speed = kOmega;
  Sprocket b = iso606_sprocket(kPitch, roller, width, kTeeth, kSpan * kPitch, 0.0, 2e8, 800.0);
  b.inertia = 0.01;
  b.load_torque = 10.0;
  // tooth_tip = false: the seats' form before the tooth tip (straight flanks to the reach R + r),
  // on which the closed form below gives 0.999 by a cancellation; the default ISO tip and arc
  // flanks give 0.820 (ToothTipDriveArticulatesAsTheClosedFormUnderALowerPinLoad says why).
  if (!tooth_tip) {
    for (Sprocket* w : {&a, &b}) {
      w->tip_radius = 0.0;
      w->flank_radius = 0.0;
    }
  }
  model.sprockets = {a, b};
  model.hinge = {.arm = arm, .rate_band = band, .pin_load = pin_load};
  model.hinge.stick_stiffness = stick;
  return model;
}

HingeDriveRun run_drive(double arm, double band, double duration, double step,
                        bool tooth_tip = false, PinLoad pin_load = PinLoad::kMean,
                        double stick = 0.0) {
  constexpr int z = kTeeth, m = kSpan;
  constexpr double pitch = kPitch, omega = kOmega;
  const std::size_t n = static_cast<std::size_t>(z + 2 * m);
  const Model model = drive_model(arm, band, tooth_tip, pin_load, stick);
  const HingeFriction pin_links{.arm = arm, .rate_band = band, .pin_load = PinLoad::kPinLink};
  const Sprocket& a = model.sprockets[0];
  State s = two_sprocket_loop(z, m, pitch, a.pitch_radius, omega);
  Integrator integ(model, {.step = step, .theta = 0.6});
  std::vector<double> tension(model.links());
  double span_tension[2] = {0.0, 0.0};  // the last step's mid-span tensions, above and below
  HingeDriveRun out;
  const int steps = static_cast<int>(std::lround(duration / step));
  long iterations = 0;
  long factorizations = 0;
  for (int k = 0; k < steps; ++k) {
    const State before = s;
    const StepReport rep = integ.step(model, s);
    // the hinges within 1.5 pitches of a span's end (a wheel's tangent point): the entering and
    // leaving hinges, which articulate there; the others (wrapped, or in a span)
    double engaging = 0.0, turn = 0.0, span_turn = 0.0, coulomb = 0.0;
    double held_span_turn[2] = {0.0, 0.0}, held_coulomb[2] = {0.0, 0.0};
    double side_engaging[2] = {0.0, 0.0}, side_span_turn[2] = {0.0, 0.0},
           side_coulomb[2] = {0.0, 0.0};
    double zone[5] = {0.0, 0.0, 0.0, 0.0, 0.0}, slow = 0.0;
    if (arm > 0.0) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t ia = (i + n - 1) % n, ic = (i + 1) % n;
        const double x0[3] = {before.x[ia], before.x[i], before.x[ic]};
        const double y0[3] = {before.y[ia], before.y[i], before.y[ic]};
        const double x1[3] = {s.x[ia], s.x[i], s.x[ic]}, y1[3] = {s.y[ia], s.y[i], s.y[ic]};
        const double ex = std::min(std::abs(s.x[i]), std::abs(s.x[i] - m * pitch));
        const double ey = std::abs(std::abs(s.y[i]) - a.pitch_radius);
        const double distance = std::hypot(ex, ey);
        // the couple the step applied: with the stick law, from the hinge's deflection at the
        // step's start
        const double d0 = before.hinge_deflection.empty() ? 0.0 : before.hinge_deflection[i];
        const HingeCouple hc = hinge_couple(model.hinge, model.axial_stiffness, model.pitch, x0, y0,
                                            x1, y1, 0.6, step, i, d0);
        for (int r = 0; r < 5; ++r) {
          if (distance <= kZones[r] * pitch) zone[r] += hc.work;
        }
        if (std::abs(hc.rate) < 2.0 * band) slow += hc.work;
        if (distance > kZones[1] * pitch) continue;
        engaging += hc.work;
        turn += std::abs(hc.turn);
        coulomb += arm * hc.load * std::abs(hc.turn);
        const double t_span = (s.y[i] > 0.0 ? span_tension[0] : span_tension[1]);
        span_turn += t_span * std::abs(hc.turn);
        // the pin link (0 the hinge's first link ia → i, 1 its second i → ic) on the span's side?
        const double cx = std::abs(s.x[i]) < std::abs(s.x[i] - m * pitch) ? 0.0 : m * pitch;
        const double r0 = std::hypot(0.5 * (x1[0] + x1[1]) - cx, 0.5 * (y1[0] + y1[1]));
        const double r1 = std::hypot(0.5 * (x1[1] + x1[2]) - cx, 0.5 * (y1[1] + y1[2]));
        const int span_link = r0 > r1 ? 0 : 1;
        const int held = pin_link_side(pin_links, i) == span_link ? 0 : 1;
        held_span_turn[held] += t_span * std::abs(hc.turn);
        held_coulomb[held] += arm * hc.load * std::abs(hc.turn);
        const int side = s.y[i] > 0.0 ? 0 : 1;
        side_engaging[side] += hc.work;
        side_span_turn[side] += t_span * std::abs(hc.turn);
        side_coulomb[side] += arm * hc.load * std::abs(hc.turn);
      }
    }
    if (!rep.converged) {
      std::printf("step %d: %d iterations, correction %g, backtracks %d\n", k, rep.iterations,
                  rep.last_correction, rep.backtracks);
      out.converged = false;
      break;
    }
    iterations += rep.iterations;
    factorizations += rep.factorizations;
    out.max_iterations = std::max(out.max_iterations, rep.iterations);
    link_tensions(model, s, tension);
    const auto [top, bottom] = span_middle_links(s, m * pitch);
    out.time.push_back(s.time);
    out.tight.push_back(tension[top]);
    out.slack.push_back(tension[bottom]);
    out.driver_torque.push_back(integ.applied_torque()[0]);
    out.hinge_power.push_back(rep.hinge_work / step);
    out.engaging_power.push_back(engaging / step);
    out.turn_rate.push_back(turn / step);
    out.span_turn.push_back(span_turn / step);
    out.coulomb_power.push_back(coulomb / step);
    for (int r = 0; r < 5; ++r) out.zone_power[r].push_back(zone[r] / step);
    out.slow_power.push_back(slow / step);
    for (int c = 0; c < 2; ++c) {
      out.held_span_turn[c].push_back(held_span_turn[c] / step);
      out.held_coulomb_power[c].push_back(held_coulomb[c] / step);
      out.side_engaging_power[c].push_back(side_engaging[c] / step);
      out.side_span_turn[c].push_back(side_span_turn[c] / step);
      out.side_coulomb_power[c].push_back(side_coulomb[c] / step);
    }
    span_tension[0] = tension[top];
    span_tension[1] = tension[bottom];
  }
  out.mean_iterations = static_cast<double>(iterations) /
                        static_cast<double>(std::max<std::size_t>(1, out.time.size()));
  out.mean_factorizations = static_cast<double>(factorizations) /
                            static_cast<double>(std::max<std::size_t>(1, out.time.size()));
  return out;
}

// The scatter of a figure averaged over the whole tooth periods after t0 (six on these runs),
// printed for the docs from the samples at hand: the mean of `series` over the window's halves and
// thirds and over the whole periods after 0.1 s, each against the closed form's 2 e ω (T_tight +
// T_slack) (`per` its share: 1 for a power, 1/ω for a torque) with the run's mean mid-span
// tensions over the same stretch.
struct WindowMeans {
  double halves[2], thirds[3], from_early;
};

WindowMeans window_means(const HingeDriveRun& run, const std::vector<double>& series, double arm,
                         double per, double t0, double period) {
  const std::vector<double>& time = run.time;
  auto ratio = [&](double a, double b) {
    const double expected =
        2.0 * arm * kOmega *
        (mean_between(time, run.tight, a, b) + mean_between(time, run.slack, a, b));
    return mean_between(time, series, a, b) / (per * expected);
  };
  const double whole = std::floor((time.back() - t0) / period) * period;
  WindowMeans w{};
  for (int k = 0; k < 2; ++k) w.halves[k] = ratio(t0 + k * whole / 2, t0 + (k + 1) * whole / 2);
  for (int k = 0; k < 3; ++k) w.thirds[k] = ratio(t0 + k * whole / 3, t0 + (k + 1) * whole / 3);
  const double early = 0.1;
  w.from_early = ratio(early, early + std::floor((time.back() - early) / period) * period);
  return w;
}

// The driver's torque rise over `without` (both runs sample the same steps), against P/ω.
WindowMeans torque_rise_windows(const HingeDriveRun& with, const HingeDriveRun& without, double arm,
                                double t0, double period) {
  std::vector<double> rise(with.time.size());
  for (std::size_t k = 0; k < rise.size(); ++k)
    rise[k] = without.driver_torque.at(k) - with.driver_torque[k];
  return window_means(with, rise, arm, 1.0 / kOmega, t0, period);
}

void print_windows(const char* what, const WindowMeans& w) {
  std::printf("%s: halves %.3f / %.3f, thirds %.3f / %.3f / %.3f, from 0.1 s %.3f\n", what,
              w.halves[0], w.halves[1], w.thirds[0], w.thirds[1], w.thirds[2], w.from_early);
}

TEST(DynamicsHinge, DriveLosesTheClosedFormPowerInItsHinges) {
  constexpr double arm = 0.1 * 0.00572 / 2;  // μ = 0.1 on the 12B pin (d2 = 5.72 mm)
  constexpr double duration = 0.5, step = 1e-4, period = 2 * kPi / (12 * 13.0);
  const HingeDriveRun with = run_drive(arm, 5.0, duration, step);
  const HingeDriveRun without = run_drive(0.0, 5.0, duration, step);
  const HingeDriveRun wide = run_drive(arm, 20.0, duration, step);  // a 20 rad/s band
  ASSERT_TRUE(with.converged);
  ASSERT_TRUE(without.converged);
  ASSERT_TRUE(wide.converged);
  const double t0 = 0.5 * duration;
  const double tight = mean_over_periods(with.time, with.tight, t0, period);
  const double slack = mean_over_periods(with.time, with.slack, t0, period);
  const double power = -mean_over_periods(with.time, with.hinge_power, t0, period);
  const double engaging = -mean_over_periods(with.time, with.engaging_power, t0, period);
  const double expected = 2.0 * arm * 13.0 * (tight + slack);
  std::printf("engaging %.4f W (%.3f)\n", engaging, engaging / expected);
  const double torque_rise = -mean_over_periods(with.time, with.driver_torque, t0, period) +
                             mean_over_periods(without.time, without.driver_torque, t0, period);
  std::printf(
      "tight %.2f slack %.2f power %.4f W expected %.4f W (%.3f); torque rise %.4f "
      "expected %.4f (%.3f); iterations %.2f (max %d) / %.2f (max %d)\n",
      tight, slack, power, expected, power / expected, torque_rise, expected / 13.0,
      torque_rise * 13.0 / expected, with.mean_iterations, with.max_iterations,
      without.mean_iterations, without.max_iterations);
  double zone[5];
  std::printf("zone radius:");
  for (int r = 0; r < 5; ++r) {
    zone[r] = -mean_over_periods(with.time, with.zone_power[r], t0, period) / expected;
    std::printf(" %.1f pitches %.3f;", kZones[r], zone[r]);
  }
  const double slow = -mean_over_periods(with.time, with.slow_power, t0, period);
  const double wide_power = -mean_over_periods(wide.time, wide.hinge_power, t0, period);
  const double wide_expected = 2.0 * arm * 13.0 *
                               (mean_over_periods(wide.time, wide.tight, t0, period) +
                                mean_over_periods(wide.time, wide.slack, t0, period));
  std::printf(
      "\nhinges at |w| < 2 w_e: %.4f W (%.3f); all hinges with a 20 rad/s band %.4f W of %.4f W "
      "(%.3f)\n",
      slow, slow / expected, wide_power, wide_expected, wide_power / wide_expected);
  // the figures' scatter over the averaging window (the same runs' samples)
  print_windows("zone 1 pitch", window_means(with, with.zone_power[0], arm, -1.0, t0, period));
  print_windows("zone 2.5 pitches", window_means(with, with.zone_power[3], arm, -1.0, t0, period));
  print_windows("hinges at |w| < 2 w_e",
                window_means(with, with.slow_power, arm, -1.0, t0, period));
  print_windows("all hinges, 20 rad/s band",
                window_means(wide, wide.hinge_power, arm, -1.0, t0, period));
  print_windows("torque rise / (P/w)", torque_rise_windows(with, without, arm, t0, period));
  // The entering and leaving hinges against the closed form: 0.999 measured on the old seat form,
  // a cancellation: 21 % more articulation than 2π/z a point (0.163 of the closed form 1–1.5
  // pitches into the span) against the lower pin load and the rate band (the factors:
  // ToothTipDriveArticulatesAsTheClosedFormUnderALowerPinLoad). Kept as a regression check of
  // the old form.
  EXPECT_NEAR(engaging / expected, 1.0, 0.05);
  // The zone's radius matters on this form, so the 5 % is the tolerance of the 1.5-pitch choice:
  // 0.836 at 1 pitch (part of the articulation missed), 1.047 at 2.5 (span vibration comes in);
  // measured 0.836 / 0.999 / 1.016 / 1.047 / 1.061 at 1, 1.5, 2, 2.5, 3 pitches; over the
  // averaging window's halves 0.836 / 0.836 and 1.047 / 1.046 (printed above).
  EXPECT_NEAR(zone[0], 0.836, 0.02);
  EXPECT_NEAR(zone[3], 1.047, 0.02);
  // All hinges: more, by the spans' transverse vibration and the rollers' motion in their seats,
  // which the regularised law dissipates within its rate band (1.162 measured).
  EXPECT_GT(power, engaging);
  EXPECT_LT(power / expected, 1.25);
  // of which the hinges turning slowly (|ω| < 2 ω_ε, any hinge) take 2.55 W, 0.284 of the closed
  // form (0.283 / 0.284 over the window's halves)
  EXPECT_NEAR(slow / expected, 0.284, 0.02);
  // A wider band trades that for the other error: at ω_ε = 20 rad/s all hinges take 0.802 of the
  // closed form (0.803 / 0.801 over the halves): the fast articulations no longer reach Coulomb's
  // torque.
  EXPECT_NEAR(wide_power / wide_expected, 0.80, 0.03);
  // The driver's torque rises by less than P/ω: the hinges' friction damps the seat impacts and
  // span vibration, so the contact and link dampers take less. Measured 0.845 over the last six
  // tooth periods; it is the noisiest figure here (0.907 / 0.782 over the window's halves,
  // 0.829 / 0.873 / 0.833 over its thirds, 0.834 over nine periods from 0.1 s; the 0.893 first
  // measured lies within that scatter), so it is held to ± 0.15 (twice the six periods' standard
  // error) and below the hinges' power.
  EXPECT_NEAR(torque_rise * 13.0 / expected, 0.845, 0.15);
  EXPECT_LT(torque_rise * 13.0, power);
}

// The closed form's three assumptions, measured on the engaging hinges (within 1.5 pitches of a
// span's end) of a run: P_engaging / P_closed = K L B exactly, with
//   K = e Σ T_span |Δβ| / (h P_closed)  the articulation: 1 if each hinge turns by 2π/z at each of
//                                        the four points under its span's tension T_span;
//   L = Σ F |Δβ| / Σ T_span |Δβ|         the pin load F (the mean of the two links' tensions) at
//                                        the articulating hinge against the span's tension;
//   B = P_engaging / (e Σ F |Δβ| / h)    the rate band: the regularised torque against Coulomb's.
struct HingeFactors {
  double tight, slack, expected, engaging, articulation, load, band, turn_per_point;
  double
      held_load[2];  // L over the hinges whose pin the span's side link holds [0], the wheel's [1]
  // per side, [0] tight, [1] slack: L, and K L B = the engaging power against the side's share of
  // the closed form, 2 e ω T_side (its two points, entering one wheel and leaving the other)
  double side_load[2], side_total[2];
  // every hinge's power, and the hinges' within each of kZones' radii, against the closed form
  double all, zone[5];
};

HingeFactors hinge_factors(const HingeDriveRun& run, double arm, double t0, double period) {
  HingeFactors f{};
  f.tight = mean_over_periods(run.time, run.tight, t0, period);
  f.slack = mean_over_periods(run.time, run.slack, t0, period);
  f.expected = 2.0 * arm * kOmega * (f.tight + f.slack);
  f.engaging = -mean_over_periods(run.time, run.engaging_power, t0, period);
  const double span = arm * mean_over_periods(run.time, run.span_turn, t0, period);
  const double coulomb = mean_over_periods(run.time, run.coulomb_power, t0, period);
  f.articulation = span / f.expected;
  f.load = coulomb / span;
  f.band = f.engaging / coulomb;
  f.turn_per_point = mean_over_periods(run.time, run.turn_rate, t0, period) / 4.0;
  for (int c = 0; c < 2; ++c)
    f.held_load[c] = mean_over_periods(run.time, run.held_coulomb_power[c], t0, period) /
                     (arm * mean_over_periods(run.time, run.held_span_turn[c], t0, period));
  for (int c = 0; c < 2; ++c) {
    const double t_side = c == 0 ? f.tight : f.slack;
    f.side_load[c] = mean_over_periods(run.time, run.side_coulomb_power[c], t0, period) /
                     (arm * mean_over_periods(run.time, run.side_span_turn[c], t0, period));
    f.side_total[c] = -mean_over_periods(run.time, run.side_engaging_power[c], t0, period) /
                      (2.0 * arm * kOmega * t_side);
  }
  std::printf(
      "tight %.1f slack %.1f: engaging %.4f W of %.4f W (%.3f) = articulation %.3f (%.2f rad/s a "
      "point, closed form %.1f) x load %.3f x band %.3f; load where the span's side link holds "
      "the pin %.3f, the wheel's %.3f\n",
      f.tight, f.slack, f.engaging, f.expected, f.engaging / f.expected, f.articulation,
      f.turn_per_point, kOmega, f.load, f.band, f.held_load[0], f.held_load[1]);
  std::printf("  tight side: load %.3f, total %.3f; slack side: load %.3f, total %.3f\n",
              f.side_load[0], f.side_total[0], f.side_load[1], f.side_total[1]);
  f.all = -mean_over_periods(run.time, run.hinge_power, t0, period) / f.expected;
  std::printf("  all hinges %.4f W (%.3f); zone radius:", f.all * f.expected, f.all);
  for (int z = 0; z < 5; ++z) {
    f.zone[z] = -mean_over_periods(run.time, run.zone_power[z], t0, period) / f.expected;
    std::printf(" %.1f pitches %.3f;", kZones[z], f.zone[z]);
  }
  std::printf(" Newton %.2f a step (max %d)\n", run.mean_iterations, run.max_iterations);
  return f;
}

// The driver's mean torque rise over a frictionless run of the same drive (`without`), over the
// whole tooth periods after t0, against the closed form's P/ω (`expected` the closed form's P).
double torque_rise_ratio(const HingeDriveRun& with, const HingeDriveRun& without, double expected,
                         double t0, double period) {
  const double rise = -mean_over_periods(with.time, with.driver_torque, t0, period) +
                      mean_over_periods(without.time, without.driver_torque, t0, period);
  return rise * kOmega / expected;
}

// The default seat form (ISO tooth tip and arc flanks): the engaging hinges give 0.820 of the
// closed form, and the factors say why: 0.820 = 1.023 x 0.893 x 0.897. The articulation is the
// closed form's (13.3 rad/s a point against ω = 13; the zone takes all of it: 1.5 to 3 pitches
// change the total by 0.008, 1 to 3 by 0.013), but the arc flank carries the roller while its hinge
// turns, so the link on the wheel's side is already partly unloaded by the seat and the pin load
// (the mean of the two links' tensions) is 0.893 of the span's; and the rate band takes 10 % of
// Coulomb's torque (a 2 rad/s band gives 0.875 in all, 1 rad/s 0.886). On the old straight-flank
// form the 0.999 above is a cancellation: 1.212 x 0.926 x 0.891 — its hinges turn 21 % more than
// 2π/z at a point (16.1 rad/s: a second articulation 1–1.5 pitches into the span, which
// the 1.5-pitch zone happened to include). The closed form assumes L = B = 1 and neither is this
// model's (L < 1 is the seat's share of the load, B < 1 the regularisation), so the total is
// pinned; K is tested.
TEST(DynamicsHinge, ToothTipDriveArticulatesAsTheClosedFormUnderALowerPinLoad) {
  constexpr double arm = 0.1 * 0.00572 / 2;
  constexpr double duration = 0.5, step = 1e-4, period = 2 * kPi / (12 * 13.0);
  const HingeDriveRun tip = run_drive(arm, 5.0, duration, step, true);
  const HingeDriveRun old = run_drive(arm, 5.0, duration, step, false);
  ASSERT_TRUE(tip.converged);
  ASSERT_TRUE(old.converged);
  const HingeFactors t = hinge_factors(tip, arm, 0.5 * duration, period);
  const HingeFactors o = hinge_factors(old, arm, 0.5 * duration, period);
  // (K L B = P_engaging / P_closed holds by the factors' definitions, whatever the run: it is not
  // asserted; the bounds below on each factor are)
  // the closed form's kinematics hold with the tip: each point turns its hinges at ω (within the
  // 5 % the closed form was held to on the old form)
  EXPECT_NEAR(t.turn_per_point / kOmega, 1.0, 0.05);
  EXPECT_NEAR(t.articulation, 1.0, 0.05);
  // and not on the old form, where the hinges articulate more than the closed form's 2π/z
  EXPECT_GT(o.articulation, t.articulation + 0.1);
  // the pin load at the articulating hinge is below the span's tension: the flank takes part of
  // it; less so on the straight flank, where the roller meets its seat later
  EXPECT_LT(t.load, 0.95);
  EXPECT_GT(t.load, 0.8);
  EXPECT_LT(t.load, o.load);
  // the regularisation costs Coulomb's torque at the rates the hinges articulate with
  EXPECT_LT(t.band, 0.95);
  EXPECT_GT(t.band, 0.8);
  // pinned: 0.820 measured
  EXPECT_NEAR(t.engaging / t.expected, 0.820, 0.03);
  // and the zone is not the cause: from 1 to 3 pitches the total moves by 0.013 (0.815, 0.820,
  // 0.823, 0.825, 0.828 at 1, 1.5, 2, 2.5, 3 pitches), the articulation lying within the zone;
  // on the old form by 0.225 (0.836 to 1.061)
  EXPECT_LT(std::abs(t.zone[4] - t.zone[0]), 0.02);
  EXPECT_GT(o.zone[4] - o.zone[0], 0.2);
  // all hinges: 0.843 of the closed form with the tip (the engaging 0.820 and 0.023 outside the
  // zone; 0.8439 / 0.8429 over the window's halves), against 1.162 on the old form
  const WindowMeans all = window_means(tip, tip.hinge_power, arm, -1.0, 0.5 * duration, period);
  std::printf("all hinges with the tip: halves %.4f / %.4f\n", all.halves[0], all.halves[1]);
  EXPECT_NEAR(t.all, 0.843, 0.01);
}

// The hinges' stick law on the same tooth-tip drive (k_t = 1e4 N·m/rad, no damper: the ratio
// k_t (θh)²/(m p²) is 4.2, below the command's warning at 10): a sliding hinge carries Coulomb's
// torque e F at any rate, so the rate band's share goes (B = 1) and the engaging hinges give K L
// of the closed form; the pin load's share L and the articulation K are the regularised run's.
// Measured: B 0.999 (0.897 regularised), L 0.893 (0.893), K 1.009 (1.023), K L B 0.901 (0.820);
// 0.900–0.901 from k_t = 1e3 to 2e4.
TEST(DynamicsHinge, StickLawTakesTheRateBandsShareOffTheToothTipDrive) {
  constexpr double arm = 0.1 * 0.00572 / 2;
  constexpr double duration = 0.5, step = 1e-4, period = 2 * kPi / (12 * 13.0);
  const HingeDriveRun band = run_drive(arm, 5.0, duration, step, true);
  const HingeDriveRun stick = run_drive(arm, 5.0, duration, step, true, PinLoad::kMean, 1e4);
  const HingeDriveRun none = run_drive(0.0, 5.0, duration, step, true);  // frictionless hinges
  ASSERT_TRUE(band.converged);
  ASSERT_TRUE(stick.converged);
  ASSERT_TRUE(none.converged);
  const HingeFactors b = hinge_factors(band, arm, 0.5 * duration, period);
  const HingeFactors s = hinge_factors(stick, arm, 0.5 * duration, period);
  const double band_rise = torque_rise_ratio(band, none, b.expected, 0.5 * duration, period);
  const double stick_rise = torque_rise_ratio(stick, none, s.expected, 0.5 * duration, period);
  std::printf("torque rise over the frictionless run: %.3f of P/w (regularised), %.3f (stick)\n",
              band_rise, stick_rise);
  const WindowMeans band_w = torque_rise_windows(band, none, arm, 0.5 * duration, period);
  const WindowMeans stick_w = torque_rise_windows(stick, none, arm, 0.5 * duration, period);
  print_windows("torque rise, regularised", band_w);
  print_windows("torque rise, stick law", stick_w);
  std::printf("their difference: halves %.3f / %.3f, thirds %.3f / %.3f / %.3f\n",
              stick_w.halves[0] - band_w.halves[0], stick_w.halves[1] - band_w.halves[1],
              stick_w.thirds[0] - band_w.thirds[0], stick_w.thirds[1] - band_w.thirds[1],
              stick_w.thirds[2] - band_w.thirds[2]);
  std::printf("frictionless run with the tip: Newton %.2f a step (max %d)\n", none.mean_iterations,
              none.max_iterations);
  // Coulomb's torque at the articulating hinges' rates, where the band took 10 %
  EXPECT_NEAR(s.band, 1.0, 0.01);
  EXPECT_LT(b.band, 0.95);
  // the pin load's share and the articulation are not the law's
  EXPECT_NEAR(s.load, b.load, 0.01);
  EXPECT_NEAR(s.articulation, 1.0, 0.05);
  // pinned: 0.901 measured
  EXPECT_NEAR(s.engaging / s.expected, 0.90, 0.03);
  EXPECT_GT(s.engaging / s.expected, b.engaging / b.expected + 0.05);
  // The driver's torque rise over the frictionless run (as in
  // DriveLosesTheClosedFormPowerInItsHinges), against P/ω: 0.784 regularised, 0.878 with the stick
  // law. Each is noisy (over the window's halves 0.851 / 0.717 and 0.953 / 0.803; nine periods
  // from 0.1 s give 0.796 and 0.872), held to ± 0.15 (twice the six periods' standard error);
  // the regularised one is the hinges' whole power (0.843) within that scatter. Their difference
  // is not noisy (0.102 / 0.086 over the halves, 0.108 / 0.089 / 0.086 over the thirds): the
  // stick law raises the rise by 0.094, as it raises all hinges' power (0.843 → 0.933).
  EXPECT_NEAR(band_rise, 0.784, 0.15);
  EXPECT_NEAR(stick_rise, 0.878, 0.15);
  EXPECT_NEAR(stick_rise - band_rise, 0.094, 0.03);
  EXPECT_NEAR(stick_rise - band_rise, s.all - b.all, 0.03);
}

// The pin load as the pin link's tension (PinLoad::kPinLink: links alternate inner and outer,
// link 0 outer; F at a hinge is its outer link's tension) on the tooth-tip drive above, against
// the mean. Split by which link holds the articulating hinge's pin: where it is the link on the
// span's side, F is the span's tension (L = 1.000 measured); where it is the link on the wheel's
// side, partly unloaded by the flank, F is lower (0.787); the mean gives both classes 0.893. The
// classes alternate, so in all L is the mean's (0.893), and so are K L B (0.820) and each side's
// L and total (tight 0.876 / 0.802, slack 0.924 / 0.852, as with the mean to 3 digits): the
// pin-holding link's tension does not explain the tip's 0.820, it averages to the mean. Checked
// against the mean's run, not against a number (the mean's K L B is pinned by the test above).
TEST(DynamicsHinge, PinLinkLoadAlternatesAtTheToothTipAndAveragesToTheMean) {
  constexpr double arm = 0.1 * 0.00572 / 2;
  constexpr double duration = 0.5, step = 1e-4, period = 2 * kPi / (12 * 13.0);
  const HingeDriveRun mean = run_drive(arm, 5.0, duration, step, true);
  const HingeDriveRun pin = run_drive(arm, 5.0, duration, step, true, PinLoad::kPinLink);
  ASSERT_TRUE(mean.converged);
  ASSERT_TRUE(pin.converged);
  const HingeFactors m = hinge_factors(mean, arm, 0.5 * duration, period);
  const HingeFactors l = hinge_factors(pin, arm, 0.5 * duration, period);
  std::printf(
      "pin link: K %.4f L %.4f B %.4f KLB %.4f (tight L %.4f total %.4f, slack L %.4f total "
      "%.4f)\nmean:     K %.4f L %.4f B %.4f KLB %.4f (tight L %.4f total %.4f, slack L %.4f "
      "total %.4f)\n",
      l.articulation, l.load, l.band, l.engaging / l.expected, l.side_load[0], l.side_total[0],
      l.side_load[1], l.side_total[1], m.articulation, m.load, m.band, m.engaging / m.expected,
      m.side_load[0], m.side_total[0], m.side_load[1], m.side_total[1]);
  // the mean loads both classes alike; the pin link loads the span side's at the span's tension
  // and the wheel side's below the mean
  EXPECT_NEAR(m.held_load[0], m.held_load[1], 0.01);
  EXPECT_NEAR(l.held_load[0], 1.0, 0.03);
  EXPECT_LT(l.held_load[1], m.load - 0.05);
  // the articulation is the closed form's with either load
  EXPECT_NEAR(l.articulation, 1.0, 0.05);
  // in all, and on each side, the alternation averages to the mean's load and total
  EXPECT_NEAR(l.load, m.load, 0.01);
  EXPECT_NEAR(l.engaging / l.expected, m.engaging / m.expected, 0.01);
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(l.side_load[c], m.side_load[c], 0.01) << c;
    EXPECT_NEAR(l.side_total[c], m.side_total[c], 0.01) << c;
  }
}

// Newton on the exact hinge Jacobian (the block-pentadiagonal solve): with hinge friction a step
// reuses factors (within the step, and the last step's for its first iterations: chord
// iterations, each a residual and a substitution), so it factors at most 0.6 times as often as
// the frictionless step, which factors at every iteration, and takes at most 1.5 times its
// iterations (11.5 with the lumped, tridiagonal matrix it replaced, every one factored); at the
// default band and at the narrow band ω_ε = 2 rad/s, which the lumped matrix could not converge.
TEST(DynamicsHinge, NewtonOnTheExactHingeJacobianFactorsLessOftenThanWithout) {
  constexpr double arm = 0.1 * 0.00572 / 2;
  const HingeDriveRun with = run_drive(arm, 5.0, 0.2, 1e-4);
  const HingeDriveRun narrow = run_drive(arm, 2.0, 0.2, 1e-4);
  const HingeDriveRun without = run_drive(0.0, 5.0, 0.2, 1e-4);
  std::printf("iterations: band 5 rad/s %.2f (max %d), 2 rad/s %.2f (max %d), none %.2f (max %d)\n",
              with.mean_iterations, with.max_iterations, narrow.mean_iterations,
              narrow.max_iterations, without.mean_iterations, without.max_iterations);
  ASSERT_TRUE(with.converged);
  ASSERT_TRUE(narrow.converged);
  ASSERT_TRUE(without.converged);
  std::printf("factorizations: band 5 rad/s %.2f, 2 rad/s %.2f, none %.2f a step\n",
              with.mean_factorizations, narrow.mean_factorizations, without.mean_factorizations);
  EXPECT_DOUBLE_EQ(without.mean_factorizations, without.mean_iterations);
  EXPECT_LT(with.mean_factorizations, 0.6 * without.mean_factorizations);
  EXPECT_LT(narrow.mean_factorizations, 0.6 * without.mean_factorizations);
  EXPECT_LT(with.mean_iterations, 1.5 * without.mean_iterations);
  EXPECT_LT(narrow.mean_iterations, 1.5 * without.mean_iterations);
}

// The convergence rate in the drive: one step of the running drive (after 20 ms) repeated with a
// cap of 1, 2, 3, … iterations, each run's last correction |δ_k|, to round-off (1e-15 p): the
// step converges there on |δ| or on its error estimate (ϑ/(1 − ϑ)·|δ_k| below the tolerance), and
// it must converge within 10 iterations. With the exact hinge Jacobian,
// hinge friction costs no iteration: at the integrator's tolerance (1e-10 p) the step converges in
// no more iterations than without it, at the default band and at 2 rad/s. To round-off
// the chord iterations' tail is linear (≈ 0.03 a step here, by design at most 0.25; the seat
// damper's exact Jacobian made the frictionless step quadratic there), so it takes two more
// iterations there (counted, not compared), and each correction below 1e-4 p must still be a
// tenth of the one before (a wrong Jacobian's ratio is larger). (The lumped
// matrix it replaced was linear at ≈ 0.6 a step: 11.5 iterations.) Quadratic convergence on a
// chain without contacts: tests/dynamics/hinge_friction_test.cpp.
// the running drive's state after 200 steps (none if a step failed)
std::optional<State> running_drive(const Model& model, double step) {
  State s = two_sprocket_loop(kTeeth, kSpan, kPitch, model.sprockets[0].pitch_radius, kOmega);
  Integrator run(model, {.step = step, .theta = 0.6});
  for (int k = 0; k < 200; ++k) {
    if (!run.step(model, s).converged) return std::nullopt;
  }
  return s;
}

// the iterations of that step at the default tolerance, from the constant-velocity predictor
// (a fresh integrator); 0 if it fails
int drive_iterations(double arm, double band) {
  constexpr double step = 1e-4;
  const Model model = drive_model(arm, band);
  std::optional<State> s = running_drive(model, step);
  if (!s) return 0;
  Integrator probe(model, {.step = step, .theta = 0.6});
  const StepReport rep = probe.step(model, *s);
  return rep.converged ? rep.iterations : 0;
}

// The step's corrections |δ_k|/p with a cap of 1, 2, 3, … iterations to round-off (1e-15 p);
// `converged` whether the step reached it (on |δ| or on the error estimate) within 10.
struct Corrections {
  std::vector<double> real;  ///< the last correction of each capped run, in pitches
  bool converged = false;
  bool estimated = false;  ///< stopped on the estimate (its last correction above the tolerance)
};

Corrections drive_corrections(double arm, double band) {
  constexpr double step = 1e-4, tolerance = 1e-15;
  const Model model = drive_model(arm, band);
  const std::optional<State> running = running_drive(model, step);
  Corrections out;
  if (!running) return out;
  const State& s = *running;
  for (int cap = 1; cap <= 10; ++cap) {
    Integrator probe(model,
                     {.step = step, .max_iterations = cap, .tolerance = tolerance, .theta = 0.6});
    State copy = s;
    const StepReport rep = probe.step(model, copy);
    if (rep.solve != SolveStatus::kSolved) return out;
    out.real.push_back(rep.last_correction / kPitch);
    if (rep.converged) {
      out.converged = true;
      out.estimated = rep.last_correction > tolerance * kPitch;
      break;
    }
  }
  std::printf("arm %.3g m, band %.0f rad/s, |dx|/p per iteration:", arm, band);
  for (double c : out.real) std::printf(" %.2e", c);
  std::printf("%s\n", out.estimated ? " (stopped on the estimate)" : "");
  return out;
}

TEST(DynamicsHinge, HingeFrictionCostsNewtonNoIterationInTheDrive) {
  constexpr double arm = 0.1 * 0.00572 / 2;
  const Corrections without = drive_corrections(0.0, 5.0);
  ASSERT_TRUE(without.converged);
  const int iterations_without = drive_iterations(0.0, 5.0);
  ASSERT_GT(iterations_without, 0);
  for (double band : {5.0, 2.0}) {
    const int iterations_with = drive_iterations(arm, band);
    std::printf("band %.0f rad/s: %d iterations at the default tolerance, %d without hinges\n",
                band, iterations_with, iterations_without);
    EXPECT_GT(iterations_with, 0) << band;
    EXPECT_LE(iterations_with, iterations_without) << band;
    // to round-off (converged on |δ| or on the estimate within the cap of 10); the chord
    // iterations' tail is linear (about 0.03 a step) where the frictionless step's is quadratic,
    // so it takes two more iterations than without hinges here (8 against 6 at 5 rad/s): their
    // count is not compared, their contraction is
    const Corrections with = drive_corrections(arm, band);
    ASSERT_TRUE(with.converged) << band;
    // each correction at most a tenth of the one before, once below 1e-4 p and while above
    // 1e-13 p (some 30 ulp of the loop's coordinates, up to 0.3 m, in pitches: corrections below
    // it are round-off, and a chord step undone there repeats its correction)
    for (std::size_t k = 0; k + 1 < with.real.size(); ++k) {
      if (with.real[k] < 1e-4 && with.real[k] > 1e-13) {
        EXPECT_LT(with.real[k + 1], 0.1 * with.real[k]) << band << " " << k;
      }
    }
  }
}

}  // namespace
}  // namespace catena::dynamics
