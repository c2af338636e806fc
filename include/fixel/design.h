#pragma once
/// @file
/// Fixture design (past the paper, docs/design.md): choose the three fixels
/// of a part so that one push seats it best. Every triple of candidate
/// contact points is a layout; each is filtered exactly (W_n nonsingular,
/// form closure with a pushing finger) and scored by the exact fraction of
/// the boundary's parameter length where a push seats the part.

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "fixel/rational.h"
#include "fixel/region.h"
#include "fixel/scene.h"

namespace fixel {

struct RunControl;

/// A place where a fixel may touch the part: parameter `u` of curve `curve`
/// of the boundary, with the boundary point and its inward normal there
/// (frame A, the part at its seat; the normal has any positive length).
struct DesignCandidate {
  int curve = 0;
  Rational u;
  Vec2 point;   ///< Boundary point at u (m, frame A).
  Vec2 normal;  ///< Inward normal: the tangent rotated by +90° (not unit).
};

/// Which push a layout is ranked by.
enum class DesignPush {
  kSustained,  ///< The sustained-push region against J (docs/theory.md §10).
  kStep,       ///< The paper's one-step region against S.
};

/// Options of a design run.
struct DesignOptions {
  DesignPush push = DesignPush::kSustained;
  /// Region resolution (curve-parameter width at which splitting stops).
  Rational resolution = Rational(1, 256);
  /// Fixel friction μ (the same for every fixel); `mu_hi` makes it the
  /// interval [mu, mu_hi], judged at mu_hi by J (the one-step model refuses
  /// intervals).
  Rational mu = Rational(1, 10);
  std::optional<Rational> mu_hi;
  /// Pusher friction (the upper end of an interval: the region shrinks as
  /// it grows, docs/theory.md §10.4).
  Rational pusher_mu = Rational(0);
  /// With a pusher friction interval [pusher_mu_lo, pusher_mu]: its lower
  /// end. Layouts are judged at pusher_mu; a layout's scene keeps the
  /// interval.
  std::optional<Rational> pusher_mu_lo;
  /// Gap given to every fixel for the one-step score (the sustained score
  /// is for the seat: gap 0).
  Rational gap = Rational(0);
  /// How many layouts to report (K > 0).
  int top = 5;
  /// Sustained ranking only: score the triples in order of their pair bound
  /// (an exact upper bound of the sustained score, docs/design.md) and stop
  /// when no triple left can enter the top K. The layouts are the same as
  /// with `bound` false (every triple scored); only the counts differ.
  bool bound = true;
  /// Worker threads; 0 means one per core. The result does not depend on it.
  int jobs = 0;
  /// Polled about once per layout from whichever thread finishes it:
  /// cancellation, time limit, progress ("design", done, total, "layouts").
  RunControl* control = nullptr;
};

/// DesignLayout::conditioning below which a layout is nearly singular
/// (display only), and a report warns when a contact lies on a curved
/// piece. Measured on seeded random parts with rounded corners and the
/// bundled parts (docs/design.md, "Reading a design"): Box2D at its default
/// settings failed pushes on 51 of 188 such layouts and on none of 316
/// above the level (208 of them on parts the level was not chosen from); a
/// finer engine (dt = h/16000, 100 + 50 iterations) seated every push of
/// all but 6, each below kVeryNearlySingular. On straight edges every
/// layout seated every push.
constexpr double kNearlySingular = 0.03;
/// Below this conditioning, with a contact on a curved piece, 6 of the 15
/// layouts measured failed pushes on the finer engine too.
constexpr double kVeryNearlySingular = 0.001;

/// One evaluated layout: three candidates (indices into the candidate list,
/// increasing) and its scores.
struct DesignLayout {
  std::array<int, 3> fixels{};
  /// Lexicographic index of the triple among all C(n, 3) (ties keep it).
  long index = 0;
  /// The ranking score: the IN parameter length of the region of the
  /// chosen push model divided by the boundary's parameter length (exact,
  /// at the resolution).
  Rational score;
  /// The sustained-push score, and whether J is empty (then it is 0).
  std::optional<Rational> sustained_score;
  std::optional<bool> sustained_empty;
  /// The one-step score (fixels at the rounded unit normals and the gap).
  std::optional<Rational> step_score;
  /// Solid angle of J as a fraction of all wrench directions, with the
  /// moment divided by the radius of gyration (display only; NaN if unknown).
  double j_width = 0;
  /// Largest angle (rad) between a candidate's normal and the rational unit
  /// normal used for the one-step score (display only).
  double normal_angle_error = 0;
  /// The smallest singular value of W_n (the three normal wrenches, moment
  /// divided by the radius of gyration): near 0 when the normal lines nearly
  /// meet in one point (display only; NaN if unknown). Below
  /// kNearlySingular, with a contact on a curved piece, Box2D at its default
  /// settings often fails pushes a finer engine seats, and below
  /// kVeryNearlySingular some fail there too (docs/design.md, "Reading a
  /// design").
  double conditioning = std::numeric_limits<double>::quiet_NaN();
  /// How many of the three contacts lie on a curved piece of the outline
  /// (degree above 1); −1 if unknown. A nearly singular layout is warned of
  /// only with one: on straight edges such layouts seated in Box2D
  /// (docs/design.md, "Reading a design").
  int curved_contacts = -1;
  /// With a gap: why the one-step scene has no seated pose (no pose closes
  /// every gap, so that fixture cannot seat the part); empty if it has one.
  std::string step_seat;
  /// Why a score is missing, if one is.
  std::string note;
};

/// Counts of a run. Every triple is exactly one of: singular, no form
/// closure, J empty (sustained ranking: scored 0 without a region), scored
/// by a region, or bounded (sustained ranking with DesignOptions::bound:
/// never scored, its bound being below the K-th score).
struct DesignStats {
  long candidates = 0;
  long triples = 0;          ///< C(candidates, 3).
  long singular = 0;         ///< W_n singular: dropped.
  long no_form_closure = 0;  ///< No boundary point where a frictionless push completes form closure: dropped.
  long j_empty = 0;          ///< J empty: score 0, no region computed (pruned).
  long regions = 0;          ///< Layouts scored by a region computation.
  long bounded = 0;          ///< Not scored: their pair bound shows they cannot enter the top K.
  long pruned() const { return singular + no_form_closure + j_empty + bounded; }
  double seconds = 0;  ///< Wall time (display only).
  int jobs = 1;        ///< Threads used.
};

/// A run's answer: the best `top` layouts, best first.
struct DesignResult {
  std::vector<DesignCandidate> candidates;
  std::vector<DesignLayout> layouts;
  DesignStats stats;
  /// Non-empty when there is no layout, saying why (e.g. fewer than three
  /// candidates, or every triple dropped).
  std::string no_layout;
};

/// Candidates every `spacing` of arc length (m) along the boundary, starting
/// half a spacing after the start of curve 0; without a spacing, 24 evenly
/// spaced ones. Arc length is measured in double precision to place them
/// (the parameter is then rounded to a multiple of 1/1024: the candidates are
/// exact boundary points, only their spacing is approximate); corners and
/// repeated points are skipped. Throws InputError for a spacing ≤ 0 or one
/// that gives more than 10000 candidates, SceneError without a boundary.
std::vector<DesignCandidate> boundary_candidates(const Scene& part, const std::optional<Rational>& spacing);

/// The candidate at parameter u of curve k, checked: the curve exists, u is
/// in its range and the boundary has one tangent there (not a corner).
/// Throws InputError naming `field` (e.g. "candidates[2].u").
DesignCandidate candidate_at(const Scene& part, int curve, const Rational& u, const std::string& field);

/// Checks a list of candidates given by the caller: at most 10000, and no
/// two at the same boundary point (a layout would put two fixels there).
/// Throws InputError naming the later entry, e.g. "candidates[3]".
void check_candidate_list(const std::vector<DesignCandidate>& candidates, const std::string& source = "candidates");

/// Throws InputError naming `candidates[k]` unless every candidate is the
/// part's own: candidate_at(part, curve, u) with the same point and normal
/// (a list made for another part would be scored as if on this one).
void check_candidates(const Scene& part, const std::vector<DesignCandidate>& candidates);

/// Parses a candidate file {"candidates": [{"curve": k, "u": ".."}, ...]}.
/// Throws ParseError for malformed JSON and InputError naming the entry
/// (check_candidate_list included).
std::vector<DesignCandidate> parse_candidates(const Scene& part, const std::string& json_text,
                                              const std::string& source = "candidates");
/// Reads and parses a candidate file.
std::vector<DesignCandidate> load_candidates(const Scene& part, const std::string& path);

/// Checks the part and the options before any work (dof 3, a boundary,
/// μ ≥ 0, lo ≤ hi, resolution > 0, gap ≥ 0, top > 0, 0 ≤ jobs ≤ 256, no
/// friction interval for the one-step ranking). Throws InputError/SceneError
/// naming the option.
void check_design(const Scene& part, const DesignOptions& options);

/// Number of triples C(n, 3). Throws InputError naming `candidates` when it
/// exceeds a long (n above about 3.8 million).
long triple_count(long n);

/// The triple of lexicographic index `index` among C(n, 3).
std::array<int, 3> triple_at(long n, long index);

/// The part with the three candidates as fixels: gap 0 and the candidates'
/// normals (the sustained analysis), or, with `step`, the rational unit
/// normals and the options' gap (the one-step analysis). `angle_error` gets
/// the largest rounding angle (rad, display only). Throws InputError naming
/// `layout[k]` for an index out of range or two fixels at one point, and
/// `candidates[i]` for a candidate that is not the part's own (as
/// check_candidates); design_scene, layout_region and complete_layouts
/// check their layouts so.
Scene layout_scene(const Scene& part, const std::vector<DesignCandidate>& candidates, const std::array<int, 3>& fixels,
                   const DesignOptions& options, bool step, double* angle_error = nullptr);

/// A layout as a scene to save and analyse on its own (`fixel design
/// --scene-out`): the part with the layout's three candidates (indices
/// into `candidates`) as fixels, as the ranking push model scored them.
/// Sustained ranking: gap 0, the options' μ (an interval kept) and pusher
/// μ, and each candidate's inward unit normal, exact when the normal's
/// length is rational; otherwise the nearby rational unit vector that the
/// one-step score uses, and the fixel is marked `off_boundary` (a slightly
/// different fixture: `angle_error` gets the largest angle, rad, display
/// only). One-step ranking: the one-step scene of layout_scene (rounded
/// normals, the options' gap), `off_boundary` where rounded. The name is
/// the part's with "-layout-" and `rank` (1 = best); the description says
/// which candidates, the score and any rounding. Throws InputError naming
/// `rank` (< 1), `layout` (a candidate index out of range), what
/// layout_scene throws, and `layout.score` when the layout's score is not
/// its score on this part under `options` (a layout of another part or
/// run: the layout is scored again, one layout's work).
Scene design_scene(const Scene& part, const std::vector<DesignCandidate>& candidates, const DesignLayout& layout,
                   int rank, const DesignOptions& options, double* angle_error = nullptr);

/// One batch: triples [first, first + count) in lexicographic order, each
/// filtered and scored by the ranking push model; returns the batch's best
/// `options.top` and adds its counts to `stats`. Single-threaded and a pure
/// function of its arguments (idempotent: the unit of a distributed run).
/// Every triple is scored: `options.bound` is not used here. Throws what
/// check_design, check_candidate_list and check_candidates throw (the
/// sustained filter reads every candidate, not only the triple's).
std::vector<DesignLayout> design_batch(const Scene& part, const std::vector<DesignCandidate>& candidates,
                                       const DesignOptions& options, long first, long count, DesignStats& stats);

/// The same for the triples of lexicographic index `indices`, in that order
/// (what DesignSearch hands out). Throws InputError naming `batch[k]` for an
/// index out of range.
std::vector<DesignLayout> design_batch(const Scene& part, const std::vector<DesignCandidate>& candidates,
                                       const DesignOptions& options, const std::vector<long>& indices,
                                       DesignStats& stats);
/// Best first: higher score, then lower triple index. Keeps the first `top`.
void rank_layouts(std::vector<DesignLayout>& layouts, int top);

/// Fills the scores of the other push model (and J's width) of reported
/// layouts, so each carries both scores. Throws what layout_scene throws
/// for a layout (another part's candidates); an analysis that fails for
/// one layout is that layout's `note`.
void complete_layouts(const Scene& part, const std::vector<DesignCandidate>& candidates, const DesignOptions& options,
                      std::vector<DesignLayout>& layouts);

/// The whole run on a oneTBB thread pool of `options.jobs` threads: batches
/// of triples, merged in index order, so the result is the same for any
/// number of threads. With the sustained ranking and `options.bound`, the
/// pair bound orders the triples and skips those that cannot enter the top
/// K (same layouts; the counts, also the same for any number of threads,
/// say how many were skipped). Throws what check_design,
/// check_candidate_list and check_candidates throw, and StoppedError when
/// `options.control` stops it.
DesignResult design(const Scene& part, const std::vector<DesignCandidate>& candidates, const DesignOptions& options);

/// The score of the scene's own three fixels with the same options (for
/// comparison with the designed layouts): the sustained and one-step IN
/// fractions at the scene's seat and gaps, with the design's friction. A
/// score the analyses refuse (e.g. a seated pose that cannot be solved) is
/// left empty and `note` says why.
DesignLayout score_scene_layout(const Scene& scene, const DesignOptions& options);

/// score_scene_layout of the scene's own fixels when it has three and they
/// can be scored; none otherwise (nothing to compare with).
std::optional<DesignLayout> shipped_layout(const Scene& scene, const DesignOptions& options);

/// Why a run has no layout: fewer than three candidates, or every triple
/// dropped (empty when there are layouts to report).
std::string no_layout_reason(const DesignStats& stats, std::size_t layouts);

/// `fixel design --json` (docs/formats.md): {"part", "push", "resolution",
/// "mu", "pusher_mu", "gap", "candidates", "layouts": [{"rank", "triple",
/// "fixels": [{"curve", "u", "point", "normal"}], "score", ...}],
/// "no_layout", "shipped", "stats"}. Exact numbers as strings.
std::string design_json(const Scene& part, const DesignResult& result, const DesignOptions& options,
                        const std::optional<DesignLayout>& shipped);
/// The same as a readable report.
std::string design_text(const Scene& part, const DesignResult& result, const DesignOptions& options,
                        const std::optional<DesignLayout>& shipped);
/// Draws the best `panels` layouts: the outline coloured by the ranking
/// region, the three fixels with their normals. Throws InputError if the
/// file cannot be written.
void write_design_svg(const std::string& path, const Scene& part, const DesignResult& result,
                      const DesignOptions& options, int panels = 3);

/// The region of one layout under the ranking push model (for pictures).
Region layout_region(const Scene& part, const std::vector<DesignCandidate>& candidates,
                     const std::array<int, 3>& fixels, const DesignOptions& options);

}  // namespace fixel
