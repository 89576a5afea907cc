// The dynamics command's boundary (issue 21): a run too short to measure a span's natural
// frequencies says so itself (null frequencies and a warning naming `duration` and the shortest
// run that measures them) instead of NaN blamed on the input's range, and an error diagnostic
// is named on stderr by `catena run` as by the subcommand, the exit status staying 0 (the
// analysis ran; docs/cli.md). Values at which the steps stop converging (a stiffness, a damping,
// a speed, a load or an inertia far outside the chain's scales) are refused before anything runs,
// each named with its range (docs/models/dynamics.md, "The inputs' bounds").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../read_text.hpp"
#include "case_text.hpp"
#include "cli_run.hpp"
#include "lead_in_loop.hpp"

namespace {

const std::string kExamples = CATENA_EXAMPLES_DIR;

// The 12B example with each `key = ...` line set to `value` (a key it does not have goes first in
// [dynamics]), written to `dir`/`name`.
std::string example_with(const std::filesystem::path& dir, const std::string& name,
                         const std::vector<std::pair<std::string, std::string>>& values) {
  std::string text = read_text(kExamples + "/dynamics_12B.toml");
  for (const auto& [key, value] : values) {
    const std::regex line("(^|\n)" + key + " *=[^\n]*");
    if (std::regex_search(text, line))
      text = std::regex_replace(text, line, "$1" + key + " = " + value);
    else
      text = with_dynamics_key(text, key + " = " + value);
  }
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

// A run meant to be clean: no step failed (a failed step is retaken as half-steps and ends with
// dynamics.not_converged only at step/16, so its absence alone no longer says none failed), no
// bare end struck and no energy from nothing (docs/models/dynamics.md, "Integrator: a failed step
// retaken as half-steps", "Integrator: the guard on energy from nothing"). Names every one found.
::testing::AssertionResult ran_clean(const std::string& out) {
  std::string found;
  for (const char* code : {"dynamics.not_converged", "dynamics.bare_rail_end",
                           "dynamics.steps_retaken", "dynamics.energy_gain"})
    if (out.find(code) != std::string::npos) found += std::string(found.empty() ? "" : " ") + code;
  if (found.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << found;
}

// The issue's reproducer: 1 ms of the serpentine drive (its second half shorter than a tooth
// period): the intermediate span is still in compression from the start.
TEST(DynamicsBoundaryCli, AShortRunNamesDurationAndTheShortestRunForSpanFrequencies) {
  const CliRun r =
      run("dynamics " + kExamples + "/dynamics_serpentine.toml --duration 1ms --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("outside the range"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& span = j.at("summary").at("span_1");
  EXPECT_LT(span.at("mean_tension").get<double>(), 0.0);
  // the fields are kept (a sweep's columns), null: absent, not a failed computation
  for (const char* key : {"transverse_frequency", "longitudinal_frequency",
                          "settled_transverse_frequency", "settled_longitudinal_frequency"}) {
    ASSERT_TRUE(span.contains(key)) << key;
    EXPECT_TRUE(span.at(key).is_null()) << key;
  }
  bool named = false;
  for (const auto& d : j.at("diagnostics")) {
    EXPECT_NE(d.at("code"), "result.non_finite") << d.dump();
    if (d.at("code") != "dynamics.span_frequencies_unmeasured") continue;
    named = true;
    const std::string m = d.at("message");
    EXPECT_NE(m.find("span 1"), std::string::npos) << m;
    EXPECT_NE(m.find("0.001 s (dynamics.duration)"), std::string::npos) << m;
    // two tooth periods of the driver (z 12 at 13 rad/s: T = 40.28 ms), in whole 1 ms samples
    EXPECT_NE(m.find("at least 0.081 s"), std::string::npos) << m;
    EXPECT_DOUBLE_EQ(d.at("value").get<double>(), 1e-3);
    EXPECT_NEAR(d.at("limit").get<double>(), 0.081, 1e-12);
  }
  EXPECT_TRUE(named) << j.at("diagnostics").dump();
  // the shortest run it names measures them: every span's frequencies are numbers, no warning
  const CliRun at =
      run("dynamics " + kExamples + "/dynamics_serpentine.toml --duration 81ms --format json");
  ASSERT_EQ(at.status, 0) << at.err;
  const auto k = nlohmann::json::parse(at.out);
  for (const char* s : {"span_0", "span_1", "span_2"}) {
    EXPECT_GT(k.at("summary").at(s).at("transverse_frequency").get<double>(), 0.0) << s;
    EXPECT_GT(k.at("summary").at(s).at("longitudinal_frequency").get<double>(), 0.0) << s;
  }
  EXPECT_TRUE(k.at("diagnostics").empty()) << k.at("diagnostics").dump();
}

// Every dynamics example down to one step, through `catena dynamics` (json, csv, table) and
// `catena run`: exit 0, no error on stderr, no non-finite result, every summary scalar a
// number or null, and the summary's keys those of the example's own run (no field dropped).
TEST(DynamicsBoundaryCli, EveryExampleDownToOneStepGivesNoNonFiniteResult) {
  const std::regex duration_line("(^|\n)duration *=[^\n]*");
  const std::regex step_line("(^|\n)step *= *\"([^\"]*)\"");
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kExamples)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("dynamics_", 0) != 0 || entry.path().extension() != ".toml") continue;
    const std::string text = read_text(entry.path().string());
    std::smatch step;
    ASSERT_TRUE(std::regex_search(text, step, step_line)) << name;
    const std::string one_step = step[2];
    // the summary's keys of a run of 0.2 s (the longer runs hold the same keys)
    const CliRun full = run("dynamics " + entry.path().string() + " --duration 0.2s --format json");
    ASSERT_EQ(full.status, 0) << name << full.err;
    const auto reference = nlohmann::json::parse(full.out).at("summary");
    for (const std::string& duration : {one_step, std::string("1ms"), std::string("5ms")}) {
      const std::string args =
          "dynamics " + entry.path().string() + " --duration \"" + duration + "\" --format ";
      const CliRun r = run(args + "json");
      ASSERT_EQ(r.status, 0) << name << " " << duration << "\n" << r.err;
      EXPECT_EQ(r.err.find("error"), std::string::npos) << name << " " << duration << r.err;
      const auto j = nlohmann::json::parse(r.out);
      for (const auto& d : j.at("diagnostics"))
        EXPECT_NE(d.at("code"), "result.non_finite") << name << " " << duration << d.dump();
      const auto& summary = j.at("summary");
      for (auto it = reference.begin(); it != reference.end(); ++it) {
        ASSERT_TRUE(summary.contains(it.key())) << name << " " << duration << " " << it.key();
        if (!it.value().is_object()) continue;
        for (auto f = it.value().begin(); f != it.value().end(); ++f) {
          ASSERT_TRUE(summary.at(it.key()).contains(f.key()))
              << name << " " << it.key() << "." << f.key();
          const auto& v = summary.at(it.key()).at(f.key());
          EXPECT_TRUE(v.is_number() || v.is_null()) << name << " " << it.key() << "." << f.key();
        }
      }
      for (const char* format : {"csv", "table"}) {
        const CliRun t = run(args + format);
        EXPECT_EQ(t.status, 0) << name << " " << duration << " " << format << "\n" << t.err;
        EXPECT_EQ(t.err.find("error"), std::string::npos) << name << " " << format << t.err;
        EXPECT_FALSE(t.out.empty()) << name << " " << format;
      }
      ++checked;
    }
    // `catena run` on the example with its duration set to one step
    const auto dir =
        std::filesystem::temp_directory_path() / ("catena_boundary_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << std::regex_replace(text, duration_line,
                                              "$1duration = \"" + one_step + "\"");
    const CliRun c = run("run " + path);
    std::filesystem::remove_all(dir);
    ASSERT_EQ(c.status, 0) << name << "\n" << c.err;
    EXPECT_EQ(c.err.find("error"), std::string::npos) << name << c.err;
    EXPECT_EQ(c.out.find("result.non_finite"), std::string::npos) << name;
  }
  EXPECT_GE(checked, 18);  // six examples, three durations
}

// A lead-in's radius is bounded by the chain: its arc's chord 2 R sin(α/2) at most half the
// chain's length N p/2 (a closed loop spans no longer chord). 1e6 m ran into "did not converge";
// it is refused naming the field and its range, with the rail's other problems at once, and a
// radius just inside the bound is not refused by it.
TEST(DynamicsBoundaryCli, ALeadInRadiusIsBoundedByTheChainsLength) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_lead_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& radius, const std::string& more) {
    const std::string path = (dir / name).string();
    std::ofstream(path) << kLeadInLoopHead
                        << lead_in_rail("30 mm", "lead_in_radius = \"" + radius + "\"\n" + more);
    return path;
  };
  // N p = 32 × 19.05 mm = 0.6096 m: at 30 deg R <= 0.6096 / (4 sin 15 deg) = 0.5888 m
  const CliRun huge = run("dynamics " + write("huge.toml", "1e6 m", "friction = 2\n"));
  EXPECT_EQ(huge.status, 2) << huge.err;
  EXPECT_TRUE(huge.out.empty());
  EXPECT_NE(huge.err.find("dynamics.guide[0].lead_in_radius (line 24)"), std::string::npos)
      << huge.err;
  EXPECT_NE(huge.err.find("0 < R <= 0.5888 m at lead_in_angle 30 deg"), std::string::npos)
      << huge.err;
  EXPECT_NE(huge.err.find("N p/2 = 0.3048 m"), std::string::npos) << huge.err;
  EXPECT_NE(huge.err.find("dynamics.guide[0].friction"), std::string::npos) << huge.err;
  // the bound follows the sweep: at 90 deg R <= 0.6096 / (4 sin 45 deg) = 0.2155 m
  const CliRun wide =
      run("dynamics " + write("wide.toml", "0.25 m", "lead_in_angle = \"90 deg\"\n"));
  EXPECT_EQ(wide.status, 2) << wide.err;
  EXPECT_NE(wide.err.find("0 < R <= 0.2155 m at lead_in_angle 90 deg"), std::string::npos)
      << wide.err;
  // inside the bound: not refused by it. The bound is necessary, not sufficient: 0.58 m is
  // refused by the arcs' clearance of the chain's path instead (next test); 0.1 m runs through.
  for (const char* inside : {"0.58 m", "0.1 m"}) {
    const CliRun ok = run("dynamics " + write("inside.toml", inside, "") + " --format json");
    EXPECT_EQ(ok.err.find("N p/2"), std::string::npos) << inside << "\n" << ok.err;
    EXPECT_EQ(ok.status, std::string(inside) == "0.1 m" ? 0 : 2) << inside << "\n" << ok.err;
    if (ok.status == 0) {
      EXPECT_TRUE(ran_clean(ok.out));
    }
  }
  const CliRun over = run("dynamics " + write("over.toml", "0.6 m", ""));
  EXPECT_EQ(over.status, 2) << over.err;
  EXPECT_NE(over.err.find("dynamics.guide[0].lead_in_radius"), std::string::npos) << over.err;
  std::filesystem::remove_all(dir);
}

