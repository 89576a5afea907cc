// Throughput of the rolling-friction hinge: syntheses, poses, sweeps. docs/performance.md.
#include <benchmark/benchmark.h>

#include "catena/hinge/kinematics.hpp"
#include "catena/hinge/sweep.hpp"
#include "catena/hinge/synthesis.hpp"

namespace {

using namespace catena::hinge;

Hinge example() {
  Hinge h;
  h.pin_diameter = 0.040;
  h.half_thickness = 0.008;
  h.plate_radius = 0.020;
  h.teeth = 8;
  return h;
}

Loads loads() {
  Loads l;
  l.tension = 29.4e3;
  l.allowable_shear = 100e6;
  l.contact_length = 0.024;
  l.allowable_contact = 1200e6;
  l.friction = 0.15;
  return l;
}

// A full synthesis: R1max, R2, a_min (root finding), sections, Hertz, rolling limit, margin.
void BM_Synthesis(benchmark::State& state) {
  Hinge h = example();
  const Loads l = loads();
  double r1 = 0.020;
  for (auto _ : state) {
    h.plate_radius = r1;
    benchmark::DoNotOptimize(synthesize(h, l));
    r1 = r1 > 0.040 ? 0.012 : r1 + 1e-4;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Synthesis);

void BM_Pose(benchmark::State& state) {
  const Hinge h = example();
  const double r2 = *r2_eq6(h.pin_diameter, h.half_thickness, h.plate_radius, gamma_max(h));
  double phi = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(pose(h, r2, phi));
    phi = phi > 0.78 ? 0.0 : phi + 1e-3;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Pose);

void BM_Sweep100(benchmark::State& state) {
  const Hinge h = example();
  const Loads l = loads();
  for (auto _ : state) benchmark::DoNotOptimize(sweep(h, l, 100));
  state.SetItemsProcessed(state.iterations() * 100);
}
BENCHMARK(BM_Sweep100)->Unit(benchmark::kMillisecond);

}  // namespace
