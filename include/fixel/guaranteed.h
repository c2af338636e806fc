#pragma once
/// @file
/// Past the paper: impulses whose every one-step outcome seats the part
/// (LCP nonuniqueness, paper §6), and the seat-and-stay set (paper §3.3).

#include <memory>
#include <vector>

#include "fixel/outcomes.h"
#include "fixel/polyhedron.h"
#include "fixel/scene.h"
#include "fixel/seating.h"

namespace fixel {

struct RunControl;

/// The impulses for which the step LCP has a solution in `modes` with fixel
/// `open_fixel` open and its gap strictly positive after the step.
struct NonSeatingSet {
  std::vector<ContactMode> modes;
  int open_fixel = 0;
  Polyhedron impulses;  ///< In impulse space (dim = dof), exact.
};

/// G = S minus every non-seating set: the impulses whose every LCP outcome
/// seats the part.
struct GuaranteedSet {
  /// The non-seating sets that meet S (the others cannot remove anything).
  std::vector<NonSeatingSet> non_seating;
  /// G as disjoint convex pieces (strict rows where a boundary is excluded).
  std::vector<Polyhedron> pieces;
  /// The affine dimension of each piece (parallel to `pieces`, exact). A
  /// piece of dimension < dof has no volume (typically a face left where a
  /// non-seating set with a strict row was subtracted); it is kept, and
  /// marked, so that the pieces partition G exactly.
  std::vector<int> dimensions;
  /// Exact membership: p ∈ S and p in no non-seating set.
  bool contains(const VectorQ& p_ext, const SeatingSet& S) const;
  /// The scene G was built from (set by guaranteed_set; null for a G built
  /// by hand, which is then not checked): a region, sample or point test
  /// against G refuses a scene that differs where G looks (h, dof, mass,
  /// inertia, centre of mass, velocity, each fixel's point, normal, gap and
  /// friction) with an InputError naming G.
  std::shared_ptr<const Scene> built_from;
};

/// Throws InputError unless S is this scene's seating set
/// (check_seating_set_of, naming `S`) and G was built from a scene that
/// agrees with this one where G looks (h, dof, mass, inertia, centre of
/// mass, velocity, each fixel's point, normal, gap and friction), naming
/// `G` and what differs. A G built by hand (no `built_from`) passes. The
/// region, sample and point tests, seat_report, dump_off and the SVG
/// writers call it before using G.
void check_guaranteed_set_of(const Scene& scene, const SeatingSet& S, const GuaranteedSet& G);

/// {τ > 0 : b0 + τ g ∈ G} exactly, as disjoint intervals in increasing order
/// (T_S minus the T_N of every non-seating set).
std::vector<Magnitudes> ray_magnitudes(const GuaranteedSet& G, const SeatingSet& S, const VectorQ& b0,
                                       const VectorQ& g);

/// Builds G by exact projection of every contact mode with an open contact
/// (docs/theory.md §9). Throws InputError on a scene without n_c == dof.
/// Polls `control` (if given) before each contact mode and each subtraction
/// of a non-seating set ("guaranteed set", counted in contact modes, then
/// non-seating sets): throws StoppedError when it is cancelled or past its
/// deadline.
GuaranteedSet guaranteed_set(const Scene& scene, const SeatingSet& S, RunControl* control = nullptr);

/// How much of S is lost: the fraction of the sample points
/// apex + t·Σ w_j r_j (r_j the rays of S, w on the simplex grid with step
/// 1/grid, t ∈ {1/4, 1/2, 1, 2, 4}) that are not in G. Exact count ratio.
/// Throws InputError naming `grid` below 1 or when the points would number
/// more than ten million.
Rational lost_fraction(const SeatingSet& S, const GuaranteedSet& G, int grid = 6);

/// Facets of the weak-stability impulse cone h·C_stab,
/// C_stab = cone{−(W_n,i ± μ_i W_t,i)} (paper §3.3): {w : a·w ≥ 0}.
std::vector<Halfspace> stability_cone(const Scene& scene);

/// The seat-and-stay set S ∩ h·C_stab.
Polyhedron seat_and_stay(const Scene& scene, const SeatingSet& S);

}  // namespace fixel