// A lead-in's arcs must clear the chain's path round the wheels and the other guides by a roller
// radius (docs/models/dynamics.md, "Lead-ins"). On this loop (a rail 30 mm high from 30 to 150 mm,
// the wheels at x = 0 and 190.5 mm) the start's arc, bending down towards sprocket[0], reaches the
// chain wrapped on it beyond 0.114 m at 30 deg, the end's arc sprocket[1]'s beyond
// 0.138 m. Before the check 0.12-0.58 m were accepted and stopped with "did not converge" (0.12 m
// at step 5, 0.15 m at step 239 of 0.1 s) while 0.1 and 0.11 m (start) and 0.13 m (end) ran 0.1 s.
// Each radius there is refused naming what its arcs run into and the largest radius (and sweep)
// that clears; the radius named is accepted and runs 5 ms without error, one 1 % above it is
// refused; a guide in the arc's way is named too.
TEST(DynamicsBoundaryCli, ALeadInMustClearTheChainsPathAndTheOtherGuides) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_clear_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& lead, const std::string& more) {
    const std::string path = (dir / name).string();
    std::ofstream(path) << std::regex_replace(kLeadInLoopHead, std::regex("0.002 s"), "5 ms")
                        << lead_in_rail("30 mm", lead) << more;
    return path;
  };
  double named = NAN;
  for (const char* radius : {"0.3 m", "0.58 m", "0.12 m"}) {
    const CliRun r = run(
        "dynamics " + write("cut.toml", "lead_in_radius = \"" + std::string(radius) + "\"\n", ""));
    EXPECT_EQ(r.status, 2) << radius << "\n" << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find("dynamics.guide[0].lead_in_radius (line 24)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the lead-in at the start of guide[0] would run into the chain on "
                         "sprocket[0]"),
              std::string::npos)
        << r.err;
    const double most = named_after(r.err, "0 < R <= ");
    EXPECT_LT(most, std::stod(radius)) << r.err;
    if (std::isnan(named)) named = most;
    EXPECT_EQ(most, named)
        << radius;  // the radius at the sweep does not depend on the radius given
  }
  EXPECT_NEAR(named, 0.114, 0.001);  // 0.1140 m (the bisection's limit, rounded down)
  // at 0.3 m the end's arc reaches sprocket[1]'s chain too: both named at once
  const CliRun both = run("dynamics " + write("both.toml", "lead_in_radius = \"0.3 m\"\n", ""));
  EXPECT_NE(both.err.find("the lead-in at the end of guide[0] would run into the chain on "
                          "sprocket[1]"),
            std::string::npos)
      << both.err;
  // the radius named runs; 1 % more is refused (the limit is found, not a round guess)
  std::ostringstream at_limit, above;
  at_limit << "lead_in_radius = \"" << named << " m\"\n";
  above << "lead_in_radius = \"" << named * 1.01 << " m\"\n";
  const CliRun ok = run("dynamics " + write("limit.toml", at_limit.str(), "") + " --format json");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(ok.err.find("error"), std::string::npos) << ok.err;
  EXPECT_TRUE(ran_clean(ok.out));
  EXPECT_EQ(run("dynamics " + write("above.toml", above.str(), "")).status, 2);
  // the sweep named at the radius given clears too
  const double sweep = named_after(both.err, "lead_in_angle <= ");
  EXPECT_GT(sweep, 0.1);
  EXPECT_LT(sweep, 30.0);
  std::ostringstream shorter;
  shorter << "lead_in_radius = \"0.3 m\"\nlead_in_angle = \"" << sweep << " deg\"\n";
  const CliRun swept = run("dynamics " + write("sweep.toml", shorter.str(), ""));
  EXPECT_EQ(swept.status, 0) << swept.err;
  EXPECT_EQ(swept.err.find("lead_in_radius"), std::string::npos) << swept.err;
  // only the end's arc: its own, larger limit (0.138 m), naming only sprocket[1]
  const CliRun end = run(
      "dynamics " + write("end.toml", "lead_in_radius = \"0.3 m\"\nlead_in_end = \"end\"\n", ""));
  EXPECT_EQ(end.status, 2);
  EXPECT_EQ(end.err.find("sprocket[0]"), std::string::npos) << end.err;
  EXPECT_NE(end.err.find("sprocket[1]"), std::string::npos) << end.err;
  EXPECT_NEAR(named_after(end.err, "0 < R <= "), 0.138, 0.001) << end.err;
  // a guide in the start's arc's way (a post 15 mm from the wheel's centre line, its top 8 mm
  // under the rail's surface): a 50 mm lead-in, clear of the chain, runs into it
  const std::string post =
      "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"15 mm\"\ny0 = \"10 mm\"\nx1 = \"15 mm\"\n"
      "y1 = \"22 mm\"\n";
  const CliRun blocked =
      run("dynamics " +
          write("post.toml", "lead_in_radius = \"50 mm\"\nlead_in_end = \"start\"\n", post));
  EXPECT_EQ(blocked.status, 2) << blocked.err;
  EXPECT_NE(blocked.err.find("the lead-in at the start of guide[0] would run into guide[1]"),
            std::string::npos)
      << blocked.err;
  EXPECT_LT(named_after(blocked.err, "0 < R <= "), 0.05) << blocked.err;
  // without the post the same lead-in is accepted
  EXPECT_EQ(run("dynamics " +
                write("nopost.toml", "lead_in_radius = \"50 mm\"\nlead_in_end = \"start\"\n", ""))
                .status,
            0);
  std::filesystem::remove_all(dir);
}

// A rail that runs to a wheel's tangent point: 30.8 mm high from x = 30 mm to sprocket[1]'s centre
// line (190.5 mm), its end 6.0 mm from the chain wrapped there, closer than a roller radius
// (6.035 mm). Its lead-in may come no closer to that wrap than the rail's end already is: a 20 mm
// arc bends away from it (inside the wheel's pitch circle) and is accepted and runs 5 ms without
// error (it was refused, "no lead-in radius", when every arc had to keep a roller radius off the
// wrap); a 0.1 m arc, flatter than the pitch circle, closes in on the wrap and is still refused.
TEST(DynamicsBoundaryCli, ALeadInAtARailRunningToTheTangentPointMayNotCloseInOnTheWrap) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_tangent_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& radius) {
    const std::string path = (dir / name).string();
    std::ofstream(path) << std::regex_replace(kLeadInLoopHead, std::regex("0.002 s"), "5 ms")
                        << "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"30 mm\"\n"
                           "y0 = \"30.8 mm\"\nx1 = \"190.5 mm\"\ny1 = \"30.8 mm\"\n"
                           "lead_in_radius = \""
                        << radius << "\"\nlead_in_end = \"end\"\n";
    return path;
  };
  const CliRun ok = run("dynamics " + write("away.toml", "20 mm") + " --format json");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(ok.err.find("lead_in_radius"), std::string::npos) << ok.err;
  EXPECT_EQ(ok.out.find("\"error\""), std::string::npos) << ok.out;
  EXPECT_TRUE(ran_clean(ok.out));
  const CliRun in = run("dynamics " + write("in.toml", "0.1 m"));
  EXPECT_EQ(in.status, 2) << in.err;
  EXPECT_NE(in.err.find("the lead-in at the end of guide[0] would run into the chain on "
                        "sprocket[1]"),
            std::string::npos)
      << in.err;
  std::filesystem::remove_all(dir);
}

