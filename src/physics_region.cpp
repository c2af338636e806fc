// Push wrenches at boundary points, and the validation of a pushing region
// through the engine ("region --validate", docs/physics.md).
#include <cmath>
#include <random>
#include <sstream>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/internal/scene_differs.h"
#include "fixel/physics.h"
#include "fixel/progress.h"
#include "fixel/seated_pose.h"

namespace fixel::physics {

using fixel::to_string;  // physics::to_string(Outcome) would hide it

namespace {

// Unit inward normal and lever arm at (curve, u), in the body frame at the
// scene pose. For a counter-clockwise loop the inside is to the left.
struct Contact {
  double nx, ny, r_cross_n;
};

Contact contact_at(const Scene& scene, int k, const Rational& u, const std::string& field) {
  if (!scene.body.boundary)
    throw SceneError("body.boundary", "", "is missing: a push at a boundary point needs the outline");
  const auto& curves = scene.body.boundary->curves;
  const std::string where = std::to_string(k) + ":" + to_string(u);
  if (k < 0 || k >= static_cast<int>(curves.size()))
    throw InputError(field, where, "names no curve (the boundary has " + std::to_string(curves.size()) + ")");
  const Curve& c = curves[k];
  if (u < c.u_begin() || u > c.u_end())
    throw InputError(field, where,
                     "is outside curve " + std::to_string(k) + "'s range [" + to_string(c.u_begin()) + ", " +
                         to_string(c.u_end()) + "]");
  const Vec2 b = c.point(u);
  const Vec2 d = c.derivative(u);
  if (d.x == 0 && d.y == 0) throw SceneError(field, where, "has a zero tangent (no normal)");
  const double tx = to_double(d.x), ty = to_double(d.y), len = std::hypot(tx, ty);
  const double nx = -ty / len, ny = tx / len;
  const double rx = to_double(b.x - scene.body.p_AoCm_A.x), ry = to_double(b.y - scene.body.p_AoCm_A.y);
  return {nx, ny, rx * ny - ry * nx};
}

// τ for the one-step model inside certified magnitudes (docs/physics.md).
std::optional<double> pick_magnitude(const Magnitudes& m, double fallback) {
  if (m.empty) return std::nullopt;
  const double lo = to_double(m.lo);
  if (m.hi) return (lo + to_double(*m.hi)) / 2;
  return lo > 0 ? 2 * lo : fallback;
}

// A push wrench computed from the scene that doubles cannot hold: not the
// user's wrench (push() would blame that), but the scene's numbers.
void require_finite(const Wrench& w, const Scene& scene, const std::string& field, int curve, const Rational& u,
                    const std::string& detail) {
  if (std::isfinite(w.fx) && std::isfinite(w.fy) && std::isfinite(w.m)) return;
  std::ostringstream shown;
  shown << "gives the push wrench (" << w.fx << ", " << w.fy << ", " << w.m
        << "), which doubles cannot hold: the part's size or position is beyond the engine's range (centre of "
           "mass ≈ ("
        << to_double(scene.body.p_AoCm_A.x) << ", " << to_double(scene.body.p_AoCm_A.y) << ") m, " << detail << ")";
  throw SceneError(field, std::to_string(curve) + ":" + to_string(u), shown.str());
}

}  // namespace

Wrench push_wrench_at(const Scene& scene, int curve, const Rational& u, const Pose& pose, const std::string& field) {
  if (!std::isfinite(pose.theta)) throw InputError("pose.theta", std::to_string(pose.theta), "must be finite (rad)");
  const Contact c = contact_at(scene, curve, u, field);
  const double cs = std::cos(pose.theta), sn = std::sin(pose.theta);
  // A rotation turns force and lever arm alike, so the moment is unchanged.
  const Wrench w{cs * c.nx - sn * c.ny, sn * c.nx + cs * c.ny, c.r_cross_n};
  std::ostringstream rotation;
  rotation << "seat rotation " << pose.theta << " rad";
  require_finite(w, scene, field, curve, u, rotation.str());
  return w;
}

CurvePoint parse_curve_point(const Scene& scene, const std::string& text, const std::string& field) {
  const auto colon = text.find(':');
  if (colon == std::string::npos || colon == 0)
    throw ParseError(field, "\"" + text + "\"", "must be K:U (curve index, exact parameter)");
  const std::string k_text = text.substr(0, colon);
  for (char ch : k_text)
    if (ch < '0' || ch > '9') throw ParseError(field, "\"" + text + "\"", "curve index is not a whole number");
  if (k_text.size() > 6) throw InputError(field, "\"" + text + "\"", "names no curve");
  CurvePoint p{std::stoi(k_text), parse_rational(text.substr(colon + 1), field)};
  contact_at(scene, p.curve, p.u, field);  // range checks
  return p;
}

PushModel one_step_push_model(const Scene& scene, const SeatingSet& S, const Rational& pusher_mu) {
  check_seating_set_of(scene, S);
  const double apex = std::hypot(to_double(S.apex[0]), to_double(S.apex[1]));
  const double h = to_double(scene.time_step);
  return [&scene, &S, pusher_mu, apex, h](const RegionInterval& iv, const Rational& u) {
    auto tau = pick_magnitude(iv.magnitudes, apex);
    if (!tau) {
      Magnitudes own;
      point_status(scene, S, iv.curve, u, pusher_mu, &own);
      tau = pick_magnitude(own, apex);
    }
    const double t = tau.value_or(apex);
    const Contact c = contact_at(scene, iv.curve, u, "interval");
    // The impulse τ (d, r ⊗ d) delivered as the constant force p / h.
    const Wrench w{t * c.nx / h, t * c.ny / h, t * c.r_cross_n / h};
    std::ostringstream magnitude;
    magnitude << "impulse magnitude " << t << " N·s, h = " << h << " s";
    require_finite(w, scene, "body", iv.curve, u, magnitude.str());
    return w;
  };
}

PushModel seated_push_model(const Scene& scene, double force) {
  if (!(force > 0) || !std::isfinite(force))
    throw InputError("force", std::to_string(force), "must be a finite number of newtons above 0");
  const auto q = seated_pose(scene).approx;
  const Pose pose{q[0], q[1], q[2]};
  return [&scene, pose, force](const RegionInterval& iv, const Rational& u) {
    const Wrench w =
        push_wrench_at(scene, iv.curve, u, pose, "body");  // a push the validation chose: the body overflows
    return Wrench{force * w.fx, force * w.fy, force * w.m};
  };
}

RegionValidation validate_region(const Scene& scene, const Region& region, const PushModel& model, int pushes,
                                 std::uint64_t seed, const PushOptions& options) {
  if (pushes < 1) throw InputError("validate_region(pushes)", std::to_string(pushes), "must be >= 1");
  internal::check_same_scene(region.built_from.get(), scene, internal::region_reads(region.target), "region");
  check_push_options(options);  // also when no interval is IN, so no option goes unchecked
  RegionValidation out;
  out.seed = seed;
  out.options = options;
  std::mt19937_64 rng(seed);
  long total = 0, done = 0;
  for (const auto& iv : region.intervals) total += iv.status == RegionStatus::kIn ? pushes : 0;
  for (const auto& iv : region.intervals) {
    if (iv.status != RegionStatus::kIn) {
      out.intervals.emplace_back();
      continue;
    }
    Validation v;
    for (int k = 0; k < pushes; ++k) {
      // An exact parameter: u0 + (u1 − u0) · j / 2^20, j pseudo-random.
      const Rational frac(static_cast<long>(rng() >> 44), 1L << 20);
      const Rational u = iv.u0 + (iv.u1 - iv.u0) * frac;
      poll(options.control, "validate", done, total, "pushes");
      PushResult r;
      try {
        r = push(scene, model(iv, u), options);
      } catch (const StoppedError& e) {  // say how far the validation got, not only the push
        const std::string why = e.reason() == StopReason::kInterrupted ? "interrupted" : "time limit reached";
        throw StoppedError(e.reason(),
                           "validate: " + why + " after " + std::to_string(done) + " of " + std::to_string(total) +
                               " pushes (in push " + std::to_string(done + 1) + ", " + std::to_string(e.done()) +
                               " of " + std::to_string(e.total()) + " engine steps); no result",
                           done, total);
      }
      ++done;
      ++v.pushes;
      v.seated += r.outcome == Outcome::kSeated;
      v.jammed += r.outcome == Outcome::kJammed;
      v.escaped += r.outcome == Outcome::kEscaped;
      v.timeout += r.outcome == Outcome::kTimeout;
      v.warned += r.warnings.empty() ? 0 : 1;
      v.seated_warned += r.outcome == Outcome::kSeated && !r.warnings.empty();
      if (!r.warnings.empty() && out.first_warning.empty()) out.first_warning = r.warnings.front();
    }
    out.total.pushes += v.pushes;
    out.total.seated += v.seated;
    out.total.jammed += v.jammed;
    out.total.escaped += v.escaped;
    out.total.timeout += v.timeout;
    out.total.warned += v.warned;
    out.total.seated_warned += v.seated_warned;
    out.intervals.push_back(v);
  }
  return out;
}

}  // namespace fixel::physics
