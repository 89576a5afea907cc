// What the analysis interface costs on top of a model: binding text through the unit parser,
// running, and describing the result as a Record (JSON tree, table, CSV columns, drawing,
// charts). Compare with BM_RunOnClosedForm/guide:2/points:721 (the model alone).
// Results are recorded in docs/performance.md.
#include <benchmark/benchmark.h>

#include "catena/catena.hpp"
#include "catena/io/record.hpp"

namespace {

const std::vector<std::pair<std::string, std::string>> kPocketwheel = {
    {"pitch", "64 mm"},      {"wire", "18 mm"}, {"teeth", "8"},         {"omega", "5 1/s"},
    {"guide", "tangential"}, {"points", "721"}, {"strand_mass", "40kg"}};

// bind + run + describe, by name, as the command line and case files call it
void BM_AnalysisRunByName(benchmark::State& state) {
  for (auto _ : state) {
    catena::analysis::Record r = catena::run("pocketwheel", kPocketwheel);
    benchmark::DoNotOptimize(r.data.size());
  }
}
BENCHMARK(BM_AnalysisRunByName)->Unit(benchmark::kMicrosecond);

// and writing the JSON text `--format json` prints
void BM_AnalysisRunToJson(benchmark::State& state) {
  for (auto _ : state) {
    const std::string json = catena::io::to_json(catena::run("pocketwheel", kPocketwheel).data);
    benchmark::DoNotOptimize(json.data());
  }
}
BENCHMARK(BM_AnalysisRunToJson)->Unit(benchmark::kMicrosecond);

const std::vector<std::pair<std::string, std::string>> kHinge = {{"pin_diameter", "40 mm"},
                                                                 {"half_thickness", "8 mm"},
                                                                 {"teeth", "8"},
                                                                 {"plate_radius", "34 mm"},
                                                                 {"pitch", "125 mm"}};

void BM_AnalysisHingeByName(benchmark::State& state) {
  for (auto _ : state) {
    catena::analysis::Record r = catena::run("hinge", kHinge);
    benchmark::DoNotOptimize(r.data.size());
  }
}
BENCHMARK(BM_AnalysisHingeByName)->Unit(benchmark::kMicrosecond);

}  // namespace
