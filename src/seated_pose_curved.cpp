// The seated pose for contacts on curved (B-spline) pieces: Newton in double
// for a candidate, then a certified enclosure by the Krawczyk test in
// outward-rounded interval arithmetic (docs/theory.md §10.1).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/internal/interval_arith.h"
#include "fixel/seated_pose.h"

namespace fixel::internal {

namespace {

constexpr int kUnknowns = 7;  // t_x, t_y, cos θ, sin θ, s_0, s_1, s_2

struct D2 {
  double x, y;
};

template <class T>
struct P2 {
  T x, y;
};

// De Casteljau on any arithmetic (double or interval).
template <class T>
P2<T> de_casteljau(std::vector<P2<T>> pts, const T& s) {
  for (std::size_t level = 1; level < pts.size(); ++level)
    for (std::size_t i = 0; i + level < pts.size(); ++i) {
      pts[i].x = pts[i].x + s * (pts[i + 1].x - pts[i].x);
      pts[i].y = pts[i].y + s * (pts[i + 1].y - pts[i].y);
    }
  return pts.front();
}

template <class T>
std::vector<P2<T>> hodograph(const std::vector<P2<T>>& pts) {
  std::vector<P2<T>> out;
  const T p(static_cast<double>(pts.size() - 1));
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    out.push_back({p * (pts[i + 1].x - pts[i].x), p * (pts[i + 1].y - pts[i].y)});
  return out;
}

struct Contact {
  int piece;
  std::vector<P2<double>> ctrl;
  std::vector<P2<IV>> ctrl_iv;
  std::vector<P2<double>> deriv;
  std::vector<P2<IV>> deriv_iv;
  P2<double> f;
  P2<IV> f_iv;
};

void load_piece(const Boundary& b, int k, Contact& c) {
  c.piece = k;
  c.ctrl.clear();
  c.ctrl_iv.clear();
  for (const auto& p : b.pieces[k].control) {
    c.ctrl.push_back({to_double(p.x), to_double(p.y)});
    c.ctrl_iv.push_back({enclose(p.x), enclose(p.y)});
  }
  c.deriv = hodograph(c.ctrl);
  c.deriv_iv = hodograph(c.ctrl_iv);
}

double dist2(const P2<double>& a, const P2<double>& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }

// The piece and local parameter of the boundary point nearest p (display-
// grade search; the seat itself is certified afterwards).
std::pair<int, double> locate(const Boundary& b, const P2<double>& p, double& best_d2) {
  best_d2 = std::numeric_limits<double>::infinity();
  int best_k = 0;
  double best_s = 0;
  for (std::size_t k = 0; k < b.pieces.size(); ++k) {
    Contact c;
    load_piece(b, static_cast<int>(k), c);
    for (int j = 0; j <= 64; ++j) {
      double s = j / 64.0;
      for (int it = 0; it < 30; ++it) {  // Newton on |B(s) − p|²
        const P2<double> q = de_casteljau(c.ctrl, s), d = de_casteljau(c.deriv, s);
        const double g = (q.x - p.x) * d.x + (q.y - p.y) * d.y, h = d.x * d.x + d.y * d.y;
        if (h <= 0) break;
        s = std::clamp(s - g / h, 0.0, 1.0);
      }
      const double d2 = dist2(de_casteljau(c.ctrl, s), p);
      if (d2 < best_d2) best_d2 = d2, best_k = static_cast<int>(k), best_s = s;
    }
  }
  return {best_k, best_s};
}

// A contact's data in arithmetic T: the double or the interval copy.
template <class T, class D, class I>
const auto& in(const D& as_double, const I& as_interval) {
  if constexpr (std::is_same_v<T, double>)
    return as_double;
  else
    return as_interval;
}

// F(z) and its Jacobian on any arithmetic (double or interval).
template <class T>
void residual(const std::vector<Contact>& cs, const P2<T>& cm, const std::array<T, kUnknowns>& z,
              std::array<T, kUnknowns>* F, std::array<std::array<T, kUnknowns>, kUnknowns>* J) {
  const T &tx = z[0], &ty = z[1], &c = z[2], &s = z[3];
  for (int i = 0; i < 3; ++i) {
    const auto& ctrl = in<T>(cs[i].ctrl, cs[i].ctrl_iv);
    const auto& deriv = in<T>(cs[i].deriv, cs[i].deriv_iv);
    const P2<T>& f = in<T>(cs[i].f, cs[i].f_iv);
    const P2<T> B = de_casteljau(ctrl, z[4 + i]), dB = de_casteljau(deriv, z[4 + i]);
    const T rx = B.x - cm.x, ry = B.y - cm.y;
    if (F) {
      (*F)[2 * i] = c * rx - s * ry + cm.x + tx - f.x;
      (*F)[2 * i + 1] = s * rx + c * ry + cm.y + ty - f.y;
    }
    if (J) {
      for (int k = 0; k < kUnknowns; ++k) (*J)[2 * i][k] = (*J)[2 * i + 1][k] = T(0.0);
      (*J)[2 * i][0] = T(1.0);
      (*J)[2 * i][2] = rx;
      (*J)[2 * i][3] = -ry;
      (*J)[2 * i][4 + i] = c * dB.x - s * dB.y;
      (*J)[2 * i + 1][1] = T(1.0);
      (*J)[2 * i + 1][2] = ry;
      (*J)[2 * i + 1][3] = rx;
      (*J)[2 * i + 1][4 + i] = s * dB.x + c * dB.y;
    }
  }
  if (F) (*F)[6] = c * c + s * s - T(1.0);
  if (J) {
    for (int k = 0; k < kUnknowns; ++k) (*J)[6][k] = T(0.0);
    (*J)[6][2] = T(2.0) * c;
    (*J)[6][3] = T(2.0) * s;
  }
}

// The Newton step −J(z)⁻¹ F(z) in double; F(z) is returned in `F`.
Eigen::Matrix<double, kUnknowns, 1> newton_step(const std::vector<Contact>& cs, const P2<double>& cm,
                                                const std::array<double, kUnknowns>& z,
                                                std::array<double, kUnknowns>& F) {
  std::array<std::array<double, kUnknowns>, kUnknowns> J;
  residual<double>(cs, cm, z, &F, &J);
  Eigen::Matrix<double, kUnknowns, kUnknowns> A;
  Eigen::Matrix<double, kUnknowns, 1> rhs;
  for (int r = 0; r < kUnknowns; ++r) {
    rhs[r] = -F[r];
    for (int k = 0; k < kUnknowns; ++k) A(r, k) = J[r][k];
  }
  return A.fullPivLu().solve(rhs);
}

std::string fixel_path(int i) { return "fixels[" + std::to_string(i) + "]"; }

}  // namespace

SeatedPose seated_pose_curved(const Scene& scene) {
  const Boundary& b = *scene.body.boundary;
  const int nc = scene.num_contacts();
  if (nc != 3) throw SceneError("fixels", std::to_string(nc) + " fixels", "the seated pose needs exactly 3");
  double size2 = 0;  // squared bounding-box diagonal of the control points
  {
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const auto& piece : b.pieces)
      for (const auto& p : piece.control) {
        const double x = to_double(p.x), y = to_double(p.y);
        xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
      }
    size2 = (xmax - xmin) * (xmax - xmin) + (ymax - ymin) * (ymax - ymin);
  }
  const P2<double> cm{to_double(scene.body.p_AoCm_A.x), to_double(scene.body.p_AoCm_A.y)};
  const P2<IV> cm_iv{enclose(scene.body.p_AoCm_A.x), enclose(scene.body.p_AoCm_A.y)};

