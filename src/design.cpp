// Fixture design: candidates, the exact filters and scores of one layout,
// batches of layouts, and the oneTBB thread pool (docs/design.md). TBB is
// used in this file only.
#include "fixel/design.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <set>
#include <utility>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"

namespace fixel {

namespace {

constexpr long kMaxCandidates = 10000;
constexpr int kMaxJobs = 256;
constexpr long kBatch = 8;  // triples per unit of work of the thread pool

const Boundary& boundary_of(const Scene& part) {
  if (!part.body.boundary) throw SceneError("body.boundary", "", "is missing: fixture design needs the part's outline");
  return *part.body.boundary;
}

// The normal wrench (d, r ⊗ d) of a push or contact at `point` along `d`.
VectorQ wrench_at(const Scene& part, const Vec2& point, const Vec2& d) {
  return contact_wrench(sub(point, part.body.p_AoCm_A), d, 3);
}

// Rows a_k with w ∈ int K ⇔ a_k · w > 0 for every k, where
// K = {w : −w ∈ int cone(W_n)} (docs/theory.md §10.2); none if W_n is singular.
std::optional<std::array<VectorQ, 3>> k_rows(const std::array<VectorQ, 3>& Wn) {
  auto cross = [](const VectorQ& a, const VectorQ& b) {
    VectorQ c(3);
    c << a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0];
    return c;
  };
  const Rational det = Wn[0].dot(cross(Wn[1], Wn[2]));
  if (det == 0) return std::nullopt;
  std::array<VectorQ, 3> rows;
  for (int i = 0; i < 3; ++i) {
    rows[i] = cross(Wn[(i + 1) % 3], Wn[(i + 2) % 3]);  // row i of adj(W_n)
    if (det > 0) rows[i] = -rows[i];
  }
  return rows;
}

bool in_open_k(const std::array<VectorQ, 3>& rows, const VectorQ& w) {
  for (const auto& a : rows)
    if (a.dot(w) <= 0) return false;
  return true;
}

// The target "−w strictly inside cone(W_n)" alone: with a frictionless
// finger, a point is IN when its push and the three fixels' normal wrenches
// are in form closure. `misses` is conservative (one separating row), so an
// undecided stretch stays PARTIAL and is never counted as OUT.
class FormClosureTarget final : public RegionTarget {
 public:
  explicit FormClosureTarget(const std::array<VectorQ, 3>& rows) : rows_(rows) {}
  const char* push_model() const override { return "form closure"; }
  const char* name() const override { return "K"; }
  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2*, const Vec2*, RegionInterval* detail) override {
    for (const auto& g : gens)
      if (!in_open_k(rows_, g)) return false;
    if (detail) detail->half_line = true;
    return true;
  }
  bool misses(const std::vector<VectorQ>& gens) override {
    for (const auto& a : rows_) {
      bool outside = true;
      for (const auto& g : gens) outside = outside && a.dot(g) <= 0;
      if (outside) return true;
    }
    return false;
  }

 private:
  std::array<VectorQ, 3> rows_;
};

Rational total_length(const Boundary& b) {
  Rational total = 0;
  for (const auto& c : b.curves) total += c.u_end() - c.u_begin();
  return total;
}

Rational in_fraction(const Region& r, const Rational& total) {
  Rational in = 0;
  for (const auto& iv : r.intervals)
    if (iv.status == RegionStatus::kIn) in += iv.u1 - iv.u0;
  return in / total;
}

RegionOptions region_options(const DesignOptions& o, const Rational& pusher_mu) {
  RegionOptions ro;
  ro.resolution = o.resolution;
  ro.pusher_mu = pusher_mu;
  return ro;
}

