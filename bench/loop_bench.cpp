// Throughput of the conveyor-loop contour method (seed 000 §1.5 fig. 19). docs/performance.md.
#include <benchmark/benchmark.h>

#include <cmath>

#include "catena/strength/loop.hpp"

namespace {

using namespace catena::strength;

// A 20-segment loop: take-up, then runs alternating with turns and guides (inclines of both
// signs), the drive last.
Loop twenty() {
  Loop l;
  Segment t;
  t.kind = SegmentKind::kTakeup;
  t.pretension = 3000.0;
  l.segments.push_back(t);
  for (int i = 0; i < 18; ++i) {
    Segment s;
    if (i % 2 == 0) {
      s.kind = SegmentKind::kStraight;
      s.length = 10.0 + i;
      s.incline = (i % 4 == 0 ? 0.1 : -0.05);
      s.chain_weight = 300.0;
      s.load_weight = i < 9 ? 0.0 : 800.0;
      s.resistance = 0.1;
    } else {
      s.kind = SegmentKind::kTurn;
      if (i % 3 == 0) {
        s.wrap = 0.2;
        s.friction = 0.25;
      } else {
        s.factor = 1.05;
      }
    }
    l.segments.push_back(s);
  }
  Segment d;
  d.kind = SegmentKind::kDrive;
  d.loss = 0.03;
  l.segments.push_back(d);
  l.speed = 0.3;
  l.efficiency = 0.85;
  l.allowable_tension = 50e3;
  return l;
}

void BM_LoopSolve20Segments(benchmark::State& state) {
  const Loop l = twenty();
  for (auto _ : state) benchmark::DoNotOptimize(solve(l));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LoopSolve20Segments);

}  // namespace
