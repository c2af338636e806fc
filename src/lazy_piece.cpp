// The subdivision's pieces (internal/lazy_piece.h): enclosures halved by de
// Casteljau in intervals, exact control points made only when asked for.
#include "fixel/internal/lazy_piece.h"

#include <vector>

#include "fixel/internal/enclosed_plane.h"

namespace fixel::internal {

namespace {

// Enclosures of the control points and of the legs, from exact points.
void enclose_exact(const std::vector<Vec2>& control, LazyPiece::Enclosures& ctrl, LazyPiece::Enclosures& legs) {
  for (std::size_t k = 0; k < control.size(); ++k) {
    ctrl.push_back(to_interval(control[k]));
    if (k > 0) legs.push_back(to_interval(sub(control[k], control[k - 1])));
  }
}

}  // namespace

LazyPiece::LazyPiece(const BezierPiece& root, bool enclose) : root_(&root), u0_(root.u0), u1_(root.u1) {
  if (!enclose) return;
  for (const auto& p : root.control) ctrl_.push_back(to_interval(p));
  // A whole piece is long, so the difference of enclosures is tight enough
  // and spares an exact subtraction per leg (polylines have many pieces).
  // A coordinate whose difference may be zero is subtracted exactly: an
  // exact zero (an axis-parallel leg) is then a point, as the exact path's
  // signs and the paper cone's grid directions need.
  Protect guard;
  for (std::size_t k = 1; k < ctrl_.size(); ++k) {
    FVec2 leg = enclosed::fsub(ctrl_[k], ctrl_[k - 1]);
    if (leg.x.inf() <= 0 && leg.x.sup() >= 0) leg.x = to_interval(Rational(root.control[k].x - root.control[k - 1].x));
    if (leg.y.inf() <= 0 && leg.y.sup() >= 0) leg.y = to_interval(Rational(root.control[k].y - root.control[k - 1].y));
    legs_.push_back(leg);
  }
}

const BezierPiece& LazyPiece::exact() const {
  asked_ = true;
  if (exact_) return *exact_;
  if (u0_ == root_->u0 && u1_ == root_->u1) return *root_;
  exact_ = root_->restrict_to(u0_, u1_);
  return *exact_;
}

std::pair<LazyPiece, LazyPiece> LazyPiece::halves() const {
  if (asked_) {  // the exact path ran here: halve exactly, as before
    auto h = exact().split(Rational(1, 2));
    std::pair<LazyPiece, LazyPiece> out{LazyPiece(root_, h.first.u0, h.first.u1),
                                        LazyPiece(root_, h.second.u0, h.second.u1)};
    out.first.exact_ = std::move(h.first);
    out.second.exact_ = std::move(h.second);
    for (LazyPiece* c : {&out.first, &out.second})
      if (!ctrl_.empty()) enclose_exact(c->exact_->control, c->ctrl_, c->legs_);
    return out;
  }
  const Rational um = (u0_ + u1_) / 2;
  std::pair<LazyPiece, LazyPiece> out{LazyPiece(root_, u0_, um), LazyPiece(root_, um, u1_)};
  if (ctrl_.empty()) return out;
  // De Casteljau at 1/2 on the enclosures.
  const std::size_t n = ctrl_.size();
  Enclosures pts = ctrl_;
  out.first.ctrl_.resize(n);
  out.second.ctrl_.resize(n);
  Protect guard;
  for (std::size_t level = 0; level < n; ++level) {
    out.first.ctrl_[level] = pts.front();
    out.second.ctrl_[n - 1 - level] = pts[n - 1 - level];
    for (std::size_t i = 0; i + 1 < n - level; ++i)
      pts[i] = {(pts[i].x + pts[i + 1].x) / 2, (pts[i].y + pts[i + 1].y) / 2};
  }
  // The legs by de Casteljau on the legs (the hodograph): with D⁰ the m
  // legs and Dʲ their level-j averages, the left half's leg j is Dʲ_0/2
  // and the right half's is D^{m−1−j}_j/2 (docs/theory.md §8).
  const std::size_t m = legs_.size();
  Enclosures d = legs_;
  out.first.legs_.resize(m);
  out.second.legs_.resize(m);
  for (std::size_t level = 0; level < m; ++level) {
    out.first.legs_[level] = {d.front().x / 2, d.front().y / 2};
    out.second.legs_[m - 1 - level] = {d[m - 1 - level].x / 2, d[m - 1 - level].y / 2};
    for (std::size_t i = 0; i + 1 < m - level; ++i) d[i] = {(d[i].x + d[i + 1].x) / 2, (d[i].y + d[i + 1].y) / 2};
  }
  return out;
}

}  // namespace fixel::internal
