// Points per second of a 10⁵-point hinge sweep through catena::sweep (bind, run, describe, the
// scalars of every point) on 1 and 2 threads: the thread pool's scaling. docs/performance.md.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

#include "catena/sweep.hpp"

namespace {

// teeth 6..105 × plate radius 8.00..17.99 mm (step 0.01 mm) on the thesis' hinge (d = 40 mm,
// a = 8 mm): 100 × 1000 = 10⁵ points, R1 inside (d/2 - a)/2 .. R1max for most of them.
catena::SweepRequest hinge_request() {
  catena::SweepRequest r;
  r.analysis = "hinge";
  r.base = {{"pin_diameter", "40 mm"},
            {"half_thickness", "8 mm"},
            {"tension", "29.4 kN"},
            {"contact_length", "24 mm"},
            {"allowable_shear", "120 MPa"},
            {"allowable_contact", "1600 MPa"},
            {"friction", "0.15"}};
  catena::SweepAxis teeth{"teeth", {}};
  for (int z = 6; z <= 105; ++z) teeth.values.push_back(std::to_string(z));
  catena::SweepAxis radius{"plate_radius", {}};
  for (int i = 0; i < 1000; ++i) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2fmm", 8.0 + 0.01 * i);
    radius.values.emplace_back(text);
  }
  r.grid = {teeth, radius};
  return r;
}

void BM_HingeSweep(benchmark::State& state) {
  const catena::SweepRequest request = hinge_request();
  catena::SweepOptions options;
  options.threads = static_cast<unsigned>(state.range(0));
  options.keep_records = false;  // what `catena sweep` keeps: scalars and worst diagnostic
  std::size_t points = 0;
  for (auto _ : state) {
    const catena::SweepResult result = catena::sweep(request, options);
    points += result.points.size();
    benchmark::DoNotOptimize(result.points.back().scalars.values.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(points));
}
BENCHMARK(BM_HingeSweep)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace
