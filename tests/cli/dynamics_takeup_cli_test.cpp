// The take-up's travel, its diagnostics and its outputs through `catena dynamics` / `catena
// report` (docs/models/dynamics.md, "Take-up"; issue 21), on examples/dynamics_takeup.toml (the
// idler z = 15 at (150, −175) mm on a slide along −y, 600 N) and variants of it:
// * an end stop holds the slide at its bound within the stop's penetration, and says so;
// * a wheel that loses the chain for longer than the stated 10 ms is diagnosed, one that keeps
//   it is not;
// * the CSV's take-up columns are the JSON's series; the animation's outline of the take-up's
//   wheel is centred where the JSON's slide puts it, at every frame;
// * spectrum_start moves the report's spectrum window (the chart against a direct Fourier sum of
//   the JSON's tension series) and is refused outside its range;
// * a take-up on a driven wheel runs and balances its force with the spans' tensions;
// * the spans' frequencies at the settled layout use the belt path through the mean centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "../read_text.hpp"
#include "case_text.hpp"
#include "chart_list.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;
constexpr double kPitch = 0.01905;  // 12B
constexpr double kMass = 1.25;      // 12B: q [kg/m]
const std::string kExample = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_takeup.toml";

std::string example_text() { return read_text(kExample); }

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "catena_dynamics_takeup_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// The line of `text` that starts with `key` replaced by `line` (the key must be there).
std::string replaced(std::string text, const std::string& key, const std::string& line) {
  const std::size_t at = text.find("\n" + key + " ");
  EXPECT_NE(at, std::string::npos) << key;
  if (at == std::string::npos) return text;
  const std::size_t end = text.find('\n', at + 1);
  return text.replace(at + 1, end - at - 1, line);
}

// The example undamped (links, seats, slide) at θ = ½: the θ point's force diverges there.
std::string undamped_at_theta_half() {
  std::string text = example_text();
  text = replaced(text, "axial_damping", "axial_damping = 0");
  text = replaced(text, "contact_damping", "contact_damping = 0");
  text = replaced(text, "takeup_damping", "takeup_damping = 0");
  return replaced(text, "theta", "theta = 0.5");
}

// `lines` added to the last [[dynamics.sprocket]] table (the idler's).
std::string in_idler(std::string text, const std::string& lines) {
  const std::size_t at = text.find("\n[analyses.dynamics]");
  EXPECT_NE(at, std::string::npos);
  return text.insert(at, "\n" + lines);
}

nlohmann::json dynamics_json(const std::string& path, const std::string& options = "") {
  const CliRun r = run("dynamics " + path + " --format json" + options);
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

std::vector<double> series(const nlohmann::json& j) { return j.get<std::vector<double>>(); }

bool has_code(const nlohmann::json& j, const std::string& code) {
  for (const auto& d : j["diagnostics"])
    if (d["code"] == code) return true;
  return false;
}

double radius(int z) { return 0.5 * kPitch / std::sin(kPi / z); }

// The outward normal angle of the outer common tangent leaving circle a for circle b, the loop
// counter-clockwise (written out here, independent of dynamics/layout.cpp).
double tangent_normal(double ax, double ay, double ra, double bx, double by, double rb) {
  const double dx = bx - ax, dy = by - ay;
  return std::atan2(dy, dx) - std::acos((ra - rb) / std::hypot(dx, dy));
}

// The mean of x over the samples with time in [from, to].
double mean_over(const std::vector<double>& time, const std::vector<double>& x, double from,
                 double to) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (time[k] < from - 1e-12 || time[k] > to + 1e-12) continue;
    sum += x[k];
    ++count;
  }
  return sum / count;
}

// The lost-chain case (below): the example with a soft chain (1e4 N/m a link), gravity, no load
// and a 100 N take-up, 0.5 s; its slide free (add takeup_travel_max = 0 to hold it).
std::string slack_loop() {
  std::string text = replaced(example_text(), "duration", "duration = \"0.5 s\"");
  text = replaced(text, "axial_stiffness", "axial_stiffness = \"1e4 N/m\"");
  text = replaced(text, "load_torque", "load_torque = 0");
  text = replaced(text, "takeup_force", "takeup_force = \"100 N\"");
  return with_dynamics_key(text, "gravity = true\n");
}

// The dynamics.takeup_lost_chain warning of `j` (null without one).
nlohmann::json lost_chain(const nlohmann::json& j) {
  for (const auto& d : j["diagnostics"])
    if (d["code"] == "dynamics.takeup_lost_chain") return d;
  return nullptr;
}

// The number after `label` in `message` (NAN without it).
double number_after(const std::string& message, const std::string& label) {
  const std::size_t at = message.find(label);
  return at == std::string::npos ? NAN : std::stod(message.substr(at + label.size()));
}

// The take-up example with sliding hinges and the stick law at ratio 96 (hinge_stick_stiffness =
// 2.3e5 N m/rad at 0.1 ms: warned, within the bound), its samples every step, over `duration`:
// its first steps fail at h and are retaken as halves down to h/4 (docs/models/dynamics.md,
// "Integrator: a failed step retaken as half-steps"), the slide rising from rest.
std::string stick_law_takeup(const std::string& duration, const std::string& idler = "") {
  std::string text = replaced(example_text(), "duration", "duration = \"" + duration + "\"");
  text = replaced(text, "output_interval", "output_interval = \"0.1 ms\"");
  text = with_dynamics_key(
      text, "hinge = \"sliding\"\nhinge_friction = 0.1\nhinge_stick_stiffness = 2.3e5\n");
  return idler.empty() ? text : in_idler(text, idler);
}

