#include "fixel/sustained.h"

#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/region_target.h"

namespace fixel {

namespace internal {

// Everything in the part's body frame at q*, where a finger's push wrench
// (d, (b − c) ⊗ d) is rational: only J's own data lives in Q(√d).
struct SustainedData {
  Q2 cos, sin;             // the rotation of q*
  std::vector<V3> K_rows;  // w ∈ int K ⇔ a·w > 0 for every row (K = −cone(W_n*))
  std::vector<V3> K_rays;  // −W_n,i*
  V3 normaliser;           // Σ K_rows: positive on K \ {0}
  struct Jam {
    std::array<int, 2> fixels;
    std::vector<V3> gens;    // −(W_n ± μ W_t) of both fixels
    std::vector<V3> facets;  // closed rows: w ∈ jam cone ⇔ a·w ≥ 0 for all
  };
  std::vector<Jam> jams;
  struct Piece {
    std::vector<V3> closed, strict, rays;
  };
  std::vector<Piece> pieces;
};

namespace {

// a·x ≥ b (or > b when strict), over Q(√d).
struct Row {
  V3 a;
  Q2 b;
  bool strict = false;
};

constexpr std::size_t kMaxRows = 200000;  // bounds Fourier–Motzkin on any input

// Exact feasibility of a system in three unknowns by Fourier–Motzkin with
// strictness tracking (docs/theory.md §10). Small systems only.
bool feasible(std::vector<Row> rows) {
  for (int j = 2; j >= -1; --j) {
    std::vector<Row> pos, neg, next;
    for (auto& r : rows) {
      bool zero = true;
      for (int k = 0; k < 3; ++k) zero = zero && sign(r.a[k]) == 0;
      if (zero) {  // 0 ≥ b or 0 > b decides itself
        const int sb = sign(r.b);
        if (r.strict ? sb >= 0 : sb > 0) return false;
        continue;
      }
      if (j < 0) {
        next.push_back(r);
        continue;
      }
      const int s = sign(r.a[j]);
      (s > 0 ? pos : (s < 0 ? neg : next)).push_back(r);
    }
    if (j < 0) return true;
    if (pos.size() * neg.size() + next.size() > kMaxRows)
      throw Error("sustained set: Fourier-Motzkin exceeded " + std::to_string(kMaxRows) + " rows");
    for (const auto& P : pos)
      for (const auto& N : neg) {
        const Q2 wp = -N.a[j], wn = P.a[j];  // both > 0
        Row r;
        for (int k = 0; k < 3; ++k) r.a[k] = wp * P.a[k] + wn * N.a[k];
        r.a[j] = Q2(0);
        r.b = wp * P.b + wn * N.b;
        r.strict = P.strict || N.strict;
        next.push_back(r);
      }
    rows = std::move(next);
  }
  return true;
}

bool parallel_same(const V3& a, const V3& b) { return is_zero(cross(a, b)) && sign(dot(a, b)) > 0; }

void add_unique(std::vector<V3>& out, const V3& a) {
  for (const auto& q : out)
    if (parallel_same(q, a)) return;
  out.push_back(a);
}

// +1 if a·g >= 0 for all g, −1 if <= 0 for all, 0 otherwise.
int supporting_side(const V3& a, const std::vector<V3>& gens) {
  bool nonneg = true, nonpos = true;
  for (const auto& g : gens) {
    const int s = sign(dot(a, g));
    nonneg = nonneg && s >= 0;
    nonpos = nonpos && s <= 0;
  }
  return nonneg ? 1 : (nonpos ? -1 : 0);
}

void add_if_supporting(std::vector<V3>& out, const V3& a, const std::vector<V3>& gens) {
  const int side = supporting_side(a, gens);
  if (side != 0) add_unique(out, side > 0 ? a : neg(a));
}

// Closed rows of cone(gens) ⊂ R³ (rank 2 or 3; rank 2 gets its plane as two
// opposite rows).
std::vector<V3> facets_of(const std::vector<V3>& gens) {
  std::vector<V3> out;
  V3 n{Q2(0), Q2(0), Q2(0)};
  for (std::size_t i = 0; i < gens.size() && is_zero(n); ++i)
    for (std::size_t j = i + 1; j < gens.size() && is_zero(n); ++j) n = cross(gens[i], gens[j]);
  if (is_zero(n)) throw Error("sustained set: a jam cone of rank < 2 (internal invariant broken)");
  bool full = false;
  for (const auto& g : gens) full = full || sign(dot(n, g)) != 0;
  if (!full) {
    out.push_back(n);
    out.push_back(neg(n));
    for (const auto& g : gens) add_if_supporting(out, cross(n, g), gens);
    return out;
  }
  for (std::size_t i = 0; i < gens.size(); ++i)
    for (std::size_t j = i + 1; j < gens.size(); ++j) {
      const V3 c = cross(gens[i], gens[j]);
      if (!is_zero(c)) add_if_supporting(out, c, gens);
    }
  return out;
}

bool satisfies(const V3& x, const std::vector<V3>& closed, const std::vector<V3>& strict) {
  for (const auto& a : closed)
    if (sign(dot(a, x)) < 0) return false;
  for (const auto& a : strict)
    if (sign(dot(a, x)) <= 0) return false;
  return true;
}

// Extreme rays of the pointed cone {a·x ≥ 0 for every row}.
std::vector<V3> rays_of(const std::vector<V3>& rows) {
  std::vector<V3> out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j) {
      const V3 c = cross(rows[i], rows[j]);
      if (is_zero(c)) continue;
      for (const V3& r : {c, neg(c)})
        if (satisfies(r, rows, {})) add_unique(out, r);
    }
  return out;
}

std::vector<Row> homogeneous(const std::vector<V3>& rows, bool strict) {
  std::vector<Row> out;
  for (const auto& a : rows) out.push_back({a, Q2(0), strict});
  return out;
}

// J's convex pieces: int K minus each jam cone, choosing for each jam cone
// the first facet it violates (so the pieces are disjoint); empty ones are
// pruned as soon as a prefix is infeasible.
void enumerate_pieces(SustainedData& d, std::size_t jam, std::vector<V3>& closed, std::vector<V3>& strict) {
  std::vector<Row> rows = homogeneous(d.K_rows, true);
  for (const auto& r : homogeneous(closed, false)) rows.push_back(r);
  for (const auto& r : homogeneous(strict, true)) rows.push_back(r);
  if (!feasible(rows)) return;
  if (jam == d.jams.size()) {
    SustainedData::Piece p;
    p.closed = closed;
    p.strict = d.K_rows;
    for (const auto& a : strict) p.strict.push_back(a);
    std::vector<V3> all = p.closed;
    for (const auto& a : p.strict) all.push_back(a);
    p.rays = rays_of(all);
    d.pieces.push_back(std::move(p));
    return;
  }
  const auto& facets = d.jams[jam].facets;
  for (std::size_t r = 0; r < facets.size(); ++r) {
    const std::size_t c0 = closed.size();
    for (std::size_t s = 0; s < r; ++s) closed.push_back(facets[s]);
    strict.push_back(neg(facets[r]));  // violate row r: a·x < 0
    enumerate_pieces(d, jam + 1, closed, strict);
    strict.pop_back();
    closed.resize(c0);
  }
}

V3 rotate_to_world(const SustainedData& d, const V3& v_B) {
  return {d.cos * v_B[0] - d.sin * v_B[1], d.sin * v_B[0] + d.cos * v_B[1], v_B[2]};
}

std::array<QuadraticIrrational, 3> world_public(const SustainedData& d, const V3& v_B) {
  const V3 w = rotate_to_world(d, v_B);
  return {internal::to_public(w[0]), internal::to_public(w[1]), internal::to_public(w[2])};
}

AlgebraicCone cone_public(const SustainedData& d, const std::vector<V3>& rays, const std::vector<V3>& closed,
                          const std::vector<V3>& strict) {
  AlgebraicCone out;
  for (const auto& r : rays) out.rays.push_back(world_public(d, r));
  for (const auto& a : closed) out.closed.push_back(world_public(d, a));
  for (const auto& a : strict) out.strict.push_back(world_public(d, a));
  return out;
}

bool in_jam(const SustainedData::Jam& jam, const V3& w) { return satisfies(w, jam.facets, {}); }

bool contains_body(const SustainedData& d, const V3& w_B) {
  if (!satisfies(w_B, {}, d.K_rows)) return false;
  for (const auto& jam : d.jams)
    if (in_jam(jam, w_B)) return false;
  return true;
}

std::string fixel_name(int i) { return "fixels[" + std::to_string(i) + "]"; }

// The J target of the region (all tests exact in Q(√d)).
class SustainedTarget final : public RegionTarget {
 public:
  explicit SustainedTarget(std::shared_ptr<const SustainedData> d) : d_(std::move(d)) {}
  const char* push_model() const override { return "sustained"; }

  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2*, const Vec2*, RegionInterval* detail) override {
    std::vector<V3> g;
    for (const auto& v : gens) g.push_back(lift(v));
    for (const auto& x : g)
      if (!satisfies(x, {}, d_->K_rows)) return false;
    std::vector<V3> cone_rows;
    bool have_rows = false;
    for (const auto& jam : d_->jams) {
      // Cheap certificate first: one facet of the jam cone with the whole cone strictly outside.
      bool separated = false;
      for (const auto& a : jam.facets) {
        bool all_out = true;
        for (const auto& x : g) all_out = all_out && sign(dot(a, x)) < 0;
        if (all_out) {
          separated = true;
          break;
        }
      }
      if (separated) continue;
      if (!have_rows) {
        for (const auto& a : cone_facet_normals(gens, 3)) cone_rows.push_back(lift(a));
        have_rows = true;
      }
      if (stats) ++stats->lp_tests;
      std::vector<Row> rows = homogeneous(cone_rows, false);
      for (const auto& r : homogeneous(jam.facets, false)) rows.push_back(r);
      rows.push_back({d_->normaliser, Q2(1), false});
      if (feasible(rows)) return false;
    }
    if (detail) {
      detail->half_line = true;  // J is a cone: any magnitude
      detail->magnitudes = Magnitudes{};
    }
    return true;
  }

