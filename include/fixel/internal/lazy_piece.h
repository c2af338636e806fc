#pragma once
// The pieces of the region's subdivision (src/lazy_piece.cpp): halved in
// intervals, made exact only when the exact path asks (docs/theory.md §8).

#include <boost/container/small_vector.hpp>
#include <optional>
#include <utility>

#include "fixel/curve.h"
#include "fixel/internal/filtered.h"
#include "fixel/rational.h"

namespace fixel::internal {

// A piece of the subdivision: a parameter range [u0, u1] of a boundary
// piece, enclosures of its control points and of its control polygon's
// legs (both halved in intervals), and its exact control points only when
// asked for (the exact path), then made from the boundary piece (the
// control points of a sub-curve are unique, so they equal those of
// repeated halving). Children of a piece whose exact points were asked for
// are halved exactly.
class LazyPiece {
 public:
  using Enclosures = boost::container::small_vector<FVec2, 4>;
  // The whole boundary piece; with `enclose`, its control points' enclosures.
  LazyPiece(const BezierPiece& root, bool enclose);
  int curve() const { return root_->curve; }
  const Rational& u0() const { return u0_; }
  const Rational& u1() const { return u1_; }
  // Empty when made without enclosures.
  const Enclosures& enclosures() const { return ctrl_; }
  // Legs P_{k+1} − P_k, enclosed on their own: a difference of two point
  // enclosures loses all relative precision once the piece is short.
  const Enclosures& leg_enclosures() const { return legs_; }
  const BezierPiece& exact() const;
  // The halves at local parameter 1/2.
  std::pair<LazyPiece, LazyPiece> halves() const;

 private:
  LazyPiece(const BezierPiece* root, Rational u0, Rational u1) : root_(root), u0_(std::move(u0)), u1_(std::move(u1)) {}
  const BezierPiece* root_;
  Rational u0_, u1_;
  Enclosures ctrl_, legs_;
  mutable std::optional<BezierPiece> exact_;
  mutable bool asked_ = false;
};

}  // namespace fixel::internal
