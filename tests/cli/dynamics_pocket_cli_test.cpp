// `catena dynamics` with a round-link chain on pocket wheels (wheel = "pocket"; docs/models/
// dynamics.md, "Pocket wheel" and "Command"; docs/cli.md): the example runs, its wheel is seed
// 003's (R and δ1 of eqs. (6)-(7), computed here from the formulas, not from Catena), the driven
// wheel's torque balance closes over whole tooth periods, the roller-chain example's output is
// unchanged, and every field that does not fit a pocket wheel is named at once with its range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "../read_text.hpp"
#include "case_text.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;
const std::string kExample = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_pocketwheel.toml";

// The example with the line starting `from` replaced by `to` (or `to` added to [dynamics] when
// `from` is empty); every replacement must hit.
std::string example_with(const std::string& name,
                         const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string s = read_text(kExample);
  for (const auto& [from, to] : edits) {
    if (from.empty()) {
      s = with_dynamics_key(s, to);
      continue;
    }
    const std::size_t at = s.find("\n" + from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) continue;
    const std::size_t end = s.find("\n", at + 1);
    s.replace(at + 1, end - at - 1, to);
  }
  const fs::path dir = fs::temp_directory_path() / "catena_dynamics_pocket_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << s;
  return path.string();
}

// The example undamped (links and seats) at θ = ½ with the discrete gradient and the work balance,
// over `duration`, the mouth's ramp `mouth` wide (none if empty), and `more` edits.
std::string undamped_keyed(const std::string& name, const std::string& duration,
                           const std::string& mouth,
                           std::vector<std::pair<std::string, std::string>> more = {}) {
  more.insert(more.begin(), {{"axial_damping", "axial_damping = 0"},
                             {"contact_damping", "contact_damping = 0"},
                             {"duration", "duration = \"" + duration + "\""},
                             {"", "theta = 0.5\nwork_balance = true\ndiscrete_gradient = true"}});
  if (!mouth.empty()) more.push_back({"", "pocket_mouth = \"" + mouth + "\""});
  return example_with(name, more);
}

CliRun bad(const std::string& name, const std::vector<std::pair<std::string, std::string>>& edits) {
  const CliRun r = run("dynamics " + example_with(name, edits) + " --format json");
  EXPECT_EQ(r.status, 2) << r.err;
  return r;
}

void named(const CliRun& r, const std::vector<std::string>& texts) {
  for (const std::string& t : texts)
    EXPECT_NE(r.err.find(t), std::string::npos) << t << "\n" << r.err;
}

// Seed 003 eqs. (6)-(7), from the paper: the example chain Ø18×64 on z = 8.
double pitch_radius(double t, double d, int z) {
  return 0.5 * std::hypot(t / std::sin(kPi / (2 * z)), d / std::cos(kPi / (2 * z)));
}

