#include "fixel/curve.h"

#include <gmp.h>

#include <algorithm>
#include <optional>

#include "fixel/error.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

Vec2 lerp(const Vec2& a, const Vec2& b, const Rational& t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }
bool same(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
std::string text(const Vec2& v) { return "(" + to_string(v.x) + ", " + to_string(v.y) + ")"; }

// One coordinate of de Casteljau at s, on storage reused per thread: each
// step a += s·(b − a) with GMP's in-place operations, so no temporary
// Rational is allocated (the region evaluates many points).
void casteljau_coordinate(const std::vector<Vec2>& pts, bool y, const Rational& s, Rational& out) {
  thread_local std::vector<Rational> c;
  thread_local Rational step;
  const std::size_t n = pts.size();
  if (c.size() < n) c.resize(n);
  for (std::size_t i = 0; i < n; ++i) mpq_set(c[i].backend().data(), (y ? pts[i].y : pts[i].x).backend().data());
  mpq_ptr t = step.backend().data();
  mpq_srcptr u = s.backend().data();
  for (std::size_t level = 1; level < n; ++level)
    for (std::size_t i = 0; i + level < n; ++i) {
      mpq_ptr a = c[i].backend().data();
      mpq_sub(t, c[i + 1].backend().data(), a);
      mpq_mul(t, t, u);
      mpq_add(a, a, t);
    }
  mpq_set(out.backend().data(), c[0].backend().data());
}

Vec2 de_casteljau(const std::vector<Vec2>& pts, const Rational& s) {
  // Only a piece built by hand has none (make_boundary never makes one).
  if (pts.empty()) throw InputError("BezierPiece.control", "0 points", "needs at least one control point");
  if (s == 0) return pts.front();  // the ends are control points
  if (s == 1) return pts.back();
  Vec2 out;
  casteljau_coordinate(pts, false, s, out.x);
  casteljau_coordinate(pts, true, s, out.y);
  return out;
}

// Control points of the derivative (hodograph) of a Bézier curve.
std::vector<Vec2> hodograph(const std::vector<Vec2>& pts) {
  const Rational p = static_cast<int>(pts.size()) - 1;
  std::vector<Vec2> out;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec2 d = sub(pts[i + 1], pts[i]);
    out.push_back({p * d.x, p * d.y});
  }
  return out;
}

// Power-basis coefficients c_j of one coordinate of a Bézier curve:
// Σ_i B_i^p(s) P_i = Σ_j c_j s^j, c_j = C(p,j) Σ_{i≤j} (−1)^{j−i} C(j,i) P_i.
std::vector<Rational> power_basis(const std::vector<Rational>& P) {
  const int p = static_cast<int>(P.size()) - 1;
  auto binom = [](int n, int k) {
    Integer r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return Rational(r);
  };
  std::vector<Rational> c(p + 1);
  for (int j = 0; j <= p; ++j) {
    Rational sum = 0;
    for (int i = 0; i <= j; ++i) sum += ((j - i) % 2 ? -1 : 1) * binom(j, i) * P[i];
    c[j] = binom(p, j) * sum;
  }
  return c;
}

using Poly = std::vector<Rational>;  // power basis in s