// The number just before `words` in `m` (-1 without them).
long count_before(const std::string& m, const std::string& words) {
  const std::size_t at = m.find(words);
  if (at == std::string::npos || at == 0) return -1;
  std::size_t from = m.rfind(' ', at - 1);
  from = from == std::string::npos ? 0 : from + 1;
  return std::stol(m.substr(from, at - from));
}

}  // namespace

// takeup_travel_max = 0.4 mm on the example (whose slide settles at about 0.54 mm and overshoots
// to 0.77 mm without it): after the first hit the stop holds the slide at the bound, never
// below it by more than the slide's rebound and never past it by more than the stop's static
// penetration under the whole take-up force, F/k_c + ε/2 = 600 N / 2e8 N/m + 0.5 µm = 3.5 µm
// (the chain's pull takes part of F, so the penetration is less). The warning names the bound
// and the first time; without the key there is no warning and the slide goes past 0.4 mm.
TEST(DynamicsTakeupCli, EndStopHoldsTheSlideAtItsBound) {
  const std::string text = replaced(example_text(), "duration", "duration = \"0.4 s\"");
  const nlohmann::json free = dynamics_json(write("free.toml", text));
  EXPECT_FALSE(has_code(free, "dynamics.takeup_at_travel_end")) << free["diagnostics"].dump();
  const auto free_position = series(free["takeup"][0]["position"]);
  EXPECT_GT(*std::max_element(free_position.begin(), free_position.end()), 0.5e-3);
  EXPECT_FALSE(free["takeup"][0].contains("travel_max"));

  const nlohmann::json j =
      dynamics_json(write("stop.toml", in_idler(text, "takeup_travel_max = \"0.4 mm\"\n")));
  ASSERT_TRUE(j.contains("takeup"));
  EXPECT_EQ(j["takeup"][0]["travel_max"].get<double>(), 0.4e-3);
  EXPECT_FALSE(j["takeup"][0].contains("travel_min"));
  EXPECT_EQ(j["units"]["travel_max"], "m");
  const auto time = series(j["time"]);
  const auto position = series(j["takeup"][0]["position"]);
  const double bound = 0.4e-3, static_penetration = 600.0 / 2e8 + 0.5e-6;
  double deepest = 0.0, lowest = INFINITY;
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (time[k] < 0.1) continue;
    deepest = std::max(deepest, position[k] - bound);
    lowest = std::min(lowest, position[k] - bound);
  }
  EXPECT_LE(deepest, static_penetration);
  EXPECT_GT(deepest, 0.0);         // it rests on the stop ...
  EXPECT_GT(lowest, -0.1 * 1e-6);  // ... and does not leave it by 0.1 µm
  int warnings = 0;
  for (const auto& d : j["diagnostics"]) {
    if (d["code"] != "dynamics.takeup_at_travel_end") continue;
    ++warnings;
    EXPECT_EQ(d["severity"], "warning");
    EXPECT_EQ(d["limit"].get<double>(), bound);
    const double first = d["value"].get<double>();
    // the first sample past the bound is at most one output interval after the reported time
    std::size_t k = 0;
    while (k < time.size() && !(position[k] > bound)) ++k;
    ASSERT_LT(k, time.size());
    EXPECT_LE(first, time[k] + 1e-12);
    EXPECT_GT(first, time[k] - 1e-3 - 1e-12);
    const std::string message = d["message"];
    EXPECT_NE(message.find("takeup_travel_max = 0.0004 m"), std::string::npos) << message;
    EXPECT_NE(message.find("sprocket 2"), std::string::npos) << message;
  }
  EXPECT_EQ(warnings, 1);
}

// A wheel that loses the chain: the example's idler held at its start by takeup_travel_max = 0
// (its 100 N pushing it into the stop, not into the chain) under a soft chain (1e4 N/m a link)
// with gravity and no load: the loop starts without pretension and nothing tensions it, so the
// chain runs off and on the idler, its force on the wheel at zero (at most 1 % of the preload,
// 1 N) for stretches longer than 10 ms — reported with the first one's time. The same case with
// the slide free (the 100 N reaching the chain) keeps the chain on the wheel, and so does the
// example: no such warning.
TEST(DynamicsTakeupCli, LosingTheChainIsDiagnosed) {
  const std::string text = slack_loop();
  const nlohmann::json sagging =
      dynamics_json(write("sag.toml", in_idler(text, "takeup_travel_max = \"0 mm\"\n")));
  bool found = false;
  for (const auto& d : sagging["diagnostics"]) {
    if (d["code"] != "dynamics.takeup_lost_chain") continue;
    found = true;
    EXPECT_EQ(d["severity"], "warning");
    EXPECT_EQ(d["limit"].get<double>(), 0.010);
    const double first = d["value"].get<double>();
    EXPECT_GT(first, 0.0);
    EXPECT_LT(first, 0.5);
    const std::string message = d["message"];
    EXPECT_NE(message.find("at most 1 N"), std::string::npos) << message;
    EXPECT_NE(message.find("longer than 10 ms"), std::string::npos) << message;
  }
  EXPECT_TRUE(found) << sagging["diagnostics"].dump();

  const nlohmann::json taut = dynamics_json(write("taut.toml", text));
  EXPECT_FALSE(has_code(taut, "dynamics.takeup_lost_chain")) << taut["diagnostics"].dump();
  const nlohmann::json plain = dynamics_json(kExample, " --duration 0.3s");
  EXPECT_FALSE(has_code(plain, "dynamics.takeup_lost_chain")) << plain["diagnostics"].dump();
  EXPECT_FALSE(has_code(plain, "dynamics.takeup_at_travel_end"));
}

