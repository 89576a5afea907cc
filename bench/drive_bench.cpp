// The exact polygon wrap of a two-sprocket drive (issue 16; its cost, issue 21):
// docs/performance.md, "The polygon wrap's hull bridges".
#include <benchmark/benchmark.h>

#include "catena/drive/layout.hpp"

namespace {

using namespace catena::drive;

constexpr double kPitch = 0.01905;  // [m] 12B

// examples/drive_12B.toml's layout: the link count for the centre distance asked (600 mm),
// rounded up to even, for z1/z2 teeth.
int links(int z1, int z2) { return round_up_even(links_for(kPitch, z1, z2, 0.6)); }

// One taut wrap: the driven sprocket's phase and the centre distance for one driver phase.
void BM_DrivePolygonWrap(benchmark::State& state) {
  const int z1 = static_cast<int>(state.range(0)), z2 = static_cast<int>(state.range(1));
  const int x = links(z1, z2);
  for (auto _ : state) benchmark::DoNotOptimize(polygon_wrap(kPitch, z1, z2, x, 0.1));
}
BENCHMARK(BM_DrivePolygonWrap)->Args({17, 25})->Args({17, 34})->Unit(benchmark::kMicrosecond);

// The exact centre distance over one driver pitch, as `catena drive` solves it.
void BM_DriveExactCenterDistance(benchmark::State& state) {
  const int z1 = static_cast<int>(state.range(0)), z2 = static_cast<int>(state.range(1));
  const int x = links(z1, z2);
  for (auto _ : state) benchmark::DoNotOptimize(exact_center_distance(kPitch, z1, z2, x));
}
BENCHMARK(BM_DriveExactCenterDistance)
    ->Args({17, 25})
    ->Args({17, 34})
    ->Unit(benchmark::kMillisecond);

}  // namespace
