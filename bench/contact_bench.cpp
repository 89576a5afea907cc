// Throughput of the roller–tooth contact models (seed 001). docs/performance.md.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
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

// The line law's inverse (LineApproach::load, docs/models/dynamics.md "Contact law"), as the
// dynamics' seat law calls it: the 12B roller (b1 = 11.68 mm) in the seat of the dynamics' tooth
// form (ISO 606's smallest seating radius, r_i = 0.505 d1), at the approaches of 64 loads spaced
// evenly in ln Q over 10 N … 50 kN (the law's cap: 50.4 kN), taken in turn. Independent of the
// trajectory, unlike the drive's seat-law benchmark.
void BM_LineApproachLoad(benchmark::State& state) {
  RollerTooth c = roller();
  c.tooth_radius = 0.505 * c.roller_diameter;
  c.profile = Profile::kConcave;
  const LineApproach law = line_approach(c);
  std::array<double, 64> approach{};
  for (std::size_t k = 0; k < approach.size(); ++k) {
    const double load = 10.0 * std::pow(5000.0, static_cast<double>(k) / (approach.size() - 1));
    approach[k] = law.approach(load / c.roller_length);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(law.load(approach[k]));
    k = (k + 1) % approach.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LineApproachLoad);

}  // namespace
