#pragma once
// Fixture design's pair bound (docs/design.md, "The bound";
// docs/theory.md §10.6): an upper bound of every triple's sustained score,
// made from the candidates' pairs, so that the search scores the likeliest
// triples first and stops when no other can enter the top K.
//
// A sustained-region IN point needs a frictionless push w strictly inside
// K = −cone(W_n): a_k · w > 0 for K's three rows, and each row is ±W_a × W_b
// for a pair {a, b} of the triple. Per pair, one region against the open
// half-space c · w > 0 (c = W_a × W_b), on a grid coarser than the score's
// (below), gives the stretches of the outline where c · w > 0 may hold (IN
// or PARTIAL) and where c · w < 0 may (OUT or PARTIAL). A second region, against
// the pair's jam cone −(FC_a + FC_b), takes off both sides the stretches
// whose every push the pair can hold (no IN point of J's region lies
// there). A triple's bound is the parameter length of the intersection of
// its three rows' stretches, over the outline's: an exact rational, at
// least the triple's sustained score.

#include <array>
#include <memory>
#include <vector>

#include "fixel/design.h"
#include "fixel/internal/region_runs.h"

namespace fixel::internal {

class PairBound {
 public:
  // The candidates' normal wrenches (frame A, about the centre of mass) and
  // each piece's grid: 2^depth cells, depth the subdivision's deepest at
  // the pair regions' resolution: the design's `resolution` or the outline's
  // parameter length over kCells, whichever is coarser (measured: a finer
  // grid costs more in pair regions than it saves in layouts scored,
  // docs/performance_log.md). Throws what the region would (no outline).
  // The jam cones use the fixels' friction J is judged at (mu_hi, else mu).
  PairBound(const Scene& part, const std::vector<DesignCandidate>& candidates, const DesignOptions& options);
  static constexpr int kCells = 256;

  long pair_count() const;
  // Computes pair p (a < b, lexicographic): its half-space's and its jam
  // cone's stretches, by the region's segment test on each piece's grid
  // (the pieces' subdivision and their cones are made once and shared by
  // every pair); safe to call for distinct p from several threads.
  void compute_pair(long p);

  // Whether W_n of triple f (increasing candidate indices) is singular
  // (filtered sign of its determinant, exact fallback).
  bool singular(const std::array<int, 3>& f) const;
  // An upper bound (outward rounding) of the exact bound of a non-singular
  // triple: the same number whatever force_exact() says.
  double upper(const std::array<int, 3>& f) const;
  // The exact bound of a non-singular triple.
  Rational exact(const std::array<int, 3>& f) const;

  // Whether triple f (index `index`, upper end `upper`) may still enter a
  // top K whose last layout has score `kth_score` and index `kth_index`: its
  // exact bound is above, or equal with an earlier index. Certified by
  // `upper` when it is below (FilterSite::kDesignBound), else decided on
  // the exact bound (the only test when the exact path is forced).
  bool can_enter(const std::array<int, 3>& f, long index, double upper, const Rational& kth_score,
                 long kth_index) const;
  // Whether no triple whose upper end is at most `upper` can enter: `upper`
  // is below `kth_score`. Counts `left` certified decisions. Always false
  // when the exact path is forced (the caller then asks can_enter of each).
  bool none_can_enter(double upper, const Rational& kth_score, long left) const;

  ~PairBound();
  PairBound(PairBound&&) noexcept;
  PairBound& operator=(PairBound&&) noexcept;

  struct Impl;  // src/design_bound.cpp: keeps the interval types out of design.cpp

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace fixel::internal
