#pragma once
/// @file
/// The pushing region (paper §5): where on the boundary a single
/// push seats the part, and how hard to push.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fixel/algebraic.h"
#include "fixel/curve.h"
#include "fixel/interval.h"
#include "fixel/rational.h"
#include "fixel/scene.h"
#include "fixel/seating.h"
#include "fixel/wrench_cone.h"

namespace fixel {

struct GuaranteedSet;
class RegionTarget;
struct RunControl;

/// Status of a stretch of boundary.
enum class RegionStatus {
  kIn,       ///< Every point is in the pushing region.
  kOut,      ///< No point is in the pushing region.
  kPartial,  ///< Undecided at the resolution.
};
std::string to_string(RegionStatus status);

/// A stretch [u0, u1] of curve `curve` (u0 == u1 for a corner point).
/// Where a region interval lies on the part, in frame A at the scene pose.
struct IntervalPlace {
  Vec2 start_A, end_A;    ///< Exact boundary points at u0 and u1 (m).
  double arc_length = 0;  ///< Length of outline covered, m (display: Gauss–Legendre quadrature).
  /// Unit inward normal at the interval's middle: the frictionless push
  /// direction (display); unset where the normal is undefined (a corner).
  std::optional<std::array<double, 2>> push_direction_A;
  /// The boundary point at the middle parameter (u0 + u1)/2, where
  /// push_direction_A is taken (m, display; on the curve, not the chord).
  std::optional<std::array<double, 2>> middle_A;
};

struct RegionInterval {
  int curve = 0;
  Rational u0, u1;
  RegionStatus status = RegionStatus::kPartial;
  /// IN only: every push ray is a half-line (any magnitude above the lower
  /// end works, so the push magnitude need not be controlled).
  bool half_line = false;
  /// IN only: Euclidean magnitudes |p| (N·s) of the push impulse's force
  /// that seat the part at every point of the interval and in every push
  /// direction of the contact cone, as a certified rational inner bound;
  /// empty when no common magnitude was found.
  Magnitudes magnitudes;
  /// With a guaranteed set (RegionOptions::guaranteed): for a point sample
  /// the admissible Euclidean magnitudes |p| along its ray as disjoint
  /// intervals (the exact union, each end rounded inward to a rational); for
  /// an IN interval the certified magnitude range of one convex piece of G.
  std::vector<Magnitudes> magnitude_set;
  /// Exact region only (RegionOptions::exact): an end that is an
  /// irrational algebraic number. `u0` (resp. `u1`) then holds a rational
  /// inside its isolating interval, the same for both intervals that share
  /// the end; a rational end is `u0`/`u1` itself and this stays empty.
  std::optional<AlgebraicReal> exact_u0, exact_u1;
};

/// Counters of a region computation.
struct RegionStats {
  long cone_tests = 0;  ///< Segment classifications (one per segment visited).
  /// OUT tests past the ray shortcut, per piece of G (the exact LP, or an
  /// interval-checked certificate standing for it: Farkas for "missed", a
  /// hitting combination of generators for "met").
  long lp_tests = 0;
  long point_tests = 0;     ///< Point tests (corners, samples).
  int depth = 0;            ///< Deepest subdivision level (0 = whole Bézier piece).
  Rational partial_length;  ///< Total parameter length left PARTIAL.
  long roots = 0;           ///< Exact region: real roots isolated in the pieces' interiors.
  double seconds = 0;       ///< Wall time (display only).
};

/// The region: intervals that tile every curve's parameter range, in order,
/// and how it was computed.
/// A corner (a polyline vertex or a knot where the tangent turns) whose
/// own status, for its whole fan of pushes, differs from the status of an
/// IN or OUT interval that ends there.
struct RegionCorner {
  int curve = 0;
  Rational u;
  RegionStatus status = RegionStatus::kPartial;
};

struct Region {
  /// The intervals tile each curve's parameter range; neighbours share an
  /// end. A status holds at every point of its interval, ends included,
  /// except at an end listed in `corners`: there the corner's own status
  /// holds for its whole fan of pushes, and the interval's only for pushes
  /// along its own piece's one-sided normal. (With `exact`, a status holds
  /// strictly between the ends.)
  std::vector<RegionInterval> intervals;
  /// The corners where an IN or OUT interval of another status ends, in
  /// loop order (empty for samples).
  std::vector<RegionCorner> corners;
  RegionStats stats;
  std::string push = "step";             ///< Push model of the target: "step" (S, G) or "sustained" (J).
  ConeMethod cone = ConeMethod::kTight;  ///< Segment cone used.
  /// The parameter width asked for (none for samples). Splitting stopped
  /// there, or at depth 200 (stats.depth 200) when that is finer.
  std::optional<Rational> resolution;
  /// With RegionOptions::resolution_length: the length L (m), and the
  /// parameter width each Bézier piece used (parallel to the boundary's
  /// pieces); `resolution` is then unset.
  std::optional<Rational> resolution_length;
  std::vector<Rational> piece_widths;
  Rational pusher_mu;        ///< Pusher friction used.
  std::string target = "S";  ///< The target's name: "S", "G" or "J".
  bool sampled = false;      ///< From sample_region (point tests), not subdivision.
  /// Computed by root isolation (RegionOptions::exact): no resolution, every
  /// end exact, no partial stretch.
  bool exact = false;
  /// With `exact`: irrational ends refined to width 10^-digits (0: as isolated).
  int digits = 0;
  /// Where each interval is on the part (parallel to `intervals`; filled
  /// by locate_intervals, which compute_region and sample_region call).
  std::vector<IntervalPlace> places;
  double outline_length = 0;  ///< Arc length of the whole boundary, m (display).
  /// The scene it was computed for (set by compute_region and
  /// sample_region; null for a region built by hand, which is not checked).
  /// region_json, region_text, the SVG writers and validate_region refuse a
  /// scene that differs where the region looks (the outline, mass
  /// properties, fixels and, for S and G, h, velocity and b0) with an
  /// InputError naming `region` and the field.
  std::shared_ptr<const Scene> built_from;
};

/// What "in" means for this region's target, as every report labels it:
/// "one-step: can seat" (S), "one-step: guaranteed" (G) or "sustained
/// push: seats and stays" (J).
std::string in_meaning(const Region& region);

/// Fills region.places and region.outline_length from the scene's boundary.
void locate_intervals(const Scene& scene, Region& region);

/// How the region was computed, as reports name it: "sample" or the cone
/// method ("tight", "paper").
std::string method_of(const Region& region);

/// Options of compute_region.
struct RegionOptions {
  /// Stop splitting at this parameter width (curve units). Splitting also
  /// stops at depth 200 (2⁻²⁰⁰ of a piece) whatever a finer resolution asks;
  /// RegionStats::depth then says 200.
  Rational resolution = Rational(1, 1024);
  /// A resolution as a length (m) instead: each Bézier piece stops splitting
  /// at its own parameter width resolution_width(piece, L), so that every
  /// stretch left has arc length <= L. Overrides `resolution` when set;
  /// InputError when <= 0, or when a piece would need more than 2^64 parts.
  std::optional<Rational> resolution_length;
  ConeMethod cone = ConeMethod::kTight;
  std::optional<Rational> pusher_mu;  ///< Overrides the scene's pusher μ.
  bool merge = true;                  ///< Merge adjacent intervals with equal status.
  /// Classify against the guaranteed set G instead of S (frictionless
  /// pusher only; G must belong to the same scene and S).
  const GuaranteedSet* guaranteed = nullptr;
  /// Polled once per segment classified: cancellation, time limit and
  /// progress (may be null). Stopping throws StoppedError.
  RunControl* control = nullptr;
  /// Exact region (docs/theory.md §12): along every Bézier piece, isolate the
  /// real roots of the polynomials whose signs decide the point test, and
  /// test one rational point between consecutive roots. `resolution` and
  /// `cone` are then unused; no interval is partial except single points
  /// where the normal is undefined. Throws UnsupportedError for a target
  /// that cannot give its sign polynomials (G).
  bool exact = false;
  /// With `exact`: refine irrational ends to width <= 10^-digits in the
  /// curve parameter (0: leave them as isolated). InputError when < 0 or > 1000.
  int digits = 0;
};

/// An exact rational upper bound on the speed |dc/ds| of a Bézier piece in
/// its local parameter s ∈ [0, 1]: degree × the longest control-polygon leg
/// (the hodograph's control points n (P_{k+1} − P_k) bound it), each leg's
/// length rounded up to a rational. For a polyline edge it is the edge's
/// length, rounded up.
Rational speed_bound(const BezierPiece& piece);

/// The parameter width at which a piece stops splitting for a resolution
/// length L > 0: (u1 − u0) / 2^d with the smallest d >= 0 such that
/// speed_bound(piece) / 2^d <= L. Every sub-piece reached by halving d times
/// has arc length <= speed_bound / 2^d <= L. Throws InputError
/// ("RegionOptions.resolution_length") when L <= 0 or d would exceed 64.
Rational resolution_width(const BezierPiece& piece, const Rational& length);

/// The pushing region by recursive subdivision. Throws
/// InputError for a non-positive resolution or negative μ, and SceneError if
/// the scene has no boundary.
Region compute_region(const Scene& scene, const SeatingSet& S, const RegionOptions& options);

/// The point-sampling baseline: N (1 to 1,000,000) uniformly spaced parameters per curve,
/// u = u_begin + k (u_end − u_begin) / N, k = 0..N−1, each an interval
/// [u, u] with status in or out (partial where the normal is undefined).
/// `control` (may be null) is polled once per point; stopping throws
/// StoppedError.
Region sample_region(const Scene& scene, const SeatingSet& S, int points_per_curve,
                     std::optional<Rational> pusher_mu = std::nullopt, const GuaranteedSet* guaranteed = nullptr,
                     RunControl* control = nullptr);

/// The region against any target (S, G, J: see region_target.h); the
/// algorithm is the same for every target. The pusher μ defaults to the
/// scene's (its upper end for a sustained-push target).
Region compute_region(const Scene& scene, RegionTarget& target, const RegionOptions& options);

/// The sampling baseline against any target.
Region sample_region(const Scene& scene, RegionTarget& target, int points_per_curve,
                     std::optional<Rational> pusher_mu = std::nullopt, RunControl* control = nullptr);

/// Exact point test against any target.
RegionStatus point_status(const Scene& scene, RegionTarget& target, int curve, const Rational& u,
                          const Rational& pusher_mu, Magnitudes* magnitudes = nullptr);

/// Exact point test at parameter u of curve k (a corner uses its whole fan of
/// push directions). kPartial when the contact normal is undefined there.
RegionStatus point_status(const Scene& scene, const SeatingSet& S, int curve, const Rational& u,
                          const Rational& pusher_mu, Magnitudes* magnitudes = nullptr,
                          const GuaranteedSet* guaranteed = nullptr);

}  // namespace fixel