// The lead-in check's work is bounded: 100 rails laid on top of one another, each with 20 mm
// lead-ins at both ends, would have every arc measured against every other guide and bisected
// (200 arcs x 513 samples x the 199 other guides and the wrap x 43 passes, a bound of 8.78e8
// distances): refused at once naming dynamics.guide and the cap, before any of it is measured.
TEST(DynamicsBoundaryCli, TheLeadInChecksWorkIsCapped) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_leadwork_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "stack.toml").string();
  {
    std::ofstream f(path);
    f << kLeadInLoopHead;
    for (int i = 0; i < 100; ++i) f << lead_in_rail("30 mm", "lead_in_radius = \"20 mm\"\n");
  }
  const CliRun r = run("dynamics " + path);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("dynamics.guide"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("200 lead-in arcs"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("distances to check"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at most 5e+08"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

// The extremes that ran into "did not converge" (an error diagnostic, exit 0) are refused up front
// (exit 2), each naming its field, the value and the range with the keys the range follows from.
// The 12B example: m = 1.244 kg/m x 19.05 mm = 0.0237 kg, theta step = 0.06 ms, R = 36.80 mm
// (M R^2 = 3.896e-4 kg m^2, M = 1.244 kg/m x 2 pi R the chain on one round of the wheel). The
// limits named are rounded inwards (an upper one down, a lower one up).
TEST(DynamicsBoundaryCli, ExtremeScalesAreRefusedNamingTheFieldAndItsRange) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_scales_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  struct Case {
    std::string key, value, field, range;
  };
  const std::vector<Case> cases{
      {"axial_stiffness", "\"1e300 N/m\"", "dynamics.axial_stiffness (line 15) = 1e+300 N/m",
       "at most 1e+06 m/(theta step)^2 = 6.582e+12 N/m, m = mass_per_metre x pitch = 0.0237 kg, "
       "theta 0.6, step 0.0001 s"},
      {"axial_damping", "1e12", "dynamics.axial_damping (line 16) = 1e+12 N s/m",
       "at most 1e+06 m/(theta step) = 3.949e+08 N s/m"},
      {"axial_damping", "1e300", "dynamics.axial_damping (line 16) = 1e+300 N s/m",
       "= 3.949e+08 N s/m"},
      {"contact_stiffness", "\"1e300 N/m\"", "dynamics.contact_stiffness (line 18) = 1e+300 N/m",
       "at most 5e+05 m/(theta step)^2 = 3.291e+12 N/m"},
      {"contact_damping", "1e12", "dynamics.contact_damping (line 19) = 1e+12 N s/m",
       "at most 5e+03 m/(theta step) = 1.974e+06 N s/m"},
      {"speed", "\"1e4 rad/s\"", "dynamics.sprocket[0].speed (line 28) = 10000 rad/s",
       "at most 1294 rad/s at step 0.0001 s, or a step of at most 1.294e-05 s at this speed"},
      {"speed", "\"1e300 rad/s\"", "dynamics.sprocket[0].speed (line 28) = 1e+300 rad/s",
       "at most 1294 rad/s"},
      {"inertia", "1e300", "dynamics.sprocket[1].inertia (line 33) = 1e+300 kg m^2",
       "in [3.896e-07, 389.5] kg m^2: 0.001 to 1e+06 times the chain's own about the wheel"},
      {"inertia", "1e-300", "dynamics.sprocket[1].inertia (line 33) = 1e-300 kg m^2",
       "in [3.896e-07, 389.5] kg m^2"},
      {"load_torque", "1e6", "dynamics.sprocket[1].load_torque (line 34) = 1e+06 N m",
       "at most 0.1 axial_stiffness x pitch x R = 3505 N m"},
      {"load_torque", "1e300", "dynamics.sprocket[1].load_torque (line 34) = 1e+300 N m",
       "= 3505 N m"},
      {"mass_per_metre", "\"1e300 kg/m\"", "dynamics.mass_per_metre (line 13) = 1e+300 kg/m",
       "in (0, 10000] kg/m"},
  };
  for (const Case& c : cases) {
    const CliRun r = run("dynamics " + example_with(dir, "extreme.toml", {{c.key, c.value}}));
    EXPECT_EQ(r.status, 2) << c.key << " " << c.value << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.key;
    EXPECT_NE(r.err.find(c.field + ": expected "), std::string::npos) << c.value << "\n" << r.err;
    EXPECT_NE(r.err.find(c.range), std::string::npos) << c.value << "\n" << r.err;
  }
  // a round-link chain on pocket wheels: a fortieth of a pitch a step (with the tension-only
  // links, 450 rad/s ran 20 ms on examples/dynamics_pocketwheel.toml at 0.1 ms, 500 rad/s stopped
  // at 15.4 ms; at 0.05 ms 650 ran, 700 stopped at 11.1 ms)
  {
    std::string text = read_text(kExamples + "/dynamics_pocketwheel.toml");
    text = std::regex_replace(text, std::regex("(^|\n)speed *=[^\n]*"), "$1speed = \"200 rad/s\"");
    const std::string pocket = (dir / "pocket.toml").string();
    std::ofstream(pocket) << text;
  }
  const CliRun p = run("dynamics " + (dir / "pocket.toml").string());
  EXPECT_EQ(p.status, 2) << p.err;
  EXPECT_NE(p.err.find("= 200 rad/s: expected at most 97.39 rad/s at step 0.0001 s"),
            std::string::npos)
      << p.err;
  EXPECT_NE(p.err.find("a fortieth of a pitch a step on pocket wheels"), std::string::npos)
      << p.err;
  // a guide's own penalty and damper: the seats' bounds
  const std::string rail = (dir / "rail.toml").string();
  std::ofstream(rail) << kLeadInLoopHead
                      << lead_in_rail(
                             "30 mm",
                             "contact_stiffness = \"1e300 N/m\"\ncontact_damping = 1e12\n");
  const CliRun g = run("dynamics " + rail);
  EXPECT_EQ(g.status, 2) << g.err;
  EXPECT_NE(g.err.find("dynamics.guide[0].contact_stiffness (line 24) = 1e+300 N/m: expected at "
                       "most 5e+05 m/(theta step)^2 = 3.291e+12 N/m"),
            std::string::npos)
      << g.err;
  EXPECT_NE(g.err.find("dynamics.guide[0].contact_damping (line 25) = 1e+12 N s/m: expected at "
                       "most 5e+03 m/(theta step) = 1.974e+06 N s/m"),
            std::string::npos)
      << g.err;
  // a step too short for the inertia terms, from the case file (named with its line) and from the
  // command line (--step named as such)
  const CliRun tiny_case =
      run("dynamics " +
          example_with(dir, "tiny.toml", {{"step", "\"1e-12 s\""}, {"duration", "\"1e-11 s\""}}) +
          " --allow-large");
  EXPECT_EQ(tiny_case.status, 2) << tiny_case.err;
  EXPECT_NE(tiny_case.err.find("dynamics.step (line 21) = 1e-12 s: expected at least 1e-09 s"),
            std::string::npos)
      << tiny_case.err;
  const CliRun tiny = run("dynamics " + kExamples +
                          "/dynamics_12B.toml --duration 1e-11s --step 1e-12s --allow-large");
  EXPECT_EQ(tiny.status, 2) << tiny.err;
  EXPECT_NE(tiny.err.find("step = 1e-12 s: expected at least 1e-09 s"), std::string::npos)
      << tiny.err;
  // the bounds follow the step: at 0.01 ms the driver may turn ten times as fast (1e4 rad/s is
  // inside, 2e4 rad/s is not)
  const CliRun fine =
      run("dynamics " + example_with(dir, "fine.toml", {{"speed", "\"1e4 rad/s\""}}) +
          " --duration 0.1ms --step 0.01ms");
  EXPECT_EQ(fine.status, 0) << fine.err;
  EXPECT_EQ(fine.err.find("error"), std::string::npos) << fine.err;  // every step converged
  const CliRun fast =
      run("dynamics " + example_with(dir, "fast.toml", {{"speed", "\"2e4 rad/s\""}}) +
          " --duration 0.1ms --step 0.01ms");
  EXPECT_EQ(fast.status, 2) << fast.err;
  EXPECT_NE(fast.err.find("at most 1.294e+04 rad/s at step 1e-05 s"), std::string::npos)
      << fast.err;
  std::filesystem::remove_all(dir);
}

// Every bad scale in one file is named at once, with the parser's other problems.
TEST(DynamicsBoundaryCli, EveryExtremeScaleInOneFileIsNamedTogether) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_together_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const CliRun r = run("dynamics " + example_with(dir, "all.toml",
                                                  {{"axial_damping", "1e12"},
                                                   {"contact_stiffness", "\"1e300 N/m\""},
                                                   {"contact_damping", "1e12"},
                                                   {"speed", "\"1e4 rad/s\""},
                                                   {"inertia", "1e300"},
                                                   {"load_torque", "1e6"},
                                                   {"pretension", "\"-5 N\""}}));
  std::filesystem::remove_all(dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("(7 problems)"), std::string::npos) << r.err;
  for (const char* field :
       {"dynamics.axial_damping (line 16)", "dynamics.contact_stiffness (line 18)",
        "dynamics.contact_damping (line 19)", "dynamics.pretension (line 17)",
        "dynamics.sprocket[0].speed (line 28)", "dynamics.sprocket[1].inertia (line 33)",
        "dynamics.sprocket[1].load_torque (line 34)"})
    EXPECT_NE(r.err.find(field), std::string::npos) << field << "\n" << r.err;
}

// Just inside each bound the case is not refused (one step runs), and the driver at 1290 rad/s
// (the bound 1294) and the load at 3490 N m (3505) each run 5 ms with every step converged.
TEST(DynamicsBoundaryCli, ScalesJustInsideTheirBoundsRun) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_inside_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::vector<std::pair<std::string, std::string>> inside{
      {"axial_stiffness", "\"6.5e12 N/m\""},
      {"axial_damping", "3.9e8"},
      {"contact_stiffness", "\"3.2e12 N/m\""},
      {"contact_damping", "1.97e6"},
      {"speed", "\"1290 rad/s\""},
      {"inertia", "3.9e-7"},
      {"inertia", "389"},
      {"load_torque", "3490"},
      {"mass_per_metre", "\"1e4 kg/m\""}};
  for (const auto& [key, value] : inside) {
    // (a chain of 1e4 kg/m needs a wheel of its scale)
    std::vector<std::pair<std::string, std::string>> values{{key, value}};
    if (key == "mass_per_metre") values.push_back({"inertia", "1000"});
    const CliRun r = run("dynamics " + example_with(dir, "inside.toml", values) +
                         " --duration 0.1ms --format json");
    EXPECT_EQ(r.status, 0) << key << " " << value << "\n" << r.err;
    EXPECT_EQ(r.err.find("invalid input"), std::string::npos) << key << "\n" << r.err;
  }
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"speed", "\"1290 rad/s\""}, {"load_torque", "3490"}}) {
    const CliRun r = run("dynamics " + example_with(dir, "run.toml", {{key, value}}) +
                         " --duration 5ms --format json");
    EXPECT_EQ(r.status, 0) << key << "\n" << r.err;
    EXPECT_TRUE(ran_clean(r.out)) << key << "\n" << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("summary").at("steps").get<int>(), 50) << key;
  }
  std::filesystem::remove_all(dir);
}

// A wheel's inertia is bounded against the chain it holds, not the loop's: a real z = 12 sprocket
// (J = 2e-4 kg m^2) on a loop of 10 000 links is accepted (the loop's mass set a lower bound of
// 3.2e-4 kg m^2), one step runs; the extremes stay refused.
TEST(DynamicsBoundaryCli, AWheelsInertiaBoundDoesNotGrowWithTheLoop) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_long_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const char* inertia : {"2e-4", "1e-300", "1e300"}) {
    const CliRun r = run(
        "dynamics " + example_with(dir, "long.toml", {{"links", "10000"}, {"inertia", inertia}}) +
        " --duration 0.1ms --allow-large --format json");
    if (std::string(inertia) == "2e-4") {
      EXPECT_EQ(r.status, 0) << r.err;
      EXPECT_EQ(r.err.find("inertia"), std::string::npos) << r.err;
      EXPECT_EQ(nlohmann::json::parse(r.out).at("summary").at("steps").get<int>(), 1);
    } else {
      EXPECT_EQ(r.status, 2) << inertia << "\n" << r.err;
      EXPECT_NE(r.err.find("in [3.896e-07, 389.5] kg m^2"), std::string::npos) << r.err;
    }
  }
  std::filesystem::remove_all(dir);
}

