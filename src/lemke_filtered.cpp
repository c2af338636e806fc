#include "fixel/internal/lemke_filtered.h"

#include <atomic>
#include <limits>
#include <vector>

#include "fixel/error.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/lemke_dixon.h"
#include "fixel/internal/lemke_dixon_words.h"
#include "fixel/internal/lemke_exact.h"
#include "fixel/internal/lemke_interval.h"
#include "fixel/internal/lemke_prepared.h"
#include "fixel/internal/lemke_scaled.h"
#include "fixel/internal/lemke_tie.h"

namespace fixel::internal {

namespace {

std::atomic<long> g_dixon_values{0}, g_factored_values{0}, g_lifting_steps{0}, g_reconstructions{0};
std::atomic<long> g_factors_by_trial{0}, g_factors_by_reconstruction{0}, g_unknowns_eliminated{0};
std::atomic<long> g_z0_settled{0}, g_z0_reruns{0};
std::atomic<bool> g_defer_every_z0_comparison{false};

// The exact side's storage, kept per thread so that GMP limbs are reused.
struct ExactWorkspace {
  ScaledProblem problem;
  ExactTableau tableau;
  BasicValues final_values;
  TieCertifier ties;
  std::vector<int> tie_basis;
};

ExactWorkspace& exact_workspace() {
  thread_local ExactWorkspace workspace;
  return workspace;
}

// One filtered run: each decision of the exact run (src/lemke.cpp) is taken
// from the intervals when they certify it, else from the exact tableau at the
// current basis (built lazily, dropped at each pivot). So the pivots, and the
// final basis, are the exact run's.
//
// One decision may be settled later instead: the z0 row against another row
// in a ratio test when the intervals cannot order their ratios. The z0 row
// wins ties, so "the z0 row wins" is right iff no candidate's ratio is
// below the z0 row's, iff every basic value after pivoting on it is ≥ 0;
// and that pivot is the last. So with `settle_z0_by_values` the run takes
// the z0 row, finds the final values exactly as always, and their exact
// signs settle the decision (docs/theory.md §6). A negative value means it
// was wrong: settlement_failed() says so and the caller runs again
// without settling (the decision is then proved or made exactly).
class FilteredRun {
 public:
  FilteredRun(const MatrixQ& B, const VectorQ& b, bool settle_z0_by_values = false,
              const PreparedLemkeMatrix* prepared = nullptr)
      : B_(B),
        b_(b),
        n_(static_cast<int>(b.size())),
        prepared_(prepared),
        T_(prepared != nullptr ? IntervalTableau(prepared->intervals, b) : IntervalTableau(B, b)),
        settle_z0_(settle_z0_by_values) {}
  ~FilteredRun() {
    record_filter(FilterSite::kLemke, certified_, exact_);
    record_filter(FilterSite::kLemkeTie, ties_proved_, ties_unproved_);
  }

  // Whether the last run's values showed a z0-row decision wrong: `result`
  // is then not set, and the run must be repeated without settling.
  bool settlement_failed() const { return settlement_failed_; }

