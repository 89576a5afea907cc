// `load_per_metre` on a [[dynamics.guide]] (docs/models/dynamics.md, "A conveyed load") through
// `catena dynamics`: a loaded rail adds the loads' work to the work balance (and nothing is added
// without one: the example's output keeps its fields), and every bad load is named at once — out
// of range, on an arc, without gravity, on a rail whose carrying side faces down — with its line
// and exit status 2; the drift is net of the load's work. And `stick_stiffness` on a guide
// ("Guides: sticking"): every bad value named at once (negative, a wrong unit, on a frictionless
// rail; an arc's is accepted), an absurd one beyond the rail's penalty's bound over a step, and
// `stick_damping` negative or without the spring. And `load_inertia`: the balance's catch and
// discharge, and its bad values named; `load_speed`: the arriving material's kinetic energy in the
// catch, and its bad values named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "../read_text.hpp"
#include "case_text.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kExample = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_conveyor.toml";

std::string example() { return read_text(kExample); }

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "catena_dynamics_load_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// `text` run through the command: refused (exit 2, nothing on stdout), naming every one of
// `fields` on stderr; the run, for its message's further checks.
CliRun refused_naming(const std::string& name, const std::string& text,
                      std::initializer_list<const char*> fields) {
  const CliRun r = run("dynamics " + write(name, text));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  for (const char* field : fields)
    EXPECT_NE(r.err.find(field), std::string::npos) << field << "\n" << r.err;
  return r;
}