// The contact's bounds catch the absurd, not a smaller chain at a coarser step: a 06B (0.39 kg/m)
// with the 12B example's contact_stiffness 2e8 N/m and contact_damping 800 N s/m runs at 0.5 ms
// and at 1 ms with every step converged (the bounds calibrated at 0.1 ms refused both).
TEST(DynamicsBoundaryCli, ContactBoundsAcceptA06BAtCoarseSteps) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_06B_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const auto& [step, steps] :
       std::vector<std::pair<std::string, int>>{{"\"0.5 ms\"", 10}, {"\"1 ms\"", 5}}) {
    const CliRun r = run("dynamics " +
                         example_with(dir, "06B.toml",
                                      {{"chain", "\"06B\""},
                                       {"mass_per_metre", "\"0.39 kg/m\""},
                                       {"step", step},
                                       {"output_interval", step}}) +
                         " --duration 5ms --format json");
    EXPECT_EQ(r.status, 0) << step << "\n" << r.err;
    EXPECT_EQ(r.err.find("contact_"), std::string::npos) << step << "\n" << r.err;
    EXPECT_TRUE(ran_clean(r.out)) << step;
    if (r.status == 0) {
      EXPECT_EQ(nlohmann::json::parse(r.out).at("summary").at("steps").get<int>(), steps) << step;
    }
  }
  std::filesystem::remove_all(dir);
}

// A limit named is inside: typed back it is accepted. The driver's speed at 0.3 ms (the bound
// 431.37 rad/s, named 431.3, not 431.4) and a wheel's lowest inertia on a chain of 1.2 kg/m (the
// bound 3.7581e-7 kg m^2, named 3.759e-7, not 3.758e-7).
TEST(DynamicsBoundaryCli, TheLimitsNamedAreAcceptedTypedBack) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_named_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string step = " --step 0.3ms --duration 0.3ms --format json";
  const CliRun fast =
      run("dynamics " + example_with(dir, "fast.toml", {{"speed", "431.4"}}) + step);
  ASSERT_EQ(fast.status, 2) << fast.err;
  const double fastest = named_after(fast.err, "expected at most ");
  EXPECT_LT(fastest, 431.4) << fast.err;
  std::ostringstream speed;
  speed << fastest;
  const CliRun back =
      run("dynamics " + example_with(dir, "back.toml", {{"speed", speed.str()}}) + step);
  EXPECT_EQ(back.status, 0) << speed.str() << "\n" << back.err;
  const std::string light = "\"1.2 kg/m\"";
  const CliRun low =
      run("dynamics " +
          example_with(dir, "low.toml", {{"mass_per_metre", light}, {"inertia", "1e-9"}}) +
          " --duration 0.1ms");
  ASSERT_EQ(low.status, 2) << low.err;
  const double least = named_after(low.err, "expected in [");
  EXPECT_GT(least, 3.758e-7) << low.err;
  std::ostringstream inertia;
  inertia << least;
  const CliRun up =
      run("dynamics " +
          example_with(dir, "up.toml", {{"mass_per_metre", light}, {"inertia", inertia.str()}}) +
          " --duration 0.1ms --format json");
  EXPECT_EQ(up.status, 0) << inertia.str() << "\n" << up.err;
  std::filesystem::remove_all(dir);
}

// An error diagnostic is never silent: a run whose step does not converge as a roller strikes a
// rail's bare end (the lead-in loop with the driven wheel on a take-up, as
// ARollerStrikingABareEntryEndIsNamedWithTheLeadIn below: a strike stops the run, with or without
// the half-step retakes, which carry the stiff links' 1e9 N/m at 1 ms this test ran before) names
// it on stderr from `catena dynamics`, `catena run` and `catena report` (by its analysis in a
// case run), the output written in full; the strike at step 462 (t = 0.0462 s). (The plain
// dynamics.not_converged on stderr:
// DynamicsPocketCli.AStepFailingAtTheRetakesFloorEndsTheRunAtItsStart.) The exit status is 0, the
// CLI's contract since issue 2 ("0 whenever the analysis ran, diagnostics part of the output").
TEST(DynamicsBoundaryCli, AnErrorDiagnosticIsNamedOnStderrWithTheOutputWritten) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("catena_boundary_error_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "bare_end.toml").string();
  std::string text =
      "title = \"bare end\"\n[chain]\ntype = \"roller-iso606\"\ndesignation = "
      "\"12B\"\n" +
      kLeadInLoopHead;
  text = std::regex_replace(text, std::regex("speed = \"13 rad/s\"\n"),
                            "speed = \"13 rad/s\"\ncentre_x = \"0 mm\"\ncentre_y = \"0 mm\"\n");
  text = std::regex_replace(text, std::regex("duration = [^\n]*"), "duration = \"0.2 s\"");
  const double R = 0.5 * 19.05 / std::sin(std::numbers::pi / 12.0), roller = 6.035;  // [mm]
  char y[64];
  std::snprintf(y, sizeof y, "%.12f mm", -R + roller - 3.0);
  std::ofstream(path)
      << text
      << "centre_x = \"185 mm\"\ncentre_y = \"0 mm\"\ntakeup_direction = \"0 deg\"\n"
         "takeup_force = \"1000 N\"\ntakeup_travel_max = \"10 mm\"\n"
         "takeup_damping = 3000\n[[dynamics.guide]]\nkind = \"straight\"\n"
         "x0 = \"130 mm\"\ny0 = \""
      << y << "\"\nx1 = \"60 mm\"\ny1 = \"" << y << "\"\n[analyses.dynamics]\n";
  const CliRun d = run("dynamics " + path + " --format json");
  const CliRun c = run("run " + path);
  const std::string html = (dir / "report.html").string();
  const CliRun h = run("report " + path + " -o " + html);
  const bool written = std::filesystem::exists(html) && std::filesystem::file_size(html) > 0;
  std::filesystem::remove_all(dir);
  EXPECT_EQ(d.status, 0) << d.err;
  EXPECT_NE(d.err.find("catena: error: step 462 (t = 0.0462 s) did not converge"),
            std::string::npos)
      << d.err;
  bool listed = false;
  const auto j = nlohmann::json::parse(d.out);
  for (const auto& g : j.at("diagnostics"))
    listed = listed || g.at("code") == "dynamics.bare_rail_end";
  EXPECT_TRUE(listed) << d.out.substr(0, 400);
  EXPECT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.err.find("catena: error: analyses.dynamics: step 462 (t = 0.0462 s)"),
            std::string::npos)
      << c.err;
  EXPECT_NE(c.out.find("dynamics.bare_rail_end"), std::string::npos);
  EXPECT_TRUE(nlohmann::json::parse(c.out).contains("analyses")) << c.out.substr(0, 400);
  EXPECT_EQ(h.status, 0) << h.err;
  EXPECT_NE(h.err.find("catena: error: analyses.dynamics: step 462 (t = 0.0462 s)"),
            std::string::npos)
      << h.err;
  EXPECT_TRUE(written);
}

