// Cost of one step of the chain dynamics (issue 21; docs/performance.md): a closed roller-chain
// loop (12B: p = 19.05 mm, 1.25 kg/m, link stiffness 5e7 N/m) running at 5 m/s under gravity,
// step 1e-4 s, at 100 / 200 / 400 / 800 links. O(N) per step: the cost should double with N.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "../tests/dynamics/two_wheel_loops.hpp"
#include "catena/catena.hpp"
#include "catena/dynamics/integrator.hpp"

namespace {

using namespace catena::dynamics;

constexpr double kPitch = 0.01905;    // [m]
constexpr double kNodeMass = 0.0238;  // [kg] 1.25 kg/m × p
constexpr double kStiffness = 5e7;    // [N/m]
constexpr double kSpeed = 5.0;        // [m/s]

// `hinge_arm` > 0: with hinge friction of that arm (docs/models/dynamics.md, "Hinges").
void loop_step(benchmark::State& bs, double hinge_arm) {
  const auto n = static_cast<std::size_t>(bs.range(0));
  Model m = uniform_chain(n, true, kPitch, kNodeMass, kStiffness, 2.0, false);
  m.gravity_y = -9.81;
  m.hinge.arm = hinge_arm;
  const double radius =
      1.0005 * kPitch / (2.0 * std::sin(std::numbers::pi / static_cast<double>(n)));
  State s(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    s.x[i] = radius * std::cos(a);
    s.y[i] = radius * std::sin(a);
    s.vx[i] = -kSpeed * std::sin(a);
    s.vy[i] = kSpeed * std::cos(a);
  }
  Integrator integ(m, {.step = 1e-4});
  long iterations = 0, steps = 0;
  for (auto _ : bs) {
    const StepReport r = integ.step(m, s);
    if (!r.converged) bs.SkipWithError("step did not converge");
    iterations += r.iterations;
    ++steps;
    benchmark::DoNotOptimize(s.x.data());
  }
  bs.counters["newton_iterations"] =
      benchmark::Counter(static_cast<double>(iterations) / static_cast<double>(steps));
  bs.counters["links"] = static_cast<double>(n);
  bs.counters["real_time_factor"] =
      benchmark::Counter(1e-4 * static_cast<double>(steps), benchmark::Counter::kIsRate);
}
void BM_DynamicsLoopStep(benchmark::State& bs) { loop_step(bs, 0.0); }
BENCHMARK(BM_DynamicsLoopStep)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(800)
    ->Unit(benchmark::kMicrosecond);
// the same loop with sliding hinges, μ = 0.1 on the 12B pin (d2 = 5.72 mm), band 5 rad/s
void BM_DynamicsLoopStepHingeFriction(benchmark::State& bs) { loop_step(bs, 0.1 * 5.72e-3 / 2); }
BENCHMARK(BM_DynamicsLoopStepHingeFriction)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(800)
    ->Unit(benchmark::kMicrosecond);

// Steps `s` once per benchmark iteration, stopping with an error on a step that does not converge;
// the Newton iterations, factorizations and backtracks summed, the steps counted and the deepest
// penetration; the stick law's switch updates and their builds summed.
struct StepTally {
  long iterations = 0, steps = 0, factorizations = 0, backtracks = 0;
  double penetration = 0.0;
  long switch_updates = 0, switch_builds = 0;
};
StepTally step_on(benchmark::State& bs, Integrator& integ, const Model& m, State& s) {
  StepTally t;
  for (auto _ : bs) {
    const StepReport rep = integ.step(m, s);
    if (!rep.converged) {
      bs.SkipWithError("step did not converge");
      break;
    }
    t.iterations += rep.iterations;
    t.factorizations += rep.factorizations;
    t.backtracks += rep.backtracks;
    t.switch_updates += rep.switch_updates;
    t.switch_builds += rep.switch_builds;
    t.penetration = std::max(t.penetration, rep.max_penetration);
    ++t.steps;
    benchmark::DoNotOptimize(s.x.data());
  }
  return t;
}

// The drive: a 200-link 12B loop over two equal sprockets (z = 20, 90 pitches apart, the
// polygons in phase), the driver at 30 rad/s (1.8 m/s), the driven wheel with J = 0.05 kg·m² and
// a 20 N·m load, gravity in the plane, contacts k_c = 2e8 N/m, c_c = 800 N·s/m, θ = 0.6 (the
// setting of the drive validation), h = 1e-4 s. Started with every roller seated and moving at
// the pitch-line speed; the benchmark steps on from there.
// `hinge_arm` > 0: the same with hinge friction of that arm (docs/models/dynamics.md, "Hinges").
// `pin_load`: the hinges' pin load rule (the mean of the two links' tensions, or the pin link's).
// `stick_stiffness` > 0: the hinges' stick law with that k_t [N·m/rad] ("Hinges: sticking").
void two_sprocket_drive(benchmark::State& bs, double hinge_arm, PinLoad pin_load = PinLoad::kMean,
                        double stick_stiffness = 0.0, bool switch_update = true) {
  testing::Loop drive = testing::benchmark_drive(hinge_arm);
  drive.model.hinge.pin_load = pin_load;
  drive.model.hinge.stick_stiffness = stick_stiffness;
  const Model& m = drive.model;
  State& s = drive.state;
  Integrator integ(m, {.step = 1e-4, .theta = 0.6, .switch_update = switch_update});
  const auto [iterations, steps, factorizations, backtracks, penetration, switch_updates,
              switch_builds] = step_on(bs, integ, m, s);
  bs.counters["newton_iterations"] =
      benchmark::Counter(static_cast<double>(iterations) / static_cast<double>(steps));
  bs.counters["factorizations"] =
      benchmark::Counter(static_cast<double>(factorizations) / static_cast<double>(steps));
  bs.counters["backtracks"] = static_cast<double>(backtracks);
  if (stick_stiffness > 0.0) {
    bs.counters["switch_updates"] = static_cast<double>(switch_updates);
    bs.counters["switch_builds"] = static_cast<double>(switch_builds);
  }
  bs.counters["simulated_s"] = 1e-4 * static_cast<double>(steps);
  bs.counters["max_penetration_um"] = 1e6 * penetration;
  bs.counters["real_time_factor"] =
      benchmark::Counter(1e-4 * static_cast<double>(steps), benchmark::Counter::kIsRate);
}
void BM_DynamicsTwoSprocketDrive(benchmark::State& bs) { two_sprocket_drive(bs, 0.0); }
BENCHMARK(BM_DynamicsTwoSprocketDrive)->Unit(benchmark::kMicrosecond)->MinTime(3.0);
// The same drive for a fixed 1000 steps from the seated start: the same work in every run, for
// instruction counts that do not depend on the machine's load (valgrind --tool=callgrind,
// docs/performance.md, "The drive's seat contacts")
BENCHMARK(BM_DynamicsTwoSprocketDrive)->Unit(benchmark::kMicrosecond)->Iterations(1000);
// with sliding hinges: μ = 0.1 on the 12B pin (d2 = 5.72 mm), the default rate band 5 rad/s
void BM_DynamicsTwoSprocketDriveHingeFriction(benchmark::State& bs) {
  two_sprocket_drive(bs, 0.1 * 5.72e-3 / 2);
}
BENCHMARK(BM_DynamicsTwoSprocketDriveHingeFriction)->Unit(benchmark::kMicrosecond)->MinTime(3.0);
// the same with the pin link's tension as each hinge's load (pin_load = "pin_link")
void BM_DynamicsTwoSprocketDriveHingeFrictionPinLink(benchmark::State& bs) {
  two_sprocket_drive(bs, 0.1 * 5.72e-3 / 2, PinLoad::kPinLink);
}
BENCHMARK(BM_DynamicsTwoSprocketDriveHingeFrictionPinLink)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(3.0);
// the same with the hinges' stick law, k_t = the argument [N·m/rad], no damper: the ratio
// k_t (θh)²/(m p²) that the stick law's convergence follows is 0.042, 0.42 and 4.2 (m p²/(θh)² =
// 2399 N·m/rad here; `catena dynamics` warns above 14), all three within the warning
void BM_DynamicsTwoSprocketDriveHingeStick(benchmark::State& bs) {
  two_sprocket_drive(bs, 0.1 * 5.72e-3 / 2, PinLoad::kMean, static_cast<double>(bs.range(0)));
}
BENCHMARK(BM_DynamicsTwoSprocketDriveHingeStick)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(3.0);
// the same work in every run (5000 steps, 0.5 s from the seated start), argument 0 the regularised
// law (BM_DynamicsTwoSprocketDriveHingeFriction's first 5000 steps): the comparison at equal
// simulated time, which MinTime's runs of different lengths are not
BENCHMARK(BM_DynamicsTwoSprocketDriveHingeStick)
    ->Arg(0)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(5000);
// the same 5000 steps with the chord iterations' kept factors alone across stick–slip switches
// (IntegratorOptions::switch_update false: as before the update; docs/performance.md, "The stick
// law's factors across stick–slip switches")
void BM_DynamicsTwoSprocketDriveHingeStickKeptFactors(benchmark::State& bs) {
  two_sprocket_drive(bs, 0.1 * 5.72e-3 / 2, PinLoad::kMean, static_cast<double>(bs.range(0)),
                     false);
}
BENCHMARK(BM_DynamicsTwoSprocketDriveHingeStickKeptFactors)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(5000);
// the same for a fixed 3000 steps from the seated start (instruction counts, as above;
// docs/performance.md, "Hinge friction: the couple's Jacobian straight into the band")
BENCHMARK(BM_DynamicsTwoSprocketDriveHingeFriction)
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(3000);

// Guides (docs/models/dynamics.md, "Guides"): the conveyor loop of examples/dynamics_conveyor.toml
// (validation (6b)): 136 links of 12B (pretension 20 N, 5e7 N/m, 100 N·s/m) over two z = 16
// wheels 60 pitches apart, the driver at 5 rad/s, a tail idler (J = 0.002 kg·m²), gravity; both
// runs on level rails with μ = 0.3 (1e7 N/m, 100 N·s/m) from 3 pitches after one wheel to 3 before
// the other, each with a 50 mm lead-in arc at its entry end; θ = 0.6, h = 1e-4 s. The argument
// cuts each straight rail into that many collinear pieces end to end (1: the example's 4 guides;
// 4: 10; 16: 34; 25: 52 —
// the same rails, a roller on a joint between two pieces touches both for an instant), and 0
// runs the loop without guides (it sags under gravity: the cost of the rest of the step).
void conveyor_guides(benchmark::State& bs, bool hint) {
  testing::Conveyor conveyor;  // validation (6b)'s loop, as the tests build it
  conveyor.pieces = static_cast<int>(bs.range(0));
  conveyor.node_mass = kNodeMass;
  testing::Loop loop = testing::conveyor_loop(conveyor);
  const Model& m = loop.model;
  State& s = loop.state;
  Integrator integ(m, {.step = 1e-4, .theta = 0.6, .guide_hint = hint});
  long iterations = 0, steps = 0;
  for (auto _ : bs) {
    const StepReport rep = integ.step(m, s);
    if (!rep.converged) {
      bs.SkipWithError("step did not converge");
      break;
    }
    iterations += rep.iterations;
    ++steps;
    benchmark::DoNotOptimize(s.x.data());
  }
  bs.counters["guides"] = static_cast<double>(m.guides.size());
  bs.counters["newton_iterations"] =
      benchmark::Counter(static_cast<double>(iterations) / static_cast<double>(steps));
  bs.counters["simulated_s"] = 1e-4 * static_cast<double>(steps);
  bs.counters["real_time_factor"] =
      benchmark::Counter(1e-4 * static_cast<double>(steps), benchmark::Counter::kIsRate);
}
// The guides tried through the per-node hint (GuideHint: O(N + G + pairs) a step), and, for the
// comparison, every node against every guide (O(N·G); the results are bit-identical). 25 pieces:
// 52 guides.
void BM_DynamicsConveyorGuides(benchmark::State& bs) { conveyor_guides(bs, true); }
BENCHMARK(BM_DynamicsConveyorGuides)
    ->Arg(0)
    ->Arg(1)
    ->Arg(4)
    ->Arg(16)
    ->Arg(25)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(2.0);
void BM_DynamicsConveyorGuidesEveryNode(benchmark::State& bs) { conveyor_guides(bs, false); }
BENCHMARK(BM_DynamicsConveyorGuidesEveryNode)
    ->Arg(1)
    ->Arg(4)
    ->Arg(16)
    ->Arg(25)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(2.0);

// The conveyor's rails (1 piece: both rails and their lead-in arcs) on each contact law, the
// elastic force at the θ point or as the discrete gradient of the contact's energy (Guide::
// discrete_gradient, "Guides: the discrete gradient": the law evaluated at the step's two ends
// besides the θ point, three times a contact). Argument 0: the penalty at the θ point (the
// example's); 1: the penalty's discrete gradient; 2: the line law at the θ point; 3: the line law's
// discrete gradient (its default, use_line_law).
void BM_DynamicsConveyorRailLaw(benchmark::State& bs) {
  testing::Conveyor conveyor;
  conveyor.node_mass = kNodeMass;
  testing::Loop loop = testing::conveyor_loop(conveyor);
  Model& m = loop.model;
  const long law = bs.range(0);
  for (Guide& g : m.guides) {
    if (law >= 2) use_line_law(g, conveyor.width);
    g.discrete_gradient = law % 2 == 1;
  }
  State& s = loop.state;
  Integrator integ(m, {.step = 1e-4, .theta = 0.6});
  const StepTally t = step_on(bs, integ, m, s);
  bs.counters["newton_iterations"] =
      benchmark::Counter(static_cast<double>(t.iterations) / static_cast<double>(t.steps));
  bs.counters["simulated_s"] = 1e-4 * static_cast<double>(t.steps);
  bs.counters["real_time_factor"] =
      benchmark::Counter(1e-4 * static_cast<double>(t.steps), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DynamicsConveyorRailLaw)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(2.0);
// the same for a fixed 4000 steps (0.4 s from the start) in every run
BENCHMARK(BM_DynamicsConveyorRailLaw)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(4000);

// The seats' law on examples/dynamics_12B.toml's drive (docs/models/dynamics.md, "Contact law"):
// 32 links of 12B (5e7 N/m, 100 N·s/m, pretension 950 N) over two z = 12 wheels 10 pitches apart,
// the driver at 13 rad/s, the driven wheel J = 0.01 kg·m² against 10 N·m, c_c = 800 N·s/m,
// θ = 0.6, h = 1e-4 s, the example's 5000 steps from the seated start. Argument 0: the linear
// penalty at the Hertz default's secant (k_c = Q0/δ(Q0), Q0 = T_L/R + pretension); 1: the line
// law; 2: the linear penalty at the example's k_c = 2e8 N/m. Counters: Newton iterations a step
// and the deepest seat.
void BM_DynamicsExampleDriveSeatLaw(benchmark::State& bs) {
  constexpr int kTeeth = 12, kSpan = 10;
  constexpr double kOmega = 13.0, kWidth = 0.01168, kLoad = 10.0, kPretension = 950.0;
  const auto n = static_cast<std::size_t>(kTeeth + 2 * kSpan);
  Model m = uniform_chain(n, true, kPitch - kPretension / kStiffness, 1.25 * kPitch, kStiffness,
                          100.0, false);
  m.sprockets = testing::equal_wheels({.teeth = kTeeth,
                                       .span = kSpan,
                                       .omega = kOmega,
                                       .inertia = 0.01,
                                       .load = kLoad,
                                       .contact_damping = 800.0});
  const double q0 = kLoad / m.sprockets[0].pitch_radius + kPretension;
  const double secant =
      q0 / catena::contact::slice_approach(seat_line_contact(m.sprockets[0], kWidth), q0 / kWidth);
  for (Sprocket& w : m.sprockets) {
    if (bs.range(0) != 2) w.contact_stiffness = secant;
    if (bs.range(0) == 1) use_line_law(w, kWidth);
  }
  State s = two_sprocket_loop(kTeeth, kSpan, kPitch, m.sprockets[0].pitch_radius, kOmega);
  Integrator integ(m, {.step = 1e-4, .theta = 0.6});
  const StepTally t = step_on(bs, integ, m, s);
  const long iterations = t.iterations, steps = t.steps;
  const double penetration = t.penetration;
  bs.counters["newton_iterations"] =
      benchmark::Counter(static_cast<double>(iterations) / static_cast<double>(steps));
  bs.counters["max_penetration_um"] = 1e6 * penetration;
}
BENCHMARK(BM_DynamicsExampleDriveSeatLaw)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(5000);

// The tension-only links' discrete gradient (docs/models/dynamics.md, "Tension-only links: the
// discrete gradient") on examples/dynamics_pocketwheel.toml: the round-link loop of 32 links over
// two z = 8 pocket wheels, 0.1 ms steps, run by the dynamics analysis for its first 20 ms (200
// steps, with the analysis's set-up and output). Argument 0: the example as it is (the links' and
// pockets' force at the θ point); 1: with `discrete_gradient = true` (both over the step).
void BM_DynamicsExamplePocketDiscreteGradient(benchmark::State& bs) {
  std::ifstream in(std::string(CATENA_EXAMPLES_DIR) + "/dynamics_pocketwheel.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string toml = text.str();
  if (bs.range(0) == 1) {
    const std::string section = "[dynamics]\n";
    const std::size_t at = toml.find(section);
    if (at == std::string::npos) {
      bs.SkipWithError("the example has no [dynamics] section");
      return;
    }
    toml.insert(at + section.size(), "discrete_gradient = true\n");
  }
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("catena_bench_pocket_" + std::to_string(bs.range(0)) + ".toml");
  std::ofstream(file) << toml;
  const std::vector<std::pair<std::string, std::string>> inputs = {{"dynamics", file.string()},
                                                                   {"duration", "20 ms"}};
  for (auto _ : bs) {
    catena::analysis::Record r = catena::run("dynamics", inputs);
    benchmark::DoNotOptimize(r.data.size());
  }
  std::filesystem::remove(file);
}
BENCHMARK(BM_DynamicsExamplePocketDiscreteGradient)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

}  // namespace
