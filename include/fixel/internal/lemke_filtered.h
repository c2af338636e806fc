#pragma once
// The filtered Lemke run (src/lemke_filtered.cpp): the exact lexicographic
// pivot path followed on an interval tableau (internal/lemke_interval.h),
// with every decision the intervals cannot certify made exactly on columns
// of the exact tableau, and the final values found exactly
// (internal/lemke_exact.h).
#include "fixel/lemke.h"
#include "fixel/rational.h"

#include <vector>

namespace fixel::internal {

// Runs Lemke on LCP(B, b) (validated sizes, b not ≥ 0) along the same path as
// the fraction-free integer tableau. Returns false, with `result` untouched,
// only when a pivot element's interval contains zero (the caller then runs
// the exact tableau); otherwise sets `result` (exact w, z when solved).
// Records the decisions in FilterSite::kLemke. A comparison of the z0 row
// that the intervals leave open may be settled by the final values' exact
// signs (a second run when they show it wrong): same answer.
// `prepared`, when not null, is B's cached parts (a LemkeMatrix of B).
bool filtered_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result,
                    const PreparedLemkeMatrix* prepared = nullptr);

// The same run without its final values, for the benchmark that measures
// what the pivot path alone costs: `result` gets status and pivots (w and
// z stay empty) and `basis` the final basic variable of each tableau row
// (0..n−1 w, n..2n−1 z, 2n z0). Same preconditions, `prepared` and false
// as above.
bool filtered_lemke_path(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result,
                         std::vector<int>& basis, const PreparedLemkeMatrix* prepared = nullptr);

// How the solved filtered runs got their final values since the last
// reset: by dixon_solve (internal/lemke_dixon.h), or from the factored
// basis block when it declined. Runs that had the final basis's exact
// columns at hand already count in neither. For tests and benchmarks.
//
// z0_settled and z0_reruns count the runs whose last pivot rested on a
// comparison of the z0 row that the intervals left open: settled by the
// final values' signs, or rerun because a value was negative.
struct FinalValueCounts {
  long dixon = 0, factored = 0;
  long lifting_steps = 0, reconstructions = 0;               // summed over the dixon runs (DixonTrace)
  long factors_by_trial = 0, factors_by_reconstruction = 0;  // likewise
  long unknowns_eliminated = 0;                              // likewise: fixed by short rows before lifting
  long z0_settled = 0, z0_reruns = 0;
};
FinalValueCounts final_value_counts();
void reset_final_value_counts();

// For tests: every comparison of the z0 row with another row in a ratio
// test is left to the final values, as if the intervals could never order
// them, so that both outcomes of settling run. Answers must not change.
void set_lemke_leave_every_z0_comparison_unordered(bool on);

}  // namespace fixel::internal
