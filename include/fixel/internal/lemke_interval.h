#pragma once
// The filtered Lemke run's interval tableau (src/lemke_interval.cpp): the
// exact run's tableau enclosed entry by entry, so that most decisions are
// certified in doubles (docs/theory.md §6). Its hot accessors are inline.
#include <cstddef>
#include <vector>

#include "fixel/internal/filtered.h"
#include "fixel/internal/lemke_tie.h"
#include "fixel/rational.h"

namespace fixel::internal {

// |z| enclosed, for 0 < |z| < 2^128 (one or two limbs), without GMP's
// conversion: exact below 2^53; else its top 64 bits, truncated, converted
// to a double v (within one ulp, in any rounding mode), then
// [prev(v), next(v)]·2^shift holds |z| (the bits dropped are below one
// unit of the top 64, and an ulp of v is 2^11 of them or more). Exposed for
// tests.
FI two_limb_magnitude(mpz_srcptr z);

// B's part of the first interval tableau: row i is [−B(i, ·), −1], n + 1
// enclosures. It depends on B alone, so a prepared matrix (LemkeMatrix)
// keeps one for all its solves. Needs a Protect scope to assign.
struct IntervalRows {
  int n = 0;
  std::vector<FI> rows;  // row-major, n + 1 per row
  void assign(const MatrixQ& B);
};

// The same tableau in intervals (Gauss–Jordan on [I, −B, −e | b]): every
// entry encloses the exact tableau's. It is the integer tableau of
// src/lemke.cpp up to positive row and column scalings, which change no
// ratio-test decision. Only the n + 1 nonbasic columns and b are stored: a
// basic variable's column is a unit vector, and the leaving variable's
// column takes over the entering one's storage. Needs a Protect scope.
class IntervalTableau {
 public:
  IntervalTableau(const MatrixQ& B, const VectorQ& b);
  // The same first tableau, B's part copied from `prepared` (made from B).
  IntervalTableau(const IntervalRows& prepared, const VectorQ& b);

  // Doubles near the first tableau's entries, for guesses only. Made on
  // the first call for a prepared tableau (only tie certificates ask).
  ApproxProblem approx() {
    if (initial_.empty()) keep_initial();
    return {initial_.data(), n_};
  }

  int z0() const { return 2 * n_; }
  int rhs() const { return 2 * n_ + 1; }
  int basic(int row) const { return basis_[row]; }
  const std::vector<int>& basis() const { return basis_; }
  int complement(int var) const { return var < n_ ? var + n_ : var - n_; }

  // Entry (i, var): a unit-vector entry for a basic variable.
  FI at(int i, int var) {
    const int k = slot_[var];
    if (k < 0) return FI(basis_[i] == var ? 1 : 0);
    bring_up_to_date(k);
    return at_slot(i, k);
  }

  // Column var (nonbasic, or b) brought up to date: entry i at [i·stride()].
  // Valid until the next pivot.
  const FI* column(int var) {
    const int k = slot_[var];
    bring_up_to_date(k);
    return &T_[k];
  }
  int stride() const { return width_; }

  // Pivot on (r, s), s nonbasic; needs a pivot interval that excludes zero.
  // The leaving variable's column, e_r before, becomes (−T(i, s)/p)_i with
  // 1/p in row r, and is stored in s's slot (made when first read). The other columns are updated
  // when they are next read (bring_up_to_date) or at the flush after 2n
  // pivots: the path reads b's column and the entering one, and others only
  // for a lexicographic tie-break.
  void pivot(int r, int s);

 private:
  friend struct IntervalRows;  // encloses B as the first tableau does
  FI& at_slot(int i, int k) { return T_[static_cast<std::size_t>(i) * width_ + k]; }

  void forget_pivots();
  // The state every first tableau starts from; T_ sized, and zero when
  // `zeros` (else every slot is written next).
  void start(bool zeros);
  // initial_ from the first tableau: T_ before a pivot, else the prepared
  // rows and b's enclosures.
  void keep_initial();

