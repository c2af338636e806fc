#pragma once
/// @file
/// Time-stepping simulation (paper eqs. 10–15) with the exact LCP solver.

#include <vector>

#include "fixel/lemke.h"
#include "fixel/rational.h"
#include "fixel/scene.h"

namespace fixel {

struct RunControl;

/// The state after one step.
struct StepRecord {
  VectorQ q;         ///< Configuration (x, y[, θ]) relative to the analysis configuration.
  VectorQ velocity;  ///< ν^{ℓ+1}.
  VectorQ gaps;      ///< ψ^{ℓ+1}, linearised (eq. 12).
  VectorQ p_n;       ///< Normal impulses.
  VectorQ p_f;       ///< Friction impulses, 2 per fixel (+t, −t columns).
  int pivots = 0;    ///< Lemke pivots for this step.
};

/// A whole simulation.
struct Simulation {
  std::vector<StepRecord> steps;
  bool seated = false;  ///< Every gap is exactly 0 after the last step.
};

/// Simulates `steps` steps from the scene's state (q = 0, ν^ℓ, ψ^ℓ). Step k
/// applies impulses[k] when k < impulses.size() and zero afterwards. W_n, W_t
/// and M stay those of the analysis configuration (docs/theory.md §6).
/// Throws InputError for steps <= 0 or an impulse of the wrong length, and
/// UnsupportedError if Lemke does not solve a step (ray termination or pivot
/// limit). `control` (may be null) is polled once per step; stopping throws
/// StoppedError.
Simulation simulate(const Scene& scene, const std::vector<VectorQ>& impulses, int steps, RunControl* control = nullptr);

}  // namespace fixel
