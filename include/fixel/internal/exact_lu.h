#pragma once
// Exact LU decomposition: Eigen's FullPivLU on Rational with threshold 0, so
// that rank and invertibility count only pivots that are exactly zero.

#include <Eigen/LU>
#include <vector>

#include "fixel/rational.h"

namespace fixel::internal {

inline Eigen::FullPivLU<MatrixQ> exact_lu(const MatrixQ& A) {
  Eigen::FullPivLU<MatrixQ> lu(A);
  lu.setThreshold(Rational(0));
  return lu;
}

// Rank of the rays (exact); each ray must have `dim` entries.
int exact_rank(const std::vector<VectorQ>& rays, int dim);

}  // namespace fixel::internal
