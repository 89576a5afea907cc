// `catena dynamics CASE.toml` as scripts call it: the JSON's fields, the drive's steady state
// against the closed forms of the core's validation (6) (tests/validation/dynamics_drive_test.cpp),
// CSV, the work cap, every input problem named with exit status 2, and the report's charts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "../dynamics/period_mean.hpp"
#include "../read_text.hpp"
#include "case_text.hpp"
#include "chart_list.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;
const std::string kExample = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_12B.toml";
constexpr double kTensionTol = 0.01;  // issue 21 (6): the mean tight-span tension within 1 %
// the driven wheel's mean speed over whole tooth periods against the driver's times z1/z2: the
// same 0.5 % the core's validation (6) holds the tension difference to (a mean over the period
// of the polygon's speed variation, which is 1 − cos(π/z) = 3.4 % peak to peak at z = 12)
constexpr double kSpeedTol = 0.005;

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "catena_dynamics_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// The example's text without its `contact_stiffness` line (the key then takes its default).
std::string example_without_contact_stiffness() {
  std::string out = read_text(kExample);
  const std::size_t at = out.find("contact_stiffness = ");
  if (at == std::string::npos) {
    ADD_FAILURE() << "the example has no contact_stiffness to leave out";
    return out;
  }
  out.erase(at, out.find('\n', at) + 1 - at);
  return out;
}

// The example's drive (z = 12 / 12, driver 13 rad/s, T_L = 10 N m, 12B) from the command's JSON:
// the mean tight-span tension over the last 8 tooth periods against the driven wheel's torque
// balance, (T_L / R) mean(sec φ) + slack, as a ratio (1 when they agree).
double tight_tension_ratio(const nlohmann::json& j) {
  const int z = 12;
  const double omega = 13.0, load = 10.0, pitch = 0.01905;
  const auto time = j["time"].get<std::vector<double>>();
  const double period = 2 * kPi / (z * omega);
  const double t0 = time.back() - 8 * period;
  const double tight =
      mean_over_periods(time, j["span"][0]["tension"].get<std::vector<double>>(), t0, period);
  const double slack =
      mean_over_periods(time, j["span"][1]["tension"].get<std::vector<double>>(), t0, period);
  const double radius = 0.5 * pitch / std::sin(kPi / z);
  const double phi = kPi / z;
  const double sec_mean = z / kPi * std::log(1.0 / std::cos(phi) + std::tan(phi));
  return tight / (load / radius * sec_mean + slack);
}

TEST(DynamicsCli, ExampleDriveGivesItsClosedForms) {
  const CliRun r = run("dynamics " + kExample + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"time", "sprocket", "span", "summary", "units", "diagnostics"})
    ASSERT_TRUE(j.contains(key)) << key;
  const auto time = j["time"].get<std::vector<double>>();
  ASSERT_EQ(time.size(), 5001u);  // t = 0 and every 0.1 ms step of 0.5 s
  ASSERT_EQ(j["sprocket"].size(), 2u);
  for (const auto& w : j["sprocket"])
    for (const char* key : {"angle", "speed", "torque"}) EXPECT_EQ(w[key].size(), time.size());
  ASSERT_EQ(j["span"].size(), 2u);
  for (const char* key :
       {"steps", "step", "wall_time", "real_time_factor", "energy_drift", "max_penetration"})
    EXPECT_TRUE(j["summary"].contains(key)) << key;
  EXPECT_EQ(j["summary"]["steps"], 5000);
  EXPECT_TRUE(j["diagnostics"].empty()) << j["diagnostics"].dump();
  EXPECT_EQ(j["units"]["tension"], "N");
  EXPECT_EQ(j["units"]["speed"], "rad/s");

  // the example's drive: z = 12 / 12, driver 13 rad/s, T_L = 10 N m, 12B
  const int z = 12;
  const double omega = 13.0, load = 10.0;
  EXPECT_EQ(j["sprocket"][0]["role"], "driver");
  EXPECT_EQ(j["span"][0]["side"], "tight");
  const double period = 2 * kPi / (z * omega);
  const double t0 = time.back() - 8 * period;
  const double driven =
      mean_over_periods(time, j["sprocket"][1]["speed"].get<std::vector<double>>(), t0, period);
  EXPECT_NEAR(driven / (omega * z / z), 1.0, kSpeedTol);
  EXPECT_NEAR(tight_tension_ratio(j), 1.0, kTensionTol);

  // `torque` is the torque each step applied (at its θ point), averaged over the steps since the
  // previous sample: for the driven wheel a true torque balance, mean τ = T_L + J Δω/Δt over the
  // window to the Newton tolerance, and so the load itself within the speed's change over whole
  // periods (0.5 %). Before this, the end-of-step contact torque's mean was 4.8 % below the load.
  const auto speed = j["sprocket"][1]["speed"].get<std::vector<double>>();
  const double inertia = 0.01;
  std::size_t first = 0, last = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (time[k] <= t0) first = k;
    if (time[k] <= t0 + std::floor((time.back() - t0) / period) * period) last = k;
  }
  const double balance = load + inertia * (speed[last] - speed[first]) / (time[last] - time[first]);
  const double torque =
      mean_over_periods(time, j["sprocket"][1]["torque"].get<std::vector<double>>(), t0, period);
  EXPECT_NEAR(torque / balance, 1.0, 1e-6) << "torque " << torque << " balance " << balance;
  EXPECT_NEAR(torque / load, 1.0, kSpeedTol) << "torque " << torque;
  // The driver's torque (clockwise on it: the chain resists) supplies the load and the power
  // the contacts' and links' dampers take; it exceeds the load, by a few per cent.
  const double driver =
      -mean_over_periods(time, j["sprocket"][0]["torque"].get<std::vector<double>>(), t0, period);
  EXPECT_GT(driver, load);
  EXPECT_LT(driver, 1.05 * load);
}

