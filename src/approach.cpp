// J′, the approach-aware sustained-push set (docs/theory.md §10.7): each
// pair's two-contact family in t = tan(θ/2), and the exact tests along it
// (a pair holds the part; a contact leaves its edge) by real root isolation.
#include "fixel/approach.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/approach_data.h"
#include "fixel/internal/cone3.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/polyline_edge.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/internal/root_isolation.h"
#include "fixel/internal/sustained_data.h"

namespace fixel {

namespace internal {

namespace {

// cos θ, sin θ and 1 (the scale), each times 1 + t².
const Polynomial kCos{Rational(1), Rational(0), Rational(-1)};
const Polynomial kSin{Rational(0), Rational(2)};
const Polynomial kOne{Rational(1), Rational(0), Rational(1)};

Polynomial lin(const Polynomial& p, const Rational& a, const Polynomial& q, const Rational& b) {
  return padd(pscale(p, a), pscale(q, b));
}

// n_k · τ = n_k · (a_k − c) − (n_k · v_k) cos θ − (n_k × v_k) sin θ, v_k = f_k − c
// (the contact condition of seated_pose, linear in τ at a given θ).
Polynomial beta(const Vec2& c, const PolylineEdge& edge, const Vec2& f) {
  const Vec2& n = edge.inward;
  const Vec2 v{f.x - c.x, f.y - c.y};
  const Rational rhs = n.x * (edge.a.x - c.x) + n.y * (edge.a.y - c.y);
  return padd(pscale(kOne, rhs), lin(kCos, -(n.x * v.x + n.y * v.y), kSin, -(n.x * v.y - n.y * v.x)));
}

// The family of poses where fixels i and j touch the lines of their edges,
// one pose per θ (docs/theory.md §10.7); none when the edges are parallel.
std::optional<PairFamily> pair_family(const Vec2& c, const std::vector<PolylineEdge>& edges,
                                      const std::vector<Vec2>& f_A, const std::vector<Rational>& mu, int i, int j) {
  const Vec2 &ni = edges[i].inward, &nj = edges[j].inward;
  const Rational det = ni.x * nj.y - ni.y * nj.x;
  if (det == 0) return std::nullopt;
  const Polynomial bi = beta(c, edges[i], f_A[i]), bj = beta(c, edges[j], f_A[j]);
  const Polynomial tau_x = pscale(lin(bi, nj.y, bj, -ni.y), 1 / det);
  const Polynomial tau_y = pscale(lin(bj, ni.x, bi, -nj.x), 1 / det);
  PairFamily fam;
  fam.fixels = {i, j};
  fam.planar = mu[i] == 0 && mu[j] == 0;
  for (int side = 0; side < 2; ++side) {
    const int k = side == 0 ? i : j;
    const Vec2 v{f_A[k].x - c.x, f_A[k].y - c.y};
    // Lever arm ρ_k = g_k − c = Rᵀ v + τ (frame B).
    const Polynomial rho_x = padd(lin(kCos, v.x, kSin, v.y), tau_x);
    const Polynomial rho_y = padd(lin(kSin, -v.x, kCos, v.y), tau_y);
    const auto& g = fam.contact_B[side] = {padd(rho_x, pscale(kOne, c.x)), padd(rho_y, pscale(kOne, c.y))};
    const PolylineEdge& e = edges[k];
    const Vec2 d{e.b.x - e.a.x, e.b.y - e.a.y};
    const Polynomial along = padd(lin(g[0], d.x, g[1], d.y), pscale(kOne, -(e.a.x * d.x + e.a.y * d.y)));
    fam.on_edge.push_back(along);
    fam.on_edge.push_back(psub(pscale(kOne, d.x * d.x + d.y * d.y), along));
    const Vec2& n = e.inward;
    const Vec2 t{-n.y, n.x};
    for (int s : {1, -1}) {
      if (s == -1 && mu[k] == 0) break;
      const Vec2 b{n.x + s * mu[k] * t.x, n.y + s * mu[k] * t.y};
      // World frame: force R(θ) b, moment ρ × b (rotation-invariant).
      fam.gens.push_back({lin(kCos, b.x, kSin, -b.y), lin(kSin, b.x, kCos, b.y), lin(rho_x, b.y, rho_y, -b.x)});
    }
  }
  return fam;
}

Rational derivative_at(const Polynomial& p, const Rational& t) {
  Rational v = 0;
  for (std::size_t i = p.size(); i-- > 1;) v = v * t + Rational(static_cast<long>(i)) * p[i];
  return v;
}

// The family's pieces on [0, end] (end a rational bound of t* beyond it):
// each generator, a quadratic in t, lies on [t0, t1] in the cone of its
// Bézier control points p(t0), p(t0) + (t1 − t0)/2 p'(t0), p(t1).
void add_pieces(PairFamily& fam, const Rational& end, int count) {
  for (int k = 0; k < count; ++k) {
    const Rational a = end * Rational(k, count), b = end * Rational(k + 1, count);
    PairFamily::Piece piece;
    piece.t0 = a;  // on 0's side
    piece.t1 = b;
    const Rational lo = a < b ? a : b, hi = a < b ? b : a;
    for (const auto& g : fam.gens) {
      const auto p0 = eval3(g, lo), p2 = eval3(g, hi);
      std::array<Rational, 3> p1;
      for (int c = 0; c < 3; ++c) p1[c] = p0[c] + (hi - lo) / 2 * derivative_at(g[c], lo);
      piece.outer_gens.insert(piece.outer_gens.end(), {p0, p1, p2});
      piece.inner_gens.push_back(eval3(g, a));
    }
    piece.outer_rows = facets_of(piece.outer_gens, false);
    if (!fam.planar || !is_zero3(cross3(piece.inner_gens[0], piece.inner_gens[1])))
      piece.inner_rows = facets_of(piece.inner_gens, fam.planar);
    fam.pieces.push_back(std::move(piece));
  }
}

bool in_rows(const std::vector<std::array<Rational, 3>>& rows, const VectorQ& v) {
  for (const auto& a : rows)
    if (a[0] * v[0] + a[1] * v[1] + a[2] * v[2] < 0) return false;
  return true;
}

Polynomial pdot(const PolyVec3& a, const PolyVec3& b) {
  return padd(padd(pmul(a[0], b[0]), pmul(a[1], b[1])), pmul(a[2], b[2]));
}

PolyVec3 pcross(const PolyVec3& a, const PolyVec3& b) {
  return {psub(pmul(a[1], b[2]), pmul(a[2], b[1])), psub(pmul(a[2], b[0]), pmul(a[0], b[2])),
          psub(pmul(a[0], b[1]), pmul(a[1], b[0]))};
}

Q2 eval_q2(const Polynomial& p, const Q2& x) {
  Q2 v(0);
  for (std::size_t i = p.size(); i-- > 0;) v = v * x + Q2(p[i]);
  return v;
}

// A point of the closed interval between 0 and t*: rational, an irrational
// root of one of the polynomials, or t* itself.
struct Point {
  enum Kind { kRational, kRoot, kStar } kind = kRational;
  Rational q;
  AlgebraicReal root;
};

// Sign of p at x. At an irrational root x of the polynomials' product, p
// either vanishes or has no root in x's isolating interval (the intervals of
// the product's roots are disjoint), so its sign there is its sign at the
// interval's midpoint.
int sign_at(const Polynomial& p, const Point& x, const Q2& t_star) {
  switch (x.kind) {
    case Point::kRational:
      return fixel::sign(peval(p, x.q));
    case Point::kRoot:
      return is_root(x.root, p) ? 0 : fixel::sign(peval(p, x.root.midpoint()));
    case Point::kStar:
      return sign(eval_q2(p, t_star));
  }
  return 0;
}

Rational upper(const Point& x) { return x.kind == Point::kRational ? x.q : x.root.hi; }
Rational lower(const Point& x) { return x.kind == Point::kRational ? x.q : x.root.lo; }

// The sign function handed to a predicate: signs of polys[k] at one point,
// computed on first use.
using Signs = std::function<int(std::size_t)>;

// Visits the closed interval between 0 and t*, from 0 towards t*: every
// point where a sign of `polys` may change, and one rational point inside
// each open cell between two such points (where every sign is constant).
// Returns the first point where `pred` is true.
std::optional<Point> first_point(const std::vector<Polynomial>& polys, const ApproachData& d,
                                 const std::function<bool(const Signs&)>& pred) {
  const QuadraticIrrational& ts = d.t_star;
  const Q2 t_star = from_public(ts);
  auto visit = [&](const Point& x) {
    std::vector<int> cache(polys.size(), 2);
    const Signs s = [&](std::size_t k) {
      if (cache[k] == 2) cache[k] = sign_at(polys[k], x, t_star);
      return cache[k];
    };
    return pred(s);
  };
  Point zero;
  zero.q = 0;
  if (sign(t_star) == 0) {
    if (visit(zero)) return zero;
    return std::nullopt;
  }
  // t*'s own polynomial joins the list, so t* is one of the roots found.
  std::vector<Polynomial> all = polys;
  if (ts.b == 0)
    all.push_back({-ts.a, Rational(1)});
  else
    all.push_back({ts.a * ts.a - ts.b * ts.b * ts.d, -2 * ts.a, Rational(1)});
  const bool positive = sign(t_star) > 0;
  const std::vector<AlgebraicReal> roots =
      positive ? real_roots(all, Rational(0), d.t_hi) : real_roots(all, d.t_lo, Rational(0));
  std::size_t star = roots.size();
  for (std::size_t k = 0; k < roots.size() && star == roots.size(); ++k)
    if (sign(Q2(roots[k].lo) - t_star) <= 0 && sign(Q2(roots[k].hi) - t_star) >= 0) star = k;
  if (star == roots.size()) throw InternalError("approach: t* is not among the roots of its own polynomial");
  // The events in increasing order, then visited from 0 towards t*.
  std::vector<Point> events;
  auto as_point = [](const AlgebraicReal& r) {
    Point p;
    if (r.is_rational()) {
      p.q = r.lo;
    } else {
      p.kind = Point::kRoot;
      p.root = r;
    }
    return p;
  };
  Point star_point;
  star_point.kind = Point::kStar;
  star_point.root = roots[star];
  if (positive) {
    events.push_back(zero);
    for (std::size_t k = 0; k < star; ++k) events.push_back(as_point(roots[k]));
    events.push_back(star_point);
  } else {
    events.push_back(star_point);
    for (std::size_t k = star + 1; k < roots.size(); ++k) events.push_back(as_point(roots[k]));
    events.push_back(zero);
  }
  // Each root's interval lies in the open search interval, so it clears 0;
  // the check guards the cell samples against an interval touching it.
  for (std::size_t k = 0; k + 1 < events.size(); ++k)
    if (!(upper(events[k]) < lower(events[k + 1])))
      throw InternalError("approach: isolating intervals overlap at a cell of the family");
  const std::size_t n = events.size();
  for (std::size_t m = 0; m < n; ++m) {
    const std::size_t k = positive ? m : n - 1 - m;
    if (visit(events[k])) return events[k];
    if (m + 1 == n) break;
    const std::size_t next = positive ? k + 1 : k - 1;
    const std::size_t left = std::min(k, next);
    Point cell;
    cell.q = (upper(events[left]) + lower(events[left + 1])) / 2;
    if (visit(cell)) return cell;
  }
  return std::nullopt;
}

// The polynomials of "v ∈ FC_i + FC_j" along a family (Carathéodory: v is in
// the cone of a linearly independent subset of the generators), in the order
// held() reads them.
std::vector<Polynomial> hold_polynomials(const PairFamily& fam, const VectorQ& v) {
  const PolyVec3 V{Polynomial{v[0]}, Polynomial{v[1]}, Polynomial{v[2]}};
  PolyVec3 Vt = V;
  for (auto& p : Vt) trim(p);
  const auto& G = fam.gens;
  const std::size_t m = G.size();
  std::vector<Polynomial> out;
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b)
      for (std::size_t c = b + 1; c < m; ++c) {
        out.push_back(pdot(G[a], pcross(G[b], G[c])));
        out.push_back(pdot(Vt, pcross(G[b], G[c])));
        out.push_back(pdot(G[a], pcross(Vt, G[c])));
        out.push_back(pdot(G[a], pcross(G[b], Vt)));
      }
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b) {
      const PolyVec3 X = pcross(G[a], G[b]);
      for (const auto& x : X) out.push_back(x);
      out.push_back(pdot(Vt, X));
      out.push_back(pdot(pcross(Vt, G[b]), X));
      out.push_back(pdot(pcross(G[a], Vt), X));
    }
  for (std::size_t a = 0; a < m; ++a) {
    for (const auto& x : pcross(G[a], Vt)) out.push_back(x);
    out.push_back(pdot(G[a], Vt));
  }
  return out;
}

bool held(std::size_t m, const Signs& s) {
  std::size_t k = 0;
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b)
      for (std::size_t c = b + 1; c < m; ++c, k += 4) {
        const int sd = s(k);
        if (sd != 0 && s(k + 1) * sd >= 0 && s(k + 2) * sd >= 0 && s(k + 3) * sd >= 0) return true;
      }
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b, k += 6) {
      const bool independent = s(k) != 0 || s(k + 1) != 0 || s(k + 2) != 0;
      if (independent && s(k + 3) == 0 && s(k + 4) >= 0 && s(k + 5) >= 0) return true;
    }
  for (std::size_t a = 0; a < m; ++a, k += 4)
    if (s(k) == 0 && s(k + 1) == 0 && s(k + 2) == 0 && s(k + 3) > 0) return true;
  return false;
}