// The lost-chain warning's thresholds are case keys on the take-up's wheel. The held case above
// reports its longest stretch L at zero force: with takeup_lost_time a little above L it no
// longer fires, a little below L it does, with that time as its limit and no more stretches than
// at 10 ms. takeup_lost_force moves the zero: the free-slide case, where the chain presses the
// wheel with about the take-up's 100 N and the default 1 N never fires, fires with a 1 kN zero
// (the whole run is one stretch from the start).
TEST(DynamicsTakeupCli, LostChainThresholdsAreCaseKeys) {
  const std::string held = in_idler(slack_loop(), "takeup_travel_max = \"0 mm\"\n");
  const nlohmann::json base = lost_chain(dynamics_json(write("held.toml", held)));
  ASSERT_FALSE(base.is_null());
  const std::string message = base["message"];
  const double longest = number_after(message, "the longest ");
  const double count = number_after(message, " ms ");
  ASSERT_GT(longest, 0.010) << message;
  ASSERT_GE(count, 1.0) << message;

  auto lost_time = [&](double factor) {  // the key at factor × L, in ms
    return "takeup_lost_time = \"" + std::to_string(factor * longest * 1e3) + " ms\"\n";
  };
  const nlohmann::json above = dynamics_json(write("above.toml", in_idler(held, lost_time(1.02))));
  EXPECT_TRUE(lost_chain(above).is_null()) << above["diagnostics"].dump();
  const nlohmann::json below =
      lost_chain(dynamics_json(write("below.toml", in_idler(held, lost_time(0.98)))));
  ASSERT_FALSE(below.is_null());
  EXPECT_NEAR(below["limit"].get<double>(), 0.98 * longest, 1e-9);
  const std::string fewer = below["message"];
  EXPECT_GE(number_after(fewer, " ms "), 1.0) << fewer;
  EXPECT_LE(number_after(fewer, " ms "), count) << fewer;

  const nlohmann::json taut = dynamics_json(write("taut.toml", slack_loop()));
  EXPECT_TRUE(lost_chain(taut).is_null()) << taut["diagnostics"].dump();
  const nlohmann::json high = lost_chain(
      dynamics_json(write("high.toml", in_idler(slack_loop(), "takeup_lost_force = \"1 kN\"\n"))));
  ASSERT_FALSE(high.is_null());
  const std::string loud = high["message"];
  EXPECT_NE(loud.find("at most 1000 N"), std::string::npos) << loud;
  EXPECT_NE(loud.find("longer than 10 ms 1 time(s)"), std::string::npos) << loud;
  EXPECT_LT(high["value"].get<double>(), 1e-3) << loud;
}

// The thresholds' keys refused, all at once, each named with its line: out of range on the
// take-up's wheel, and on a wheel without a take-up (the driver; the driven wheel).
TEST(DynamicsTakeupCli, LostChainThresholdsRefused) {
  std::string text =
      in_idler(example_text(), "takeup_lost_force = \"-1 N\"\ntakeup_lost_time = \"2000 s\"\n");
  text.insert(text.find("role = \"driven\"\n"), "takeup_lost_time = \"5 ms\"\n");
  text.insert(text.find("role = \"driver\"\n"), "takeup_lost_force = \"2 N\"\n");
  const CliRun r = run("dynamics " + write("bad_lost.toml", text));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  for (const char* piece :
       {"dynamics.sprocket[2].takeup_lost_force (line",
        ") = -1: expected the lost-chain warning's "
        "zero, in [0, 1e6] N",
        "dynamics.sprocket[2].takeup_lost_time (line",
        ") = 2000: expected the lost-chain warning's "
        "time, in [0, 1000] s",
        "dynamics.sprocket[1].takeup_lost_time (line", "only on a wheel with a take-up",
        "dynamics.sprocket[0].takeup_lost_force (line", "a take-up only on an idler"})
    EXPECT_NE(r.err.find(piece), std::string::npos) << piece << "\n" << r.err;
}