// A guide against the chain's starting path (docs/models/dynamics.md, "Guides against the starting
// path") on the lead-in loop (the upper run 36.80 mm high, sprocket[1] at x = 190.5 mm): a rail may
// hold the start's rollers in its contact no deeper than its surface. The inside ring of 43.8 mm
// round sprocket[1] from -170 to 170 deg crosses the spans leaving that wheel (they pass its
// surface at ±122.84 deg): refused on dynamics.guide[0] naming the span, how far past the surface
// and the part of the ring clear of them, which typed back passes this check (at its ends the
// spans lie a roller radius into the ring's surface, on the edge of the rule) but is refused at
// its square entry end ("the square ends"; the message says so), and the part of it clear of its
// contact, which typed back runs; the same ring from -60 to 60 deg and a flat convex arc carrying
// the upper run (with lead-ins: bare, refused at its entry end 0.07275 mm into the run) are
// accepted and run. At the rule's edge: a straight rail and the flat arc with their surface 0.02 mm
// below the upper run's roller centres (6.015 mm into the rollers) pass this check but are refused
// at their square entry ends, 0.02 mm above it refused, naming the move that clears this check
// (typed back: refused at the square end alone), and the move to touching the rollers (6.055 mm),
// which typed back runs.
TEST(DynamicsBoundaryCli, AGuideMayNotCrossTheChainsStartingPath) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "catena_dynamics_boundary_cli_rail_path";
  std::filesystem::create_directories(dir);
  const auto ring = [](const std::string& from, const std::string& to) {
    return "[[dynamics.guide]]\nkind = \"arc\"\ncentre_x = \"190.5 mm\"\ncentre_y = 0\n"
           "radius = \"43.8 mm\"\ninside = true\nstart_angle = \"" +
           from + " deg\"\nend_angle = \"" + to + " deg\"\n";
  };
  const auto write = [&](const std::string& name, const std::string& text) {
    const std::filesystem::path file = dir / name;
    std::ofstream(file) << kLeadInLoopHead << text;
    return file.string();
  };
  const CliRun cut =
      run("dynamics " +
          write("ring_across.toml", ring("-170", "170") + "lead_in_radius = \"20 mm\"\n"
                                                          "lead_in_angle = \"15.18 deg\"\n"));
  EXPECT_EQ(cut.status, 2) << cut.err;
  EXPECT_TRUE(cut.out.empty());
  for (const char* text :
       {"dynamics.guide[0] (line 19) = the span sprocket[", " mm past its surface at ",
        "at most the roller radius (6.035 mm) into it",
        "start_angle >= ", " deg and end_angle <= ", " deg clears this check only",
        "and is refused at an entry end without a lead-in: give that end one)",
        "; clear of its contact (its surface at most touching the rollers): start_angle >= ",
        " (with a lead-in at an entry end that has none: a bare entry end near the path may stop "
        "the run)"})
    EXPECT_NE(cut.err.find(text), std::string::npos) << text << "\n" << cut.err;
  // the clear part named lies within ±122.84 deg, where the spans pass the ring's surface
  const double from = named_after(cut.err, "start_angle >= ");
  const double to = named_after(cut.err, "end_angle <= ");
  EXPECT_GT(from, -122.84) << cut.err;
  EXPECT_LT(from, -118.0) << cut.err;
  EXPECT_LT(to, 122.84) << cut.err;
  EXPECT_GT(to, 118.0) << cut.err;
  std::ostringstream at, bt;
  at << from;
  bt << to;
  const CliRun typed =
      run("dynamics " + write("ring_part.toml", ring(at.str(), bt.str())) + " --format json");
  // it passes this check, but its square entry end then holds the spans a roller radius deep
  // ("the square ends")
  EXPECT_EQ(typed.status, 2) << typed.err;
  EXPECT_EQ(typed.err.find(" past its surface"), std::string::npos) << typed.err;
  EXPECT_NE(typed.err.find("dynamics.guide[0] (line 19) = its square end at start_angle"),
            std::string::npos)
      << typed.err;
  // the part clear of its contact: inside the one that clears the check, and it runs its 2 ms
  const std::string touch = "at most touching the rollers): start_angle >= ";
  const std::size_t at_touch = cut.err.find(touch);
  ASSERT_NE(at_touch, std::string::npos) << cut.err;
  const double touch_from = named_after(cut.err.substr(at_touch), touch);
  const double touch_to = named_after(cut.err.substr(at_touch), "end_angle <= ");
  EXPECT_GT(touch_from, from) << cut.err;
  EXPECT_LT(touch_to, to) << cut.err;
  std::ostringstream ct, dt;
  ct << touch_from;
  dt << touch_to;
  const CliRun clear =
      run("dynamics " + write("ring_clear.toml", ring(ct.str(), dt.str())) + " --format json");
  EXPECT_EQ(clear.status, 0) << clear.err;
  EXPECT_TRUE(ran_clean(clear.out)) << clear.err;

  // lying on the chain: accepted and run (the flat arc, its entry end 0.07275 mm into the upper
  // run, with lead-ins: "the square ends")
  const std::string flat =
      "[[dynamics.guide]]\nkind = \"arc\"\ncentre_x = \"95.25 mm\"\ncentre_y = \"-4968.8 mm\"\n"
      "radius = \"5 m\"\nstart_angle = \"89.3124 deg\"\nend_angle = \"90.6876 deg\"\n";
  const std::string flat_led = flat + "lead_in_radius = \"20 mm\"\nlead_in_angle = \"30 deg\"\n";
  for (const std::string& text : {ring("-60", "60"), flat_led}) {
    const CliRun ok = run("dynamics " + write("on_chain.toml", text) + " --format json");
    ASSERT_EQ(ok.status, 0) << text << ok.err;
    EXPECT_TRUE(ran_clean(ok.out)) << text;
  }
  // the bare flat arc: refused at its entry end (start_angle: the upper run moves towards -x),
  // 0.07275 mm into its contact
  const CliRun bare = run("dynamics " + write("bare_flat.toml", flat) + " --format json");
  EXPECT_EQ(bare.status, 2) << bare.err;
  EXPECT_NE(bare.err.find("its square end at start_angle (155.3, 30.84) mm"), std::string::npos)
      << bare.err;
  EXPECT_NE(bare.err.find("crossing it 0.07275 mm into its contact"), std::string::npos)
      << bare.err;
  EXPECT_EQ(bare.err.find("its square end at end_angle"), std::string::npos) << bare.err;

  // the rule's edge: the upper run's roller centres at the pitch radius, 36.8017 mm; a straight
  // rail's surface and the flat arc's top (centre_y + 5 m) 0.02 mm below or above them
  const double run_height = 0.5 * 19.05 / std::sin(std::numbers::pi / 12.0);  // [mm]
  for (const double off : {-0.02, 0.02}) {
    std::ostringstream height, centre;
    height.precision(10);
    centre.precision(10);
    height << run_height + off << " mm";
    centre << run_height + off - 5000.0 << " mm";
    const std::string rail = lead_in_rail(height.str(), "");
    const std::string arc =
        "[[dynamics.guide]]\nkind = \"arc\"\ncentre_x = \"95.25 mm\"\ncentre_y = \"" +
        centre.str() +
        "\"\nradius = \"5 m\"\nstart_angle = \"89.3124 deg\"\nend_angle = \"90.6876 deg\"\n";
    for (const std::string& text : {rail, arc}) {
      const CliRun r = run("dynamics " + write("edge.toml", text) + " --duration \"0.1 ms\"");
      // below the edge the check passes, but the square entry end holds the run 6.015 mm deep:
      // refused by that rule alone ("the square ends")
      const std::string square = "dynamics.guide[0] (line 19) = its square end at ";
      if (off < 0.0) {
        EXPECT_EQ(r.status, 2) << text << r.err;
        EXPECT_EQ(r.err.find(" past its surface"), std::string::npos) << text << r.err;
        EXPECT_NE(r.err.find(square), std::string::npos) << text << r.err;
        continue;
      }
      EXPECT_EQ(r.status, 2) << text << r.err;
      const std::string named =
          "dynamics.guide[0] (line 19) = the span sprocket[1] -> sprocket[0] ";
      EXPECT_NE(r.err.find(named), std::string::npos) << text << r.err;
      const double past = named_after(r.err, named);  // [mm] past the surface
      EXPECT_GT(past, 0.0199) << r.err;
      EXPECT_LT(past, 0.0201) << r.err;
      // the move named, typed back: not cut
      const bool straight = text == rail;
      const double moved = named_after(r.err, straight ? "the rail moved " : "radius <= ");
      // the case with the rail moved as named (a straight rail by `given` mm down, an arc to the
      // radius `given` m)
      auto typed_back = [&](double given) {
        std::ostringstream value;
        value.precision(12);
        if (straight) value << run_height + off - given << " mm";
        if (!straight) value << given << " m";
        return straight ? lead_in_rail(value.str(), "")
                        : std::regex_replace(text, std::regex("radius = \"5 m\""),
                                             "radius = \"" + value.str() + "\"");
      };
      if (straight) {
        EXPECT_GE(moved, 0.02) << r.err;
        EXPECT_LT(moved, 0.0201) << r.err;
      } else {
        EXPECT_GE(moved, 5.0 - 0.0201e-3) << r.err;
        EXPECT_LE(moved, 5.0 - 0.02e-3) << r.err;
      }
      const std::string fixed = typed_back(moved);
      const CliRun ok =
          run("dynamics " + write("edge_moved.toml", fixed) + " --duration \"0.1 ms\"");
      // it clears this check (no cut named), the square entry end still refused
      EXPECT_EQ(ok.status, 2) << fixed << ok.err;
      EXPECT_EQ(ok.err.find(" past its surface"), std::string::npos) << fixed << ok.err;
      EXPECT_NE(ok.err.find(square), std::string::npos) << fixed << ok.err;
      // the move to touching the rollers (the surface a roller radius above their centres, 0.02
      // mm higher than now), typed back: accepted and runs its 2 ms
      const std::string touching = "at most touching the rollers): ";
      const std::size_t at_lift = r.err.find(touching);
      ASSERT_NE(at_lift, std::string::npos) << r.err;
      const std::string tail = r.err.substr(at_lift);
      const double lifted = named_after(tail, straight ? "the rail moved " : "radius <= ");
      if (straight) {
        EXPECT_GE(lifted, 6.055) << r.err;
        EXPECT_LT(lifted, 6.057) << r.err;
      } else {
        EXPECT_GE(lifted, 5.0 - 6.057e-3) << r.err;
        EXPECT_LE(lifted, 5.0 - 6.055e-3) << r.err;
      }
      const std::string lifted_text = typed_back(lifted);
      const CliRun runs =
          run("dynamics " + write("edge_touching.toml", lifted_text) + " --format json");
      EXPECT_EQ(runs.status, 0) << lifted_text << runs.err;
      EXPECT_TRUE(ran_clean(runs.out)) << lifted_text;
    }
  }
  std::filesystem::remove_all(dir);
}

// A rail's square entry end against the chain's starting path (docs/models/dynamics.md, "Guides
// against the starting path: the square ends") on the lead-in loop: a straight rail from 30 to 150
// mm under the upper run (which runs towards -x, onto the rail at x = 150 mm), its surface set so
// that the run lies 4 mm into its contact (of the roller radius 6.035 mm), stopped at step 43 with
// "did not converge" before: now refused on dynamics.guide[0] naming its entry end (x1, y1), the
// 4 mm and the lead-in, the only remedy (a bare entry end clear of the rollers stops as often:
// no move is named), and not its exit end (x0, y0). The lead-in typed back (50 mm, 30 deg at both
// ends) runs 10 ms (past the old step 43) without a diagnostic.
TEST(DynamicsBoundaryCli, ARailsSquareEntryEndMayNotBePressedIntoTheStartingPath) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "catena_dynamics_boundary_cli_square_end";
  std::filesystem::create_directories(dir);
  const auto write = [&](const std::string& name, const std::string& text) {
    const std::filesystem::path file = dir / name;
    std::ofstream(file) << kLeadInLoopHead << text;
    return file.string();
  };
  // the upper run's roller centres at the pitch radius; the surface a roller radius below them
  // less `depth`
  const double run_height = 0.5 * 19.05 / std::sin(std::numbers::pi / 12.0);  // [mm]
  const auto rail_at = [&](double depth, const std::string& keys) {
    std::ostringstream height;
    height.precision(12);
    height << run_height - 6.035 + depth << " mm";
    return lead_in_rail(height.str(), keys);
  };
  const CliRun pressed = run("dynamics " + write("pressed.toml", rail_at(4.0, "")));
  EXPECT_EQ(pressed.status, 2) << pressed.err;
  const std::string named = "dynamics.guide[0] (line 19) = its square end at (x1, y1) (150, ";
  EXPECT_NE(pressed.err.find(named), std::string::npos) << pressed.err;
  EXPECT_EQ(pressed.err.find("its square end at (x0, y0)"), std::string::npos) << pressed.err;
  for (const char* text : {"the chain's starting path crossing it 4 mm into its contact",
                           "at most its contact's ramp (0.001 mm) deep",
                           "lead_in_end = \"end\" or \"both\"), the only remedy"})
    EXPECT_NE(pressed.err.find(text), std::string::npos) << text << "\n" << pressed.err;
  EXPECT_EQ(pressed.err.find("move"), std::string::npos) << pressed.err;
  const std::string led = rail_at(4.0, "lead_in_radius = \"50 mm\"\nlead_in_angle = \"30 deg\"\n");
  const CliRun ok =
      run("dynamics " + write("fixed.toml", led) + " --duration \"10 ms\" --format json");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(ok.err.empty()) << ok.err;
  EXPECT_TRUE(ran_clean(ok.out));
  // a sliver 0.5 µm long, shorter than the contact's ramp, pressed 4 mm in: its two ends lie
  // within ε of each other but close no ring (a straight rail), so both are square
  std::ostringstream sliver_y;
  sliver_y.precision(12);
  sliver_y << run_height - 6.035 + 4.0 << " mm";
  const CliRun sliver =
      run("dynamics " + write("sliver.toml",
                              "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"100 mm\"\n"
                              "y0 = \"" +
                                  sliver_y.str() + "\"\nx1 = \"100.0005 mm\"\ny1 = \"" +
                                  sliver_y.str() + "\"\n"));
  EXPECT_EQ(sliver.status, 2) << sliver.err;
  EXPECT_NE(sliver.err.find("dynamics.guide[0] (line 19) = its square end at (x1, y1)"),
            std::string::npos)
      << sliver.err;
  std::filesystem::remove_all(dir);
}