Poly mul(const Poly& a, const Poly& b) {
  Poly r(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
Poly deriv(const Poly& a) {
  if (a.size() <= 1) return Poly{Rational(0)};
  Poly r(a.size() - 1);
  for (std::size_t i = 1; i < a.size(); ++i) r[i - 1] = a[i] * static_cast<int>(i);
  return r;
}
Rational integral01(const Poly& a) {
  Rational r = 0;
  for (std::size_t i = 0; i < a.size(); ++i) r += a[i] / static_cast<int>(i + 1);
  return r;
}

void validate_curve(const Curve& c, const std::string& path) {
  if (c.type == Curve::Type::kPolyline) {
    if (c.points.size() < 2)
      throw SceneError(path + ".points", std::to_string(c.points.size()) + " point(s)", "a polyline needs at least 2");
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
      if (same(c.points[i], c.points[i + 1]))
        throw SceneError(path + ".points[" + std::to_string(i + 1) + "]", text(c.points[i + 1]),
                         "repeats the previous point: a zero-length edge has no normal");
    return;
  }
  const int p = c.degree, n = static_cast<int>(c.points.size());
  if (p < 1) throw SceneError(path + ".degree", std::to_string(p), "must be >= 1");
  if (n < p + 1)
    throw SceneError(path + ".control_points", std::to_string(n) + " point(s)",
                     "a degree-" + std::to_string(p) + " B-spline needs at least " + std::to_string(p + 1));
  if (static_cast<int>(c.knots.size()) != n + p + 1)
    throw SceneError(path + ".knots", std::to_string(c.knots.size()) + " knots",
                     "but " + std::to_string(n) + " control points of degree " + std::to_string(p) + " need " +
                         std::to_string(n + p + 1) + " (n + degree + 1)");
  for (std::size_t i = 0; i + 1 < c.knots.size(); ++i)
    if (c.knots[i + 1] < c.knots[i])
      throw SceneError(path + ".knots[" + std::to_string(i + 1) + "]", to_string(c.knots[i + 1]),
                       "is smaller than the previous knot " + to_string(c.knots[i]) + ": knots must be non-decreasing");
  for (std::size_t i = 0; i < c.knots.size();) {
    std::size_t j = i;
    while (j < c.knots.size() && c.knots[j] == c.knots[i]) ++j;
    if (static_cast<int>(j - i) > p + 1)
      throw SceneError(path + ".knots", to_string(c.knots[i]),
                       "has multiplicity " + std::to_string(j - i) + " > degree + 1 = " + std::to_string(p + 1));
    i = j;
  }
  if (!(c.knots[p] < c.knots[n]))
    throw SceneError(path + ".knots", "[" + to_string(c.knots[p]) + ", " + to_string(c.knots[n]) + "]",
                     "is an empty parameter range (knots[degree] must be < knots[n])");
}

// The blossom of span j (U[j] <= U[j+1], p <= j < n) at arguments t[0..p−1]:
// de Boor's recursion with argument t[r−1] at level r. With all arguments
// equal it is the curve point; with (a^{p−i}, b^i) it is the i-th Bézier
// point of the span [a, b] = [U[j], U[j+1]].
Vec2 blossom(const std::vector<Rational>& U, const std::vector<Vec2>& P, int p, int j, const std::vector<Rational>& t) {
  std::vector<Vec2> d(P.begin() + (j - p), P.begin() + j + 1);
  for (int r = 1; r <= p; ++r)
    for (int i = p; i >= r; --i) {
      const Rational lo = U[i + j - p], hi = U[i + 1 + j - r];
      d[i] = lerp(d[i - 1], d[i], (t[r - 1] - lo) / (hi - lo));
    }
  return d[p];
}

}  // namespace

Vec2 BezierPiece::point(const Rational& s) const { return de_casteljau(control, s); }

Rational BezierPiece::local(const Rational& u) const {
  if (!(u0 < u1))
    throw InputError("BezierPiece.u1", to_string(u1),
                     "must be above u0 = " + to_string(u0) + " (a piece covers a parameter range)");
  return (u - u0) / (u1 - u0);
}

Vec2 BezierPiece::derivative(const Rational& s, int k) const {
  if (k == 0) return de_casteljau(control, s);
  if (k == 1 && control.size() > 1) {  // the region's case: hodograph on reused storage
    thread_local std::vector<Vec2> h;
    thread_local Rational degree;
    const std::size_t n = control.size() - 1;
    h.resize(n);
    degree = static_cast<int>(n);
    for (std::size_t i = 0; i < n; ++i) {
      mpq_sub(h[i].x.backend().data(), control[i + 1].x.backend().data(), control[i].x.backend().data());
      mpq_mul(h[i].x.backend().data(), h[i].x.backend().data(), degree.backend().data());
      mpq_sub(h[i].y.backend().data(), control[i + 1].y.backend().data(), control[i].y.backend().data());
      mpq_mul(h[i].y.backend().data(), h[i].y.backend().data(), degree.backend().data());
    }
    return de_casteljau(h, s);
  }
  std::vector<Vec2> pts = control;
  for (int i = 0; i < k; ++i) {
    if (pts.size() <= 1) return {Rational(0), Rational(0)};
    pts = hodograph(pts);
  }
  return de_casteljau(pts, s);
}

namespace {
// (a + b) / 2 in place of lerp(a, b, 1/2): the same canonical rational, one
// addition and a halving that needs no gcd (mpq_div_2exp).
void halfway(Rational& out, const Rational& a, const Rational& b) {
  mpq_add(out.backend().data(), a.backend().data(), b.backend().data());
  mpq_div_2exp(out.backend().data(), out.backend().data(), 1);
}

// a += s·(b − a) in place (lerp without temporaries).
void toward(Rational& a, const Rational& b, const Rational& s) {
  thread_local Rational step;
  mpq_ptr t = step.backend().data();
  mpq_sub(t, b.backend().data(), a.backend().data());
  mpq_mul(t, t, s.backend().data());
  mpq_add(a.backend().data(), a.backend().data(), t);
}
}  // namespace

std::pair<BezierPiece, BezierPiece> BezierPiece::split(const Rational& s) const {
  const std::size_t n = control.size();
  const bool half = s == Rational(1, 2);  // the region's subdivision
  std::vector<Vec2> left(n), right(n), pts = control;
  for (std::size_t level = 0; level < n; ++level) {
    left[level] = pts.front();
    right[n - 1 - level] = pts[n - 1 - level];
    for (std::size_t i = 0; i + 1 < n - level; ++i) {
      if (!half) {
        toward(pts[i].x, pts[i + 1].x, s);
        toward(pts[i].y, pts[i + 1].y, s);
        continue;
      }
      halfway(pts[i].x, pts[i].x, pts[i + 1].x);
      halfway(pts[i].y, pts[i].y, pts[i + 1].y);
    }
  }
  Rational um;
  if (half)
    halfway(um, u0, u1);
  else
    um = u0 + s * (u1 - u0);
  return {BezierPiece{curve, u0, um, std::move(left)}, BezierPiece{curve, um, u1, std::move(right)}};
}

BezierPiece BezierPiece::restrict_to(const Rational& a, const Rational& b) const {
  BezierPiece piece = *this;
  if (a > u0) piece = piece.split(piece.local(a)).second;
  if (b < u1) piece = piece.split(piece.local(b)).first;
  piece.u0 = a;
  piece.u1 = b;
  return piece;
}

std::vector<Vec2> BezierPiece::legs() const {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i + 1 < control.size(); ++i) out.push_back(sub(control[i + 1], control[i]));
  return out;
}