// Solid angle (fraction of the sphere) of J's pieces, with the moment scaled
// by 1/ρ (ρ the radius of gyration) so that force and moment weigh alike.
// Display only: doubles.
double j_width(const Scene& part, const SustainedSet& J) {
  const double rho = std::sqrt(to_double(part.body.inertia) / to_double(part.body.mass));
  double total = 0;
  for (const auto& piece : J.pieces) {
    std::vector<std::array<double, 3>> rays;
    for (const auto& r : piece.rays) {
      std::array<double, 3> v{r[0].approx(), r[1].approx(), r[2].approx() / rho};
      const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (n == 0) continue;
      for (auto& x : v) x /= n;
      rays.push_back(v);
    }
    if (rays.size() < 3) continue;
    std::array<double, 3> c{0, 0, 0};
    for (const auto& v : rays)
      for (int k = 0; k < 3; ++k) c[k] += v[k];
    // Order the rays around c, then sum the fan's spherical triangles
    // (Van Oosterom and Strackee).
    std::array<double, 3> e1{0, 0, 0}, e2;
    const int ax = std::abs(c[0]) < std::abs(c[1]) ? (std::abs(c[0]) < std::abs(c[2]) ? 0 : 2)
                                                   : (std::abs(c[1]) < std::abs(c[2]) ? 1 : 2);
    e1[ax] = 1;
    auto crs = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    auto dt = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    e1 = crs(c, e1);
    e2 = crs(c, e1);
    std::sort(rays.begin(), rays.end(), [&](const auto& a, const auto& b) {
      return std::atan2(dt(a, e2), dt(a, e1)) < std::atan2(dt(b, e2), dt(b, e1));
    });
    for (std::size_t k = 1; k + 1 < rays.size(); ++k) {
      const auto &a = rays[0], &b = rays[k], &d = rays[k + 1];
      const double num = std::abs(dt(a, crs(b, d)));
      const double den = 1 + dt(a, b) + dt(b, d) + dt(d, a);
      total += 2 * std::atan2(num, den);
    }
  }
  return total / (4 * M_PI);
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

// The sustained score of a scene with three fixels: J and, if J is not
// empty, the region against it.
void score_sustained(const Scene& scene, const DesignOptions& o, const Rational& total, DesignLayout& out) {
  const SustainedSet J = sustained_set(scene, false);  // strong stability: by the theorem
  out.sustained_empty = J.empty;
  if (J.empty) {
    out.sustained_score = Rational(0);
    out.j_width = 0;
    return;
  }
  out.j_width = j_width(scene, J);
  const auto target = sustained_target(J);
  out.sustained_score = in_fraction(compute_region(scene, *target, region_options(o, o.pusher_mu)), total);
}

void score_step(const Scene& scene, const DesignOptions& o, const Rational& total, DesignLayout& out) {
  const SeatingSet S = seating_set(scene);
  out.step_score = in_fraction(compute_region(scene, S, region_options(o, o.pusher_mu)), total);
}

enum class Verdict { kSingular, kNoFormClosure, kJEmpty, kScored };

// Filters and scores one triple by the ranking push model.
Verdict evaluate(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o,
                 const Rational& total, const std::array<int, 3>& f, DesignLayout& out) {
  std::array<VectorQ, 3> Wn;
  for (int i = 0; i < 3; ++i) Wn[i] = wrench_at(part, cands[f[i]].point, cands[f[i]].normal);
  const auto rows = k_rows(Wn);
  if (!rows) return Verdict::kSingular;
  const Scene scene = layout_scene(part, cands, f, o, false);
  // Form closure with a frictionless finger: a candidate whose push is in
  // int K proves it; otherwise the region against int K decides.
  bool closure = false;
  for (const auto& c : cands)
    if (in_open_k(*rows, wrench_at(part, c.point, c.normal))) {
      closure = true;
      break;
    }
  if (!closure) {
    FormClosureTarget target(*rows);
    const Region r = compute_region(scene, target, region_options(o, Rational(0)));
    for (const auto& iv : r.intervals) closure = closure || iv.status != RegionStatus::kOut;
  }
  if (!closure) return Verdict::kNoFormClosure;
  if (o.push == DesignPush::kSustained) {
    score_sustained(scene, o, total, out);
    out.score = *out.sustained_score;
    return *out.sustained_empty ? Verdict::kJEmpty : Verdict::kScored;
  }
  double err = 0;
  const Scene step = layout_scene(part, cands, f, o, true, &err);
  out.normal_angle_error = err;
  score_step(step, o, total, out);
  out.score = *out.step_score;
  return Verdict::kScored;
}

bool better(const DesignLayout& a, const DesignLayout& b) {
  if (a.score != b.score) return a.score > b.score;
  return a.index < b.index;
}

template <class OnLayout>
std::vector<DesignLayout> run_range(const Scene& part, const std::vector<DesignCandidate>& cands,
                                    const DesignOptions& o, long first, long count, DesignStats& stats,
                                    OnLayout&& on_layout) {
  const long n = static_cast<long>(cands.size());
  const Rational total = total_length(boundary_of(part));
  std::vector<DesignLayout> best;
  std::array<int, 3> f = triple_at(n, first);
  for (long k = 0; k < count; ++k) {
    DesignLayout layout;
    layout.fixels = f;
    layout.index = first + k;
    switch (evaluate(part, cands, o, total, f, layout)) {
      case Verdict::kSingular:
        ++stats.singular;
        break;
      case Verdict::kNoFormClosure:
        ++stats.no_form_closure;
        break;
      case Verdict::kJEmpty:
        ++stats.j_empty;
        best.push_back(std::move(layout));
        break;
      case Verdict::kScored:
        ++stats.regions;
        best.push_back(std::move(layout));
        break;
    }
    if (static_cast<int>(best.size()) > 2 * o.top) rank_layouts(best, o.top);
    on_layout();
    // Next triple in lexicographic order.
    if (k + 1 < count) {
      if (f[2] + 1 < n) {
        ++f[2];
      } else if (f[1] + 2 < n) {
        ++f[1];
        f[2] = f[1] + 1;
      } else {
        ++f[0];
        f[1] = f[0] + 1;
        f[2] = f[0] + 2;
      }
    }
  }
  rank_layouts(best, o.top);
  return best;
}

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

long triple_count(long n) { return n < 3 ? 0 : n * (n - 1) / 2 * (n - 2) / 3; }

std::array<int, 3> triple_at(long n, long index) {
  if (index < 0 || index >= triple_count(n))
    throw InputError("triple index", std::to_string(index), "is out of range for " + std::to_string(n) + " candidates");
  std::array<int, 3> f{};
  long r = index;
  int i = 0;
  for (;; ++i) {  // triples whose first entry is i: C(n − 1 − i, 2)
    const long m = n - 1 - i;
    const long c = m * (m - 1) / 2;
    if (r < c) break;
    r -= c;
  }
  int j = i + 1;
  for (;; ++j) {
    const long c = n - 1 - j;
    if (r < c) break;
    r -= c;
  }
  f = {i, j, static_cast<int>(j + 1 + r)};
  return f;
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

std::vector<DesignCandidate> boundary_candidates(const Scene& part, const std::optional<Rational>& spacing) {
  const Boundary& b = boundary_of(part);
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

void check_design(const Scene& part, const DesignOptions& o) {
  if (part.body.dof != 3) throw SceneError("body.dof", "2", "fixture design needs a rigid body (dof 3)");
  boundary_of(part);
  if (o.resolution <= 0) throw InputError("DesignOptions.resolution", to_string(o.resolution), "must be > 0");
  if (o.mu < 0) throw InputError("DesignOptions.mu", to_string(o.mu), "must be >= 0");
  if (o.mu_hi && *o.mu_hi < o.mu)
    throw InputError("DesignOptions.mu", to_string(o.mu) + "," + to_string(*o.mu_hi), "has lo > hi");
  if (o.pusher_mu < 0) throw InputError("DesignOptions.pusher_mu", to_string(o.pusher_mu), "must be >= 0");
  if (o.gap < 0) throw InputError("DesignOptions.gap", to_string(o.gap), "must be >= 0");
  if (o.top <= 0) throw InputError("DesignOptions.top", std::to_string(o.top), "must be > 0");
  if (o.jobs < 0 || o.jobs > kMaxJobs)
    throw InputError("DesignOptions.jobs", std::to_string(o.jobs), "must be between 0 (one per core) and 256");
  if (o.push == DesignPush::kStep && o.mu_hi)
    throw UnsupportedError("DesignOptions.mu", to_string(o.mu) + "," + to_string(*o.mu_hi),
                           "is an interval: the one-step ranking (--push step) needs one value");
}

Scene layout_scene(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f,
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

void rank_layouts(std::vector<DesignLayout>& layouts, int top) {
  std::sort(layouts.begin(), layouts.end(), better);
  if (top >= 0 && static_cast<int>(layouts.size()) > top) layouts.resize(top);
}

std::vector<DesignLayout> design_batch(const Scene& part, const std::vector<DesignCandidate>& cands,
                                       const DesignOptions& o, long first, long count, DesignStats& stats) {
  check_design(part, o);
  const long total = triple_count(static_cast<long>(cands.size()));
  if (first < 0 || count < 0 || first + count > total)
    throw InputError("batch", std::to_string(first) + "+" + std::to_string(count),
                     "is outside the " + std::to_string(total) + " triples");
  if (count == 0) return {};
  long done = 0;
  return run_range(part, cands, o, first, count, stats, [&] { poll(o.control, "design", ++done, count, "layouts"); });
}

void complete_layouts(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o,
                      std::vector<DesignLayout>& layouts) {
  const Rational total = total_length(boundary_of(part));
  for (auto& l : layouts) {
    try {
      if (!l.sustained_score) score_sustained(layout_scene(part, cands, l.fixels, o, false), o, total, l);
    } catch (const Error& e) {
      l.note += std::string(l.note.empty() ? "" : "; ") + "sustained score: " + e.what();
    }
    if (l.step_score) continue;
    if (o.mu_hi) {
      l.note += std::string(l.note.empty() ? "" : "; ") + "no one-step score: it needs one fixel mu, not an interval";
      continue;
    }
    try {
      double err = 0;
      const Scene step = layout_scene(part, cands, l.fixels, o, true, &err);
      l.normal_angle_error = err;
      score_step(step, o, total, l);
    } catch (const Error& e) {
      l.note += std::string(l.note.empty() ? "" : "; ") + "one-step score: " + e.what();
    }
  }
}

DesignResult design(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o) {
  check_design(part, o);
  const auto start = std::chrono::steady_clock::now();
  DesignResult result;
  result.candidates = cands;
  const long n = static_cast<long>(cands.size());
  result.stats.candidates = n;
  result.stats.triples = triple_count(n);
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1, tbb::info::default_concurrency());
  result.stats.jobs = jobs;
  if (n < 3) {
    result.no_layout = no_layout_reason(result.stats, 0);
    return result;
  }
  const long T = result.stats.triples;
  const long batches = (T + kBatch - 1) / kBatch;
  std::vector<std::vector<DesignLayout>> best(batches);
  std::vector<DesignStats> counts(batches);
  std::atomic<long> done{0};
  std::mutex poll_mutex;
  auto on_layout = [&] {
    const long d = ++done;
    if (!o.control) return;
    std::unique_lock<std::mutex> lock(poll_mutex, std::try_to_lock);
    if (lock.owns_lock()) o.control->poll("design", d, T, "layouts");
  };
  tbb::task_arena arena(jobs);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<long>(0, batches, 1), [&](const tbb::blocked_range<long>& r) {
      for (long b = r.begin(); b != r.end(); ++b) {
        const long first = b * kBatch, count = std::min(kBatch, T - first);
        best[b] = run_range(part, cands, o, first, count, counts[b], on_layout);
      }
    });
  });
  for (long b = 0; b < batches; ++b) {
    for (auto& l : best[b]) result.layouts.push_back(std::move(l));
    result.stats.singular += counts[b].singular;
    result.stats.no_form_closure += counts[b].no_form_closure;
    result.stats.j_empty += counts[b].j_empty;
    result.stats.regions += counts[b].regions;
  }
  rank_layouts(result.layouts, o.top);
  complete_layouts(part, cands, o, result.layouts);
  result.no_layout = no_layout_reason(result.stats, result.layouts.size());
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string no_layout_reason(const DesignStats& stats, std::size_t layouts) {
  if (stats.candidates < 3)
    return "only " + std::to_string(stats.candidates) + " candidate" + (stats.candidates == 1 ? "" : "s") +
           ": a layout needs three fixels";
  if (layouts > 0) return "";
  return "every one of the " + std::to_string(stats.triples) + " triples was dropped (" +
         std::to_string(stats.singular) + " with W_n singular, " + std::to_string(stats.no_form_closure) +
         " without form closure)";
}

std::optional<DesignLayout> shipped_layout(const Scene& scene, const DesignOptions& options) {
  if (scene.num_contacts() != 3) return std::nullopt;
  try {
    return score_scene_layout(scene, options);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

DesignLayout score_scene_layout(const Scene& scene, const DesignOptions& o) {
  check_design(scene, o);
  const Rational total = total_length(boundary_of(scene));
  Scene s = scene;
  for (auto& f : s.fixels) {
    f.mu = o.mu;
    f.mu_hi = o.mu_hi;
  }
  s.pusher_mu = o.pusher_mu;
  s.pusher_mu_hi.reset();
  DesignLayout out;
  out.index = -1;
  try {
    score_sustained(s, o, total, out);
  } catch (const InputError& e) {
    out.note = std::string("no sustained score: ") + e.what();
  }
  if (!o.mu_hi) {
    try {
      score_step(s, o, total, out);
    } catch (const InputError& e) {
      out.note += std::string(out.note.empty() ? "" : "; ") + "no one-step score: " + e.what();
    }
  }
  out.score = (o.push == DesignPush::kSustained ? out.sustained_score : out.step_score).value_or(Rational(0));
  return out;
}

Region layout_region(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f,
                     const DesignOptions& o) {
  if (o.push == DesignPush::kSustained) {
    const Scene s = layout_scene(part, cands, f, o, false);
    const SustainedSet J = sustained_set(s, false);
    const auto target = sustained_target(J);
    return compute_region(s, *target, region_options(o, o.pusher_mu));
  }
  const Scene s = layout_scene(part, cands, f, o, true);
  return compute_region(s, seating_set(s), region_options(o, o.pusher_mu));
}

}  // namespace fixel
