// Round-link chain on a pocket wheel, forced run-on (issue 21 validation (1), second half;
// docs/models/dynamics.md, "Pocket wheel: forced run-on"): the strand in a straight guide against
// the forced run-on kinematics of seed 003 (catena::pocketwheel::plan_run_on). Its runs, six of 10
// periods (8 averaged) and one of 18 (16 averaged), take about 2.8 s of CPU: a slow test (label
// "slow"); the free run-on is in dynamics_pocket_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/pocket_wheel.hpp"
#include "catena/pocketwheel/run_on.hpp"
#include "pocket_run.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
using testing::PocketRun;

// Forced (guided) run-on, seed 003 §3 (docs/models/dynamics.md, "Pocket wheel: forced run-on"):
// the strand runs in a straight guide at height H whose end is at x = −l (the paper's l =
// 256 mm), between two rails that hold its joints on the line y = H, and leaves it for the
// wheel as a free span. Compared with catena pocketwheel's forced run-on (plan_run_on with the
// chordal or tangential guide: the slider span, the paper's, and the pivot span over the edge).
// The state at t = 0 is the kinematics' φ = 0: the crank where y = H meets the pitch circle
// (θ0 = δ1/2 chordal, 0 tangential), the link that seats first (plan.first_link) upstream of it,
// the strand straight along the guide line and moving at ω dx/dφ(0). The chain's downstream end
// is pulled down by PocketRun::tail_force, so the chain leaves the wheel on its far side.
struct Forced {
  double worst = 0.0;        // max over the bins of |v_sim − v_slider| / ωR
  double worst_pivot = 0.0;  // the same against the pivot span
  double rms = 0.0;          // the rms over the bins of (v_sim − v_slider) / ωR
  double max_penetration = 0.0;
  double rail_gap = 0.0;  // [m] the largest |y − H| of a guided joint
  // [m] the largest |x − R| of a joint downstream of the crank off the wheel (more than 1 mm
  // outside the pitch circle), over the whole leaving chain: the joints that started wrapped and
  // those wound on during the run; the slack side hanging from the wheel's far side keeps it small
  double tail_astray = 0.0;
  bool converged = true;
  // the synchronous averages (400 bins of a period) of the guided strand's speed and of the
  // free span's shortening rate dD/dt, D = Σ (L_i − |Δx_i|) over the 4 links from the last
  // joint before the guide's end, both band-passed to the tooth harmonics in 40–150 Hz
  double ripple_rms = 0.0, shortening_rms = 0.0, ripple_correlation = 0.0;
};

// x (one value a bin of a period, `period` s long) band-passed to the harmonics in [lo, hi] Hz
// by a direct Fourier sum over the bins
std::vector<double> band_pass(const std::vector<double>& x, double period, double lo, double hi) {
  const int n = static_cast<int>(x.size());
  std::vector<double> y(x.size(), 0.0);
  for (int k = 1; k < n / 2; ++k) {
    if (k / period < lo || k / period > hi) continue;
    double a = 0.0, b = 0.0;
    for (int j = 0; j < n; ++j) {
      const double arg = 2 * kPi * k * j / n;
      a += x[static_cast<std::size_t>(j)] * std::cos(arg);
      b += x[static_cast<std::size_t>(j)] * std::sin(arg);
    }
    for (int j = 0; j < n; ++j) {
      const double arg = 2 * kPi * k * j / n;
      y[static_cast<std::size_t>(j)] += 2.0 / n * (a * std::cos(arg) + b * std::sin(arg));
    }
  }
  return y;
}

