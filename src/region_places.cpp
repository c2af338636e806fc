// Where region intervals are on the part: exact end points, and display
// figures (arc length, push direction) for reports.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "fixel/geometry.h"
#include "fixel/internal/filtered.h"
#include "fixel/region.h"

namespace fixel {

namespace {

// A piece's hodograph control points in doubles (display only), computed
// once per piece: n·(P_{k+1} − P_k), each difference taken exactly first.
using Hodograph = std::vector<std::array<double, 2>>;

// to_double(a − b): when a and b are doubles (point enclosures) and their
// double difference is exact (its two-sum error is 0), that difference is
// the value itself; otherwise the exact difference, converted.
double difference(const Rational& a, const Rational& b) {
  const internal::FI fa = internal::to_interval(a), fb = internal::to_interval(b);
  if (fa.inf() == fa.sup() && fb.inf() == fb.sup()) {
    const double x = fa.inf(), y = -fb.inf(), s = x + y, yy = s - x;
    if (std::isfinite(s) && (x - (s - yy)) + (y - yy) == 0) return s;
  }
  return to_double(a - b);
}

Hodograph hodograph(const BezierPiece& piece) {
  const int n = static_cast<int>(piece.control.size()) - 1;
  Hodograph d;
  d.reserve(n);
  for (int k = 0; k < n; ++k)
    d.push_back({n * difference(piece.control[k + 1].x, piece.control[k].x),
                 n * difference(piece.control[k + 1].y, piece.control[k].y)});
  return d;
}

// Speed |B'(s)| in metres per unit of local parameter: de Casteljau on the
// hodograph (display).
double speed(const Hodograph& h, double s) {
  const int n = static_cast<int>(h.size());
  if (n < 1) return 0;
  std::array<std::array<double, 2>, 8> small;  // no allocation for degree <= 8
  Hodograph large;
  std::array<double, 2>* d = small.data();
  if (n > 8) {
    large = h;
    d = large.data();
  } else {
    std::copy(h.begin(), h.end(), small.begin());
  }
  for (int r = 1; r < n; ++r)
    for (int k = 0; k + r < n; ++k) d[k] = {(1 - s) * d[k][0] + s * d[k + 1][0], (1 - s) * d[k][1] + s * d[k + 1][1]};
  return std::hypot(d[0][0], d[0][1]);
}

// Arc length between local parameters a < b: 8-point Gauss–Legendre.
double arc_length(const Hodograph& d, double a, double b) {
  static const double x[] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double w[] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const double mid = (a + b) / 2, half = (b - a) / 2;
  double sum = 0;
  for (int k = 0; k < 4; ++k) sum += w[k] * (speed(d, mid - half * x[k]) + speed(d, mid + half * x[k]));
  return sum * half;
}

// The pieces in loop order, with each curve's contiguous index range, so a
// lookup by (curve, u) is a binary search (pieces of a curve are in
// parameter order) and locating every interval stays O(n log n).
class PieceIndex {
 public:
  explicit PieceIndex(const Boundary& b) : b_(b) {
    for (std::size_t i = 0; i < b.pieces.size(); ++i) {
      const int c = b.pieces[i].curve;
      if (c < 0) continue;
      if (static_cast<std::size_t>(c) >= range_.size()) range_.resize(c + 1, {b.pieces.size(), b.pieces.size()});
      if (range_[c].first == b.pieces.size()) range_[c].first = i;
      range_[c].second = i + 1;
    }
  }
  // Index of the first piece of `curve` whose u1 ≥ u (or `end` of the
  // curve's range when there is none).
  std::size_t first_ending_at_or_after(int curve, const Rational& u, bool strictly = false) const {
    const auto [lo, hi] = curve_range(curve);
    std::size_t a = lo, e = hi;
    while (a < e) {
      const std::size_t m = a + (e - a) / 2;
      if (strictly ? b_.pieces[m].u1 <= u : b_.pieces[m].u1 < u)
        a = m + 1;
      else
        e = m;
    }
    return a;
  }
  std::pair<std::size_t, std::size_t> curve_range(int curve) const {
    if (curve < 0 || static_cast<std::size_t>(curve) >= range_.size()) return {0, 0};
    return range_[curve];
  }
  // The first piece of `curve` containing u, or null.
  const BezierPiece* at(int curve, const Rational& u) const {
    const std::size_t i = first_ending_at_or_after(curve, u);
    if (i >= curve_range(curve).second || u < b_.pieces[i].u0) return nullptr;
    return &b_.pieces[i];
  }

