// `catena dynamics` with hinge friction (docs/models/dynamics.md, "Hinges"; docs/cli.md): the
// default is the frictionless run, byte for byte; a sliding hinge takes its pin from the ISO 606
// catalogue or the input; a rolling hinge's arm is c_r R*; the hinge work is in the work balance;
// every input problem is named at once.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kExample = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_12B.toml";

// The example (`source`, by default the 12B drive) with `extra` lines added to its [dynamics]
// table (after its theta line).
std::string example_with(const std::string& name, const std::string& extra,
                         const std::string& source = kExample) {
  std::string s = read_text(source);
  const std::size_t at = s.find("\n", s.find("theta = 0.6"));
  s.insert(at + 1, extra);
  const fs::path dir = fs::temp_directory_path() / "catena_dynamics_hinge_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << s;
  return path.string();
}

nlohmann::json run_json(const std::string& file, const std::string& flags) {
  const CliRun r = run("dynamics " + file + " " + flags + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  j["summary"].erase("wall_time");
  j["summary"].erase("real_time_factor");
  return j;
}

TEST(DynamicsHingeCli, FrictionlessIsTheDefaultByteForByte) {
  const auto plain = run_json(kExample, "--duration 0.02s");
  const auto named =
      run_json(example_with("frictionless.toml", "hinge = \"frictionless\"\n"), "--duration 0.02s");
  EXPECT_EQ(plain.dump(), named.dump());
  EXPECT_FALSE(plain.contains("hinge"));
  EXPECT_FALSE(plain["summary"].contains("hinge_friction_work"));
}

TEST(DynamicsHingeCli, SlidingHingeTakesTheCataloguePinAndEntersTheWorkBalance) {
  const auto j =
      run_json(example_with("sliding.toml",
                            "hinge = \"sliding\"\nhinge_friction = 0.1\nwork_balance = true\n"),
               "--duration 0.1s");
  EXPECT_EQ(j["hinge"], "sliding");
  EXPECT_DOUBLE_EQ(j["hinge_arm"].get<double>(), 0.1 * 5.72e-3 / 2);  // ISO 606 12B: d2 5.72 mm
  EXPECT_DOUBLE_EQ(j["hinge_band"].get<double>(), 5.0);
  const double hinge = j["summary"]["hinge_friction_work"].get<double>();
  EXPECT_LT(hinge, 0.0);
  EXPECT_EQ(j["summary"]["work_balance"]["hinge_friction"].get<double>(), hinge);
  EXPECT_EQ(j["units"]["hinge_friction_work"], "J");
  // 0.1 s of the drive: about 2 e ω (T_t + T_s) × 0.1 s ≈ 0.9 J (the closed form of
  // tests/validation/dynamics_hinge_test.cpp, with the start's transient)
  EXPECT_GT(-hinge, 0.5);
  EXPECT_LT(-hinge, 1.5);
  // the hinge work is taken out of the energy drift like the guides' friction: the drift of the
  // run with hinge friction stays of the order of the frictionless run's (≪ the hinge work)
  const auto plain = run_json(kExample, "--duration 0.1s");
  EXPECT_LT(std::abs(j["summary"]["energy_drift"].get<double>()),
            std::abs(plain["summary"]["energy_drift"].get<double>()) + 0.2 * std::abs(hinge));
  // the pin diameter as an input replaces the catalogue's
  const auto given = run_json(example_with("pin.toml",
                                           "hinge = \"sliding\"\nhinge_friction = 0.2\n"
                                           "pin_diameter = \"6 mm\"\nhinge_band = \"10 rad/s\"\n"),
                              "--duration 0.01s");
  EXPECT_DOUBLE_EQ(given["hinge_arm"].get<double>(), 0.2 * 0.006 / 2);
  EXPECT_DOUBLE_EQ(given["hinge_band"].get<double>(), 10.0);
}

TEST(DynamicsHingeCli, RollingHingeArmIsTheRollingCoefficientTimesTheReducedRadius) {
  const auto concave = run_json(example_with("rolling.toml",
                                             "hinge = \"rolling\"\nrolling_resistance = 0.001\n"
                                             "plate_radius = \"3 mm\"\nface_radius = \"4 mm\"\n"),
                                "--duration 0.01s");
  EXPECT_NEAR(concave["hinge_arm"].get<double>(), 0.001 * 0.003 * 0.004 / 0.001, 1e-15);
  const auto flat = run_json(example_with("flat.toml",
                                          "hinge = \"rolling\"\nrolling_resistance = 0.001\n"
                                          "plate_radius = \"3 mm\"\n"),
                             "--duration 0.01s");
  EXPECT_NEAR(flat["hinge_arm"].get<double>(), 0.001 * 0.003, 1e-15);
}

TEST(DynamicsHingeCli, EveryHingeProblemIsNamedAtOnce) {
  const CliRun r = run("dynamics " +
                       example_with("bad.toml",
                                    "hinge = \"rolling\"\nrolling_resistance = 0.2\n"
                                    "face_radius = \"1 mm\"\nhinge_friction = 2\n"
                                    "hinge_band = \"-1 rad/s\"\n") +
                       " --format json");
  EXPECT_EQ(r.status, 2);
  for (const char* field : {"dynamics.rolling_resistance", "dynamics.plate_radius",
                            "dynamics.hinge_friction", "dynamics.hinge_band"})
    EXPECT_NE(r.err.find(field), std::string::npos) << field << "\n" << r.err;
  EXPECT_NE(r.err.find("in [0, 0.1]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("only with hinge = \"sliding\""), std::string::npos) << r.err;

  const CliRun kind =
      run("dynamics " + example_with("kind.toml", "hinge = \"ball\"\n") + " --format json");
  EXPECT_EQ(kind.status, 2);
  EXPECT_NE(kind.err.find("frictionless, sliding or rolling"), std::string::npos) << kind.err;

  const CliRun pin = run("dynamics " +
                         example_with("pin_bad.toml",
                                      "hinge = \"sliding\"\nhinge_friction = 0.1\n"
                                      "pin_diameter = \"15 mm\"\n") +
                         " --format json");
  EXPECT_EQ(pin.status, 2);
  EXPECT_NE(pin.err.find("dynamics.pin_diameter"), std::string::npos) << pin.err;
  EXPECT_NE(pin.err.find("< p/2"), std::string::npos) << pin.err;
}

// pin_load = "pin_link": the pin load is the outer link's tension (docs/models/dynamics.md,
// "Hinges"); the JSON names it (a run with the mean, given or not, prints what it did before),
// and the run's hinge work is smaller in size than the mean's by the measured margin. A bad
// value, the key without hinge friction and an odd loop (the three-wheel example lays 55 links) are
// refused by name.
TEST(DynamicsHingeCli, PinLinkLoadIsAnOptionNamedInTheOutput) {
  const std::string sliding = "hinge = \"sliding\"\nhinge_friction = 0.1\n";
  const auto mean = run_json(example_with("mean.toml", sliding), "--duration 0.02s");
  const auto named = run_json(example_with("mean_named.toml", sliding + "pin_load = \"mean\"\n"),
                              "--duration 0.02s");
  EXPECT_EQ(mean.dump(), named.dump());
  EXPECT_FALSE(mean.contains("hinge_pin_load"));
  const auto pin = run_json(example_with("pin_link.toml", sliding + "pin_load = \"pin_link\"\n"),
                            "--duration 0.02s");
  EXPECT_EQ(pin["hinge_pin_load"], "pin_link");
  const double w_mean = mean["summary"]["hinge_friction_work"].get<double>();
  const double w_pin = pin["summary"]["hinge_friction_work"].get<double>();
  EXPECT_LT(w_pin, 0.0);
  // over these 20 ms (half a tooth period) the two classes of hinge do not yet average out: the
  // pin link's work is 0.942 of the mean's (measured); with the parities swapped (the integrator
  // handing each hinge node i + 1) it is 1.058, with the mean's load 1: the bound separates all
  // three
  EXPECT_GT(w_pin / w_mean, 0.90);
  EXPECT_LT(w_pin / w_mean, 0.97);
  const CliRun table =
      run("dynamics " + example_with("pin_link_table.toml", sliding + "pin_load = \"pin_link\"\n") +
          " --duration 0.005s");
  EXPECT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("pin load the pin link's"), std::string::npos) << table.out;

  const CliRun bad =
      run("dynamics " + example_with("pin_bad_value.toml", sliding + "pin_load = \"outer\"\n") +
          " --format json");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("dynamics.pin_load"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("mean or pin_link"), std::string::npos) << bad.err;

  const CliRun alone = run(
      "dynamics " + example_with("pin_alone.toml", "pin_load = \"pin_link\"\n") + " --format json");
  EXPECT_EQ(alone.status, 2);
  EXPECT_NE(alone.err.find("dynamics.pin_load"), std::string::npos) << alone.err;
  EXPECT_NE(alone.err.find("only with hinge"), std::string::npos) << alone.err;

  const std::string three = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_three_wheels.toml";
  const CliRun odd =
      run("dynamics " + example_with("pin_odd.toml", sliding + "pin_load = \"pin_link\"\n", three) +
          " --format json");
  EXPECT_EQ(odd.status, 2);
  EXPECT_NE(odd.err.find("dynamics.links"), std::string::npos) << odd.err;
  EXPECT_NE(odd.err.find("55"), std::string::npos) << odd.err;
  EXPECT_NE(odd.err.find("an even count"), std::string::npos) << odd.err;
  // the count is the layout's (links omitted): said so
  EXPECT_NE(odd.err.find("the layout's choice"), std::string::npos) << odd.err;
  // the same loop with the mean runs
  const CliRun odd_mean =
      run("dynamics " + example_with("mean_odd.toml", sliding, three) + " --duration 0.002s");
  EXPECT_EQ(odd_mean.status, 0) << odd_mean.err;
}

