#include "fixel/stepper.h"

#include <utility>

#include "fixel/error.h"
#include "fixel/lcp.h"
#include "fixel/progress.h"

namespace fixel {

Simulation simulate(const Scene& scene, const std::vector<VectorQ>& impulses, int steps, RunControl* control) {
  const internal::ControlScopeIfGiven scope(control);  // its exact steps poll it too
  check_scene_values(scene);                           // the scene before the impulses measured against it
  const int dof = scene.body.dof, nc = scene.num_contacts();
  if (steps <= 0) throw InputError("simulate(steps)", std::to_string(steps), "must be >= 1");
  for (std::size_t k = 0; k < impulses.size(); ++k)
    if (impulses[k].size() != dof)
      throw InputError("impulse[" + std::to_string(k) + "]", std::to_string(impulses[k].size()) + " components",
                       "but the scene has dof " + std::to_string(dof));

  Scene state = scene;  // carries ν^ℓ and ψ^ℓ from step to step
  VectorQ q = VectorQ::Zero(dof);
  Simulation sim;
  LemkeResult solved;  // reused from step to step
  // B, P and W depend on the contacts' geometry, the masses and μ, which no
  // step changes: built and prepared once; each step sets a (ν, ψ).
  TimeSteppingLcp lcp = build_lcp(state);
  const LemkeMatrix B(std::move(lcp.B));  // lcp.b() needs only P and a
  for (int k = 0; k < steps; ++k) {
    poll(control, "simulate", k, steps, "steps");
    const VectorQ p = k < static_cast<int>(impulses.size()) ? impulses[k] : VectorQ(VectorQ::Zero(dof));
    if (k > 0) set_lcp_state(lcp, state);
    solve_lcp_lemke(B, lcp.b(p), solved);
    if (solved.status != LemkeStatus::kSolved)
      throw UnsupportedError("step " + std::to_string(k + 1), "Lemke ended in " + to_string(solved.status),
                             "and no motion was computed; fixel does not handle this contact situation");
    StepRecord rec;
    rec.p_n = solved.z.head(nc);
    rec.p_f = solved.z.segment(nc, 2 * nc);
    const VectorQ impulse = lcp.W.Wn * rec.p_n + lcp.W.Wf * rec.p_f + p;
    rec.velocity = state.body.velocity;
    for (int j = 0; j < dof; ++j) rec.velocity[j] += impulse[j] / lcp.W.M(j, j);
    q += scene.time_step * rec.velocity;  // eq. (11)
    rec.q = q;
    rec.gaps = VectorQ(nc);
    for (int i = 0; i < nc; ++i) {
      rec.gaps[i] = state.fixels[i].gap + scene.time_step * lcp.W.Wn.col(i).dot(rec.velocity);  // eq. (12)
      state.fixels[i].gap = rec.gaps[i];
    }
    rec.pivots = solved.pivots;
    state.body.velocity = rec.velocity;
    sim.steps.push_back(rec);
  }
  sim.seated = (sim.steps.back().gaps.array() == Rational(0)).all();
  return sim;
}

}  // namespace fixel
