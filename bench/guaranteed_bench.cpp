// The guaranteed seating set G: time to build it, and membership tests.
#include <benchmark/benchmark.h>

#include <iostream>
#include <random>

#include "../tests/test_util.h"
#include "bench_util.h"
#include "fixel/guaranteed.h"
#include "fixel/scene_json.h"

namespace {

struct Case {
  fixel::Scene scene;
  fixel::SeatingSet S;
};

const Case& design_scene() {
  static const Case c = [] {
    Case k;
    k.scene = fixel::load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/nonunique.json");
    k.S = fixel::seating_set(k.scene);
    return k;
  }();
  return c;
}

const std::vector<Case>& random_scenes() {
  static const std::vector<Case> all = [] {
    std::vector<Case> out;
    std::mt19937_64 rng(101);
    while (out.size() < 8) {
      Case c;
      c.scene = fixel::test::random_scene(rng, 3, 20);
      try {
        c.S = fixel::seating_set(c.scene);
      } catch (const std::exception&) {
        continue;
      }
      out.push_back(std::move(c));
    }
    return out;
  }();
  return all;
}

void BM_BuildG_DesignScene(benchmark::State& state) {
  const Case& c = design_scene();
  for (auto _ : state) benchmark::DoNotOptimize(fixel::guaranteed_set(c.scene, c.S));
}
BENCHMARK(BM_BuildG_DesignScene)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);

void BM_BuildG_RandomScenes(benchmark::State& state) {
  const auto& all = random_scenes();
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fixel::guaranteed_set(all[k].scene, all[k].S));
    k = (k + 1) % all.size();
  }
}
BENCHMARK(BM_BuildG_RandomScenes)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);

void BM_MembershipG(benchmark::State& state) {
  const Case& c = design_scene();
  const fixel::GuaranteedSet G = fixel::guaranteed_set(c.scene, c.S);
  std::mt19937_64 rng(7);
  std::vector<fixel::VectorQ> points;
  for (int k = 0; k < 256; ++k) {
    fixel::VectorQ p = c.S.apex;
    for (const auto& g : c.S.generators) p -= fixel::test::random_rational(rng, -1, 3, 11) * g;
    points.push_back(p);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(G.contains(points[k], c.S));
    k = (k + 1) % points.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MembershipG)->Repetitions(3)->ReportAggregatesOnly(true);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const Case& c = design_scene();
  const fixel::GuaranteedSet G = fixel::guaranteed_set(c.scene, c.S);
  std::cout << "DESIGN scene: " << G.non_seating.size() << " non-seating sets meet S, G has " << G.pieces.size()
            << " pieces, lost fraction " << fixel::to_string(fixel::lost_fraction(c.S, G)) << "\n";
  fixel::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios(std::cout);
  return 0;
}
