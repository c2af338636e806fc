#include "fixel/seat_report.h"

#include <algorithm>

#include "fixel/error.h"
#include "fixel/internal/seating_sets_check.h"

namespace fixel {

SeatReport seat_report(const Scene& scene, const SeatingSet& S, const std::optional<VectorQ>& impulse,
                       const GuaranteedSet* G, bool stable) {
  internal::check_seating_sets_of(scene, S, G);
  SeatReport r;
  if (G) r.lost_fraction = lost_fraction(S, *G);
  r.stable = stable;
  if (stable) {
    r.stability_cone = stability_cone(scene);
    r.seat_and_stay = seat_and_stay(scene, S);
  }
  if (!impulse) return r;
  ImpulseVerdict v;
  v.impulse = *impulse;
  v.in_S = S.contains(*impulse);
  if (std::find(S.sliding.begin(), S.sliding.end(), 0) == S.sliding.end()) {  // eq. 27 needs sliding
    const SeatingSystem sys = seating_system(scene, S);
    v.y = sys.y(*impulse);
    v.y_names = sys.y_names;
  }
  if (G) v.guaranteed = G->contains(*impulse, S);
  if (stable) v.seat_and_stay = r.seat_and_stay.contains(*impulse);
  v.outcomes = count_outcomes(enumerate_outcomes(scene, *impulse));
  r.impulse = v;
  return r;
}

WrenchVerdict wrench_verdict(const SustainedSet& J, const VectorQ& w_W) {
  WrenchVerdict v;
  v.wrench = w_W;
  try {
    v.why_not = J.why_not(w_W);
    v.contains = v.why_not.empty();
  } catch (const UnsupportedError& e) {
    v.why_not = e.what();
  }
  return v;
}

ApproachVerdict approach_verdict(const ApproachSet& A, const VectorQ& w_W) {
  ApproachVerdict v;
  try {
    ApproachHold hold;
    hold.fixels = {-1, -1};
    v.why_not = A.why_not(w_W, &hold);
    v.contains = v.why_not.empty();
    if (hold.fixels[0] >= 0) v.hold = hold;
  } catch (const UnsupportedError& e) {
    v.why_not = e.what();
  }
  return v;
}

}  // namespace fixel
