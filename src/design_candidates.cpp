// Fixture design, candidates: the places on the part's outline where a
// fixel may touch it, and the scene of one layout of three of them.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "fixel/curve.h"
#include "fixel/design.h"
#include "fixel/error.h"
#include "fixel/internal/design_detail.h"

namespace fixel {

namespace internal {

const Boundary& boundary_of(const Scene& part) {
  if (!part.body.boundary) throw SceneError("body.boundary", "", "is missing: fixture design needs the part's outline");
  return *part.body.boundary;
}

Rational total_length(const Boundary& b) {
  Rational total = 0;
  for (const auto& c : b.curves) total += c.u_end() - c.u_begin();
  return total;
}

// A rational unit vector near the direction of n (exact when |n| is
// rational), from the rational point ((1−t²)/(1+t²), 2t/(1+t²)) of the
// circle with t = tan(φ/2) rounded to a multiple of 2^-24.
Vec2 unit_near(const Vec2& n, double* angle_error) {
  const Rational len2 = n.x * n.x + n.y * n.y;
  const Integer p = boost::multiprecision::numerator(len2), q = boost::multiprecision::denominator(len2);
  const Integer rp = boost::multiprecision::sqrt(p), rq = boost::multiprecision::sqrt(q);
  if (rp * rp == p && rq * rq == q) {
    const Rational len = Rational(rp) / Rational(rq);
    if (angle_error) *angle_error = 0;
    return {n.x / len, n.y / len};
  }
  const double phi = std::atan2(to_double(n.y), to_double(n.x));
  const bool flip = std::abs(phi) > M_PI / 2;  // keep |t| ≤ 1
  const double half = (flip ? (phi > 0 ? phi - M_PI : phi + M_PI) : phi) / 2;
  const Rational t(static_cast<long long>(std::llround(std::tan(half) * (1 << 24))), 1 << 24);
  Vec2 u{(1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)};
  if (flip) u = {-u.x, -u.y};
  if (angle_error) {
    const double got = std::atan2(to_double(u.y), to_double(u.x));
    double e = std::abs(got - phi);
    if (e > M_PI) e = 2 * M_PI - e;
    *angle_error = e;
  }
  return u;
}

}  // namespace internal

namespace {

constexpr long kMaxCandidates = 10000;

// Where on the loop (curve index, piece) u of curve k lies: the pieces
// before and after the point, in loop order.
std::pair<const BezierPiece*, const BezierPiece*> pieces_around(const Boundary& b, int curve, const Rational& u) {
  const int np = static_cast<int>(b.pieces.size());
  for (int i = 0; i < np; ++i) {
    const BezierPiece& p = b.pieces[i];
    if (p.curve != curve) continue;
    if (p.u0 <= u && u < p.u1) {
      const BezierPiece* left = &p;
      if (u == p.u0) left = &b.pieces[(i + np - 1) % np];
      return {left, &p};
    }
    if (u == p.u1 && (i + 1 == np || b.pieces[i + 1].curve != curve || b.pieces[i + 1].u0 != u))
      return {&p, &b.pieces[(i + 1) % np]};
  }
  return {nullptr, nullptr};
}

}  // namespace

using internal::boundary_of;
using internal::unit_near;

namespace {

void check_candidate(const Scene& part, const DesignCandidate& c, const std::string& field) {
  const DesignCandidate own = candidate_at(part, c.curve, c.u, field);
  if (!(own.point.x == c.point.x && own.point.y == c.point.y && own.normal.x == c.normal.x &&
        own.normal.y == c.normal.y))
    throw InputError(field, "curve " + std::to_string(c.curve) + ", u = " + to_string(c.u),
                     "is not this part's candidate: its point or normal is not the outline's there (make "
                     "candidates with boundary_candidates or candidate_at of this part)");
}

}  // namespace

void check_candidates(const Scene& part, const std::vector<DesignCandidate>& candidates) {
  for (std::size_t k = 0; k < candidates.size(); ++k)
    check_candidate(part, candidates[k], "candidates[" + std::to_string(k) + "]");
}

DesignCandidate candidate_at(const Scene& part, int curve, const Rational& u, const std::string& field) {
  const Boundary& b = boundary_of(part);
  const int nc = static_cast<int>(b.curves.size());
  if (curve < 0 || curve >= nc)
    throw InputError(field + ".curve", std::to_string(curve),
                     "is not a curve of the boundary (it has " + std::to_string(nc) + ")");
  const Curve& c = b.curves[curve];
  if (u < c.u_begin() || u > c.u_end())
    throw InputError(field + ".u", to_string(u),
                     "is off curve " + std::to_string(curve) + " (its parameter runs over [" + to_string(c.u_begin()) +
                         ", " + to_string(c.u_end()) + "])");
  const auto [left, right] = pieces_around(b, curve, u);
  if (!left || !right)
    throw InputError(field + ".u", to_string(u), "lies on no piece of curve " + std::to_string(curve));
  // A neighbouring piece that does not contain u touches the point at its end.
  const bool left_holds = left->curve == curve && left->u0 < u && u <= left->u1;
  const bool right_holds = right->curve == curve && right->u0 <= u && u < right->u1;
  const Vec2 tl = left->derivative(left_holds ? left->local(u) : Rational(1));
  const Rational s_right = right_holds ? right->local(u) : Rational(0);
  const Vec2 tr = right->derivative(s_right);
  if (is_zero(tl) || is_zero(tr))
    throw InputError(field + ".u", to_string(u), "is where the boundary's tangent vanishes: no normal there");
  if (cross(tl, tr) != 0 || dot(tl, tr) <= 0)
    throw InputError(field + ".u", to_string(u),
                     "is a corner of curve " + std::to_string(curve) + ": the boundary has no single normal there");
  DesignCandidate d;
  d.curve = curve;
  d.u = u;
  d.point = right->point(s_right);
  d.normal = {-tr.y, tr.x};
  return d;
}

void check_candidate_list(const std::vector<DesignCandidate>& candidates, const std::string& source) {
  if (candidates.size() > 10000)
    throw InputError(source, std::to_string(candidates.size()) + " entries", "is more than 10000");
  // Sorted by point (exact), equal points become neighbours: O(n log n).
  std::vector<std::size_t> order(candidates.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto before = [&](std::size_t i, std::size_t j) {
    const Vec2 &a = candidates[i].point, &b = candidates[j].point;
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return i < j;
  };
  std::sort(order.begin(), order.end(), before);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const DesignCandidate &first = candidates[order[k - 1]], &again = candidates[order[k]];
    if (first.point.x != again.point.x || first.point.y != again.point.y) continue;
    throw InputError(source + "[" + std::to_string(order[k]) + "]",
                     "curve " + std::to_string(again.curve) + ", u " + to_string(again.u),
                     "is the same boundary point as " + source + "[" + std::to_string(order[k - 1]) +
                         "]: a layout would put two fixels there");
  }
}

std::vector<DesignCandidate> boundary_candidates(const Scene& part, const std::optional<Rational>& spacing) {
  const Boundary& b = boundary_of(part);
  check_scene_values(part);
  if (spacing && *spacing <= 0) throw InputError("boundary_candidates(spacing)", to_string(*spacing), "must be > 0");
  // Arc length by chords of 128 points per piece (placement only).
  struct Sample {
    int curve;
    Rational u;
    double s;
  };
  std::vector<Sample> samples;
  constexpr int kPer = 128;
  double s = 0, px = 0, py = 0;
  for (const auto& piece : b.pieces)
    for (int j = 0; j <= kPer; ++j) {
      const Rational t(j, kPer);
      const Vec2 p = piece.point(t);
      const double x = to_double(p.x), y = to_double(p.y);
      if (!samples.empty()) s += std::hypot(x - px, y - py);
      px = x;
      py = y;
      samples.push_back({piece.curve, piece.u0 + t * (piece.u1 - piece.u0), s});
    }
  const double perimeter = s;
  const double step = spacing ? to_double(*spacing) : perimeter / 24;
  if (!(step > 0) || perimeter / step > kMaxCandidates)
    throw InputError("boundary_candidates(spacing)", spacing ? to_string(*spacing) : "default",
                     "gives more than " + std::to_string(kMaxCandidates) + " candidates on a boundary of length " +
                         std::to_string(perimeter));
  std::vector<DesignCandidate> out;
  std::set<std::pair<Rational, Rational>> seen;
  std::size_t at = 0;
  for (long k = 0;; ++k) {
    const double target = (static_cast<double>(k) + 0.5) * step;
    if (target >= perimeter) break;
    while (at + 1 < samples.size() && samples[at + 1].s < target) ++at;
    if (at + 1 >= samples.size()) break;
    const Sample &a = samples[at], &z = samples[at + 1];
    int curve = z.curve;
    double u = to_double(z.u);
    if (a.curve == z.curve && z.s > a.s)
      u = to_double(a.u) + (target - a.s) / (z.s - a.s) * (to_double(z.u) - to_double(a.u));
    const Curve& c = b.curves[curve];
    Rational ur(static_cast<long long>(std::llround(u * 1024)), 1024);
    ur = std::max(c.u_begin(), std::min(c.u_end(), ur));
    try {
      DesignCandidate d = candidate_at(part, curve, ur, "boundary_candidates(spacing)");
      if (seen.insert({d.point.x, d.point.y}).second) out.push_back(std::move(d));
    } catch (const InputError&) {
      // a corner or a vanishing tangent: no fixel there
    }
  }
  return out;
}

namespace internal {

Scene build_layout_scene(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f,
                         const DesignOptions& o, bool step, double* angle_error) {
  Scene s = part;
  s.fixels.clear();
  double worst = 0;
  for (int i : f) {
    Fixel fx;
    fx.p_AoF_A = cands.at(i).point;
    fx.mu = o.mu;
    if (!step) fx.mu_hi = o.mu_hi;
    if (step) {
      double e = 0;
      fx.n_A = unit_near(cands[i].normal, &e);
      worst = std::max(worst, e);
      fx.gap = o.gap;
    } else {
      fx.n_A = cands[i].normal;
      fx.gap = 0;
    }
    s.fixels.push_back(fx);
  }
  s.pusher_mu = o.pusher_mu;
  s.pusher_mu_hi.reset();
  if (angle_error) *angle_error = worst;
  return s;
}

}  // namespace internal

namespace internal {

void check_layout(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f) {
  for (int k = 0; k < 3; ++k)
    if (f[k] < 0 || f[k] >= static_cast<int>(cands.size()))
      throw InputError("layout[" + std::to_string(k) + "]", std::to_string(f[k]),
                       "is not a candidate index (there are " + std::to_string(cands.size()) + ")");
  // A list made for another part would be scored as if on this one.
  for (int k = 0; k < 3; ++k) {
    const DesignCandidate& c = cands[static_cast<std::size_t>(f[k])];
    check_candidate(part, c, "candidates[" + std::to_string(f[k]) + "]");
    for (int j = 0; j < k; ++j) {
      const Vec2& other = cands[static_cast<std::size_t>(f[j])].point;
      if (other.x == c.point.x && other.y == c.point.y)
        throw InputError("layout[" + std::to_string(k) + "]", std::to_string(f[k]),
                         "puts a second fixel at the point of layout[" + std::to_string(j) + "] (candidate " +
                             std::to_string(f[j]) + ")");
    }
  }
}

int curved_contacts(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f) {
  int n = 0;
  for (int i : f) {
    const DesignCandidate& c = cands[static_cast<std::size_t>(i)];
    // Both pieces that meet at the point, whichever curve names it: at a
    // join of a straight and a curved piece the part is curved on one side.
    const auto [left, right] = pieces_around(boundary_of(part), c.curve, c.u);
    n += (left && left->degree() > 1) || (right && right->degree() > 1);
  }
  return n;
}

}  // namespace internal

Scene layout_scene(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f,
                   const DesignOptions& o, bool step, double* angle_error) {
  internal::check_layout(part, cands, f);
  return internal::build_layout_scene(part, cands, f, o, step, angle_error);
}

Scene design_scene(const Scene& part, const std::vector<DesignCandidate>& candidates, const DesignLayout& layout,
                   int rank, const DesignOptions& o, double* angle_error) {
  if (rank < 1) throw InputError("rank", std::to_string(rank), "must be >= 1 (1 is the best layout)");
  for (int i : layout.fixels)
    if (i < 0 || i >= static_cast<int>(candidates.size()))
      throw InputError("layout", std::to_string(i),
                       "is not a candidate index (there are " + std::to_string(candidates.size()) + ")");
  const bool step = o.push == DesignPush::kStep;
  double worst = 0;
  Scene s = layout_scene(part, candidates, layout.fixels, o, step, &worst);
  // The description states the layout's score: it must be this part's
  // under these options (a layout of another part or run had its own).
  DesignLayout again;
  again.fixels = layout.fixels;
  internal::evaluate(part, candidates, o, internal::total_length(internal::boundary_of(part)), layout.fixels, again);
  if (again.score != layout.score)
    throw InputError("layout.score", to_string(layout.score),
                     "is not this layout's score on this part under these options (it scores " +
                         to_string(again.score) + " here): a layout of another part or of another run");
  if (o.pusher_mu_lo && *o.pusher_mu_lo < o.pusher_mu) {  // the scene keeps the interval it was judged over
    s.pusher_mu = *o.pusher_mu_lo;
    s.pusher_mu_hi = o.pusher_mu;
  }
  std::vector<int> rounded;
  for (int k = 0; k < 3; ++k) {
    Fixel& f = s.fixels[static_cast<std::size_t>(k)];
    const Vec2& normal = candidates[static_cast<std::size_t>(layout.fixels[k])].normal;
    if (!step) {
      double e = 0;
      f.n_A = internal::unit_near(normal, &e);
      worst = std::max(worst, e);
    }
    // Decided exactly: the unit vector is the candidate's direction or not.
    f.off_boundary = f.n_A.x * normal.y != f.n_A.y * normal.x;
    if (f.off_boundary) rounded.push_back(k);
  }
  if (rounded.empty()) worst = 0;
  s.name = (part.name.empty() ? std::string("part") : part.name) + "-layout-" + std::to_string(rank);
  std::string d = "Layout #" + std::to_string(rank) + " of fixel design on " +
                  (part.name.empty() ? std::string("the part") : part.name) + " (" + (step ? "one-step" : "sustained") +
                  " ranking, resolution " + to_string(o.resolution) + "): fixels at";
  for (int k = 0; k < 3; ++k) {
    const DesignCandidate& c = candidates[static_cast<std::size_t>(layout.fixels[k])];
    d += std::string(k == 0 ? " " : ", ") + "curve " + std::to_string(c.curve) + " u = " + to_string(c.u);
  }
  d += "; score " + to_string(layout.score) + " of the boundary's parameter length.";
  if (!rounded.empty()) {
    std::ostringstream angle;
    angle << std::setprecision(3) << worst;
    const bool one = rounded.size() == 1;
    d += one ? " The normal of fixel" : " The normals of fixels";
    for (std::size_t k = 0; k < rounded.size(); ++k) d += (k == 0 ? " " : ", ") + std::to_string(rounded[k]);
    d += std::string(one ? " has" : " have") + " irrational length: rounded to " +
         (one ? "a rational unit vector" : "rational unit vectors") + " (by at most " + angle.str() + " rad), so " +
         (one ? "it is" : "they are") + " marked off_boundary and this is a slightly different fixture.";
  }
  s.description = d;
  if (angle_error) *angle_error = worst;
  return s;
}

}  // namespace fixel
