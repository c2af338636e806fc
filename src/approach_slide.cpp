// J′ for a pair of fixels on parallel edges (docs/theory.md §10.7): at each
// rotation where both touch, the part can slide along the edges, and the
// pair's cone moves by a linear map of the slide s. Every test is then a
// sign of a + b s with a, b in Q(√d): exact intervals of s.
#include <cmath>

#include "fixel/error.h"
#include "fixel/internal/approach_data.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/quadratic_field.h"

namespace fixel::internal {

namespace {

using Q3 = std::array<Q2, 3>;

// A set of slides {s}: an interval with optional ends, open or closed.
struct Slides {
  std::optional<Q2> lo, hi;
  bool lo_open = false, hi_open = false, empty = false;

  void lower(const Q2& x, bool open) {
    if (!lo || sign(x - *lo) > 0 || (sign(x - *lo) == 0 && open)) lo = x, lo_open = open;
    settle();
  }
  void upper(const Q2& x, bool open) {
    if (!hi || sign(x - *hi) < 0 || (sign(x - *hi) == 0 && open)) hi = x, hi_open = open;
    settle();
  }
  void settle() {
    if (lo && hi) {
      const int c = sign(*hi - *lo);
      empty = empty || c < 0 || (c == 0 && (lo_open || hi_open));
    }
  }
  // {s : a + b s ≥ 0} (or > 0 when `strict`).
  void at_least(const Q2& a, const Q2& b, bool strict) {
    const int sb = sign(b);
    if (sb == 0) {
      const int sa = sign(a);
      empty = empty || sa < 0 || (sa == 0 && strict);
    } else if (sb > 0) {
      lower(-a / b, strict);
    } else {
      upper(-a / b, strict);
    }
  }
  // {s : a + b s = 0}.
  void zero(const Q2& a, const Q2& b) {
    at_least(a, b, false);
    at_least(-a, -b, false);
  }
  // A point of the set (display): the middle, or an end.
  double some() const {
    if (lo && hi) return (CGAL::to_double(*lo) + CGAL::to_double(*hi)) / 2;
    if (lo) return CGAL::to_double(*lo);
    if (hi) return CGAL::to_double(*hi);
    return 0;
  }
};

Q2 det3(const Q3& a, const Q3& b, const Q3& c) { return dot(a, cross(b, c)); }

Q3 lift3(const std::array<QuadraticIrrational, 3>& v) {
  return {from_public(v[0]), from_public(v[1]), from_public(v[2])};
}

Q2 eval(const Polynomial& p, const Q2& x) {
  Q2 v(0);
  for (std::size_t k = p.size(); k-- > 0;) v = v * x + Q2(p[k]);
  return v;
}

}  // namespace

bool slide_families(const Scene& scene, const std::vector<PolylineEdge>& edges, const std::vector<Vec2>& f_A,
                    const std::vector<Rational>& mu, int i, int j, const Polynomial& p, const Polynomial& beta_i,
                    const SeatedPose& seat, const QuadraticIrrational& t_star_public, std::vector<SlideFamily>& out) {
  if (p.empty()) return false;
  const Q2 t_star = from_public(t_star_public);
  if (sign(eval(p, t_star)) != 0) throw InternalError("approach: a parallel pair does not touch at the seat");
  // The rotations where both touch: t* and, for a quadratic p, the other
  // root −p₁/p₂ − t* (Vieta), when it lies between 0 and t*.
  std::vector<Q2> ts{t_star};
  if (p.size() == 3) {
    const Q2 other = Q2(-p[1] / p[2]) - t_star;
    const bool between = sign(other) * sign(t_star) >= 0 && sign(other - t_star) * sign(t_star) < 0;
    if (between && sign(other - t_star) != 0) ts.push_back(other);
  }
  const Vec2& c = scene.body.p_AoCm_A;
  const Vec2& ni = edges[i].inward;
  const Vec2 e{-ni.y, ni.x};
  for (const Q2& t : ts) {
    const bool at_seat = sign(t - t_star) == 0;
    const Q2 scale = Q2(1) + t * t;
    const Q2 C = (Q2(1) - t * t) / scale, S = Q2(2) * t / scale;
    // Lever arms at s = 0: q* itself at the seat; elsewhere the pose whose
    // translation is along n_i.
    std::array<std::array<Q2, 2>, 2> rho;
    for (int side = 0; side < 2; ++side) {
      const int k = side == 0 ? i : j;
      if (at_seat) {
        rho[side] = {from_public(seat.p_BoG_B[k][0]) - Q2(c.x), from_public(seat.p_BoG_B[k][1]) - Q2(c.y)};
      } else {
        const Vec2 v{f_A[k].x - c.x, f_A[k].y - c.y};
        const Q2 along_n = eval(beta_i, t) / scale / Q2(ni.x * ni.x + ni.y * ni.y);
        rho[side] = {C * Q2(v.x) + S * Q2(v.y) + along_n * Q2(ni.x), -S * Q2(v.x) + C * Q2(v.y) + along_n * Q2(ni.y)};
      }
    }
    SlideFamily fam;
    fam.fixels = {i, j};
    fam.cos = to_public(C);
    fam.sin = to_public(S);
    fam.at_seat = at_seat;
    fam.theta = 2 * std::atan(CGAL::to_double(t));
    fam.e = e;
    Slides range;
    for (int side = 0; side < 2; ++side) {
      const int k = side == 0 ? i : j;
      const PolylineEdge& edge = edges[k];
      const Vec2 d{edge.b.x - edge.a.x, edge.b.y - edge.a.y};
      // (ρ + c + s e − a)·d ∈ [0, |d|²].
      const Q2 a0 = (rho[side][0] + Q2(c.x - edge.a.x)) * Q2(d.x) + (rho[side][1] + Q2(c.y - edge.a.y)) * Q2(d.y);
      const Q2 a1(e.x * d.x + e.y * d.y);
      range.at_least(a0, a1, false);
      range.at_least(Q2(d.x * d.x + d.y * d.y) - a0, -a1, false);
      const Vec2& n = edge.inward;
      const Vec2 tg{-n.y, n.x};
      for (int s : {1, -1}) {
        if (s == -1 && mu[k] == 0) break;
        const Vec2 b{n.x + s * mu[k] * tg.x, n.y + s * mu[k] * tg.y};
        fam.gens.push_back(
            {to_public(Q2(b.x)), to_public(Q2(b.y)), to_public(rho[side][0] * Q2(b.y) - rho[side][1] * Q2(b.x))});
      }
    }
    if (range.empty || !range.lo || !range.hi) {
      // At θ* the seat's contacts lie inside their edges; at the other
      // rotation no slide may keep both on their edges: no such pose.
      if (at_seat) throw InternalError("approach: the seat's slide family is off its edges");
      continue;
    }
    fam.s_lo = to_public(*range.lo);
    fam.s_hi = to_public(*range.hi);
    out.push_back(std::move(fam));
  }
  return true;
}

std::optional<double> slide_hold(const SlideFamily& fam, const VectorQ& v_W) {
  return slide_hold(fam, v_W, VectorQ::Zero(3), Rational(0));
}

std::optional<double> slide_hold(const SlideFamily& fam, const VectorQ& v0, const VectorQ& v1, const Rational& d) {
  Q3 v_W;
  for (int k = 0; k < 3; ++k) v_W[k] = d == 0 || v1[k] == 0 ? Q2(v0[k]) : Q2(v0[k], v1[k], d);
  const Q2 C = from_public(fam.cos), S = from_public(fam.sin);
  // v in frame B at θ_r; the cone at slide s is M(s) cone(G(0)) with
  // M(s)(f, m) = (f, m + s e × f), so v ∈ cone(G(s)) ⇔ v + s h ∈ cone(G(0)),
  // h = (0, 0, −e × v_f).
  const Q3 v{C * v_W[0] + S * v_W[1], -S * v_W[0] + C * v_W[1], v_W[2]};
  const Q3 h{Q2(0), Q2(0), -(Q2(fam.e.x) * v[1] - Q2(fam.e.y) * v[0])};
  std::vector<Q3> G;
  for (const auto& g : fam.gens) G.push_back(lift3(g));
  auto within = [&]() {
    Slides s;
    s.lower(from_public(fam.s_lo), false);
    s.upper(from_public(fam.s_hi), false);
    return s;
  };
  const std::size_t m = G.size();
  // Carathéodory: v + s h lies in the cone of a linearly independent subset.
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b)
      for (std::size_t c = b + 1; c < m; ++c) {
        const int sd = sign(det3(G[a], G[b], G[c]));
        if (sd == 0) continue;
        Slides s = within();
        const Q2 k(sd);
        s.at_least(k * det3(v, G[b], G[c]), k * det3(h, G[b], G[c]), false);
        s.at_least(k * det3(G[a], v, G[c]), k * det3(G[a], h, G[c]), false);
        s.at_least(k * det3(G[a], G[b], v), k * det3(G[a], G[b], h), false);
        if (!s.empty) return s.some();
      }
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b) {
      const Q3 X = cross(G[a], G[b]);
      if (is_zero(X)) continue;
      Slides s = within();
      s.zero(dot(v, X), dot(h, X));
      s.at_least(dot(cross(v, G[b]), X), dot(cross(h, G[b]), X), false);
      s.at_least(dot(cross(G[a], v), X), dot(cross(G[a], h), X), false);
      if (!s.empty) return s.some();
    }
  for (std::size_t a = 0; a < m; ++a) {
    Slides s = within();
    const Q3 cv = cross(v, G[a]), ch = cross(h, G[a]);
    for (int k = 0; k < 3; ++k) s.zero(cv[k], ch[k]);
    s.at_least(dot(v, G[a]), dot(h, G[a]), true);
    if (!s.empty) return s.some();
  }
  return std::nullopt;
}

}  // namespace fixel::internal