// The odd-loop rule is the model's (validate_pin_links: the pin link's load with friction on),
// named at the case's links field: an odd count given in the case is refused at its line (not
// called the layout's choice); a sliding hinge of zero friction (arm 0, no hinge friction at all)
// with pin_load = "pin_link" on the same odd loop runs, as the model accepts it.
TEST(DynamicsHingeCli, PinLinkOddLoopRuleIsTheModelsNamedAtTheLinksField) {
  const std::string three = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_three_wheels.toml";
  const std::string pin = "pin_load = \"pin_link\"\n";
  const CliRun given =
      run("dynamics " +
          example_with("pin_odd_given.toml",
                       "links = 55\nhinge = \"sliding\"\nhinge_friction = 0.1\n" + pin, three) +
          " --format json");
  EXPECT_EQ(given.status, 2) << given.err;
  EXPECT_NE(given.err.find("dynamics.links (line "), std::string::npos) << given.err;
  EXPECT_NE(given.err.find("an even count with pin_load = \"pin_link\""), std::string::npos)
      << given.err;
  EXPECT_EQ(given.err.find("the layout's choice"), std::string::npos) << given.err;
  const CliRun still = run(
      "dynamics " +
      example_with("pin_odd_still.toml", "hinge = \"sliding\"\nhinge_friction = 0\n" + pin, three) +
      " --duration 0.002s");
  EXPECT_EQ(still.status, 0) << still.err;
}