// The CSV's take-up columns: position_2, slide_speed_2, force_2 after the spans' tensions, the
// JSON's takeup[0] series sample by sample (12 significant digits); every earlier column as
// before.
TEST(DynamicsTakeupCli, CsvColumnsAreTheJsonSeries) {
  const CliRun csv = run("dynamics " + kExample + " --duration 0.05s --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  const nlohmann::json j = dynamics_json(kExample, " --duration 0.05s");
  std::istringstream lines(csv.out);
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header,
            "time,angle_0,speed_0,torque_0,angle_1,speed_1,torque_1,angle_2,speed_2,torque_2,"
            "tension_0_2,tension_2_1,tension_1_0,position_2,slide_speed_2,force_2");
  const auto position = series(j["takeup"][0]["position"]);
  const auto speed = series(j["takeup"][0]["slide_speed"]);
  const auto force = series(j["takeup"][0]["force"]);
  std::string row;
  std::size_t k = 0;
  double moved = 0.0;
  while (std::getline(lines, row)) {
    std::vector<double> cells;
    std::istringstream cols(row);
    for (std::string cell; std::getline(cols, cell, ',');) cells.push_back(std::stod(cell));
    ASSERT_EQ(cells.size(), 16u) << row;
    ASSERT_LT(k, position.size());
    EXPECT_NEAR(cells[13], position[k], 1e-11 * std::abs(position[k]) + 1e-300) << k;
    EXPECT_NEAR(cells[14], speed[k], 1e-11 * std::abs(speed[k]) + 1e-300) << k;
    EXPECT_NEAR(cells[15], force[k], 1e-11 * std::abs(force[k])) << k;
    moved = std::max(moved, std::abs(cells[13]));
    ++k;
  }
  EXPECT_EQ(k, position.size());
  EXPECT_GT(moved, 1e-5);  // the slide moved: the columns are not zeros
}

// The report's animation: the take-up wheel's outline is drawn about the centre the slide puts
// it at, c₀ + s e with s the JSON's position at the frame's time (a sample every step here), to
// the drawing's 1 µm rounding — the outline's vertices are z-fold symmetric, so their mean is
// its centre. The other wheels' outlines stay on their centres.
TEST(DynamicsTakeupCli, AnimationOutlineFollowsTheSlide) {
  std::string text = replaced(example_text(), "duration", "duration = \"0.1 s\"");
  text = replaced(text, "output_interval", "output_interval = \"0.1 ms\"");
  const std::string file = write("frames.toml", text);
  const nlohmann::json j = dynamics_json(file);
  const auto time = series(j["time"]);
  const auto position = series(j["takeup"][0]["position"]);
  const fs::path html = fs::temp_directory_path() / "catena_dynamics_takeup_cli_test" / "r.html";
  const CliRun report = run("report " + file + " -o " + html.string());
  ASSERT_EQ(report.status, 0) << report.err;
  const std::string page = read_text(html);
  const auto extra = chart_list(page, "catena-charts-extra");
  ASSERT_EQ(extra.size(), 2u);
  const auto& frames = extra[1]["frames"];
  ASSERT_GE(frames.size(), 10u);
  const double centres[3][2] = {{0.0, 0.0}, {300.0, 0.0}, {150.0, -175.0}};  // [mm]
  double travelled = 0.0;
  for (const auto& frame : frames) {
    const double t = std::stod(frame["name"].get<std::string>().substr(4));
    std::size_t k = 0;
    for (std::size_t m = 0; m < time.size(); ++m)
      if (std::abs(time[m] - t) < std::abs(time[k] - t)) k = m;
    ASSERT_LT(std::abs(time[k] - t), 1e-6) << frame["name"];
    for (std::size_t w = 0; w < 3; ++w) {
      const auto ox = frame["traces"][w]["x"].get<std::vector<double>>();
      const auto oy = frame["traces"][w]["y"].get<std::vector<double>>();
      ASSERT_GT(ox.size(), 2u);
      double mx = 0.0, my = 0.0;  // the closing point repeats the first: left out
      for (std::size_t i = 0; i + 1 < ox.size(); ++i) {
        mx += ox[i];
        my += oy[i];
      }
      mx /= static_cast<double>(ox.size() - 1);
      my /= static_cast<double>(oy.size() - 1);
      const double sy = w == 2 ? -position[k] * 1e3 : 0.0;  // e = −y
      EXPECT_NEAR(mx, centres[w][0], 1e-3) << frame["name"] << " wheel " << w;
      EXPECT_NEAR(my, centres[w][1] + sy, 1e-3) << frame["name"] << " wheel " << w;
    }
    travelled = std::max(travelled, position[k] * 1e3);
  }
  EXPECT_GT(travelled, 0.1);  // the idler moved by more than 0.1 mm: the check can see it
}

