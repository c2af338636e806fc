// The paper cone on enclosures (internal/paper_cone_filter.h): the exact
// construction's grid points by the same certified side tests, its moment
// bounds enclosed without deciding every candidate (docs/theory.md §8).
#include "fixel/internal/paper_cone_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fixel/internal/wrench_cone_detail.h"

namespace fixel::internal {

namespace {

using enclosed::extremes;
using enclosed::fcross;
using enclosed::fdot;
using enclosed::FGens;
using enclosed::frot90;
using enclosed::fsub;
using enclosed::FVecs;
using enclosed::Open;
using enclosed::sign_of;
using enclosed::zero_state;

// The paper cone's unit direction bound (unit_direction_outward,
// wrench_cone.cpp) of the direction enclosed by d: the same grid point,
// found by the same side tests, each certified. u encloses it; k and flip
// name it exactly.
struct GridUnit {
  long k = 0;
  bool flip = false;
  FVec2 u;
};

// u(τ) or −u(τ), τ = k/2^20 (|k| < 2^26: τ², 1 ± τ² and 2τ are exact doubles).
FVec2 grid_point(long k, bool flip) {
  const double t = std::ldexp(static_cast<double>(k), -20);
  const FI n(1 + t * t);
  const FVec2 u{FI(1 - t * t) / n, FI(2 * t) / n};
  return flip ? FVec2{-u.x, -u.y} : u;
}

GridUnit unit_outward(const FVec2& d, bool cw) {
  GridUnit g;
  g.flip = sign_of(d.x) < 0;  // the exact path's d.x < 0
  // Any start gives the same answer; this one is usually it.
  long k = unit_grid_guess((d.x.inf() + d.x.sup()) / 2, (d.y.inf() + d.y.sup()) / 2, g.flip);
  const long outward = cw ? -1 : 1;
  auto on_side = [&](long j, FVec2& u) {
    u = grid_point(j, g.flip);
    return sign_of(cw ? fcross(u, d) : fcross(d, u)) >= 0;
  };
  int steps = 0;
  for (; !on_side(k, g.u); k += outward)
    if (++steps > kUnitGridSteps) throw Open{};
  for (FVec2 inner; on_side(k - outward, inner); k -= outward) {
    g.u = inner;
    if (++steps > kUnitGridSteps) throw Open{};
  }
  g.k = k;
  return g;
}

// in_cone_filtered(d, a, b) (wrench_cone.cpp) as 1, 0 or kUndecided, given
// ab, the exact sign of a ⊗ b (0 only for a = b here).
int in_arc(const FVec2& d, const FVec2& a, const FVec2& b, int ab) {
  const int c1 = certain_sign(fcross(a, d));
  if (ab == 0) {
    if (c1 == kUndecided) return kUndecided;
    if (c1 != 0) return 0;
    const int along = certain_sign(fdot(a, d));
    return along == kUndecided ? kUndecided : along > 0;
  }
  const int c2 = certain_sign(fcross(d, b));
  if ((c1 != kUndecided && c1 < 0) || (c2 != kUndecided && c2 < 0)) return 0;
  return c1 == kUndecided || c2 == kUndecided ? kUndecided : 1;
}

// Whether control point k is a vertex of the control points' convex hull
// (what convex_hull_2 returns; a repeated point counts once, with the same
// values): 1, 0 or kUndecided. It is iff the nonzero P_j − P_k lie in an
// open half-plane, i.e. are pointed as direction_extremes decides. The
// differences are sums of legs, which keep their precision on short pieces.
int hull_vertex(const LazyPiece::Enclosures& legs, std::size_t k) {
  FVecs v;
  for (std::size_t j = 0; j <= legs.size(); ++j) {
    if (j == k) continue;
    FVec2 diff{FI(0), FI(0)};
    for (std::size_t i = std::min(j, k); i < std::max(j, k); ++i) diff = {diff.x + legs[i].x, diff.y + legs[i].y};
    if (j < k) diff = {-diff.x, -diff.y};
    const int zero = zero_state(diff);
    if (zero == kUndecided) return kUndecided;
    if (zero == 0) v.push_back(diff);
  }
  if (v.empty()) return 1;
  try {
    std::size_t s = 0, e = 0;
    return extremes(v, s, e) ? 1 : 0;
  } catch (const Open&) {
    return kUndecided;
  }
}

}  // namespace

// The paper cone of the push directions enclosed by ds and de
// (internal/paper_cone_filter.h): (û_s, X_min), (û_s, X_max), (û_e, X_min), (û_e, X_max), the
// last two left out when û_e = û_s exactly; false when û_s, û_e span π (the
// exact path splits). X_min and X_max are enclosed without deciding every
// candidate: the moments r ⊗ û over all control points have the hull's
// extremes, and a ⊥-angle bound R ∈ [|r|, |r| + 2^-20] (sqrt_upper) raises
// the lower end of the enclosure only when its point is certainly a hull
// vertex with ⊥ certainly in the arc, the upper end whenever it may be.
// A positive X_min (negative X_max) is shrunk by c ∈ [√h − 2^-20, √h],
// h = (1 + û_s·û_e)/2 (sqrt_lower); its sign must be certain.
bool enclosed::paper_cone(const FVec2& ds, const FVec2& de, const FVecs& r, const LazyPiece::Enclosures& legs,
                          FGens& gens, FVecs& forces) {
  const GridUnit us = unit_outward(ds, true), ue = unit_outward(de, false);
  const bool same = us.flip == ue.flip && us.k == ue.k;
  const int span = same ? 0 : sign_of(fcross(us.u, ue.u));
  if (span < 0 || (span == 0 && !same && sign_of(fdot(us.u, ue.u)) < 0)) return false;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double max_lo = -inf, max_hi = -inf, min_lo = inf, min_hi = inf;
  for (const FVec2& rk : r)
    for (const FVec2* u : {&us.u, &ue.u}) {
      const FI m = fcross(rk, *u);
      max_lo = std::max(max_lo, m.inf());
      max_hi = std::max(max_hi, m.sup());
      min_lo = std::min(min_lo, m.inf());
      min_hi = std::min(min_hi, m.sup());
    }
  const FI step(1.0 / 1048576);
  for (std::size_t k = 0; k < r.size(); ++k) {
    const int zero = zero_state(r[k]);
    if (zero == 1) continue;  // the exact path skips r = 0
    const FI length = CGAL::sqrt(fdot(r[k], r[k]));
    const double R_lo = length.inf(), R_hi = (length + step).sup();
    int hull = 2;  // not asked yet
    for (const bool plus : {true, false}) {
      const FVec2 perp = plus ? frot90(r[k]) : FVec2{-frot90(r[k]).x, -frot90(r[k]).y};
      const int in = in_arc(perp, us.u, ue.u, span);
      if (in == 0) continue;
      if (hull == 2) hull = hull_vertex(legs, k);
      if (hull == 0) continue;
      const bool certain = zero == 0 && in == 1 && hull == 1;
      if (plus) {
        if (certain) max_lo = std::max(max_lo, R_lo);
        max_hi = std::max(max_hi, R_hi);
      } else {
        if (certain) min_hi = std::min(min_hi, -R_lo);
        min_lo = std::min(min_lo, -R_hi);
      }
    }
  }
  FI xmin(min_lo, min_hi), xmax(max_lo, max_hi);
  if (!(min_lo > 0) && !(min_hi <= 0)) throw Open{};  // the sign of X_min decides the shrink
  if (!(max_hi < 0) && !(max_lo >= 0)) throw Open{};
  if (min_lo > 0 || max_hi < 0) {
    const FI h = (1 + fdot(us.u, ue.u)) / 2;
    const FI root = CGAL::sqrt(FI(std::max(0.0, h.inf()), std::max(0.0, h.sup())));
    const FI c(std::max(0.0, (root - step).inf()), root.sup());
    if (min_lo > 0) xmin = xmin * c;
    if (max_hi < 0) xmax = xmax * c;
  }
  gens.push_back({us.u.x, us.u.y, xmin});
  gens.push_back({us.u.x, us.u.y, xmax});
  forces.push_back(us.u);
  if (same) return true;
  gens.push_back({ue.u.x, ue.u.y, xmin});
  gens.push_back({ue.u.x, ue.u.y, xmax});
  forces.push_back(ue.u);
  return true;
}

int paper_cone_enclosure(const FVec2& ds, const FVec2& de, const LazyPiece::Enclosures& control,
                         const LazyPiece::Enclosures& legs, const Vec2& c, std::vector<FGen>& gens) {
  gens.clear();
  try {
    Protect guard;
    const FVec2 fc = to_interval(c);
    FVecs r;
    for (const FVec2& p : control) r.push_back(fsub(p, fc));
    FGens built;
    FVecs forces;
    if (!enclosed::paper_cone(ds, de, r, legs, built, forces)) return 0;
    gens.assign(built.begin(), built.end());
    return 1;
  } catch (const Open&) {
    return kUndecided;
  }
}

}  // namespace fixel::internal
