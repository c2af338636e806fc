// The boundary simplicity check (check_simple_loop) on large polylines:
// star-shaped polygons with integer vertices (the exact-double CGAL sweep)
// and with decimal vertices scaled to integers, plus one with a huge
// denominator that needs the rational kernel.
#include <benchmark/benchmark.h>

#include <cmath>

#include "fixel/curve.h"

namespace {

using fixel::Rational;
using fixel::Vec2;

// n vertices, radius alternating R and 0.99 R, coordinates rounded to 1/den.
std::vector<fixel::BezierPiece> star(int n, long den) {
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i) {
    const double r = i % 2 ? 9.9e6 : 1e7, a = 2 * M_PI * i / n;
    pts.push_back({Rational(std::lround(r * std::cos(a))) / den, Rational(std::lround(r * std::sin(a))) / den});
  }
  pts.push_back(pts.front());
  fixel::Curve c;
  c.points = pts;
  return c.bezier_pieces(0);
}

void BM_SimpleLoopIntegerPolyline(benchmark::State& state) {
  const auto pieces = star(static_cast<int>(state.range(0)), 1);
  for (auto _ : state) fixel::check_simple_loop(pieces);
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_SimpleLoopIntegerPolyline)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_SimpleLoopDecimalPolyline(benchmark::State& state) {
  const auto pieces = star(static_cast<int>(state.range(0)), 1000);
  for (auto _ : state) fixel::check_simple_loop(pieces);
}
BENCHMARK(BM_SimpleLoopDecimalPolyline)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_SimpleLoopRationalPolyline(benchmark::State& state) {
  auto pieces = star(static_cast<int>(state.range(0)), 1);
  // One coordinate with a denominator above 2^53: no exact double scaling.
  pieces[0].control[0].x += Rational(1) / Rational(fixel::Integer("1000000000000000009"));
  pieces.back().control[1] = pieces[0].control[0];
  for (auto _ : state) fixel::check_simple_loop(pieces);
}
BENCHMARK(BM_SimpleLoopRationalPolyline)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
