#pragma once
/// @file
/// Exact H-polyhedra with strict inequalities (relatively open pieces), and
/// the set operations the guaranteed seating set needs.

#include <string>
#include <vector>

#include "fixel/cone.h"
#include "fixel/interval.h"
#include "fixel/rational.h"

namespace fixel {

/// {p ∈ R^dim : a·p ≥ c for every closed row, a·p > c for every strict row}.
/// An equality is two opposite closed rows.
struct Polyhedron {
  int dim = 3;
  std::vector<Halfspace> closed;
  std::vector<Halfspace> strict;

  /// Exact membership.
  bool contains(const VectorQ& p) const;
  /// The intersection with another polyhedron of the same dimension.
  Polyhedron intersect(const Polyhedron& other) const;
  /// True for the canonical empty form drop_constant_rows leaves: the one
  /// row 0 >= 1.
  bool is_trivially_empty() const;
};

/// Rows whose left side is zero decide themselves: 0 >= c (0 > c) holds for
/// every p when c <= 0 (c < 0) and is dropped; when it holds for no p the
/// polyhedron is empty and becomes the canonical form {0 >= 1} alone.
void drop_constant_rows(Polyhedron& P);

/// Exact emptiness (an exact LP that maximises the slack of the strict rows).
bool is_empty(const Polyhedron& P);

/// The dimension of P's affine hull, exactly (dim minus the rank of the
/// closed rows that hold with equality on all of P); -1 for an empty P.
int affine_dimension(const Polyhedron& P);

/// Q \ P as disjoint polyhedra (empty ones dropped): piece k keeps P's
/// rows 0..k−1 and violates row k.
std::vector<Polyhedron> subtract(const Polyhedron& Q, const Polyhedron& P);

/// Linear constraints over (x, p) ∈ R^{nx} × R^{np}, for projection.
struct LiftedSystem {
  int nx = 0, np = 0;
  MatrixQ A_eq;  ///< rows over (x, p)
  VectorQ b_eq;
  MatrixQ A_in;  ///< rows a·(x, p) ≥ b (strict where strict_in is true)
  VectorQ b_in;
  std::vector<bool> strict_in;
};

/// {p : ∃x with the system} exactly: Gaussian elimination on the equalities,
/// then Fourier–Motzkin on the x left free. Duplicate rows are removed, and
/// so are rows with a zero left side (drop_constant_rows).
Polyhedron project_out_x(const LiftedSystem& system);

/// T = {τ > 0 : b0 + τ g ∈ P}, exact (an interval; strict rows give open ends).
/// Throws InputError when b0 or g differs in length from P's rows.
Magnitudes ray_magnitudes(const Polyhedron& P, const VectorQ& b0, const VectorQ& g);

}  // namespace fixel
