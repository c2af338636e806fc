// Exact point-on-outline and normal tests (gcd over Q and Sturm–Tarski
// queries on each Bézier piece), and display figures for messages.
#include "fixel/on_boundary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fixel/error.h"

namespace fixel {

namespace {

using Poly = std::vector<Rational>;  // power basis in s, trimmed (empty is 0)

void trim(Poly& a) {
  while (!a.empty() && a.back() == 0) a.pop_back();
}

Rational eval(const Poly& a, const Rational& s) {
  Rational r = 0;
  for (auto it = a.rbegin(); it != a.rend(); ++it) r = r * s + *it;
  return r;
}

Poly deriv(const Poly& a) {
  Poly r;
  for (std::size_t i = 1; i < a.size(); ++i) r.push_back(a[i] * static_cast<int>(i));
  trim(r);
  return r;
}

Poly mul(const Poly& a, const Poly& b) {
  if (a.empty() || b.empty()) return {};
  Poly r(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}

Poly lin(const Rational& ca, const Poly& a, const Rational& cb, const Poly& b) {
  Poly r(std::max(a.size(), b.size()), Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += ca * a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] += cb * b[i];
  trim(r);
  return r;
}

// Remainder of a by b (b non-zero).
Poly rem(Poly a, const Poly& b) {
  while (a.size() >= b.size() && !a.empty()) {
    const Rational f = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t i = 0; i < b.size(); ++i) a[i + shift] -= f * b[i];
    a.pop_back();  // the leading term cancels exactly
    trim(a);
  }
  return a;
}

Poly monic(Poly a) {
  if (a.empty()) return a;
  const Rational lead = a.back();
  for (auto& c : a) c /= lead;
  return a;
}

Poly gcd(Poly a, Poly b) {
  trim(a);
  trim(b);
  while (!b.empty()) {
    Poly r = rem(a, b);
    a = monic(b);
    b = monic(r);
  }
  return monic(a);
}

// Exact quotient a / b (b divides a).
Poly quotient(Poly a, const Poly& b) {
  Poly q(a.size() >= b.size() ? a.size() - b.size() + 1 : 0, Rational(0));
  while (a.size() >= b.size() && !a.empty()) {
    const Rational f = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    q[shift] = f;
    for (std::size_t i = 0; i < b.size(); ++i) a[i + shift] -= f * b[i];
    a.pop_back();
    trim(a);
  }
  trim(q);
  return q;
}

int sgn(const Rational& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// Sign variations of the signed remainder sequence of (p, q) at s.
int variations(const std::vector<Poly>& seq, const Rational& s) {
  int count = 0, last = 0;
  for (const auto& p : seq) {
    const int v = sgn(eval(p, s));
    if (v == 0) continue;
    if (last != 0 && v != last) ++count;
    last = v;
  }
  return count;
}

std::vector<Poly> remainder_sequence(const Poly& p, const Poly& q) {
  std::vector<Poly> seq{p};
  if (q.empty()) return seq;
  seq.push_back(q);
  // Bounded by deg p + 1 steps: degrees fall strictly.
  while (!seq.back().empty() && seq.size() <= p.size() + 1) {
    Poly r = rem(seq[seq.size() - 2], seq.back());
    if (r.empty()) break;
    for (auto& c : r) c = -c;
    seq.push_back(r);
  }
  return seq;
}

// Tarski query on (0, 1) for squarefree p with p(0), p(1) != 0:
// #{roots with q > 0} − #{roots with q < 0}; with q = 1 the root count.
int tarski_query(const Poly& p, const Poly& q) {
  if (p.size() <= 1) return 0;
  const auto seq = remainder_sequence(p, mul(deriv(p), q));
  return variations(seq, Rational(0)) - variations(seq, Rational(1));
}

Poly squarefree(const Poly& p) {
  const Poly g = gcd(p, deriv(p));
  return g.size() <= 1 ? monic(p) : monic(quotient(p, g));
}

// Power-basis coefficients of one coordinate of a Bézier curve.
Poly power_basis(const std::vector<Rational>& P) {
  const int p = static_cast<int>(P.size()) - 1;
  auto binom = [](int n, int k) {
    Integer r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return Rational(r);
  };
  Poly c(p + 1);
  for (int j = 0; j <= p; ++j) {
    Rational sum = 0;
    for (int i = 0; i <= j; ++i) sum += ((j - i) % 2 ? -1 : 1) * binom(j, i) * P[i];
    c[j] = binom(p, j) * sum;
  }
  trim(c);
  return c;
}

Vec2 rot90(const Vec2& v) { return {-v.y, v.x}; }
bool same(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }

// The first and last non-zero legs: the tangent directions at s = 0 and 1.
Vec2 start_tangent(const BezierPiece& piece) {
  for (const auto& leg : piece.legs())
    if (!is_zero(leg)) return leg;
  throw InternalError("a boundary piece with no non-zero leg passed make_boundary");
}
Vec2 end_tangent(const BezierPiece& piece) {
  const auto legs = piece.legs();
  for (auto it = legs.rbegin(); it != legs.rend(); ++it)
    if (!is_zero(*it)) return *it;
  throw InternalError("a boundary piece with no non-zero leg passed make_boundary");
}

// n matches inward normal direction v (any length): parallel and alike.
bool matches(const Vec2& n, const Vec2& v) { return cross(n, v) == 0 && dot(n, v) > 0; }

// n in the closed cone (angle < π) spanned by a and b.
bool in_short_cone(const Vec2& n, const Vec2& a, const Vec2& b) {
  const int o = orientation(a, b);
  if (o > 0) return in_cone(n, a, b);
  if (o < 0) return in_cone(n, b, a);
  return matches(n, a) || matches(n, b);
}

struct Approx {
  double x, y;
};
Approx approx(const Vec2& v) { return {to_double(v.x), to_double(v.y)}; }

Approx point_d(const std::vector<Approx>& c, double s) {
  std::vector<Approx> p = c;
  for (std::size_t level = 1; level < p.size(); ++level)
    for (std::size_t i = 0; i + level < p.size(); ++i)
      p[i] = {p[i].x + s * (p[i + 1].x - p[i].x), p[i].y + s * (p[i + 1].y - p[i].y)};
  return p.front();
}

// Display: the nearest point of the loop to p (piece, local s, distance²).
void nearest_point(const Boundary& b, const Approx& p, int& best_piece, double& best_s, double& best_d2) {
  best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < b.pieces.size(); ++k) {
    std::vector<Approx> c;
    for (const auto& q : b.pieces[k].control) c.push_back(approx(q));
    std::vector<Approx> d;
    for (std::size_t i = 0; i + 1 < c.size(); ++i) d.push_back({c[i + 1].x - c[i].x, c[i + 1].y - c[i].y});
    const int samples = c.size() == 2 ? 1 : 16 * static_cast<int>(c.size());
    for (int j = 0; j <= samples; ++j) {
      double s = static_cast<double>(j) / samples;
      if (c.size() == 2) {  // a segment: the exact projection, in doubles
        const double len2 = d[0].x * d[0].x + d[0].y * d[0].y;
        s = len2 > 0 ? std::clamp(((p.x - c[0].x) * d[0].x + (p.y - c[0].y) * d[0].y) / len2, 0.0, 1.0) : 0.0;
      } else {
        for (int it = 0; it < 30; ++it) {  // Newton on |B(s) − p|²
          const Approx q = point_d(c, s), legs = point_d(d, s);
          const double degree = static_cast<double>(d.size());
          const Approx t{degree * legs.x, degree * legs.y};
          const double g = (q.x - p.x) * t.x + (q.y - p.y) * t.y, h = t.x * t.x + t.y * t.y;
          if (!(h > 0)) break;
          s = std::clamp(s - g / h, 0.0, 1.0);
        }
      }
      const Approx q = point_d(c, s);
      const double d2 = (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
      if (d2 < best_d2) best_d2 = d2, best_piece = static_cast<int>(k), best_s = s;
      if (c.size() == 2) break;
    }
  }
}

Approx unit_d(double x, double y) {
  const double len = std::hypot(x, y);
  return len > 0 ? Approx{x / len, y / len} : Approx{0, 0};
}

}  // namespace

std::optional<Vec2> exact_unit(const Vec2& v) {
  const Rational q = v.x * v.x + v.y * v.y;
  if (q == 0) return std::nullopt;
  const Integer num = boost::multiprecision::numerator(q), den = boost::multiprecision::denominator(q);
  const Integer rn = boost::multiprecision::sqrt(num), rd = boost::multiprecision::sqrt(den);
  if (rn * rn != num || rd * rd != den) return std::nullopt;
  const Rational len(rn, rd);
  return Vec2{v.x / len, v.y / len};
}

Vec2 nearby_exact_unit(double radians) {
  if (!std::isfinite(radians)) {
    std::ostringstream shown;
    shown << radians;
    throw InputError("radians", shown.str(), "must be finite");
  }
  // Reduce to |θ| ≤ π/2, where t = tan(θ/2) ∈ [−1, 1]; flip back at the end.
  double theta = std::remainder(radians, 2 * M_PI);
  bool flip = false;
  if (theta > M_PI / 2) theta -= M_PI, flip = true;
  if (theta < -M_PI / 2) theta += M_PI, flip = true;
  const double t = std::tan(theta / 2);
  // Continued-fraction convergents of t until within 1e-11 (angle error ≤ 2·Δt).
  Integer h0 = 0, h1 = 1, k0 = 1, k1 = 0;
  double x = t;
  for (int i = 0; i < 60; ++i) {
    const double a = std::floor(x);
    const Integer ai = static_cast<long long>(a);
    const Integer h2 = ai * h1 + h0, k2 = ai * k1 + k0;
    h0 = h1, h1 = h2, k0 = k1, k1 = k2;
    const double approx_t = static_cast<double>(h1) / static_cast<double>(k1);
    if (std::abs(approx_t - t) < 1e-11 || x == a) break;
    x = 1 / (x - a);
  }
  const Rational tq(h1, k1);
  Vec2 n{(1 - tq * tq) / (1 + tq * tq), 2 * tq / (1 + tq * tq)};
  if (flip) n = {-n.x, -n.y};
  return n;
}

BoundaryFit fit_to_boundary(const Boundary& b, const Vec2& p, const Vec2* n) {
  // A Boundary assembled by hand may lack what every fit reads.
  if (b.pieces.empty()) throw SceneError("boundary", "0 pieces", "has no Bezier pieces: build it with make_boundary");
  for (const auto& piece : b.pieces)
    if (piece.control.size() < 2)
      throw SceneError("boundary", "a piece of " + std::to_string(piece.control.size()) + " control points",
                       "needs at least 2: build it with make_boundary");
  BoundaryFit fit;
  const std::size_t count = b.pieces.size();
  for (std::size_t k = 0; k < count && !fit.on_boundary; ++k) {
    const BezierPiece& piece = b.pieces[k];
    // A joint: p is where piece k starts (and the previous piece ends).
    if (same(piece.control.front(), p)) {
      const BezierPiece& prev = b.pieces[(k + count - 1) % count];
      const Vec2 n_in = rot90(end_tangent(prev)), n_out = rot90(start_tangent(piece));
      fit.on_boundary = true;
      fit.curve = piece.curve;
      fit.u = piece.u0;
      fit.corner = !matches(n_in, n_out);
      if (!fit.corner) fit.inward_normal = n_in;
      if (n) fit.normal_matches = fit.corner ? in_short_cone(*n, n_in, n_out) : matches(*n, n_in);
      break;
    }
    if (same(piece.control.back(), p)) continue;  // the next piece's joint
    // Quick exclusion: outside the control points' bounding box.
    Rational lo_x = piece.control[0].x, hi_x = lo_x, lo_y = piece.control[0].y, hi_y = lo_y;
    for (const auto& q : piece.control) {
      lo_x = std::min(lo_x, q.x), hi_x = std::max(hi_x, q.x);
      lo_y = std::min(lo_y, q.y), hi_y = std::max(hi_y, q.y);
    }
    if (p.x < lo_x || p.x > hi_x || p.y < lo_y || p.y > hi_y) continue;
    if (piece.degree() == 1) {
      const Vec2 d = sub(piece.control[1], piece.control[0]), ap = sub(p, piece.control[0]);
      if (cross(d, ap) != 0) continue;
      const Rational s = dot(d, ap) / dot(d, d);
      if (!(s > 0 && s < 1)) continue;
      fit.on_boundary = true;
      fit.curve = piece.curve;
      fit.u = piece.u0 + s * (piece.u1 - piece.u0);
      fit.inward_normal = rot90(d);
      if (n) fit.normal_matches = matches(*n, rot90(d));
      break;
    }
    // A curved piece: common roots in (0, 1) of x(s) − p_x and y(s) − p_y.
    std::vector<Rational> xs, ys;
    for (const auto& q : piece.control) xs.push_back(q.x), ys.push_back(q.y);
    Poly X = power_basis(xs), Y = power_basis(ys);
    X = lin(1, X, -1, Poly{p.x});
    Y = lin(1, Y, -1, Poly{p.y});
    const Poly g = squarefree(gcd(X, Y));
    if (g.size() <= 1 || tarski_query(g, Poly{Rational(1)}) == 0) continue;
    fit.on_boundary = true;
    fit.curve = piece.curve;
    std::optional<Rational> rational_root;
    if (g.size() == 2) rational_root = -g[0] / g[1];
    if (g.size() == 3) {  // monic quadratic: rational roots when the discriminant is a square
      const Rational disc = g[1] * g[1] - 4 * g[0];
      const Integer num = boost::multiprecision::numerator(disc), den = boost::multiprecision::denominator(disc);
      const Integer rn = disc > 0 ? Integer(boost::multiprecision::sqrt(num)) : Integer(0),
                    rd = boost::multiprecision::sqrt(den);
      if (disc > 0 && rn * rn == num && rd * rd == den) {
        const Rational root(rn, rd);
        for (const Rational& s : {(-g[1] + root) / 2, (-g[1] - root) / 2})
          if (s > 0 && s < 1) rational_root = s;
      }
    }
    if (rational_root) {
      const Rational s = *rational_root;
      fit.u = piece.u0 + s * (piece.u1 - piece.u0);
      fit.inward_normal = rot90(piece.derivative(s));
      if (is_zero(*fit.inward_normal)) fit.inward_normal.reset();
    }
    if (n) {
      // Tangent T(s) = B'(s); match iff T·n = 0 and T ⊗ n > 0 at the root.
      const Poly Tx = deriv(power_basis(xs)), Ty = deriv(power_basis(ys));
      const Poly along = lin(n->x, Tx, n->y, Ty), across = lin(n->y, Tx, -n->x, Ty);  // T·n, T ⊗ n
      const Poly h = along.empty() ? g : gcd(g, along);
      if (h.size() > 1) {
        const int roots = tarski_query(h, Poly{Rational(1)});
        const Poly z = gcd(h, across);
        const int zeros = z.size() > 1 ? tarski_query(z, Poly{Rational(1)}) : 0;
        const int positive = (roots - zeros + tarski_query(h, across)) / 2;
        fit.normal_matches = positive > 0;
      }
    }
    break;
  }

  // Display figures: the nearest point, its parameter and inward normal.
  const Approx pd = approx(p);
  int piece_index = 0;
  double s = 0, d2 = 0;
  nearest_point(b, pd, piece_index, s, d2);
  const BezierPiece& piece = b.pieces[piece_index];
  std::vector<Approx> c, d;
  for (const auto& q : piece.control) c.push_back(approx(q));
  for (std::size_t i = 0; i + 1 < c.size(); ++i) d.push_back({c[i + 1].x - c[i].x, c[i + 1].y - c[i].y});
  const Approx q = point_d(c, s), t = point_d(d, s);
  if (!fit.on_boundary) {
    fit.curve = piece.curve;
    fit.distance = std::sqrt(d2);
  }
  fit.nearest = {fit.on_boundary ? pd.x : q.x, fit.on_boundary ? pd.y : q.y};
  fit.u_approx = fit.u ? to_double(*fit.u) : to_double(piece.u0) + s * to_double(piece.u1 - piece.u0);
  Approx normal = unit_d(-t.y, t.x);
  if (fit.corner) {  // the bisector of the two one-sided normals
    std::size_t k = 0;
    while (k < count && !same(b.pieces[k].control.front(), p)) ++k;
    const BezierPiece& next = b.pieces[k % count];
    const BezierPiece& prev = b.pieces[(k + count - 1) % count];
    const Approx a = approx(rot90(end_tangent(prev))), bb = approx(rot90(start_tangent(next)));
    const Approx ua = unit_d(a.x, a.y), ub = unit_d(bb.x, bb.y);
    normal = unit_d(ua.x + ub.x, ua.y + ub.y);
  } else if (fit.inward_normal) {
    const Approx e = approx(*fit.inward_normal);
    normal = unit_d(e.x, e.y);
  }
  fit.inward_normal_approx = {normal.x, normal.y};
  if (n) {
    const Approx nd = approx(*n);
    fit.angle_degrees =
        fit.normal_matches
            ? 0.0
            : std::abs(std::atan2(nd.x * normal.y - nd.y * normal.x, nd.x * normal.x + nd.y * normal.y)) * 180 / M_PI;
  }
  return fit;
}

}  // namespace fixel
