// Throughput of the pocket-wheel run-on: closed forms vs the independent numerical solver.
// Results are recorded in docs/performance.md.
#include <benchmark/benchmark.h>

#include "catena/pocketwheel/run_on.hpp"
#include "catena/pocketwheel/run_on_numeric.hpp"

namespace {

using namespace catena::pocketwheel;

const PocketWheel kWheel{0.064, 0.018, 8};

Guide guide_for(int kind) {
  return Guide{static_cast<GuideKind>(kind), 0.0, 0.256, SpanModel::kSlider};
}

// Points per second of a whole analysis (plan + samples + extremes), as the CLI runs it.
void BM_RunOnClosedForm(benchmark::State& state) {
  const Guide guide = guide_for(static_cast<int>(state.range(0)));
  const Sampling sampling{5.0, static_cast<int>(state.range(1)), 40.0};
  for (auto _ : state) {
    RunOnResult r = run_on(kWheel, guide, sampling);
    benchmark::DoNotOptimize(r.series.ax.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(1));
}
BENCHMARK(BM_RunOnClosedForm)
    ->ArgNames({"guide", "points"})
    ->Args({0, 1000000})
    ->Args({1, 1000000})
    ->Args({2, 1000000})
    ->Args({2, 721})
    ->Unit(benchmark::kMillisecond);

// Pointwise closed-form evaluation only (the plan is built once).
void BM_EvaluateClosedForm(benchmark::State& state) {
  const RunOnPlan plan = plan_run_on(kWheel, guide_for(static_cast<int>(state.range(0))));
  const double step = plan.geometry.tooth_angle / 4096.0;
  double phi = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(evaluate(plan, phi));
    phi = phi + step >= plan.geometry.tooth_angle ? 0.0 : phi + step;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateClosedForm)->ArgName("guide")->DenseRange(0, 2);

// The numerical solver: positions by Newton's method, derivatives by finite differences.
void BM_EvaluateNumeric(benchmark::State& state) {
  const numeric::NumericPlan plan =
      numeric::plan(kWheel, guide_for(static_cast<int>(state.range(0))));
  const double step = plan.period / 4096.0;
  double phi = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(numeric::evaluate(plan, phi));
    phi = phi + step >= plan.period ? 0.0 : phi + step;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateNumeric)->ArgName("guide")->DenseRange(0, 2);

// Planning: seating events (closed form with the order rule) and the numerical event search.
void BM_PlanClosedForm(benchmark::State& state) {
  const Guide guide = guide_for(2);
  for (auto _ : state) benchmark::DoNotOptimize(plan_run_on(kWheel, guide));
}
BENCHMARK(BM_PlanClosedForm);

void BM_PlanNumeric(benchmark::State& state) {
  const Guide guide = guide_for(2);
  for (auto _ : state) benchmark::DoNotOptimize(numeric::plan(kWheel, guide));
}
BENCHMARK(BM_PlanNumeric)->Unit(benchmark::kMicrosecond);

}  // namespace