Rational Curve::u_begin() const { return type == Type::kPolyline ? Rational(0) : knots[degree]; }
Rational Curve::u_end() const {
  return type == Type::kPolyline ? Rational(static_cast<int>(points.size()) - 1) : knots[points.size()];
}

std::vector<BezierPiece> Curve::bezier_pieces(int curve_index) const {
  std::vector<BezierPiece> out;
  if (type == Type::kPolyline) {
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      out.push_back(
          {curve_index, Rational(static_cast<int>(i)), Rational(static_cast<int>(i + 1)), {points[i], points[i + 1]}});
    return out;
  }
  const internal::ExactTask task("a B-spline's Bezier pieces");
  const int p = degree, n = static_cast<int>(points.size());
  for (int j = p; j < n; ++j) {
    if (!(knots[j] < knots[j + 1])) continue;  // empty span
    const Rational a = knots[j], b = knots[j + 1];
    std::vector<Vec2> ctrl;
    for (int i = 0; i <= p; ++i) {
      internal::poll_exact_step();  // O(p²) operations on the knots' and points' digits
      std::vector<Rational> t(p - i, a);
      t.insert(t.end(), i, b);
      ctrl.push_back(blossom(knots, points, p, j, t));
    }
    out.push_back({curve_index, a, b, ctrl});
  }
  return out;
}

Vec2 Curve::point(const Rational& u) const {
  for (const auto& piece : bezier_pieces(0))
    if (u >= piece.u0 && (u < piece.u1 || (u == piece.u1 && u == u_end()))) return piece.point(piece.local(u));
  throw InputError("u", to_string(u),
                   "is outside the curve's parameter range [" + to_string(u_begin()) + ", " + to_string(u_end()) + "]");
}

Vec2 Curve::derivative(const Rational& u, int k) const {
  for (const auto& piece : bezier_pieces(0))
    if (u >= piece.u0 && (u < piece.u1 || (u == piece.u1 && u == u_end()))) {
      // d/du = (1 / (u1 − u0)) d/ds for each order.
      Vec2 d = piece.derivative(piece.local(u), k);
      Rational scale = 1;
      for (int i = 0; i < k; ++i) scale /= (piece.u1 - piece.u0);
      return {d.x * scale, d.y * scale};
    }
  throw InputError("u", to_string(u),
                   "is outside the curve's parameter range [" + to_string(u_begin()) + ", " + to_string(u_end()) + "]");
}

Rational MassProperties::polar_moment_about(const Vec2& c) const {
  // ∬|p − c|² = ∬|p|² − 2 c·∬p + A|c|², with ∬p = A·centroid.
  return polar_moment - 2 * area * (c.x * centroid.x + c.y * centroid.y) + area * (c.x * c.x + c.y * c.y);
}