  // With `values` false (filtered_lemke_path) the run stops at the final
  // basis: no exact values, w and z left empty.
  bool run(int max_pivots, LemkeResult& result, bool values = true) {
    // z0 enters; the row with the most negative b leaves, ties to the larger index.
    int r = 0;
    for (int i = 1; i < n_; ++i) {
      int c = certain_sign(T_.at(i, T_.rhs()) - T_.at(r, T_.rhs()));
      if (c == kUndecided) {
        c = fixel::sign(b_[i] - b_[r]);
        ++exact_;
      } else {
        ++certified_;
      }
      if (c <= 0) r = i;
    }
    int entering = T_.complement(T_.basic(r));
    if (!pivot(r, T_.z0())) return false;
    int pivots = 1;
    LemkeStatus status = LemkeStatus::kSolved;
    while (true) {
      if (pivots >= max_pivots) {
        status = LemkeStatus::kPivotLimit;
        break;
      }
      r = ratio_test(entering);
      if (r < 0) {
        status = LemkeStatus::kRayTermination;
        break;
      }
      final_settles_ = z0_taken_unordered_;  // then r is the z0 row: the last pivot
      const int leaving = T_.basic(r);
      // The last pivot: when this basis's exact columns are at hand (the z0
      // row usually wins a tie), the final values follow from them.
      if (leaving == T_.z0() && tableau_current_) {
        ExactTableau& E = exact_workspace().tableau;
        if (E.has_column(T_.rhs()) && E.has_column(entering))
          final_ready_ = E.basic_values_after_pivot(r, entering, T_.rhs(), final_);
      }
      if (!pivot(r, entering)) return false;
      ++pivots;
      if (leaving == T_.z0()) break;
      entering = T_.complement(leaving);
    }
    if (status == LemkeStatus::kSolved && values) {
      // Dixon's values first (their equations hold by construction, so only
      // signs and basis are checked); the factored block when lifting
      // declines, with the full check.
      bool equations_hold = false;
      if (!final_ready_) {
        thread_local std::vector<double> rhs_lo, rhs_hi;
        rhs_lo.resize(n_);
        rhs_hi.resize(n_);
        for (int t = 0; t < n_; ++t) {
          const FI x = T_.at(t, T_.rhs());
          rhs_lo[t] = x.inf();
          rhs_hi[t] = x.sup();
        }
        DixonTrace trace;
        equations_hold = dixon_basic_values(problem(), T_.basis(), rhs_lo, rhs_hi, final_, trace);
        ++(equations_hold ? g_dixon_values : g_factored_values);
        g_lifting_steps += trace.steps;
        g_reconstructions += trace.attempts;
        g_factors_by_trial += trace.factors_by_trial;
        g_factors_by_reconstruction += trace.factors_by_reconstruction;
        g_unknowns_eliminated += trace.unknowns_eliminated;
        if (!equations_hold) exact().basic_values(T_.rhs(), final_);
      }
      thread_local std::vector<int> row_of;
      const bool solves = equations_hold ? complementary_and_nonnegative(n_, T_.basis(), final_, row_of)
                                         : solves_lcp_at_basis(exact_workspace().problem, T_.basis(), final_);
      if (final_settles_) ++(solves ? g_z0_settled : g_z0_reruns);
      if (!solves) {
        if (final_settles_) {  // a negative value: the z0 row should not have won
          settlement_failed_ = true;
          return true;
        }
        // Never report a wrong "solved" (the exact path uses is_solution).
        throw InternalError("solve_lcp_lemke: the filtered run's final values fail the exact check of the equations");
      }
    }
    result.status = status;
    result.pivots = pivots;
    if (status != LemkeStatus::kSolved || !values) {
      result.w.resize(0);
      result.z.resize(0);
    } else {
      // Into the result's own storage when it has the size already (a
      // caller solving in a loop): each basic value in lowest terms,
      // written straight in (den > 0), then zeros for the rest (the
      // nonbasic variables and basic ones of value 0).
      result.w.resize(n_);
      result.z.resize(n_);
      const auto value = [&](int var) { return (var < n_ ? result.w[var] : result.z[var - n_]).backend().data(); };
      thread_local std::vector<char> written;
      written.assign(2 * n_, 0);
      thread_local Integer den_w, g;
      for (int t = 0; t < n_; ++t) {
        const int v = T_.basic(t);
        const mpz_srcptr num = mp(final_.num[t]);
        if (mpz_sgn(num) == 0) continue;
        written[v] = 1;
        auto* q = value(v);
        mpz_srcptr den = mp(final_.den);
        if (v < n_) {
          mpz_mul(mp(den_w), den, mp(exact_workspace().problem.scale(v)));
          den = mp(den_w);
        }
        if (lowest_terms_in_words(num, den, q)) continue;  // the seating LCPs' usual case
        mpz_gcd(mp(g), num, den);
        mpz_divexact(mpq_numref(q), num, mp(g));
        mpz_divexact(mpq_denref(q), den, mp(g));
      }
      for (int var = 0; var < 2 * n_; ++var)
        if (!written[var]) mpq_set_ui(value(var), 0, 1);
    }
    return true;
  }

  // The basic variable of each tableau row.
  const std::vector<int>& basis() const { return T_.basis(); }

 private:
  ExactTableau& exact() {
    ExactWorkspace& ws = exact_workspace();
    if (!tableau_current_) {
      ws.tableau.assign(problem(), T_.basis());
      tableau_current_ = true;
    }
    return ws.tableau;
  }

  bool pivot(int r, int s) {
    if (certain_sign(T_.at(r, s)) == kUndecided) return false;  // the division would lose everything
    T_.pivot(r, s);
    tableau_current_ = false;
    return true;
  }

