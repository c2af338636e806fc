// Pushing region: subdivision against sampling, tight against paper cones,
// the exact ray test against an exact LP, the 2^-20 goal (filtered against
// --exact-only in the same run) and a float64 point sampler written with
// Eigen (what a NumPy user would write instead; decides nothing exactly).
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <vector>

#include "bench_util.h"
#include "fixel/filter.h"
#include "fixel/guaranteed.h"
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

// The same run with every filter off (fixel region --exact-only).
void BM_Goal32PiecesAt2PowMinus20ExactOnly(benchmark::State& state) {
  const Loaded& l = scene(3);
  fixel::RegionOptions opt;
  opt.resolution = Rational(1, 1 << 20);
  fixel::ForceExactScope exact;
  fixel::Region r;
  for (auto _ : state) r = fixel::compute_region(l.scene, l.S, opt);
  state.counters["cone_tests"] = static_cast<double>(r.stats.cone_tests);
}
BENCHMARK(BM_Goal32PiecesAt2PowMinus20ExactOnly)->Unit(benchmark::kMillisecond);

// Subdivision at 2^-10, filtered and exact-only, against the float64 sampler
// at the same spacing (2^10 points per parameter unit).
void BM_Subdivision2PowMinus10(benchmark::State& state) {
  const Loaded& l = scene(static_cast<int>(state.range(0)));
  fixel::RegionOptions opt;
  opt.resolution = Rational(1, 1024);
  fixel::ForceExactScope exact(state.range(1) != 0);
  fixel::Region r;
  for (auto _ : state) r = fixel::compute_region(l.scene, l.S, opt);
  state.counters["cone_tests"] = static_cast<double>(r.stats.cone_tests);
  state.SetLabel(std::string(names[state.range(0)]) + (state.range(1) ? " exact-only" : " filtered"));
}
BENCHMARK(BM_Subdivision2PowMinus10)
    ->Args({3, 0})
    ->Args({3, 1})
    ->Args({0, 0})
    ->Args({0, 1})
    ->Unit(benchmark::kMillisecond);

// The float64 baseline: the scene's Bézier pieces, S's halfspaces and b0 in
// doubles (set up once, outside the timing); per point the de Casteljau
// point and tangent, the push directions of the pusher's friction edges,
// their wrenches and the ray test against S, all in double.
struct DoubleScene {
  std::vector<Eigen::Matrix2Xd> pieces;  // control points as columns
  std::vector<double> u0, u1;
  Eigen::Matrix3Xd a;    // halfspace normals
  Eigen::VectorXd beta;  // c − a·b0
  Eigen::Vector2d c;
  double mu = 0;
};

DoubleScene doubles_of(const Loaded& l) {
  DoubleScene d;
  for (const auto& p : l.scene.body.boundary->pieces) {
    Eigen::Matrix2Xd m(2, p.control.size());
    for (std::size_t k = 0; k < p.control.size(); ++k)
      m.col(static_cast<int>(k)) << fixel::to_double(p.control[k].x), fixel::to_double(p.control[k].y);
    d.pieces.push_back(m);
    d.u0.push_back(fixel::to_double(p.u0));
    d.u1.push_back(fixel::to_double(p.u1));
  }
  const auto& hs = l.S.halfspaces;
  d.a.resize(3, static_cast<int>(hs.size()));
  d.beta.resize(static_cast<int>(hs.size()));
  for (std::size_t k = 0; k < hs.size(); ++k) {
    for (int i = 0; i < 3; ++i) d.a(i, static_cast<int>(k)) = fixel::to_double(hs[k].a[i]);
    d.beta[static_cast<int>(k)] = fixel::to_double(hs[k].c - hs[k].a.dot(l.scene.background_impulse));
  }
  d.c << fixel::to_double(l.scene.body.p_AoCm_A.x), fixel::to_double(l.scene.body.p_AoCm_A.y);
  d.mu = fixel::to_double(l.scene.pusher_mu_upper());
  return d;
}

bool double_ray_hits(const DoubleScene& d, const Eigen::Vector3d& g) {
  double lo = 0, hi = std::numeric_limits<double>::infinity();
  const Eigen::VectorXd alpha = d.a.transpose() * g;
  for (int k = 0; k < alpha.size(); ++k) {
    if (alpha[k] > 0)
      lo = std::max(lo, d.beta[k] / alpha[k]);
    else if (alpha[k] < 0)
      hi = std::min(hi, d.beta[k] / alpha[k]);
    else if (d.beta[k] > 0)
      return false;
  }
  return lo <= hi && hi > 0;
}

