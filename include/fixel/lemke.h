#pragma once
/// @file
/// Exact LCP solving: lexicographic Lemke on a fraction-free integer tableau,
/// and an independent solution checker.

#include <memory>
#include <string>

#include "fixel/rational.h"

namespace fixel {

namespace internal {
struct PreparedLemkeMatrix;
}

/// How a Lemke run ended. Only kSolved carries a solution.
enum class LemkeStatus {
  kSolved,          ///< w, z solve the LCP (checked exactly before they are returned).
  kRayTermination,  ///< The path left on an unbounded ray: no solution was found on it.
  kPivotLimit,      ///< Stopped after max_pivots pivots.
};

/// "solved", "ray termination" or "pivot limit".
std::string to_string(LemkeStatus status);

/// Result of solve_lcp_lemke.
struct LemkeResult {
  LemkeStatus status = LemkeStatus::kRayTermination;
  VectorQ w, z;    ///< The solution when status == kSolved, else empty.
  int pivots = 0;  ///< Pivots performed, including the first one on z0.
};

/// Solves LCP(B, b): find w = Bz + b with 0 ≤ w ⊥ z ≥ 0. Lemke's method with
/// covering vector e and the lexicographic ratio test, so it cannot cycle on
/// degenerate problems. The tableau holds integers and one common
/// denominator; every ratio comparison is the exact sign of a·d − b·c.
/// Unless force_exact(), the same pivot path is first followed on an
/// interval tableau: an exact ratio tie the intervals cannot certify is
/// proved by an integer null vector, and any other decision they leave open
/// is taken on exact columns of the tableau (docs/theory.md §6); status,
/// pivots, w and z are the same either way.
/// A kSolved result has been verified exactly: by is_solution on the exact
/// path, and on the filtered path by a residual check of every equation in
/// integers (docs/theory.md §6). max_pivots <= 0 means
/// 100·(n + 1). Throws InputError if B is not square or b has the wrong size.
LemkeResult solve_lcp_lemke(const MatrixQ& B, const VectorQ& b, int max_pivots = 0);

/// The same into `result`, every field overwritten: for a caller solving
/// many LCPs in a loop. When result.w and result.z already have b's size,
/// their rationals' storage is reused instead of allocated anew (on the
/// seating LCPs of size 12, about a twentieth of a filtered solve). The
/// answer is the returning overload's, field for field. On a throw,
/// `result` holds no meaningful answer.
void solve_lcp_lemke(const MatrixQ& B, const VectorQ& b, LemkeResult& result, int max_pivots = 0);

class LemkeMatrix;

/// solve_lcp_lemke(B.matrix(), b, max_pivots) for a prepared B (below): the
/// same answer, field for field, and the same exceptions.
LemkeResult solve_lcp_lemke(const LemkeMatrix& B, const VectorQ& b, int max_pivots = 0);

/// The same into `result`, as the MatrixQ overload does.
void solve_lcp_lemke(const LemkeMatrix& B, const VectorQ& b, LemkeResult& result, int max_pivots = 0);

/// An LCP matrix B prepared once for many solves of LCP(B, b) with
/// different b, as a time-stepper's steps or a scene's impulses have: B's
/// rationals, with each entry's interval enclosure and B's rows scaled to
/// integers (and, when they fit, 64-bit words) cached beside them. A
/// solve then does only b's share of that
/// work (`docs/performance.md`, "Lemke"). Preparing costs about one solve
/// with the bare B, so it pays from the second solve. Copies share the prepared data,
/// which is never modified, so one LemkeMatrix may be solved from several
/// threads.
class LemkeMatrix {
 public:
  /// Throws InputError if B is not square.
  explicit LemkeMatrix(MatrixQ B);
  /// B, exactly as given.
  const MatrixQ& matrix() const;
  /// B's size n.
  int size() const;

 private:
  friend void solve_lcp_lemke(const LemkeMatrix& B, const VectorQ& b, LemkeResult& result, int max_pivots);
  std::shared_ptr<const internal::PreparedLemkeMatrix> prepared_;
};

/// Exact check that w = Bz + b, w ≥ 0, z ≥ 0 and wᵀz = 0.
bool is_solution(const MatrixQ& B, const VectorQ& b, const VectorQ& w, const VectorQ& z);

}  // namespace fixel