// The hinges' stick law (docs/models/dynamics.md, "Hinges: sticking"): its keys reach the model
// (the output names them; the run's hinge work differs from the regularised law's, Coulomb's full
// torque at any rate), the balance holds with the springs' energy (the numerical term as the
// regularised run's), and every problem with the keys is named at once.
TEST(DynamicsHingeCli, StickLawKeysReachTheModelAndAreChecked) {
  const std::string sliding = "hinge = \"sliding\"\nhinge_friction = 0.1\nwork_balance = true\n";
  const auto stick = run_json(example_with("stick.toml", sliding + "hinge_stick_stiffness = 100\n"
                                                                   "hinge_stick_damping = 0.002\n"),
                              "--duration 0.05s");
  EXPECT_DOUBLE_EQ(stick["hinge_stick_stiffness"].get<double>(), 100.0);
  EXPECT_DOUBLE_EQ(stick["hinge_stick_damping"].get<double>(), 0.002);
  EXPECT_EQ(stick["units"]["hinge_stick_stiffness"], "N m/rad");
  const auto plain = run_json(example_with("regularised.toml", sliding), "--duration 0.05s");
  EXPECT_FALSE(plain.contains("hinge_stick_stiffness"));
  const double w_stick = stick["summary"]["hinge_friction_work"].get<double>();
  const double w_plain = plain["summary"]["hinge_friction_work"].get<double>();
  EXPECT_LT(w_stick, 0.0);
  EXPECT_GT(std::abs(w_stick - w_plain), 1e-3 * std::abs(w_plain));
  // the balance's numerical term is the regularised run's (-0.16571 J against -0.16510 J): the
  // springs' energy (1.26e-3 J at the end) is counted; without it the term is -0.16697 J
  EXPECT_NEAR(stick["summary"]["work_balance"]["numerical"].get<double>(),
              plain["summary"]["work_balance"]["numerical"].get<double>(), 1.2e-3);
  // well inside the step's ratio (k_t (theta h)^2/(m p^2) = 0.04): no warning
  EXPECT_TRUE(stick["diagnostics"].empty()) << stick["diagnostics"].dump();

  const CliRun bad = run("dynamics " +
                         example_with("stick_bad.toml", sliding + "hinge_stick_stiffness = -1\n"
                                                                  "hinge_stick_damping = -2\n") +
                         " --format json");
  EXPECT_EQ(bad.status, 2);
  for (const char* field : {"dynamics.hinge_stick_stiffness", "dynamics.hinge_stick_damping"})
    EXPECT_NE(bad.err.find(field), std::string::npos) << field << "\n" << bad.err;
  const CliRun lone =
      run("dynamics " + example_with("stick_lone.toml", sliding + "hinge_stick_damping = 0.1\n") +
          " --format json");
  EXPECT_EQ(lone.status, 2);
  EXPECT_NE(lone.err.find("0 without hinge_stick_stiffness"), std::string::npos) << lone.err;
  const CliRun stiff = run(
      "dynamics " + example_with("stick_stiff.toml", sliding + "hinge_stick_stiffness = 1e10\n") +
      " --format json");
  EXPECT_EQ(stiff.status, 2);
  EXPECT_NE(stiff.err.find("4 theta k_t/p^2"), std::string::npos) << stiff.err;
  const CliRun bare_damper =
      run("dynamics " + example_with("stick_bare_damper.toml", "hinge_stick_damping = 1\n") +
          " --format json");
  EXPECT_EQ(bare_damper.status, 2);
  EXPECT_NE(bare_damper.err.find("only with hinge = \"sliding\" or \"rolling\""), std::string::npos)
      << bare_damper.err;
  // one problem named once: not also "0 without hinge_stick_stiffness"
  EXPECT_EQ(bare_damper.err.find("dynamics.hinge_stick_damping"),
            bare_damper.err.rfind("dynamics.hinge_stick_damping"))
      << bare_damper.err;
  const CliRun bare = run(
      "dynamics " +
      example_with("stick_bare.toml", "hinge_stick_stiffness = 100\nhinge_stick_damping = 1\n") +
      " --format json");
  EXPECT_EQ(bare.status, 2);
  EXPECT_NE(bare.err.find("only with hinge = \"sliding\" or \"rolling\""), std::string::npos)
      << bare.err;
  const CliRun still = run("dynamics " +
                           example_with("stick_still.toml",
                                        "hinge = \"sliding\"\nhinge_friction = 0\n"
                                        "hinge_stick_stiffness = 100\n") +
                           " --format json");
  EXPECT_EQ(still.status, 2);
  EXPECT_NE(still.err.find("nothing to stick with"), std::string::npos) << still.err;
}

