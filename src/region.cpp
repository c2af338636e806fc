#include "fixel/region.h"

#include <chrono>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/internal/exact_lp.h"
#include "fixel/lcp.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

Rational cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
Rational dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
bool is_zero(const Vec2& v) { return v.x == 0 && v.y == 0; }
Vec2 sub(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }

std::vector<EdgeFamily> families(const Rational& mu) {
  if (mu == 0) return {EdgeFamily::kNormal};
  return {EdgeFamily::kMinus, EdgeFamily::kPlus};
}

// Limiting tangent directions at the ends of a Bézier piece: the first
// non-zero forward difference P_k − P_0 (resp. P_p − P_k).
Vec2 start_tangent(const BezierPiece& p) {
  for (std::size_t k = 1; k < p.control.size(); ++k)
    if (!is_zero(sub(p.control[k], p.control[0]))) return sub(p.control[k], p.control[0]);
  return {0, 0};
}
Vec2 end_tangent(const BezierPiece& p) {
  const Vec2& last = p.control.back();
  for (std::size_t k = p.control.size() - 1; k-- > 0;)
    if (!is_zero(sub(last, p.control[k]))) return sub(last, p.control[k]);
  return {0, 0};
}

// A tangent discontinuity between consecutive pieces.
bool is_corner(const Vec2& t_in, const Vec2& t_out) { return cross(t_in, t_out) != 0 || dot(t_in, t_out) < 0; }

// Push directions at a point with incoming and outgoing tangents (equal at
// a smooth point): the extreme edge directions of all friction cones around
// the normals of the fan. False if they span π or more.
bool push_extremes(const Vec2& t_in, const Vec2& t_out, const Rational& mu, Vec2& first, Vec2& last) {
  std::vector<Vec2> dirs;
  for (auto f : families(mu)) {
    dirs.push_back(push_direction(t_in, f, mu));
    dirs.push_back(push_direction(t_out, f, mu));
  }
  return direction_extremes(dirs, first, last);
}

// Certified inner bound of the common Euclidean magnitudes (docs/theory.md
// §8): generators g_j with force parts f_j in cone(d_first, d_last) and
// exact T(g_j). Any m in the result has b0 + m w ∈ S for every wrench w of
// the cone whose force part is a unit vector.
Magnitudes common_magnitudes(const std::vector<VectorQ>& gens, const std::vector<Magnitudes>& T, const Vec2& d_first,
                             const Vec2& d_last) {
  Magnitudes m;
  m.empty = false;
  m.lo = 0;
  m.lo_closed = true;
  m.hi_closed = true;
  const Rational c = internal::cos_half_angle_lower(d_first, d_last);
  if (c <= 0) return Magnitudes{};
  for (std::size_t j = 0; j < gens.size(); ++j) {
    if (T[j].empty) return Magnitudes{};
    const Rational f2 = gens[j][0] * gens[j][0] + gens[j][1] * gens[j][1];
    const Rational lo = T[j].lo * internal::sqrt_upper(f2);
    if (lo > m.lo) m.lo = lo;
    m.lo_closed = m.lo_closed && T[j].lo_closed;
    if (T[j].hi) {
      // m·K must stay below hi_j |f_j|, K = 1/cos(Δ/2) <= 1/c.
      const Rational hi = *T[j].hi * internal::sqrt_lower(f2) * c;
      if (!m.hi || hi < *m.hi) m.hi = hi;
      m.hi_closed = m.hi_closed && T[j].hi_closed;
    }
  }
  if (m.hi && (*m.hi < m.lo || (*m.hi == m.lo && !(m.lo_closed && m.hi_closed)))) return Magnitudes{};
  return m;
}

struct Context {
  const Scene& scene;
  const SeatingSet& S;
  const VectorQ& b0;
  Rational mu;
  ConeMethod method;
  Rational resolution;
  RegionStats stats;
  const GuaranteedSet* G = nullptr;
  RunControl* control = nullptr;
};

bool cone_misses(Context& ctx, const std::vector<VectorQ>& gens);

