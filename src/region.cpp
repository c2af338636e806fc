#include "fixel/region.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/region_exact.h"
#include "fixel/internal/region_filter.h"
#include "fixel/internal/region_runs.h"
#include "fixel/lcp.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"

namespace fixel {

namespace {

const std::vector<EdgeFamily>& families(const Rational& mu) {
  static const std::vector<EdgeFamily> normal{EdgeFamily::kNormal}, edges{EdgeFamily::kMinus, EdgeFamily::kPlus};
  return mu == 0 ? normal : edges;
}

// Push directions at a point with incoming and outgoing tangents (equal at
// a smooth point): the extreme edge directions of all friction cones around
// the normals of the fan. False if they span π or more.
bool push_extremes(const Vec2& t_in, const Vec2& t_out, const Rational& mu, Vec2& first, Vec2& last) {
  std::vector<Vec2> dirs;
  for (auto f : families(mu)) {
    dirs.push_back(push_direction(t_in, f, mu));
    dirs.push_back(push_direction(t_out, f, mu));
  }
  return direction_extremes(dirs, first, last);
}

struct Context {
  const Scene& scene;
  RegionTarget& target;
  Rational mu;
  ConeMethod method;
  Rational resolution;
  RegionStats stats;
  RunControl* control = nullptr;
  // When set, IN answers whose magnitudes the enclosures bound wait here for
  // the merge (internal::settle); index SIZE_MAX until the interval is placed.
  std::vector<internal::Deferred>* deferred = nullptr;
};

constexpr std::size_t kUnplaced = static_cast<std::size_t>(-1);

// Exact point test from the extreme push directions at lever arm r.
RegionStatus test_directions(Context& ctx, const Vec2& r, const Vec2& d_first, const Vec2& d_last, Magnitudes* out,
                             std::vector<Magnitudes>* set = nullptr) {
  ++ctx.stats.point_tests;
  const std::vector<VectorQ> gens = {contact_wrench(r, d_first, 3), contact_wrench(r, d_last, 3)};
  return ctx.target.test_point(gens, d_first, d_last, out, set);
}

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

void subdivide(Context& ctx, const internal::LazyPiece& seg, int depth, std::vector<RegionInterval>& out) {
  RegionInterval r = classify(ctx, seg);
  ctx.stats.depth = std::max(ctx.stats.depth, depth);
  if (r.status != RegionStatus::kPartial || seg.u1() - seg.u0() <= ctx.resolution || depth >= 200) {
    if (r.status == RegionStatus::kPartial) ctx.stats.partial_length += seg.u1() - seg.u0();
    out.push_back(std::move(r));
    place_deferred(ctx, out.size() - 1);
    return;
  }
  const auto halves = seg.halves();
  subdivide(ctx, halves.first, depth + 1, out);
  subdivide(ctx, halves.second, depth + 1, out);
}

void check_inputs(const Scene& scene, const Rational& mu, const RegionTarget& target) {
  target.check_pusher(mu);
  if (!scene.body.boundary)
    throw SceneError("body.boundary", "", "is missing: the pushing region needs the part's outline");
  if (scene.body.dof != 3) throw SceneError("body.dof", "2", "a point mass has no boundary to push on");
  if (mu < 0) throw InputError("RegionOptions.pusher_mu", to_string(mu), "must be >= 0");
}

// `first`: no piece before it holds u (the caller knows; saves a scan of
// every piece per corner, which made long polylines quadratic).
RegionStatus status_at(Context& ctx, const Boundary& b, const std::vector<internal::Join>& js, int curve,
                       const Rational& u, Magnitudes* mags, std::vector<Magnitudes>* set = nullptr,
                       std::size_t first = 0) {
  for (std::size_t k = first; k < b.pieces.size(); ++k) {
    const BezierPiece& piece = b.pieces[k];
    if (piece.curve != curve) continue;
    const bool at_start = u == piece.u0, inside = u > piece.u0 && u < piece.u1;
    const bool at_curve_end = u == piece.u1 && (k + 1 == b.pieces.size() || b.pieces[k + 1].curve != curve);
    if (!at_start && !inside && !at_curve_end) continue;
    // At a piece start the join has the tangents' enclosures; the exact
    // tangents are made only when the exact path needs them.
    const internal::Join* j = at_start || at_curve_end ? &js[at_start ? k : (k + 1) % b.pieces.size()] : nullptr;
    const Vec2 point = j ? (at_start ? piece.control.front() : piece.control.back()) : piece.point(piece.local(u));
    const Vec2 t = j ? Vec2{} : piece.derivative(piece.local(u));
    auto tangents = [&b, j, t](Vec2& t_in, Vec2& t_out) {
      t_in = j ? internal::end_tangent(b.pieces[j->prev]) : t;
      t_out = j ? internal::start_tangent(b.pieces[j->next]) : t;
    };
    if (!force_exact())
      if (internal::IntervalTarget* it = ctx.target.interval_target(); it && it->answers_points()) {
        const long lp_before = ctx.stats.lp_tests;  // what the pre-test counted goes if the exact path runs
        std::optional<internal::MagnitudeBounds> bounds;
        const internal::FVec2 ft = j ? internal::FVec2{} : internal::to_interval(t);
        const internal::Quick q =
            internal::quick_point(j ? j->t_in : ft, j ? j->t_out : ft, point, ctx.scene.body.p_AoCm_A, ctx.mu,
                                  families(ctx.mu), *it, ctx.deferred ? &bounds : nullptr);
        internal::record_filter(FilterSite::kRegionTest, q != internal::Quick::kUnknown);
        if (q == internal::Quick::kPartial) return RegionStatus::kPartial;
        if (q == internal::Quick::kOut) {
          ++ctx.stats.point_tests;
          if (mags) *mags = Magnitudes{};
          return RegionStatus::kOut;
        }
        // IN magnitudes: certainly empty (certified), none bounded (the exact
        // path below), or deferred (settle() counts them).
        if (q == internal::Quick::kIn && ctx.deferred && mags && (!bounds || bounds->empty))
          internal::record_filter(FilterSite::kInMagnitudes, bounds.has_value());
        if (q == internal::Quick::kIn && bounds && mags) {
          ++ctx.stats.point_tests;
          if (bounds->empty) {
            *mags = Magnitudes{};  // no common magnitude: nothing to wait for
            return RegionStatus::kIn;
          }
          *mags = internal::neutral_magnitudes();
          ctx.deferred->push_back(
              {kUnplaced, *bounds, [&ctx, tangents, point] {
                 Vec2 t_in, t_out, first, last;
                 tangents(t_in, t_out);
                 const Vec2 r = sub(point, ctx.scene.body.p_AoCm_A);
                 Magnitudes m;
                 if (!push_extremes(t_in, t_out, ctx.mu, first, last) ||
                     ctx.target.test_point({contact_wrench(r, first, 3), contact_wrench(r, last, 3)}, first, last, &m,
                                           nullptr) != RegionStatus::kIn)
                   throw InternalError("region: a certified IN point is not IN exactly");
                 return m;
               }});
          return RegionStatus::kIn;
        }
        ctx.stats.lp_tests = lp_before;
      }
    Vec2 t_in, t_out;
    tangents(t_in, t_out);
    if (is_zero(t_in) || is_zero(t_out)) return RegionStatus::kPartial;  // undefined normal (cusp)
    Vec2 first, last;
    if (!push_extremes(t_in, t_out, ctx.mu, first, last)) return RegionStatus::kPartial;  // fan of π or more
    return test_directions(ctx, sub(point, ctx.scene.body.p_AoCm_A), first, last, mags, set);
  }
  throw InputError("u", to_string(u), "is outside curve " + std::to_string(curve) + "'s parameter range");
}

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

namespace {

std::unique_ptr<RegionTarget> step_target(const Scene& scene, const SeatingSet& S, const GuaranteedSet* G) {
  if (G) return guaranteed_target(*G, S, scene.background_impulse);
  return seating_target(S, scene.background_impulse);
}

// A push is judged at the upper end of the pusher's friction interval: the
// set of push directions grows with μ_p, so the region shrinks
// (docs/theory.md §10).
Rational default_pusher_mu(const Scene& scene, const RegionTarget&) { return scene.pusher_mu_upper(); }

bool in_half_line(const RegionTarget& target, const RegionInterval& r) {
  if (r.status != RegionStatus::kIn) return false;
  return std::string(target.push_model()) == "sustained" || r.magnitudes.half_line();
}

}  // namespace

Region compute_region(const Scene& scene, RegionTarget& target, const RegionOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Rational mu = options.pusher_mu.value_or(default_pusher_mu(scene, target));
  check_inputs(scene, mu, target);
  if (options.resolution <= 0)
    throw InputError("RegionOptions.resolution", to_string(options.resolution), "must be > 0");
  if (options.resolution_length && *options.resolution_length <= 0)
    throw InputError("RegionOptions.resolution_length", to_string(*options.resolution_length), "must be > 0");
  if (options.digits < 0 || options.digits > 1000)
    throw InputError("RegionOptions.digits", std::to_string(options.digits), "must be in [0, 1000]");
  const Boundary& b = *scene.body.boundary;
  Context ctx{scene, target, mu, options.cone, options.resolution, RegionStats{}, options.control};
  std::vector<Rational> widths;
  if (options.resolution_length && !options.exact)
    for (const auto& piece : b.pieces) widths.push_back(resolution_width(piece, *options.resolution_length));
  target.stats = &ctx.stats;
  const std::vector<internal::Join> js = internal::joins(b);
  std::vector<RegionInterval> raw;
  raw.reserve(2 * b.pieces.size());  // a corner and a segment per piece when nothing splits
  std::vector<internal::Deferred> deferred;
  if (!options.exact) ctx.deferred = &deferred;
  for (std::size_t k = 0; k < b.pieces.size(); ++k) {
    const BezierPiece& piece = b.pieces[k];
    if (js[k].corner) {
      RegionInterval corner{piece.curve, piece.u0, piece.u0, RegionStatus::kPartial, false, Magnitudes{}, {}, {}, {}};
      corner.status = status_at(ctx, b, js, piece.curve, piece.u0, &corner.magnitudes, &corner.magnitude_set, k);
      corner.half_line = in_half_line(target, corner);
      if (!deferred.empty() && deferred.back().index == kUnplaced)  // its magnitudes wait: the bounds say
        corner.half_line = std::string(target.push_model()) == "sustained" || !deferred.back().bounds.has_hi;
      raw.push_back(corner);
      place_deferred(ctx, raw.size() - 1);
    }
    if (options.exact) {
      poll(ctx.control, "region", static_cast<long>(k), static_cast<long>(b.pieces.size()), "pieces");
      for (auto& r : internal::exact_piece_intervals(scene, target, piece, mu, ctx.stats)) raw.push_back(std::move(r));
      target.stats = &ctx.stats;  // the point tests reset it
    } else {
      if (!widths.empty()) ctx.resolution = widths[k];
      const bool enclose = !force_exact() && target.interval_target();
      subdivide(ctx, internal::LazyPiece(piece, enclose), 0, raw);
    }
  }
  internal::settle(raw, deferred, options.merge);
  target.stats = nullptr;
  Region region;
  region.intervals = options.merge ? internal::merge_runs(std::move(raw)) : std::move(raw);
  if (options.exact) {
    region.exact = true;
    region.digits = options.digits;
    if (options.digits > 0) {
      Rational width = 1;
      for (int k = 0; k < options.digits; ++k) width /= 10;
      for (auto& r : region.intervals) {
        if (r.exact_u0) r.u0 = (r.exact_u0 = refined(*r.exact_u0, width))->midpoint();
        if (r.exact_u1) r.u1 = (r.exact_u1 = refined(*r.exact_u1, width))->midpoint();
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
  locate_intervals(scene, region);
  region.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return region;
}

std::string method_of(const Region& region) {
  if (region.sampled) return "sample";
  return region.exact ? "exact" : to_string(region.cone);
}

Region compute_region(const Scene& scene, const SeatingSet& S, const RegionOptions& options) {
  const auto target = step_target(scene, S, options.guaranteed);
  return compute_region(scene, *target, options);
}

RegionStatus point_status(const Scene& scene, RegionTarget& target, int curve, const Rational& u, const Rational& mu,
                          Magnitudes* magnitudes) {
  check_inputs(scene, mu, target);
  Context ctx{scene, target, mu, ConeMethod::kTight, Rational(1), RegionStats{}};
  target.stats = nullptr;
  return status_at(ctx, *scene.body.boundary, internal::joins(*scene.body.boundary), curve, u, magnitudes);
}

RegionStatus point_status(const Scene& scene, const SeatingSet& S, int curve, const Rational& u, const Rational& mu,
                          Magnitudes* magnitudes, const GuaranteedSet* guaranteed) {
  const auto target = step_target(scene, S, guaranteed);
  return point_status(scene, *target, curve, u, mu, magnitudes);
}

Region sample_region(const Scene& scene, RegionTarget& target, int points_per_curve, std::optional<Rational> pusher_mu,
                     RunControl* control) {
  const auto start = std::chrono::steady_clock::now();
  const Rational mu = pusher_mu.value_or(default_pusher_mu(scene, target));
  check_inputs(scene, mu, target);
  if (points_per_curve <= 0)
    throw InputError("sample_region(points_per_curve)", std::to_string(points_per_curve), "must be >= 1");
  const Boundary& b = *scene.body.boundary;
  Context ctx{scene, target, mu, ConeMethod::kTight, Rational(1), RegionStats{}};
  target.stats = &ctx.stats;
  const std::vector<internal::Join> js = internal::joins(b);
  const long total = static_cast<long>(b.curves.size()) * points_per_curve;
  Region region;
  for (std::size_t c = 0; c < b.curves.size(); ++c) {
    const Curve& curve = b.curves[c];
    for (int k = 0; k < points_per_curve; ++k) {
      poll(control, "sample", static_cast<long>(region.intervals.size()), total, "points");
      const Rational u = curve.u_begin() + (curve.u_end() - curve.u_begin()) * Rational(k, points_per_curve);
      RegionInterval r{static_cast<int>(c), u, u, RegionStatus::kPartial, false, Magnitudes{}, {}, {}, {}};
      r.status = status_at(ctx, b, js, static_cast<int>(c), u, &r.magnitudes, &r.magnitude_set);
      r.half_line = in_half_line(target, r);
      region.intervals.push_back(r);
    }
  }
  target.stats = nullptr;
  region.stats = ctx.stats;
  region.push = target.push_model();
  region.target = target.name();
  region.sampled = true;
  region.pusher_mu = mu;
  locate_intervals(scene, region);
  region.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return region;
}

Region sample_region(const Scene& scene, const SeatingSet& S, int points_per_curve, std::optional<Rational> pusher_mu,
                     const GuaranteedSet* guaranteed, RunControl* control) {
  const auto target = step_target(scene, S, guaranteed);
  return sample_region(scene, *target, points_per_curve, pusher_mu, control);
}

}  // namespace fixel