Forced forced_run_on(const PocketRun& d, pocketwheel::GuideKind kind, double end_distance) {
  constexpr int kBins = 40;
  const pocketwheel::PocketWheel pw{.pitch = d.pitch, .wire = d.wire, .teeth = d.teeth};
  const pocketwheel::RunOnPlan plan =
      pocketwheel::plan_run_on(pw, {.kind = kind, .end_distance = end_distance});
  const pocketwheel::RunOnPlan pivot = pocketwheel::plan_run_on(
      pw,
      {.kind = kind, .end_distance = end_distance, .span_model = pocketwheel::SpanModel::kPivot});
  Sprocket w = pocket_wheel(d.pitch, d.wire, d.teeth, 0.0, 0.0, d.clearance, d.contact_stiffness,
                            d.contact_damping);
  w.driver = true;
  w.speed = -d.omega;
  const double r = w.pitch_radius, d1 = w.pocket_angle;
  const double tau = 2 * kPi / d.teeth, d2 = tau - d1;
  const double h = plan.guide_height, l = end_distance;
  const double th0 = plan.phases.front().crank_angle0;
  const bool long_first = plan.first_link > d.pitch;  // t + d seats first
  // link c − 1 (upstream of the crank c) is t + d for c − 1 even
  const int c = d.strand_links + ((d.strand_links % 2 == 1) == long_first ? 0 : 1);
  const auto n = static_cast<std::size_t>(c + 1 + d.wrapped);
  Model model = uniform_chain(n, false, d.pitch, d.node_mass, d.stiffness, d.damping, false);
  model.alternation = d.wire;
  model.links_carry_compression = !d.tension_only;
  model.sprockets = {w};
  model.loads = {{.node = 0, .fx = -d.force, .fy = 0.0}};
  if (d.tail_force > 0.0) model.loads.push_back({.node = n - 1, .fx = 0.0, .fy = -d.tail_force});
  // two rails holding the joints on y = H up to the guide's end: the lower carries them on top,
  // the upper (run from its end back) holds them from above; the joints ride a rail's roller
  // radius from its surface
  const double rr = 0.5 * d.wire, far = -l - 2.0 * d.strand_links * d.pitch;
  Guide lower{.x0 = far, .y0 = h - rr, .x1 = -l, .y1 = h - rr};
  Guide upper{.x0 = -l, .y0 = h + rr, .x1 = far, .y1 = h + rr};
  for (Guide* g : {&lower, &upper}) {
    g->roller_radius = rr;
    g->contact_stiffness = d.contact_stiffness;
    g->contact_damping = d.contact_damping;
  }
  if (d.rails) model.guides = {lower, upper};
  State s(n, 1);
  const double polar_c = kPi / 2 + th0;
  // vertex 2m at ψ + mτ, 2m + 1 at ψ + mτ + δ1: the crank is odd when its upstream link is t − d
  s.angle = {long_first ? polar_c : polar_c - d1};
  s.speed = {-d.omega};
  const double cx = -r * std::sin(th0), cy = r * std::cos(th0);
  const double v0 = d.omega * pocketwheel::evaluate(plan, 0.0).dx;
  double x = cx;
  for (int i = c; i >= 0; --i) {
    s.x[i] = x;
    s.y[i] = cy;  // = H
    s.vx[i] = i == c ? d.omega * r * std::cos(th0) : v0;
    s.vy[i] = i == c ? d.omega * r * std::sin(th0) : 0.0;
    if (i > 0) x -= model.rest_length(static_cast<std::size_t>(i - 1)) + d.force / d.stiffness;
  }
  double polar = polar_c;
  for (int k = 1; k <= d.wrapped; ++k) {
    const auto i = static_cast<std::size_t>(c + k);
    // link c + k − 1 downstream: t + d (δ1) when its index is even
    polar -= (c + k - 1) % 2 == 0 ? d1 : d2;
    s.x[i] = r * std::cos(polar);
    s.y[i] = r * std::sin(polar);
    s.vx[i] = d.omega * r * std::sin(polar);
    s.vy[i] = -d.omega * r * std::cos(polar);
  }
  EXPECT_NEAR(cy, h, 1e-12);
  // the strand's nodes that stay in the guide over the run (2 links leave it a period)
  std::vector<int> guided;
  for (int i = 2; i < c; ++i)
    if (s.x[i] < -l - (2.0 * d.periods + 2.0) * d.pitch) guided.push_back(i);
  EXPECT_GT(guided.size(), 10u);
  Integrator integ(model, {.step = d.step, .theta = d.theta});
  std::vector<double> sum(kBins, 0.0);
  std::vector<int> count(kBins, 0);
  const double period = tau / d.omega;
  const int steps = static_cast<int>(std::lround(d.periods * period / d.step));
  Forced out;
  std::vector<double> speeds, shortening, phases;
  std::vector<int> first_free;
  for (int k = 0; k < steps; ++k) {
    const StepReport rep = integ.step(model, s);
    if (!rep.converged) {
      out.converged = false;
      break;
    }
    out.max_penetration = std::max(out.max_penetration, rep.max_penetration);
    // every joint downstream of the crank: those that started wrapped and the 2 a period wound on
    // since (the crank moves 2 joints upstream a period; a joint that seats late is the crank on
    // the pitch circle, never one of the free span's)
    const int wound = c + 1 - 2 * static_cast<int>(s.time / period);
    for (auto i = static_cast<std::size_t>(std::max(wound, 1)); i < n; ++i)
      if (std::hypot(s.x[i], s.y[i]) > r + 1e-3)
        out.tail_astray = std::max(out.tail_astray, std::abs(s.x[i] - r));
    if (s.time < d.skip_periods * period) continue;
    double v = 0.0;
    for (int i : guided) {
      v += s.vx[i];
      out.rail_gap = std::max(out.rail_gap, std::abs(s.y[i] - h));
    }
    const double phase = std::fmod(d.omega * s.time, tau) / tau;
    // the free span's shortening from the last joint before the guide's end
    int f = 1;
    while (f < static_cast<int>(n) - 4 && s.x[f] <= -l) ++f;
    double shorter = 0.0;
    for (int i = f - 1; i < f + 3; ++i)
      shorter +=
          std::hypot(s.x[i + 1] - s.x[i], s.y[i + 1] - s.y[i]) - std::abs(s.x[i + 1] - s.x[i]);
    speeds.push_back(v / static_cast<double>(guided.size()));
    shortening.push_back(shorter);
    phases.push_back(phase);
    first_free.push_back(f);
    const int b = std::min(kBins - 1, static_cast<int>(phase * kBins));
    sum[b] += v / static_cast<double>(guided.size());
    ++count[b];
  }
  // the synchronous averages of the speed and of dD/dt (central differences, leaving out the
  // steps where the span's first joint changes), band-passed to 40–150 Hz
  constexpr int kFine = 400;
  std::vector<double> v_sync(kFine, 0.0), d_sync(kFine, 0.0), v_n(kFine, 0.0), d_n(kFine, 0.0);
  for (std::size_t k = 1; k + 1 < speeds.size(); ++k) {
    const int b = std::min(kFine - 1, static_cast<int>(phases[k] * kFine));
    v_sync[b] += speeds[k];
    v_n[b] += 1;
    if (first_free[k - 1] != first_free[k + 1]) continue;
    d_sync[b] += (shortening[k + 1] - shortening[k - 1]) / (2 * d.step);
    d_n[b] += 1;
  }
  for (int b = 0; b < kFine; ++b) {
    v_sync[b] = v_n[b] > 0 ? v_sync[b] / v_n[b] : 0.0;
    d_sync[b] = d_n[b] > 0 ? d_sync[b] / d_n[b] : 0.0;
  }
  const std::vector<double> vb = band_pass(v_sync, period, 40.0, 150.0);
  const std::vector<double> db = band_pass(d_sync, period, 40.0, 150.0);
  double vv = 0.0, dd = 0.0, vd = 0.0;
  for (int b = 0; b < kFine; ++b) {
    vv += vb[b] * vb[b];
    dd += db[b] * db[b];
    vd += vb[b] * db[b];
  }
  out.ripple_rms = std::sqrt(vv / kFine);
  out.shortening_rms = std::sqrt(dd / kFine);
  out.ripple_correlation = vd / std::sqrt(vv * dd);
  const double vr = d.omega * r;
  for (int b = 0; b < kBins; ++b) {
    const double phi = (b + 0.5) / kBins * tau;
    const double sim = count[b] ? sum[b] / count[b] : NAN;
    const double dev = (sim - d.omega * pocketwheel::evaluate(plan, phi).dx) / vr;
    out.rms += dev * dev / kBins;
    out.worst = std::max(out.worst, std::abs(dev));
    out.worst_pivot = std::max(out.worst_pivot,
                               std::abs(sim - d.omega * pocketwheel::evaluate(pivot, phi).dx) / vr);
  }
  out.rms = std::sqrt(out.rms);
  std::printf(
      "%s%s l %.3f k %.2g F %.0f, %d periods: worst %.4f (pivot %.4f), rms %.5f, rail gap %.1f um, "
      "pen %.1f um, tail astray %.1f mm, 40-150 Hz ripple %.2f mm/s, dD/dt %.2f mm/s, "
      "correlation %.3f\n",
      pocketwheel::to_string(kind), d.rails ? "" : " (no rails)", l, d.stiffness, d.force,
      d.periods, out.worst, out.worst_pivot, out.rms, out.rail_gap * 1e6, out.max_penetration * 1e6,
      out.tail_astray * 1e3, out.ripple_rms * 1e3, out.shortening_rms * 1e3,
      out.ripple_correlation);
  return out;
}