  std::vector<Contact> cs(nc);
  std::array<double, kUnknowns> z{0, 0, 1, 0, 0, 0, 0};
  for (int i = 0; i < nc; ++i) {
    const Fixel& fx = scene.fixels[i];
    double d2 = 0;
    const auto [k, s] = locate(b, {to_double(fx.p_AoF_A.x), to_double(fx.p_AoF_A.y)}, d2);
    if (d2 > 1e-12 * size2)
      throw SceneError(fixel_path(i) + ".point", "(" + to_string(fx.p_AoF_A.x) + ", " + to_string(fx.p_AoF_A.y) + ")",
                       "is not on the part's boundary (distance " + std::to_string(std::sqrt(d2)) + " m)");
    load_piece(b, k, cs[i]);
    const Rational fxq = fx.p_AoF_A.x - fx.gap * fx.n_A.x, fyq = fx.p_AoF_A.y - fx.gap * fx.n_A.y;
    cs[i].f = {to_double(fxq), to_double(fyq)};
    cs[i].f_iv = {enclose(fxq), enclose(fyq)};
    z[4 + i] = s;
  }

  // Newton in double, damped so that no step grows the residual. A contact
  // that runs off its piece (beyond a small hysteresis, since fixels often
  // sit exactly on knots) moves to the neighbouring piece of the loop.
  const int npieces = static_cast<int>(b.pieces.size());
  auto norm = [](const std::array<double, kUnknowns>& F) {
    double n = 0;
    for (double f : F) n = std::max(n, std::abs(f));
    return n;
  };
  int switches = 0;
  auto switch_pieces = [&](double margin) {
    bool moved = false;
    for (int i = 0; i < nc; ++i) {
      if (z[4 + i] >= -margin && z[4 + i] <= 1 + margin) continue;
      if (++switches > 40)
        throw SceneError("fixels", "",
                         "have no seated pose near the scene pose: the search moved the contact points across "
                         "40 boundary pieces without settling (fixel " +
                             std::to_string(i) + " last)");
      const int next = (cs[i].piece + (z[4 + i] > 1 ? 1 : npieces - 1)) % npieces;
      const double old = z[4 + i];
      load_piece(b, next, cs[i]);
      z[4 + i] = old > 1 ? old - 1 : old + 1;
      moved = true;
    }
    return moved;
  };
  for (int it = 0; it < 400; ++it) {
    std::array<double, kUnknowns> F;
    const auto dz = newton_step(cs, cm, z, F);
    if (!dz.allFinite()) throw SceneError("fixels", "", "have no seated pose (singular contact conditions)");
    const double before = norm(F);
    double step = 1;
    // Stay near the piece: a Bézier polynomial means nothing far outside [0, 1],
    // and a rotation step above ~0.1 rad leaves the neighbourhood of the seat.
    for (int i = 0; i < nc; ++i) step = std::min(step, 0.25 / std::max(std::abs(dz[4 + i]), 1e-300));
    step = std::min(step, 0.1 / std::max(std::abs(dz[3]), 1e-300));
    std::array<double, kUnknowns> trial = z;
    for (int halve = 0; halve < 30; ++halve, step /= 2) {
      for (int k = 0; k < kUnknowns; ++k) trial[k] = z[k] + step * dz[k];
      std::array<double, kUnknowns> Ft;
      residual<double>(cs, cm, trial, &Ft, nullptr);
      if (norm(Ft) <= before || before < 1e-14) break;
    }
    if (step < 1e-9 && before > 1e-12)
      throw SceneError("fixels", "",
                       "have no seated pose near the scene pose: the contact conditions' residual stalls at " +
                           std::to_string(before) + " m (a fixel cannot touch the boundary there)");
    z = trial;
    const bool moved = switch_pieces(1e-9);
    if (!moved && step * dz.norm() < 1e-15) break;
  }
  switch_pieces(0);  // the enclosure must lie on the piece's own parameter range
  for (int it = 0; it < 20; ++it) {
    std::array<double, kUnknowns> F;
    const auto dz = newton_step(cs, cm, z, F);
    for (int k = 0; k < kUnknowns; ++k) z[k] += dz[k];
  }
  for (int i = 0; i < nc; ++i)
    if (!(z[4 + i] >= 0 && z[4 + i] <= 1))
      throw UnsupportedError(
          fixel_path(i), "",
          "touches the boundary at a knot at the seated pose: its enclosure is not implemented there");