// Returns the number of IN samples.
long double_sample(const DoubleScene& d, double spacing) {
  long in = 0;
  Eigen::Matrix2Xd work;
  for (std::size_t k = 0; k < d.pieces.size(); ++k) {
    const Eigen::Matrix2Xd& P = d.pieces[k];
    const int deg = static_cast<int>(P.cols()) - 1;
    for (double u = d.u0[k]; u < d.u1[k]; u += spacing) {
      const double t = (u - d.u0[k]) / (d.u1[k] - d.u0[k]);
      work = P;
      for (int level = deg; level > 1; --level)
        for (int i = 0; i < level; ++i) work.col(i) = (1 - t) * work.col(i) + t * work.col(i + 1);
      const Eigen::Vector2d tangent = work.col(1) - work.col(0);
      const Eigen::Vector2d point = (1 - t) * work.col(0) + t * work.col(1);
      const Eigen::Vector2d n(-tangent.y(), tangent.x()), tt(-n.y(), n.x());
      const Eigen::Vector2d r = point - d.c;
      bool hit = true;
      for (double s : d.mu == 0 ? std::vector<double>{0} : std::vector<double>{-1, 1}) {
        const Eigen::Vector2d dir = (n + s * d.mu * tt).normalized();
        hit = hit && double_ray_hits(d, Eigen::Vector3d(dir.x(), dir.y(), r.x() * dir.y() - r.y() * dir.x()));
      }
      in += hit;
    }
  }
  return in;
}

void BM_Float64EigenSampling2PowMinus10(benchmark::State& state) {
  const DoubleScene d = doubles_of(scene(static_cast<int>(state.range(0))));
  long in = 0;
  for (auto _ : state) benchmark::DoNotOptimize(in = double_sample(d, 1.0 / 1024));
  state.counters["in_samples"] = static_cast<double>(in);
  state.SetLabel(names[state.range(0)]);
}
BENCHMARK(BM_Float64EigenSampling2PowMinus10)->Arg(3)->Arg(0)->Unit(benchmark::kMillisecond);

// The region against G (--guaranteed) on blob32 at 2^-20, filtered and
// exact-only: G's own interval pre-test (OUT and partial from enclosures).
void BM_GuaranteedBlob32At2PowMinus20(benchmark::State& state) {
  const Loaded& l = scene(3);
  static const fixel::GuaranteedSet G = fixel::guaranteed_set(l.scene, l.S);
  fixel::RegionOptions opt;
  opt.resolution = Rational(1, 1 << 20);
  opt.guaranteed = &G;
  fixel::ForceExactScope exact(state.range(0) != 0);
  fixel::Region r;
  for (auto _ : state) r = fixel::compute_region(l.scene, l.S, opt);
  state.counters["cone_tests"] = static_cast<double>(r.stats.cone_tests);
  state.SetLabel(state.range(0) ? "G exact-only" : "G filtered");
}
BENCHMARK(BM_GuaranteedBlob32At2PowMinus20)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Filter decisions and exact fallbacks of one filtered run per scene.
void report_filter_counts() {
  std::cout << "Filter decisions (certified / exact fallbacks) of one filtered region run:\n";
  for (int k : {3, 0, 1, 2}) {
    for (const Rational& res : {Rational(1, 1024), Rational(1, 1 << 20)}) {
      if (k != 3 && res != Rational(1, 1024)) continue;
      const Loaded& l = scene(k);
      fixel::RegionOptions opt;
      opt.resolution = res;
      fixel::ForceExactScope filtered(false);
      fixel::reset_filter_stats();
      const auto r = fixel::compute_region(l.scene, l.S, opt);
      const auto st = fixel::filter_stats();
      std::cout << "  " << names[k] << " at 1/" << fixel::to_string(1 / res) << ":";
      for (auto site : {fixel::FilterSite::kRegionTest, fixel::FilterSite::kInMagnitudes, fixel::FilterSite::kRayTest,
                        fixel::FilterSite::kOutTest, fixel::FilterSite::kOrientation, fixel::FilterSite::kCone})
        std::cout << " " << fixel::to_string(site) << " " << st.at(site).certified << "/" << st.at(site).fallbacks;
      std::cout << " (cone tests " << r.stats.cone_tests << ", OUT tests past the ray shortcut " << r.stats.lp_tests
                << ")\n";
    }
  }
}

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
  report_filter_counts();
  fixel::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios(std::cout);
  return 0;
}