// The strand in the guide against catena pocketwheel's forced run-on (the paper's slider span;
// the pivot span differs from it by < 0.12 % of ωR in speed), the paper's l = 256 mm, on the stiff
// strand of the free run-on's passing case (k = 1.6e9 N/m), a 10-period run (8 averaged: the first
// 2 tooth periods skipped); without `rails` the same strand unguided. `periods` longer
// with a strand of `links` long enough that its guided joints stay in the guide.
Forced forced(pocketwheel::GuideKind kind, double force, bool rails = true, int periods = 10,
              int links = 70) {
  PocketRun d;
  d.stiffness = 1.6e9;
  d.force = force;
  d.periods = periods;
  d.skip_periods = 2;
  d.rails = rails;
  d.strand_links = links;  // 2 links leave the guide a period (10 periods: 20 of 70)
  const Forced f = forced_run_on(d, kind, 0.256);
  EXPECT_TRUE(f.converged);
  // every joint held in its pocket (clearance 0.1 mm; F/k_c = 50 µm at 5 kN)
  EXPECT_LT(f.max_penetration, d.clearance);
  // the rails hold the guided joints on the guide line
  if (rails) {
    EXPECT_LT(f.rail_gap, 1e-5);
  }
  // the chain leaves the wheel on its far side and hangs there, every joint wound on past the crank
  // (measured |x − R| 11.5-19.5 mm over this test's runs at 4 picometre lifts; with the end free
  // the wound-on chain flies off, 120-755 mm in this test's runs, and after about 10 periods whips
  // back into the wheel: a joint 17-24 mm from its pocket)
  EXPECT_LT(f.tail_astray, 0.04);
  return f;
}

// Within 1 % of ωR (the tolerance, as for the free run-on): the tangential guide at 1, 2
// and 5 kN and the chordal guide at 5 kN (an 18-period run, 16 averaged), each the largest
// deviation over the 40 bins.
//
// The runs are chaotic (docs/models/dynamics.md, "Pocket wheel: forced run-on", "The bounds
// against the runs' scatter"): a change of the start or of Newton's tolerance at the picometre
// level gives another trajectory, and the synchronous average keeps part of that. The bounds here
// are set from the scatter measured over picometre lifts of the start (a probe kept out of the
// suite), mean ± σ [range] with the seat damper's rotation term in the Newton matrix and the
// chain's downstream end pulled down (PocketRun::tail_force): largest deviation, tangential 1 kN
// 0.519 ± 0.022 % [0.489, 0.553] (10 lifts), 2 kN 0.469 ± 0.006 % [0.462, 0.485] (10), 5 kN 0.58
// ± 0.09 % [0.36, 0.71] (30) (10-period runs, 8 averaged); chordal 5 kN in 10-period runs (8
// averaged) 0.80 ± 0.05 % [0.67, 0.92] (30), 3.9 σ inside the 1 %, in 18-period runs (16 averaged)
// 0.73 ± 0.035 % [0.67, 0.80] (30), 7.7 σ inside it: so the chordal 5 kN run is an 18-period run
// (the pivot span, < 0.12 % of ωR from the slider's, to the same 1 %). (With the end free, 1 in
// 20-30 18-period runs had a joint of the wound-on chain, flung off the wheel and whirling round
// with it, strike back into the wheel 17-24 mm from a pocket; with it pulled down, none in 60
// 18-period runs.)
//
// The 1 % alone does not tell a guided strand from a free one (the speed profiles of free and
// forced run-on differ by less than 1 % of ωR). The largest bin does not either: its σ at 5 kN is
// up to 0.09 % of ωR, across any bound between guided and unguided. The rms over the bins does,
// at each force, with a bound of its own: guided 0.217 ± 0.003 % [0.211, 0.221] (1 kN), 0.130 ±
// 0.0005 % [0.130, 0.132] (2 kN), 0.145 ± 0.007 % [0.130, 0.160] (5 kN, 30 lifts); the same runs
// without the rails 0.283 ± 0.004 % [0.277, 0.290] (1 kN), 0.214 ± 0.003 % [0.208, 0.219] (5 kN)
// (10 lifts each; 2 kN before the end was pulled down: ≥ 0.317 %). Each bound sits well above the
// guided runs and below every unguided run: 1 kN 0.26 % (the unguided mean 5.8 σ above it), 2 kN
// 0.16 %, 5 kN 0.19 % (the guided mean + 6 σ; the unguided ≥ 0.208 %). The unguided runs at 1
// and 5 kN are in the test, so each of those bounds is checked to tell the two strands apart (2 kN
// has the widest gap and is not run unguided).
//
// Pinned as measured: the chordal guide at low tension misses the 1 % (1.83-1.94 % at 1 kN over
// 10 lifts; with the bilateral links 0.98 % at 2 kN, at the edge and not asserted). The simulated
// speed follows the kinematics' profile with a ripple (3.8° of φ by the bins, 89 Hz by its
// spectrum) that starts at the seating on φ = 0 (the first bin, 0.955 against 0.971 ωR) and comes
// back every period, so the synchronous average keeps it (an 18-period run, 16 averaged: 1.64 % at
// 1 kN); it falls as the tension rises — as the free run-on's slack strand. The tangential guide,
// whose seatings fall inside the period (15.9° and 37.6°), passes at 1 kN. The ripple is the free
// span's transverse swing at twice its frequency (asserted below). The first bin's and the
// 18-period run's figures were measured with the bilateral links.
TEST(DynamicsPocketWheel, ForcedRunOnStrandSpeedAgainstPocketwheel) {
  using pocketwheel::GuideKind;
  // the rms bounds (above), one a force: the guided runs below, the unguided above
  struct RmsBound {
    double force;
    double rms;
    bool unguided_run;
  };
  constexpr RmsBound kRms[] = {
      {1000.0, 0.0026, true}, {2000.0, 0.0016, false}, {5000.0, 0.0019, true}};
  for (const RmsBound& b : kRms) {
    const Forced f = forced(GuideKind::kTangential, b.force);
    EXPECT_LT(f.worst, 0.01) << "tangential F " << b.force;
    EXPECT_LT(f.worst_pivot, 0.01) << "tangential F " << b.force;
    EXPECT_LT(f.rms, b.rms) << "tangential F " << b.force;
    if (b.unguided_run) {
      // the strand without the rails: the bound tells it from the guided
      const Forced free = forced(GuideKind::kTangential, b.force, false);
      EXPECT_GT(free.rms, b.rms) << "unguided F " << b.force;
    }
  }
  // the chordal guide at 5 kN, an 18-period run (16 averaged; a strand 20 links longer), within
  // the 1 % (above: the 1 % is 7.7 σ above its mean)
  const Forced high = forced(GuideKind::kChordal, 5000.0, true, 18, 90);
  EXPECT_LT(high.worst, 0.01);
  EXPECT_LT(high.worst_pivot, 0.01);
  const Forced low = forced(GuideKind::kChordal, 1000.0);
  EXPECT_GT(low.worst, 0.01);
  EXPECT_LT(low.worst, 0.025);
  EXPECT_GT(low.worst, 1.5 * high.worst);  // the deviation falls with the tension
  // the ripple identified (docs/models/dynamics.md, "Pocket wheel: forced run-on"): the free
  // span's transverse swing (≈ 45 Hz at 1 kN) shortens it at twice its frequency, and the stiff
  // strand follows, v = v_crank + dD/dt. Measured by a probe: the band-passed synchronous
  // ripple 6.9 mm/s rms, dD/dt 5.6 mm/s, correlated at 0.92.
  EXPECT_GT(low.ripple_correlation, 0.8);
  EXPECT_GT(low.shortening_rms, 0.6 * low.ripple_rms);
  EXPECT_LT(low.shortening_rms, 1.2 * low.ripple_rms);
  const double omega_r =
      5.0 * pocket_wheel(0.064, 0.018, 8, 0.0, 0.0, 1e-4, 1e8, 2000.0).pitch_radius;
  EXPECT_GT(low.ripple_rms, 0.005 * omega_r);  // measured 0.88 % of ωR (6.95 mm/s)
}

}  // namespace
}  // namespace catena::dynamics