// No ray of the cone (τ > 0) meets the convex piece Q: the set
// {μ >= 0 : b0 + Σ μ_j g_j ∈ Q} is empty (exact LP with strict rows). When
// b0 itself lies in Q (μ = 0) this cannot be certified this way.
bool cone_misses_piece(Context& ctx, const std::vector<VectorQ>& gens, const Polyhedron& Q) {
  if (Q.contains(ctx.b0)) return false;
  ++ctx.stats.lp_tests;
  const int n = static_cast<int>(gens.size());
  Polyhedron lifted;
  lifted.dim = n;
  auto lift = [&](const Halfspace& h) {
    VectorQ a(n);
    for (int j = 0; j < n; ++j) a[j] = h.a.dot(gens[j]);
    return Halfspace{a, h.c - h.a.dot(ctx.b0)};
  };
  for (const auto& h : Q.closed) lifted.closed.push_back(lift(h));
  for (const auto& h : Q.strict) lifted.strict.push_back(lift(h));
  for (int j = 0; j < n; ++j) lifted.closed.push_back({VectorQ::Unit(n, j), Rational(0)});
  return is_empty(lifted);
}

// Classification of a cone (generators with force directions in
// cone(d_first, d_last)) against the non-convex G.
RegionStatus classify_against_g(Context& ctx, const std::vector<VectorQ>& gens, const Vec2& d_first, const Vec2& d_last,
                                RegionInterval* out) {
  for (const auto& piece : ctx.G->pieces) {
    std::vector<Magnitudes> T;
    bool all = true;
    for (const auto& g : gens) {
      T.push_back(ray_magnitudes(piece, ctx.b0, g));
      all = all && !T.back().empty;
    }
    if (all) {  // the hit set of one convex piece is convex
      if (out) {
        out->magnitudes = common_magnitudes(gens, T, d_first, d_last);
        out->magnitude_set = {out->magnitudes};
        bool half = true;
        for (const auto& t : T) half = half && t.half_line();
        out->half_line = half;
      }
      return RegionStatus::kIn;
    }
  }
  // G is the disjoint union of its pieces: the cone misses G iff it misses
  // every piece.
  for (const auto& piece : ctx.G->pieces)
    if (!cone_misses_piece(ctx, gens, piece)) return RegionStatus::kPartial;
  return RegionStatus::kOut;
}

// Exact point test from the extreme push directions at lever arm r.
RegionStatus test_directions(Context& ctx, const Vec2& r, const Vec2& d_first, const Vec2& d_last, Magnitudes* out,
                             std::vector<Magnitudes>* set = nullptr) {
  ++ctx.stats.point_tests;
  std::vector<VectorQ> gens = {contact_wrench(r, d_first, 3), contact_wrench(r, d_last, 3)};
  if (ctx.G) {
    if (cross(d_first, d_last) == 0) {  // one ray: exact union of intervals
      const std::vector<Magnitudes> parts = ray_magnitudes(*ctx.G, ctx.S, ctx.b0, gens[0]);
      if (set) {
        // Report Euclidean |p| like every other magnitude: τ|d| with |d|
        // irrational, so each end is rounded inward (a certified subset).
        set->clear();
        const Rational d2 = d_first.x * d_first.x + d_first.y * d_first.y;
        for (const auto& t : parts) {
          Magnitudes m = t;
          m.lo = t.lo * internal::sqrt_upper(d2);
          if (t.hi) m.hi = *t.hi * internal::sqrt_lower(d2);
          if (m.hi && (*m.hi < m.lo || (*m.hi == m.lo && !(m.lo_closed && m.hi_closed)))) continue;
          set->push_back(m);
        }
      }
      if (out) *out = set && !set->empty() ? set->front() : Magnitudes{};
      return parts.empty() ? RegionStatus::kOut : RegionStatus::kIn;
    }
    RegionInterval tmp;
    const RegionStatus st = classify_against_g(ctx, gens, d_first, d_last, &tmp);
    if (out) *out = tmp.magnitudes;
    if (set) *set = tmp.magnitude_set;
    return st;
  }
  std::vector<Magnitudes> T;
  for (const auto& g : gens) {
    T.push_back(ray_magnitudes(ctx.S, ctx.b0, g));
    if (T.back().empty) {
      if (out) *out = Magnitudes{};
      return RegionStatus::kOut;
    }
  }
  if (out) *out = common_magnitudes(gens, T, d_first, d_last);
  return RegionStatus::kIn;
}