  // Krawczyk: K(X) = z − Y F(z) + (I − Y J(X)) (X − z) ⊂ int X proves a unique root in X.
  std::array<IV, kUnknowns> X, K;
  bool certified = false;
  for (double radius : {1e-12, 1e-10, 1e-8, 1e-6}) {
    std::array<IV, kUnknowns> zi;
    for (int k = 0; k < kUnknowns; ++k) {
      zi[k] = IV(z[k]);
      const double r = radius * std::max(1.0, std::abs(z[k]));
      X[k] = IV(z[k] - r, z[k] + r);
    }
    for (int i = 0; i < nc; ++i) X[4 + i] = boost::numeric::intersect(X[4 + i], IV(0.0, 1.0));
    std::array<IV, kUnknowns> Fz;
    std::array<std::array<IV, kUnknowns>, kUnknowns> JX;
    residual<IV>(cs, cm_iv, zi, &Fz, nullptr);
    residual<IV>(cs, cm_iv, X, nullptr, &JX);
    Eigen::Matrix<double, kUnknowns, kUnknowns> mid;
    for (int r = 0; r < kUnknowns; ++r)
      for (int k = 0; k < kUnknowns; ++k) mid(r, k) = boost::numeric::median(JX[r][k]);
    const Eigen::Matrix<double, kUnknowns, kUnknowns> Y = mid.inverse();
    if (!Y.allFinite()) break;
    bool inside = true;
    for (int r = 0; r < kUnknowns; ++r) {
      IV acc = zi[r];
      for (int k = 0; k < kUnknowns; ++k) acc -= IV(Y(r, k)) * Fz[k];
      for (int k = 0; k < kUnknowns; ++k) {
        IV m = IV(r == k ? 1.0 : 0.0);
        for (int j = 0; j < kUnknowns; ++j) m -= IV(Y(r, j)) * JX[j][k];
        acc += m * (X[k] - zi[k]);
      }
      K[r] = acc;
      inside = inside && K[r].lower() > X[r].lower() && K[r].upper() < X[r].upper();
    }
    if (inside) {
      certified = true;
      for (int k = 0; k < kUnknowns; ++k) X[k] = boost::numeric::intersect(X[k], K[k]);
      break;
    }
  }
  if (!certified)
    throw UnsupportedError("fixels", "", "the seated pose on curved pieces could not be certified (Krawczyk failed)");

