// Cost of one step of the chain dynamics (issue 21; docs/performance.md): a closed roller-chain
// loop (12B: p = 19.05 mm, 1.25 kg/m, link stiffness 5e7 N/m) running at 5 m/s under gravity,
// step 1e-4 s, at 100 / 200 / 400 / 800 links. O(N) per step: the cost should double with N.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "catena/dynamics/integrator.hpp"

namespace {

using namespace catena::dynamics;

constexpr double kPitch = 0.01905;    // [m]
constexpr double kNodeMass = 0.0238;  // [kg] 1.25 kg/m × p
constexpr double kStiffness = 5e7;    // [N/m]
constexpr double kSpeed = 5.0;        // [m/s]

void BM_DynamicsLoopStep(benchmark::State& bs) {
  const auto n = static_cast<std::size_t>(bs.range(0));
  Model m = uniform_chain(n, true, kPitch, kNodeMass, kStiffness, 2.0, false);
  m.gravity_y = -9.81;
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
BENCHMARK(BM_DynamicsLoopStep)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(800)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
