// Strong stability at the seat, checked by the contact-mode enumeration of
// the step LCP at the seated pose (docs/theory.md §10.3).
#include "fixel/outcomes.h"
#include "fixel/sustained.h"

namespace fixel {

namespace {

bool rational(const QuadraticIrrational& x) { return x.b == 0; }

}  // namespace

int check_strong_stability(const Scene& scene, SustainedSet& J) {
  if (J.empty || !J.pieces_decided || !J.pose.exact || J.pose.p_BoG_B.size() != J.mu.size()) return 0;
  for (const auto& v : *J.pose.exact)
    if (!rational(v)) return 0;
  for (const auto& g : J.pose.p_BoG_B)
    if (!rational(g[0]) || !rational(g[1])) return 0;
  // The scene at its seat, at rest, every gap closed. A step of length h
  // under the impulse h·w from rest is the acceleration-level LCP scaled by
  // h, so "every outcome has zero velocity" is strong stability under w.
  // Normals need not be unit here: scaling n and t alike scales W_n and W_t
  // columns and leaves every velocity unchanged.
  Scene seat = scene;
  seat.body.velocity = VectorQ::Zero(3);
  for (std::size_t i = 0; i < seat.fixels.size(); ++i) {
    Fixel& f = seat.fixels[i];
    f.p_AoF_A = {J.pose.p_BoG_B[i][0].a, J.pose.p_BoG_B[i][1].a};
    f.n_A = J.pose.n_B[i];
    f.gap = 0;
    f.mu = J.mu[i];
    f.mu_hi.reset();
  }
  const Rational c = (*J.pose.exact)[2].a, s = (*J.pose.exact)[3].a;
  int checked = 0;
  for (const auto& piece : J.pieces) {
    VectorQ w = VectorQ::Zero(3);  // inside the piece: the sum of its closure's rays (world frame)
    for (const auto& r : piece.rays)
      for (int k = 0; k < 3; ++k) w[k] += r[k].a;
    VectorQ p(3);  // h·w in the body frame at the seat
    p << seat.time_step * (c * w[0] + s * w[1]), seat.time_step * (-s * w[0] + c * w[1]), seat.time_step * w[2];
    for (const auto& outcome : enumerate_outcomes(seat, p))
      if (!outcome.velocity.isZero() || !outcome.seated) {
        J.strongly_stable = false;
        return ++checked;
      }
    ++checked;
  }
  return checked;
}

}  // namespace fixel
