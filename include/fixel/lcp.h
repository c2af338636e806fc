#pragma once
/// @file
/// The Stewart–Trinkle time-stepping LCP of the paper, eqs. (5), (14)–(19).
///
/// Variable order: w = (ρ_n, ρ_f, σ) and z = (p_n, p_f, s), each of size
/// n_c, 2 n_c, n_c. In p_f, entry 2i is contact i's +t_i column and 2i+1 its
/// −t_i column (the paper's (p_if)_1 and (p_if)_2).

#include <string>
#include <vector>

#include "fixel/geometry.h"
#include "fixel/rational.h"
#include "fixel/scene.h"

namespace fixel {

/// The one-step analyses need n_c == dof fixels with W_n nonsingular: throws
/// SceneError naming the first fixel that breaks this. (A scene loads
/// without it, e.g. a part with no fixels for fixture design.)
void require_determined_fixture(const Scene& scene);

/// The one-step analyses need one friction value per fixel: throws
/// UnsupportedError naming the first fixel whose μ is an interval.
void require_single_friction(const Scene& scene);

/// W_n (dof × n_c): column i is the normal wrench of fixel i.
MatrixQ normal_wrench_matrix(const Scene& scene);

/// The matrices of eqs. (5) and (14)–(15), exact.
struct ContactMatrices {
  MatrixQ M;   ///< dof × dof mass matrix diag(m, m, I).
  MatrixQ Wn;  ///< dof × n_c normal wrenches.
  MatrixQ Wt;  ///< dof × n_c tangent wrenches.
  MatrixQ Wf;  ///< dof × 2 n_c: [W_t,i, −W_t,i] per contact.
  MatrixQ E;   ///< 2 n_c × n_c block diagonal of e = (1, 1).
  MatrixQ U;   ///< n_c × n_c diag(μ_i).
};

/// Builds the contact matrices of a scene.
ContactMatrices contact_matrices(const Scene& scene);

/// The LCP(B, b) of eqs. (16)–(18) with b = P p_ext + a (eq. 19).
struct TimeSteppingLcp {
  ContactMatrices W;
  MatrixQ B;  ///< 4 n_c × 4 n_c, eq. (17).
  MatrixQ P;  ///< 4 n_c × dof, eq. (19).
  VectorQ a;  ///< 4 n_c, eq. (19).

  /// b for a given external impulse p_ext (length dof), eq. (18).
  VectorQ b(const VectorQ& p_ext) const;
  /// Names of the w and z entries, e.g. "rho_n[0]", "p_f[1]-" (for display).
  std::vector<std::string> w_names() const;
  std::vector<std::string> z_names() const;
};

/// Builds the time-stepping LCP of a validated scene.
TimeSteppingLcp build_lcp(const Scene& scene);

/// Sets lcp.a from the scene's velocity ν and gaps ψ, eq. (19): all that
/// changes from one time step to the next (B, P and W depend on the
/// contacts' geometry, the masses and μ only). `scene` is the one `lcp`
/// was built from, or a later state of it with the same fixels.
void set_lcp_state(TimeSteppingLcp& lcp, const Scene& scene);

}  // namespace fixel
