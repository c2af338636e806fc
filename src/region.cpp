#include "fixel/region.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/region_context.h"
#include "fixel/internal/region_exact.h"
#include "fixel/internal/region_filter.h"
#include "fixel/internal/region_runs.h"
#include "fixel/lcp.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"

namespace fixel {

namespace {

using Context = internal::RegionContext;
using internal::families;
using internal::kUnplaced;

// Segment test: IN when the cone of every family's wrenches reaches the
// target, OUT when one family's cone misses it (that edge direction then
// misses at every point), else PARTIAL.
RegionInterval classify_exact(Context& ctx, const BezierPiece& seg) {
  RegionInterval out{seg.curve, seg.u0, seg.u1, RegionStatus::kPartial, false, Magnitudes{}, {}, {}, {}};
  // The tight cone needs no hull (min/max over all control points is the
  // same); the paper cone's ⊥-angle test wants the polygon's vertices.
  const SegmentBounds bounds = segment_bounds(seg, ctx.method == ConeMethod::kPaper);
  std::vector<WrenchCone> cones;
  for (auto f : families(ctx.mu)) {
    auto cone = segment_wrench_cone(bounds, ctx.scene.body.p_AoCm_A, f, ctx.mu, ctx.method, /*with_facets=*/false);
    if (!cone) return out;  // tangent or friction cone reaches π: split
    cones.push_back(std::move(*cone));
  }
  std::vector<VectorQ> gens;
  std::vector<Vec2> dirs;
  for (const auto& cone : cones)
    for (const auto& g : cone.generators) {
      gens.push_back(g);
      // A cone's generators come in pairs with one force part: keep one.
      if (dirs.empty() || dirs.back().x != g[0] || dirs.back().y != g[1]) dirs.push_back({g[0], g[1]});
    }
  Vec2 first, last;
  const bool pointed = direction_extremes(dirs, first, last);
  if (ctx.target.contains_cone(gens, pointed ? &first : nullptr, pointed ? &last : nullptr, &out)) {
    out.status = RegionStatus::kIn;
    return out;
  }
  for (const auto& cone : cones)
    if (ctx.target.misses(cone.generators)) {
      out.status = RegionStatus::kOut;
      return out;
    }
  return out;
}

RegionInterval classify(Context& ctx, const internal::LazyPiece& seg) {
  poll(ctx.control, "region", ctx.stats.cone_tests, 0, "segments classified");
  ++ctx.stats.cone_tests;
  RegionInterval out{seg.curve(), seg.u0(), seg.u1(), RegionStatus::kPartial, false, Magnitudes{}, {}, {}, {}};
  // OUT and partial from enclosures alone when the target answers on them;
  // IN with enclosed magnitudes waits for the merge; the rest: exact.
  if (!force_exact())
    if (internal::IntervalTarget* it = ctx.target.interval_target()) {
      const long lp_before = ctx.stats.lp_tests;  // what the pre-test counted goes if the exact path runs
      std::optional<internal::MagnitudeBounds> bounds;
      const internal::Quick q =
          internal::quick_segment(seg.enclosures(), seg.leg_enclosures(), ctx.scene.body.p_AoCm_A, ctx.mu,
                                  families(ctx.mu), ctx.method, *it, ctx.deferred ? &bounds : nullptr);
      internal::record_filter(FilterSite::kRegionTest, q != internal::Quick::kUnknown);
      if (q == internal::Quick::kPartial) return out;
      if (q == internal::Quick::kOut) {
        out.status = RegionStatus::kOut;
        return out;
      }
      if (q == internal::Quick::kIn && bounds) {
        out.status = RegionStatus::kIn;
        out.half_line = bounds->all_half;
        if (bounds->empty) {  // no common magnitude, as the exact path would find: nothing to wait for
          internal::record_filter(FilterSite::kInMagnitudes, true);
          return out;  // out.magnitudes is Magnitudes{}
        }
        // Deferred: settle() computes and counts it.
        out.magnitudes = internal::neutral_magnitudes();
        ctx.deferred->push_back({kUnplaced, *bounds, [&ctx, seg] {
                                   const RegionInterval r = classify_exact(ctx, seg.exact());
                                   if (r.status != RegionStatus::kIn)
                                     throw InternalError("region: a certified IN segment is not IN exactly");
                                   return r.magnitudes;
                                 }});
        return out;
      }
      if (q == internal::Quick::kIn && ctx.deferred) internal::record_filter(FilterSite::kInMagnitudes, false);
      ctx.stats.lp_tests = lp_before;
    }
  return classify_exact(ctx, seg.exact());
}

// Gives a deferred answer just pushed as out.back() its index.
void place_deferred(Context& ctx, std::size_t index) {
  if (ctx.deferred && !ctx.deferred->empty() && ctx.deferred->back().index == kUnplaced)
    ctx.deferred->back().index = index;
}

// region_reaches: an interval that is not OUT was placed.
struct Reached {};

// Places an interval of the run.
void place(Context& ctx, RegionInterval&& r, std::vector<RegionInterval>& out) {
  const RegionStatus status = r.status;
  out.push_back(std::move(r));
  place_deferred(ctx, out.size() - 1);
  if (ctx.stop_at_reach && status != RegionStatus::kOut) throw Reached{};
}

void subdivide(Context& ctx, const internal::LazyPiece& seg, int depth, std::vector<RegionInterval>& out) {
  RegionInterval r = classify(ctx, seg);
  ctx.stats.depth = std::max(ctx.stats.depth, depth);
  if (r.status != RegionStatus::kPartial || seg.u1() - seg.u0() <= ctx.resolution || depth >= 200) {
    if (r.status == RegionStatus::kPartial) ctx.stats.partial_length += seg.u1() - seg.u0();
    place(ctx, std::move(r), out);
    return;
  }
  const auto halves = seg.halves();
  subdivide(ctx, halves.first, depth + 1, out);
  subdivide(ctx, halves.second, depth + 1, out);
}

void check_options(const RegionOptions& options) {
  if (options.resolution <= 0)
    throw InputError("RegionOptions.resolution", to_string(options.resolution), "must be > 0");
  if (options.resolution_length && *options.resolution_length <= 0)
    throw InputError("RegionOptions.resolution_length", to_string(*options.resolution_length), "must be > 0");
  if (options.digits < 0 || options.digits > 1000)
    throw InputError("RegionOptions.digits", std::to_string(options.digits), "must be in [0, 1000]");
}

// Each piece's parameter width to stop splitting at, when the resolution is a length.
std::vector<Rational> piece_widths(const Boundary& b, const RegionOptions& options) {
  std::vector<Rational> widths;
  if (options.resolution_length && !options.exact)
    for (const auto& piece : b.pieces) widths.push_back(resolution_width(piece, *options.resolution_length));
  return widths;
}

// Every piece's corner and segment intervals, in loop order, before the
// deferred magnitudes are settled and runs merged. The deferred answers
// refer to `js`, which must outlive them.
void classify_pieces(Context& ctx, const RegionOptions& options, const std::vector<internal::Join>& js,
                     const std::vector<Rational>& widths, std::vector<RegionInterval>& raw,
                     std::vector<internal::Deferred>& deferred, std::vector<std::size_t>* corner_entries = nullptr) {
  const Boundary& b = *ctx.scene.body.boundary;
  RegionTarget& target = ctx.target;
  raw.reserve(2 * b.pieces.size());  // a corner and a segment per piece when nothing splits
  if (!options.exact) ctx.deferred = &deferred;
  for (std::size_t k = 0; k < b.pieces.size(); ++k) {
    const BezierPiece& piece = b.pieces[k];
    if (js[k].corner) {
      RegionInterval corner{piece.curve, piece.u0, piece.u0, RegionStatus::kPartial, false, Magnitudes{}, {}, {}, {}};
      corner.status =
          internal::status_at(ctx, b, js, piece.curve, piece.u0, &corner.magnitudes, &corner.magnitude_set, k);
      corner.half_line = internal::in_half_line(target, corner);
      if (!deferred.empty() && deferred.back().index == kUnplaced)  // its magnitudes wait: the bounds say
        corner.half_line = std::string(target.push_model()) == "sustained" || !deferred.back().bounds.has_hi;
      if (corner_entries) corner_entries->push_back(raw.size());
      place(ctx, std::move(corner), raw);
    }
    if (options.exact) {
      poll(ctx.control, "region", static_cast<long>(k), static_cast<long>(b.pieces.size()), "pieces");
      for (auto& r : internal::exact_piece_intervals(ctx.scene, target, piece, ctx.mu, ctx.stats))
        place(ctx, std::move(r), raw);
      target.stats = &ctx.stats;  // the point tests reset it
    } else {
      if (!widths.empty()) ctx.resolution = widths[k];
      const bool enclose = !force_exact() && target.interval_target();
      subdivide(ctx, internal::LazyPiece(piece, enclose), 0, raw);
    }
  }
}

std::vector<internal::Join> joins_of(const Scene& scene) { return internal::joins(*scene.body.boundary); }

// Joins a caller made beforehand: one per piece of the scene's outline.
const std::vector<internal::Join>& checked(const std::vector<internal::Join>& js, const Scene& scene) {
  if (js.size() != scene.body.boundary->pieces.size())
    throw InternalError("region: " + std::to_string(js.size()) + " joins given for an outline of " +
                        std::to_string(scene.body.boundary->pieces.size()) + " pieces");
  return js;
}

// target.stats points at the run's counters while it runs, and at nothing after.
struct StatsScope {
  RegionTarget& target;
  StatsScope(RegionTarget& t, RegionStats& stats) : target(t) { target.stats = &stats; }
  ~StatsScope() { target.stats = nullptr; }
};

}  // namespace

std::string to_string(RegionStatus status) {
  switch (status) {
    case RegionStatus::kIn:
      return "in";
    case RegionStatus::kOut:
      return "out";
    case RegionStatus::kPartial:
      return "partial";
  }
  return "?";
}

Region compute_region(const Scene& scene, RegionTarget& target, const RegionOptions& options) {
  return internal::compute_region_joined(scene, target, options, nullptr);
}

Region internal::compute_region_joined(const Scene& scene, RegionTarget& target, const RegionOptions& options,
                                       const std::vector<Join>* given_joins, bool locate) {
  const ControlScopeIfGiven scope(options.control);  // its exact steps poll it too
  const ExactTask task("region");
  const auto start = std::chrono::steady_clock::now();
  const Rational mu = options.pusher_mu.value_or(internal::default_pusher_mu(scene, target));
  internal::check_region_inputs(scene, mu, target, !options.pusher_mu);
  check_options(options);
  Context ctx{scene, target, mu, options.cone, options.resolution, RegionStats{}, options.control};
  const std::vector<Rational> widths = piece_widths(*scene.body.boundary, options);
  std::vector<RegionInterval> raw;
  std::vector<internal::Deferred> deferred;
  std::vector<std::size_t> corner_entries;
  {
    const StatsScope counting(target, ctx.stats);
    const std::vector<internal::Join> made = given_joins ? std::vector<internal::Join>{} : joins_of(scene);
    classify_pieces(ctx, options, given_joins ? checked(*given_joins, scene) : made, widths, raw, deferred,
                    &corner_entries);
    internal::settle(raw, deferred, options.merge);
  }
  Region region;
  region.built_from = std::make_shared<const Scene>(scene);
  region.corners = internal::corner_ends(raw, corner_entries);
  region.intervals = options.merge ? internal::merge_runs(std::move(raw)) : std::move(raw);
  if (options.exact) {
    region.exact = true;
    region.digits = options.digits;
    if (options.digits > 0) {
      Rational width = 1;
      for (int k = 0; k < options.digits; ++k) width /= 10;
      // An interval's end is usually the next one's start: refined once.
      std::optional<AlgebraicReal> last_given, last_refined;
      auto refine = [&](std::optional<AlgebraicReal>& end, Rational& u) {
        if (!end) return;
        const bool same =
            last_given && last_given->poly == end->poly && last_given->lo == end->lo && last_given->hi == end->hi;
        if (!same) {
          last_given = end;
          last_refined = refined(*end, width);
        }
        end = last_refined;
        u = end->midpoint();
      };
      const long n = static_cast<long>(region.intervals.size());
      for (long k = 0; k < n; ++k) {
        poll(options.control, "region", k, n, "intervals' ends refined");  // --max-seconds, Ctrl-C
        auto& r = region.intervals[static_cast<std::size_t>(k)];
        refine(r.exact_u0, r.u0);
        refine(r.exact_u1, r.u1);
      }
    }
  }
  region.stats = ctx.stats;
  region.push = target.push_model();
  region.target = target.name();
  region.cone = options.cone;
  if (!options.exact && options.resolution_length) {
    region.resolution_length = options.resolution_length;
    region.piece_widths = widths;
  } else if (!options.exact) {
    region.resolution = options.resolution;
  }
  region.pusher_mu = mu;
  if (locate) locate_intervals(scene, region);
  region.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return region;
}

std::string method_of(const Region& region) {
  if (region.sampled) return "sample";
  return region.exact ? "exact" : to_string(region.cone);
}

Region compute_region(const Scene& scene, const SeatingSet& S, const RegionOptions& options) {
  const auto target = internal::step_target(scene, S, options.guaranteed);
  return compute_region(scene, *target, options);
}

namespace internal {

bool region_reaches(const Scene& scene, RegionTarget& target, const RegionOptions& options,
                    const std::vector<Join>* given_joins) {
  const Rational mu = options.pusher_mu.value_or(default_pusher_mu(scene, target));
  check_region_inputs(scene, mu, target, !options.pusher_mu);
  check_options(options);
  Context ctx{scene, target, mu, options.cone, options.resolution, RegionStats{}, options.control};
  ctx.stop_at_reach = true;
  const std::vector<Rational> widths = piece_widths(*scene.body.boundary, options);
  std::vector<RegionInterval> raw;
  std::vector<Deferred> deferred;
  const StatsScope counting(target, ctx.stats);
  const std::vector<Join> made = given_joins ? std::vector<Join>{} : joins_of(scene);
  try {
    classify_pieces(ctx, options, given_joins ? checked(*given_joins, scene) : made, widths, raw, deferred);
  } catch (const Reached&) {
    return true;
  }
  return false;
}

const std::vector<EdgeFamily>& families(const Rational& mu) {
  static const std::vector<EdgeFamily> normal{EdgeFamily::kNormal}, edges{EdgeFamily::kMinus, EdgeFamily::kPlus};
  return mu == 0 ? normal : edges;
}

void check_region_scene(const Scene& scene) {
  if (!scene.body.boundary)
    throw SceneError("body.boundary", "", "is missing: the pushing region needs the part's outline");
  if (scene.body.dof != 3)
    throw SceneError("body.dof", std::to_string(scene.body.dof),
                     "a point mass has no boundary to push on: the pushing region needs a rigid body (dof 3)");
  check_scene_values(scene);
}

void check_region_inputs(const Scene& scene, const Rational& mu, const RegionTarget& target, bool mu_from_scene) {
  check_region_scene(scene);
  target.check_scene(scene);
  try {
    target.check_pusher(mu);
  } catch (const UnsupportedError& e) {
    if (!mu_from_scene) throw;
    // what() is "field: value reason": keep the reason, name the scene's field.
    std::string reason = e.what();
    const std::string prefix = e.field() + ": " + e.value() + " ";
    if (reason.rfind(prefix, 0) == 0) reason.erase(0, prefix.size());
    throw UnsupportedError("pusher.mu", e.value(),
                           reason + "; it is the scene's pusher friction, taken when no pusher mu is given");
  }
  if (mu < 0) throw InputError("RegionOptions.pusher_mu", to_string(mu), "must be >= 0");
}

Rational default_pusher_mu(const Scene& scene, const RegionTarget&) { return scene.pusher_mu_upper(); }

bool in_half_line(const RegionTarget& target, const RegionInterval& r) {
  if (r.status != RegionStatus::kIn) return false;
  return std::string(target.push_model()) == "sustained" || r.magnitudes.half_line();
}

std::unique_ptr<RegionTarget> step_target(const Scene& scene, const SeatingSet& S, const GuaranteedSet* G) {
  check_region_scene(scene);  // before a target is built from S: a point mass's S has two dimensions
  // S against the scene: the target's check_scene, which every region,
  // point and sample function asks first (once, not here too).
  if (G) return guaranteed_target(*G, S, scene.background_impulse);
  return seating_target(S, scene.background_impulse);
}

}  // namespace internal

}  // namespace fixel