  // Applies the pivots made since slot k was last read, in order, with the
  // operations of a Gauss–Jordan step on that column (row i less
  // m_i·(old row r) for the rows where T(i, s) is not an exact zero, m_i =
  // T(i, s)/p enclosed at the pivot; then row r times 1/p), so its
  // enclosures are bit for bit those of an eager update. m_i rather than
  // T(i, s)·(row r/p): one product less on the chain from pivot to pivot.
  void bring_up_to_date(int k) {
    if (pending_[k] >= 0) take_pivot_column(k);
    for (int t = stamp_[k]; t < pivots_; ++t) {
      const FI* g = &eta_[static_cast<std::size_t>(t) * n_];
      const int r = eta_row_[t];
      const FI x = at_slot(r, k);
      at_slot(r, k) = x * eta_inverse_[t];
      if (x.inf() == 0 && x.sup() == 0) continue;
      const int end = t + 1 < pivots_ ? eta_support_start_[t + 1] : static_cast<int>(eta_support_.size());
      for (int e = eta_support_start_[t]; e < end; ++e) {
        const int i = eta_support_[e];
        at_slot(i, k) -= g[i] * x;
      }
    }
    stamp_[k] = pivots_;
  }

  // Brings every column up to date and forgets the pivots.
  void flush();
  // Slot k as pivot t (pending_[k]) left it: 1/p in row r, −m_i on the
  // pivot's support, the slot's exact zeros kept. Made when
  // the column is first read rather than at the pivot (when the variable
  // enters again, at a lexicographic tie-break, or at the flush): most
  // leaving columns are never read again.
  void take_pivot_column(int k);

  // q in an interval: when numerator and denominator are exact doubles, one
  // interval division (outward rounded); when they have at most two limbs,
  // their two_limb_magnitude enclosures divided; up to 15 limbs, their
  // truncated doubles widened by an ulp, divided; else the shared
  // conversion (to_interval).
  static FI enclosure(const Rational& q);

  // The vectors' storage, reused from run to run (one per thread; a run
  // does not nest another).
  struct Storage {
    std::vector<FI> T, eta, eta_inverse, first_rhs;
    std::vector<double> initial;
    std::vector<int> basis, slot, stamp, pending, eta_row, eta_support, eta_support_start;
  };
  static Storage& storage();

  int n_, width_;
  Storage& storage_ = storage();
  std::vector<FI>& T_ = storage_.T;                      // row-major, width_ slots per row
  std::vector<double>& initial_ = storage_.initial;      // the first tableau's slots, approximately
  std::vector<int>& basis_ = storage_.basis;             // basic variable of each row
  std::vector<int>& slot_ = storage_.slot;               // storage slot of each nonbasic variable (and b), else −1
  std::vector<int>& stamp_ = storage_.stamp;             // per slot: how many pivots its column has seen
  std::vector<int>& pending_ = storage_.pending;         // per slot: the pivot whose column it still holds, or −1
  std::vector<FI>& eta_ = storage_.eta;                  // per pivot: n slots, m_i = T(i, s)/p on its support
  std::vector<int>& eta_row_ = storage_.eta_row;         // per pivot: its row
  std::vector<FI>& eta_inverse_ = storage_.eta_inverse;  // per pivot: 1/p, p its pivot
  // Per pivot t, from eta_support_start_[t]: the rows i ≠ r whose T(i, s)
  // is not an exact zero, the only rows its update changes.
  std::vector<int>& eta_support_ = storage_.eta_support;
  std::vector<int>& eta_support_start_ = storage_.eta_support_start;
  int pivots_ = 0;
  const IntervalRows* prepared_ = nullptr;           // the first tableau's B part, when prepared
  std::vector<FI>& first_rhs_ = storage_.first_rhs;  // b's enclosures, when prepared
};

}  // namespace fixel::internal