// A rail's own end below a lead-in smaller than the roller, crossed by the starting path past the
// lead-in's centre (docs/models/dynamics.md, "A rail's own end below a small lead-in"): the lead-in
// loop's upper run (roller centres at the run's height, moving -x) under a straight rail from 100
// to 120 mm, its free side up, its surface 2.9876 mm above those centres, with a lead-in of 0.3 mm
// at its end (x1 = 120 mm, where the chain runs onto it): the path crosses the rail's own end G =
// 2.9876 + 6.035 = 9.0226 mm below the line of its rollers, past the centre's 6.335 mm. Refused on
// dynamics.guide[0] naming that end, G, the limit R + r and the parallel clearance's radius at 30
// deg (G / (1 - cos 30 deg) - r) and at 90 deg (G - r), rounded up (3 digits) from G rounded up.
// Typed back at 90 deg, that end's refusal is gone (the rail still cuts the run: refused for that
// alone).
TEST(DynamicsBoundaryCli, ARailsOwnEndBelowASmallLeadInCrossedPastItsCentreIsRefused) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "catena_dynamics_boundary_cli_under_lead_in";
  std::filesystem::create_directories(dir);
  const double run_height = 0.5 * 19.05 / std::sin(std::numbers::pi / 12.0), roller = 6.035;
  char y[64];
  std::snprintf(y, sizeof y, "%.12f mm", run_height + 2.9876);
  const auto write = [&](const std::string& keys) {
    const std::filesystem::path file = dir / "under.toml";
    std::ofstream(file) << kLeadInLoopHead << "[[dynamics.guide]]\nkind = \"straight\"\n"
                        << "x0 = \"100 mm\"\ny0 = \"" << y << "\"\nx1 = \"120 mm\"\ny1 = \"" << y
                        << "\"\nlead_in_end = \"end\"\n"
                        << keys;
    return run("dynamics " + file.string());
  };
  const CliRun r = write("lead_in_radius = \"0.3 mm\"\n");
  EXPECT_EQ(r.status, 2) << r.err;
  for (const char* text :
       {"dynamics.guide[0] (line 19) = its end at (x1, y1) (120, ",
        " mm under the lead-in at the end of dynamics.guide[0] (lead_in_radius 0.3 mm, "
        "lead_in_angle 30 deg), whose contact ends 6.335 mm below the line of the rail's rollers "
        "at the arc's centre (lead_in_radius + roller radius), where the chain runs onto it, the "
        "chain's starting path crossing it ",
        "expected a rail's end the starting path crosses no deeper than the arc joined to it "
        "covers, its centre (6.335 mm)",
        "(lead_in_radius + roller radius 6.035 mm) (1 - cos lead_in_angle) >= 9.023 mm, which no "
        "lead_in_angle meets at its lead_in_radius 0.3 mm: at its lead_in_angle 30 deg, "
        "lead_in_radius >= ",
        "(lead_in_end = \"end\" or \"both\")"})
    EXPECT_NE(r.err.find(text), std::string::npos) << text << "\n" << r.err;
  const double G = named_after(r.err, "the chain's starting path crossing it ");
  EXPECT_NEAR(G, 2.9876 + roller, 1e-3) << r.err;
  const double at30 = named_after(r.err, "at its lead_in_angle 30 deg, lead_in_radius >= ");
  const double least30 = 9.023 / (1.0 - std::cos(std::numbers::pi / 6.0)) - roller;
  EXPECT_GE(at30, least30) << r.err;
  EXPECT_LT(at30 - least30, 0.01 * least30) << r.err;
  const double at90 = named_after(r.err, "or at lead_in_angle 90 deg, lead_in_radius >= ");
  EXPECT_GE(at90, 9.023 - roller) << r.err;
  EXPECT_LT(at90 - (9.023 - roller), 0.01 * (9.023 - roller)) << r.err;
  std::ostringstream keys;
  keys << "lead_in_radius = \"" << at90 << " mm\"\nlead_in_angle = \"90 deg\"\n";
  const CliRun led = write(keys.str());
  EXPECT_EQ(led.err.find("its end at (x1, y1)"), std::string::npos) << keys.str() << led.err;
  EXPECT_NE(led.err.find("past its surface"), std::string::npos) << led.err;
  // the same arc laid by hand as dynamics.guide[1] (start_angle 60 deg, end_angle 90 deg, a 30 deg
  // sweep), tangent at (x1, y1): named by its guide, its remedy the clearance at its own sweep,
  // G/(1 - cos 30 deg) - r (G - r, 2.99 mm, passes over its centre and strikes its own far end).
  // Typed back, the centre moved to stay tangent, neither the rail's end nor the arc's far end
  // (start_angle) is refused.
  const auto hand = [&](double radius) {
    char centre[64], text[64];
    std::snprintf(centre, sizeof centre, "%.12f mm", run_height + 2.9876 - radius);
    std::snprintf(text, sizeof text, "%.6g mm", radius);
    const std::filesystem::path file = dir / "hand.toml";
    std::ofstream(file) << kLeadInLoopHead << "[[dynamics.guide]]\nkind = \"straight\"\n"
                        << "x0 = \"100 mm\"\ny0 = \"" << y << "\"\nx1 = \"120 mm\"\ny1 = \"" << y
                        << "\"\n[[dynamics.guide]]\nkind = \"arc\"\ncentre_x = \"120 mm\"\n"
                        << "centre_y = \"" << centre << "\"\nradius = \"" << text << "\"\n"
                        << "start_angle = \"60 deg\"\nend_angle = \"90 deg\"\n";
    return run("dynamics " + file.string());
  };
  const CliRun small = hand(0.3);
  EXPECT_EQ(small.status, 2) << small.err;
  EXPECT_NE(small.err.find(" mm under the arc dynamics.guide[1] (radius 0.3 mm, less than the "
                           "roller radius 6.035 mm) joined to it, whose contact ends 6.335 mm "
                           "below the line of the rail's rollers at the arc's centre (radius + "
                           "roller radius), where the chain runs onto it, the chain's starting "
                           "path crossing it 9.023 mm into its contact"),
            std::string::npos)
      << small.err;
  EXPECT_NE(small.err.find("give that arc a radius a roller running parallel to the rail there "
                           "clears, (radius + roller radius 6.035 mm) (1 - cos sweep) >= 9.023 "
                           "mm, at its sweep 30 deg (end_angle - start_angle, a quarter turn at "
                           "most counted): radius >= "),
            std::string::npos)
      << small.err;
  const double named = named_after(small.err, "a quarter turn at most counted): radius >= ");
  EXPECT_GE(named, least30) << small.err;
  EXPECT_LT(named - least30, 0.01 * least30) << small.err;
  EXPECT_NE(small.err.find("or at a sweep of 90 deg, radius >= 2.99 mm"), std::string::npos)
      << small.err;
  const CliRun cleared = hand(named);
  EXPECT_EQ(cleared.err.find("its end at (x1, y1)"), std::string::npos) << cleared.err;
  EXPECT_EQ(cleared.err.find("its square end at start_angle"), std::string::npos) << cleared.err;
  std::filesystem::remove_all(dir);
}

