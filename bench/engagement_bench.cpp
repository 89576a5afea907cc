// Throughput of the engagement forces: a sliding and a rolling engagement of 91 samples.
// docs/performance.md.
#include <benchmark/benchmark.h>

#include "catena/engagement/engagement.hpp"

namespace {

using namespace catena::engagement;

void BM_EngagementSliding91(benchmark::State& state) {
  SlidingInput in;
  in.tension = 29.4e3;
  in.teeth = 8;
  in.strokes = 2;
  in.friction = 0.15;
  in.journal_diameter = 0.040;
  in.tooth_diameter = 0.040;
  for (auto _ : state) benchmark::DoNotOptimize(solve_sliding(in));
}
BENCHMARK(BM_EngagementSliding91);

void BM_EngagementRolling91(benchmark::State& state) {
  RollingInput in;
  in.hinge.pin_diameter = 0.040;
  in.hinge.half_thickness = 0.008;
  in.hinge.plate_radius = 0.015;
  in.hinge.teeth = 8;
  in.hinge.strokes = 2;
  in.tension = 29.4e3;
  in.flank_angle = 0.3779;
  for (auto _ : state) benchmark::DoNotOptimize(solve_rolling(in));
}
BENCHMARK(BM_EngagementRolling91);

}  // namespace