// The cone misses S − b0 except at 0: the LP max Σμ_j s.t. b0 + Σ μ_j g_j
// ∈ S, μ >= 0 is infeasible or has optimum 0. (No cap on Σμ: S is not a
// cone from b0, so a cap would also cap the push magnitude.)
bool cone_misses(Context& ctx, const std::vector<VectorQ>& gens) {
  ++ctx.stats.lp_tests;
  const int n = static_cast<int>(gens.size());
  std::vector<internal::LinearConstraint> rows;
  for (const auto& h : ctx.S.halfspaces) {
    VectorQ a(n);
    for (int j = 0; j < n; ++j) a[j] = h.a.dot(gens[j]);
    rows.push_back({a, internal::Relation::kGreaterEqual, h.c - h.a.dot(ctx.b0)});
  }
  for (int j = 0; j < n; ++j) rows.push_back({VectorQ::Unit(n, j), internal::Relation::kGreaterEqual, Rational(0)});
  const internal::LpResult lp = internal::solve_lp(n, rows, VectorQ(-VectorQ::Ones(n)));
  if (lp.status == internal::LpStatus::kInfeasible) return true;
  if (lp.status == internal::LpStatus::kUnbounded) return false;
  return lp.value == 0;
}

RegionInterval classify(Context& ctx, const BezierPiece& seg) {
  poll(ctx.control, "region", ctx.stats.cone_tests, 0, "segments classified");
  ++ctx.stats.cone_tests;
  RegionInterval out{seg.curve, seg.u0, seg.u1, RegionStatus::kPartial, false, Magnitudes{}, {}};
  // The tight cone needs no hull (min/max over all control points is the
  // same); the paper cone's ⊥-angle test wants the polygon's vertices.
  const SegmentBounds bounds = segment_bounds(seg, ctx.method == ConeMethod::kPaper);
  std::vector<WrenchCone> cones;
  for (auto f : families(ctx.mu)) {
    auto cone = segment_wrench_cone(bounds, ctx.scene.body.p_AoCm_A, f, ctx.mu, ctx.method, /*with_facets=*/false);
    if (!cone) return out;  // tangent or friction cone reaches π: split
    cones.push_back(std::move(*cone));
  }
  if (ctx.G) {
    const auto& gens = cones.front().generators;  // frictionless: one family
    Vec2 first, last;
    std::vector<Vec2> dirs;
    for (const auto& g : gens) dirs.push_back({g[0], g[1]});
    if (!direction_extremes(dirs, first, last)) return out;
    out.status = classify_against_g(ctx, gens, first, last, &out);
    return out;
  }
  bool all_hit = true, all_half = true;
  std::vector<VectorQ> gens;
  std::vector<Magnitudes> T;
  std::vector<bool> family_misses_somewhere;
  for (const auto& cone : cones) {
    bool misses = false;
    for (const auto& g : cone.generators) {
      gens.push_back(g);
      T.push_back(ray_magnitudes(ctx.S, ctx.b0, g));
      misses = misses || T.back().empty;
      all_half = all_half && T.back().half_line();
    }
    all_hit = all_hit && !misses;
    family_misses_somewhere.push_back(misses);
  }
  if (all_hit) {
    out.status = RegionStatus::kIn;
    out.half_line = all_half;
    Vec2 first, last;
    std::vector<Vec2> dirs;
    for (const auto& g : gens) dirs.push_back({g[0], g[1]});
    if (direction_extremes(dirs, first, last)) out.magnitudes = common_magnitudes(gens, T, first, last);
    return out;
  }
  for (std::size_t f = 0; f < cones.size(); ++f)
    if (family_misses_somewhere[f] && cone_misses(ctx, cones[f].generators)) {
      out.status = RegionStatus::kOut;
      return out;
    }
  return out;
}

void subdivide(Context& ctx, const BezierPiece& seg, int depth, std::vector<RegionInterval>& out) {
  RegionInterval r = classify(ctx, seg);
  ctx.stats.depth = std::max(ctx.stats.depth, depth);
  if (r.status != RegionStatus::kPartial || seg.u1 - seg.u0 <= ctx.resolution || depth >= 200) {
    if (r.status == RegionStatus::kPartial) ctx.stats.partial_length += seg.u1 - seg.u0;
    out.push_back(std::move(r));
    return;
  }
  const auto halves = seg.split(Rational(1, 2));
  subdivide(ctx, halves.first, depth + 1, out);
  subdivide(ctx, halves.second, depth + 1, out);
}

Magnitudes intersect(const Magnitudes& a, const Magnitudes& b) {
  if (a.empty || b.empty) return Magnitudes{};
  Magnitudes m = a;
  if (b.lo > m.lo || (b.lo == m.lo && !b.lo_closed)) {
    m.lo_closed = b.lo == m.lo ? (m.lo_closed && b.lo_closed) : b.lo_closed;
    m.lo = b.lo;
  }
  if (b.hi && (!m.hi || *b.hi < *m.hi || (*b.hi == *m.hi && !b.hi_closed))) {
    m.hi_closed = m.hi && *b.hi == *m.hi ? (m.hi_closed && b.hi_closed) : b.hi_closed;
    m.hi = b.hi;
  }
  if (m.hi && (*m.hi < m.lo || (*m.hi == m.lo && !(m.lo_closed && m.hi_closed)))) return Magnitudes{};
  return m;
}