  bool misses(const std::vector<VectorQ>& gens) override {
    std::vector<V3> g;
    for (const auto& v : gens) g.push_back(lift(v));
    for (const auto& a : d_->K_rows) {
      bool outside = true;
      for (const auto& x : g) outside = outside && sign(dot(a, x)) <= 0;
      if (outside) return true;
    }
    for (const auto& jam : d_->jams) {
      bool inside = true;
      for (const auto& x : g) inside = inside && in_jam(jam, x);
      if (inside) return true;
    }
    if (stats) ++stats->lp_tests;
    std::vector<V3> cone_rows;
    for (const auto& a : cone_facet_normals(gens, 3)) cone_rows.push_back(lift(a));
    std::vector<Row> rows = homogeneous(cone_rows, false);
    for (const auto& r : homogeneous(d_->K_rows, true)) rows.push_back(r);
    return !feasible(rows);
  }

 private:
  std::shared_ptr<const SustainedData> d_;
};

}  // namespace

}  // namespace internal

std::unique_ptr<RegionTarget> sustained_target(const SustainedSet& J) {
  if (!J.data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  return std::make_unique<internal::SustainedTarget>(J.data);
}

using internal::Q2;
using internal::V3;

namespace {

V3 to_body(const internal::SustainedData& d, const VectorQ& w_W) {
  if (w_W.size() != 3)
    throw InputError("wrench", std::to_string(w_W.size()) + " components", "must have 3 (fx, fy, moment)");
  const Q2 fx(w_W[0]), fy(w_W[1]);
  return {d.cos * fx + d.sin * fy, -d.sin * fx + d.cos * fy, Q2(w_W[2])};
}

}  // namespace

bool SustainedSet::contains(const VectorQ& w_W) const {
  if (!data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  return internal::contains_body(*data, to_body(*data, w_W));
}

std::string SustainedSet::why_not(const VectorQ& w_W) const {
  if (!data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  const V3 w = to_body(*data, w_W);
  if (!internal::satisfies(w, {}, data->K_rows))
    return "can escape: -w is not strictly inside cone(W_n*), so the push does not drive the part into its seat";
  for (const auto& jam : data->jams)
    if (internal::in_jam(jam, w))
      return internal::fixel_name(jam.fixels[0]) + " and " + internal::fixel_name(jam.fixels[1]) +
             " can hold the part at rest with friction under this push (it can jam short of the seat)";
  return "";
}

SustainedSet sustained_set(const Scene& scene) {
  if (scene.body.dof != 3) throw SceneError("body.dof", "2", "the sustained-push set needs a rigid body (dof 3)");
  SustainedSet J;
  J.pose = seated_pose(scene);
  auto d = std::make_shared<internal::SustainedData>();
  d->cos = internal::from_public((*J.pose.exact)[2]);
  d->sin = internal::from_public((*J.pose.exact)[3]);
  const int nc = scene.num_contacts();
  const Vec2& c = scene.body.p_AoCm_A;
  std::vector<V3> Wn, Wt;
  for (int i = 0; i < nc; ++i) {
    const Q2 rx = internal::from_public(J.pose.p_BoG_B[i][0]) - Q2(c.x);
    const Q2 ry = internal::from_public(J.pose.p_BoG_B[i][1]) - Q2(c.y);
    const Vec2& n = J.pose.n_B[i];
    const Vec2 t{-n.y, n.x};
    Wn.push_back({Q2(n.x), Q2(n.y), rx * Q2(n.y) - ry * Q2(n.x)});
    Wt.push_back({Q2(t.x), Q2(t.y), rx * Q2(t.y) - ry * Q2(t.x)});
    J.mu.push_back(scene.fixels[i].mu_upper());
  }
  if (nc != 3) throw SceneError("fixels", std::to_string(nc) + " fixels", "the sustained-push set needs exactly 3");
  const Q2 det = internal::dot(Wn[0], internal::cross(Wn[1], Wn[2]));
  if (internal::sign(det) == 0)
    throw SceneError("fixels", "", "make W_n* singular at the seated pose: the seat is degenerate");
  const int sd = internal::sign(det);
  for (int i = 0; i < 3; ++i) {
    V3 row = internal::cross(Wn[(i + 1) % 3], Wn[(i + 2) % 3]);  // row i of adj(W_n*)
    if (sd > 0) row = internal::neg(row);                        // a_i = −sign(det) adj_i
    d->K_rows.push_back(row);
    d->K_rays.push_back(internal::neg(Wn[i]));
  }
  d->normaliser = {d->K_rows[0][0] + d->K_rows[1][0] + d->K_rows[2][0],
                   d->K_rows[0][1] + d->K_rows[1][1] + d->K_rows[2][1],
                   d->K_rows[0][2] + d->K_rows[1][2] + d->K_rows[2][2]};
  for (int i = 0; i < nc; ++i)
    for (int j = i + 1; j < nc; ++j) {
      internal::SustainedData::Jam jam;
      jam.fixels = {i, j};
      for (int k : {i, j}) {
        const Q2 mu(J.mu[k]);
        for (int s : {1, -1}) {
          if (s == -1 && J.mu[k] == 0) break;
          V3 g;
          for (int m = 0; m < 3; ++m) g[m] = -(Wn[k][m] + Q2(s) * mu * Wt[k][m]);
          jam.gens.push_back(g);
        }
      }
      jam.facets = internal::facets_of(jam.gens);
      d->jams.push_back(std::move(jam));
    }
  std::vector<V3> closed, strict;
  internal::enumerate_pieces(*d, 0, closed, strict);

  J.cone = internal::cone_public(*d, d->K_rays, {}, d->K_rows);
  for (const auto& jam : d->jams)
    J.jam_cones.push_back(JamCone{jam.fixels, internal::cone_public(*d, jam.gens, jam.facets, {})});
  for (const auto& p : d->pieces) J.pieces.push_back(internal::cone_public(*d, p.rays, p.closed, p.strict));
  J.empty = d->pieces.empty();
  // Strong stability holds on all of J by the theorem of docs/theory.md §10
  // ((a) forces zero acceleration, (b) forces every contact to carry load).
  J.strongly_stable = true;
  if (J.empty) {
    // Which pairs can hold some push that drives the part into its seat.
    std::vector<std::string> holders;
    for (const auto& jam : d->jams) {
      bool covers = true;
      for (const auto& r : d->K_rays) covers = covers && internal::in_jam(jam, r);
      if (covers) {
        J.empty_reason = "every push direction that drives the part into its seat can be held at rest by " +
                         internal::fixel_name(jam.fixels[0]) + " and " + internal::fixel_name(jam.fixels[1]) +
                         " with friction";
        break;
      }
      std::vector<internal::Row> rows = internal::homogeneous(d->K_rows, true);
      for (const auto& r : internal::homogeneous(jam.facets, false)) rows.push_back(r);
      if (internal::feasible(rows))
        holders.push_back("(" + internal::fixel_name(jam.fixels[0]) + ", " + internal::fixel_name(jam.fixels[1]) + ")");
    }
    if (J.empty_reason.empty()) {
      std::string list;
      for (std::size_t k = 0; k < holders.size(); ++k) list += (k ? ", " : "") + holders[k];
      J.empty_reason = "the pairs " + list +
                       " can together hold every push direction that drives the part into its seat, with friction";
    }
  }
  J.data = d;
  return J;
}

}  // namespace fixel
