// J′'s wrench tests (docs/theory.md §10.7): a wrench is outside J′ when it
// is outside J, when a contact leaves its edge on the way, or when a pair
// holds the part at a pose of its family ("v ∈ FC_i + FC_j" by Carathéodory
// sign conditions, after the pieces filter, decided by the exact visit of
// approach_visit.cpp) or while it slides along parallel edges
// (approach_slide.cpp). The wrench is world-frame and rational, or given
// in frame B at the seat, whose world-frame form lies in Q(√d).
#include <cmath>

#include "fixel/approach.h"
#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/approach_data.h"
#include "fixel/internal/approach_visit.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/internal/sustained_data.h"
#include "fixel/progress.h"

namespace fixel {

namespace internal {

namespace {

// v = v0 + √d·v1 (v1 zero for a rational wrench), world frame.
struct FieldWrench {
  VectorQ v0, v1;
  Rational d;  // 0 when v is rational
};

bool in_rows(const std::vector<std::array<Rational, 3>>& rows, const FieldWrench& v) {
  for (const auto& a : rows) {
    const Rational x0 = a[0] * v.v0[0] + a[1] * v.v0[1] + a[2] * v.v0[2];
    if (v.d == 0) {
      if (x0 < 0) return false;
      continue;
    }
    const Rational x1 = a[0] * v.v1[0] + a[1] * v.v1[1] + a[2] * v.v1[2];
    if (sign(Q2(x0, x1, v.d)) < 0) return false;
  }
  return true;
}

Polynomial pdot(const PolyVec3& a, const PolyVec3& b) {
  return padd(padd(pmul(a[0], b[0]), pmul(a[1], b[1])), pmul(a[2], b[2]));
}

PolyVec3 pcross(const PolyVec3& a, const PolyVec3& b) {
  return {psub(pmul(a[1], b[2]), pmul(a[2], b[1])), psub(pmul(a[2], b[0]), pmul(a[0], b[2])),
          psub(pmul(a[0], b[1]), pmul(a[1], b[0]))};
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

// The same polynomials for v = v0 + √d·v1: each is free of v or linear in
// it, so it is P(v0) + √d·(P(v1) − P(0)).
std::vector<FieldPolynomial> hold_polynomials(const PairFamily& fam, const FieldWrench& v) {
  const std::vector<Polynomial> p0 = hold_polynomials(fam, v.v0);
  std::vector<FieldPolynomial> out;
  out.reserve(p0.size());
  if (v.d == 0) {
    for (const auto& p : p0) out.push_back({p, {}});
    return out;
  }
  const std::vector<Polynomial> p1 = hold_polynomials(fam, v.v1), pz = hold_polynomials(fam, VectorQ::Zero(3));
  for (std::size_t k = 0; k < p0.size(); ++k) {
    Polynomial b = psub(p1[k], pz[k]);
    trim(b);
    out.push_back({p0[k], b});
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

// The pairs' holds of v = −w (world frame) along the approach: "" when
// no pair holds the part, else the reason (and the pose in `hold`). The
// reason names the first pose of the first pair that holds, as the exact
// visit finds it, so that the filter changes no output: with `witness` a
// hold at a piece's start settles the answer only at t = 0, where the
// visit starts; without it (a yes/no question) at any piece's start.
std::string holds(const ApproachSet& A, const FieldWrench& v, ApproachHold* hold, bool witness) {
  const ExactTask task("approach-aware J' (a wrench's test)");
  for (const auto& fam : A.data->pairs) {
    poll_exact_step();
    // Filters, exact: a hold at a piece's start settles it; a wrench outside
    // every piece's outer cone is held nowhere on the family. Root isolation
    // decides the rest.
    bool maybe = force_exact();
    for (std::size_t k = 0; k < fam.pieces.size() && !force_exact(); ++k) {
      const auto& piece = fam.pieces[k];
      if ((!witness || k == 0) && !piece.inner_rows.empty() && in_rows(piece.inner_rows, v)) {
        record_filter(FilterSite::kApproach, true);
        if (hold) {
          *hold = ApproachHold{};
          hold->fixels = fam.fixels;
          hold->t = AlgebraicReal::rational(piece.t0);
          hold->theta = 2 * std::atan(to_double(piece.t0));
        }
        return fixel_name(fam.fixels[0]) + " and " + fixel_name(fam.fixels[1]) +
               " can hold the part at rest with friction on the way to the seat (at theta ~ " +
               theta_text(2 * std::atan(to_double(piece.t0))) + " rad, where only they touch)";
      }
      maybe = maybe || in_rows(piece.outer_rows, v);
    }
    if (!force_exact()) record_filter(FilterSite::kApproach, !maybe);
    if (!maybe) continue;
    const std::vector<FieldPolynomial> polys = hold_polynomials(fam, v);
    const std::size_t m = fam.gens.size();
    const auto found = first_point(polys, *A.data, [&](const Signs& s) { return held(m, s); });
    if (!found) continue;
    const double theta = theta_of(*found, A.theta_star);
    if (hold) {
      *hold = ApproachHold{};
      hold->fixels = fam.fixels;
      hold->theta = theta;
      if (found->kind == Point::kStar)
        hold->at_seat = true;
      else
        hold->t = found->kind == Point::kRational ? AlgebraicReal::rational(found->q) : found->root;
    }
    return fixel_name(fam.fixels[0]) + " and " + fixel_name(fam.fixels[1]) +
           " can hold the part at rest with friction on the way to the seat (at theta ~ " + theta_text(theta) +
           " rad, where only they touch)";
  }
  for (const auto& fam : A.data->slides) {
    const auto slide = slide_hold(fam, v.v0, v.v1, v.d);
    if (!slide) continue;
    if (hold) {
      *hold = ApproachHold{};
      hold->fixels = fam.fixels;
      hold->theta = fam.theta;
      hold->at_seat = fam.at_seat;
      hold->slide = *slide;
    }
    return fixel_name(fam.fixels[0]) + " and " + fixel_name(fam.fixels[1]) +
           " can hold the part at rest with friction while it slides along their parallel edges (theta ~ " +
           theta_text(fam.theta) + " rad, slid ~ " + theta_text(*slide) + (fam.at_seat ? " m from the seat)" : " m)");
  }
  return "";
}

}  // namespace

}  // namespace internal

using internal::Q2;

namespace internal {

void require_decided(const ApproachSet& A) {
  if (A.decided) return;
  // approach_set gives every undecided set its reason; none means no data.
  if (A.undecided_reason.empty()) throw InputError("J'", "", "has no data (default-constructed ApproachSet)");
  throw UnsupportedError("J'", "", "cannot be decided: " + A.undecided_reason);
}

namespace {

std::string world_reason(const ApproachSet& A, const VectorQ& w_W, ApproachHold* hold, bool witness) {
  require_decided(A);
  std::string reason = A.J.why_not(w_W);
  if (!reason.empty()) return reason;
  if (!A.on_edges) return "J' is empty: " + A.edge_reason;
  return holds(A, {-w_W, VectorQ::Zero(3), Rational(0)}, hold, witness);
}

std::string part_frame_reason(const ApproachSet& A, const VectorQ& w_B, ApproachHold* hold, bool witness) {
  require_decided(A);
  std::string reason = why_not_in_frame_B(A.J, w_B);
  if (!reason.empty()) return reason;
  if (!A.on_edges) return "J' is empty: " + A.edge_reason;
  // v = −R(θ*)·w_B = v0 + √d·v1, the world-frame wrench held along the way.
  const Q2 c = from_public((*A.J.pose.exact)[2]), s = from_public((*A.J.pose.exact)[3]);
  const std::array<Q2, 3> v{-(c * Q2(w_B[0]) - s * Q2(w_B[1])), -(s * Q2(w_B[0]) + c * Q2(w_B[1])), Q2(-w_B[2])};
  FieldWrench f{VectorQ::Zero(3), VectorQ::Zero(3), Rational(0)};
  for (int k = 0; k < 3; ++k) {
    f.v0[k] = v[k].a0();
    if (!v[k].is_extended() || v[k].a1() == 0) continue;
    if (f.d == 0) f.d = v[k].root();
    if (f.d != v[k].root()) throw InternalError("approach: a wrench with coordinates in two quadratic fields");
    f.v1[k] = v[k].a1();
  }
  if (f.d != 0 && f.d != A.data->t_star.d) throw InternalError("approach: the wrench is not in t*'s field");
  return holds(A, f, hold, witness);
}

}  // namespace
}  // namespace internal

bool ApproachSet::contains(const VectorQ& w_W) const {
  return internal::world_reason(*this, w_W, nullptr, false).empty();
}

std::string ApproachSet::why_not(const VectorQ& w_W, ApproachHold* hold) const {
  return internal::world_reason(*this, w_W, hold, true);
}

bool ApproachSet::contains_part_frame(const VectorQ& w_B) const {
  return internal::part_frame_reason(*this, w_B, nullptr, false).empty();
}

std::string ApproachSet::why_not_part_frame(const VectorQ& w_B, ApproachHold* hold) const {
  return internal::part_frame_reason(*this, w_B, hold, true);
}

}  // namespace fixel