std::vector<RegionInterval> merge(const std::vector<RegionInterval>& in) {
  std::vector<RegionInterval> out;
  for (const auto& r : in) {
    if (!out.empty() && out.back().curve == r.curve && out.back().status == r.status && out.back().u1 == r.u0) {
      out.back().u1 = r.u1;
      out.back().half_line = out.back().half_line && r.half_line;
      out.back().magnitudes = intersect(out.back().magnitudes, r.magnitudes);
      if (!out.back().magnitude_set.empty() && !r.magnitude_set.empty() && !out.back().magnitudes.empty)
        out.back().magnitude_set = {out.back().magnitudes};  // certified pieces intersect to one interval
      else
        out.back().magnitude_set.clear();
      continue;
    }
    out.push_back(r);
  }
  return out;
}

void check_inputs(const Scene& scene, const Rational& mu, const GuaranteedSet* G = nullptr) {
  if (G && mu != 0)
    throw UnsupportedError("--pusher-mu", to_string(mu),
                           "with --guaranteed is not supported: G is not convex, so the two friction edges hitting G "
                           "does not make every push direction between them hit G (use a frictionless pusher)");
  if (!scene.body.boundary)
    throw SceneError("body.boundary", "", "is missing: the pushing region needs the part's outline");
  if (scene.body.dof != 3) throw SceneError("body.dof", "2", "a point mass has no boundary to push on");
  if (mu < 0) throw InputError("--pusher-mu", to_string(mu), "must be >= 0");
}

// Tangents on both sides of every piece start (in loop order).
struct Join {
  Vec2 t_in, t_out;
  bool corner;
};
std::vector<Join> joins(const Boundary& b) {
  std::vector<Join> out;
  const std::size_t n = b.pieces.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 t_in = end_tangent(b.pieces[(k + n - 1) % n]), t_out = start_tangent(b.pieces[k]);
    out.push_back({t_in, t_out, is_corner(t_in, t_out)});
  }
  return out;
}

RegionStatus status_at(Context& ctx, const Boundary& b, const std::vector<Join>& js, int curve, const Rational& u,
                       Magnitudes* mags, std::vector<Magnitudes>* set = nullptr) {
  for (std::size_t k = 0; k < b.pieces.size(); ++k) {
    const BezierPiece& piece = b.pieces[k];
    if (piece.curve != curve) continue;
    const bool at_start = u == piece.u0, inside = u > piece.u0 && u < piece.u1;
    const bool at_curve_end = u == piece.u1 && (k + 1 == b.pieces.size() || b.pieces[k + 1].curve != curve);
    if (!at_start && !inside && !at_curve_end) continue;
    Vec2 t_in, t_out;
    Vec2 point;
    if (at_start || at_curve_end) {
      const Join& j = js[at_start ? k : (k + 1) % b.pieces.size()];
      t_in = j.t_in;
      t_out = j.t_out;
      point = at_start ? piece.control.front() : piece.control.back();
    } else {
      t_in = t_out = piece.derivative(piece.local(u));
      point = piece.point(piece.local(u));
    }
    if (is_zero(t_in) || is_zero(t_out)) return RegionStatus::kPartial;  // undefined normal (cusp)
    Vec2 first, last;
    if (!push_extremes(t_in, t_out, ctx.mu, first, last)) return RegionStatus::kPartial;  // fan of π or more
    return test_directions(ctx, sub(point, ctx.scene.body.p_AoCm_A), first, last, mags, set);
  }
  throw InputError("u", to_string(u), "is outside curve " + std::to_string(curve) + "'s parameter range");
}

}  // namespace

bool Magnitudes::contains(const Rational& x) const {
  if (empty) return false;
  if (x < lo || (x == lo && !lo_closed)) return false;
  if (hi && (x > *hi || (x == *hi && !hi_closed))) return false;
  return true;
}

std::string Magnitudes::describe() const {
  if (empty) return "empty";
  return std::string(lo_closed ? "[" : "(") + to_string(lo) + ", " + (hi ? to_string(*hi) : "inf") +
         (hi && hi_closed ? "]" : ")");
}

std::string to_string(RegionStatus status) {
  switch (status) {
    case RegionStatus::kIn:
      return "in";
    case RegionStatus::kOut:
      return "out";
    case RegionStatus::kPartial:
      return "partial";
  }
  return "?";
}

