// Throughput of the orthotropic ring solvers (seed 002). docs/performance.md.
#include <benchmark/benchmark.h>

#include <vector>

#include "catena/composite/ring.hpp"

namespace {

using namespace catena::composite;

Ring paper_ring() {  // the example: α = 0.472, E_r/E_φ = 0.25
  Ring r;
  r.outer_radius = 10e-3;
  r.inner_radius = 4.72e-3;
  r.thickness = 1e-3;
  r.E_r = 10e9;
  r.E_phi = 40e9;
  r.G = 4e9;
  r.nu_phi_r = 0.28;
  r.gap = 0.02e-3;
  return r;
}

std::vector<double> radii(double alpha, int points) {
  std::vector<double> rho;
  for (int i = 0; i < points; ++i) rho.push_back(alpha + (1 - alpha) * i / (points - 1.0));
  rho.back() = 1.0;
  return rho;
}

// One harmonic (n = 20) by the exact power-law solution at 41 radii.
void BM_RingExactHarmonic(benchmark::State& state) {
  const Ring r = paper_ring();
  const auto rho = radii(0.472, 41);
  for (auto _ : state) benchmark::DoNotOptimize(solve_exact(r, 20, rho));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RingExactHarmonic);

// One harmonic by the paper's sweep with m intervals: items = nodes.
void BM_RingSweepHarmonic(benchmark::State& state) {
  const Ring r = paper_ring();
  const int m = static_cast<int>(state.range(0));
  const auto rho = radii(0.472, 41);
  for (auto _ : state) benchmark::DoNotOptimize(solve_sweep(r, 20, m, rho));
  state.SetItemsProcessed(state.iterations() * m);
}
BENCHMARK(BM_RingSweepHarmonic)->Arg(400)->Arg(4320);

// The whole analysis with the defaults (N = 380 harmonics): items = harmonics.
void BM_RingAnalyseExact(benchmark::State& state) {
  const Ring r = paper_ring();
  for (auto _ : state) benchmark::DoNotOptimize(analyse(r));
  state.SetItemsProcessed(state.iterations() * 191);
}
BENCHMARK(BM_RingAnalyseExact)->Unit(benchmark::kMillisecond);

// The paper's method with the defaults (N = 380, m = 4320, plus m/2 for Richardson):
// items = harmonics × nodes of the fine grid.
void BM_RingAnalyseSweep(benchmark::State& state) {
  const Ring r = paper_ring();
  Options o;
  o.method = Method::kSweep;
  for (auto _ : state) benchmark::DoNotOptimize(analyse(r, o));
  state.SetItemsProcessed(state.iterations() * 191 * 4320);
}
BENCHMARK(BM_RingAnalyseSweep)->Unit(benchmark::kMillisecond);

// Unilateral contact (active set, dense collocation) with N = 160 and the default N = 380.
void BM_RingUnilateral(benchmark::State& state) {
  const Ring r = paper_ring();
  Options o;
  o.unilateral = true;
  o.harmonics = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(analyse(r, o));
}
BENCHMARK(BM_RingUnilateral)->Arg(160)->Arg(380)->Unit(benchmark::kMillisecond);

}  // namespace
