#pragma once
// J′'s data (approach.cpp builds it, approach_target.cpp reads it): each
// pair's two-contact family as polynomials in t = tan(θ/2), every one
// multiplied by 1 + t² (> 0), so signs and cones are unchanged
// (docs/theory.md §10.7). No CGAL here.

#include <array>
#include <optional>
#include <vector>

#include "fixel/algebraic.h"
#include "fixel/internal/polyline_edge.h"
#include "fixel/seated_pose.h"

namespace fixel {
struct ApproachSet;
}  // namespace fixel

namespace fixel::internal {

// Throws unless A is decided: InputError for a default-constructed set,
// UnsupportedError (with A's reason) for one that could not be decided.
void require_decided(const ApproachSet& A);

using PolyVec3 = std::array<Polynomial, 3>;

struct PairFamily {
  std::array<int, 2> fixels{};
  // World-frame generators of FC_i + FC_j at the pose t: W_n ± μ W_t of
  // both fixels (f_x, f_y, moment about the centre of mass).
  std::vector<PolyVec3> gens;
  // Body-frame contact points g_i, g_j on their edges (x, y).
  std::array<std::array<Polynomial, 2>, 2> contact_B;
  // ≥ 0 exactly while both contacts lie on their edges (two per fixel).
  std::vector<Polynomial> on_edge;
  // Both fixels frictionless: the generators span a plane.
  bool planar = false;
  // Pieces of the family from t = 0 to a rational bound of t* beyond it
  // (about kPieceAngle of θ each), world frame: the cone of every
  // generator's Bézier control points on the piece (outer: it holds the
  // pair's cone at every pose of the piece) and the pair's cone at the
  // piece's start (inner: one pose of the approach), as generators and
  // closed rows a·v ≥ 0 (inner rows empty when they cannot be made).
  struct Piece {
    Rational t0, t1;
    std::vector<std::array<Rational, 3>> outer_gens, outer_rows, inner_gens, inner_rows;
  };
  std::vector<Piece> pieces;
};

// Radians of θ per piece of a family, and a cap on the pieces.
inline constexpr double kPieceAngle = 0.02;
inline constexpr int kMaxPieces = 64;

// A pair on parallel edges touches both lines only at isolated rotations
// θ_r; there the part can slide along the edges (docs/theory.md §10.7).
// Frame B at θ_r, slide s along `e`: lever arms ρ_k(s) = ρ_k(0) + s e.
struct SlideFamily {
  std::array<int, 2> fixels{};
  QuadraticIrrational cos, sin;                          // θ_r
  bool at_seat = false;                                  // θ_r = θ* (then s = 0 is q*)
  double theta = 0;                                      // θ_r, display
  Vec2 e;                                                // slide direction, frame B
  std::vector<std::array<QuadraticIrrational, 3>> gens;  // W_n ± μ W_t at s = 0, frame B at θ_r
  QuadraticIrrational s_lo, s_hi;                        // both contacts on their edges
};

// The slide families of fixels i, j (parallel edges) at the rotations between
// 0 and θ* (ends included) where both touch, appended to `out`; `p` is the
// pair's consistency polynomial (zero at those t = tan(θ/2)) and `beta_i`
// the right side of fixel i's contact condition, both times 1 + t². False
// when p is zero: the pair touches at every rotation (not one family).
bool slide_families(const Scene& scene, const std::vector<PolylineEdge>& edges, const std::vector<Vec2>& f_A,
                    const std::vector<Rational>& mu, int i, int j, const Polynomial& p, const Polynomial& beta_i,
                    const SeatedPose& seat, const QuadraticIrrational& t_star, std::vector<SlideFamily>& out);

// A slide s (display) of the family at which v_W ∈ FC_i + FC_j (world
// frame): the pair holds the part under the wrench −v_W; none if no s does.
std::optional<double> slide_hold(const SlideFamily& fam, const VectorQ& v_W);
// The same for v_W = v0 + √d·v1 in the seat's field (a frame-B wrench at
// the seat, rotated to the world frame by θ*).
std::optional<double> slide_hold(const SlideFamily& fam, const VectorQ& v0, const VectorQ& v1, const Rational& d);

struct ApproachData {
  std::vector<PairFamily> pairs;
  std::vector<SlideFamily> slides;
  QuadraticIrrational t_star{0, 0, 0};
  // Rational bounds with t_lo < t* < t_hi when t* ≠ 0, tight to about 2⁻⁴⁰.
  Rational t_lo, t_hi;
};

// Evaluates the polynomials of a vector at a rational t.
inline std::array<Rational, 3> eval3(const PolyVec3& p, const Rational& t) {
  std::array<Rational, 3> out;
  for (int k = 0; k < 3; ++k) {
    Rational v = 0;
    for (std::size_t i = p[k].size(); i-- > 0;) v = v * t + p[k][i];
    out[k] = v;
  }
  return out;
}

}  // namespace fixel::internal
