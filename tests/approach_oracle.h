#pragma once
// The second method for J′'s holds (tests only): the pose of a pair's
// two-contact family at a rational t = tan(θ/2), solved directly by Cramer's
// rule on the two contact conditions, its world-frame friction-cone
// generators, and v ∈ FC_i + FC_j by an exact LP (CGAL's solver). Shares no
// code with src/approach.cpp.
#include <array>
#include <vector>

#include "fixel/internal/exact_lp.h"
#include "fixel/internal/polyline_edge.h"
#include "fixel/scene.h"
#include "test_util.h"

namespace fixel::test {

struct DirectPose {
  std::vector<VectorQ> gens;
  std::array<Rational, 2> along;  // contact position along each edge, 0 at a, 1 at b
};

inline DirectPose direct_pose(const Scene& scene, const std::vector<Rational>& mu, int i, int j, const Rational& t) {
  const Rational C = (1 - t * t) / (1 + t * t), S = 2 * t / (1 + t * t);
  const Vec2& c = scene.body.p_AoCm_A;
  std::array<internal::PolylineEdge, 2> e;
  std::array<Vec2, 2> f;
  for (int s = 0; s < 2; ++s) {
    const Fixel& fx = scene.fixels[s == 0 ? i : j];
    e[s] = *internal::polyline_edge_through(*scene.body.boundary, fx.p_AoF_A, fx.n_A);
    f[s] = {fx.p_AoF_A.x - fx.gap * fx.n_A.x, fx.p_AoF_A.y - fx.gap * fx.n_A.y};
  }
  // Body frame: g = Rᵀ(f − c) + τ + c on the line n·(g − a) = 0.
  std::array<Vec2, 2> RTv;
  std::array<Rational, 2> rhs;
  for (int s = 0; s < 2; ++s) {
    const Vec2 v{f[s].x - c.x, f[s].y - c.y};
    RTv[s] = {C * v.x + S * v.y, -S * v.x + C * v.y};
    const Vec2& n = e[s].inward;
    rhs[s] = n.x * (e[s].a.x - c.x - RTv[s].x) + n.y * (e[s].a.y - c.y - RTv[s].y);
  }
  const Vec2 &n0 = e[0].inward, &n1 = e[1].inward;
  const Rational det = n0.x * n1.y - n0.y * n1.x;
  const Vec2 tau{(rhs[0] * n1.y - rhs[1] * n0.y) / det, (n0.x * rhs[1] - n1.x * rhs[0]) / det};
  DirectPose out;
  for (int s = 0; s < 2; ++s) {
    const Vec2 rho{RTv[s].x + tau.x, RTv[s].y + tau.y};
    const Vec2 d{e[s].b.x - e[s].a.x, e[s].b.y - e[s].a.y};
    out.along[s] = ((rho.x + c.x - e[s].a.x) * d.x + (rho.y + c.y - e[s].a.y) * d.y) / (d.x * d.x + d.y * d.y);
    const Vec2& n = e[s].inward;
    const Rational m = mu[s == 0 ? i : j];
    for (int sign : {1, -1}) {
      const Vec2 b{n.x - sign * m * n.y, n.y + sign * m * n.x};
      out.gens.push_back(test::vec({C * b.x - S * b.y, S * b.x + C * b.y, rho.x * b.y - rho.y * b.x}));
    }
  }
  return out;
}

inline bool in_cone_lp(const std::vector<VectorQ>& gens, const VectorQ& v) {
  const int n = static_cast<int>(gens.size());
  std::vector<internal::LinearConstraint> rows;
  for (int k = 0; k < 3; ++k) {
    VectorQ a(n);
    for (int g = 0; g < n; ++g) a[g] = gens[g][k];
    rows.push_back({a, internal::Relation::kEqual, v[k]});
  }
  for (int g = 0; g < n; ++g) {
    VectorQ a = VectorQ::Zero(n);
    a[g] = 1;
    rows.push_back({a, internal::Relation::kGreaterEqual, Rational(0)});
  }
  return internal::solve_lp(n, rows).status == internal::LpStatus::kOptimal;
}

}  // namespace fixel::test