// spectrum_start: the report's span-tension spectrum over the samples from that time to the end.
// The chart's amplitudes at its bins against a direct Fourier sum of the JSON's tension series
// over the same window (Hann window, its weighted mean removed, zero-padded to the power of two
// ≥ 4n, one-sided 2|X|/Σw): at 0.25 s its resolution is that of 751 samples, not the default
// half's 501; spectrum_start = 0.5 s gives exactly the default chart.
TEST(DynamicsTakeupCli, SpectrumStartChoosesTheWindow) {
  const std::string text = example_text();
  auto spectrum_of = [&](const std::string& name, const std::string& toml) {
    const fs::path html =
        fs::temp_directory_path() / "catena_dynamics_takeup_cli_test" / (name + ".html");
    const CliRun report = run("report " + write(name + ".toml", toml) + " -o " + html.string());
    EXPECT_EQ(report.status, 0) << report.err;
    const std::string page = read_text(html);
    const auto extra = chart_list(page, "catena-charts-extra");
    EXPECT_EQ(extra.size(), 2u);
    return extra.empty() ? nlohmann::json::object() : extra[0];
  };
  const nlohmann::json base = spectrum_of("default", text);
  const nlohmann::json half =
      spectrum_of("half", with_dynamics_key(text, "spectrum_start = \"0.5 s\"\n"));
  EXPECT_EQ(base["traces"], half["traces"]);
  EXPECT_EQ(base["title"], half["title"]);
  const nlohmann::json quarter =
      spectrum_of("quarter", with_dynamics_key(text, "spectrum_start = \"0.25 s\"\n"));
  EXPECT_NE(quarter["title"].get<std::string>().find("0.25 s"), std::string::npos)
      << quarter["title"];
  EXPECT_NE(base["traces"], quarter["traces"]);

  const nlohmann::json j = dynamics_json(kExample);
  const auto time = series(j["time"]);
  const auto tension = series(j["span"][2]["tension"]);  // the tight span, 1 -> 0
  std::size_t from = 0;
  while (time[from] < 0.25 - 1e-9) ++from;
  const std::size_t n = time.size() - from;
  ASSERT_EQ(n, 751u);
  const double dt = (time.back() - time[from]) / static_cast<double>(n - 1);
  std::size_t length = 1;
  while (length < 4 * n) length <<= 1;
  std::vector<double> w(n), x(n);
  double wsum = 0.0, mean = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    w[k] = 0.5 - 0.5 * std::cos(2 * kPi * static_cast<double>(k) / static_cast<double>(n - 1));
    wsum += w[k];
    mean += w[k] * tension[from + k];
  }
  mean /= wsum;
  for (std::size_t k = 0; k < n; ++k) x[k] = w[k] * (tension[from + k] - mean);
  const auto& trace = quarter["traces"][2];
  const auto f = trace["x"].get<std::vector<double>>();
  const auto a = trace["y"].get<std::vector<double>>();
  ASSERT_GT(f.size(), 100u);
  EXPECT_NEAR(f[1] - f[0], 1.0 / (static_cast<double>(length) * dt), 1e-9);
  const double peak = *std::max_element(a.begin(), a.end());
  for (std::size_t m = 1; m < f.size(); m += 7) {
    std::complex<double> sum = 0.0;
    for (std::size_t k = 0; k < n; ++k)
      sum += x[k] *
             std::polar(1.0, -2 * kPi * static_cast<double>(m * k) / static_cast<double>(length));
    EXPECT_NEAR(a[m], 2.0 * std::abs(sum) / wsum, 1e-9 * peak) << "bin " << m;
  }
}

// spectrum_start and the travel keys out of range: every one named with its line and range, at
// once, before anything runs.
TEST(DynamicsTakeupCli, BadWindowAndTravelNamed) {
  std::string text = with_dynamics_key(example_text(), "spectrum_start = \"0.995 s\"\n");
  text = in_idler(text, "takeup_travel_min = \"5 mm\"\ntakeup_travel_max = \"-1 mm\"\n");
  const CliRun r = run("dynamics " + write("bad.toml", text));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  for (const char* piece : {"dynamics.spectrum_start (line 17) = 0.995: expected in [0, 0.985] s",
                            "dynamics.sprocket[2].takeup_travel_min (line", "in [-10, 0] m",
                            "dynamics.sprocket[2].takeup_travel_max (line", "in [0, 10] m"})
    EXPECT_NE(r.err.find(piece), std::string::npos) << piece << "\n" << r.err;
  const CliRun negative =
      run("dynamics " +
          write("negative.toml", with_dynamics_key(example_text(), "spectrum_start = -1\n")));
  EXPECT_EQ(negative.status, 2);
  EXPECT_NE(negative.err.find("dynamics.spectrum_start (line 17) = -1: expected in [0, 0.985] s"),
            std::string::npos)
      << negative.err;
  // an output interval that does not divide the run: the last sample is at 0.9999 s (3333 samples
  // of 0.3 ms), not at the duration, so the window's latest start is 0.9999 - 15 x 0.3 ms
  const std::string odd =
      replaced(example_text(), "output_interval", "output_interval = \"0.3 ms\"");
  const CliRun late = run("dynamics " + write("late.toml", with_dynamics_key(odd,
                                                                             "spectrum_start = "
                                                                             "\"0.9955 s\"\n")));
  EXPECT_EQ(late.status, 2);
  EXPECT_NE(late.err.find("dynamics.spectrum_start (line 17) = 0.9955: expected in [0, 0.9954] s"),
            std::string::npos)
      << late.err;
  // a travel key alone does not make a take-up: its direction and force are asked for
  std::string alone = example_text();
  for (const char* key : {"takeup_force", "takeup_direction", "takeup_damping", "takeup_mass"})
    alone = replaced(alone, key, "");
  const CliRun lone =
      run("dynamics " + write("alone.toml", in_idler(alone, "takeup_travel_max = \"1 mm\"\n")));
  EXPECT_EQ(lone.status, 2);
  for (const char* piece :
       {"dynamics.sprocket[2].takeup_direction", "(missing)", "dynamics.sprocket[2].takeup_force"})
    EXPECT_NE(lone.err.find(piece), std::string::npos) << piece << "\n" << lone.err;
}

