// Push-plan reports: `fixel push-plan` text and JSON.
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fixel/internal/approach_json.h"
#include "fixel/internal/json_approx.h"
#include "fixel/internal/json_exact.h"
#include "fixel/internal/readable.h"
#include "fixel/io.h"
#include "fixel/on_boundary.h"

namespace fixel {

namespace {

using json = nlohmann::ordered_json;

using internal::exact_json;

json window_json(const Magnitudes& m) {
  if (m.empty) return nullptr;
  const double w = relative_width(m);
  return {{"min", to_string(m.lo)},
          {"min_inclusive", m.lo_closed},
          {"max", m.hi ? json(to_string(*m.hi)) : json(nullptr)},
          {"max_inclusive", m.hi.has_value() && m.hi_closed},
          {"relative_width", std::isfinite(w) ? json(w) : json(nullptr)}};
}

std::string width_text(const Magnitudes& m) {
  if (m.empty) return "";
  if (!m.hi) return " (unbounded above: any harder push also lands)";
  if (m.lo == 0) return " (from 0: a relative width (max - min) / min is not defined)";
  return " (relative width " + internal::decimal(100 * relative_width(m), 3) + "%: (max - min) / min)";
}

}  // namespace

std::string push_plan_json(const Scene& scene, const PushPlan& plan) {
  json doc;
  doc["scene"] = scene.name;
  doc["curve"] = plan.curve;
  doc["u"] = to_string(plan.u);
  doc["point"] = {to_string(plan.point_A.x), to_string(plan.point_A.y)};
  doc["normal"] = {to_string(plan.normal_A.x), to_string(plan.normal_A.y)};
  doc["corner"] = plan.corner;
  doc["wrench_direction"] = exact_json(plan.wrench_direction);
  // The plan is for a frictionless finger along the normal whatever the
  // scene's pusher μ (which region and sample use): both are stated.
  doc["pusher_mu"] = "0";
  doc["scene_pusher_mu"] = to_string(scene.pusher_mu_upper());
  json one = {{"meaning", "one-step: can seat"},
              {"status", to_string(plan.in_S)},
              {"magnitudes", window_json(plan.magnitudes_S)}};
  if (plan.sample_impulse) {
    one["sample_push"] = exact_json(VectorQ(*plan.sample_impulse - scene.background_impulse));
    one["sample_impulse"] = exact_json(*plan.sample_impulse);
    one["sample_outcomes"] = {{"total", plan.sample_outcomes.total}, {"seating", plan.sample_outcomes.seating}};
    if (plan.sample_in_G) one["sample_in_G"] = *plan.sample_in_G;
  }
  doc["one_step"] = one;
  doc["guaranteed"] = plan.in_G ? json{{"meaning", "one-step: guaranteed"},
                                       {"status", to_string(*plan.in_G)},
                                       {"magnitudes", window_json(plan.magnitudes_G)}}
                                : json(nullptr);
  doc["sustained"] = plan.in_J ? json{{"meaning", "sustained push: seats and stays"}, {"status", to_string(*plan.in_J)}}
                               : json{{"note", plan.J_note}};
  if (plan.approach) {
    json a = {
        {"meaning",
         "sustained push: seats and stays, no pair holding the part on the way"}};  // region --approach's meaning.in
    if (plan.in_J_approach)
      a["status"] = to_string(*plan.in_J_approach);
    else
      a["note"] = plan.J_approach_note;
    a.update(internal::approach_json(*plan.approach, plan.J_approach_verdict));
    doc["sustained"]["approach"] = a;
  }
  internal::add_approx(doc);
  return doc.dump(2) + "\n";
}

namespace {

// The direction of a normal of any length, as a unit vector: exact when its
// length is rational, else decimals marked ≈ (display).
std::string unit_text(const Vec2& n) {
  if (const auto unit = exact_unit(n))
    return "(" + internal::readable(unit->x) + ", " + internal::readable(unit->y) + ")";
  const double x = to_double(n.x), y = to_double(n.y), approx_length = std::hypot(x, y);
  std::ostringstream out;
  out << std::setprecision(6) << "(≈ " << x / approx_length << ", ≈ " << y / approx_length << ")";
  return out.str();
}

}  // namespace

std::string push_plan_text(const Scene& scene, const PushPlan& plan) {
  std::ostringstream out;
  out << "Push plan for scene \"" << scene.name << "\" at curve " << plan.curve
      << ", u = " << internal::readable(plan.u) << "\n";
  out << "  point (m, frame A) = (" << internal::readable(plan.point_A.x) << ", " << internal::readable(plan.point_A.y)
      << "), push along " << (plan.corner ? "the next edge's inward normal " : "the inward normal ")
      << unit_text(plan.normal_A)
      << (plan.corner ? "; a corner: the pushes fan out between its two edges' normals, and each status below is "
                        "for the whole fan"
                      : "")
      << "\n";
  if (scene.pusher_mu_upper() != 0)
    out << "  pusher: a frictionless finger pushing along the normal; the scene's pusher mu = "
        << internal::readable(scene.pusher_mu_upper())
        << (scene.pusher_mu_hi ? " (the upper end of its interval [" + internal::readable(scene.pusher_mu) + ", " +
                                     internal::readable(*scene.pusher_mu_hi) + "], at which every analysis judges it)"
                               : std::string())
        << " is not used here (`region` and `sample` use it: their pushes fan out over its friction cone, so they "
           "can say out where this plan, for the normal push alone, says in)\n";
  out << "  wrench direction g = " << internal::readable(plan.wrench_direction)
      << " (force, moment about the centre of mass, frame A: N*s and N*m*s for the one-step impulse, N and N*m for "
         "a held push; a direction: its length comes from the curve's parametrization, and |p| below is the size of "
         "the force part)\n";
  out << "  one-step: can seat: " << to_string(plan.in_S);
  if (plan.in_S == RegionStatus::kIn)
    out << ", |p| in " << plan.magnitudes_S.describe_readable() << " N*s" << width_text(plan.magnitudes_S);
  else if (plan.corner && plan.in_S == RegionStatus::kOut)
    out << " (a corner: not every push of its fan lands in S)";
  out << "\n";
  if (plan.sample_impulse) {
    const OutcomeCount& c = plan.sample_outcomes;
    const VectorQ push = *plan.sample_impulse - scene.background_impulse;
    out << "    at p = " << internal::readable(push) << " N*s (|p| inside the window)";
    if (!scene.background_impulse.isZero())
      out << ", with the scene's b0 the impulse b0 + p = " << internal::readable(*plan.sample_impulse) << " N*s";
    out << ": " << c.total << " one-step outcome(s), " << c.seating << " seat"
        << (c.total > 1 ? " (see `fixel solutions`)" : "");
    if (plan.sample_in_G) out << "; " << (*plan.sample_in_G ? "in G" : "not in G");
    out << "\n";
  }
  if (plan.in_G) {
    out << "  one-step: guaranteed: " << to_string(*plan.in_G);
    if (*plan.in_G == RegionStatus::kIn && !plan.magnitudes_G.empty)
      out << ", |p| in " << plan.magnitudes_G.describe_readable() << " N*s" << width_text(plan.magnitudes_G);
    else if (*plan.in_G == RegionStatus::kIn)
      out << " for some magnitudes (no single certified window; test one with `seat --guaranteed --impulse`)";
    else if (plan.corner && *plan.in_G == RegionStatus::kPartial)
      out << " (a corner: some pushes of its fan land in G, perhaps not all; G is not convex, so its fan is not "
             "judged IN or OUT as S's is)";
    else if (plan.corner && *plan.in_G == RegionStatus::kOut)
      out << " (a corner: no push of its fan lands in G)";
    out << "\n";
  }
  if (plan.in_J)
    out << "  sustained push: seats and stays: " << to_string(*plan.in_J) << " (any magnitude: J is a cone"
        << (plan.corner && *plan.in_J == RegionStatus::kOut ? "; a corner: not every push of its fan is in J" : "")
        << ")\n";
  else if (!plan.J_note.empty())
    out << "  sustained push: not judged: " << plan.J_note << "\n";
  if (plan.in_J_approach) {
    out << "  sustained push, approach-aware J': " << to_string(*plan.in_J_approach);
    if (*plan.in_J_approach == RegionStatus::kIn)
      out << " (no pair of fixels can hold the part on its way to the seat; any magnitude)";
    else if (plan.J_approach_verdict)
      out << ": " << plan.J_approach_verdict->why_not;
    else
      out << " (a corner: not every push of its fan is in J'; push at a smooth point for a verdict with its "
             "reason)";
    out << "\n";
  } else if (plan.approach) {
    out << "  sustained push, approach-aware J': not judged: " << plan.J_approach_note << "\n";
  }
  if (plan.approach) out << "  " << seat_rotation_note(plan.approach->J.pose);
  return out.str();
}

}  // namespace fixel
