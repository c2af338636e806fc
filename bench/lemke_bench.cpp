// Exact lexicographic Lemke (forced exact, and filtered: interval tableau with
// the exact tableau as fallback) against a double-precision Lemke and
// Siconos's lcp_lexicolemke (when available) on the seating LCPs of random
// scenes.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <string>

#include "../tests/test_util.h"
#include "bench_util.h"
#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/lemke_filtered.h"
#include "fixel/internal/lemke_prepared.h"
#include "fixel/lcp.h"
#include "fixel/lemke.h"
#include "fixel/seating.h"

#ifdef FIXEL_HAVE_SICONOS
#include <siconos/numerics/LCP_Solvers.h>
#include <siconos/numerics/LinearComplementarityProblem.h>
#include <siconos/numerics/NumericsMatrix.h>
#include <siconos/numerics/SolverOptions.h>
#include <siconos/numerics/lcp_cst.h>
#endif

namespace {

using fixel::MatrixQ;
using fixel::Rational;
using fixel::VectorQ;

// Each solver gets B in its own form, made once per problem outside the
// timed loops: Siconos and the double Lemke B in doubles, fixel's prepared
// solve a LemkeMatrix (B with its enclosures and integer rows).
struct Problem {
  MatrixQ B;
  VectorQ b;
  Eigen::MatrixXd Bd;
  Eigen::VectorXd bd;
  fixel::LemkeMatrix prepared;
  // The same parts as the filtered run's own, for the pivot path alone.
  std::shared_ptr<fixel::internal::PreparedLemkeMatrix> path_parts;
};

std::shared_ptr<fixel::internal::PreparedLemkeMatrix> path_parts(const MatrixQ& B) {
  auto parts = std::make_shared<fixel::internal::PreparedLemkeMatrix>();
  parts->B = B;
  {
    fixel::internal::Protect guard;
    parts->intervals.assign(parts->B);
  }
  parts->scaled.assign(parts->B);
  return parts;
}

// Seating LCPs (size 12) of random 3-fixel scenes, at impulses around S.
const std::vector<Problem>& problems() {
  static const std::vector<Problem> all = [] {
    std::vector<Problem> out;
    std::mt19937_64 rng(2026);
    while (out.size() < 64) {
      fixel::Scene scene = fixel::test::random_scene(rng, 3);
      fixel::SeatingSet S;
      try {
        S = fixel::seating_set(scene);
      } catch (const fixel::Error&) {
        continue;
      }
      VectorQ p = S.apex;
      for (int j = 0; j < 3; ++j) p -= fixel::test::random_rational(rng, -1, 3, 7) * S.generators[j];
      const fixel::TimeSteppingLcp lcp = fixel::build_lcp(scene);
      Problem pr{
          lcp.B, lcp.b(p), Eigen::MatrixXd(12, 12), Eigen::VectorXd(12), fixel::LemkeMatrix(lcp.B), path_parts(lcp.B)};
      for (int i = 0; i < 12; ++i) {
        pr.bd[i] = fixel::to_double(pr.b[i]);
        for (int j = 0; j < 12; ++j) pr.Bd(i, j) = fixel::to_double(pr.B(i, j));
      }
      out.push_back(std::move(pr));
    }
    return out;
  }();
  return all;
}

// Textbook double-precision Lemke: covering vector e, smallest-ratio rule
// with a tolerance, no lexicographic tie-breaking.
bool double_lemke(const Eigen::MatrixXd& B, const Eigen::VectorXd& b, Eigen::VectorXd& z) {
  const int n = static_cast<int>(b.size());
  const double tol = 1e-12;
  z = Eigen::VectorXd::Zero(n);
  if (b.minCoeff() >= 0) return true;
  Eigen::MatrixXd T(n, 2 * n + 2);
  T << Eigen::MatrixXd::Identity(n, n), -B, -Eigen::VectorXd::Ones(n), b;
  std::vector<int> basis(n);
  for (int i = 0; i < n; ++i) basis[i] = i;
  auto pivot = [&](int r, int s) {
    T.row(r) /= T(r, s);
    for (int i = 0; i < n; ++i)
      if (i != r) T.row(i) -= T(i, s) * T.row(r);
    basis[r] = s;
  };
  int r;
  T.col(2 * n + 1).minCoeff(&r);
  int entering = basis[r] + n;
  pivot(r, 2 * n);
  for (int it = 0; it < 1000; ++it) {
    int best = -1;
    double ratio = 0;
    for (int i = 0; i < n; ++i)
      if (T(i, entering) > tol) {
        const double q = T(i, 2 * n + 1) / T(i, entering);
        if (best < 0 || q < ratio - tol || (q <= ratio + tol && basis[i] == 2 * n)) best = i, ratio = q;
      }
    if (best < 0) return false;
    const int leaving = basis[best];
    pivot(best, entering);
    if (leaving == 2 * n) {
      for (int i = 0; i < n; ++i)
        if (basis[i] >= n && basis[i] < 2 * n) z[basis[i] - n] = T(i, 2 * n + 1);
      return true;
    }
    entering = leaving < n ? leaving + n : leaving - n;
  }
  return false;
}

#ifdef FIXEL_HAVE_SICONOS
bool siconos_lemke(const Eigen::MatrixXd& B, const Eigen::VectorXd& b, Eigen::VectorXd& z) {
  const int n = static_cast<int>(b.size());
  Eigen::MatrixXd M = B;  // column-major, as Siconos expects
  Eigen::VectorXd q = b, w(n);
  z = Eigen::VectorXd::Zero(n);
  NumericsMatrix* NM = NM_create_from_data(NM_DENSE, n, n, M.data());
  LinearComplementarityProblem problem{n, NM, q.data()};
  SolverOptions* options = solver_options_create(SICONOS_LCP_LEMKE);
  int info = 0;
  lcp_lexicolemke(&problem, z.data(), w.data(), &info, options);
  solver_options_delete(options);
  NM->matrix0 = nullptr;  // the data belongs to M
  NM_clear(NM);
  free(NM);
  return info == 0;
}
#endif

// A double solution disagrees if its status differs from the exact one or
// its support {i : z_i > 1e-9} differs from the exact support.
template <typename Solver>
int report_disagreements(const char* name, Solver solve) {
  int disagreements = 0;
  const auto& all = problems();
  for (std::size_t k = 0; k < all.size(); ++k) {
    const auto exact = fixel::solve_lcp_lemke(all[k].B, all[k].b);
    Eigen::VectorXd z;
    const bool ok = solve(all[k].Bd, all[k].bd, z);
    bool differ = ok != (exact.status == fixel::LemkeStatus::kSolved);
    double worst = 0;
    if (!differ && ok)
      for (int i = 0; i < 12; ++i) {
        differ = differ || ((z[i] > 1e-9) != (exact.z[i] > 0));
        worst = std::max(worst, std::abs(z[i] - fixel::to_double(exact.z[i])));
      }
    if (differ) {
      ++disagreements;
      // Seating LCPs may have several solutions. Decide exactly whether the
      // complementary basis the solver ended on (z_i basic where z_i > w_i)
      // is an exact solution: solve it in rationals and check it.
      std::string verdict = "no solution reported";
      if (ok) {
        const Eigen::VectorXd w = all[k].Bd * z + all[k].bd;
        std::vector<int> S;
        for (int i = 0; i < 12; ++i)
          if (z[i] > w[i]) S.push_back(i);
        VectorQ zq = VectorQ::Zero(12);
        bool solvable = true;
        if (!S.empty()) {
          MatrixQ BSS(S.size(), S.size());
          VectorQ bS(S.size());
          for (std::size_t r = 0; r < S.size(); ++r) {
            bS[r] = -all[k].b[S[r]];
            for (std::size_t c = 0; c < S.size(); ++c) BSS(r, c) = all[k].B(S[r], S[c]);
          }
          const auto lu = fixel::internal::exact_lu(BSS);
          solvable = lu.isInvertible();
          if (solvable) {
            const VectorQ zS = lu.solve(bS);
            for (std::size_t r = 0; r < S.size(); ++r) zq[S[r]] = zS[r];
          }
        }
        verdict = solvable && fixel::is_solution(all[k].B, all[k].b, VectorQ(all[k].B * zq + all[k].b), zq)
                      ? "its basis is an exact solution (another solution of a non-unique LCP)"
                      : "its basis is NOT an exact solution";
      }
      std::cout << "  " << name << " disagrees on problem " << k << " (exact: " << fixel::to_string(exact.status)
                << ", double: " << (ok ? "solved" : "failed") << ", max |dz| " << worst << "): " << verdict << "\n";
    }
  }
  std::cout << name << ": " << disagreements << " of " << all.size() << " problems disagree with exact Lemke\n";
  return disagreements;
}

void BM_ExactLemke(benchmark::State& state) {
  const auto& all = problems();
  fixel::ForceExactScope exact;
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fixel::solve_lcp_lemke(all[k].B, all[k].b));
    k = (k + 1) % all.size();
  }
}
BENCHMARK(BM_ExactLemke)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_FilteredLemke(benchmark::State& state) {
  const auto& all = problems();
  fixel::ForceExactScope filtered(false);
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fixel::solve_lcp_lemke(all[k].B, all[k].b));
    k = (k + 1) % all.size();
  }
}
BENCHMARK(BM_FilteredLemke)->Repetitions(5)->ReportAggregatesOnly(true);

