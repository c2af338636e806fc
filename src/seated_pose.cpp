#include "fixel/seated_pose.h"

#include <cmath>
#include <optional>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/polyline_edge.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/progress.h"

namespace fixel {

namespace internal {
SeatedPose seated_pose_curved(const Scene& scene);  // seated_pose_curved.cpp
}

namespace {

using internal::Q2;
using internal::sign;

using Edge = internal::PolylineEdge;

std::string fixel_path(int i) { return "fixels[" + std::to_string(i) + "]"; }
std::string text(const Vec2& v) { return "(" + to_string(v.x) + ", " + to_string(v.y) + ")"; }

bool is_perfect_square(const Integer& n, Integer& root) {
  if (n < 0) return false;
  root = boost::multiprecision::sqrt(n);
  return root * root == n;
}

// √r for a rational r = p/q > 0: rational when r is a square, else
// (k/q)·√m with p·q = k²·m and m free of small square factors (a readable
// root; any positive m would be as exact).
Q2 sqrt_of(const Rational& r) {
  const Integer p = boost::multiprecision::numerator(r), q = boost::multiprecision::denominator(r);
  Integer m = p * q, k = 1, root;
  if (is_perfect_square(m, root)) return Q2(Rational(root) / Rational(q));
  // Bounded trial division; each factor's power at once (mpz_remove), not
  // one division per power: a decimal's 10^N made N divisions of N digits.
  Integer rest, power;
  for (unsigned long f = 2; f <= 1000 && Integer(f) * f <= m; ++f) {
    internal::poll_exact_step();
    const Integer factor(f);
    const mp_bitcnt_t e = mpz_remove(rest.backend().data(), m.backend().data(), factor.backend().data());
    if (e < 2) continue;
    mpz_ui_pow_ui(power.backend().data(), f, e / 2);
    k *= power;
    m = e % 2 ? rest * f : rest;
  }
  return Q2(Rational(0), Rational(k) / Rational(q), Rational(m));
}

double approx(const Q2& x) { return internal::approx(internal::to_public(x)); }

// A certified enclosure (CGAL's own overflows to inf · 0 for huge d).
std::array<double, 2> enclose(const Q2& x) {
  const auto [lo, hi] = internal::bounds(internal::to_public(x));
  return {internal::to_interval(lo).inf(), internal::to_interval(hi).sup()};
}

SeatedPose scene_pose(const Scene& scene) {
  SeatedPose q;
  q.at_scene_pose = true;
  const QuadraticIrrational zero{0, 0, 0}, one{1, 0, 0};
  q.exact = std::array<QuadraticIrrational, 4>{zero, zero, one, zero};
  for (const auto& f : scene.fixels) {
    q.p_BoG_B.push_back({QuadraticIrrational{f.p_AoF_A.x, 0, 0}, QuadraticIrrational{f.p_AoF_A.y, 0, 0}});
    q.n_B.push_back(f.n_A);
    q.contact_curve.push_back(-1);
    q.contact_u.push_back(0);
  }
  return q;
}

}  // namespace

namespace internal {

std::optional<Edge> polyline_edge_through(const Boundary& boundary, const Vec2& p, const Vec2& n) {
  std::optional<Edge> found;
  for (std::size_t k = 0; k < boundary.pieces.size(); ++k) {
    const BezierPiece& piece = boundary.pieces[k];
    if (piece.degree() != 1) continue;
    const Vec2 &a = piece.control[0], &b = piece.control[1];
    const Vec2 e{b.x - a.x, b.y - a.y}, ap{p.x - a.x, p.y - a.y};
    if (e.x * ap.y - e.y * ap.x != 0) continue;
    const Rational along = e.x * ap.x + e.y * ap.y, len2 = e.x * e.x + e.y * e.y;
    if (along < 0 || along > len2) continue;
    Edge edge{static_cast<int>(k), a, b, {-e.y, e.x}, piece.u0, piece.u1 - piece.u0};
    const bool aligned =
        edge.inward.x * n.y - edge.inward.y * n.x == 0 && edge.inward.x * n.x + edge.inward.y * n.y > 0;
    if (!found || aligned) found = edge;
    if (aligned) break;
  }
  return found;
}

}  // namespace internal

std::string QuadraticIrrational::text() const {
  if (b == 0) return to_string(a);
  const std::string root = to_string(b) + "*sqrt(" + to_string(d) + ")";
  if (a == 0) return root;
  return to_string(a) + (b > 0 ? "+" : "") + root;
}

double QuadraticIrrational::approx() const { return internal::approx(*this); }

std::pair<Rational, Rational> internal::bounds(const QuadraticIrrational& x) {
  poll_exact_step();  // one square root and a few products: on long numbers, seconds
  const Rational pad = Rational(1) / Rational(Integer(1) << 60);
  if (x.b == 0) return {x.a - pad, x.a + pad};
  const Integer p = boost::multiprecision::numerator(x.d), q = boost::multiprecision::denominator(x.d);
  const Integer scale = Integer(1) << 64;
  const Integer r = boost::multiprecision::sqrt(p * q * scale * scale);  // ⌊√(pq)·2⁶⁴⌋
  const Rational root_lo = Rational(r) / Rational(q * scale), root_hi = Rational(r + 1) / Rational(q * scale);
  const Rational u = x.b * root_lo, v = x.b * root_hi;
  return {x.a + (u < v ? u : v) - pad, x.a + (u < v ? v : u) + pad};
}

double internal::approx(const QuadraticIrrational& x) {
  if (x.b == 0) return to_double(x.a);
  const auto [lo, hi] = bounds(x);
  return to_double((lo + hi) / 2);
}

SeatedPose seated_pose(const Scene& scene) {
  const internal::ExactTask task("seated pose q*");
  if (!scene.body.boundary)
    throw SceneError("body.boundary", "", "is missing: the seated pose needs the part's outline");
  if (scene.body.dof != 3)
    throw SceneError("body.dof", "2", "is a point mass, which has no seated pose to rotate into");
  check_scene_values(scene);
  const int nc = scene.num_contacts();
  bool all_closed = true;
  for (const auto& f : scene.fixels) all_closed = all_closed && f.gap == 0;
  if (all_closed) {
    SeatedPose q = scene_pose(scene);
    // Locate the contacts for display when they are on polyline edges.
    for (int i = 0; i < nc; ++i)
      if (auto e =
              internal::polyline_edge_through(*scene.body.boundary, scene.fixels[i].p_AoF_A, scene.fixels[i].n_A)) {
        const BezierPiece& piece = scene.body.boundary->pieces[e->piece];
        q.contact_curve[i] = piece.curve;
        const Vec2 d{e->b.x - e->a.x, e->b.y - e->a.y},
            ap{scene.fixels[i].p_AoF_A.x - e->a.x, scene.fixels[i].p_AoF_A.y - e->a.y};
        q.contact_u[i] = to_double(e->u0 + e->du * (d.x * ap.x + d.y * ap.y) / (d.x * d.x + d.y * d.y));
      }
    return q;
  }

  // Any contact off a polyline edge: the certified enclosure instead.
  for (int i = 0; i < nc; ++i)
    if (!internal::polyline_edge_through(*scene.body.boundary, scene.fixels[i].p_AoF_A, scene.fixels[i].n_A)) {
      bool curved = false;
      for (const auto& piece : scene.body.boundary->pieces) curved = curved || piece.degree() > 1;
      if (curved) return internal::seated_pose_curved(scene);
      break;
    }

  const Vec2& c = scene.body.p_AoCm_A;
  std::vector<Edge> edges;
  std::vector<Vec2> f_A;  // fixel points f_i = p_i − ψ_i n_i
  for (int i = 0; i < nc; ++i) {
    const Fixel& fx = scene.fixels[i];
    auto e = internal::polyline_edge_through(*scene.body.boundary, fx.p_AoF_A, fx.n_A);
    if (!e) {
      bool curved = false;
      for (const auto& piece : scene.body.boundary->pieces) curved = curved || piece.degree() > 1;
      if (curved)
        throw UnsupportedError(fixel_path(i) + ".point", text(fx.p_AoF_A),
                               "is not on a polyline edge: the seated pose for contacts on curved pieces with open "
                               "gaps needs a certified enclosure, which is not implemented");
      throw SceneError(fixel_path(i) + ".point", text(fx.p_AoF_A), "is not on the part's boundary");
    }
    edges.push_back(*e);
    f_A.push_back({fx.p_AoF_A.x - fx.gap * fx.n_A.x, fx.p_AoF_A.y - fx.gap * fx.n_A.y});
  }

  // Unknowns z = (τx, τy, cos θ, sin θ) with τ = −Rᵀ t: the fixel point in
  // frame B is g_i = Rᵀ (f_i − c) + τ + c, and n_e · (g_i − a_e) = 0 is
  // linear in z (docs/theory.md, seated pose).
  MatrixQ M(nc, 4);
  VectorQ rhs(nc);
  for (int i = 0; i < nc; ++i) {
    const Vec2& n = edges[i].inward;
    const Vec2 v{f_A[i].x - c.x, f_A[i].y - c.y};
    M(i, 0) = n.x;
    M(i, 1) = n.y;
    M(i, 2) = n.x * v.x + n.y * v.y;
    M(i, 3) = n.x * v.y - n.y * v.x;
    rhs[i] = n.x * (edges[i].a.x - c.x) + n.y * (edges[i].a.y - c.y);
  }
  const auto lu = internal::exact_lu(M);
  if (lu.rank() < 3)
    throw SceneError("fixels", "", "touch edges whose lines do not fix the part's pose (the seat is degenerate)");
  const VectorQ z0 = lu.solve(rhs);
  if (M * z0 != rhs) throw SceneError("fixels", "", "have no seated pose (the contact conditions are inconsistent)");
  const MatrixQ kernel = lu.kernel();
  const VectorQ D = kernel.col(0);
  const Rational A = D[2] * D[2] + D[3] * D[3], B = 2 * (z0[2] * D[2] + z0[3] * D[3]),
                 C = z0[2] * z0[2] + z0[3] * z0[3] - 1;
  if (A == 0) {
    if (C != 0) throw SceneError("fixels", "", "have no seated pose: the contact conditions force |(cos, sin)| != 1");
    throw SceneError("fixels", "", "have infinitely many seated poses: the part can slide while touching every fixel");
  }
  const Rational disc = B * B - 4 * A * C;
  if (disc < 0)
    throw SceneError("fixels", "", "have no seated pose: no rotation brings every fixel point onto its edge");
  std::vector<Q2> lambdas;
  const Q2 root = sqrt_of(disc);
  lambdas.push_back((Q2(-B) + root) / Q2(2 * A));
  if (disc != 0) lambdas.push_back((Q2(-B) - root) / Q2(2 * A));

  std::optional<SeatedPose> best;
  std::string why_not;
  for (const Q2& lambda : lambdas) {
    std::array<Q2, 4> z;
    for (int k = 0; k < 4; ++k) z[k] = Q2(z0[k]) + lambda * Q2(D[k]);
    const Q2 &cs = z[2], &sn = z[3];
    SeatedPose q;
    bool valid = true;
    for (int i = 0; i < nc && valid; ++i) {
      const Vec2 v{f_A[i].x - c.x, f_A[i].y - c.y};
      const Q2 gx = cs * Q2(v.x) + sn * Q2(v.y) + z[0] + Q2(c.x);
      const Q2 gy = -sn * Q2(v.x) + cs * Q2(v.y) + z[1] + Q2(c.y);
      const Edge& e = edges[i];
      const Vec2 d{e.b.x - e.a.x, e.b.y - e.a.y};
      const Q2 along = (gx - Q2(e.a.x)) * Q2(d.x) + (gy - Q2(e.a.y)) * Q2(d.y);
      const Rational len2 = d.x * d.x + d.y * d.y;
      if (sign(along) <= 0 || sign(along - Q2(len2)) >= 0) {
        valid = false;
        why_not = fixel_path(i) +
                  " would touch the line of its edge beyond the edge's end (at a corner or on a "
                  "neighbouring edge)";
        break;
      }
      q.p_BoG_B.push_back({internal::to_public(gx), internal::to_public(gy)});
      q.n_B.push_back(e.inward);
      q.contact_curve.push_back(scene.body.boundary->pieces[e.piece].curve);
      q.contact_u.push_back(to_double(e.u0) + to_double(e.du) * approx(along / Q2(len2)));
    }
    if (!valid) continue;
    // The centre of mass moves by t = −R τ.
    const Q2 tx = -(cs * z[0] - sn * z[1]), ty = -(sn * z[0] + cs * z[1]);
    q.exact = std::array<QuadraticIrrational, 4>{internal::to_public(tx), internal::to_public(ty),
                                                 internal::to_public(cs), internal::to_public(sn)};
    const double theta = std::atan2(approx(sn), approx(cs));
    q.approx = {approx(tx), approx(ty), theta};
    const auto cs_iv = enclose(cs), sn_iv = enclose(sn);
    // θ from the interval corners (atan2 is monotone on the small boxes met here; display only).
    const double t1 = std::atan2(sn_iv[0], cs_iv[1]), t2 = std::atan2(sn_iv[1], cs_iv[0]);
    q.enclosure = {enclose(tx), enclose(ty),
                   std::array<double, 2>{std::min({t1, t2, theta}), std::max({t1, t2, theta})}};
    if (best)
      throw SceneError("fixels", "",
                       "have two seated poses (θ ≈ " + std::to_string(best->approx[2]) + " and " +
                           std::to_string(theta) + " rad): the seat is not unique");
    best = q;
  }
  if (!best) {
    // A contact that leaves its edge may land on a curved neighbour.
    for (const auto& piece : scene.body.boundary->pieces)
      if (piece.degree() > 1) return internal::seated_pose_curved(scene);
    throw SceneError("fixels", "", "have no seated pose: " + why_not);
  }
  return *best;
}

}  // namespace fixel