Magnitudes ray_magnitudes(const SeatingSet& S, const VectorQ& b0, const VectorQ& g) {
  Magnitudes m;
  m.empty = false;
  m.lo = 0;
  m.lo_closed = false;  // τ > 0
  for (const auto& h : S.halfspaces) {
    const Rational alpha = h.a.dot(g), beta = h.c - h.a.dot(b0);  // need τ α >= β
    if (alpha > 0) {
      const Rational v = beta / alpha;
      if (v > m.lo) {
        m.lo = v;
        m.lo_closed = true;
      }
    } else if (alpha < 0) {
      const Rational v = beta / alpha;
      if (!m.hi || v < *m.hi) {
        m.hi = v;
        m.hi_closed = true;
      }
    } else if (beta > 0) {
      return Magnitudes{};
    }
  }
  if (m.hi && (*m.hi < m.lo || (*m.hi == m.lo && !(m.lo_closed && m.hi_closed)))) return Magnitudes{};
  return m;
}

Region compute_region(const Scene& scene, const SeatingSet& S, const RegionOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Rational mu = options.pusher_mu.value_or(scene.pusher_mu);
  check_inputs(scene, mu, options.guaranteed);
  if (options.resolution <= 0) throw InputError("--resolution", to_string(options.resolution), "must be > 0");
  const Boundary& b = *scene.body.boundary;
  Context ctx{scene,
              S,
              scene.background_impulse,
              mu,
              options.cone,
              options.resolution,
              RegionStats{},
              options.guaranteed,
              options.control};
  const std::vector<Join> js = joins(b);
  std::vector<RegionInterval> raw;
  for (std::size_t k = 0; k < b.pieces.size(); ++k) {
    const BezierPiece& piece = b.pieces[k];
    if (js[k].corner) {
      RegionInterval corner{piece.curve, piece.u0, piece.u0, RegionStatus::kPartial, false, Magnitudes{}, {}};
      corner.status = status_at(ctx, b, js, piece.curve, piece.u0, &corner.magnitudes, &corner.magnitude_set);
      corner.half_line = corner.status == RegionStatus::kIn && corner.magnitudes.half_line();
      raw.push_back(corner);
    }
    subdivide(ctx, piece, 0, raw);
  }
  Region region;
  region.intervals = options.merge ? merge(raw) : raw;
  region.stats = ctx.stats;
  region.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return region;
}

RegionStatus point_status(const Scene& scene, const SeatingSet& S, int curve, const Rational& u, const Rational& mu,
                          Magnitudes* magnitudes, const GuaranteedSet* guaranteed) {
  check_inputs(scene, mu, guaranteed);
  Context ctx{scene, S, scene.background_impulse, mu, ConeMethod::kTight, Rational(1), RegionStats{}, guaranteed};
  return status_at(ctx, *scene.body.boundary, joins(*scene.body.boundary), curve, u, magnitudes);
}

Region sample_region(const Scene& scene, const SeatingSet& S, int points_per_curve, std::optional<Rational> pusher_mu,
                     const GuaranteedSet* guaranteed, RunControl* control) {
  const auto start = std::chrono::steady_clock::now();
  const Rational mu = pusher_mu.value_or(scene.pusher_mu);
  check_inputs(scene, mu, guaranteed);
  if (points_per_curve <= 0) throw InputError("--points", std::to_string(points_per_curve), "must be >= 1");
  const Boundary& b = *scene.body.boundary;
  Context ctx{scene, S, scene.background_impulse, mu, ConeMethod::kTight, Rational(1), RegionStats{}, guaranteed};
  const std::vector<Join> js = joins(b);
  const long total = static_cast<long>(b.curves.size()) * points_per_curve;
  Region region;
  for (std::size_t c = 0; c < b.curves.size(); ++c) {
    const Curve& curve = b.curves[c];
    for (int k = 0; k < points_per_curve; ++k) {
      poll(control, "sample", static_cast<long>(region.intervals.size()), total, "points");
      const Rational u = curve.u_begin() + (curve.u_end() - curve.u_begin()) * Rational(k, points_per_curve);
      RegionInterval r{static_cast<int>(c), u, u, RegionStatus::kPartial, false, Magnitudes{}, {}};
      r.status = status_at(ctx, b, js, static_cast<int>(c), u, &r.magnitudes, &r.magnitude_set);
      r.half_line = r.status == RegionStatus::kIn && r.magnitudes.half_line();
      region.intervals.push_back(r);
    }
  }
  region.stats = ctx.stats;
  region.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return region;
}

}  // namespace fixel