// The take-up on the driven wheel z = 18 (its slide along +x, 600 N, a 500 N s/m damper, 3 kg),
// the idler fixed: the chain's pull on the wheel along the slide balances the take-up's force —
// the spans arriving (from the idler) and leaving (to the driver) as outer tangents through the
// wheel's mean settled centre, (T_out − q v²) e·d_out − (T_in − q v²) e·d_in = −F, means over the
// summary window, within 1 %. The tension difference across the wheel is its load.
TEST(DynamicsTakeupCli, TakeupOnADrivenWheelBalancesItsForce) {
  std::string text = example_text();
  for (const char* key : {"takeup_force", "takeup_direction", "takeup_damping", "takeup_mass"})
    text = replaced(text, key, "");
  const std::size_t at = text.find("centre_x = \"300 mm\"\ncentre_y = \"0 mm\"\n");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 38,
              "takeup_force = \"600 N\"\ntakeup_direction = \"0 deg\"\ntakeup_damping = 500\n"
              "takeup_mass = 3\n");
  text = replaced(text, "duration", "duration = \"0.6 s\"");
  const nlohmann::json j = dynamics_json(write("driven.toml", text));
  ASSERT_EQ(j["takeup"].size(), 1u);
  EXPECT_EQ(j["takeup"][0]["sprocket"], 1);
  const auto time = series(j["time"]);
  const double from = j["summary"]["window_start"], to = j["summary"]["window_end"];
  const double slide = mean_over(time, series(j["takeup"][0]["position"]), from, to);
  const double pushed = mean_over(time, series(j["takeup"][0]["force"]), from, to);
  EXPECT_GT(slide, 1e-5);
  EXPECT_NEAR(pushed, 600.0, 0.005 * 600.0);
  const double t_in = j["summary"]["span_1"]["mean_tension"];   // 2 -> 1
  const double t_out = j["summary"]["span_2"]["mean_tension"];  // 1 -> 0
  const double r0 = radius(12), r1 = radius(18), r2 = radius(15);
  const double n_in = tangent_normal(0.15, -0.175, r2, 0.3 + slide, 0.0, r1);
  const double n_out = tangent_normal(0.3 + slide, 0.0, r1, 0.0, 0.0, r0);
  const double v = 13.0 * r0, qv2 = kMass * v * v;
  // travel directions (−sin n, cos n); e = +x
  const double pull = (t_out - qv2) * -std::sin(n_out) - (t_in - qv2) * -std::sin(n_in);
  EXPECT_NEAR(-pull, pushed, 0.01 * pushed) << t_in << " " << t_out;
  // the driven wheel's torque balance: T_out − T_in carries the 10 N m load (polygon aside)
  EXPECT_NEAR((t_out - t_in) * r1, 10.0, 0.05 * 10.0);
}

// The span frequencies at the settled layout: the belt path through the take-up's mean centre
// over the summary window. The two spans at the idler get the outer tangents' lengths
// √(D² − (R_a − R_b)²) there, and their frequencies scale as the moving string's 1/L and the
// chain's sin(π p / 2L); the span that does not touch the idler is unchanged; the start
// layout's fields are those of before.
TEST(DynamicsTakeupCli, SettledSpanFrequenciesUseTheMeanCentre) {
  const nlohmann::json j = dynamics_json(kExample, " --duration 0.6s");
  const auto time = series(j["time"]);
  const double from = j["summary"]["window_start"], to = j["summary"]["window_end"];
  const double slide = mean_over(time, series(j["takeup"][0]["position"]), from, to);
  const double r0 = radius(12), r1 = radius(18), r2 = radius(15), iy = -0.175 - slide;
  const double settled[3] = {std::sqrt(0.15 * 0.15 + iy * iy - (r0 - r2) * (r0 - r2)),
                             std::sqrt(0.15 * 0.15 + iy * iy - (r2 - r1) * (r2 - r1)),
                             std::sqrt(0.3 * 0.3 - (r1 - r0) * (r1 - r0))};
  const double start[3] = {std::sqrt(0.15 * 0.15 + 0.175 * 0.175 - (r0 - r2) * (r0 - r2)),
                           std::sqrt(0.15 * 0.15 + 0.175 * 0.175 - (r2 - r1) * (r2 - r1)),
                           settled[2]};
  for (int k = 0; k < 3; ++k) {
    const auto& s = j["summary"]["span_" + std::to_string(k)];
    EXPECT_NEAR(s["settled_length"].get<double>(), settled[k], 1e-9) << k;
    const double ft = s["transverse_frequency"], fts = s["settled_transverse_frequency"];
    EXPECT_NEAR(fts, ft * start[k] / settled[k], 1e-9 * ft) << k;
    const double fl = s["longitudinal_frequency"], fls = s["settled_longitudinal_frequency"];
    EXPECT_NEAR(
        fls,
        fl * std::sin(kPi * kPitch / (2 * settled[k])) / std::sin(kPi * kPitch / (2 * start[k])),
        1e-9 * fl)
        << k;
    if (k < 2) {
      EXPECT_LT(fts, ft);  // the idler moved out: its spans are longer
    }
  }
  EXPECT_EQ(j["units"]["settled_length"], "m");
  EXPECT_EQ(j["units"]["settled_transverse_frequency"], "Hz");
}