std::string theta_text(double theta) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.4f", theta);
  return buf;
}

double theta_of(const Point& x, double theta_star) {
  if (x.kind == Point::kStar) return theta_star;
  const double t = x.kind == Point::kRational ? to_double(x.q) : x.root.approx();
  return 2 * std::atan(t);
}

}  // namespace

}  // namespace internal

using internal::Q2;

ApproachSet approach_set(const Scene& scene, const SustainedSet& J) {
  ApproachSet A;
  A.J = J;
  const SeatedPose& q = J.pose;
  A.theta_star = q.approx[2];
  if (!J.data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  if (!q.exact) {
    A.undecided_reason =
        "q* is only enclosed (a contact lies on a curved piece); J' needs every contact on a polyline edge";
    return A;
  }
  auto data = std::make_shared<internal::ApproachData>();
  const Q2 cs = internal::from_public((*q.exact)[2]), sn = internal::from_public((*q.exact)[3]);
  if (internal::sign(cs + Q2(1)) == 0) {
    A.undecided_reason = "the seat is rotated by pi: t = tan(theta/2) is infinite there";
    return A;
  }
  const Q2 t_star = internal::sign(sn) == 0 ? Q2(0) : sn / (cs + Q2(1));
  data->t_star = A.t_star = internal::to_public(t_star);
  if (internal::sign(t_star) != 0) {
    const auto [lo, hi] = internal::bounds(A.t_star);
    data->t_lo = lo;
    data->t_hi = hi;
    if (internal::sign(Q2(data->t_lo) - t_star) >= 0 || internal::sign(Q2(data->t_hi) - t_star) <= 0)
      throw InternalError("approach: the enclosure of t* is not certified");
  }
  try {
    // With every gap 0 the part starts seated: no approach. Otherwise each
    // pair has its families: one in θ (a single pose, q*, when θ* = 0), or for
    // parallel edges the slides at the rotations where both touch.
    if (!q.at_scene_pose) {
      const int nc = scene.num_contacts();
      const Vec2& c = scene.body.p_AoCm_A;
      std::vector<internal::PolylineEdge> edges;
      std::vector<Vec2> f_A;
      for (int i = 0; i < nc; ++i) {
        const Fixel& fx = scene.fixels[i];
        auto e = internal::polyline_edge_through(*scene.body.boundary, fx.p_AoF_A, fx.n_A);
        if (!e) throw InternalError("approach: an exact seat with a contact off every polyline edge");
        edges.push_back(*e);
        f_A.push_back({fx.p_AoF_A.x - fx.gap * fx.n_A.x, fx.p_AoF_A.y - fx.gap * fx.n_A.y});
      }
      for (int i = 0; i < nc; ++i)
        for (int j = i + 1; j < nc; ++j) {
          if (auto fam = internal::pair_family(c, edges, f_A, J.mu, i, j)) {
            if (internal::sign(t_star) == 0) continue;
            const int count = std::clamp(static_cast<int>(std::ceil(std::abs(A.theta_star) / internal::kPieceAngle)), 1,
                                         internal::kMaxPieces);
            internal::add_pieces(*fam, internal::sign(t_star) > 0 ? data->t_hi : data->t_lo, count);
            data->pairs.push_back(std::move(*fam));
            continue;
          }
          const Vec2 &ni = edges[i].inward, &nj = edges[j].inward;
          const Rational kappa = (nj.x * ni.x + nj.y * ni.y) / (ni.x * ni.x + ni.y * ni.y);  // n_j = κ n_i
          const Polynomial bi = internal::beta(c, edges[i], f_A[i]);
          const Polynomial p = internal::psub(internal::beta(c, edges[j], f_A[j]), internal::pscale(bi, kappa));
          if (!internal::slide_families(scene, edges, f_A, J.mu, i, j, p, bi, q, A.t_star, data->slides)) {
            A.undecided_reason = internal::fixel_name(i) + " and " + internal::fixel_name(j) +
                                 " touch parallel edges at every rotation: their two-contact poses are not one "
                                 "family (not implemented)";
            return A;
          }
        }
    }
  } catch (const InternalError& e) {  // a defect, reported rather than failing J's report
    A.undecided_reason = std::string("could not be built (") + e.what() + ")";
    return A;
  }
  A.on_edges = true;
  try {
    for (const auto& fam : data->pairs) {
      const auto found = internal::first_point(fam.on_edge, *data, [&](const internal::Signs& s) {
        for (std::size_t k = 0; k < fam.on_edge.size(); ++k)
          if (s(k) < 0) return true;
        return false;
      });
      if (found) {
        A.on_edges = false;
        A.edge_reason = "the two-contact family of " + internal::fixel_name(fam.fixels[0]) + " and " +
                        internal::fixel_name(fam.fixels[1]) + " runs a contact off its edge (at theta ~ " +
                        internal::theta_text(internal::theta_of(*found, A.theta_star)) + " rad)";
        break;
      }
    }
  } catch (const InternalError& e) {
    A.on_edges = false;
    A.undecided_reason = std::string("could not be built (") + e.what() + ")";
    return A;
  }
  A.decided = true;
  A.empty = J.empty || !A.on_edges;
  A.data = std::move(data);
  return A;
}

bool ApproachSet::contains(const VectorQ& w_W) const { return why_not(w_W).empty(); }

std::string ApproachSet::why_not(const VectorQ& w_W, ApproachHold* hold) const {
  if (!decided) throw UnsupportedError("J'", "", "cannot be decided: " + undecided_reason);
  std::string reason = J.why_not(w_W);
  if (!reason.empty()) return reason;
  if (!on_edges) return "J' is empty: " + edge_reason;
  VectorQ v(3);
  for (int k = 0; k < 3; ++k) v[k] = -w_W[k];
  for (const auto& fam : data->pairs) {
    // Filters, exact: a hold at a piece's start settles it; a wrench outside
    // every piece's outer cone is held nowhere on the family. Root isolation
    // decides the rest.
    bool maybe = force_exact();
    for (std::size_t k = 0; k < fam.pieces.size() && !force_exact(); ++k) {
      const auto& piece = fam.pieces[k];
      if (!piece.inner_rows.empty() && internal::in_rows(piece.inner_rows, v)) {
        internal::record_filter(FilterSite::kApproach, true);
        if (hold) {
          *hold = ApproachHold{};
          hold->fixels = fam.fixels;
          hold->t = AlgebraicReal::rational(piece.t0);
          hold->theta = 2 * std::atan(to_double(piece.t0));
        }
        return internal::fixel_name(fam.fixels[0]) + " and " + internal::fixel_name(fam.fixels[1]) +
               " can hold the part at rest with friction on the way to the seat (at theta ~ " +
               internal::theta_text(2 * std::atan(to_double(piece.t0))) + " rad, where only they touch)";
      }
      maybe = maybe || internal::in_rows(piece.outer_rows, v);
    }
    if (!force_exact()) internal::record_filter(FilterSite::kApproach, !maybe);
    if (!maybe) continue;
    const std::vector<Polynomial> polys = internal::hold_polynomials(fam, v);
    const std::size_t m = fam.gens.size();
    const auto found =
        internal::first_point(polys, *data, [&](const internal::Signs& s) { return internal::held(m, s); });
    if (!found) continue;
    const double theta = internal::theta_of(*found, theta_star);
    if (hold) {
      *hold = ApproachHold{};
      hold->fixels = fam.fixels;
      hold->theta = theta;
      if (found->kind == internal::Point::kStar)
        hold->at_seat = true;
      else
        hold->t = found->kind == internal::Point::kRational ? AlgebraicReal::rational(found->q) : found->root;
    }
    return internal::fixel_name(fam.fixels[0]) + " and " + internal::fixel_name(fam.fixels[1]) +
           " can hold the part at rest with friction on the way to the seat (at theta ~ " +
           internal::theta_text(theta) + " rad, where only they touch)";
  }
  for (const auto& fam : data->slides) {
    const auto slide = internal::slide_hold(fam, v);
    if (!slide) continue;
    if (hold) {
      *hold = ApproachHold{};
      hold->fixels = fam.fixels;
      hold->theta = fam.theta;
      hold->at_seat = fam.at_seat;
      hold->slide = *slide;
    }
    return internal::fixel_name(fam.fixels[0]) + " and " + internal::fixel_name(fam.fixels[1]) +
           " can hold the part at rest with friction while it slides along their parallel edges (theta ~ " +
           internal::theta_text(fam.theta) + " rad, slid ~ " + internal::theta_text(*slide) +
           (fam.at_seat ? " m from the seat)" : " m)");
  }
  return "";
}

}  // namespace fixel