// The same solves into one LemkeResult reused from solve to solve (the
// overload for callers solving in a loop): the result's rationals are not
// allocated anew each time.
void BM_FilteredLemkeIntoReusedResult(benchmark::State& state) {
  const auto& all = problems();
  fixel::ForceExactScope filtered(false);
  fixel::LemkeResult result;
  std::size_t k = 0;
  for (auto _ : state) {
    fixel::solve_lcp_lemke(all[k].B, all[k].b, result);
    benchmark::DoNotOptimize(result);
    k = (k + 1) % all.size();
  }
}
BENCHMARK(BM_FilteredLemkeIntoReusedResult)->Repetitions(5)->ReportAggregatesOnly(true);

// The same with each problem's B prepared (a LemkeMatrix, made once per
// problem as Bd is for Siconos): what a solve costs in a stepper.
void BM_FilteredLemkePreparedIntoReusedResult(benchmark::State& state) {
  const auto& all = problems();
  fixel::ForceExactScope filtered(false);
  fixel::LemkeResult result;
  std::size_t k = 0;
  for (auto _ : state) {
    fixel::solve_lcp_lemke(all[k].prepared, all[k].b, result);
    benchmark::DoNotOptimize(result);
    k = (k + 1) % all.size();
  }
}
BENCHMARK(BM_FilteredLemkePreparedIntoReusedResult)->Repetitions(5)->ReportAggregatesOnly(true);

