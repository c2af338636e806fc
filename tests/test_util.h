#pragma once
// Helpers shared by the tests (namespace fixel::test, so that GoogleTest's
// ::testing stays visible): exact literals, bundled scenes, and seeded
// random scenes with exact unit normals.

#include <functional>
#include <random>
#include <string>

#include "fixel/error.h"
#include "fixel/progress.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"

namespace fixel::test {

// How many repetitions a long randomized test makes: all n normally, a
// quarter in the sanitizer tree (scripts/sanitize.sh defines
// FIXEL_SANITIZED_BUILD), where the same code runs 5–8× slower and the run
// is there for memory errors and undefined behaviour; the Release suite
// keeps the full count.
inline int sanitizer_scaled(int n) {
#ifdef FIXEL_SANITIZED_BUILD
  return n / 4 > 0 ? n / 4 : 1;
#else
  return n;
#endif
}

// The message of the StoppedError `call` throws ("(no stop)" if none).
inline std::string stop_message(const std::function<void()>& call) {
  try {
    call();
  } catch (const StoppedError& e) {
    return e.what();
  }
  return "(no stop)";
}

// "field: message" of the InputError `call` throws ("(no InputError)" if none).
inline std::string input_error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.field() + ": " + e.what();
  }
  return "(no InputError)";
}

// A control cancelled before the run: it stops at its first check.
struct CancelledControl {
  RunControl control;
  CancelledControl() { control.cancel = true; }
};

// An exact vector or matrix from literals.
inline VectorQ vec(std::initializer_list<Rational> xs) {
  VectorQ v(static_cast<int>(xs.size()));
  int k = 0;
  for (const auto& x : xs) v[k++] = x;
  return v;
}
inline MatrixQ mat(std::initializer_list<std::initializer_list<int>> rows) {
  MatrixQ m(static_cast<int>(rows.size()), static_cast<int>(rows.begin()->size()));
  int r = 0;
  for (const auto& row : rows) {
    int c = 0;
    for (int v : row) m(r, c++) = v;
    ++r;
  }
  return m;
}
inline VectorQ v2(Rational a, Rational b) { return vec({a, b}); }
inline VectorQ v3(Rational a, Rational b, Rational c) { return vec({a, b, c}); }

// A bundled scene from data/scenes/ by name.
inline Scene scene_file(const std::string& name) {
  return load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/" + name + ".json");
}

// The polygon with every gap 0, and two scenes that differ from it: a
// heavier part (its S is the polygon's, since S's apex stays 0, but G's
// one-step model differs) and a gap at fixel 0 (S's apex moves). For the
// tests that a set of another scene is refused, naming the set.
struct SetCheckScenes {
  Scene scene, heavier, gapped;
};
inline SetCheckScenes set_check_scenes() {
  SetCheckScenes s;
  s.scene = scene_file("polygon");
  for (auto& f : s.scene.fixels) f.gap = 0;
  s.heavier = s.scene;
  s.heavier.body.mass *= 2;
  s.heavier.body.mass_from_area = false;
  s.gapped = s.scene;
  s.gapped.fixels[0].gap = Rational(1, 10);
  return s;
}

// Lemke's tableau data [A | b] = [I, −B, −e | b] of LCP(B, b) in rationals,
// columns numbered as the filtered run's variables (w 0..n−1, z n..2n−1,
// z0 2n, b 2n+1).
inline MatrixQ lemke_tableau_data(const MatrixQ& B, const VectorQ& b) {
  const int n = static_cast<int>(b.size());
  MatrixQ A = MatrixQ::Zero(n, 2 * n + 2);
  for (int i = 0; i < n; ++i) {
    A(i, i) = 1;
    for (int j = 0; j < n; ++j) A(i, n + j) = -B(i, j);
    A(i, 2 * n) = -1;
    A(i, 2 * n + 1) = b[i];
  }
  return A;
}

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

}  // namespace fixel::test

#include <cmath>
#include <memory>

#include "fixel/curve.h"

namespace fixel::test {

// A random closed uniform cubic B-spline blob around the origin (radii in
// [1, 2], counter-clockwise), with three fixels in the pattern of the
// paper's Example 2 (one pushing +x on the left, two pushing +y below),
// their normals slightly rotated by random rational rotations.
inline Scene random_blob_scene(std::mt19937_64& rng, const Rational& pusher_mu = 0) {
  const int n = 8 + static_cast<int>(rng() % 5);
  std::vector<Vec2> ctrl;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * M_PI * k / n;
    const Rational r = Rational(1) + random_rational(rng, 0, 1, 16);
    ctrl.push_back({r * Rational(static_cast<long long>(std::lround(std::cos(angle) * 1000)), 1000),
                    r * Rational(static_cast<long long>(std::lround(std::sin(angle) * 1000)), 1000)});
  }
  for (int k = 0; k < 3; ++k) ctrl.push_back(ctrl[k]);
  Curve c;
  c.type = Curve::Type::kBSpline;
  c.degree = 3;
  c.points = ctrl;
  for (int k = 0; k < static_cast<int>(ctrl.size()) + 4; ++k) c.knots.push_back(Rational(k));
  Scene s;
  s.name = "random blob";
  s.time_step = 1;
  s.body.dof = 3;
  s.body.boundary = std::make_shared<const Boundary>(make_boundary({c}));
  s.body.mass = 1;
  s.body.p_AoCm_A = {Rational(0), Rational(0)};
  s.body.inertia = s.body.boundary->mass.polar_moment_about(s.body.p_AoCm_A) / s.body.boundary->mass.area;
  s.body.velocity = VectorQ::Zero(3);
  auto tilt = [&](Vec2 n) {  // rotate by a small rational rotation
    const Rational t = random_rational(rng, -1, 1, 20) / 4, d = 1 + t * t;
    const Rational co = (1 - t * t) / d, si = 2 * t / d;
    return Vec2{co * n.x - si * n.y, si * n.x + co * n.y};
  };
  const Rational y1 = random_rational(rng, -1, 0, 8), x2 = random_rational(rng, -1, 0, 8),
                 x3 = random_rational(rng, 0, 1, 8) + Rational(1, 4);
  s.fixels = {Fixel{{Rational(-3, 2), y1},
                    tilt({1, 0}),
                    random_rational(rng, 0, 1, 10) / 3,
                    random_rational(rng, 1, 3, 20) / 10,
                    std::nullopt},
              Fixel{{x2, Rational(-3, 2)},
                    tilt({0, 1}),
                    random_rational(rng, 0, 1, 10) / 3,
                    random_rational(rng, 1, 3, 20) / 10,
                    std::nullopt},
              Fixel{{x3, Rational(-3, 2)},
                    tilt({0, 1}),
                    random_rational(rng, 0, 1, 10) / 3,
                    random_rational(rng, 1, 3, 20) / 10,
                    std::nullopt}};
  s.pusher_mu = pusher_mu;
  s.background_impulse = VectorQ::Zero(3);
  return s;
}

}  // namespace fixel::test
