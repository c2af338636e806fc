// The C++ side of the binding-overhead figures in docs/python.md: the same
// calls that bench/binding_bench.py times through the Python module.

#include <benchmark/benchmark.h>

#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"

namespace {

const std::string kScenes = std::string(FIXEL_SOURCE_DIR) + "/data/scenes/";

// S.contains(p) with p already exact: the library call itself.
void BM_ContainsCpp(benchmark::State& state) {
  const fixel::SeatingSet S = fixel::seating_set(fixel::load_scene(kScenes + "example2.json"));
  const fixel::VectorQ p = fixel::parse_impulse("-1,-1,-1", 3);
  for (auto _ : state) benchmark::DoNotOptimize(S.contains(p));
}
BENCHMARK(BM_ContainsCpp);

// The same with p parsed from exact text each time, as the binding does.
void BM_ContainsCppFromText(benchmark::State& state) {
  const fixel::SeatingSet S = fixel::seating_set(fixel::load_scene(kScenes + "example2.json"));
  for (auto _ : state) benchmark::DoNotOptimize(S.contains(fixel::parse_impulse("-1,-1,-1", 3)));
}
BENCHMARK(BM_ContainsCppFromText);

// compute_region on the rounded Example 2 part at the default resolution.
void BM_RegionCpp(benchmark::State& state) {
  const fixel::Scene scene = fixel::load_scene(kScenes + "example2_rounded.json");
  const fixel::SeatingSet S = fixel::seating_set(scene);
  fixel::RegionOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(fixel::compute_region(scene, S, options));
}
BENCHMARK(BM_RegionCpp)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