// Preparing B: what the prepared solves leave out of each solve.
void BM_PrepareLemkeMatrix(benchmark::State& state) {
  const auto& all = problems();
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fixel::LemkeMatrix(all[k].B));
    k = (k + 1) % all.size();
  }
}
BENCHMARK(BM_PrepareLemkeMatrix)->Repetitions(5)->ReportAggregatesOnly(true);

// The filtered run's pivot path alone, without its exact final values: what
// the interval path and its tie certificates cost, a floor for
// BM_FilteredLemke (docs/performance.md). Every problem here has a negative
// b entry, so solve_lcp_lemke would run exactly this path. `prepared`: with
// B's prepared parts, the path of BM_FilteredLemkePreparedIntoReusedResult.
void pivot_path_only(benchmark::State& state, bool prepared) {
  const auto& all = problems();
  for (const auto& pr : all)
    if ((pr.b.array() >= Rational(0)).all()) state.SkipWithError("a problem with b >= 0 never reaches the pivot path");
  fixel::ForceExactScope filtered(false);
  fixel::LemkeResult result;
  std::vector<int> basis;
  std::size_t k = 0;
  for (auto _ : state) {
    const int n = static_cast<int>(all[k].b.size());
    benchmark::DoNotOptimize(fixel::internal::filtered_lemke_path(all[k].B, all[k].b, 100 * (n + 1), result, basis,
                                                                  prepared ? all[k].path_parts.get() : nullptr));
    k = (k + 1) % all.size();
  }
}

void BM_LemkePivotPathOnly(benchmark::State& state) { pivot_path_only(state, false); }
BENCHMARK(BM_LemkePivotPathOnly)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_LemkePreparedPivotPathOnly(benchmark::State& state) { pivot_path_only(state, true); }
BENCHMARK(BM_LemkePreparedPivotPathOnly)->Repetitions(5)->ReportAggregatesOnly(true);