TEST(DynamicsPocketCli, ExampleRunsOnSeed003sWheelAndBalancesTheDrivenWheel) {
  const CliRun r = run("dynamics " + kExample + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double t = 0.064, d = 0.018, R = pitch_radius(t, d, 8);
  EXPECT_EQ(j["wheel"], "pocket");
  EXPECT_NEAR(j["pitch_radius"].get<double>(), R, 1e-12);
  EXPECT_NEAR(j["pocket_angle"].get<double>(), 2 * std::asin((t + d) / (2 * R)), 1e-12);
  EXPECT_DOUBLE_EQ(j["wire_diameter"].get<double>(), d);
  EXPECT_DOUBLE_EQ(j["pocket_clearance"].get<double>(), 1e-4);
  EXPECT_EQ(j["units"]["pocket_angle"], "rad");
  EXPECT_EQ(j["links"], 32);
  EXPECT_NEAR(j["centre_distance"].get<double>(), 8 * t, 1e-15);  // 8 links a span, 2m t
  // the one diagnostic: its 3-period means are samples of a response that does not repeat with
  // the tooth period (tests/cli/dynamics_pocket_means_cli_test.cpp)
  ASSERT_EQ(j["diagnostics"].size(), 1u) << j["diagnostics"].dump();
  EXPECT_EQ(j["diagnostics"][0]["code"], "dynamics.means_not_settled");
  // against the largest span mean, the tight span's; 3 periods taken as independent, as it says
  const std::string message = j["diagnostics"][0]["message"];
  for (const char* text :
       {"dynamics.duration = 1 s", "of the largest span mean tension (span 0's",
        "taken as independent: 3 periods are too few to estimate their correlation, at least 10"})
    EXPECT_NE(message.find(text), std::string::npos) << text << "\n" << message;
  const auto& s = j["summary"];
  for (const char* span : {"span_0", "span_1"}) {
    EXPECT_TRUE(s[span]["period_correlation"].is_null()) << span;
    EXPECT_EQ(s[span]["effective_periods"], 3) << span;
    EXPECT_DOUBLE_EQ(s[span]["mean_tension_error"].get<double>(),
                     s[span]["period_tension_sd"].get<double>() / std::sqrt(3.0))
        << span;
  }
  EXPECT_EQ(s["steps"], 10000);
  EXPECT_GE(s["window_periods"].get<int>(), 3);
  // every joint stays in its pocket: within the clearance plus F/k_c (3.5 kN peak / 1e8 N/m)
  EXPECT_LT(s["max_penetration"].get<double>(), 1e-4);
  // the driven wheel over whole tooth periods: its speed is the driver's and the chain's mean
  // torque carries the load (100 N m; measured 100.26; over 20 runs with the pretension changed by
  // 0-9 µN, 99.69-100.31)
  EXPECT_NEAR(s["sprocket_1"]["mean_speed"].get<double>(), 5.0, 5e-3);
  EXPECT_NEAR(s["sprocket_1"]["mean_torque"].get<double>(), 100.0, 1.0);
  // tight - slack against T_L/R times the polygon's mean(sec θ): the crank swings over
  // [-δ2/2, δ1/2] and [-δ1/2, δ2/2], mean(sec θ) = (z/π)(F(δ1/2) + F(δ2/2)), F(x) =
  // ln(sec x + tan x) = 1.0081 here. Measured +2.56 % (the soft loop's spans ring: their tensions
  // swing from 65 N to 4.9 kN over the window). The 1 s run's rise is a sample of a chaotic
  // response (docs/models/dynamics.md, "Pocket wheel: the example's means"): over 20 runs with the
  // pretension changed by 0-9 µN (far below Newton's tolerance; 10 with the seat damper's rotation
  // term in the Newton matrix, 10 without) +1.16 ± 0.69 % (σ), from −0.41 % to +2.56 %; over 24
  // such 4 s runs +1.38 ± 0.32 %: the closed form (quasi-static, no dampers) sits about 1.4 %
  // below. Held to 4 %: the mean + 4 σ of the 1 s runs. (At this scatter neither run length tells
  // mean(sec θ) − 1 = 0.81 % apart; the reported mean_tension_error, 9-281 N a span, is of each
  // span's mean, whose swings the two spans share, and bounds their difference only loosely.)
  const double d1 = 2 * std::asin((t + d) / (2 * R)), d2 = kPi / 4 - d1;
  auto F = [](double x) { return std::log(1 / std::cos(x) + std::tan(x)); };
  const double mean_sec = 8 / kPi * (F(d1 / 2) + F(d2 / 2));
  const double rise =
      s["span_0"]["mean_tension"].get<double>() - s["span_1"]["mean_tension"].get<double>();
  EXPECT_NEAR(rise / (100.0 / R * mean_sec), 1.0, 0.04) << rise;
  // the first sample (t = 0, the initial state's contact torque) is the pocket's, not an ISO
  // seat's: of the order of the load (an ISO seat's law put ~1e5 N on each joint at a vertex)
  for (int w = 0; w < 2; ++w)
    EXPECT_LT(std::abs(j["sprocket"][w]["torque"][0].get<double>()), 10 * 100.0) << w;
  // the CSV has the two-wheel columns
  const CliRun csv = run("dynamics " + kExample + " --duration 0.01s --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')),
            "time,angle_0,speed_0,torque_0,angle_1,speed_1,torque_1,tension_upper,tension_lower");
}

// Round links carry no compression (docs/models/dynamics.md, "Tension-only links"; the exact
// invariant, that the upright links never push, is FlatLinksJointsDoNotPassEachOther's): a span's
// sampled link (the one nearest its middle) is of either kind, and a flat link is rigid ("The flat
// links": bilateral), so a sampled tension may be a flat link's push. How far it may push: a flat
// link whose upright neighbours have gone slack is a dumbbell of two joints, μ = m/2 = 0.211 kg
// (6.6 kg/m × 64 mm / 2), on k = 1e8 N/m and c = 2000 N·s/m: ζ = c/(2√(kμ)) = 0.22, and released
// from a tension T_r it overshoots into compression by exp(−πζ/√(1 − ζ²)) = 0.50 T_r. Over 41
// draws of the example (the pretension changed by 1-40 µN) the deepest push was −16.1 N at these
// 1 ms samples and −47.7 N at every step, so releases of up to 96 N; held to −100 N, the overshoot
// of a 200 N release (twice the largest seen: a bound from the ensemble and the ringing, not a
// proof). With the bilateral links everywhere the series went down to −954 N and −889 N, and the
// h = 0.05 ms run's lower span's summary minimum to −159.5 N.
TEST(DynamicsPocketCli, SpanTensionsPushOnlyAsAFlatLinksRinging) {
  for (const char* step : {"", " --step 0.05ms"}) {
    const CliRun r = run("dynamics " + kExample + step + " --format json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    double lowest = INFINITY;
    for (const auto& span : j["span"])
      for (const auto& t : span["tension"]) lowest = std::min(lowest, t.get<double>());
    EXPECT_GE(lowest, -100.0) << step;
    for (const char* span : {"span_0", "span_1"})
      EXPECT_GE(j["summary"][span]["min_tension"].get<double>(), -100.0) << step << " " << span;
    std::printf("pocket example%s: lowest sampled span tension %.3g N\n", step, lowest);
  }
}

// The flat (t + d) links are rigid (docs/models/dynamics.md, "The flat links": bilateral in the
// command): over the whole 1 s example sampled at every step (positions = true, 0.1 ms) no flat
// link's joints come closer than its rest length p + d (p the pitch less pretension/k) less
// 30 µm, a push of k × 30 µm = 3 kN. Measured: 7.02 µm at the closest (702 N); with the flat
// links tension-only (the command before) their joints passed freely, by up to 57.7 µm. The
// upright (t − d) links stay tension-only and close by more (107.8 µm), 28 mm short of their jam
// at d, so they never push: at every sample whose span link (span_middle_links: of the links
// above (below) the axis, the one whose middle is nearest x = centre_distance/2) is an upright
// one, the span's tension is ≥ 0 exactly (tension_only_link_force: T = max(0, k s + c ṡ) above
// the jam's ramp); the flat links' samples may push (SpanTensionsPushOnlyAsAFlatLinksRinging).
TEST(DynamicsPocketCli, FlatLinksJointsDoNotPassEachOther) {
  const CliRun r =
      run("dynamics " +
          example_with("positions.toml", {{"output_interval", "output_interval = \"0.1 ms\""},
                                          {"", "positions = true"}}) +
          " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& xs = j["positions"]["x"];
  const auto& ys = j["positions"]["y"];
  ASSERT_EQ(xs.size(), 10001u);
  ASSERT_EQ(j["span"].size(), 2u);
  for (const auto& span : j["span"]) ASSERT_EQ(span["tension"].size(), xs.size());
  const double rest = 0.064 - 1000.0 / 1e8, d = 0.018;
  double flat = INFINITY, upright = INFINITY;  // the least l − rest length of each kind
  const double half = 0.5 * j["centre_distance"].get<double>();
  double upright_sampled = INFINITY, flat_sampled = INFINITY;  // the least span tension by kind
  std::size_t upright_samples = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const std::size_t n = xs[k].size();
    ASSERT_EQ(n, 32u);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t b = (i + 1) % n;
      const double l = std::hypot(xs[k][b].get<double>() - xs[k][i].get<double>(),
                                  ys[k][b].get<double>() - ys[k][i].get<double>());
      if (i % 2 == 0) {
        flat = std::min(flat, l - (rest + d));
      } else {
        upright = std::min(upright, l - (rest - d));
      }
    }
    for (std::size_t w = 0; w < 2; ++w) {  // span 0 above the axis, span 1 below
      std::size_t link = n;
      double gap = INFINITY;
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t b = (i + 1) % n;
        const double xm = 0.5 * (xs[k][i].get<double>() + xs[k][b].get<double>());
        const double ym = 0.5 * (ys[k][i].get<double>() + ys[k][b].get<double>());
        if (ym == 0.0 || (ym > 0.0) != (w == 0)) continue;
        if (std::abs(xm - half) < gap) gap = std::abs(xm - half), link = i;
      }
      ASSERT_LT(link, n) << k;
      const double tension = j["span"][w]["tension"][k].get<double>();
      if (link % 2 == 1) {
        upright_sampled = std::min(upright_sampled, tension);
        ++upright_samples;
      } else {
        flat_sampled = std::min(flat_sampled, tension);
      }
    }
  }
  std::printf("pocket example: flat links at most %.2f um short, upright links %.2f um\n",
              -flat * 1e6, -upright * 1e6);
  EXPECT_GT(flat, -30e-6);
  EXPECT_LT(upright, -30e-6);  // the upright links are not rigid: their joints close freely
  // ... but never push; the sampled links are of both kinds
  std::printf("pocket example: %zu upright span samples, lowest %.3g N; flat lowest %.3g N\n",
              upright_samples, upright_sampled, flat_sampled);
  EXPECT_GT(upright_samples, 1000u);
  EXPECT_LT(upright_samples, 2 * xs.size() - 1000u);
  EXPECT_GE(upright_sampled, 0.0);
}

