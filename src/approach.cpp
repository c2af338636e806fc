// J′, the approach-aware sustained-push set (docs/theory.md §10.7), built:
// each pair's two-contact family in t = tan(θ/2), its pieces, and whether a
// contact leaves its edge on the way (an exact visit, approach_visit.cpp).
// Its wrench tests are in approach_hold.cpp.
#include "fixel/approach.h"

#include <algorithm>
#include <cmath>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/approach_data.h"
#include "fixel/internal/approach_visit.h"
#include "fixel/internal/cone3.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/polyline_edge.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/internal/sustained_data.h"
#include "fixel/progress.h"

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
    poll_exact_step();
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

}  // namespace

}  // namespace internal

using internal::Q2;

ApproachSet approach_set(const Scene& scene, const SustainedSet& J) {
  const internal::ExactTask task("approach-aware J'");
  ApproachSet A;
  A.J = J;
  const SeatedPose& q = J.pose;
  A.theta_star = q.approx[2];
  if (!J.data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  internal::check_built_from(*J.data, scene, "J");
  // J of another scene (its shape, at least): J' reads the scene's outline at J's contacts.
  if (scene.body.dof != 3 || !scene.body.boundary)
    throw SceneError(scene.body.dof != 3 ? "body.dof" : "body.boundary", scene.body.dof != 3 ? "2" : "",
                     "J' needs a rigid body with an outline (the scene J was built from)");
  if (J.mu.size() != scene.fixels.size())
    throw InputError("J", std::to_string(J.mu.size()) + " fixels",
                     "is not this scene's sustained-push set (" + std::to_string(scene.fixels.size()) +
                         " fixels): build it with sustained_set(scene)");
  // seated_pose leaves a contact's curve −1 where it does not locate it: a
  // closed contact off every polyline edge (on a curved piece), or an
  // enclosed q*. Anywhere else −1, like a curve beyond the outline's, is
  // another scene's J.
  bool on_curved_piece = false;
  const int curves = static_cast<int>(scene.body.boundary->curves.size());
  for (std::size_t i = 0; i < J.pose.contact_curve.size(); ++i) {
    const int curve = J.pose.contact_curve[i];
    const bool unlocated_here =
        curve < 0 && (!q.exact || (scene.fixels[i].gap == 0 &&
                                   !internal::polyline_edge_through(*scene.body.boundary, scene.fixels[i].p_AoF_A,
                                                                    scene.fixels[i].n_A)));
    if (curve >= curves || (curve < 0 && !unlocated_here))
      throw InputError("J", "a contact on curve " + std::to_string(curve),
                       "is not on this scene's outline: build J with sustained_set(scene)");
    on_curved_piece = on_curved_piece || curve < 0;
  }
  if (!q.exact || on_curved_piece) {
    A.undecided_reason = q.exact ? "a contact lies on a curved piece; J' needs every contact on a polyline edge"
                                 : "q* is only enclosed (a contact lies on a curved piece); J' needs every contact "
                                   "on a polyline edge";
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

}  // namespace fixel
