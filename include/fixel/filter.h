#pragma once
/// @file
/// Floating-point filters with exact fallback (after CGAL's filtered
/// predicates): a decision is first evaluated in outward-rounded interval
/// arithmetic; when the interval certifies the sign, that is the exact
/// answer, otherwise the decision is recomputed in exact rationals. No answer
/// depends on which path ran. This header holds the global switch that forces
/// the exact path and the counters of how often each filter decided.

#include <string>

namespace fixel {

/// The filtered decisions, one counter pair each.
enum class FilterSite {
  kLemke,         ///< Lemke's pivot-path decisions (signs and ratio comparisons on an interval
                  ///< tableau; a fallback is one decided on exact tableau columns, or one whole
                  ///< run on the integer tableau when a pivot's interval held zero). A ratio tie
                  ///< proved by kLemkeTie counts as certified: no exact fallback ran.
  kLemkeTie,      ///< Lemke's ratio comparisons the intervals leave open: proved to be exact
                  ///< ties by a left null vector checked in integers (certified), or not
                  ///< (fallback: then decided on exact tableau columns, one kLemke fallback).
  kRayTest,       ///< Does the ray b0 + τ g (τ > 0) meet a convex target piece.
  kOutTest,       ///< Does a segment's wrench cone miss S, or one piece of G (before the exact LP).
  kOrientation,   ///< Signs of planar cross products (direction extremes).
  kCone,          ///< The extreme moments of a segment's tight wrench cone.
  kMembership,    ///< Side of a half-space a·p ≥ c or > c (S, G and polyhedron membership).
  kJam,           ///< Signs of J's escape and jam rows at an exact seated pose (Q(√d)).
  kRegionTest,    ///< A region segment or point test on enclosures of its cone (OUT and partial need
                  ///< no exact value; an IN answer's magnitudes are counted by kInMagnitudes).
  kInMagnitudes,  ///< The magnitudes of a region IN answer the pre-test certified: settled from their
                  ///< enclosures (certainly empty, or unable to change their merged run's), or
                  ///< computed on the exact path (fallback).
  kFeasibility,   ///< Fourier–Motzkin feasibility of a cone system over Q(√d) at an exact seated pose
                  ///< (J's pieces, and the J region's IN and OUT tests), run on enclosures first.
  kDesignBound,   ///< Fixture design's pair bound: the sign of a triple's det W_n, and whether a
                  ///< triple's score can still enter the top K (certified by an upper bound of its
                  ///< bound; a fallback computes the bound exactly).
  kApproach,      ///< J′'s hold test on one pair's family: settled by its pieces' cones (a hold at a
                  ///< piece's start, or outside every piece's outer cone), or by root isolation (fallback).
  kCount,
};

/// "lemke", "lemke tie", "ray test", "out test", "orientation", "cone", "membership", "jam test",
/// "region test", "in magnitudes", "feasibility", "design bound", "approach".
std::string to_string(FilterSite site);

/// How often one filter decided (certified) and how often it could not and
/// the exact path ran (fallbacks). Runs under force_exact() count neither.
struct FilterCounts {
  long certified = 0;  ///< Decided by the interval filter.
  long fallbacks = 0;  ///< Undecided by the filter: the exact path ran.
};

/// Counters of every site since the last reset_filter_stats().
struct FilterStats {
  FilterCounts site[static_cast<int>(FilterSite::kCount)];
  /// The counters of one site.
  const FilterCounts& at(FilterSite s) const { return site[static_cast<int>(s)]; }
  /// Sum of the fallbacks of every site.
  long total_fallbacks() const;
  /// Sum of the certified decisions of every site.
  long total_certified() const;
};

/// Sets the switch that forces (true) or releases (false) the exact path for
/// every filtered decision in the process; releasing it turns the filters
/// on only where directed_rounding_works(). The initial value is true when
/// the environment variable FIXEL_FORCE_EXACT is set to anything but "" or
/// "0". Answers are identical either way; only the time differs.
void set_force_exact(bool on);

/// Whether set_force_exact (or FIXEL_FORCE_EXACT) asks for the exact path:
/// what ForceExactScope saves and restores.
bool force_exact_set();

/// Whether the exact path is forced: by set_force_exact, or because
/// directed rounding does not work here (directed_rounding_works()), which
/// no call can release.
bool force_exact();

/// Whether setting the processor's rounding mode takes effect, so that the
/// filters' intervals hold their exact values. Checked once per process
/// (three interval operations). False under emulators that round to nearest
/// whatever the mode, valgrind among them: then every decision takes the
/// exact path (force_exact() is true), and answers stay exact, only slower.
bool directed_rounding_works();

/// A snapshot of the counters (thread-safe, relaxed).
FilterStats filter_stats();

/// Sets every counter to zero.
void reset_filter_stats();

/// Sets the switch (set_force_exact) for the lifetime of the object and
/// restores its previous value after (tests, the CLI's --exact-only).
class ForceExactScope {
 public:
  /// Sets the switch to `on`.
  explicit ForceExactScope(bool on = true) : previous_(force_exact_set()) { set_force_exact(on); }
  ~ForceExactScope() { set_force_exact(previous_); }
  ForceExactScope(const ForceExactScope&) = delete;
  ForceExactScope& operator=(const ForceExactScope&) = delete;

 private:
  bool previous_;
};

}  // namespace fixel
