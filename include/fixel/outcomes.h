#pragma once
/// @file
/// Every outcome of one time step: enumeration of the LCP's solutions by
/// contact mode (open, sliding +t, sliding −t, sticking per fixel).

#include <string>
#include <vector>

#include "fixel/rational.h"
#include "fixel/scene.h"

namespace fixel {

struct RunControl;

/// What a contact does during the step.
enum class ContactMode { kOpen, kSlidePlus, kSlideMinus, kStick };

/// "open", "slide+", "slide-", "stick".
std::string to_string(ContactMode mode);

/// A physical outcome of one step: the pair (ν^{ℓ+1}, contact impulses). The
/// split of friction between the +t and −t columns of the LCP does not count.
struct Outcome {
  std::vector<ContactMode> modes;  ///< A contact mode that realises it.
  VectorQ velocity;                ///< ν^{ℓ+1}.
  VectorQ p_n;                     ///< Normal impulses, one per fixel.
  VectorQ p_t;                     ///< Net friction impulse along t_i, one per fixel.
  VectorQ gaps;                    ///< ψ^{ℓ+1} = ψ^ℓ + h W_nᵀ ν^{ℓ+1}.
  bool seated = false;             ///< Every gap is exactly 0.
  /// True when the mode admits exactly this outcome; false when its linear
  /// system is singular and one outcome of a family is reported.
  bool isolated = true;
};

/// How many distinct one-step outcomes an impulse has, and how many seat.
struct OutcomeCount {
  int total = 0;
  int seating = 0;
};
OutcomeCount count_outcomes(const std::vector<Outcome>& outcomes);

/// A polyhedron {x : A_eq x = b_eq, A_in x ≥ b_in} in the variables
/// x = (ν^{ℓ+1}, p_n, p_t) of size dof + 2 n_c.
struct ModeSystem {
  MatrixQ A_eq;
  VectorQ b_eq;
  MatrixQ A_in;
  VectorQ b_in;
};

/// The contact modes numbered `code` ∈ [0, 4^n_c): digit i in base 4 is
/// fixel i's mode (open, slide+, slide−, stick). Throws InputError naming
/// `code` or `num_contacts` (0 to 31) out of range.
std::vector<ContactMode> contact_modes(long code, int num_contacts);

/// The outcomes of `modes` (one per fixel) under external impulse p_ext:
/// Newton's law, and per fixel: open (p = 0, gap ≥ 0), sliding ±t (gap 0,
/// p_n ≥ 0, p_t = ∓μ p_n, ±v_t ≥ 0) or sticking (gap 0, v_t = 0,
/// |p_t| ≤ μ p_n). Every point is an LCP solution and every LCP solution is
/// a point of some mode (docs/theory.md §5). Throws InputError naming
/// `modes` unless there is one per fixel.
ModeSystem mode_system(const Scene& scene, const std::vector<ContactMode>& modes, const VectorQ& p_ext);

/// Every distinct physical outcome of the step LCP at p_ext, by exact
/// enumeration of the 4^n_c contact modes. Throws InputError if p_ext has the
/// wrong length. `control` (may be null) is polled once per mode; stopping
/// throws StoppedError.
std::vector<Outcome> enumerate_outcomes(const Scene& scene, const VectorQ& p_ext, RunControl* control = nullptr);

/// The physical outcome of an LCP solution z = (p_n, p_f, s) at p_ext.
Outcome outcome_from_lcp_solution(const Scene& scene, const VectorQ& p_ext, const VectorQ& z);

/// Same (ν^{ℓ+1}, p_n, p_t), exactly.
bool same_outcome(const Outcome& a, const Outcome& b);

}  // namespace fixel