// Filtered against forced exact on all problems: status, pivots, w and z.
void report_filtered_agreement() {
  int differ = 0;
  fixel::reset_filter_stats();
  fixel::internal::reset_final_value_counts();
  for (const auto& pr : problems()) {
    fixel::LemkeResult f, e;
    {
      fixel::ForceExactScope filtered(false);
      f = fixel::solve_lcp_lemke(pr.B, pr.b);
    }
    {
      fixel::ForceExactScope exact;
      e = fixel::solve_lcp_lemke(pr.B, pr.b);
    }
    differ += f.status != e.status || f.pivots != e.pivots || f.w != e.w || f.z != e.z;
  }
  const auto c = fixel::filter_stats().at(fixel::FilterSite::kLemke);
  const auto ties = fixel::filter_stats().at(fixel::FilterSite::kLemkeTie);
  const auto values = fixel::internal::final_value_counts();
  std::cout << "filtered Lemke: " << differ << " of " << problems().size()
            << " problems differ from forced exact Lemke; decisions certified " << c.certified << ", exact fallback "
            << c.fallbacks << "; exact ties proved by a null vector " << ties.certified << ", not proved "
            << ties.fallbacks << "; final values by p-adic lifting " << values.dixon << ", from the factored block "
            << values.factored << " (unknowns fixed by short rows first " << values.unknowns_eliminated
            << ", lifting steps " << values.lifting_steps << ", reconstructions tried " << values.reconstructions
            << "; factors the first denominator lacked, found by trial " << values.factors_by_trial
            << ", by reconstruction " << values.factors_by_reconstruction
            << "); z0-row decisions settled by the final values " << values.z0_settled << ", runs repeated "
            << values.z0_reruns << "\n";
  int prepared_differ = 0;
  for (const auto& pr : problems()) {
    fixel::ForceExactScope filtered(false);
    const fixel::LemkeResult f = fixel::solve_lcp_lemke(pr.prepared, pr.b);
    fixel::ForceExactScope exact;
    const fixel::LemkeResult e = fixel::solve_lcp_lemke(pr.B, pr.b);
    prepared_differ += f.status != e.status || f.pivots != e.pivots || f.w != e.w || f.z != e.z;
  }
  std::cout << "filtered Lemke with B prepared (LemkeMatrix): " << prepared_differ << " of " << problems().size()
            << " problems differ from forced exact Lemke\n";
}

