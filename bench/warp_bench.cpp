// Throughput of the roller-warp solver (seed 000 §1.4). docs/performance.md.
#include <benchmark/benchmark.h>

#include "catena/warp/warp.hpp"

namespace {

using namespace catena::warp;

Warp example(double n) {
  Warp w;
  const double z[4] = {0.0, 0.008, 0.048, 0.056};
  for (std::size_t i = 0; i < 4; ++i)
    w.supports[i] = {z[i], i == 2 ? 2e-5 : 0.0, n == 1.0 ? 2e8 : 2e13, 0.008};
  w.exponent = n;
  w.roller_diameter = 0.024;
  return w;
}

void BM_WarpSolveLinear(benchmark::State& state) {
  const Warp w = example(1.0);
  for (auto _ : state) benchmark::DoNotOptimize(solve(w, {35e3, 0.030}));
}
BENCHMARK(BM_WarpSolveLinear);

void BM_WarpSolveLevinaReshetov(benchmark::State& state) {
  const Warp w = example(2.0);
  for (auto _ : state) benchmark::DoNotOptimize(solve(w, {35e3, 0.030}));
}
BENCHMARK(BM_WarpSolveLevinaReshetov);

void BM_WarpFiniteElementCheck(benchmark::State& state) {
  const Warp w = example(1.0);
  for (auto _ : state) benchmark::DoNotOptimize(solve_fe(w, {35e3, 0.030}, 10));
}
BENCHMARK(BM_WarpFiniteElementCheck);

}  // namespace