TEST(DynamicsPocketCli, ShortRunHasNoMeanErrorAndSaysSo) {
  // 0.5 s: the window (the second half) holds 1 whole tooth period, 0.157 s: no scatter of the
  // periods' means to estimate the means' error from; the warning names the duration and 4 T
  const CliRun r = run("dynamics " + kExample + " --duration 0.5s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["summary"]["window_periods"], 1);
  for (const char* span : {"span_0", "span_1"}) {
    // the fields are kept (a sweep's columns), null: no value to give
    ASSERT_TRUE(j["summary"][span].contains("mean_tension_error")) << span;
    EXPECT_TRUE(j["summary"][span]["mean_tension_error"].is_null()) << span;
    ASSERT_TRUE(j["summary"][span].contains("period_tension_sd")) << span;
    EXPECT_TRUE(j["summary"][span]["period_tension_sd"].is_null()) << span;
    for (const char* key : {"period_correlation", "effective_periods"}) {
      ASSERT_TRUE(j["summary"][span].contains(key)) << span << key;
      EXPECT_TRUE(j["summary"][span][key].is_null()) << span << key;
    }
  }
  ASSERT_EQ(j["diagnostics"].size(), 1u) << j["diagnostics"].dump();
  EXPECT_EQ(j["diagnostics"][0]["code"], "dynamics.means_not_settled");
  const std::string message = j["diagnostics"][0]["message"];
  for (const char* text :
       {"holds 1 whole tooth period", "dynamics.duration = 0.5 s", "more than 0.628 s"})
    EXPECT_NE(message.find(text), std::string::npos) << text << "\n" << message;
}

// A coarse output_interval: the window (0.4 s) holds 2 whole tooth periods (0.157 s) but 0.15 s
// samples give the first period one sample, whose "mean" would be an instantaneous value. No
// estimate (null fields), and the warning names output_interval and half a tooth period.
TEST(DynamicsPocketCli, SparseSamplesGiveNoMeanErrorAndNameTheOutputInterval) {
  const std::string path =
      example_with("sparse.toml", {{"duration =", "duration = \"0.8 s\""},
                                   {"output_interval =", "output_interval = \"0.15 s\""}});
  const CliRun r = run("dynamics " + path + " --format json");
  std::filesystem::remove(path);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["summary"]["window_periods"], 2);
  for (const char* span : {"span_0", "span_1"}) {
    ASSERT_TRUE(j["summary"][span].contains("mean_tension_error")) << span;
    EXPECT_TRUE(j["summary"][span]["mean_tension_error"].is_null()) << span;
    EXPECT_TRUE(j["summary"][span]["period_tension_sd"].is_null()) << span;
  }
  ASSERT_EQ(j["diagnostics"].size(), 1u) << j["diagnostics"].dump();
  EXPECT_EQ(j["diagnostics"][0]["code"], "dynamics.means_not_settled");
  const std::string message = j["diagnostics"][0]["message"];
  for (const char* text : {"not estimated", "dynamics.output_interval = 0.15 s", "at most 0.0785"})
    EXPECT_NE(message.find(text), std::string::npos) << text << "\n" << message;
}

// A slack span whose mean is near zero against the loop's: no pretension and 800 N m on the
// driven wheel (measured with the flat links rigid 5035.3 ± 12.9 N tight, 102.5 ± 18.4 N slack
// over the 3 periods: the slack span 2.0 % of the tight span's mean). Against the largest span
// mean the means are settled (0.37 %), no warning; against the slack span's own mean (18 %) the
// run would have been told to last far longer, for 18 N of a 5 kN loop (with every round link
// tension-only: 5089.7 ± 24.3 and 162.2 ± 16.6 N, about 98 s; with the bilateral links
// everywhere: 4997.6 ± 4.6 and 65.3 ± 12.7 N, 355 s).
TEST(DynamicsPocketCli, SlackSpanNearZeroDoesNotAskForAnAbsurdDuration) {
  const std::string path = example_with("slack.toml", {{"pretension =", "pretension = \"0 N\""},
                                                       {"load_torque =", "load_torque = 800"}});
  const CliRun r = run("dynamics " + path + " --format json");
  std::filesystem::remove(path);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& tight = j["summary"]["span_0"];
  const auto& slack = j["summary"]["span_1"];
  const double scale = tight["mean_tension"].get<double>();
  // the case is what it says: a slack span near zero whose own relative error exceeds 1 %
  EXPECT_LT(std::abs(slack["mean_tension"].get<double>()), 0.05 * scale);
  EXPECT_GT(slack["mean_tension_error"].get<double>(),
            0.01 * std::abs(slack["mean_tension"].get<double>()));
  for (const auto* span : {&tight, &slack})
    EXPECT_LT((*span)["mean_tension_error"].get<double>(), 0.01 * scale);
  // no means' warning; the one diagnostic is the deep joint's: 0.312 mm into a pocket's wall
  // (0.391 mm, 4.9c from its vertex, with every round link tension-only; not the load's: 4.9 kN /
  // k_c is 49 µm), so within the pocket's capture of 10c (docs/models/dynamics.md, "Pocket wheel:
  // the body between the pockets"). The warning says the forces "are not to be trusted" while the
  // means above are pinned to 1 %: the deep event is a transient in the slack span (a joint with
  // next to no tension landing off its vertex as it seats), a contact force at one joint for the
  // steps it takes to seat; the means are the spans' tensions averaged over the 3 whole periods,
  // which that short event's impulse barely moves, and the tight span's 5 kN is carried by joints
  // seated at their vertices
  ASSERT_EQ(j["diagnostics"].size(), 1u) << j["diagnostics"].dump();
  EXPECT_EQ(j["diagnostics"][0]["code"], "dynamics.pocket_penetration_deep");
  EXPECT_GT(j["summary"]["max_penetration"].get<double>(), 1e-4);
}

