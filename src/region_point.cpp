// The pushing region at single points: the point test (status_at, which
// compute_region also asks at corners), point_status and the sampling
// baseline sample_region.
#include <chrono>

#include "fixel/error.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/region_context.h"
#include "fixel/internal/region_filter.h"
#include "fixel/progress.h"
#include "fixel/region.h"

namespace fixel {

namespace internal {

namespace {

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

// Exact point test from the extreme push directions at lever arm r.
RegionStatus test_directions(RegionContext& ctx, const Vec2& r, const Vec2& d_first, const Vec2& d_last,
                             Magnitudes* out, std::vector<Magnitudes>* set = nullptr) {
  ++ctx.stats.point_tests;
  const std::vector<VectorQ> gens = {contact_wrench(r, d_first, 3), contact_wrench(r, d_last, 3)};
  return ctx.target.test_point(gens, d_first, d_last, out, set);
}

}  // namespace

RegionStatus status_at(RegionContext& ctx, const Boundary& b, const std::vector<Join>& js, int curve, const Rational& u,
                       Magnitudes* mags, std::vector<Magnitudes>* set, std::size_t first) {
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

}  // namespace internal

RegionStatus point_status(const Scene& scene, RegionTarget& target, int curve, const Rational& u, const Rational& mu,
                          Magnitudes* magnitudes) {
  internal::check_region_inputs(scene, mu, target);
  const int curves = static_cast<int>(scene.body.boundary->curves.size());
  if (curve < 0 || curve >= curves)
    throw InputError("curve", std::to_string(curve),
                     "is not a curve of the boundary (it has " + std::to_string(curves) + ")");
  internal::RegionContext ctx{scene, target, mu, ConeMethod::kTight, Rational(1), RegionStats{}};
  target.stats = nullptr;
  return internal::status_at(ctx, *scene.body.boundary, internal::joins(*scene.body.boundary), curve, u, magnitudes);
}

RegionStatus point_status(const Scene& scene, const SeatingSet& S, int curve, const Rational& u, const Rational& mu,
                          Magnitudes* magnitudes, const GuaranteedSet* guaranteed) {
  const auto target = internal::step_target(scene, S, guaranteed);
  return point_status(scene, *target, curve, u, mu, magnitudes);
}

Region sample_region(const Scene& scene, RegionTarget& target, int points_per_curve, std::optional<Rational> pusher_mu,
                     RunControl* control) {
  const internal::ControlScopeIfGiven scope(control);  // its exact steps poll it too
  const internal::ExactTask task("sample");
  const auto start = std::chrono::steady_clock::now();
  const Rational mu = pusher_mu.value_or(internal::default_pusher_mu(scene, target));
  internal::check_region_inputs(scene, mu, target, !pusher_mu);
  // Bounded, as every loop whose length the caller sets: a million points
  // of one curve is far beyond any resolution a region needs.
  if (points_per_curve <= 0 || points_per_curve > 1000000)
    throw InputError("sample_region(points_per_curve)", std::to_string(points_per_curve), "must be in [1, 1000000]");
  const Boundary& b = *scene.body.boundary;
  internal::RegionContext ctx{scene, target, mu, ConeMethod::kTight, Rational(1), RegionStats{}};
  target.stats = &ctx.stats;
  const std::vector<internal::Join> js = internal::joins(b);
  const long total = static_cast<long>(b.curves.size()) * points_per_curve;
  Region region;
  region.built_from = std::make_shared<const Scene>(scene);
  for (std::size_t c = 0; c < b.curves.size(); ++c) {
    const Curve& curve = b.curves[c];
    for (int k = 0; k < points_per_curve; ++k) {
      poll(control, "sample", static_cast<long>(region.intervals.size()), total, "points");
      const Rational u = curve.u_begin() + (curve.u_end() - curve.u_begin()) * Rational(k, points_per_curve);
      RegionInterval r{static_cast<int>(c), u, u, RegionStatus::kPartial, false, Magnitudes{}, {}, {}, {}};
      r.status = internal::status_at(ctx, b, js, static_cast<int>(c), u, &r.magnitudes, &r.magnitude_set);
      r.half_line = internal::in_half_line(target, r);
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
  const auto target = internal::step_target(scene, S, guaranteed);
  return sample_region(scene, *target, points_per_curve, pusher_mu, control);
}

}  // namespace fixel