  // Sign of T(i, col)·T(j, s) − T(j, col)·T(i, s): the ratio T(i, col)/T(i, s)
  // against T(j, col)/T(j, s) when both T(·, s) > 0.
  int compare_ratio(int i, int j, int col, int s) {
    const int c = certain_sign(T_.at(i, col) * T_.at(j, s) - T_.at(j, col) * T_.at(i, s));
    if (c != kUndecided) return ++certified_, c;
    if (certified_tie(i, j, col, s)) return ++certified_, 0;  // no fallback ran
    ++exact_;
    return exact().cross_sign(i, j, col, s);
  }

  const ScaledProblem& problem() {
    ExactWorkspace& ws = exact_workspace();
    if (!scaled_) {
      if (prepared_ != nullptr)
        ws.problem.assign(prepared_->scaled, b_);
      else
        ws.problem.assign(B_, b_);
      scaled_ = true;
    }
    return ws.problem;
  }

  // Whether T(i, col)·T(j, s) − T(j, col)·T(i, s) = 0, proved exactly
  // (internal/lemke_tie.h): that 2×2 minor of the tableau is
  // det A_β' / det A_β, β' being β with row i's basic variable replaced by
  // col and row j's by s.
  bool certified_tie(int i, int j, int col, int s) {
    ExactWorkspace& ws = exact_workspace();
    ws.tie_basis = T_.basis();
    ws.tie_basis[i] = col;
    ws.tie_basis[j] = s;
    const bool proved = ws.ties.singular(ws.tie_basis, T_.approx(), problem());
    ++(proved ? ties_proved_ : ties_unproved_);
    return proved;
  }

  // The lexicographic minimum ratio test of Tableau::ratio_test in
  // src/lemke.cpp, decision by decision. Its answer is the minimum of a
  // total order on the candidate rows (ratio, then the z0 row, then the
  // lexicographic columns), so the rows may be visited in any order: rows
  // whose entry sign the intervals leave open go last, and one that
  // certainly loses to the best so far, whatever that sign is, needs no
  // exact sign (docs/theory.md §6).
  //
  // With settling on, an unordered comparison of the z0 row with another
  // row is taken as a z0 win (z0_taken_unordered_). That holds only if the
  // z0 row is still best at the end; otherwise the test runs again with
  // every decision made.
  int ratio_test(int s) {
    z0_taken_unordered_ = false;
    const int best = ratio_test_once(s, settle_z0_);
    if (!z0_taken_unordered_ || T_.basic(best) == T_.z0()) return best;
    z0_taken_unordered_ = false;
    return ratio_test_once(s, false);
  }

  //
  // Rows with a certainly positive entry first, each with an enclosure of
  // its ratio; a row whose ratio is certainly above another's (its
  // enclosure starts above the least upper end) cannot be the minimum, so
  // it is dropped before any pairwise comparison: ties among rows that
  // lose anyway are never proved.
  int ratio_test_once(int s, bool settle_z0) {
    int best = -1;
    // Rows of open sign, rows of positive entry and their ratios: n slots
    // each, reused (a ratio test does not nest another).
    thread_local std::vector<int> open_rows, positive_rows;
    thread_local std::vector<FI> ratios;
    open_rows.resize(n_);
    positive_rows.resize(n_);
    ratios.resize(n_);
    int* const open = open_rows.data();
    int* const positive = positive_rows.data();
    FI* const ratio = ratios.data();
    int opened = 0, positives = 0;
    double least_upper = std::numeric_limits<double>::infinity();
    const FI* entries = T_.column(s);
    const FI* values = T_.column(T_.rhs());
    const std::size_t stride = static_cast<std::size_t>(T_.stride());
    for (int i = 0; i < n_; ++i) {
      const FI entry = entries[i * stride];
      const int sign = certain_sign(entry);
      if (sign == kUndecided) {
        open[opened++] = i;
        continue;
      }
      ++certified_;
      if (sign <= 0) continue;
      positive[positives] = i;
      ratio[positives] = values[i * stride] / entry;
      least_upper = std::min(least_upper, ratio[positives].sup());
      ++positives;
    }
    for (int a = 0; a < positives; ++a) {
      const bool kept_for_tests = g_defer_every_z0_comparison && T_.basic(positive[a]) == T_.z0();
      if (ratio[a].inf() > least_upper && !kept_for_tests) {
        ++certified_;
        continue;
      }
      consider(positive[a], best, s, settle_z0);
    }
    for (int o = 0; o < opened; ++o) {
      const int i = open[o];
      if (best >= 0 && certainly_loses(i, best, s)) {
        ++certified_;
        continue;
      }
      ++exact_;
      if (exact().entry_sign(i, s) > 0) consider(i, best, s, settle_z0);
    }
    return best;
  }

