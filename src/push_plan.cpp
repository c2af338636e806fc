#include "fixel/push_plan.h"

#include <cmath>
#include <limits>

#include "fixel/error.h"
#include "fixel/geometry.h"
#include "fixel/guaranteed.h"
#include "fixel/on_boundary.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"

namespace fixel {

double relative_width(const Magnitudes& m) {
  if (m.empty) return std::numeric_limits<double>::quiet_NaN();
  if (!m.hi) return std::numeric_limits<double>::infinity();
  if (m.lo == 0) return std::numeric_limits<double>::infinity();
  return to_double((*m.hi - m.lo) / m.lo);
}

PushPlan plan_push(const Scene& scene, int curve, const Rational& u, bool with_guaranteed, RunControl* control) {
  const internal::ControlScopeIfGiven scope(control);  // its exact steps poll it too
  const internal::ExactTask task("push-plan");
  if (!scene.body.boundary) throw SceneError("body.boundary", "", "is missing: a push plan needs the part's outline");
  const Boundary& b = *scene.body.boundary;
  if (curve < 0 || curve >= static_cast<int>(b.curves.size()))
    throw InputError("plan_push(curve)", std::to_string(curve), "is not a curve of the boundary");
  const Curve& c = b.curves[curve];
  if (u < c.u_begin() || u > c.u_end())
    throw InputError(
        "plan_push(u)", to_string(u),
        "is outside the curve's parameter range [" + to_string(c.u_begin()) + ", " + to_string(c.u_end()) + "]");
  PushPlan plan;
  plan.curve = curve;
  plan.u = u;
  plan.point_A = c.point(u);
  const Vec2 t = c.derivative(u);
  plan.normal_A = {-t.y, t.x};  // inward: the loop is counter-clockwise
  plan.corner = fit_to_boundary(b, plan.point_A).corner;
  const Vec2 r = sub(plan.point_A, scene.body.p_AoCm_A);
  const VectorQ g = contact_wrench(r, plan.normal_A, scene.body.dof);
  plan.wrench_direction = g;

  const SeatingSet S = seating_set(scene);
  plan.in_S = point_status(scene, S, curve, u, Rational(0), &plan.magnitudes_S);
  std::optional<GuaranteedSet> G;
  if (with_guaranteed) {
    G = guaranteed_set(scene, S, control);
    plan.in_G = point_status(scene, S, curve, u, Rational(0), &plan.magnitudes_G, &*G);
  }
  // A representative impulse: exact τ window of the ray b0 + τ g in S. Only
  // for an IN point: at an OUT corner g's own ray (one edge's normal) can
  // still hit S while another ray of the fan misses.
  const Magnitudes tau = ray_magnitudes(S, scene.background_impulse, g);
  if (plan.in_S == RegionStatus::kIn && !tau.empty && !(t.x == 0 && t.y == 0)) {
    const Rational tau_star = tau.hi ? (tau.lo + *tau.hi) / 2 : (tau.lo > 0 ? 2 * tau.lo : Rational(1));
    const VectorQ p = scene.background_impulse + tau_star * g;
    plan.sample_impulse = p;
    plan.sample_outcomes = count_outcomes(enumerate_outcomes(scene, p, control));
    if (G) plan.sample_in_G = G->contains(p, S);
  }
  if (scene.body.dof == 3) {
    try {
      const SustainedSet J = sustained_set(scene);
      auto target = sustained_target(J);
      plan.in_J = point_status(scene, *target, curve, u, Rational(0));
      plan.approach = approach_set(scene, J);
      try {
        if (plan.corner) {  // a fan: J' is not convex, so its rays do not decide it
          const auto approach = approach_target(*plan.approach);
          // As for J and S at a point: IN when the whole fan is in J', else
          // OUT. The region's PARTIAL (its stand-ins leave the fan
          // undecided) is no claim that some push is in J'.
          const RegionStatus fan = point_status(scene, *approach, curve, u, Rational(0));
          plan.in_J_approach = fan == RegionStatus::kIn ? RegionStatus::kIn : RegionStatus::kOut;
        } else {
          ApproachVerdict v;
          ApproachHold hold;
          hold.fixels = {-1, -1};
          v.why_not = plan.approach->why_not_part_frame(g, &hold);
          v.contains = v.why_not.empty();
          if (hold.fixels[0] >= 0) v.hold = hold;
          plan.in_J_approach = *v.contains ? RegionStatus::kIn : RegionStatus::kOut;
          plan.J_approach_verdict = v;
        }
      } catch (const UnsupportedError& e) {  // J' not decided (curved contacts)
        plan.J_approach_note = e.what();
      }
    } catch (const InputError& e) {
      plan.J_note = e.what();
    }
  }
  return plan;
}

}  // namespace fixel
