// Where region intervals are on the part: exact end points, and display
// figures (arc length, push direction) for reports.
#include <cmath>

#include "fixel/geometry.h"
#include "fixel/region.h"

namespace fixel {

namespace {

// Speed |B'(s)| of a piece in metres per unit of local parameter (display).
double speed(const BezierPiece& piece, double s) {
  // de Casteljau on the hodograph in doubles: display only.
  const int n = static_cast<int>(piece.control.size()) - 1;
  if (n < 1) return 0;
  std::vector<std::array<double, 2>> d;
  for (int k = 0; k < n; ++k)
    d.push_back({n * to_double(piece.control[k + 1].x - piece.control[k].x),
                 n * to_double(piece.control[k + 1].y - piece.control[k].y)});
  for (int r = 1; r < n; ++r)
    for (int k = 0; k + r < n; ++k) d[k] = {(1 - s) * d[k][0] + s * d[k + 1][0], (1 - s) * d[k][1] + s * d[k + 1][1]};
  return std::hypot(d[0][0], d[0][1]);
}

// Arc length of a piece between local parameters a < b: 8-point Gauss–Legendre.
double arc_length(const BezierPiece& piece, double a, double b) {
  static const double x[] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double w[] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const double mid = (a + b) / 2, half = (b - a) / 2;
  double sum = 0;
  for (int k = 0; k < 4; ++k) sum += w[k] * (speed(piece, mid - half * x[k]) + speed(piece, mid + half * x[k]));
  return sum * half;
}

const BezierPiece* piece_at(const Boundary& b, int curve, const Rational& u) {
  for (const auto& piece : b.pieces)
    if (piece.curve == curve && piece.u0 <= u && u <= piece.u1) return &piece;
  return nullptr;
}

}  // namespace

std::string in_meaning(const Region& region) {
  if (region.target == "J") return "sustained push: seats and stays";
  if (region.target == "G") return "one-step: guaranteed";
  return "one-step: can seat";
}

void locate_intervals(const Scene& scene, Region& region) {
  region.places.clear();
  region.outline_length = 0;
  if (!scene.body.boundary) return;
  const Boundary& b = *scene.body.boundary;
  for (const auto& piece : b.pieces) region.outline_length += arc_length(piece, 0, 1);
  region.places.reserve(region.intervals.size());
  for (const auto& r : region.intervals) {
    IntervalPlace place;
    const BezierPiece* first = piece_at(b, r.curve, r.u0);
    const BezierPiece* last = piece_at(b, r.curve, r.u1);
    if (first) place.start_A = first->point(first->local(r.u0));
    if (last) place.end_A = last->point(last->local(r.u1));
    for (const auto& piece : b.pieces) {
      if (piece.curve != r.curve || piece.u1 <= r.u0 || piece.u0 >= r.u1) continue;
      const Rational a = std::max(piece.u0, r.u0), e = std::min(piece.u1, r.u1);
      place.arc_length += arc_length(piece, to_double(piece.local(a)), to_double(piece.local(e)));
    }
    const Rational mid = (r.u0 + r.u1) / 2;
    const BezierPiece* p = piece_at(b, r.curve, mid);
    if (p) {
      const Vec2 t = p->derivative(p->local(mid));
      // A point on a junction of pieces: defined only if both sides agree.
      bool defined = true;
      for (const auto& q : b.pieces)
        if (q.curve == r.curve && &q != p && q.u0 <= mid && mid <= q.u1) {
          const Vec2 t2 = q.derivative(q.local(mid));
          defined = defined && cross(t, t2) == 0 && dot(t, t2) > 0;
        }
      const double tx = to_double(t.x), ty = to_double(t.y), len = std::hypot(tx, ty);
      if (defined && len > 0) place.push_direction_A = std::array<double, 2>{-ty / len, tx / len};  // inward: CCW loop
    }
    region.places.push_back(place);
  }
}

}  // namespace fixel