// The stick law's bounds over the step (docs/models/dynamics.md, "Hinges: sticking"): on the 12B
// example (m = 0.0237 kg, p = 19.05 mm, theta 0.6, h = 0.1 ms) k_t above 100 m p^2/(theta h)^2 =
// 2.388e5 N m/rad is refused, the limit named; above 14 m p^2/(theta h)^2 = 3.344e4 N m/rad a run
// is warned, and k_t = 2.3e5 (ratio 96, well past the failures from 40) fails at its sixth step,
// which is retaken as two half-steps (ratio 24 each) and the run goes on (it stopped there with
// advice naming the key before the retakes); the
// damper c_t above 5e3 m p^2/(theta h) (the seats' damper ratio) = 716.6 N m s/rad is refused.
TEST(DynamicsHingeCli, StickLawBoundsFollowTheStep) {
  const std::string sliding = "hinge = \"sliding\"\nhinge_friction = 0.1\n";
  const CliRun refused =
      run("dynamics " + example_with("stick_3e5.toml", sliding + "hinge_stick_stiffness = 3e5\n") +
          " --format json");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("dynamics.hinge_stick_stiffness (line "), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("at most 100 m p^2/(theta step)^2 = 2.388e+05 N m/rad"),
            std::string::npos)
      << refused.err;
  const auto warned =
      run_json(example_with("stick_2.3e5.toml", sliding + "hinge_stick_stiffness = 2.3e5\n"),
               "--duration 0.002s");
  bool warning = false, retaken = false;
  for (const auto& d : warned["diagnostics"]) {
    if (d["code"] == "dynamics.hinge_stick_stiffness_high") {
      warning = true;
      EXPECT_EQ(d["severity"], "warning");
      EXPECT_NE(d["message"].get<std::string>().find("3.344e+04 N m/rad"), std::string::npos)
          << d.dump();
    }
    EXPECT_NE(d["code"], "dynamics.not_converged") << d.dump();
    if (d["code"] == "dynamics.steps_retaken")
      retaken = d["message"].get<std::string>().find("the first at step 6 ") != std::string::npos;
  }
  EXPECT_TRUE(warning) << warned["diagnostics"].dump();
  EXPECT_TRUE(retaken) << warned["diagnostics"].dump();
  EXPECT_EQ(warned["summary"]["steps"], 20);
  // without the stick law a failure is retaken the same way: stiff links at 1 ms, whose step 3
  // fails and is retaken (the not_converged advice without the key is pinned in
  // DynamicsPocketCli.AStepFailingAtTheRetakesFloorEndsTheRunAtItsStart; the advice naming
  // hinge_stick_stiffness is reached by no case found, every stick-law failure tried being
  // carried by the retakes)
  const std::string links = example_with("links_1e9.toml", "");
  std::string text = read_text(links);
  text.replace(text.find("\"5e7 N/m\""), 9, "\"1e9 N/m\"");
  std::ofstream(links) << text;
  const auto stiff_links = run_json(links, "--step 1ms --duration 5ms");
  bool links_retaken = false;
  for (const auto& d : stiff_links["diagnostics"]) {
    EXPECT_NE(d["code"], "dynamics.not_converged") << d.dump();
    if (d["code"] == "dynamics.steps_retaken")
      links_retaken =
          d["message"].get<std::string>().find("the first at step 3 ") != std::string::npos;
  }
  EXPECT_TRUE(links_retaken) << stiff_links["diagnostics"].dump();
  EXPECT_EQ(stiff_links["summary"]["steps"], 5);

  const CliRun damped =
      run("dynamics " +
          example_with("stick_damped.toml", sliding + "hinge_stick_stiffness = 100\n"
                                                      "hinge_stick_damping = 1e9\n") +
          " --format json");
  EXPECT_EQ(damped.status, 2);
  EXPECT_NE(damped.err.find("dynamics.hinge_stick_damping (line "), std::string::npos)
      << damped.err;
  EXPECT_NE(damped.err.find("at most 716.6 N m s/rad"), std::string::npos) << damped.err;
  const CliRun under =
      run("dynamics " +
          example_with("stick_under.toml", sliding + "hinge_stick_stiffness = 100\n"
                                                     "hinge_stick_damping = 716\n") +
          " --duration 0.0002s --format json");
  EXPECT_EQ(under.status, 0) << under.err;
}