// A roller striking a rail's bare entry end in the run (docs/models/dynamics.md, "Guides against
// the starting path: the square ends", the run's diagnostic), on a case that reaches it whatever
// the rounding: the lead-in loop's chain on the free layout, the driver at (0, 0) and the driven
// wheel at (185, 0) mm on a take-up (1000 N along 0 deg, damping 3000 N s/m, travel up to 10 mm),
// the lower run sagging with 8.4 mm of slack at the start; a straight rail over the lower run, its
// free side down, from 130 to 60 mm at y = -R + r - 3 mm, 3 mm into where the straight lower run
// would lie (the sag keeps the start's path clear of it). The take-up pulls the sag up onto the
// rail's entry end (x1, y1), which the lower run's rollers (moving +x) cross from below the roller
// line. Three copies, run 0.2 s: the rail k × 1e-10 mm up for k = 0 and 1, and k = 3 with a take-up
// of 300 N damped by 1000 N s/m (its roller crosses the face in the step before the one that fails:
// named from the last converged step's move), and k = 0 with a lead-in of 2 mm at 45 deg at the
// rail's start (its exit end). Each stops with dynamics.bare_rail_end
// alone, not dynamics.not_converged, naming the step, a node, dynamics.guide[0]'s (x1, y1)
// (60, -33.77) mm, the depth (the JSON value g, past ε, within the contact) and the lead-in at
// "end" with a sufficient radius, R (1 - cos α) past the depth, at the rail's own lead_in_angle
// (45 deg) or else the default 30 deg; that lead-in typed back (at "end", or "both" at the rail's
// angle) runs the 0.2 s without a diagnostic. The control: a failure elsewhere (links
// of 1e10 N/m at a 2 ms step on the lead-in loop, which fails at step 4 without any rail) with a
// rail 0.5 mm clear of the upper run's rollers ending at x1 = 149 mm, whose face node 24 crosses
// in that step short of the ramp (g < ε: it fails the test if the strike's g > ε is dropped),
// is not named a strike: the step is retaken as half-steps and the run goes on (it kept
// dynamics.not_converged and its message before the retakes).
TEST(DynamicsBoundaryCli, ARollerStrikingABareEntryEndIsNamedWithTheLeadIn) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "catena_dynamics_boundary_cli_bare_end";
  std::filesystem::create_directories(dir);
  const double R = 0.5 * 19.05 / std::sin(std::numbers::pi / 12.0), roller = 6.035;  // [mm]
  struct Copy {
    const char* force;
    int damping, k;
    int angle;  // [deg] the rail's lead-in at its start (exit) end at this lead_in_angle; 0: none
  };
  const auto takeup = [&](const Copy& c, const std::string& keys) {
    std::string head = kLeadInLoopHead;
    head = std::regex_replace(head, std::regex("speed = \"13 rad/s\"\n"),
                              "speed = \"13 rad/s\"\ncentre_x = \"0 mm\"\ncentre_y = \"0 mm\"\n");
    head +=
        "centre_x = \"185 mm\"\ncentre_y = \"0 mm\"\ntakeup_direction = \"0 deg\"\n"
        "takeup_force = \"" +
        std::string(c.force) +
        "\"\ntakeup_travel_max = \"10 mm\"\ntakeup_damping = " + std::to_string(c.damping) + "\n";
    char y[64];
    std::snprintf(y, sizeof y, "%.12f mm", -R + roller - 3.0 + c.k * 1e-10);
    const std::filesystem::path file = dir / "takeup.toml";
    std::ofstream(file) << head << "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"130 mm\"\n"
                        << "y0 = \"" << y << "\"\nx1 = \"60 mm\"\ny1 = \"" << y << "\"\n"
                        << keys;
    return run("dynamics " + file.string() + " --duration \"0.2 s\" --format json");
  };
  const auto codes = [](const CliRun& r) {
    std::vector<std::string> found;
    const auto j = nlohmann::json::parse(r.out);
    for (const auto& g : j.at("diagnostics")) found.push_back(g.at("code").get<std::string>());
    return found;
  };
  for (const Copy& c : {Copy{"1000 N", 3000, 0, 0}, Copy{"1000 N", 3000, 1, 0},
                        Copy{"300 N", 1000, 3, 0}, Copy{"1000 N", 3000, 0, 45}}) {
    const int k = c.k;
    const std::string angle =
        c.angle ? "lead_in_angle = \"" + std::to_string(c.angle) + " deg\"\n" : std::string();
    const CliRun r =
        takeup(c, c.angle ? "lead_in_radius = \"2 mm\"\nlead_in_end = \"start\"\n" + angle : "");
    ASSERT_EQ(r.status, 0) << k << r.err;
    ASSERT_EQ(codes(r), std::vector<std::string>{"dynamics.bare_rail_end"}) << k << r.err;
    for (const char* text :
         {"catena: error: step ", " did not converge in ", " Newton iterations",
          " crosses the square end of dynamics.guide[0] at (x1, y1) (60, -33.77) mm, where it "
          "runs onto the rail, ",
          "deeper than its contact's ramp (0.001 mm)", "the run stopped there",
          "(lead_in_radius, lead_in_end = \"end\" or \"both\")"})
      EXPECT_NE(r.err.find(text), std::string::npos) << k << text << "\n" << r.err;
    EXPECT_EQ(r.err.find("try a smaller step"), std::string::npos) << k << r.err;
    const double node = named_after(r.err, ": node ");
    EXPECT_GE(node, 0.0) << r.err;
    EXPECT_LT(node, 32.0) << r.err;
    // the depth: the JSON's value g [m] (its limit ε), written to 4 digits in the message
    const auto j = nlohmann::json::parse(r.out);
    const double g = j.at("diagnostics").at(0).at("value").get<double>() * 1e3;  // [mm]
    EXPECT_EQ(j.at("diagnostics").at(0).at("limit").get<double>(), 1e-6);
    const double depth = named_after(r.err, "where it runs onto the rail, ");  // [mm]
    EXPECT_NEAR(depth, g, 5e-4 * g) << r.err;
    EXPECT_GT(g, 0.001) << r.err;
    EXPECT_LT(g, 2.0 * roller) << r.err;
    // the bound written rounded up: at or past g, by less than its last digit
    const double bound = named_after(r.err, "lead_in_radius (1 - cos lead_in_angle) > ");
    EXPECT_GE(bound, g) << r.err;
    EXPECT_LT(bound - g, 1e-3 * g) << r.err;
    // the lead-in named: R (1 - cos α) past the depth at the rail's lead_in_angle (else 30°),
    // rounded up to 3 digits, and it runs
    const double radius = named_after(
        r.err, c.angle
                   ? "at its lead_in_angle " + std::to_string(c.angle) + " deg, lead_in_radius >= "
                   : std::string("at the default 30 deg, lead_in_radius >= "));
    const double alpha = (c.angle ? c.angle : 30) * std::numbers::pi / 180.0;
    const double least = g / (1.0 - std::cos(alpha));
    EXPECT_GT(radius, least) << r.err;
    EXPECT_LT(radius - least, 0.01 * least) << r.err;
    std::ostringstream keys;
    keys << "lead_in_radius = \"" << radius << " mm\"\nlead_in_end = \""
         << (c.angle ? "both" : "end") << "\"\n"
         << angle;
    const CliRun led = takeup(c, keys.str());
    EXPECT_EQ(led.status, 0) << led.err;
    EXPECT_TRUE(led.err.empty()) << k << keys.str() << led.err;
    EXPECT_TRUE(codes(led).empty()) << k;
  }
  // a lead-in's own far end: the 300 N copy k = 0 with a lead-in of 0.3 mm (30 deg) at the entry
  // end stops where its roller crosses the arc's far end, named with the depth G below the rail's
  // roller line (rounded up, from the JSON's g: (R + r) - (R + r - g) cos 30 deg) and the exact
  // clearance (R + r)(1 - cos α) >= G: the radius at 30 deg and the angle at 0.3 mm, each rounded
  // up, each typed back running the 0.2 s without a diagnostic
  {
    const Copy c{"300 N", 1000, 0, 0};
    const CliRun r = takeup(c, "lead_in_radius = \"0.3 mm\"\nlead_in_end = \"end\"\n");
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(codes(r), std::vector<std::string>{"dynamics.bare_rail_end"}) << r.err;
    for (const char* text :
         {"catena: error: step ", " did not converge in ",
          " crosses the far end of the lead-in at the end of dynamics.guide[0] (lead_in_radius "
          "0.3 mm, lead_in_angle 30 deg) at (",
          "where it runs onto the lead-in, ", "deeper than its contact's ramp (0.001 mm)",
          "the run stopped there",
          " mm below the line of the rail's rollers at its end, along its tangent; ",
          "(lead_in_radius + roller radius 6.035 mm) (1 - cos "
          "lead_in_angle) >= ",
          "(lead_in_end = \"end\" or \"both\""})
      EXPECT_NE(r.err.find(text), std::string::npos) << text << "\n" << r.err;
    EXPECT_EQ(r.err.find("try a smaller step"), std::string::npos) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double g = j.at("diagnostics").at(0).at("value").get<double>() * 1e3;  // [mm]
    const double a = std::numbers::pi / 6.0, lead = 0.3;
    EXPECT_GT(g, 0.001) << r.err;
    EXPECT_LT(g, lead + roller) << r.err;  // the far face's reach: the arc's centre
    EXPECT_NEAR(named_after(r.err, "where it runs onto the lead-in, "), g, 5e-4 * g) << r.err;
    const double G = (lead + roller) - (lead + roller - g) * std::cos(a);
    const double named = named_after(r.err, "There the roller lies ");
    EXPECT_GE(named, G) << r.err;
    EXPECT_LT(named - G, 1e-3 * G) << r.err;
    EXPECT_EQ(named_after(r.err, "(1 - cos lead_in_angle) >= "), named) << r.err;
    const double radius = named_after(r.err, "at its lead_in_angle 30 deg, lead_in_radius >= ");
    const double least = named / (1.0 - std::cos(a)) - roller;
    EXPECT_GE(radius, least) << r.err;
    EXPECT_LT(radius - least, 0.01 * least) << r.err;
    const double angle = named_after(r.err, "at its lead_in_radius 0.3 mm, lead_in_angle >= ");
    const double fewest = std::acos(1.0 - named / (lead + roller)) * 180.0 / std::numbers::pi;
    EXPECT_GE(angle, fewest) << r.err;
    EXPECT_LT(angle - fewest, 0.01 * fewest) << r.err;
    std::ostringstream by_radius, by_angle;
    by_radius << "lead_in_radius = \"" << radius << " mm\"\n";
    by_angle << "lead_in_radius = \"0.3 mm\"\nlead_in_angle = \"" << angle << " deg\"\n";
    for (const std::string& keys : {by_radius.str(), by_angle.str()}) {
      const CliRun led = takeup(c, keys + "lead_in_end = \"end\"\n");
      EXPECT_EQ(led.status, 0) << led.err;
      EXPECT_TRUE(led.err.empty()) << keys << led.err;
      EXPECT_TRUE(codes(led).empty()) << keys;
    }
  }
  // a failure elsewhere, a bare end crossed in that step short of the ramp: not named a strike
  // (retaken, below)
  std::string stiff = kLeadInLoopHead;
  stiff = std::regex_replace(stiff, std::regex("axial_stiffness = [^\n]*"),
                             "axial_stiffness = \"1e10 N/m\"");
  stiff = std::regex_replace(stiff, std::regex("\nstep = [^\n]*"), "\nstep = \"2 ms\"");
  char clear[64];
  std::snprintf(clear, sizeof clear, "%.12f mm", R - roller - 0.5);
  const std::filesystem::path stiff_file = dir / "stiff.toml";
  std::ofstream(stiff_file) << stiff << "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"30 mm\"\n"
                            << "y0 = \"" << clear << "\"\nx1 = \"149 mm\"\ny1 = \"" << clear
                            << "\"\n";
  const CliRun other =
      run("dynamics " + stiff_file.string() + " --duration \"0.05 s\" --format json");
  std::filesystem::remove_all(dir);
  EXPECT_EQ(other.status, 0) << other.err;
  // not named a strike: retaken as half-steps, and the run goes on (before the retakes it stopped
  // with dynamics.not_converged, "step 4 (t = 0.008 s) did not converge in 50 Newton iterations
  // in all, ..."); its energy from nothing passes twice what it received at step 12 (+2.29 J
  // against 0.94 J, the 1e10 N/m links at 2 ms) and is back under it at the guard's checks (every
  // 10 steps, and the last), so it runs its 25 steps
  EXPECT_EQ(codes(other), (std::vector<std::string>{"dynamics.steps_retaken"})) << other.err;
  EXPECT_EQ(nlohmann::json::parse(other.out)["summary"]["steps"], 25) << other.err;
  EXPECT_NE(other.out.find("the first at step 4 (t = 0.008 s)"), std::string::npos)
      << other.out.substr(0, 400);
}

