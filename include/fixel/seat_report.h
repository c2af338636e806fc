#pragma once
/// @file
/// What `fixel seat` reports about S and an optional impulse, computed once
/// so that the formatters (io.h) only format.

#include <optional>
#include <string>
#include <vector>

#include "fixel/approach.h"
#include "fixel/guaranteed.h"
#include "fixel/outcomes.h"
#include "fixel/polyhedron.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"

namespace fixel {

/// The verdicts on one impulse p (N·s, N·m·s; world frame).
struct ImpulseVerdict {
  VectorQ impulse;
  bool in_S = false;
  /// Eq. (27)'s y = K⁻¹ (P p + a) and its entries' names, when every fixel
  /// slides (otherwise eq. 27 does not apply and these are empty).
  std::optional<VectorQ> y;
  std::vector<std::string> y_names;
  std::optional<bool> guaranteed;     ///< p ∈ G, when G was computed.
  std::optional<bool> seat_and_stay;  ///< p ∈ S ∩ h·C_stab, when asked.
  OutcomeCount outcomes;              ///< All one-step outcomes of p (exact enumeration).
};

/// The seat report's derived results beyond S itself.
struct SeatReport {
  std::optional<ImpulseVerdict> impulse;
  std::optional<Rational> lost_fraction;  ///< With G: the grid-sampled share of S outside G.
  bool stable = false;                    ///< Whether the seat-and-stay set was asked for.
  std::vector<Halfspace> stability_cone;  ///< With `stable`: C_stab.
  Polyhedron seat_and_stay;               ///< With `stable`: S ∩ h·C_stab.
};

/// Computes the report. `G` may be null; the impulse must have length dof.
/// Throws InputError naming S or G when they are not this scene's
/// (check_guaranteed_set_of).
SeatReport seat_report(const Scene& scene, const SeatingSet& S, const std::optional<VectorQ>& impulse,
                       const GuaranteedSet* G, bool stable);

/// Whether a wrench w_W (N, N·m; world frame) is in J, and why not.
struct WrenchVerdict {
  VectorQ wrench;
  std::optional<bool> contains;  ///< Unset when J cannot decide it (unsupported case).
  std::string why_not;           ///< Empty when contained; the failing condition or the reason it is undecided.
};

/// Decides w_W ∈ J; an UnsupportedError from J becomes an undecided verdict.
WrenchVerdict wrench_verdict(const SustainedSet& J, const VectorQ& w_W);

/// J′'s verdict on a wrench (approach.h).
struct ApproachVerdict {
  std::optional<bool> contains;      ///< Unset when J′ cannot be decided.
  std::string why_not;               ///< Empty when contained; else the reason.
  std::optional<ApproachHold> hold;  ///< The pose where a pair holds the part, if that is why.
};

/// Decides w_W ∈ J′; an UnsupportedError becomes an undecided verdict.
ApproachVerdict approach_verdict(const ApproachSet& A, const VectorQ& w_W);

}  // namespace fixel
