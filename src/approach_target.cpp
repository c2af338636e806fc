// J′ as a target of the pushing region (docs/theory.md §10.7). The jam
// cones sweep with the pose, so J′ is not a finite union of polyhedral
// cones; the region asks its IN question of J's rows plus outer cones of the
// swept jam cones (each generator is a quadratic in t, or affine in the
// slide, so over a piece of the approach it lies in the cone of its Bézier
// control points), and its OUT question of J's rows plus exact jam cones at
// sampled poses. Both answers are exact; a segment neither settles is
// PARTIAL.
#include <algorithm>
#include <cmath>
#include <variant>

#include "fixel/approach.h"
#include "fixel/error.h"
#include "fixel/internal/approach_data.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/sustained_core.h"
#include "fixel/internal/sustained_data.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"

namespace fixel {

namespace internal {

namespace {

using V = A3<Q2>;

// Pieces of a slide per outer cone.
constexpr int kSlidePieces = 8;

// World frame → frame B at q* (J's data): Rᵀ(θ*) on the force part.
V to_seat(const Q2& cs, const Q2& sn, const V& w) { return {cs * w[0] + sn * w[1], -sn * w[0] + cs * w[1], w[2]}; }

V neg(const V& v) { return {-v[0], -v[1], -v[2]}; }

// A world-frame cone (generators and closed rows, rational) as a jam cone
// of J's data: negated (w-space) and rotated into frame B at q*; rows turn
// with the vectors, as the rotation is orthogonal.
void add_rotated(std::vector<Data<Q2>::Jam>& jams, const std::array<int, 2>& fixels,
                 const std::vector<std::array<Rational, 3>>& gens, const std::vector<std::array<Rational, 3>>& rows,
                 const Q2& cs, const Q2& sn) {
  poll_exact_step();  // products in Q(√d): on long numbers, seconds per cone
  Data<Q2>::Jam jam;
  jam.fixels = fixels;
  for (const auto& g : gens) jam.gens.push_back(neg(to_seat(cs, sn, {Q2(g[0]), Q2(g[1]), Q2(g[2])})));
  for (const auto& a : rows) jam.facets.push_back(neg(to_seat(cs, sn, {Q2(a[0]), Q2(a[1]), Q2(a[2])})));
  for (const auto& a : jam.facets) cache_enclosures(a);
  jams.push_back(std::move(jam));
}

// The jam cone −cone(gens) as J's data holds it (frame B at q*).
void add_jam(std::vector<Data<Q2>::Jam>& jams, const std::array<int, 2>& fixels, std::vector<V> gens, bool planar) {
  for (auto& g : gens) g = neg(g);
  if (planar && is_zero3(cross3(gens[0], gens[1]))) return;  // a degenerate plane: no exact rows
  Data<Q2>::Jam jam;
  jam.fixels = fixels;
  jam.facets = facets_of(gens, planar);
  jam.gens = std::move(gens);
  for (const auto& a : jam.facets) cache_enclosures(a);
  jams.push_back(std::move(jam));
}

}  // namespace

}  // namespace internal

std::unique_ptr<RegionTarget> approach_target(const ApproachSet& A) {
  const internal::ExactTask task("approach-aware J' (its region target)");
  using internal::Q2;
  using internal::V;
  internal::require_decided(A);
  if (!A.data || !A.J.data) throw InputError("J'", "", "has no data (default-constructed ApproachSet)");
  const auto* seat = std::get_if<internal::Data<Q2>>(&A.J.data->data);
  if (!seat) throw UnsupportedError("J'", "", "needs an exact seated pose");
  auto in = std::make_shared<internal::SustainedData>(), out = std::make_shared<internal::SustainedData>();
  internal::Data<Q2> d_in = *seat, d_out = *seat;
  d_in.pieces.clear();
  d_out.pieces.clear();
  const Q2 &cs = seat->cos, &sn = seat->sin;
  const internal::ApproachData& data = *A.data;

  // θ-families: their pieces (approach.cpp), outer cones for IN, the cone
  // at each piece's start for OUT.
  for (const auto& fam : data.pairs)
    for (const auto& piece : fam.pieces) {
      internal::add_rotated(d_in.jams, fam.fixels, piece.outer_gens, piece.outer_rows, cs, sn);
      if (!piece.inner_rows.empty())
        internal::add_rotated(d_out.jams, fam.fixels, piece.inner_gens, piece.inner_rows, cs, sn);
    }
  // Slides of pairs on parallel edges: generators affine in s.
  for (const auto& fam : data.slides) {
    // Frame B at θ_r → frame B at q*: R(θ_r − θ*).
    const Q2 cr = internal::from_public(fam.cos), sr = internal::from_public(fam.sin);
    const Q2 c = cr * cs + sr * sn, s = sr * cs - cr * sn;
    auto to_q = [&](const V& v) { return V{c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]}; };
    const Q2 s_lo = internal::from_public(fam.s_lo), s_hi = internal::from_public(fam.s_hi);
    bool planar = true;
    for (int k : fam.fixels) planar = planar && A.J.mu[k] == 0;
    auto at = [&](const Q2& slide) {
      std::vector<V> gens;
      for (const auto& g : fam.gens) {
        const Q2 fx = internal::from_public(g[0]), fy = internal::from_public(g[1]);
        // (f, m + s e × f)
        gens.push_back(to_q({fx, fy, internal::from_public(g[2]) + slide * (Q2(fam.e.x) * fy - Q2(fam.e.y) * fx)}));
      }
      return gens;
    };
    for (int k = 0; k < internal::kSlidePieces; ++k) {
      const Q2 a = s_lo + (s_hi - s_lo) * Q2(Rational(k, internal::kSlidePieces));
      const Q2 b = s_lo + (s_hi - s_lo) * Q2(Rational(k + 1, internal::kSlidePieces));
      std::vector<V> outer = at(a), end = at(b);
      outer.insert(outer.end(), end.begin(), end.end());
      internal::add_jam(d_in.jams, fam.fixels, outer, false);
      internal::add_jam(d_out.jams, fam.fixels, at(a), planar);
    }
  }
  in->data = std::move(d_in);
  out->data = std::move(d_out);
  in->built_from = A.J.data->built_from;  // J′ answers for J's scene
  return internal::sustained_target(std::move(in), std::move(out), A.empty);
}

}  // namespace fixel