// The take-up with the seats' discrete gradient (docs/models/dynamics.md, "Sprockets: the
// discrete gradient"): the example undamped (links, seats, slide) at θ = ½ over 0.1 s, where a
// roller's gap is taken relative to the sliding centre. With discrete_gradient = true all 1000
// steps converge and the work balance's numerical part stays below 1e-6 J (the chain's kinetic
// energy q L v²/2 is about 0.2 J: 1.25 kg/m, 1.6 m at 0.48 m/s);
// with the θ point's force the contacts gain energy from the first contact (step 6) until Newton
// fails (measured: at step 66, which stopped the run before failed steps were retaken as
// half-steps; with the retakes it went on to 1000 steps and +3.3e6 J in its numerical term). The
// guard on energy from nothing (docs/models/dynamics.md, "Integrator: the guard on energy from
// nothing") stops it at its first check past twice the energy the run has received (step 27 per
// step; the sample at step 30, t = 3 ms: +4.82 J against 1.24 J), the error's value the summary's
// numerical term.
TEST(DynamicsTakeupCli, DiscreteGradientKeepsTheUndampedBalanceAtThetaHalf) {
  const std::string text = undamped_at_theta_half();
  const std::string gradient = replaced(text, "theta", "theta = 0.5\ndiscrete_gradient = true");
  const nlohmann::json kept = dynamics_json(write("dg_half.toml", gradient), " --duration 0.1s");
  const nlohmann::json plain = dynamics_json(write("half.toml", text), " --duration 0.1s");
  ASSERT_TRUE(kept.contains("summary"));
  ASSERT_TRUE(plain.contains("summary"));
  const auto& wk = kept["summary"]["work_balance"];
  const double input = wk["input"], numerical = wk["numerical"];
  std::printf(
      "take-up at theta = 1/2: numerical work %.3g J of the input %.4g J with the discrete "
      "gradient (%d steps); without it %d steps\n",
      numerical, input, kept["summary"]["steps"].get<int>(), plain["summary"]["steps"].get<int>());
  EXPECT_EQ(kept["summary"]["steps"], 1000);
  EXPECT_FALSE(has_code(kept, "dynamics.not_converged")) << kept["diagnostics"].dump();
  EXPECT_LT(std::abs(numerical), 1e-6);
  EXPECT_FALSE(has_code(kept, "dynamics.energy_gain")) << kept["diagnostics"].dump();
  EXPECT_EQ(plain["summary"]["steps"], 30) << plain["diagnostics"].dump();
  EXPECT_FALSE(has_code(plain, "dynamics.steps_retaken")) << plain["diagnostics"].dump();
  int gains = 0;
  for (const auto& d : plain["diagnostics"]) {
    if (d["code"] != "dynamics.energy_gain") continue;
    ++gains;
    EXPECT_EQ(d["severity"], "error");
    EXPECT_EQ(d["value"].get<double>(),
              plain["summary"]["work_balance"]["numerical"].get<double>());
    // twice the received: the start's kinetic and elastic energy (1.02 J) and the potential
    // released (the work put in is negative here)
    EXPECT_GT(d["limit"].get<double>(), 1.0) << d.dump();
    EXPECT_GT(d["value"].get<double>(), d["limit"].get<double>()) << d.dump();
    const std::string m = d["message"].get<std::string>();
    for (const char* part :
         {"step 30 (t = 0.003 s): the work balance's numerical term, energy gained from nothing, "
          "is ",
          " J, more than twice the ",
          " J the run has received (the start's kinetic and elastic energy 1.019 J, the potential "
          "energy released ",
          "the loop's kinetic energy is ",
          "stopped there (try theta nearer 1, a smaller step, or discrete_gradient = true)"})
      EXPECT_NE(m.find(part), std::string::npos) << part << "\n" << m;
  }
  EXPECT_EQ(gains, 1) << plain["diagnostics"].dump();
}

// The guard also checks the run's last step when it is not a sample's: the same diverging run to
// 2.8 ms (28 steps, samples every 10) stops there, past twice the energy it has received since
// step 27 (2.83 times it at step 28).
TEST(DynamicsTakeupCli, EnergyGainIsCheckedAtTheLastStepToo) {
  const std::string text = undamped_at_theta_half();
  const nlohmann::json j = dynamics_json(write("half_end.toml", text), " --duration 2.8ms");
  ASSERT_TRUE(j.contains("summary"));
  EXPECT_EQ(j["summary"]["steps"], 28);
  EXPECT_TRUE(has_code(j, "dynamics.energy_gain")) << j["diagnostics"].dump();
}

// The take-ups' watch runs on every sub-step of a step taken as sub-steps (docs/models/
// dynamics.md, "Integrator: a failed step retaken as half-steps"): the stick-law take-up to 3 ms
// with takeup_travel_max = 0.0002 mm, which the slide passes within step 1 (it is at 0.00212 mm
// at the step's end), taken as sub-steps of 25 µs: the end stop is reached at the second
// sub-step's end, t = 50 µs, not at the grid's 0.1 ms (the time the watch of the step's last
// sub-step alone named), and the time held counts each sub-step's share (3 ms less the first
// sub-step: 2.975 ms, where whole steps alone count 3 ms). The deepest the slide goes past the
// end, 6.43e-06 m, is reached within an earlier sub-step of a step and comes partly back by its
// end: the watch of the last sub-step alone saw 6.35e-06 m.
TEST(DynamicsTakeupCli, EndStopIsWatchedAtEverySubStep) {
  const nlohmann::json j = dynamics_json(
      write("stick_stop.toml", stick_law_takeup("3 ms", "takeup_travel_max = \"0.0002 mm\"\n")));
  ASSERT_TRUE(j.contains("summary"));
  EXPECT_EQ(j["summary"]["steps"], 30);
  bool retaken = false;
  int stops = 0;
  for (const auto& d : j["diagnostics"]) {
    if (d["code"] == "dynamics.steps_retaken")
      retaken = d["message"].get<std::string>().find("the first at step 1 ") != std::string::npos;
    if (d["code"] != "dynamics.takeup_at_travel_end") continue;
    ++stops;
    EXPECT_NEAR(d["value"].get<double>(), 50e-6, 1e-15) << d.dump();
    const std::string m = d["message"];
    for (const char* part :
         {"takeup_travel_max = 2e-07 m at t = 5e-05 s", "held the slide for 0.002975 s in all",
          "at most 6.43e-06 m past the end"})
      EXPECT_NE(m.find(part), std::string::npos) << part << "\n" << m;
  }
  EXPECT_TRUE(retaken) << j["diagnostics"].dump();
  EXPECT_EQ(stops, 1) << j["diagnostics"].dump();
}