  SeatedPose q;
  const double th = std::atan2(z[3], z[2]);
  q.approx = {z[0], z[1], th};
  const double t1 = std::atan2(X[3].lower(), X[2].upper()), t2 = std::atan2(X[3].upper(), X[2].lower());
  q.enclosure = {std::array<double, 2>{X[0].lower(), X[0].upper()}, std::array<double, 2>{X[1].lower(), X[1].upper()},
                 std::array<double, 2>{std::min({t1, t2, th}), std::max({t1, t2, th})}};
  q.cos_sin_enclosure = {std::array<double, 2>{X[2].lower(), X[2].upper()},
                         std::array<double, 2>{X[3].lower(), X[3].upper()}};
  for (int i = 0; i < nc; ++i) {
    const P2<IV> g = de_casteljau(cs[i].ctrl_iv, X[4 + i]), d = de_casteljau(cs[i].deriv_iv, X[4 + i]);
    q.p_BoG_B_enclosure.push_back(
        {std::array<double, 2>{g.x.lower(), g.x.upper()}, std::array<double, 2>{g.y.lower(), g.y.upper()}});
    q.tangent_B_enclosure.push_back(
        {std::array<double, 2>{d.x.lower(), d.x.upper()}, std::array<double, 2>{d.y.lower(), d.y.upper()}});
    const BezierPiece& piece = b.pieces[cs[i].piece];
    q.contact_curve.push_back(piece.curve);
    q.contact_u.push_back(to_double(piece.u0) + to_double(piece.u1 - piece.u0) * z[4 + i]);
  }
  return q;
}

}  // namespace fixel::internal