MassProperties mass_properties(const std::vector<BezierPiece>& pieces, RunControl* control) {
  // Green's theorem on each polynomial piece:
  //   A = ½∮(x dy − y dx),  ∬x = ½∮x² dy,  ∬y = −½∮y² dx,  ∬(x²+y²) = ⅓∮(x³ dy − y³ dx).
  Rational area2 = 0, mx2 = 0, my2 = 0, j3 = 0;
  // Segments in closed form (the integrals of (a + t(b − a))^k over [0, 1]),
  // with the divisions by 3 and 4 taken once at the end: a 100,000-edge
  // polyline loads in a fraction of the polynomial path's time, same value.
  Rational seg_mx2_times3 = 0, seg_my2_times3 = 0, seg_j3_times4 = 0;
  const long total = static_cast<long>(pieces.size());
  long done = 0;
  for (const auto& piece : pieces) {
    // Every piece: a high-degree B-spline's piece on long numbers takes seconds.
    poll(control, "load", done++, total, "pieces integrated (mass properties)");
    if (piece.control.size() == 2) {
      const Rational &x0 = piece.control[0].x, &y0 = piece.control[0].y;
      const Rational &x1 = piece.control[1].x, &y1 = piece.control[1].y;
      const Rational dx = x1 - x0, dy = y1 - y0;
      area2 += x0 * y1 - x1 * y0;
      const Rational xx = x0 * x0 + x0 * x1 + x1 * x1, yy = y0 * y0 + y0 * y1 + y1 * y1;
      seg_mx2_times3 += dy * xx;
      seg_my2_times3 -= dx * yy;
      seg_j3_times4 += dy * (x0 + x1) * (x0 * x0 + x1 * x1) - dx * (y0 + y1) * (y0 * y0 + y1 * y1);
      continue;
    }
    std::vector<Rational> xs, ys;
    for (const auto& p : piece.control) {
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
    const Poly x = power_basis(xs), y = power_basis(ys), dx = deriv(x), dy = deriv(y);
    const Poly x2 = mul(x, x), y2 = mul(y, y);
    area2 += integral01(mul(x, dy)) - integral01(mul(y, dx));
    mx2 += integral01(mul(x2, dy));
    my2 -= integral01(mul(y2, dx));
    j3 += integral01(mul(mul(x2, x), dy)) - integral01(mul(mul(y2, y), dx));
  }
  mx2 += seg_mx2_times3 / 3;
  my2 += seg_my2_times3 / 3;
  j3 += seg_j3_times4 / 4;
  MassProperties m;
  m.area = area2 / 2;
  if (m.area != 0)
    m.centroid = {mx2 / 2 / m.area, my2 / 2 / m.area};
  else
    m.centroid = {Rational(0), Rational(0)};
  m.polar_moment = j3 / 3;
  return m;
}

Boundary make_boundary(std::vector<Curve> curves, const std::string& path, RunControl* control) {
  if (curves.empty()) throw SceneError(path, "[]", "must contain at least one curve");
  const internal::ControlScopeIfGiven scope(control);  // one curve's Bézier pieces poll it
  const internal::ExactTask task("load");
  Boundary b;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const std::string cpath = path + "[" + std::to_string(k) + "]";
    poll(control, "load", static_cast<long>(k), static_cast<long>(curves.size()), "curves checked");
    validate_curve(curves[k], cpath);
    auto pieces = curves[k].bezier_pieces(static_cast<int>(k));
    for (std::size_t j = 0; j < pieces.size(); ++j) {
      bool moves = false;
      for (const auto& leg : pieces[j].legs()) moves = moves || leg.x != 0 || leg.y != 0;
      if (!moves)
        throw SceneError(cpath, "u in [" + to_string(pieces[j].u0) + ", " + to_string(pieces[j].u1) + "]",
                         "is a degenerate piece: all its control points coincide at " + text(pieces[j].control[0]));
      if (j > 0 && !same(pieces[j - 1].control.back(), pieces[j].control.front()))
        throw SceneError(cpath, "u = " + to_string(pieces[j].u0),
                         "is discontinuous: the curve jumps from " + text(pieces[j - 1].control.back()) + " to " +
                             text(pieces[j].control.front()) + " (a knot of multiplicity degree + 1)");
    }
    b.pieces.insert(b.pieces.end(), pieces.begin(), pieces.end());
  }
  // Counted as done, so that a stop in the closure check below says so.
  poll(control, "load", static_cast<long>(curves.size()), static_cast<long>(curves.size()), "curves checked");
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const std::size_t next = (k + 1) % curves.size();
    const Vec2 end = curves[k].point(curves[k].u_end()), start = curves[next].point(curves[next].u_begin());
    if (!same(end, start))
      throw SceneError(path + "[" + std::to_string(next) + "]", text(start),
                       next == 0 ? "does not close the loop: the last curve ends at " + text(end)
                                 : "does not start where the previous curve ends, " + text(end));
  }
  check_simple_loop(b.pieces, path, control);
  b.mass = mass_properties(b.pieces, control);
  if (b.mass.area == 0) throw SceneError(path, "area 0", "encloses no area");
  if (b.mass.area < 0)
    throw SceneError(path, "signed area " + to_string(b.mass.area),
                     "runs clockwise; list the loop counter-clockwise (interior on the left)");
  b.curves = std::move(curves);
  return b;
}

}  // namespace fixel
