// Pushing region: subdivision against sampling, tight against paper cones,
// the exact ray test against an exact LP, and the 2^-20 goal.
#include <benchmark/benchmark.h>

#include <cmath>
#include <iostream>
#include <memory>

#include "bench_util.h"
#include "fixel/internal/exact_lp.h"
#include "fixel/lcp.h"
#include "fixel/region.h"
#include "fixel/scene_json.h"

namespace {

using fixel::Rational;

struct Loaded {
  fixel::Scene scene;
  fixel::SeatingSet S;
};

const Loaded& scene(int which) {
  static const std::vector<std::unique_ptr<Loaded>> all = [] {
    std::vector<std::unique_ptr<Loaded>> out;
    for (const char* name : {"example2_rounded", "blob", "polygon", "blob32"}) {
      auto l = std::make_unique<Loaded>();
      l->scene = fixel::load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/" + name + ".json");
      l->S = fixel::seating_set(l->scene);
      out.push_back(std::move(l));
    }
    return out;
  }();
  return *all.at(which);
}
const char* names[] = {"example2_rounded", "blob", "polygon", "blob32"};

Rational total_range(const fixel::Scene& s) {
  Rational t = 0;
  for (const auto& c : s.body.boundary->curves) t += c.u_end() - c.u_begin();
  return t;
}

void BM_Subdivision(benchmark::State& state) {
  const Loaded& l = scene(static_cast<int>(state.range(0)));
  fixel::RegionOptions opt;
  opt.resolution = Rational(1, 1024);
  fixel::Region r;
  for (auto _ : state) r = fixel::compute_region(l.scene, l.S, opt);
  state.counters["cone_tests"] = static_cast<double>(r.stats.cone_tests);
  state.SetLabel(names[state.range(0)]);
}
BENCHMARK(BM_Subdivision)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// Sampling at the same spacing as the resolution: range / (1/1024) points.
void BM_Sampling(benchmark::State& state) {
  const Loaded& l = scene(static_cast<int>(state.range(0)));
  const Rational range =
      l.scene.body.boundary->curves.front().u_end() - l.scene.body.boundary->curves.front().u_begin();
  const int n = static_cast<int>(boost::multiprecision::numerator(range * 1024) /
                                 boost::multiprecision::denominator(range * 1024));
  fixel::Region r;
  for (auto _ : state) r = fixel::sample_region(l.scene, l.S, n);
  state.counters["point_tests"] = static_cast<double>(r.stats.point_tests);
  state.SetLabel(names[state.range(0)]);
}
BENCHMARK(BM_Sampling)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void BM_SubdivisionPaperCone(benchmark::State& state) {
  const Loaded& l = scene(static_cast<int>(state.range(0)));
  fixel::RegionOptions opt;
  opt.resolution = Rational(1, 1024);
  opt.cone = fixel::ConeMethod::kPaper;
  fixel::Region r;
  for (auto _ : state) r = fixel::compute_region(l.scene, l.S, opt);
  state.counters["cone_tests"] = static_cast<double>(r.stats.cone_tests);
  state.SetLabel(names[state.range(0)]);
}
BENCHMARK(BM_SubdivisionPaperCone)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// The same IN question for one generator: does its ray meet S?
std::vector<fixel::VectorQ> probe_rays() {
  std::vector<fixel::VectorQ> out;
  const Loaded& l = scene(0);
  for (const auto& piece : l.scene.body.boundary->pieces) {
    const auto cone = fixel::segment_wrench_cone(piece, l.scene.body.p_AoCm_A, fixel::EdgeFamily::kNormal, 0,
                                                 fixel::ConeMethod::kTight);
    if (cone) out.insert(out.end(), cone->generators.begin(), cone->generators.end());
  }
  return out;
}

void BM_RayTestExact(benchmark::State& state) {
  const auto rays = probe_rays();
  const Loaded& l = scene(0);
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fixel::ray_magnitudes(l.S, l.scene.background_impulse, rays[k]).empty);
    k = (k + 1) % rays.size();
  }
}
BENCHMARK(BM_RayTestExact);

