#include <benchmark/benchmark.h>

#include "catena/pocketwheel/run_on.hpp"

static void BM_Placeholder(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(state.iterations());
}
BENCHMARK(BM_Placeholder);