TEST(DynamicsLoadCli, LoadedRailAddsTheLoadsWorkToTheBalance) {
  const std::string balance = with_dynamics_key(example(), "work_balance = true");
  const CliRun r =
      run("dynamics " +
          write("loaded.toml", with_guide_key(balance, 0, "load_per_metre = \"2.5 kg/m\"")) +
          " --duration 0.02s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& b = j["summary"]["work_balance"];
  ASSERT_TRUE(b.contains("loads")) << b.dump();
  // the loaded chain settles onto the level rail: the load's weight works on that small sink
  EXPECT_GT(b["loads"].get<double>(), 0.0);
  const CliRun plain =
      run("dynamics " + write("plain.toml", balance) + " --duration 0.02s --format json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const auto p = nlohmann::json::parse(plain.out);
  EXPECT_FALSE(p["summary"]["work_balance"].contains("loads"));
  // the load presses the upper run onto its rail: more friction than without it
  EXPECT_LT(j["summary"]["friction_work"].get<double>(),
            p["summary"]["friction_work"].get<double>());
}

// A two-wheel loop of the example's chain and wheels, its line of centres at `incline` [deg] from
// the driver at the origin, one rail under its upper run (the example's, turned with the loop)
// carrying `load` kg/m, the work balance on.
std::string inclined_loop(double incline, double load) {
  const double b = incline * std::numbers::pi / 180.0, c = std::cos(b), s = std::sin(b);
  const double centres = 60 * 19.05, y = 48.510 - 6.035;  // [mm]; the rail's surface level
  const double ends[2] = {57.15, 1085.85};
  char text[1600];
  std::snprintf(text, sizeof text,
                "[dynamics]\nchain = \"12B\"\nlinks = 136\naxial_stiffness = \"5e7 N/m\"\n"
                "axial_damping = 100\npretension = \"20 N\"\ncontact_stiffness = \"2e8 N/m\"\n"
                "contact_damping = 800\nstep = \"0.1 ms\"\noutput_interval = \"1 ms\"\n"
                "theta = 0.6\ngravity = true\nwork_balance = true\nduration = \"0.05 s\"\n"
                "[[dynamics.sprocket]]\nteeth = 16\nrole = \"driver\"\nspeed = \"5 rad/s\"\n"
                "centre_x = \"0 mm\"\ncentre_y = \"0 mm\"\n"
                "[[dynamics.sprocket]]\nteeth = 16\nrole = \"driven\"\ninertia = 0.002\n"
                "load_torque = 0\ncentre_x = \"%.9g mm\"\ncentre_y = \"%.9g mm\"\n"
                "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"%.9g mm\"\ny0 = \"%.9g mm\"\n"
                "x1 = \"%.9g mm\"\ny1 = \"%.9g mm\"\nfriction = 0.3\n"
                "contact_stiffness = \"1e7 N/m\"\ncontact_damping = 100\n"
                "load_per_metre = \"%.9g kg/m\"\n",
                centres * c, centres * s, ends[0] * c - y * s, ends[0] * s + y * c,
                ends[1] * c - y * s, ends[1] * s + y * c, load);
  return text;
}

// On a loop inclined at 25° carrying 100 kg/m the load's weight along the rail does most of the
// work on the chain (its upper run moves down the slope): `energy_drift` and so `numerical` are
// net of it. Without that subtraction `numerical` would be the load's work itself (measured:
// loads 5.5 J, numerical −0.22 J in 0.05 s).
TEST(DynamicsLoadCli, DriftIsNetOfTheLoadsWork) {
  const CliRun r = run("dynamics " + write("inclined.toml", inclined_loop(25.0, 100.0)) +
                       " --duration 0.05s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& b = j["summary"]["work_balance"];
  ASSERT_TRUE(b.contains("loads")) << b.dump();
  const double loads = b["loads"], numerical = b["numerical"];
  EXPECT_GT(std::abs(loads), 1.0) << b.dump();  // [J] the load's work dominates
  EXPECT_LT(std::abs(numerical), 0.1 * std::abs(loads)) << b.dump();
}

TEST(DynamicsLoadCli, EveryBadLoadNamed) {
  std::string text = with_guide_key(example(), 0, "load_per_metre = \"-1 kg/m\"");
  // the upper rail's lead-in arc turned inside: its carrying side would face down
  text = with_guide_key(text, 1, "load_per_metre = \"3 kg/m\"\ninside = true");
  text = with_guide_key(text, 2, "load_per_metre = \"2e4 kg/m\"");
  text = with_guide_key(text, 3, "load_per_metre = \"4 m\"");
  const CliRun r = refused_naming(
      "bad.toml", text,
      {"dynamics.guide[0].load_per_metre (line", "dynamics.guide[1].load_per_metre (line",
       "dynamics.guide[2].load_per_metre (line", "dynamics.guide[3].load_per_metre"});
  EXPECT_NE(r.err.find("over the whole arc, and at 90 deg"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[0, 10000] kg/m"), std::string::npos) << r.err;

  // a loaded rail whose carrying side faces down (x1 < x0: the rollers would hang under it) or
  // sideways (x1 = x0): the load would pull the chain off it; refused with the other problems
  std::string facing = with_guide_key(example(), 2, "load_per_metre = \"2 kg/m\"");
  const std::string lower_x0 = "x0 = \"57.15 mm\"\ny0 = \"-54.545 mm\"";
  const std::size_t at = facing.find(lower_x0);
  ASSERT_NE(at, std::string::npos);
  facing.replace(at, lower_x0.size(), "x0 = \"2000 mm\"\ny0 = \"-54.545 mm\"");
  facing.insert(facing.find("[analyses.dynamics]"),
                "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"0 mm\"\ny0 = \"-300 mm\"\n"
                "x1 = \"0 mm\"\ny1 = \"-200 mm\"\nload_per_metre = 1\n\n");
  facing = with_guide_key(facing, 0, "load_per_metre = \"-1 kg/m\"");
  const CliRun d =
      refused_naming("facing.toml", facing,
                     {"dynamics.guide[0].load_per_metre", "dynamics.guide[2].load_per_metre",
                      "dynamics.guide[4].load_per_metre"});
  EXPECT_NE(d.err.find("the load must press the chain onto the rail, and this rail's carrying "
                       "side (left going from its first end to its second) faces down"),
            std::string::npos)
      << d.err;
  EXPECT_NE(d.err.find("second) faces sideways"), std::string::npos) << d.err;
  EXPECT_EQ(d.err.find("-0 m/s^2"), std::string::npos) << d.err;

  std::string weightless = example();
  const std::string gravity = "gravity = true";
  weightless.replace(weightless.find(gravity), gravity.size(), "gravity = false");
  const CliRun w =
      refused_naming("weightless.toml", with_guide_key(weightless, 0, "load_per_metre = 2"),
                     {"dynamics.guide[0].load_per_metre"});
  EXPECT_NE(w.err.find("without gravity"), std::string::npos) << w.err;
}

// `load_inertia = true` on a loaded rail (docs/models/dynamics.md, "A conveyed load: its inertia,
// loading and discharge"): the example's conveyor driven at 30 rad/s (the chain's mean speed
// v = z p ω/2π = 1.4553 m/s) with 10 kg/m on its upper rail, 0.2 s. The work balance gains the
// catch's and the discharge's works, each −½ q_L v³ t within 3 % (measured −3.098 and −3.085 J
// against −3.082 J), and `energy_drift` is net of them: `numerical` within 5 % of their sum
// (measured −0.135 J against −6.18 J). The weight-only run prints neither field.
TEST(DynamicsLoadCli, LoadInertiaAddsTheCatchAndDischargeToTheBalance) {
  std::string balance = with_dynamics_key(example(), "work_balance = true");
  const std::string speed = "speed = \"5 rad/s\"";
  ASSERT_NE(balance.find(speed), std::string::npos);
  balance.replace(balance.find(speed), speed.size(), "speed = \"30 rad/s\"");
  const std::string loaded = with_guide_key(balance, 0, "load_per_metre = \"10 kg/m\"");
  const CliRun r =
      run("dynamics " + write("inertia.toml", with_guide_key(loaded, 0, "load_inertia = true")) +
          " --duration 0.2s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& b = j["summary"]["work_balance"];
  ASSERT_TRUE(b.contains("load_catch")) << b.dump();
  ASSERT_TRUE(b.contains("load_discharge")) << b.dump();
  const double v = 16 * 0.01905 * 30.0 / (2 * std::numbers::pi);
  const double half = 0.5 * 10.0 * v * v * v * 0.2;  // [J] ½ q_L v³ t
  const double caught = b["load_catch"], discharged = b["load_discharge"];
  std::printf("catch %.4g J discharge %.4g J (-1/2 q_L v^3 t %.4g J) numerical %.4g J\n", caught,
              discharged, -half, b["numerical"].get<double>());
  EXPECT_NEAR(caught / -half, 1.0, 0.03) << b.dump();
  EXPECT_NEAR(discharged / -half, 1.0, 0.03) << b.dump();
  EXPECT_LT(std::abs(b["numerical"].get<double>()), 0.05 * std::abs(caught + discharged))
      << b.dump();
  // the material arrives at rest: it brings nothing, the catch is all loss
  ASSERT_TRUE(b.contains("load_arrival")) << b.dump();
  EXPECT_EQ(b["load_arrival"].get<double>(), 0.0) << b.dump();
  const CliRun w =
      run("dynamics " + write("weight.toml", loaded) + " --duration 0.02s --format json");
  ASSERT_EQ(w.status, 0) << w.err;
  const auto p = nlohmann::json::parse(w.out);
  EXPECT_TRUE(p["summary"]["work_balance"].contains("loads"));
  EXPECT_FALSE(p["summary"]["work_balance"].contains("load_catch"));
  EXPECT_FALSE(p["summary"]["work_balance"].contains("load_discharge"));
  EXPECT_FALSE(p["summary"]["work_balance"].contains("load_arrival"));
}

// Every bad `load_inertia` named at once, with its line: not true or false, and true on a rail
// without a load; beside a bad load on another guide (exit status 2).
TEST(DynamicsLoadCli, EveryBadLoadInertiaNamed) {
  std::string text = with_guide_key(example(), 0, "load_per_metre = 2\nload_inertia = \"yes\"");
  text = with_guide_key(text, 2, "load_inertia = true");
  text = with_guide_key(text, 3, "load_per_metre = \"-1 kg/m\"");
  const CliRun r = refused_naming(
      "inertia_bad.toml", text,
      {"dynamics.guide[0].load_inertia (line", "dynamics.guide[2].load_inertia (line",
       "dynamics.guide[3].load_per_metre (line"});
  EXPECT_NE(r.err.find("true or false"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("false without a load (load_per_metre > 0 kg/m)"), std::string::npos)
      << r.err;
}

// `load_speed` (docs/models/dynamics.md, "A conveyed load: its inertia, loading and discharge"):
// the run of LoadInertiaAddsTheCatchAndDischargeToTheBalance with the material arriving at the
// chain's mean speed along its travel (the upper run travels −x, the rail's direction +x:
// load_speed = −v). Nothing is lost in the catch, and the material brings ½ q_L v u² = ½ q_L v³
// of kinetic energy: `load_catch` is +½ q_L v³ t within 3 % (at rest it is −½ q_L v³ t), the
// discharge as before, and `numerical` within 5 % of the discharge (`energy_drift` stays net of
// both). `load_arrival`, the part of `load_catch` the material brings, is ½ q_L v u² t = ½ q_L v³ t
// within 3 %, and the catch's loss, `load_catch` less it, within 3 % of ½ q_L v³ t of 0.
TEST(DynamicsLoadCli, LoadSpeedBringsTheArrivingMaterialsEnergy) {
  std::string balance = with_dynamics_key(example(), "work_balance = true");
  const std::string speed = "speed = \"5 rad/s\"";
  ASSERT_NE(balance.find(speed), std::string::npos);
  balance.replace(balance.find(speed), speed.size(), "speed = \"30 rad/s\"");
  const double v = 16 * 0.01905 * 30.0 / (2 * std::numbers::pi);
  const std::string loaded =
      with_guide_key(balance, 0,
                     "load_per_metre = \"10 kg/m\"\nload_inertia = true\nload_speed = \"" +
                         std::to_string(-v * 1e3) + " mm/s\"");
  const CliRun r =
      run("dynamics " + write("arriving.toml", loaded) + " --duration 0.2s --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& b = j["summary"]["work_balance"];
  ASSERT_TRUE(b.contains("load_catch")) << b.dump();
  const double half = 0.5 * 10.0 * v * v * v * 0.2;  // [J] ½ q_L v³ t
  const double caught = b["load_catch"], discharged = b["load_discharge"];
  std::printf(
      "arriving at v: catch %.4g J discharge %.4g J (1/2 q_L v^3 t %.4g J) numerical %.4g J\n",
      caught, discharged, half, b["numerical"].get<double>());
  EXPECT_NEAR(caught / half, 1.0, 0.03) << b.dump();
  EXPECT_NEAR(discharged / -half, 1.0, 0.03) << b.dump();
  EXPECT_LT(std::abs(b["numerical"].get<double>()), 0.05 * std::abs(discharged)) << b.dump();
  ASSERT_TRUE(b.contains("load_arrival")) << b.dump();
  const double arrival = b["load_arrival"];
  std::printf("arrival %.4g J (1/2 q_L v u^2 t %.4g J), the catch's loss %.4g J\n", arrival, half,
              caught - arrival);
  EXPECT_NEAR(arrival / half, 1.0, 0.03) << b.dump();
  EXPECT_LT(std::abs(caught - arrival), 0.03 * half) << b.dump();
}

// Every bad `load_speed` named at once, with its line and the valid range: beyond 100 m/s, a
// wrong unit, and a speed on a loaded rail without `load_inertia` (exit status 2).
TEST(DynamicsLoadCli, EveryBadLoadSpeedNamed) {
  std::string text = with_guide_key(example(), 0,
                                    "load_per_metre = 2\nload_inertia = true\nload_speed = "
                                    "\"-150 m/s\"");
  text = with_guide_key(text, 1, "load_speed = \"2 kg\"");
  text = with_guide_key(text, 2, "load_per_metre = 2\nload_speed = \"1 m/s\"");
  const CliRun r =
      refused_naming("speed_bad.toml", text,
                     {"dynamics.guide[0].load_speed (line", "dynamics.guide[1].load_speed (line",
                      "dynamics.guide[2].load_speed (line"});
  EXPECT_NE(r.err.find("a speed in [-100, 100] m/s"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0 without load_inertia = true"), std::string::npos) << r.err;
}

TEST(DynamicsLoadCli, EveryBadStickStiffnessNamed) {
  std::string text = with_guide_key(example(), 0, "stick_stiffness = \"-1 N/m\"");
  // the upper lead-in's arc: an arc sticks as a straight rail does, not refused; its damper
  // negative, refused
  text = with_guide_key(text, 1, "stick_stiffness = \"1e5 N/m\"\nstick_damping = -1");
  text = with_guide_key(text, 3, "stick_stiffness = \"2 m\"");
  // the lower rail made frictionless: nothing to stick with
  const std::string mu = "friction = 0.3";
  std::size_t at = 0;
  for (int k = 0; k < 3; ++k) at = text.find(mu, k == 0 ? 0 : at + 1);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, mu.size(), "friction = 0\nstick_stiffness = \"1e5 N/m\"");
  const CliRun r = refused_naming(
      "stick.toml", text,
      {"dynamics.guide[0].stick_stiffness (line", "dynamics.guide[2].stick_stiffness",
       "dynamics.guide[3].stick_stiffness (line", "dynamics.guide[1].stick_damping (line"});
  for (const char* why : {"a finite stiffness >= 0 N/m", "0 on a frictionless guide", "N/m",
                          "a finite damping >= 0 N*s/m"})
    EXPECT_NE(r.err.find(why), std::string::npos) << why << "\n" << r.err;
  EXPECT_EQ(r.err.find("dynamics.guide[1].stick_stiffness"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("arc guide"), std::string::npos) << r.err;
  // an absurd spring: the bound of the rail's penalty over a step ("The inputs' bounds")
  const CliRun big =
      run("dynamics " +
          write("stick_big.toml", with_guide_key(example(), 2, "stick_stiffness = \"1e300 N/m\"")));
  EXPECT_EQ(big.status, 2);
  EXPECT_NE(big.err.find("dynamics.guide[2].stick_stiffness (line"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("at most 5e+05 m/(theta step)^2"), std::string::npos) << big.err;
  // an absurd damper beside a spring: the bound of the rail's damper over a step
  const CliRun loud = refused_naming(
      "stick_loud.toml",
      with_guide_key(example(), 2, "stick_stiffness = \"1e5 N/m\"\nstick_damping = 1e300"),
      {"dynamics.guide[2].stick_damping (line"});
  EXPECT_EQ(loud.err.find("stick_stiffness"), std::string::npos) << loud.err;
  // a damper without the spring: refused, named
  const CliRun bare =
      refused_naming("stick_bare.toml", with_guide_key(example(), 2, "stick_damping = 10"),
                     {"dynamics.guide[2].stick_damping"});
  EXPECT_NE(bare.err.find("0 without stick_stiffness"), std::string::npos) << bare.err;
}

}  // namespace