 private:
  const Boundary& b_;
  std::vector<std::pair<std::size_t, std::size_t>> range_;
};

}  // namespace

std::string in_meaning(const Region& region) {
  if (region.target == "J") return "sustained push: seats and stays";
  if (region.target == "J'") return "sustained push: seats and stays, no pair holding the part on the way";
  if (region.target == "G") return "one-step: guaranteed";
  return "one-step: can seat";
}

void locate_intervals(const Scene& scene, Region& region) {
  region.places.clear();
  region.outline_length = 0;
  if (!scene.body.boundary) return;
  const Boundary& b = *scene.body.boundary;
  const PieceIndex index(b);
  std::vector<Hodograph> hodographs;
  std::vector<double> piece_length;
  hodographs.reserve(b.pieces.size());
  piece_length.reserve(b.pieces.size());
  for (const auto& piece : b.pieces) {
    hodographs.push_back(hodograph(piece));
    piece_length.push_back(arc_length(hodographs.back(), 0, 1));
    region.outline_length += piece_length.back();
  }
  region.places.reserve(region.intervals.size());
  for (const auto& r : region.intervals) {
    IntervalPlace place;
    const BezierPiece* first = index.at(r.curve, r.u0);
    const BezierPiece* last = index.at(r.curve, r.u1);
    // Intervals tile each curve: a start is usually the previous end.
    const RegionInterval* prev = region.places.empty() ? nullptr : &region.intervals[region.places.size() - 1];
    if (first && prev && prev->curve == r.curve && prev->u1 == r.u0)
      place.start_A = region.places.back().end_A;
    else if (first)
      place.start_A = first->point(first->local(r.u0));
    if (last) place.end_A = last->point(last->local(r.u1));
    // The pieces overlapping (u0, u1), in parameter order.
    const std::size_t end = index.curve_range(r.curve).second;
    for (std::size_t i = index.first_ending_at_or_after(r.curve, r.u0, /*strictly=*/true);
         i < end && b.pieces[i].u0 < r.u1; ++i) {
      const BezierPiece& piece = b.pieces[i];
      const bool whole = r.u0 <= piece.u0 && piece.u1 <= r.u1;
      if (whole) {
        place.arc_length += piece_length[i];
        continue;
      }
      const Rational a = std::max(piece.u0, r.u0), e = std::min(piece.u1, r.u1);
      place.arc_length += arc_length(hodographs[i], to_double(piece.local(a)), to_double(piece.local(e)));
    }
    const Rational mid = (r.u0 + r.u1) / 2;
    const BezierPiece* p = index.at(r.curve, mid);
    if (p) {
      const Vec2 at_mid = p->point(p->local(mid));
      place.middle_A = std::array<double, 2>{to_double(at_mid.x), to_double(at_mid.y)};
      const Vec2 t = p->derivative(p->local(mid));
      // A point on a junction of pieces: defined only if both sides agree.
      // p is the first piece containing mid; only the following ones that
      // start at mid can contain it too.
      bool defined = true;
      for (const BezierPiece* q = p + 1; q < b.pieces.data() + end && q->u0 <= mid; ++q)
        if (mid <= q->u1) {
          const Vec2 t2 = q->derivative(q->local(mid));
          defined = defined && cross(t, t2) == 0 && dot(t, t2) > 0;
        }
      const double tx = to_double(t.x), ty = to_double(t.y), len = std::hypot(tx, ty);
      if (defined && len > 0) place.push_direction_A = std::array<double, 2>{-ty / len, tx / len};  // inward: CCW loop
    }
    region.places.push_back(place);
  }
}

}  // namespace fixel
