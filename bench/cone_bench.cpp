// Segment wrench cones: construction time and width, tight against paper.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>
#include <random>

#include "../tests/test_util.h"
#include "bench_util.h"
#include "fixel/wrench_cone.h"

namespace {

using fixel::BezierPiece;
using fixel::Rational;
using fixel::Vec2;

// Random cubic segments around the origin, restricted to sub-segments of
// parameter width 1/4 (a typical subdivision depth).
const std::vector<BezierPiece>& segments() {
  static const std::vector<BezierPiece> all = [] {
    std::vector<BezierPiece> out;
    std::mt19937_64 rng(7);
    while (out.size() < 256) {
      BezierPiece piece{0, Rational(0), Rational(1), {}};
      for (int i = 0; i < 4; ++i)
        piece.control.push_back(
            {fixel::test::random_rational(rng, -2, 2, 9), fixel::test::random_rational(rng, -2, 2, 9)});
      const Rational a(static_cast<int>(out.size() % 4), 4);
      piece = piece.restrict_to(a, a + Rational(1, 4));
      if (fixel::segment_bounds(piece).pointed) out.push_back(piece);
    }
    return out;
  }();
  return all;
}

// Solid angle (steradians, display only) of a cone with generators in
// cyclic order, by Van Oosterom–Strackee on a triangle fan.
double solid_angle(const std::vector<fixel::VectorQ>& g) {
  auto unit = [](const fixel::VectorQ& v) {
    Eigen::Vector3d d(fixel::to_double(v[0]), fixel::to_double(v[1]), fixel::to_double(v[2]));
    return Eigen::Vector3d(d / d.norm());
  };
  // Tight and paper generators come as (d_s, lo), (d_s, hi), (d_e, lo), (d_e, hi).
  const std::vector<Eigen::Vector3d> c = {unit(g[0]), unit(g[1]), unit(g[3]), unit(g[2])};
  double total = 0;
  for (int k = 1; k + 1 < 4; ++k) {
    const Eigen::Vector3d &a = c[0], &b = c[k], &d = c[k + 1];
    total += 2 * std::atan2(std::abs(a.dot(b.cross(d))), 1 + a.dot(b) + b.dot(d) + d.dot(a));
  }
  return total;
}

void report_widths() {
  double tight_sum = 0, paper_sum = 0, max_ratio = 0;
  int n = 0;
  for (const auto& seg : segments()) {
    const auto t = fixel::segment_wrench_cone(seg, {0, 0}, fixel::EdgeFamily::kNormal, 0, fixel::ConeMethod::kTight);
    const auto p = fixel::segment_wrench_cone(seg, {0, 0}, fixel::EdgeFamily::kNormal, 0, fixel::ConeMethod::kPaper);
    if (!t || !p) continue;
    const double wt = solid_angle(t->generators), wp = solid_angle(p->generators);
    tight_sum += wt;
    paper_sum += wp;
    if (wt > 0) max_ratio = std::max(max_ratio, wp / wt);
    ++n;
  }
  std::cout << "Cone width (solid angle, sr) over " << n
            << " random cubic segments of parameter width 1/4, frictionless:\n"
            << "  tight mean " << tight_sum / n << ", paper mean " << paper_sum / n << ", paper/tight of the means "
            << paper_sum / tight_sum << ", largest per-segment ratio " << max_ratio << "\n";
}

void BM_ConeConstruction(benchmark::State& state) {
  const auto method = state.range(0) == 0 ? fixel::ConeMethod::kTight : fixel::ConeMethod::kPaper;
  const auto& all = segments();
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fixel::segment_wrench_cone(all[k], {0, 0}, fixel::EdgeFamily::kNormal, 0, method));
    k = (k + 1) % all.size();
  }
  state.SetLabel(state.range(0) == 0 ? "tight" : "paper");
}
BENCHMARK(BM_ConeConstruction)->Arg(0)->Arg(1)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  report_widths();
  fixel::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios(std::cout);
  return 0;
}