// After a retake the run goes on at the sub-step that converged (docs/models/dynamics.md,
// "Integrator: the sub-step size kept"): the stick-law take-up to 20 ms, whose first steps need
// sub-steps, retook 11 grid steps with 12 failed solves going back to h after each retake
// (measured with the size not kept); it now retakes fewer and fails fewer solves in all (4 and 5
// measured; it takes more sub-step solves, 58 against 24), as its warning counts. Its result
// stays within the step's convergence: its wheels' speeds and the spans' tensions differ from a
// run at h/4 by at most 4 times what the run at h/2 does (a first-order method: 3 times; 2.7
// measured on a wheel's speed, 2.5 on a span).
TEST(DynamicsTakeupCli, SubStepSizeIsKeptAfterARetake) {
  const std::string text = stick_law_takeup("20 ms");
  const nlohmann::json j = dynamics_json(write("stick_20ms.toml", text));
  const nlohmann::json half =
      dynamics_json(write("stick_half.toml", replaced(text, "step", "step = \"0.05 ms\"")));
  const nlohmann::json fine =
      dynamics_json(write("stick_fine.toml", replaced(text, "step", "step = \"0.025 ms\"")));
  ASSERT_TRUE(j.contains("summary") && half.contains("summary") && fine.contains("summary"));
  EXPECT_EQ(j["summary"]["steps"], 200);
  int warned = 0;
  for (const auto& d : j["diagnostics"]) {
    if (d["code"] != "dynamics.steps_retaken") continue;
    ++warned;
    const std::string m = d["message"];
    const long retaken = count_before(m, " steps of step = 0.1 ms");
    const long failed = count_before(m, " failed solves in all");
    EXPECT_GT(retaken, 0) << m;
    EXPECT_LT(retaken, 11) << m;
    EXPECT_GE(failed, retaken) << m;
    EXPECT_LT(failed, 11) << m;
    EXPECT_GT(count_before(m, " more steps taken as sub-steps"), 0) << m;
    EXPECT_GT(count_before(m, " sub-step solves"), 0) << m;
  }
  EXPECT_EQ(warned, 1) << j["diagnostics"].dump();
  // the three runs sample every 0.1 ms: the same times
  const std::size_t samples = j["time"].size();
  ASSERT_EQ(half["time"].size(), samples);
  ASSERT_EQ(fine["time"].size(), samples);
  // a series' largest difference from the fine run's
  auto off = [&](const nlohmann::json& a, const char* list, std::size_t i, const char* key) {
    double most = 0.0;
    for (std::size_t k = 0; k < samples; ++k)
      most = std::max(
          most, std::abs(a[list][i][key][k].get<double>() - fine[list][i][key][k].get<double>()));
    return most;
  };
  for (std::size_t w = 0; w < j["sprocket"].size(); ++w)
    EXPECT_LE(off(j, "sprocket", w, "speed"), 4.0 * off(half, "sprocket", w, "speed")) << w;
  for (std::size_t s = 0; s < j["span"].size(); ++s)
    EXPECT_LE(off(j, "span", s, "tension"), 4.0 * off(half, "span", s, "tension")) << s;
}

// The lost-chain watch on every sub-step too: the stick-law take-up to 3 ms with
// takeup_lost_force = 500 N and takeup_lost_time = 0 (every stretch counted). The chain's force
// on the idler rises past 500 N within an earlier sub-step of step 7 only and is back under it at
// the step's end: the watch of each step's last sub-step alone saw one stretch from the start,
// 1.5 ms long (checked); watched per sub-step there are 3, the first 0.6 ms, the longest 0.65 ms
// (a sub-step's boundary, off the grid).
TEST(DynamicsTakeupCli, LostChainIsWatchedAtEverySubStep) {
  const nlohmann::json j = dynamics_json(write(
      "stick_lost.toml",
      stick_law_takeup("3 ms", "takeup_lost_force = \"500 N\"\ntakeup_lost_time = \"0 s\"\n")));
  const nlohmann::json lost = lost_chain(j);
  ASSERT_FALSE(lost.is_null()) << j["diagnostics"].dump();
  EXPECT_EQ(lost["value"].get<double>(), 0.0);
  const std::string m = lost["message"];
  EXPECT_NE(m.find("at most 500 N) for longer than 0 ms 3 time(s), first at t = 0 s for 0.0006 s, "
                   "the longest 0.00065 s"),
            std::string::npos)
      << m;
}