  // Row i (entry T(i, s) > 0) against the best row so far.
  void consider(int i, int& best, int s, bool settle_z0) {
    if (best < 0) {
      best = i;
      return;
    }
    const bool z0_row = T_.basic(i) == T_.z0() || T_.basic(best) == T_.z0();
    if (z0_row && settle_z0) {
      const int c = g_defer_every_z0_comparison
                        ? kUndecided
                        : certain_sign(T_.at(i, T_.rhs()) * T_.at(best, s) - T_.at(best, T_.rhs()) * T_.at(i, s));
      if (c == kUndecided) {  // the z0 row taken to win; its final values settle it
        z0_taken_unordered_ = true;
        if (T_.basic(i) == T_.z0()) best = i;
        return;
      }
      ++certified_;
      if (c < 0) best = i;
      if (c == 0 && T_.basic(i) == T_.z0()) best = i;  // a certified tie (exact zeros): the z0 row wins
      return;
    }
    int c = compare_ratio(i, best, T_.rhs(), s);
    if (c == 0 && (T_.basic(i) == T_.z0() || T_.basic(best) == T_.z0())) {
      if (T_.basic(i) == T_.z0()) best = i;
      return;
    }
    for (int col = 0; c == 0 && col < n_; ++col) c = compare_ratio(i, best, col, s);
    if (c < 0) best = i;
  }

  // Whether row i, were T(i, s) positive, would have a ratio strictly above
  // the best row's: T(i, rhs)·T(best, s) − T(best, rhs)·t > 0 for every t in
  // (0, sup T(i, s)]. Then row i cannot win, nor tie, whatever its sign.
  bool certainly_loses(int i, int best, int s) {
    const double hi = T_.at(i, s).sup();
    if (!(hi > 0)) return false;
    const FI d = T_.at(i, T_.rhs()) * T_.at(best, s) - T_.at(best, T_.rhs()) * FI(0, hi);
    return d.inf() > 0;
  }

  const MatrixQ& B_;
  const VectorQ& b_;
  int n_;
  const PreparedLemkeMatrix* prepared_;
  Protect guard_;  // the interval tableau's whole life
  IntervalTableau T_;
  bool scaled_ = false, tableau_current_ = false;
  bool final_ready_ = false;  // final_ holds the final basis's values
  bool settle_z0_;            // take unordered z0-row comparisons, settle them by the final values
  bool z0_taken_unordered_ = false, final_settles_ = false, settlement_failed_ = false;
  BasicValues& final_ = exact_workspace().final_values;
  long certified_ = 0, exact_ = 0;
  long ties_proved_ = 0, ties_unproved_ = 0;
};

}  // namespace

bool filtered_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result,
                    const PreparedLemkeMatrix* prepared) {
  {
    // One run at a time: the runs share per-thread storage.
    FilteredRun run(B, b, true, prepared);
    if (!run.run(max_pivots, result)) return false;
    if (!run.settlement_failed()) return true;
  }
  FilteredRun run(B, b, false, prepared);
  return run.run(max_pivots, result);
}

void set_lemke_leave_every_z0_comparison_unordered(bool on) { g_defer_every_z0_comparison = on; }

bool filtered_lemke_path(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result,
                         std::vector<int>& basis, const PreparedLemkeMatrix* prepared) {
  FilteredRun run(B, b, false, prepared);
  if (!run.run(max_pivots, result, false)) return false;
  basis = run.basis();
  return true;
}

FinalValueCounts final_value_counts() {
  FinalValueCounts counts;
  counts.dixon = g_dixon_values;
  counts.factored = g_factored_values;
  counts.lifting_steps = g_lifting_steps;
  counts.reconstructions = g_reconstructions;
  counts.factors_by_trial = g_factors_by_trial;
  counts.factors_by_reconstruction = g_factors_by_reconstruction;
  counts.unknowns_eliminated = g_unknowns_eliminated;
  counts.z0_settled = g_z0_settled;
  counts.z0_reruns = g_z0_reruns;
  return counts;
}

void reset_final_value_counts() {
  g_dixon_values = 0;
  g_factored_values = 0;
  g_lifting_steps = 0;
  g_reconstructions = 0;
  g_factors_by_trial = 0;
  g_factors_by_reconstruction = 0;
  g_unknowns_eliminated = 0;
  g_z0_settled = 0;
  g_z0_reruns = 0;
}

}  // namespace fixel::internal
