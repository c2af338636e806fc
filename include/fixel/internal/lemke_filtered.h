#pragma once
// The filtered Lemke run (src/lemke_filtered.cpp): the exact lexicographic
// pivot path followed on an interval tableau, with every decision the
// intervals cannot certify made exactly on columns of the exact tableau.
#include "fixel/lemke.h"
#include "fixel/rational.h"

namespace fixel::internal {

// Runs Lemke on LCP(B, b) (validated sizes, b not ≥ 0) along the same path as
// the fraction-free integer tableau. Returns false, with `result` untouched,
// only when a pivot element's interval contains zero (the caller then runs
// the exact tableau); otherwise sets `result` (exact w, z when solved).
// Records the decisions in FilterSite::kLemke.
bool filtered_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots, LemkeResult& result);

}  // namespace fixel::internal
