// Throughput of the roller and plate strength checks (seed 000 §1.5). docs/performance.md.
#include <benchmark/benchmark.h>

#include "catena/strength/strength.hpp"

namespace {

using namespace catena::strength;

Input example(HingeKind kind) {
  Input in;
  in.hinge.heights = {0.0, 0.008, 0.048, 0.056};
  in.hinge.widths = {0.008, 0.008, 0.008, 0.008};
  in.hinge.pin_diameter = 0.040;
  in.hinge.plate_width = 0.080;
  in.hinge.end_distance = 0.040;
  in.hinge.kind = kind;
  in.hinge.r1 = 0.034;
  in.hinge.r2 = 0.0354;
  in.loads = {29.4e3, 0.0, 0.0, 0.030, 0.010};  // N = S over a 10 mm tooth
  in.material = {600e6, 355e6, 490e6, 60e6, 1600e6, 1.5};
  return in;
}

void BM_StrengthSlidingBothLayouts(benchmark::State& state) {
  const Input in = example(HingeKind::kSliding);
  for (auto _ : state) benchmark::DoNotOptimize(assess(in));
}
BENCHMARK(BM_StrengthSlidingBothLayouts);

void BM_StrengthRollingBothLayouts(benchmark::State& state) {
  const Input in = example(HingeKind::kRolling);
  for (auto _ : state) benchmark::DoNotOptimize(assess(in));
}
BENCHMARK(BM_StrengthRollingBothLayouts);

void BM_StrengthSlidingLinksAtAnAngle(benchmark::State& state) {
  Input in = example(HingeKind::kSliding);
  in.loads.exit_tension = 12.7e3;  // the thesis' F2 at the end of the engagement
  in.loads.link_angle = 0.785;     // 45°: both directions loaded, the resultant's scan
  for (auto _ : state) benchmark::DoNotOptimize(assess(in));
}
BENCHMARK(BM_StrengthSlidingLinksAtAnAngle);

void BM_StrengthMomentAt(benchmark::State& state) {
  const Input in = example(HingeKind::kSliding);
  const Beam b = beam(in, layout_loads(in, 1));
  double z = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(moment(b, z));
    z = z > 0.06 ? -0.004 : z + 1e-4;
  }
}
BENCHMARK(BM_StrengthMomentAt);

}  // namespace
