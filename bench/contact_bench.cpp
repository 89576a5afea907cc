// Throughput of the roller–tooth contact models (seed 001). docs/performance.md.
#include <benchmark/benchmark.h>

#include <numbers>

#include "catena/contact/roller_tooth.hpp"

namespace {

using namespace catena::contact;

RollerTooth roller() {
  RollerTooth c;
  c.roller_diameter = 12.07e-3;
  c.roller_length = 11.68e-3;
  c.tooth_radius = 15.56e-3;
  return c;
}

void BM_HertzLineContact(benchmark::State& state) {
  const RollerTooth c = roller();
  double load = 1000.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(hertz(c, load));
    load = load > 5000 ? 1000 : load + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_HertzLineContact);

void BM_SliceModel(benchmark::State& state) {
  const RollerTooth c = roller();
  const double skew = 42.0 * std::numbers::pi / 10800.0;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        slice_model(c, 1000.0, skew, SliceOptions{static_cast<int>(state.range(0))}));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SliceModel)->Arg(51)->Arg(201)->Unit(benchmark::kMillisecond);

}  // namespace