TEST(DynamicsPocketCli, RollerChainOutputHasNoPocketFields) {
  const CliRun r = run("dynamics " + std::string(CATENA_EXAMPLES_DIR) +
                       "/dynamics_12B.toml --duration 0.01s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"wheel", "wire_diameter", "pocket_clearance", "pitch_radius", "pocket_angle"}) {
    EXPECT_FALSE(j.contains(key)) << key;
    EXPECT_FALSE(j["units"].contains(key)) << key;
  }
  // nor the pocket's summary fields
  for (const char* key :
       {"mean_tension_error", "period_tension_sd", "period_correlation", "effective_periods"}) {
    EXPECT_FALSE(j["summary"]["span_0"].contains(key)) << key;
    EXPECT_FALSE(j["units"].contains(key)) << key;
  }
}

// Friction in the pockets (docs/models/dynamics.md, "Pocket wheel: friction"): `seat_friction`
// on a pocket wheel runs (exit 0), reports seat_friction and its work, which is < 0 and in the
// work balance, and the drift is net of it: at θ = ½ and h = 0.05 ms (μ = 0.3, 0.1 s) the
// balance's numerical rest, the drift less the dampers' work, is 0.0053 J against the friction's
// −0.202 J (measured); the bound, a tenth of the friction's work, fails by 10× when the friction's
// work is left in the drift (the rest would be −0.197 J). (That the balance closes with the
// pockets' friction is tests/validation/dynamics_work_balance_test.cpp's: at the example's
// θ = 0.6 the rest is −0.16 J in 0.1 s, the θ-method's, larger than the friction's work.)
TEST(DynamicsPocketCli, SeatFrictionActsInThePocketsAndIsInTheBalance) {
  const CliRun r = run("dynamics " +
                       example_with("mu.toml", {{"", "work_balance = true\nseat_friction = 0.1"}}) +
                       " --duration 0.1s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["seat_friction"], 0.1);
  const double seat = j["summary"]["seat_friction_work"];
  const auto& b = j["summary"]["work_balance"];
  EXPECT_EQ(b["seat_friction"], seat);
  const double links = b["link_dampers"], contact = b["contact_dampers"],
               numerical = b["numerical"], drift = j["summary"]["energy_drift"];
  std::printf(
      "pockets' friction work %.6g J, link dampers %.6g, contact dampers %.6g, "
      "numerical %.3g, drift %.6g\n",
      seat, links, contact, numerical, drift);
  EXPECT_LT(seat, 0.0);
  // the drift net of the friction's work: the θ = ½ run's numerical rest is far below it
  const std::string half_keys = "work_balance = true\nseat_friction = 0.3\ntheta = 0.5";
  const CliRun half =
      run("dynamics " +
          example_with("mu_half.toml", {{"", half_keys}, {"step = ", "step = \"0.05 ms\""}}) +
          " --duration 0.1s --format json");
  ASSERT_EQ(half.status, 0) << half.err;
  const auto h = nlohmann::json::parse(half.out);
  const double half_seat = h["summary"]["seat_friction_work"];
  const double half_rest = h["summary"]["work_balance"]["numerical"];
  std::printf("theta 1/2, h 0.05 ms, mu 0.3: friction %.4g J, numerical rest %.3g J\n", half_seat,
              half_rest);
  EXPECT_LT(half_seat, -0.1);
  EXPECT_LT(std::abs(half_rest), 0.1 * std::abs(half_seat));
}

// A joint deeper than the pocket's clearance is warned (dynamics.pocket_penetration_deep, naming
// the depth and the clearance); the run still reports (exit 0). A contact stiffness 25 times
// softer than the example's puts the loaded joints 0.14 mm into their pockets' walls over 0.1 s
// (measured: 0.1408 mm); the example itself (54 µm over 1 s) has no such warning
// (ExampleRunsOnSeed003sWheelAndBalancesTheDrivenWheel: its one diagnostic is the means').
TEST(DynamicsPocketCli, JointDeeperThanTheClearanceIsWarned) {
  const CliRun r =
      run("dynamics " +
          example_with("soft.toml", {{"contact_stiffness = ", "contact_stiffness = \"4e6 N/m\""}}) +
          " --duration 0.1s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double depth = j["summary"]["max_penetration"];
  std::printf("contact stiffness 4e6 N/m: deepest joint %.4g mm\n", depth * 1e3);
  EXPECT_GT(depth, 1e-4);
  bool warned = false;
  for (const auto& d : j["diagnostics"]) {
    if (d["code"] != "dynamics.pocket_penetration_deep") continue;
    warned = true;
    EXPECT_EQ(d["severity"], "warning");
    EXPECT_DOUBLE_EQ(d["value"].get<double>(), depth);
    EXPECT_DOUBLE_EQ(d["limit"].get<double>(), 1e-4);
    const std::string message = d["message"];
    for (const char* text : {"more than the pocket clearance 0.1 mm", "contact_stiffness"})
      EXPECT_NE(message.find(text), std::string::npos) << text << "\n" << message;
  }
  EXPECT_TRUE(warned) << j["diagnostics"].dump();
  // the same run at the example's stiffness: no warning
  const CliRun ok = run("dynamics " + kExample + " --duration 0.1s --format json");
  ASSERT_EQ(ok.status, 0) << ok.err;
  const auto quiet = nlohmann::json::parse(ok.out);  // (named: the loop reads into it)
  for (const auto& d : quiet["diagnostics"])
    EXPECT_NE(d["code"], "dynamics.pocket_penetration_deep") << d.dump();
}

TEST(DynamicsPocketCli, FieldsThatDoNotFitAPocketWheelAreNamedAtOnce) {
  // the roller chain's keys and what is not built on a pocket, all in one run
  const CliRun parts = bad("parts.toml", {{"", "chain = \"12B\""},
                                          {"", "roller_diameter = \"12 mm\""},
                                          {"", "inner_width = \"11 mm\""},
                                          {"", "seat_friction = 0.2"},
                                          {"", "hinge = \"sliding\""}});
  named(parts, {"dynamics.chain", "dynamics.roller_diameter", "dynamics.inner_width",
                "dynamics.hinge", "frictionless with wheel = \"pocket\""});
  EXPECT_EQ(parts.err.find("dynamics.seat_friction"), std::string::npos) << parts.err;
  // the pockets' friction keeps its range, [0, 1], on [dynamics] and on a wheel
  const CliRun mu =
      bad("mu.toml", {{"", "seat_friction = 1.5"},
                      {"role = \"driven\"", "role = \"driven\"\nseat_friction = -0.1"}});
  named(mu, {"dynamics.seat_friction", "in [0, 1]", "dynamics.sprocket[1].seat_friction"});
  // guides and centres (the free layout) are not built for pocket wheels
  const CliRun layout =
      bad("layout.toml", {{"role = \"driver\"", "role = \"driver\"\ncentre_x = 0\ncentre_y = 0"}});
  named(layout, {"dynamics.sprocket[0].centre_x", "dynamics.sprocket[0].centre_y",
                 "no centres with wheel = \"pocket\""});
  const std::string guide =
      "\n[[dynamics.guide]]\nkind = \"straight\"\nx0 = 0.5\ny0 = 0.1\nx1 = 0.1\ny1 = 0.1\n";
  const CliRun guided = bad("guide.toml", {{"[analyses.dynamics]", guide + "[analyses.dynamics]"}});
  named(guided, {"dynamics.guide", "no [[dynamics.guide]] with wheel = \"pocket\""});
  // the chain and wheel: wire, clearance, contact stiffness, teeth and links with their ranges
  const CliRun values = bad("values.toml", {{"wire_diameter", "wire_diameter = \"70 mm\""},
                                            {"pocket_clearance", "pocket_clearance = \"9 mm\""},
                                            {"contact_stiffness", "# no contact stiffness"},
                                            {"links", "links = 30"}});
  named(values, {"dynamics.wire_diameter", "= (0, 0.0319945] m", "dynamics.pocket_clearance",
                 "in (0, 0.1 pitch] = (0, 0.0064] m", "dynamics.contact_stiffness",
                 "(no Hertz default)", "dynamics.links", "2z + 4m with m >= 1"});
  const CliRun teeth = bad("teeth.toml", {{"teeth = 8", "teeth = 7"}});
  named(teeth, {"dynamics.sprocket[0].teeth", "an even integer in [4, 150]"});
  // z = 4 with a thick wire: δ1 above 60 deg, the pocket cannot hold the crank (25 mm: a wire
  // the link can hold, 2d ≤ t, with δ1 = 63.4 deg; 20 mm gives 59.8 deg)
  const CliRun wide = bad("wide.toml", {{"teeth = 8", "teeth = 4"},
                                        {"teeth = 8", "teeth = 4"},
                                        {"wire_diameter", "wire_diameter = \"25 mm\""},
                                        {"links", "links = 12"}});
  named(wide, {"dynamics.sprocket[0].teeth", "pocket angle delta1 < 60 deg"});
  // a wire of half the pitch: the link's inner length cannot hold its two neighbours' wires (its
  // jam, at d, would be at its rest length t − d; docs/models/dynamics.md "Tension-only links:
  // the jam")
  const CliRun thick = bad("thick.toml", {{"wire_diameter", "wire_diameter = \"32 mm\""}});
  named(thick, {"dynamics.wire_diameter", "= (0, 0.0319945] m", "holds its two neighbours' wires"});
  const CliRun missing = bad("missing.toml", {{"wire_diameter", "# no wire"}});
  named(missing, {"dynamics.wire_diameter", "(missing)"});
  const CliRun kind = bad("kind.toml", {{"wheel", "wheel = \"sprocket\""}});
  named(kind, {"dynamics.wheel", "iso606 or pocket"});
  // and the pocket's keys on a roller chain
  const std::string roller = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_12B.toml";
  const std::string text = read_text(roller);
  const std::string s =
      with_dynamics_key(text, "wire_diameter = \"5 mm\"\npocket_clearance = \"0.1 mm\"");
  const fs::path p = fs::temp_directory_path() / "catena_dynamics_pocket_cli_test" / "roller.toml";
  std::ofstream(p) << s;
  const CliRun r = run("dynamics " + p.string() + " --format json");
  EXPECT_EQ(r.status, 2);
  named(r, {"dynamics.wire_diameter", "dynamics.pocket_clearance", "only with wheel = \"pocket\""});
}

// A pocket wheel's wire against the upright link's jam (docs/models/dynamics.md, "Tension-only
// links: the jam"): d is the jam, at most ε = 1 µm below the link's rest length
// t − pretension/k − d, so 2d ≤ t − pretension/k − ε. With the example's 1000 N (pretension/k =
// 10 µm) the bound is 31.9945 mm: 31.994 mm runs, 31.995 mm is refused on dynamics.wire_diameter
// with the bound, and with dynamics.pretension, which is what refuses it (without it the bound is
// 31.9995 mm); 50 kN (0.5 mm) refuses 31.8 mm the same way; 32 mm is refused without the
// pretension named. The model's internal link_jam_length is never named.
TEST(DynamicsPocketCli, WireIsCheckedAgainstTheJamWithThePretension) {
  const std::string inside =
      example_with("inside.toml", {{"wire_diameter", "wire_diameter = \"31.994 mm\""}});
  const CliRun ok = run("dynamics " + inside + " --duration 0.01s --format json");
  EXPECT_EQ(ok.status, 0) << ok.err;
  auto unnamed = [](const CliRun& r) {
    EXPECT_EQ(r.err.find("link_jam_length"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("link-jam-length"), std::string::npos) << r.err;
  };
  const CliRun out = bad("outside.toml", {{"wire_diameter", "wire_diameter = \"31.995 mm\""}});
  named(out, {"dynamics.wire_diameter", "0.031995",
              "(0, (pitch - pretension/axial_stiffness - 1e-06 m)/2] = (0, 0.0319945] m",
              "dynamics.pretension",
              "1000 N shortens the links by pretension/axial_stiffness = 1e-05 m: without it the "
              "bound is 0.0319995 m"});
  unnamed(out);
  const CliRun pulled = bad("pulled.toml", {{"wire_diameter", "wire_diameter = \"31.8 mm\""},
                                            {"pretension =", "pretension = \"50000 N\""}});
  named(pulled,
        {"dynamics.wire_diameter", "= (0, 0.0317495] m", "dynamics.pretension", "0.0005 m"});
  unnamed(pulled);
  const CliRun thick = bad("thick32.toml", {{"wire_diameter", "wire_diameter = \"32 mm\""}});
  named(thick, {"dynamics.wire_diameter", "= (0, 0.0319945] m"});
  EXPECT_EQ(thick.err.find("dynamics.pretension"), std::string::npos) << thick.err;
  unnamed(thick);
}

// The pockets' mouth ramp and release as keys (docs/models/dynamics.md, "Pocket wheel in the
// command"): `pocket_mouth` (a length in [0, pocket_clearance]) and `pocket_release` (true or
// false) reach both wheels, are echoed (the ramp with its unit) and change the run against the
// same run without them; their defaults given explicitly leave the output as it was, every field
// but the wall time equal and neither echoed.
TEST(DynamicsPocketCli, MouthRampAndReleaseKeysReachTheWheelsAndAreEchoed) {
  auto json_run = [](const std::string& name, const std::string& keys) {
    const std::string path = keys.empty() ? kExample : example_with(name, {{"", keys}});
    const CliRun r = run("dynamics " + path + " --duration 50ms --format json");
    EXPECT_EQ(r.status, 0) << name << "\n" << r.err;
    auto j = r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
    if (j.contains("summary")) {
      j["summary"].erase("wall_time");
      j["summary"].erase("real_time_factor");
    }
    return j;
  };
  const auto plain = json_run("", "");
  ASSERT_TRUE(plain.contains("span"));
  for (const char* key : {"pocket_mouth", "pocket_release"}) {
    EXPECT_FALSE(plain.contains(key)) << key;
    EXPECT_FALSE(plain["units"].contains(key)) << key;
  }
  const auto ramp = json_run("ramp.toml", "pocket_mouth = \"0.05 mm\"");
  ASSERT_TRUE(ramp.contains("pocket_mouth")) << ramp.dump().substr(0, 2000);
  EXPECT_DOUBLE_EQ(ramp["pocket_mouth"].get<double>(), 5e-5);
  EXPECT_EQ(ramp["units"]["pocket_mouth"], "m");
  EXPECT_FALSE(ramp.contains("pocket_release"));
  EXPECT_TRUE(ramp["span"] != plain["span"]) << "the ramp left the spans' tensions as they were";
  const auto release = json_run("release.toml", "pocket_release = true");
  EXPECT_EQ(release["pocket_release"], true);
  EXPECT_FALSE(release.contains("pocket_mouth"));
  EXPECT_TRUE(release["span"] != plain["span"])
      << "the release left the spans' tensions as they were";
  EXPECT_TRUE(release["span"] != ramp["span"]) << "the release ran as the ramp";
  // a bare length is in mm, as every length of the table
  const auto bare = json_run("bare.toml", "pocket_mouth = 0.05");
  EXPECT_TRUE(bare["span"] == ramp["span"]) << "a bare 0.05 is not 0.05 mm";
  // the defaults written out: the sharp mouth, the output as without them
  const auto defaults =
      json_run("defaults.toml", "pocket_mouth = \"0 mm\"\npocket_release = false");
  EXPECT_TRUE(defaults == plain) << nlohmann::json::diff(plain, defaults).dump().substr(0, 2000);
}

// Out of range, together and each named with its range: the ramp beyond the clearance (the range
// following a clearance given), a negative ramp, a release that is not true or false, with the
// table's other problems at once; the ramp with the release is refused naming both keys.
TEST(DynamicsPocketCli, MouthRampAndReleaseOutOfRangeAreNamed) {
  const CliRun wide = bad("mouth_wide.toml", {{"", "pocket_mouth = \"0.2 mm\""},
                                              {"", "pocket_release = \"yes\""},
                                              {"wire_diameter", "wire_diameter = \"70 mm\""}});
  named(wide, {"dynamics.pocket_mouth (line ",
               ") = 0.0002: expected in [0, pocket_clearance] = "
               "[0, 0.0001] m",
               "dynamics.pocket_release (line ", ") = 'yes': expected true or false",
               "dynamics.wire_diameter"});
  const CliRun tight = bad("mouth_tight.toml", {{"", "pocket_mouth = \"0.06 mm\""},
                                                {"pocket_clearance", "pocket_clearance = 0.05"}});
  named(tight, {"dynamics.pocket_mouth", "in [0, pocket_clearance] = [0, 5e-05] m"});
  const CliRun negative = bad("mouth_negative.toml", {{"", "pocket_mouth = \"-0.01 mm\""}});
  named(negative, {"dynamics.pocket_mouth", "= -1e-05: expected in [0, pocket_clearance]"});
  const CliRun both =
      bad("mouth_release.toml", {{"", "pocket_mouth = \"0.05 mm\"\npocket_release = true"}});
  named(both, {"dynamics.pocket_mouth (line ", "expected 0 while dynamics.pocket_release (line ",
               ") is true: the ramp is the sharp mouth's option",
               "a ramp in [0, pocket_clearance] = [0, 0.0001] m needs pocket_release = false"});
  // an unreadable clearance: the ramp's range named without a number
  const CliRun unread =
      bad("mouth_release_unread.toml", {{"pocket_clearance", "pocket_clearance = \"abc\""},
                                        {"", "pocket_mouth = \"0.05 mm\"\npocket_release = true"}});
  named(unread, {"dynamics.pocket_clearance", "dynamics.pocket_mouth (line ",
                 "a ramp in [0, pocket_clearance] needs pocket_release = false"});
  EXPECT_EQ(unread.err.find("nan"), std::string::npos) << unread.err;
}

// On ISO 606 sprockets the two keys are refused by name, each with its value, as the pocket's
// other keys are.
TEST(DynamicsPocketCli, MouthRampAndReleaseAreRefusedOnARollerChain) {
  const std::string text = read_text(std::string(CATENA_EXAMPLES_DIR) + "/dynamics_12B.toml");
  const fs::path p =
      fs::temp_directory_path() / "catena_dynamics_pocket_cli_test" / "roller_mouth.toml";
  fs::create_directories(p.parent_path());
  std::ofstream(p) << with_dynamics_key(text, "pocket_mouth = \"0.05 mm\"\npocket_release = true");
  const CliRun r = run("dynamics " + p.string() + " --format json");
  EXPECT_EQ(r.status, 2);
  named(r, {") = 5e-05: expected only with wheel = \"pocket\"",
            ") = true: expected only with wheel = \"pocket\""});
  for (const char* key : {"dynamics.pocket_mouth (line ", "dynamics.pocket_release (line "}) {
    const std::size_t at = r.err.find(key);
    ASSERT_NE(at, std::string::npos) << key << "\n" << r.err;
    const std::size_t end = r.err.find('\n', at);
    EXPECT_NE(r.err.substr(at, end - at).find("only with wheel = \"pocket\""), std::string::npos)
        << r.err.substr(at, end - at);
  }
}

// Without a [dynamics] table the message lists what the table needs: contact_stiffness with
// wheel = "pocket" only (the ISO 606 seats default to the Hertz stiffness at the expected load),
// contact_damping always.
TEST(DynamicsPocketCli, MissingTableSaysContactStiffnessIsThePocketsOnly) {
  const fs::path p =
      fs::temp_directory_path() / "catena_dynamics_pocket_cli_test" / "no_table.toml";
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "[chain]\ntype = \"round-link\"\npitch = \"64 mm\"\nwire = \"18 mm\"\n";
  const CliRun r = run("dynamics " + p.string());
  EXPECT_EQ(r.status, 2);
  named(r, {"dynamics = (missing): expected a [dynamics] table (chain, links unless a free "
            "layout chooses it, axial_stiffness "
            "unless chain is 08A … 32A and no pitch is given, contact_damping, duration, step; "
            "with wheel = \"pocket\" pitch, wire_diameter and mass_per_metre instead of chain, "
            "and contact_stiffness, which the ISO 606 seats default to the Hertz stiffness at "
            "the expected load)"});
}

}  // namespace

// A step that folds is retaken as half-steps (docs/models/dynamics.md, "Integrator: a failed step
// retaken as half-steps"; "Pocket wheel: the ramp's fold"): the example undamped at θ = ½ with the
// discrete gradient and the mouth's ramp w = c = 0.1 mm, 0.25 s, whose step 2457 has no root near
// its start at h = 0.1 ms (a joint leaving over the ramp, whose softening passes the joint's
// 2M/(θh²)) and stopped there, runs every step, warned once with the smallest sub-step and the
// first retaken step. The retaken steps' accounting closes: the work balance's numerical term
// stays at the discrete gradient's (against 0.25 J of input the retaken step alone takes), and the
// driven wheel's torque balance J Δω = Δt (τ̄ − T_L) holds over every sample, the retaken ones'
// mean torque weighted by the sub-steps' share of h.
TEST(DynamicsPocketCli, RampsFoldedStepIsRetakenAsHalvesAndItsAccountingCloses) {
  const std::string file = undamped_keyed("ramp_half.toml", "0.25 s", "0.1 mm");
  const CliRun r = run("dynamics " + file + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["summary"]["steps"], 2500) << r.err;
  int retaken = 0;
  for (const auto& d : j["diagnostics"]) {
    EXPECT_NE(d["code"], "dynamics.not_converged") << d.dump();
    // a correct run with a retake is not stopped by the guard on energy from nothing (its
    // largest numerical term, +0.83 J in the mouth's band at step 2458, about 0.03 of what it has
    // received)
    EXPECT_NE(d["code"], "dynamics.energy_gain") << d.dump();
    if (d["code"] != "dynamics.steps_retaken") continue;
    ++retaken;
    EXPECT_EQ(d["severity"], "warning");
    EXPECT_DOUBLE_EQ(d["limit"].get<double>(), 1e-4);  // the step
    const double smallest = d["value"].get<double>();
    EXPECT_LE(smallest, 5e-5) << d.dump();
    EXPECT_GE(smallest, 1e-4 / 16) << d.dump();
    const std::string m = d["message"].get<std::string>();
    for (const char* text : {" of step = 0.1 ms did not converge and were retaken from their "
                             "start as two half-steps",
                             "down to step/16)", "the first at step "})
      EXPECT_NE(m.find(text), std::string::npos) << text << "\n" << m;
  }
  EXPECT_EQ(retaken, 1) << j["diagnostics"].dump();
  const auto& balance = j["summary"]["work_balance"];
  EXPECT_GT(balance["input"].get<double>(), 10.0) << balance.dump();
  EXPECT_LT(std::abs(balance["numerical"].get<double>()), 1e-5) << balance.dump();
  const auto& time = j["time"];
  const auto& driven = j["sprocket"][1];
  ASSERT_EQ(driven["role"], "driven");
  double worst = 0.0;
  for (std::size_t k = 1; k < time.size(); ++k) {
    const double dt = time[k].get<double>() - time[k - 1].get<double>();
    const double lhs =
        0.2 * (driven["speed"][k].get<double>() - driven["speed"][k - 1].get<double>());
    worst = std::max(worst, std::abs(lhs - dt * (driven["torque"][k].get<double>() - 100.0)));
  }
  EXPECT_LT(worst, 1e-6);  // N m s (1e-8 measured; the steps' own Newton tolerance)
}

// The guard on energy from nothing (docs/models/dynamics.md, "Integrator: the guard on energy
// from nothing"): the ramp's run (θ = ½, undamped, discrete gradient, w = c) to 1 s went on with
// retakes to 1 s, +2537 J in its numerical term, its joints 2.42 mm deep (measured going back to
// h after each retake, without the guard). Asserted are the guard's properties, not where on the
// run's path it fires (the path past the ramp's folds moves with rounding-level changes: 3230,
// 3240 and 3600 steps measured on three builds): the run is stopped by `dynamics.energy_gain`
// before 0.5 s, its value the summary's numerical term, above its limit (twice what the run has
// received, over 100 J: the driver's work dominates), on stderr too. The joints' depth at the
// stop is below 2.42 mm, the least depth the run ends at by 1 s unguarded (3.28 mm on the path
// with the size kept, measured with the guard's bound raised): the guard stops it short of that
// end but bounds it no closer, its bound growing with the driver's work (1.47 to 1.79 mm
// measured; "Not built yet").
TEST(DynamicsPocketCli, RampsDivergingRunStopsWhereItGainsEnergyFromNothing) {
  const CliRun r =
      run("dynamics " + undamped_keyed("ramp_1s.toml", "1 s", "0.1 mm") + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double stopped = j["summary"]["steps"].get<int>() * j["summary"]["step"].get<double>();
  EXPECT_LT(stopped, 0.5);
  EXPECT_LT(j["summary"]["max_penetration"].get<double>(), 2.42e-3);
  int gains = 0;
  for (const auto& d : j["diagnostics"]) {
    EXPECT_NE(d["code"], "dynamics.not_converged") << d.dump();
    if (d["code"] != "dynamics.energy_gain") continue;
    ++gains;
    EXPECT_EQ(d["severity"], "error");
    EXPECT_EQ(d["value"].get<double>(), j["summary"]["work_balance"]["numerical"].get<double>());
    EXPECT_GT(d["value"].get<double>(), d["limit"].get<double>());
    EXPECT_GT(d["limit"].get<double>(), 100.0) << d.dump();  // the work put in dominates
  }
  EXPECT_EQ(gains, 1) << j["diagnostics"].dump();
  EXPECT_NE(r.err.find("catena: error: step "), std::string::npos) << r.err;
}

// A grid step that fails at the kept size h/16 itself, the retakes' floor, is not retaken
// (docs/models/dynamics.md, "Integrator: the sub-step size kept"): the narrow ramp (w = 0.01 mm)
// undamped at θ = ½ with the discrete gradient at 0.2 ms goes on at sixteenths after a retake
// that needed them, and one of those grid steps fails (step 444, t = 0.0888 s, measured): the
// run ends there with `dynamics.not_converged`, its message naming the kept size and the floor in
// place of the retake's clause, its value the failed step's end.
TEST(DynamicsPocketCli, AStepFailingAtTheKeptFloorIsNotRetaken) {
  const std::string file =
      undamped_keyed("kept_floor.toml", "0.2 s", "0.01 mm", {{"step", "step = \"0.2 ms\""}});
  const CliRun r = run("dynamics " + file + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const int steps = j["summary"]["steps"].get<int>();
  EXPECT_LT(steps, 1000);  // stopped before the end
  int stopped = 0;
  for (const auto& d : j["diagnostics"]) {
    if (d["code"] != "dynamics.not_converged") continue;
    ++stopped;
    const std::string m = d["message"];
    EXPECT_EQ(m.rfind("step " + std::to_string(steps + 1) + " (t = ", 0), 0u) << m;
    for (const char* part : {" did not converge as sub-steps of step/16 in ",
                             ", the retakes' floor; the run stopped there (try a smaller step"})
      EXPECT_NE(m.find(part), std::string::npos) << part << "\n" << m;
    EXPECT_EQ(m.find("also retaken"), std::string::npos) << m;
    EXPECT_NEAR(d["value"].get<double>(), (steps + 1) * 2e-4, 1e-12);
  }
  EXPECT_EQ(stopped, 1) << j["diagnostics"].dump();
}

// A step that fails even as sixteenths ends the run as before the retakes (docs/models/
// dynamics.md, "Integrator: a failed step retaken as half-steps"): the example undamped at θ = ½
// with the discrete gradient and a narrow ramp w = 0.01 mm at 0.5 ms (within the speed bound),
// 0.08 s. Steps are retaken and the run goes on at the sub-steps they took ("Integrator: the
// sub-step size kept") until step 78 (t = 0.039 s), taken as quarters, which fails at every level
// below: the state is restored to the end of step 77, the error names the step with the message
// as before plus the size it was taken at and the retake, on stderr too, and the earlier retakes
// are warned. (Going back to h after each retake it ended at step 149, the coarse steps carrying
// joints over the ramp where the finer ones fold.) The run is no physics (joints 0.39 mm deep,
// warned); it is here for the path.
TEST(DynamicsPocketCli, AStepFailingAtTheRetakesFloorEndsTheRunAtItsStart) {
  const std::string file =
      undamped_keyed("ramp_floor.toml", "0.08 s", "0.01 mm", {{"step", "step = \"0.5 ms\""}});
  const CliRun r = run("dynamics " + file + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["summary"]["steps"], 77) << r.err;
  const std::string text =
      "step 78 (t = 0.039 s) did not converge as sub-steps of step/4 in 50 Newton iterations in "
      "all, from 2 starting points with at most 25 from each; also retaken from its start as "
      "half-steps down to step/16, which failed too; the run stopped there (try a smaller step or "
      "theta nearer 1)";
  int stopped = 0, retaken = 0;
  for (const auto& d : j["diagnostics"]) {
    if (d["code"] == "dynamics.steps_retaken") ++retaken;
    if (d["code"] != "dynamics.not_converged") continue;
    ++stopped;
    EXPECT_EQ(d["severity"], "error");
    EXPECT_EQ(d["message"], text);
    EXPECT_NEAR(d["value"].get<double>(), 0.039, 1e-12);
  }
  EXPECT_EQ(stopped, 1);
  EXPECT_EQ(retaken, 1);
  EXPECT_NE(r.err.find("catena: error: " + text), std::string::npos) << r.err;
}

// The ramp's fold-free step from the model's own data (docs/models/dynamics.md, "Pocket wheel:
// the ramp's fold"): a joint's step residual M/(hθ) (u − x₀ − h v₀) − h F(x₀ + θ(u − x₀)) has the
// Jacobian M/(hθ) + hθ K, singular where −K reaches M/(θh)², so h < √(M/κ)/θ with κ the ramp's
// largest −λ_min(∇²E). The windows are from central differences of E₀(g) W(g) s(h) written out
// independently of the code (κ = 7.317e8 N/m at w = c, 1.698e9 N/m at c/2; M = 0.4224 kg):
// 48.0 µs and 31.5 µs at θ = ½. Warned naming the key, the bound and the retakes when the step
// is above it; the bound goes as 1/θ; a step below it, and the sharp mouth, are not warned.
TEST(DynamicsPocketCli, RampsFoldFreeStepIsWarnedFromTheModelsData) {
  auto fold = [](const std::string& name, const std::string& keys, const std::string& flags) {
    const CliRun r = run("dynamics " + example_with(name, {{"", keys}}) + " --duration 1ms " +
                         flags + " --format json");
    EXPECT_EQ(r.status, 0) << name << "\n" << r.err;
    nlohmann::json found;
    if (r.status != 0) return found;
    const auto j = nlohmann::json::parse(r.out);
    for (const auto& d : j["diagnostics"])
      if (d["code"] == "dynamics.pocket_mouth_fold") found = d;
    return found;
  };
  const auto half = fold("fold_half.toml", "pocket_mouth = \"0.1 mm\"\ntheta = 0.5", "");
  ASSERT_FALSE(half.is_null());
  EXPECT_EQ(half["severity"], "warning");
  EXPECT_DOUBLE_EQ(half["value"].get<double>(), 1e-4);
  const double bound = half["limit"].get<double>();
  EXPECT_GT(bound, 4.75e-5);
  EXPECT_LT(bound, 4.85e-5);
  const std::string m = half["message"].get<std::string>();
  for (const char* text : {"pocket_mouth = 0.1 mm with step = 0.1 ms",
                           "m/(theta step)^2 = ", "retaken as half-steps (dynamics.steps_retaken)",
                           "below 0.048 ms a single joint's step cannot fold on the ramp"})
    EXPECT_NE(m.find(text), std::string::npos) << text << "\n" << m;
  const auto narrow = fold("fold_narrow.toml", "pocket_mouth = \"0.05 mm\"\ntheta = 0.5", "");
  ASSERT_FALSE(narrow.is_null());
  EXPECT_GT(narrow["limit"].get<double>(), 3.1e-5);
  EXPECT_LT(narrow["limit"].get<double>(), 3.2e-5);
  // θ = 0.6 (the θ-point force): the residual's θ² puts the bound at ½/0.6 of θ = ½'s
  const auto damped = fold("fold_damped.toml", "pocket_mouth = \"0.1 mm\"\ntheta = 0.6", "");
  ASSERT_FALSE(damped.is_null());
  EXPECT_NEAR(damped["limit"].get<double>(), bound * 0.5 / 0.6, 1e-12 * bound);
  EXPECT_TRUE(fold("fold_small.toml", "pocket_mouth = \"0.1 mm\"\ntheta = 0.5", "--step 0.045ms")
                  .is_null());
  EXPECT_TRUE(fold("fold_sharp.toml", "theta = 0.5", "").is_null());
}