// The chain runs counter-clockwise round its path whichever side its driver is on (docs/models/
// dynamics.md, "Guides against the starting path: the square ends"): the serpentine layout of
// examples/dynamics_serpentine.toml (z 12 at the origin, z 18 on the chain's back at (275, -27)
// mm, z 18 at (400, 0) mm) with a straight rail under its upper span, from a quarter to three
// quarters of it, 4 mm into it. The upper span runs towards -x, onto the rail at (x1, y1), with
// the driver inside (the first wheel) and with the driver on the chain's back (turning clockwise):
// both refused naming (x1, y1) and a lead-in at "end", neither naming (x0, y0). The driver on the
// back named (x0, y0) before, and a lead-in there, typed back, was accepted and stopped at 88 ms.
TEST(DynamicsBoundaryCli, ARailsEntryEndFollowsTheChainWhicheverSideTheDriverIsOn) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "catena_dynamics_boundary_cli_back_driver";
  std::filesystem::create_directories(dir);
  const auto serpentine = [&](bool back) {
    return std::string(R"([dynamics]
chain = "12B"
axial_stiffness = "5e7 N/m"
axial_damping = 100
contact_stiffness = "2e8 N/m"
contact_damping = 800
duration = "0.1 ms"
step = "0.1 ms"
theta = 0.6
gravity = true
[[dynamics.sprocket]]
teeth = 12
)") +
           (back ? "role = \"driven\"\ninertia = 0.02\nload_torque = 1\n"
                 : "role = \"driver\"\nspeed = \"13 rad/s\"\n") +
           R"(centre_x = "0 mm"
centre_y = "0 mm"
[[dynamics.sprocket]]
teeth = 18
side = "outside"
)" + (back ? "role = \"driver\"\nspeed = \"13 rad/s\"\n" : "role = \"idler\"\ninertia = 0.002\n") +
           R"(centre_x = "275 mm"
centre_y = "-27 mm"
[[dynamics.sprocket]]
teeth = 18
role = "driven"
inertia = 0.02
load_torque = 10
centre_x = "400 mm"
centre_y = "0 mm"
[[dynamics.guide]]
kind = "straight"
x0 = "98.227466394 mm"
y0 = "39.239388387 mm"
x1 = "297.820190035 mm"
y1 = "48.255451705 mm"
)";
  };
  for (const bool back : {false, true}) {
    const std::filesystem::path file = dir / (back ? "back.toml" : "inside.toml");
    std::ofstream(file) << serpentine(back);
    const CliRun r = run("dynamics " + file.string());
    EXPECT_EQ(r.status, 2) << back << r.err;
    EXPECT_NE(r.err.find("its square end at (x1, y1) (297.8, 48.26) mm, where the chain runs onto "
                         "it, the chain's starting path crossing it 4"),
              std::string::npos)
        << back << r.err;
    EXPECT_NE(r.err.find("lead_in_end = \"end\" or \"both\")"), std::string::npos) << back << r.err;
    EXPECT_EQ(r.err.find("its square end at (x0, y0)"), std::string::npos) << back << r.err;
  }
  std::filesystem::remove_all(dir);
}

// A full ring has no ends (docs/models/dynamics.md, "Guides against the starting path: the square
// ends"): an outside ring of 20 mm under the lead-in loop's upper run, 0.5 mm into it, from 90 to
// 450 deg (its seam at the top, in the run's contact) and from -90 to 270 deg (its seam at the
// bottom): both accepted and run without a diagnostic. The seam at the top was refused as a square
// entry end before, naming a lead-in that a full ring cannot have.
TEST(DynamicsBoundaryCli, AFullRingHasNoSquareEnds) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "catena_dynamics_boundary_cli_full_ring";
  std::filesystem::create_directories(dir);
  const double run_height = 0.5 * 19.05 / std::sin(std::numbers::pi / 12.0);  // [mm]
  std::ostringstream centre;
  centre.precision(12);
  centre << run_height - 6.035 + 0.5 - 20.0 << " mm";
  for (const auto& [from, to] : {std::pair{"90", "450"}, std::pair{"-90", "270"}}) {
    const std::string ring =
        "[[dynamics.guide]]\nkind = \"arc\"\ncentre_x = \"95.25 mm\"\n"
        "centre_y = \"" +
        centre.str() + "\"\nradius = \"20 mm\"\nstart_angle = \"" + from +
        " deg\"\nend_angle = \"" + to + " deg\"\n";
    const std::filesystem::path file = dir / "ring.toml";
    std::ofstream(file) << kLeadInLoopHead << ring;
    const CliRun r = run("dynamics " + file.string() + " --format json");
    EXPECT_EQ(r.status, 0) << from << r.err;
    EXPECT_TRUE(r.err.empty()) << from << r.err;
    EXPECT_TRUE(ran_clean(r.out)) << from;
  }
  std::filesystem::remove_all(dir);
}

// Two rails whose lifts of the start disagree (docs/models/dynamics.md, "Guides against the
// starting path: several rails") on the lead-in loop: guide[0] under the upper run from 30 to 150
// mm, 3 mm into it, with 50 mm, 30 deg lead-ins; guide[1], facing up too, 9.5 mm above guide[0]'s
// surface from 60 to 120 mm: the run lies 12.5 mm behind its surface, out of its contact (its
// checks pass), until guide[0]'s lift sets the rollers 9.5 mm into it, past its surface. Accepted
// before, the chain pulled up through guide[1]; now refused naming both rails, the 3 nodes and the
// depth.
TEST(DynamicsBoundaryCli, ARollerLiftedOntoOneRailMayNotLandBehindAnother) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "catena_dynamics_boundary_cli_two_rails";
  std::filesystem::create_directories(dir);
  const double run_height = 0.5 * 19.05 / std::sin(std::numbers::pi / 12.0);  // [mm]
  std::ostringstream low, high;
  low.precision(12);
  high.precision(12);
  low << run_height - 6.035 + 3.0 << " mm";
  high << run_height - 6.035 + 12.5 << " mm";
  const std::string upper = "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"60 mm\"\ny0 = \"" +
                            high.str() + "\"\nx1 = \"120 mm\"\ny1 = \"" + high.str() + "\"\n";
  const std::filesystem::path file = dir / "two.toml";
  std::ofstream(file) << kLeadInLoopHead
                      << lead_in_rail(low.str(),
                                      "lead_in_radius = \"50 mm\"\nlead_in_angle = \"30 deg\"\n")
                      << upper;
  const CliRun r = run("dynamics " + file.string() + " --duration \"0.1 ms\"");
  std::filesystem::remove_all(dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("dynamics.guide = 3 nodes of the chain's start lifted onto guide[0] then "
                       "lay behind the surface of guide[1] (node "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(" 9.5 mm deep in it"), std::string::npos) << r.err;
}

// The check of the rails against the starting path bounded (docs/models/dynamics.md, "The
// check's work"): the lead-in loop with 10000 links (its path 190 m) and straight rails from 30 mm
// to 95 m along the upper run, 0.02 mm above its roller centres (each cut), each visiting some
// 1.26e5 of the path's samples. 200 rails (2.5e7 samples) are refused on dynamics.guide naming the
// count and the cap before any is checked; 20 (2.5e6) are checked, each refused on its own line.
TEST(DynamicsBoundaryCli, TheRailsCheckAgainstTheStartingPathIsBounded) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "catena_dynamics_boundary_cli_rail_work";
  std::filesystem::create_directories(dir);
  const std::string head =
      std::regex_replace(kLeadInLoopHead, std::regex("links = 32"), "links = 10000");
  const double run_height = 0.5 * 19.05 / std::sin(std::numbers::pi / 12.0);  // [mm]
  std::ostringstream y;
  y.precision(10);
  y << run_height + 0.02 << " mm";
  const std::string rail = "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"30 mm\"\ny0 = \"" +
                           y.str() + "\"\nx1 = \"95000 mm\"\ny1 = \"" + y.str() + "\"\n";
  for (const int rails : {200, 20}) {
    const std::filesystem::path file = dir / ("rails" + std::to_string(rails) + ".toml");
    std::string text = head;
    for (int k = 0; k < rails; ++k) text += rail;
    std::ofstream(file) << text;
    const CliRun r = run("dynamics " + file.string() + " --duration \"0.1 ms\"");
    EXPECT_EQ(r.status, 2) << r.err.substr(0, 600);
    const std::string capped = "dynamics.guide = " + std::to_string(rails) + " rails, ";
    if (rails == 200) {
      EXPECT_NE(r.err.find(capped), std::string::npos) << r.err.substr(0, 600);
      EXPECT_NE(r.err.find("samples of the chain's starting path to check against them: "
                           "expected at most 2e+07"),
                std::string::npos)
          << r.err.substr(0, 600);
      EXPECT_EQ(r.err.find("past its surface"), std::string::npos) << r.err.substr(0, 600);
    } else {
      EXPECT_EQ(r.err.find(capped), std::string::npos) << r.err.substr(0, 600);
      EXPECT_NE(r.err.find("dynamics.guide[19] (line "), std::string::npos) << r.err.substr(0, 600);
      EXPECT_NE(r.err.find("0.02 mm past its surface"), std::string::npos) << r.err.substr(0, 600);
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