// Ratios where the stick law stopped converging before the line search's crossing cut
// (docs/models/dynamics.md, "Hinges: sticking"): the 12B example at k_t = 7e4 N m/rad, h = 0.1 ms
// (ratio 29; stopped at step 6 without the cut) and at k_t = 1.5e4, h = 0.2 ms (ratio 25; stopped
// at step 3 without the cut, and at step 1 with the cut but without the last start from constant
// velocity with the halvings alone) run 2 ms, warned.
TEST(DynamicsHingeCli, StickLawRunsPastTheRatiosThatStoppedBeforeTheCrossingCut) {
  const std::string sliding = "hinge = \"sliding\"\nhinge_friction = 0.1\n";
  for (const auto& [kt, step] : {std::pair<std::string, std::string>{"7e4", "0.1ms"},
                                 std::pair<std::string, std::string>{"1.5e4", "0.2ms"}}) {
    const auto out = run_json(
        example_with("stick_" + kt + ".toml", sliding + "hinge_stick_stiffness = " + kt + "\n"),
        "--step " + step + " --duration 0.002s");
    bool warned = false;
    for (const auto& d : out["diagnostics"]) {
      EXPECT_NE(d["code"], "dynamics.not_converged") << kt << " " << d.dump();
      warned = warned || d["code"] == "dynamics.hinge_stick_stiffness_high";
    }
    EXPECT_TRUE(warned) << kt;
    EXPECT_EQ(out["summary"]["steps"].get<int>(), step == "0.1ms" ? 20 : 10) << kt;
  }
}

}  // namespace