void BM_RayTestExactLp(benchmark::State& state) {
  const auto rays = probe_rays();
  const Loaded& l = scene(0);
  std::size_t k = 0;
  for (auto _ : state) {
    // max τ s.t. b0 + τ g ∈ S, τ >= 0; the ray hits iff feasible with τ > 0.
    std::vector<fixel::internal::LinearConstraint> rows;
    for (const auto& h : l.S.halfspaces) {
      fixel::VectorQ a(1);
      a[0] = h.a.dot(rays[k]);
      rows.push_back({a, fixel::internal::Relation::kGreaterEqual, h.c - h.a.dot(l.scene.background_impulse)});
    }
    fixel::VectorQ one(1), minus(1);
    one[0] = 1;
    minus[0] = -1;
    rows.push_back({one, fixel::internal::Relation::kGreaterEqual, Rational(0)});
    benchmark::DoNotOptimize(fixel::internal::solve_lp(1, rows, minus).status);
    k = (k + 1) % rays.size();
  }
}
BENCHMARK(BM_RayTestExactLp);

// The goal: resolution 2^-20 on a 32-piece closed cubic B-spline part.
void BM_Goal32PiecesAt2PowMinus20(benchmark::State& state) {
  const Loaded& l = scene(3);
  fixel::RegionOptions opt;
  opt.resolution = Rational(1, 1 << 20);
  fixel::Region r;
  for (auto _ : state) r = fixel::compute_region(l.scene, l.S, opt);
  state.counters["cone_tests"] = static_cast<double>(r.stats.cone_tests);
  state.counters["pieces"] = static_cast<double>(l.scene.body.boundary->pieces.size());
}
BENCHMARK(BM_Goal32PiecesAt2PowMinus20)->Unit(benchmark::kMillisecond);

// The same part at 2^-10, and the exact region (root isolation, issue 15),
// frictionless (the scene's pusher) and with pusher mu = 1/5.
void BM_Blob32SubdivisionAt2PowMinus10(benchmark::State& state) {
  const Loaded& l = scene(3);
  fixel::RegionOptions opt;
  opt.resolution = Rational(1, 1 << 10);
  fixel::Region r;
  for (auto _ : state) r = fixel::compute_region(l.scene, l.S, opt);
  state.counters["cone_tests"] = static_cast<double>(r.stats.cone_tests);
}
BENCHMARK(BM_Blob32SubdivisionAt2PowMinus10)->Unit(benchmark::kMillisecond);

void BM_Blob32Exact(benchmark::State& state) {
  const Loaded& l = scene(3);
  fixel::RegionOptions opt;
  opt.exact = true;
  if (state.range(0)) opt.pusher_mu = Rational(1, 5);
  fixel::Region r;
  for (auto _ : state) r = fixel::compute_region(l.scene, l.S, opt);
  state.counters["roots"] = static_cast<double>(r.stats.roots);
  state.counters["point_tests"] = static_cast<double>(r.stats.point_tests);
  state.SetLabel(state.range(0) ? "pusher mu 1/5" : "frictionless");
}
BENCHMARK(BM_Blob32Exact)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

void report_counts() {
  std::cout << "Per scene at resolution 1/1024 (tight vs paper) and at fixed depth 6 (resolution 1/64):\n";
  for (int k = 0; k < 3; ++k) {
    const Loaded& l = scene(k);
    for (auto method : {fixel::ConeMethod::kTight, fixel::ConeMethod::kPaper}) {
      fixel::RegionOptions fine, coarse;
      fine.resolution = Rational(1, 1024);
      fine.cone = coarse.cone = method;
      coarse.resolution = Rational(1, 64);
      const auto a = fixel::compute_region(l.scene, l.S, fine), b = fixel::compute_region(l.scene, l.S, coarse);
      std::cout << "  " << names[k] << " " << (method == fixel::ConeMethod::kTight ? "tight" : "paper")
                << ": cone tests to 1/1024 " << a.stats.cone_tests << ", partial length at 1/64 "
                << fixel::to_double(b.stats.partial_length) << " of " << fixel::to_double(total_range(l.scene)) << "\n";
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  report_counts();
  fixel::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios(std::cout);
  return 0;
}