// Per-problem times: each problem solved `reps` times by each solver in
// turn (so machine noise hits all alike), the mean per solve kept; then the
// median over the 64 problems, and each problem's ratio filtered / Siconos.
void report_per_problem_times() {
  constexpr int reps = 100;
  using clock = std::chrono::steady_clock;
  std::vector<double> filtered, reused, prepared, path, preparing, doubles, siconos, ratios, reused_ratios,
      prepared_ratios;
  std::vector<int> basis;
  fixel::LemkeResult path_result;  // the path alone leaves w and z empty
  Eigen::VectorXd z;
  fixel::LemkeResult result;  // solve_lcp_lemke into a caller's result, as the stepper does
  for (const auto& pr : problems()) {
    fixel::ForceExactScope filter(false);
    auto time = [&](auto&& solve) {
      const auto t0 = clock::now();
      for (int r = 0; r < reps; ++r) solve();
      return std::chrono::duration<double, std::micro>(clock::now() - t0).count() / reps;
    };
    filtered.push_back(time([&] { benchmark::DoNotOptimize(fixel::solve_lcp_lemke(pr.B, pr.b)); }));
    reused.push_back(time([&] {
      fixel::solve_lcp_lemke(pr.B, pr.b, result);
      benchmark::DoNotOptimize(result);
    }));
    prepared.push_back(time([&] {
      fixel::solve_lcp_lemke(pr.prepared, pr.b, result);
      benchmark::DoNotOptimize(result);
    }));
    path.push_back(time([&] {
      const int n = static_cast<int>(pr.b.size());
      benchmark::DoNotOptimize(
          fixel::internal::filtered_lemke_path(pr.B, pr.b, 100 * (n + 1), path_result, basis, pr.path_parts.get()));
    }));
    preparing.push_back(time([&] { benchmark::DoNotOptimize(fixel::LemkeMatrix(pr.B)); }));
    doubles.push_back(time([&] { benchmark::DoNotOptimize(double_lemke(pr.Bd, pr.bd, z)); }));
#ifdef FIXEL_HAVE_SICONOS
    siconos.push_back(time([&] { benchmark::DoNotOptimize(siconos_lemke(pr.Bd, pr.bd, z)); }));
    ratios.push_back(filtered.back() / siconos.back());
    reused_ratios.push_back(reused.back() / siconos.back());
    prepared_ratios.push_back(prepared.back() / siconos.back());
#endif
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : (v[(v.size() - 1) / 2] + v[v.size() / 2]) / 2;
  };
  auto range = [](const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return "[" + std::to_string(*lo) + ", " + std::to_string(*hi) + "]";
  };
  auto mean = [](const std::vector<double>& v) {
    double sum = 0;
    for (const double x : v) sum += x;
    return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
  };
  // The benchmarks above cycle through the problems; these loops repeat
  // each one, so its branches are learnt: the means show what cycling costs.
  std::cout << "per problem (mean of " << reps
            << " solves each in a row), median over the 64 problems [min, max]; mean:\n"
            << "  filtered exact Lemke  " << median(filtered) << " us " << range(filtered) << "; " << mean(filtered)
            << " us\n"
            << "  the same into a reused result  " << median(reused) << " us " << range(reused) << "; " << mean(reused)
            << " us\n"
            << "  the same with B prepared (LemkeMatrix)  " << median(prepared) << " us " << range(prepared) << "; "
            << mean(prepared) << " us\n"
            << "  its pivot path alone (no exact values)  " << median(path) << " us " << range(path) << "; "
            << mean(path) << " us\n"
            << "  preparing B (LemkeMatrix)  " << median(preparing) << " us " << range(preparing) << "; "
            << mean(preparing) << " us\n"
            << "  double Lemke          " << median(doubles) << " us " << range(doubles) << "; " << mean(doubles)
            << " us\n";
#ifdef FIXEL_HAVE_SICONOS
  std::cout << "  Siconos lexicolemke   " << median(siconos) << " us " << range(siconos) << "; " << mean(siconos)
            << " us\n"
            << "  filtered / Siconos: median of the ratios " << median(ratios) << ", range " << range(ratios)
            << "; ratio of the medians " << median(filtered) / median(siconos) << "\n"
            << "  into a reused result / Siconos: median of the ratios " << median(reused_ratios) << ", range "
            << range(reused_ratios) << "; ratio of the medians " << median(reused) / median(siconos) << "\n"
            << "  with B prepared / Siconos: median of the ratios " << median(prepared_ratios) << ", range "
            << range(prepared_ratios) << "; ratio of the medians " << median(prepared) / median(siconos) << "\n";
#endif
}

void BM_DoubleLemke(benchmark::State& state) {
  const auto& all = problems();
  std::size_t k = 0;
  Eigen::VectorXd z;
  for (auto _ : state) {
    benchmark::DoNotOptimize(double_lemke(all[k].Bd, all[k].bd, z));
    k = (k + 1) % all.size();
  }
}
BENCHMARK(BM_DoubleLemke)->Repetitions(5)->ReportAggregatesOnly(true);

#ifdef FIXEL_HAVE_SICONOS
void BM_SiconosLexicoLemke(benchmark::State& state) {
  const auto& all = problems();
  std::size_t k = 0;
  Eigen::VectorXd z;
  for (auto _ : state) {
    benchmark::DoNotOptimize(siconos_lemke(all[k].Bd, all[k].bd, z));
    k = (k + 1) % all.size();
  }
}
BENCHMARK(BM_SiconosLexicoLemke)->Repetitions(5)->ReportAggregatesOnly(true);
#endif

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::cout << "Seating LCPs of " << problems().size()
            << " random 3-fixel scenes (size 12); one solve per iteration.\n";
  report_filtered_agreement();
  report_per_problem_times();
  report_disagreements("double Lemke", double_lemke);
#ifdef FIXEL_HAVE_SICONOS
  report_disagreements("Siconos lcp_lexicolemke", siconos_lemke);
#else
  std::cout << "Siconos not found at configure time: its benchmark is skipped.\n";
#endif
  fixel::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios(std::cout);
  return 0;
}
