#pragma once
/// @file
/// The set S of external impulses that seat the part in one time step
/// (paper §3, eqs. (19)–(27)).

#include <string>
#include <vector>

#include "fixel/cone.h"
#include "fixel/interval.h"
#include "fixel/lcp.h"
#include "fixel/rational.h"
#include "fixel/scene.h"

namespace fixel {

/// S = {apex + Σ λ_k rays_k : λ ≥ 0}, a translated polyhedral cone in impulse
/// space (N·s for the force rows, N·m·s for the moment row), kept in both
/// V-form (apex, rays) and H-form (halfspaces). Frames: every impulse,
/// velocity and generator is in the world frame A, in generalised
/// coordinates (x, y[, θ]) with moments about the centre of mass Cm; the
/// fields keep the paper's symbols (ν⁺, g_i, ...) instead of Drake monograms,
/// since all of them share that one frame.
struct SeatingSet {
  int dof = 3;
  VectorQ nu_plus;              ///< ν^{ℓ+1} = −W_n^{-T} Ψ / h, the seating velocity.
  VectorQ tangential_velocity;  ///< v_t = W_tᵀ ν^{ℓ+1}, one per fixel.
  std::vector<int> sliding;     ///< σ_i = sign(v_t,i) ∈ {−1, 0, +1}; 0 = sticking.
  VectorQ apex;                 ///< M (ν^{ℓ+1} − ν^ℓ).
  /// g_i = W_n,i − σ_i μ_i W_t,i for a sliding fixel; W_n,i ± μ_i W_t,i
  /// (two generators, one if μ_i = 0) for a sticking one.
  std::vector<VectorQ> generators;
  std::vector<int> generator_fixel;   ///< The fixel of each generator.
  std::vector<VectorQ> rays;          ///< −g_i, the rays of S.
  std::vector<Halfspace> halfspaces;  ///< S = ∩ halfspaces (exact facets).

  /// Exact membership from the H-form; boundary points are members.
  bool contains(const VectorQ& p_ext) const;
};

/// Ray test: T(g) = {τ > 0 : b0 + τ g ∈ S}, exact from the H-form, one facet
/// at a time. The ray hits S iff the result is not empty. Throws InputError
/// when b0 or g does not have S.dof components.
Magnitudes ray_magnitudes(const SeatingSet& S, const VectorQ& b0, const VectorQ& g);

/// Throws InputError naming `field` unless S is the scene's seating set:
/// its shape (dof, one sliding flag per fixel, rows and apex of length
/// dof), then, exactly, its ν⁺ (W_nᵀ ν⁺ = −Ψ/h), v_t, apex, sliding signs,
/// generators and rays as seating_set(scene) derives them, and its rows,
/// which must be the facets of that cone through the apex, in
/// seating_set's order. The message names the first part that differs.
void check_seating_set_of(const Scene& scene, const SeatingSet& S, const std::string& field = "S");

/// Computes S for a validated scene (n_c == dof, W_n nonsingular), for
/// sliding and sticking (v_t,i == 0) contacts alike.
SeatingSet seating_set(const Scene& scene);

/// The reduced system K y = P p + a of eqs. (21)–(22), y ≥ 0 ⇔ p ∈ S.
/// y lists, in the paper's order, the kept ρ_f entries, p_n, the kept p_f
/// entries and s (4 n_c values).
struct SeatingSystem {
  MatrixQ K;                         ///< 4 n_c × 4 n_c, columns of [I −B] kept.
  MatrixQ K_inv;                     ///< Exact inverse of K.
  MatrixQ P;                         ///< As in eq. (19).
  VectorQ a;                         ///< As in eq. (19).
  std::vector<int> kept;             ///< Indices into (w, z) (0 .. 8 n_c − 1) of y's entries.
  std::vector<std::string> y_names;  ///< e.g. "rho_f[0]+", "p_n[2]".

  /// y = K⁻¹ (P p + a); p ∈ S ⇔ y ≥ 0 (eq. 27).
  VectorQ y(const VectorQ& p_ext) const;
  /// K⁻¹ P p, the left side of eq. (27).
  VectorQ linear_part(const VectorQ& p_ext) const;
  /// −K⁻¹ a, the right side of eq. (27).
  VectorQ threshold() const;
};

/// Builds the eq. (21) system for the sliding modes of `S`. Throws
/// UnsupportedError when a contact sticks (eq. 21 assumes sliding) or K is
/// singular (the generators of S are linearly dependent, so S is flat and
/// eq. (27) does not apply).
SeatingSystem seating_system(const Scene& scene, const SeatingSet& S);

}  // namespace fixel
