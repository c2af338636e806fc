#pragma once
// Seeded random scenes with exact unit normals, shared by the tests.

#include <random>

#include "fixel/scene.h"

namespace fixel::testing {

// A rational in [lo, hi] with denominator `den`.
inline Rational random_rational(std::mt19937_64& rng, int lo, int hi, int den) {
  std::uniform_int_distribution<int> d(lo * den, hi * den);
  return Rational(d(rng), den);
}

// An exact unit vector: the rational point ((1−t²)/(1+t²), 2t/(1+t²)) of the
// circle, with random signs and a random swap of the coordinates.
inline Vec2 random_unit(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> num(0, 40), den(1, 40), bit(0, 1);
  const Rational t(num(rng), den(rng));
  Vec2 n{(1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)};
  if (bit(rng)) n = {n.y, n.x};
  if (bit(rng)) n.x = -n.x;
  if (bit(rng)) n.y = -n.y;
  return n;
}

// A dof-3 (or dof-2) scene with dof fixels around the origin. The fixture
// may be singular; callers skip those (seating_set throws SceneError).
inline Scene random_scene(std::mt19937_64& rng, int dof = 3, int max_mu_tenths = 10) {
  Scene s;
  s.name = "random";
  s.time_step = random_rational(rng, 1, 2, 4);
  s.body.dof = dof;
  s.body.mass = random_rational(rng, 1, 3, 5);
  s.body.inertia = dof == 3 ? random_rational(rng, 1, 2, 7) : Rational(0);
  s.body.velocity = VectorQ::Zero(dof);
  for (int k = 0; k < dof; ++k) s.body.velocity[k] = random_rational(rng, -1, 1, 8) / 4;
  s.body.p_AoCm_A = {Rational(0), Rational(0)};
  for (int i = 0; i < dof; ++i) {
    Fixel f;
    f.p_AoF_A = {random_rational(rng, -1, 1, 16), random_rational(rng, -1, 1, 16)};
    f.n_A = random_unit(rng);
    f.mu = Rational(std::uniform_int_distribution<int>(0, max_mu_tenths)(rng), 10);
    f.gap = random_rational(rng, 0, 1, 20) / 4 + Rational(1, 100);
    s.fixels.push_back(f);
  }
  s.pusher_mu = 0;
  s.background_impulse = VectorQ::Zero(dof);
  return s;
}

}  // namespace fixel::testing