// summary.sprocket_<i> and summary.span_<j>: the means (and a span's least and greatest
// tension) over the stated window, recomputed here from the JSON's own series: on the example
// the whole tooth periods after half the run (mean_over_periods from t_end/2, the validations'
// mean), on a run shorter than two tooth periods the whole second half.
TEST(DynamicsCli, SummaryMeansAreTheSeriesOverTheWindow) {
  const double period = 2 * kPi / (12 * 13.0);  // the driver's tooth period, z = 12 at 13 rad/s
  for (const char* duration : {"0.5s", "6ms"}) {
    const CliRun r = run("dynamics " + kExample + " --duration " + duration + " --format json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto time = j["time"].get<std::vector<double>>();
    const auto& summary = j["summary"];
    const double t0 = 0.5 * time.back();
    const int periods = static_cast<int>(std::floor((time.back() - t0) / period));
    const double end = periods > 0 ? t0 + periods * period : time.back();
    EXPECT_EQ(summary["window_start"].get<double>(), t0) << duration;
    EXPECT_EQ(summary["window_end"].get<double>(), end) << duration;
    EXPECT_EQ(summary["window_periods"].get<int>(), periods) << duration;
    EXPECT_EQ(periods, std::string(duration) == "0.5s" ? 6 : 0);  // 0.25 s / 40.3 ms
    int samples = 0;
    for (double t : time) samples += t > t0 && t <= end;
    EXPECT_EQ(summary["window_samples"].get<int>(), samples);
    EXPECT_GT(samples, 10);
    // a plain mean over the window's samples, and the validations' whole-period mean
    auto window_mean = [&](const std::vector<double>& x) {
      double sum = 0.0;
      for (std::size_t k = 0; k < time.size(); ++k)
        if (time[k] > t0 && time[k] <= end) sum += x[k];
      return sum / samples;
    };
    auto near = [](double got, double want) {
      EXPECT_NEAR(got, want, 1e-12 * std::abs(want) + 1e-12);
    };
    for (std::size_t w = 0; w < 2; ++w) {
      const auto& s = summary["sprocket_" + std::to_string(w)];
      for (const char* key : {"speed", "torque"}) {
        const auto x = j["sprocket"][w][key].get<std::vector<double>>();
        near(s[std::string("mean_") + key].get<double>(), window_mean(x));
        if (periods > 0)
          near(s[std::string("mean_") + key].get<double>(), mean_over_periods(time, x, t0, period));
      }
    }
    EXPECT_EQ(summary["sprocket_0"]["mean_speed"].get<double>(), 13.0);  // prescribed
    for (std::size_t k = 0; k < 2; ++k) {
      const auto& s = summary["span_" + std::to_string(k)];
      const auto x = j["span"][k]["tension"].get<std::vector<double>>();
      near(s["mean_tension"].get<double>(), window_mean(x));
      double least = INFINITY, most = -INFINITY;
      for (std::size_t i = 0; i < time.size(); ++i) {
        if (!(time[i] > t0 && time[i] <= end)) continue;
        least = std::min(least, x[i]);
        most = std::max(most, x[i]);
      }
      EXPECT_EQ(s["min_tension"].get<double>(), least);
      EXPECT_EQ(s["max_tension"].get<double>(), most);
      EXPECT_LT(least, s["mean_tension"].get<double>());
      EXPECT_GT(most, s["mean_tension"].get<double>());
    }
    for (const char* key : {"mean_tension", "min_tension", "max_tension"})
      EXPECT_EQ(j["units"][key], "N");
    EXPECT_EQ(j["units"]["mean_torque"], "N m");
    EXPECT_EQ(j["units"]["mean_speed"], "rad/s");
    EXPECT_EQ(j["units"]["window_start"], "s");
  }
}

TEST(DynamicsCli, CsvTableAndOverrides) {
  const CliRun csv = run("dynamics " + kExample + " --duration 2ms --step 0.5ms --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  std::istringstream lines(csv.out);
  std::string head, line;
  std::getline(lines, head);
  EXPECT_EQ(head,
            "time,angle_0,speed_0,torque_0,angle_1,speed_1,torque_1,tension_upper,tension_lower");
  int rows = 0;
  while (std::getline(lines, line)) ++rows;
  // --step overrides the table's 0.1 ms; the table's output interval (0.1 ms) rounds up to
  // every step: rows at t = 0 and after each of the 4 steps
  EXPECT_EQ(rows, 5);
  const CliRun table = run("dynamics " + kExample + " --duration 1ms");
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("10 steps"), std::string::npos) << table.out;
}

TEST(DynamicsCli, WorkCapRefusesUnlessAllowed) {
  const CliRun big = run("dynamics " + kExample + " --duration 1000s");
  EXPECT_EQ(big.status, 2);
  EXPECT_NE(big.err.find("--duration"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("link-steps"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("--allow-large"), std::string::npos) << big.err;
}

TEST(DynamicsCli, EveryBadFieldNamedWithExitTwo) {
  const std::string path = write("bad.toml", R"([dynamics]
chain = "12B"
links = 13.5
axial_stiffness = -1
contact_stiffness = "2e8 N/m"
contact_damping = -800
duration = 0
step = "1 kg"
theta = 2
seat_friction = 1.5
[[dynamics.sprocket]]
teeth = 11
role = "driver"
speed = -3
[[dynamics.sprocket]]
teeth = 12
role = "idler"
)");
  const CliRun r = run("dynamics " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  for (const char* field :
       {"dynamics.links (line 3)", "dynamics.axial_stiffness (line 4)",
        "dynamics.contact_damping (line 6)", "dynamics.duration (line 7)", "dynamics.step (line 8)",
        "dynamics.theta (line 9)", "dynamics.seat_friction (line 10)", "dynamics.sprocket[0].teeth",
        "dynamics.sprocket[0].speed", "dynamics.sprocket[1].role"})
    EXPECT_NE(r.err.find(field), std::string::npos) << field << "\n" << r.err;
  EXPECT_NE(r.err.find("an even integer in [8, 150]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("in [0.5, 1]"), std::string::npos) << r.err;

  const std::string layout = write("unequal.toml", R"([dynamics]
chain = "12B"
links = 33
axial_stiffness = "5e7 N/m"
contact_stiffness = "2e8 N/m"
contact_damping = 800
duration = "0.01 s"
step = "0.1 ms"
[[dynamics.sprocket]]
teeth = 12
role = "driver"
speed = "13 rad/s"
[[dynamics.sprocket]]
teeth = 14
role = "driven"
inertia = 0.01
)");
  const CliRun u = run("dynamics " + layout);
  EXPECT_EQ(u.status, 2);
  EXPECT_NE(u.err.find("dynamics.sprocket[1].teeth"), std::string::npos) << u.err;
  const CliRun missing =
      run("dynamics " + write("none.toml", "[chain]\ntype = \"roller-iso606\"\n"));
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("dynamics"), std::string::npos) << missing.err;
}

// `work_balance = true` adds summary.work_balance: the run's input, friction, link and contact
// damper works and the numerical rest, which add up to E_end − E_0 (the energy drift plus the
// input and friction works); without it the output has no such field. A value other than true or
// false is named with its line.
TEST(DynamicsCli, WorkBalanceIsOptInAndAddsUp) {
  const std::string text = read_text(kExample);
  const std::string with = with_dynamics_key(text, "work_balance = true");
  const CliRun r =
      run("dynamics " + write("balance.toml", with) + " --duration 0.1s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["summary"].contains("work_balance")) << j["summary"].dump();
  EXPECT_EQ(j["units"]["work_balance"], "J");
  const auto& b = j["summary"]["work_balance"];
  const double input = b["input"], friction = b["friction"], links = b["link_dampers"],
               contact = b["contact_dampers"], numerical = b["numerical"];
  EXPECT_GT(input, 0.0);     // the driver puts in more than the load takes while the dampers work
  EXPECT_EQ(friction, 0.0);  // no guides
  EXPECT_LT(links, 0.0);
  EXPECT_LT(contact, 0.0);
  EXPECT_LT(numerical, 0.0);  // θ = 0.6 dissipates
  const double drift = j["summary"]["energy_drift"];
  EXPECT_NEAR(links + contact + numerical, drift, 1e-12 + 1e-9 * std::abs(drift));
  const CliRun plain = run("dynamics " + kExample + " --duration 0.1s --format json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const auto p = nlohmann::json::parse(plain.out);
  EXPECT_FALSE(p["summary"].contains("work_balance"));
  EXPECT_FALSE(p["units"].contains("work_balance"));
  EXPECT_EQ(p["summary"]["energy_drift"], j["summary"]["energy_drift"]);

  const std::string bad = with_dynamics_key(text, "work_balance = \"yes\"");
  const CliRun e = run("dynamics " + write("balance_bad.toml", bad));
  EXPECT_EQ(e.status, 2);
  EXPECT_NE(e.err.find("dynamics.work_balance"), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("true or false"), std::string::npos) << e.err;
}

// `seat_friction = mu` gives the seats Coulomb friction: the JSON gains seat_friction and
// summary.seat_friction_work (< 0; with work_balance also in the balance), and the energy drift
// is net of it, so the balance's terms still add up to it; without it none of these appear.
TEST(DynamicsCli, SeatFrictionIsOptInAndInTheBalance) {
  const std::string text = read_text(kExample);
  const std::string with = with_dynamics_key(text, "work_balance = true\nseat_friction = 0.1");
  const CliRun r = run("dynamics " + write("seat.toml", with) + " --duration 0.1s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["seat_friction"], 0.1);
  EXPECT_EQ(j["units"]["seat_friction_work"], "J");
  const double seat = j["summary"]["seat_friction_work"];
  EXPECT_LT(seat, 0.0);
  const auto& b = j["summary"]["work_balance"];
  EXPECT_EQ(b["seat_friction"], seat);
  const double links = b["link_dampers"], contact = b["contact_dampers"],
               numerical = b["numerical"], drift = j["summary"]["energy_drift"];
  EXPECT_NEAR(links + contact + numerical, drift, 1e-12 + 1e-9 * std::abs(drift));
  const CliRun plain = run("dynamics " + kExample + " --duration 0.1s --format json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const auto p = nlohmann::json::parse(plain.out);
  EXPECT_FALSE(p.contains("seat_friction"));
  EXPECT_FALSE(p["summary"].contains("seat_friction_work"));
  EXPECT_FALSE(p["units"].contains("seat_friction_work"));
}

// `seat_friction` on a [[dynamics.sprocket]] overrides the [dynamics] one for that wheel: each
// wheel's μ is then in its sprocket entry; the same μ given per wheel runs the same as given once;
// a different one on one wheel changes the run; a value outside [0, 1] is refused naming the
// wheel's field and line, every one at once.
TEST(DynamicsCli, SeatFrictionPerWheel) {
  const std::string base = read_text(kExample);
  auto with = [&](const std::string& dynamics, const std::string& driver,
                  const std::string& driven) {
    std::string t = base;
    const std::size_t at = t.find("load_torque = 10");
    EXPECT_NE(at, std::string::npos);
    t.insert(t.find('\n', at) + 1, driven);
    const std::size_t sp = t.find("speed = \"13 rad/s\"");
    EXPECT_NE(sp, std::string::npos);
    t.insert(t.find('\n', sp) + 1, driver);
    return with_dynamics_key(t, dynamics);
  };
  const std::string flags = " --duration 0.02s --format json";
  const CliRun once =
      run("dynamics " + write("mu_once.toml", with("seat_friction = 0.1\n", "", "")) + flags);
  const CliRun each = run(
      "dynamics " +
      write("mu_each.toml", with("", "seat_friction = 0.1\n", "seat_friction = 0.1\n")) + flags);
  const CliRun one =
      run("dynamics " +
          write("mu_one.toml", with("seat_friction = 0.1\n", "", "seat_friction = 0.3\n")) + flags);
  ASSERT_EQ(once.status, 0) << once.err;
  ASSERT_EQ(each.status, 0) << each.err;
  ASSERT_EQ(one.status, 0) << one.err;
  const auto a = nlohmann::json::parse(once.out), b = nlohmann::json::parse(each.out),
             c = nlohmann::json::parse(one.out);
  EXPECT_FALSE(a["sprocket"][0].contains("seat_friction"));  // none given per wheel
  EXPECT_EQ(b["sprocket"][0]["seat_friction"], 0.1);
  EXPECT_EQ(b["sprocket"][1]["seat_friction"], 0.1);
  EXPECT_EQ(b["seat_friction"], 0.0);  // the [dynamics] default, under the wheels' own
  EXPECT_EQ(a["span"][0]["tension"], b["span"][0]["tension"]);
  EXPECT_EQ(a["sprocket"][1]["speed"], b["sprocket"][1]["speed"]);
  EXPECT_EQ(a["summary"]["seat_friction_work"], b["summary"]["seat_friction_work"]);
  EXPECT_EQ(c["sprocket"][0]["seat_friction"], 0.1);
  EXPECT_EQ(c["sprocket"][1]["seat_friction"], 0.3);
  EXPECT_NE(a["span"][0]["tension"], c["span"][0]["tension"]);
  EXPECT_LT(c["summary"]["seat_friction_work"].get<double>(), 0.0);

  const std::string bad = with("", "seat_friction = -0.1\n", "seat_friction = 1.5\n");
  const CliRun e = run("dynamics " + write("mu_bad.toml", bad));
  EXPECT_EQ(e.status, 2);
  EXPECT_TRUE(e.out.empty());
  for (const char* field :
       {"dynamics.sprocket[0].seat_friction (line ", "dynamics.sprocket[1].seat_friction (line "})
    EXPECT_NE(e.err.find(field), std::string::npos) << field << "\n" << e.err;
  EXPECT_NE(e.err.find("in [0, 1]"), std::string::npos) << e.err;
}

// `positions = true` adds every node's x and y at each output sample: each link's length is the
// pitch within its stretch (the tension over k, < 0.2 %), and the report's animation frames (its
// own copy of the positions, drawn in mm to 1 µm) show the same nodes at the same times.
// Without it there is no such field; the size is capped, and a value other than true or false
// is named with its line.
TEST(DynamicsCli, PositionsAreOptInAndMatchTheAnimation) {
  const std::string text = read_text(kExample);
  const std::string with = with_dynamics_key(text, "positions = true");
  const std::string file = write("positions.toml", with);
  const CliRun r = run("dynamics " + file + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("positions"));
  EXPECT_EQ(j["units"]["x"], "m");
  EXPECT_EQ(j["units"]["y"], "m");
  const auto time = j["time"].get<std::vector<double>>();
  const auto x = j["positions"]["x"].get<std::vector<std::vector<double>>>();
  const auto y = j["positions"]["y"].get<std::vector<std::vector<double>>>();
  ASSERT_EQ(x.size(), time.size());
  ASSERT_EQ(y.size(), time.size());
  const double pitch = 0.01905;
  double worst = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    ASSERT_EQ(x[k].size(), 32u);
    ASSERT_EQ(y[k].size(), 32u);
    for (std::size_t i = 0; i < 32; ++i) {
      const std::size_t e = (i + 1) % 32;
      worst =
          std::max(worst, std::abs(std::hypot(x[k][e] - x[k][i], y[k][e] - y[k][i]) / pitch - 1));
    }
  }
  EXPECT_LT(worst, 2e-3);
  EXPECT_GT(worst, 0.0);  // the links stretch: these are the model's positions, not a drawing

  const fs::path html = fs::temp_directory_path() / "catena_dynamics_cli_test" / "positions.html";
  const CliRun report = run("report " + file + " -o " + html.string());
  ASSERT_EQ(report.status, 0) << report.err;
  const std::string page = read_text(html);
  const auto extra = chart_list(page, "catena-charts-extra");
  ASSERT_EQ(extra.size(), 2u);
  const auto& frames = extra[1]["frames"];
  ASSERT_GE(frames.size(), 50u);
  for (const auto& frame : frames) {
    // "t = 0.1234 s": the sample nearest that time (the frames fall on steps; a sample every step)
    const double t = std::stod(frame["name"].get<std::string>().substr(4));
    std::size_t k = 0;
    for (std::size_t m = 0; m < time.size(); ++m)
      if (std::abs(time[m] - t) < std::abs(time[k] - t)) k = m;
    const auto cx = frame["traces"][2]["x"].get<std::vector<double>>();
    const auto cy = frame["traces"][2]["y"].get<std::vector<double>>();
    ASSERT_EQ(cx.size(), 33u);
    for (std::size_t i = 0; i < 33; ++i) {
      EXPECT_NEAR(cx[i], x[k][i % 32] * 1e3, 1e-3) << frame["name"] << " node " << i;
      EXPECT_NEAR(cy[i], y[k][i % 32] * 1e3, 1e-3) << frame["name"] << " node " << i;
    }
  }

  const CliRun plain = run("dynamics " + kExample + " --duration 1ms --format json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const auto p = nlohmann::json::parse(plain.out);
  EXPECT_FALSE(p.contains("positions"));
  EXPECT_FALSE(p["units"].contains("x"));

  // 20 001 samples × 32 nodes = 640 032 node-samples, over the 500 000 cap
  const CliRun big = run("dynamics " + file + " --duration 20s --step 1ms");
  EXPECT_EQ(big.status, 2);
  EXPECT_NE(big.err.find("dynamics.positions (line 13)"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("at most 500000 node-samples"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("here 640032"), std::string::npos) << big.err;

  const std::string bad = with_dynamics_key(text, "positions = 1");
  const CliRun e = run("dynamics " + write("positions_bad.toml", bad));
  EXPECT_EQ(e.status, 2);
  EXPECT_NE(e.err.find("dynamics.positions"), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("true or false"), std::string::npos) << e.err;
}

// Samples too sparse for the summary's window (one at t = 0 and one at the end): the summary is
// the last sample alone, and says so — no whole periods, one sample.
TEST(DynamicsCli, SummaryOfTooSparseSamplesIsTheLastSample) {
  std::string sparse = read_text(kExample);
  const std::size_t at = sparse.find("output_interval = ");
  ASSERT_NE(at, std::string::npos);
  sparse.replace(at, sparse.find('\n', at) - at, "output_interval = \"0.2 s\"");
  const CliRun r =
      run("dynamics " + write("sparse.toml", sparse) + " --duration 0.2s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["time"].size(), 2u);
  const auto& s = j["summary"];
  EXPECT_EQ(s["window_periods"], 0);
  EXPECT_EQ(s["window_samples"], 1);
  EXPECT_EQ(s["window_start"], s["window_end"]);
  EXPECT_EQ(s["span_0"]["mean_tension"], j["span"][0]["tension"][1]);
}

// The example's text with its `key = ...` line replaced by `replacement` (empty: removed).
std::string example_with(const std::string& key, const std::string& replacement) {
  std::string out = read_text(kExample);
  const std::size_t at = out.find(key + " = ");
  if (at == std::string::npos) {
    ADD_FAILURE() << "the example has no " << key;
    return out;
  }
  const std::size_t end = out.find('\n', at) + 1;
  out.replace(at, end - at, replacement.empty() ? "" : replacement + "\n");
  return out;
}

// axial_stiffness omitted with a chain whose catalogue row has one (the A series, issue 21): the
// row's value, 12 k lbf / p from the source's stretch factor k (12A: 38794.33465, written here
// from jordanrobot/Calculators xml/ansi_chain_specs.xml at b6f5c7e5), reported with its source
// and an info diagnostic; the same run as one giving that number; a B row or no chain: missing,
// naming the rows that have one; an A row with a pitch of its own, or a pocket wheel: missing;
// the inputs' bounds hold for it too.
TEST(DynamicsCli, AxialStiffnessFromTheCatalogueWhereARowHasOne) {
  std::string a12 = example_with("axial_stiffness", "");
  a12.replace(a12.find("chain = \"12B\""), 13, "chain = \"12A\"");
  const CliRun r =
      run("dynamics " + write("stiff_12A.toml", a12) + " --duration 5ms --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto omitted = nlohmann::json::parse(r.out);
  const double k = 12 * 38794.33465 * 4.4482216152605 / 0.01905;  // 1.08703e8 N/m
  EXPECT_NEAR(omitted["axial_stiffness"].get<double>(), k, 1e-12 * k);
  EXPECT_EQ(omitted["units"]["axial_stiffness"], "N/m");
  EXPECT_NE(omitted["axial_stiffness_source"].get<std::string>().find("CALCULATORS_K"),
            std::string::npos);
  ASSERT_EQ(omitted["diagnostics"].size(), 1u) << omitted["diagnostics"].dump();
  const auto& info = omitted["diagnostics"][0];
  EXPECT_EQ(info["severity"], "info");
  EXPECT_EQ(info["code"], "dynamics.axial_stiffness_from_catalogue");
  for (const char* part : {"12A", "order of magnitude", "Tsubaki", "CALCULATORS_K"})
    EXPECT_NE(info["message"].get<std::string>().find(part), std::string::npos) << part;

  // the catalogue's number given: the same run, without the added fields and the diagnostic
  char value[64];
  std::snprintf(value, sizeof value, "axial_stiffness = \"%.17g N/m\"", k);
  std::string given_text = a12;
  given_text.replace(given_text.find("axial_damping"), 0, std::string(value) + "\n");
  const CliRun g = run("dynamics " + write("stiff_12A_given.toml", given_text) +
                       " --duration 5ms --format json");
  ASSERT_EQ(g.status, 0) << g.err;
  auto given = nlohmann::json::parse(g.out);
  EXPECT_FALSE(given.contains("axial_stiffness"));
  EXPECT_FALSE(given["units"].contains("axial_stiffness"));
  EXPECT_TRUE(given["diagnostics"].empty()) << given["diagnostics"].dump();
  for (auto* j : {&omitted, &given}) {
    j->erase("axial_stiffness");
    j->erase("axial_stiffness_source");
    (*j)["units"].erase("axial_stiffness");
    j->erase("diagnostics");
    (*j)["summary"].erase("wall_time");
    (*j)["summary"].erase("real_time_factor");
  }
  EXPECT_EQ(omitted, given);
  // a different number given wins over the catalogue's
  std::string soft = a12;
  soft.replace(soft.find("axial_damping"), 0, "axial_stiffness = \"5e7 N/m\"\n");
  const auto j5 = nlohmann::json::parse(
      run("dynamics " + write("stiff_12A_soft.toml", soft) + " --duration 5ms --format json").out);
  EXPECT_FALSE(j5.contains("axial_stiffness"));
  EXPECT_NE(j5["span"][0]["tension"], given["span"][0]["tension"]);

  const std::string rows = "08A, 10A, 12A, 16A, 20A, 24A, 28A, 32A";
  const CliRun b12 =
      run("dynamics " + write("stiff_12B.toml", example_with("axial_stiffness", "")));
  EXPECT_EQ(b12.status, 2);
  EXPECT_NE(b12.err.find("dynamics.axial_stiffness = (missing)"), std::string::npos) << b12.err;
  EXPECT_NE(b12.err.find("the catalogue has no axial stiffness for 12B"), std::string::npos)
      << b12.err;
  EXPECT_NE(b12.err.find(rows), std::string::npos) << b12.err;
  std::string bare = example_with("axial_stiffness", "");  // explicit chain data, no `chain`
  bare.replace(bare.find("chain = \"12B\""), 13,
               "pitch = \"19.05 mm\"\nmass_per_metre = 1.244\nroller_diameter = \"12.07 mm\"\n"
               "inner_width = \"11.68 mm\"");
  const CliRun none = run("dynamics " + write("stiff_bare.toml", bare));
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("dynamics.axial_stiffness = (missing)"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("chain = an ISO 606 designation that has it: " + rows), std::string::npos)
      << none.err;

  // a pitch given with an A row makes another chain: the row's k = EA/p is for 19.05 mm, so
  // axial_stiffness is required (it was taken as 12A's, 1.087e8 N/m, at 25.4 mm too)
  std::string pitched = a12;
  pitched.replace(pitched.find("chain = \"12A\""), 13, "chain = \"12A\"\npitch = \"25.4 mm\"");
  const CliRun other = run("dynamics " + write("stiff_12A_pitch.toml", pitched));
  EXPECT_EQ(other.status, 2) << other.out;
  EXPECT_NE(other.err.find("dynamics.axial_stiffness = (missing)"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("the catalogue's k for 12A is for its own pitch 19.05 mm"),
            std::string::npos)
      << other.err;
  pitched.replace(pitched.find("axial_damping"), 0, "axial_stiffness = \"5e7 N/m\"\n");
  const CliRun pitched_given =
      run("dynamics " + write("stiff_12A_pitch_k.toml", pitched) + " --duration 5ms");
  EXPECT_EQ(pitched_given.status, 0) << pitched_given.err;

  // a pocket wheel's chain has no catalogue row: missing, no rows named
  std::string pocket = read_text(std::string(CATENA_EXAMPLES_DIR) + "/dynamics_pocketwheel.toml");
  const std::size_t k_at = pocket.find("axial_stiffness = ");
  ASSERT_NE(k_at, std::string::npos);
  pocket.erase(k_at, pocket.find('\n', k_at) + 1 - k_at);
  const CliRun wheel = run("dynamics " + write("stiff_pocket.toml", pocket));
  EXPECT_EQ(wheel.status, 2);
  EXPECT_NE(wheel.err.find("dynamics.axial_stiffness = (missing)"), std::string::npos) << wheel.err;
  EXPECT_EQ(wheel.err.find("08A"), std::string::npos) << wheel.err;
  EXPECT_EQ(wheel.err.find("catalogue"), std::string::npos) << wheel.err;

  // the inputs' bounds apply to the catalogue's value: k (theta h)^2 / m <= 1e6 breaks at a 30 ms
  // step (m = 1.506 kg/m x 19.05 mm)
  const CliRun coarse =
      run("dynamics " + write("stiff_12A.toml", a12) + " --step 30ms --duration 0.3s");
  EXPECT_EQ(coarse.status, 2);
  EXPECT_NE(coarse.err.find("dynamics.axial_stiffness = 1.08703e+08 N/m (the catalogue's, 12A)"),
            std::string::npos)
      << coarse.err;
}

// contact_stiffness omitted: the Hertz default, the secant Q0/δ(Q0) of the plane-strain line
// contact (Johnson 1985, eq. 5.36 form) of the 12B roller (d1 = 12.07 mm) in the ISO 606
// minimum seating arc (ri = 0.505 d1) over the inner width b1 = 11.68 mm, steel on steel, at
// the expected seat load Q0 = T_L/R + pretension — recomputed here from those formulas, not
// through the library. The JSON then names it (contact_stiffness, contact_load); a case that
// gives it has no such fields; no load and no pretension leave nothing to linearise at.
TEST(DynamicsCli, ContactStiffnessDefaultsToTheHertzLineContact) {
  const std::string without = example_without_contact_stiffness();
  ASSERT_EQ(without.find("contact_stiffness = "), std::string::npos);
  const std::string file = write("hertz.toml", without);
  const CliRun r = run("dynamics " + file + " --duration 20ms --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["diagnostics"].empty()) << j["diagnostics"].dump();
  const double d1 = 12.07e-3, b1 = 11.68e-3, pitch = 0.01905, modulus = 210e9, nu = 0.3;
  const double radius = 0.5 * pitch / std::sin(kPi / 12);
  const double load = 10.0 / radius + 950.0;
  const double q = load / b1;
  const double ri = 0.505 * d1;
  const double rho = d1 * ri / (2 * (ri - 0.5 * d1));  // roller in the concave seat
  const double e_star = modulus / (2 * (1 - nu * nu));
  const double half_width = std::sqrt(4 * q * rho / (kPi * e_star));
  const double approach =
      q / kPi * 2 * (1 - nu * nu) / modulus * (2 * std::log(4 * 0.5 * d1 / half_width) - 1);
  EXPECT_NEAR(j["contact_load"].get<double>(), load, 1e-9 * load);
  EXPECT_NEAR(j["contact_stiffness"].get<double>(), load / approach, 1e-9 * load / approach);
  EXPECT_EQ(j["units"]["contact_stiffness"], "N/m");
  // the approach at the load is what the linear penalty reproduces: a few µm
  EXPECT_GT(approach, 1e-6);
  EXPECT_LT(approach, 3e-6);
  EXPECT_LT(j["summary"]["max_penetration"].get<double>(), 10 * approach);

  const auto given =
      nlohmann::json::parse(run("dynamics " + kExample + " --duration 1ms --format json").out);
  EXPECT_FALSE(given.contains("contact_stiffness"));
  EXPECT_FALSE(given["units"].contains("contact_stiffness"));

  std::string unloaded = without;
  for (const std::string key : {"pretension = ", "load_torque = "}) {
    const std::size_t k = unloaded.find(key);
    ASSERT_NE(k, std::string::npos);
    unloaded.erase(k, unloaded.find('\n', k) + 1 - k);
  }
  const CliRun none = run("dynamics " + write("hertz_unloaded.toml", unloaded));
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("dynamics.contact_stiffness = (missing)"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("expected seat load"), std::string::npos) << none.err;

  // the free layout (examples/dynamics_three_wheels.toml): the expected load is the pretension
  // plus each driven wheel's T_L/R (one driven z = 18 wheel with 10 N m here), and the same law
  std::string three = read_text(std::string(CATENA_EXAMPLES_DIR) + "/dynamics_three_wheels.toml");
  const std::size_t k3 = three.find("contact_stiffness = ");
  ASSERT_NE(k3, std::string::npos);
  three.erase(k3, three.find('\n', k3) + 1 - k3);
  const CliRun r3 =
      run("dynamics " + write("hertz_three.toml", three) + " --duration 5ms --format json");
  ASSERT_EQ(r3.status, 0) << r3.err;
  const auto j3 = nlohmann::json::parse(r3.out);
  const double load3 = 10.0 / (0.5 * pitch / std::sin(kPi / 18)) + 950.0;
  EXPECT_NEAR(j3["contact_load"].get<double>(), load3, 1e-9 * load3);
  const double q3 = load3 / b1;
  const double hw3 = std::sqrt(4 * q3 * rho / (kPi * e_star));
  const double approach3 =
      q3 / kPi * 2 * (1 - nu * nu) / modulus * (2 * std::log(4 * 0.5 * d1 / hw3) - 1);
  EXPECT_NEAR(j3["contact_stiffness"].get<double>(), load3 / approach3, 1e-9 * load3 / approach3);
}

// contact_law = "line" (docs/models/dynamics.md, "Contact law"): the example without its k_c
// runs with the seats on the Hertz line law; the mean tight-span tension still meets validation
// (6)'s torque balance within 1 %, the JSON names the law, and the seats go less deep than on the
// linear secant the default takes at the same expected load (measured: 1.01 against 2.91 µm; the
// law is softer at first touch, so the rollers engage with less impact, and it has no ramp's ε/2;
// with the linear law in its place the two runs are the same). The law's field and keys are
// checked: an unknown law, a pocket wheel with it and an expected seat load past its cap are
// refused, each by name; with no expected seat load contact_stiffness (then the guides' and the
// take-up's stops' penalty) is asked for, and given, accepted.
TEST(DynamicsCli, LineContactLawRunsTheExampleDrive) {
  const std::string linear = example_without_contact_stiffness();
  ASSERT_EQ(linear.find("contact_stiffness = "), std::string::npos);
  const std::string line = with_dynamics_key(linear, "contact_law = \"line\"");
  const CliRun r = run("dynamics " + write("line.toml", line) + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["diagnostics"].empty()) << j["diagnostics"].dump();
  EXPECT_EQ(j["contact_law"], "line");
  EXPECT_EQ(j["summary"]["steps"], 5000);
  EXPECT_NEAR(tight_tension_ratio(j), 1.0, kTensionTol);
  const auto secant =
      nlohmann::json::parse(run("dynamics " + write("secant.toml", linear) + " --format json").out);
  EXPECT_FALSE(secant.contains("contact_law"));
  const double deepest = j["summary"]["max_penetration"].get<double>();
  const double deepest_secant = secant["summary"]["max_penetration"].get<double>();
  std::printf("line law: max penetration %.4g um (the secant's %.4g um), tension ratio %.5f\n",
              deepest * 1e6, deepest_secant * 1e6, tight_tension_ratio(j));
  EXPECT_LT(deepest, deepest_secant - 0.4e-6);
  // the line law takes the seats' discrete gradient by default, and says so: the same run with
  // discrete_gradient = false differs and echoes false
  EXPECT_EQ(j["discrete_gradient"], true);
  const CliRun r_off = run(
      "dynamics " + write("line_nodg.toml", with_dynamics_key(line, "discrete_gradient = false")) +
      " --format json");
  ASSERT_EQ(r_off.status, 0) << r_off.err;
  const auto off = nlohmann::json::parse(r_off.out);
  EXPECT_EQ(off["discrete_gradient"], false);
  EXPECT_NE(off["span"], j["span"]);
  EXPECT_NE(off["summary"]["max_penetration"], j["summary"]["max_penetration"]);

  auto refused = [&](const std::string& name, const std::string& toml, const std::string& what) {
    const CliRun bad = run("dynamics " + write(name, toml));
    EXPECT_EQ(bad.status, 2) << name;
    EXPECT_NE(bad.err.find(what), std::string::npos) << bad.err;
  };
  std::string unknown = line;
  unknown.replace(unknown.find("\"line\""), 6, "\"hertz\"");
  refused("law_unknown.toml", unknown, "linear or line");
  const std::string rest = "pretension = \"950 N\"";
  ASSERT_NE(line.find(rest), std::string::npos);
  std::string heavy = line;  // Q0 = T_L/R + pretension past the law's cap (50.4 kN for 12B)
  heavy.replace(heavy.find(rest), rest.size(), "pretension = \"60 kN\"");
  refused("law_heavy.toml", heavy,
          "below the line law's cap 50.4 kN (b = 4R_ref/e^1.5; here 60.3 kN)");
  // no expected seat load (no pretension, no load torque): the Hertz default has no load to be
  // taken at, so contact_stiffness is asked for as the guides' and the stops' penalty (not the
  // seats': they follow the load), and given, the case runs
  std::string idle = line;
  idle.replace(idle.find(rest), rest.size(), "pretension = \"0 N\"");
  const std::string torque = "load_torque = 10";
  ASSERT_NE(idle.find(torque), std::string::npos);
  idle.replace(idle.find(torque), torque.size(), "load_torque = 0");
  const CliRun missing = run("dynamics " + write("law_idle.toml", idle));
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("dynamics.contact_stiffness = (missing)"), std::string::npos)
      << missing.err;
  EXPECT_NE(missing.err.find("the penalty of a take-up's end stops"), std::string::npos)
      << missing.err;
  EXPECT_EQ(missing.err.find("roller-seat penalty"), std::string::npos) << missing.err;
  std::string idle_stiff = idle;
  idle_stiff.insert(idle_stiff.find("contact_law"), "contact_stiffness = \"2e8 N/m\"\n");
  const CliRun idle_run =
      run("dynamics " + write("law_idle_stiff.toml", idle_stiff) + " --duration 5ms --format json");
  ASSERT_EQ(idle_run.status, 0) << idle_run.err;
  const auto ji = nlohmann::json::parse(idle_run.out);
  EXPECT_EQ(ji["contact_law"], "line");
  EXPECT_FALSE(ji.contains("contact_load"));  // the penalty given: no Hertz default reported
  const std::string pocket_text =
      read_text(std::string(CATENA_EXAMPLES_DIR) + "/dynamics_pocketwheel.toml");
  const std::string pocket = with_dynamics_key(pocket_text, "contact_law = \"line\"");
  refused("law_pocket.toml", pocket, "dynamics.contact_law");
}

// discrete_gradient (docs/models/dynamics.md, "Sprockets: the discrete gradient"): true on the
// example's penalty seats changes the run and is echoed in the JSON; false, the penalty's default,
// is the run without the key, bit for bit, and not echoed; a value that is not a boolean is refused
// by name. On the pocket wheel's example true is accepted, echoed and changes the run ("Pocket
// wheel: the discrete gradient"); without the key it is not echoed (its default there is false).
TEST(DynamicsCli, DiscreteGradientKeyTakesTheSeatsForceOverTheStep) {
  const std::string base = read_text(kExample);
  auto json_run = [&](const std::string& name, const std::string& text) {
    const CliRun r = run("dynamics " + write(name, text) + " --duration 5ms --format json");
    EXPECT_EQ(r.status, 0) << r.err;
    return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
  };
  const auto plain = json_run("dg_plain.toml", base);
  const auto on = json_run("dg_on.toml", with_dynamics_key(base, "discrete_gradient = true"));
  const auto off = json_run("dg_off.toml", with_dynamics_key(base, "discrete_gradient = false"));
  ASSERT_TRUE(plain.contains("span"));
  EXPECT_FALSE(plain.contains("discrete_gradient"));
  EXPECT_EQ(on["discrete_gradient"], true);
  EXPECT_NE(on["span"], plain["span"]);
  EXPECT_FALSE(off.contains("discrete_gradient"));
  EXPECT_EQ(off["span"], plain["span"]);
  EXPECT_EQ(off["summary"]["max_penetration"], plain["summary"]["max_penetration"]);
  // below θ = 0.6 the warning says what the discrete gradient changes; without it, as before
  auto theta_warning = [](const nlohmann::json& j) {
    for (const auto& d : j["diagnostics"])
      if (d["code"] == "dynamics.theta_below_0_6") return d["message"].get<std::string>();
    return std::string();
  };
  const std::string theta = "theta = 0.6 ";
  ASSERT_NE(base.find(theta), std::string::npos);
  std::string half = base;
  half.replace(half.find(theta), theta.size(), "theta = 0.5 ");
  const std::string half_on =
      theta_warning(json_run("dg_half.toml", with_dynamics_key(half, "discrete_gradient = true")));
  const std::string half_off = theta_warning(json_run("dg_half_off.toml", half));
  EXPECT_NE(half_on.find("with discrete_gradient = true drives with roller-seat contact, damped "
                         "or not, keep their work balance"),
            std::string::npos)
      << half_on;
  EXPECT_EQ(half_off,
            "theta = 0.5 < 0.6: drives with roller-seat contact diverged below 0.6 "
            "(docs/models/dynamics.md)");
  const CliRun text = run(
      "dynamics " + write("dg_text.toml", with_dynamics_key(base, "discrete_gradient = \"yes\"")));
  EXPECT_EQ(text.status, 2);
  EXPECT_NE(text.err.find("dynamics.discrete_gradient"), std::string::npos) << text.err;
  EXPECT_NE(text.err.find("true or false"), std::string::npos) << text.err;
  const std::string pocket_text =
      read_text(std::string(CATENA_EXAMPLES_DIR) + "/dynamics_pocketwheel.toml");
  // on the pocket wheel: accepted, the pockets' force over the step; its default stays false
  const auto pocket_plain = json_run("dg_pocket_plain.toml", pocket_text);
  const auto pocket_on =
      json_run("dg_pocket.toml", with_dynamics_key(pocket_text, "discrete_gradient = true"));
  ASSERT_TRUE(pocket_plain.contains("span"));
  EXPECT_FALSE(pocket_plain.contains("discrete_gradient"));
  EXPECT_EQ(pocket_on["discrete_gradient"], true);
  EXPECT_NE(pocket_on["span"], pocket_plain["span"]);
  // below θ = 0.6 on the pocket wheel the warning does not promise the seats' balance at ½ (the
  // undamped example there stops, docs "Pocket wheel: the discrete gradient"): a 10 ms run is
  // enough to read it
  std::string pocket_short = pocket_text;
  const std::string one_second = "duration = \"1 s\"";
  ASSERT_NE(pocket_short.find(one_second), std::string::npos);
  pocket_short.replace(pocket_short.find(one_second), one_second.size(), "duration = \"10 ms\"");
  const std::string pocket_half =
      with_dynamics_key(pocket_short, "discrete_gradient = true\ntheta = 0.5");
  const std::string pocket_warning = theta_warning(json_run("dg_pocket_half.toml", pocket_half));
  EXPECT_NE(pocket_warning.find("pocket-wheel runs below 0.6 may stop"), std::string::npos)
      << pocket_warning;
  EXPECT_EQ(pocket_warning.find("damped or not"), std::string::npos) << pocket_warning;
}

// discrete_gradient = true with wheel = "pocket" takes the tension-only links' force over the step
// too (docs/models/dynamics.md, "Tension-only links: the discrete gradient"): the pocket example at
// θ = ½, undamped, its first 10 ms (the joints seated, the slack strand's links through their
// ramp) closes its work balance to Newton's tolerance, −1.4e-8 J (−9.2e-9 J before the mouth's
// band; +0.30 J with the pockets' force over the step alone, before the links'; +0.111 J without
// the key, +0.27 J before the flat links were bilateral: their ramp's steps were part of it;
// −7.6e-9 J with the key then).
TEST(DynamicsCli, DiscreteGradientKeyTakesThePocketChainsLinksOverTheStep) {
  std::string text = read_text(std::string(CATENA_EXAMPLES_DIR) + "/dynamics_pocketwheel.toml");
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"duration = \"1 s\"", "duration = \"10 ms\""},
        {"axial_damping = 2000", "axial_damping = 0"},
        {"contact_damping = 2000", "contact_damping = 0"}}) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  }
  text = with_dynamics_key(text, "theta = 0.5\nwork_balance = true");
  auto numerical = [&](const std::string& name, const std::string& key) -> double {
    const CliRun r =
        run("dynamics " + write(name, with_dynamics_key(text, key)) + " --format json");
    EXPECT_EQ(r.status, 0) << r.err;
    if (r.status != 0) return NAN;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["summary"]["steps"], 100);
    return j["summary"]["work_balance"]["numerical"].get<double>();
  };
  const double on = numerical("dg_links_on.toml", "discrete_gradient = true");
  const double off = numerical("dg_links_off.toml", "discrete_gradient = false");
  std::printf("pocket example, theta = 0.5 undamped, 10 ms: numerical %.3g J (key), %.3g J\n", on,
              off);
  EXPECT_LT(std::abs(on), 1e-6);
  // the contrast, not the size: without the key the ramp's steps leave an error (measured
  // 0.111 J, 0.27 J before the flat links were rigid) three orders above the key's bound
  EXPECT_GT(std::abs(off), 1e-3);
}

// `catena report` on the example: the time series (each curve's extremes those of the JSON),
// the span-tension spectrum with the tooth-mesh harmonics marked and peaks at them, and the
// animation, whose rollers sit in the drawn outlines' seats.
TEST(DynamicsCli, ReportHasTimeSeriesSpectrumAndAnimation) {
  const fs::path out = fs::temp_directory_path() / "catena_dynamics_cli_test" / "report.html";
  fs::create_directories(out.parent_path());
  const CliRun r = run("report " + kExample + " -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string html = read_text(out);
  EXPECT_LT(html.size(), 2'000'000u);  // the browser test's bound: Plotly's basic bundle + data
  const auto plain = chart_list(html, "catena-charts");
  const auto extra = chart_list(html, "catena-charts-extra");
  ASSERT_EQ(plain.size(), 3u);
  ASSERT_EQ(extra.size(), 2u);

  const auto j = nlohmann::json::parse(run("dynamics " + kExample + " --format json").out);
  auto extremes = [](const std::vector<double>& v) {
    return std::make_pair(*std::min_element(v.begin(), v.end()),
                          *std::max_element(v.begin(), v.end()));
  };
  // 1. time series: speeds, torques, span tensions; at most 2000 points a curve, the extremes kept
  const std::vector<std::pair<std::string, std::string>> series = {
      {"Sprocket speeds", "speed"}, {"Chain torque on the sprockets", "torque"}};
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(plain[c]["title"], series[c].first);
    ASSERT_EQ(plain[c]["traces"].size(), 2u);
    for (std::size_t w = 0; w < 2; ++w) {
      const auto y = plain[c]["traces"][w]["y"].get<std::vector<double>>();
      EXPECT_LE(y.size(), 2000u);
      const auto want = extremes(j["sprocket"][w][series[c].second].get<std::vector<double>>());
      EXPECT_NEAR(extremes(y).first, want.first, 1e-9 * std::abs(want.first) + 1e-12);
      EXPECT_NEAR(extremes(y).second, want.second, 1e-9 * std::abs(want.second) + 1e-12);
    }
  }
  EXPECT_EQ(plain[2]["traces"][0]["name"], "upper span (tight)");
  EXPECT_EQ(plain[2]["traces"][1]["name"], "lower span (slack)");
  for (std::size_t s = 0; s < 2; ++s) {
    const auto want = extremes(j["span"][s]["tension"].get<std::vector<double>>());
    const auto got = extremes(plain[2]["traces"][s]["y"].get<std::vector<double>>());
    EXPECT_NEAR(got.first, want.first, 1e-9 * want.second);
    EXPECT_NEAR(got.second, want.second, 1e-9 * want.second);
  }

  // 2. the spectrum: markers at k z ω / 2π, k = 1…6, and the tight span's spectrum has a peak
  // within one frequency resolution 1/T (T = the analysed half, 0.25 s) of each: the ripple of
  // the polygonal action at the tooth-mesh frequency and its harmonics; then each span's first
  // transverse frequency and twice it, as the JSON's summary has them (the longitudinal ones,
  // 2.3 kHz, are above the chart's 161 Hz)
  const auto& spectrum = extra[0];
  const double mesh = 12 * 13.0 / (2 * kPi);
  ASSERT_EQ(spectrum["markers"].size(), 10u);
  {
    const CliRun json = run("dynamics " + kExample + " --format json");
    ASSERT_EQ(json.status, 0) << json.err;
    const auto summary = nlohmann::json::parse(json.out)["summary"];
    for (int span = 0; span < 2; ++span) {
      const double f1 =
          summary["span_" + std::to_string(span)]["transverse_frequency"].get<double>();
      EXPECT_NEAR(spectrum["markers"][6 + 2 * span]["x"].get<double>(), f1, 1e-9 * f1);
      EXPECT_NEAR(spectrum["markers"][7 + 2 * span]["x"].get<double>(), 2 * f1, 1e-9 * f1);
      EXPECT_NE(spectrum["markers"][6 + 2 * span]["label"].get<std::string>().find("transverse"),
                std::string::npos);
    }
  }
  const auto f = spectrum["traces"][0]["x"].get<std::vector<double>>();
  const auto a = spectrum["traces"][0]["y"].get<std::vector<double>>();
  EXPECT_GT(f.back(), 6 * mesh);
  std::vector<double> peaks;
  for (std::size_t m = 1; m + 1 < a.size(); ++m)
    if (a[m] > a[m - 1] && a[m] >= a[m + 1]) peaks.push_back(f[m]);
  for (int k = 1; k <= 6; ++k) {
    EXPECT_NEAR(spectrum["markers"][k - 1]["x"].get<double>(), k * mesh, 1e-6);
    double nearest = INFINITY;
    for (double p : peaks) nearest = std::min(nearest, std::abs(p - k * mesh));
    EXPECT_LT(nearest, 1.0 / 0.25) << "harmonic " << k;
  }
  EXPECT_NE(spectrum["markers"][0]["label"].get<std::string>().find("24.83 Hz"), std::string::npos);

  // 3. the animation: at most 60 frames from t = 0, the two outlines and the chain's 32 nodes
  // (closed); each roller well inside the wrap sits in a seat of the outline drawn at its frame
  const auto& loop = extra[1];
  EXPECT_TRUE(loop["equal"].get<bool>());
  const auto& frames = loop["frames"];
  ASSERT_GE(frames.size(), 50u);
  ASSERT_LE(frames.size(), 60u);
  EXPECT_EQ(frames[0]["name"], "t = 0 s");
  const double radius = 0.5 * 19.05 / std::sin(kPi / 12) * 1e3;  // pitch radius [mm]
  for (const auto& frame : frames) {
    ASSERT_EQ(frame["traces"].size(), 3u);
    const auto cx = frame["traces"][2]["x"].get<std::vector<double>>();
    const auto cy = frame["traces"][2]["y"].get<std::vector<double>>();
    ASSERT_EQ(cx.size(), 33u);
    EXPECT_EQ(cx.front(), cx.back());
    for (std::size_t w = 0; w < 2; ++w) {
      const double centre = w == 0 ? 0.0 : 10 * 19.05;
      const auto ox = frame["traces"][w]["x"].get<std::vector<double>>();
      const auto oy = frame["traces"][w]["y"].get<std::vector<double>>();
      // the seat bottoms: the outline's points nearest the centre
      double bottom = INFINITY;
      for (std::size_t i = 0; i < ox.size(); ++i)
        bottom = std::min(bottom, std::hypot(ox[i] - centre, oy[i]));
      std::vector<double> seats;
      for (std::size_t i = 0; i < ox.size(); ++i)
        if (std::hypot(ox[i] - centre, oy[i]) < bottom + 0.01)
          seats.push_back(std::atan2(oy[i], ox[i] - centre));
      EXPECT_GE(seats.size(), 12u);
      for (std::size_t i = 0; i + 1 < cx.size(); ++i) {
        // well inside the wrap (the outer half of the wheel): seated, not entering or leaving
        const double outward = w == 0 ? centre - cx[i] : cx[i] - centre;
        if (outward < 0.5 * radius || std::hypot(cx[i] - centre, cy[i]) > radius + 1.0) continue;
        const double at = std::atan2(cy[i], cx[i] - centre);
        double off = INFINITY;
        for (double s : seats) off = std::min(off, std::abs(std::remainder(at - s, 2 * kPi)));
        EXPECT_LT(off, 1.0 * kPi / 180) << frame["name"] << ", wheel " << w << ", node " << i;
      }
    }
  }
}

}  // namespace
