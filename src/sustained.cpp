#include "fixel/sustained.h"

#include <variant>

#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/cone3.h"
#include "fixel/region_target.h"

namespace fixel {

namespace internal {

// Everything in the part's body frame at q*, where a finger's push wrench
// (d, (b − c) ⊗ d) is rational: only J's own data lives in NT, exact Q(√d)
// for polyline contacts or certified intervals for curved ones.
template <class NT>
struct Data {
  using V = std::array<NT, 3>;
  NT cos, sin;            // the rotation of q*
  std::vector<V> K_rows;  // w ∈ int K ⇔ a·w > 0 for every row (K = −cone(W_n*))
  std::vector<V> K_rays;  // −W_n,i*
  V normaliser;           // Σ K_rows: positive on K \ {0}
  struct Jam {
    std::array<int, 2> fixels;
    std::vector<V> gens;    // −(W_n ± μ W_t) of both fixels
    std::vector<V> facets;  // closed rows: w ∈ jam cone ⇔ a·w ≥ 0 for all
  };
  std::vector<Jam> jams;
  struct Piece {
    std::vector<V> closed, strict, rays;
  };
  std::vector<Piece> pieces;
  bool pieces_decided = true;
};

struct SustainedData {
  std::variant<Data<Q2>, Data<IV>> data;
};

namespace {

// J's convex pieces: int K minus each jam cone, choosing for each jam cone
// the first facet it violates (so the pieces are disjoint); empty ones are
// pruned as soon as a prefix is infeasible.
template <class NT>
void enumerate_pieces(Data<NT>& d, std::size_t jam, std::vector<A3<NT>>& closed, std::vector<A3<NT>>& strict) {
  std::vector<Row<NT>> rows = homogeneous(d.K_rows, true);
  for (const auto& r : homogeneous(closed, false)) rows.push_back(r);
  for (const auto& r : homogeneous(strict, true)) rows.push_back(r);
  if (!feasible(rows)) return;
  if (jam == d.jams.size()) {
    typename Data<NT>::Piece p;
    p.closed = closed;
    p.strict = d.K_rows;
    for (const auto& a : strict) p.strict.push_back(a);
    std::vector<A3<NT>> all = p.closed;
    for (const auto& a : p.strict) all.push_back(a);
    p.rays = rays_of(all);
    d.pieces.push_back(std::move(p));
    return;
  }
  const auto& facets = d.jams[jam].facets;
  for (std::size_t r = 0; r < facets.size(); ++r) {
    const std::size_t c0 = closed.size();
    for (std::size_t s = 0; s < r; ++s) closed.push_back(facets[s]);
    strict.push_back(neg3(facets[r]));  // violate row r: a·x < 0
    enumerate_pieces(d, jam + 1, closed, strict);
    strict.pop_back();
    closed.resize(c0);
  }
}

template <class NT>
A3<NT> rotate_to_world(const Data<NT>& d, const A3<NT>& v_B) {
  return {d.cos * v_B[0] - d.sin * v_B[1], d.sin * v_B[0] + d.cos * v_B[1], v_B[2]};
}

void publish(const A3<Q2>& v, std::vector<std::array<QuadraticIrrational, 3>>& exact,
             std::vector<std::array<std::array<double, 2>, 3>>&) {
  exact.push_back({to_public(v[0]), to_public(v[1]), to_public(v[2])});
}
void publish(const A3<IV>& v, std::vector<std::array<QuadraticIrrational, 3>>&,
             std::vector<std::array<std::array<double, 2>, 3>>& enclosed) {
  std::array<std::array<double, 2>, 3> e;
  for (int k = 0; k < 3; ++k) e[k] = {v[k].lower(), v[k].upper()};
  enclosed.push_back(e);
}

template <class NT>
AlgebraicCone cone_public(const Data<NT>& d, const std::vector<A3<NT>>& rays, const std::vector<A3<NT>>& closed,
                          const std::vector<A3<NT>>& strict) {
  AlgebraicCone out;
  out.exact = std::is_same_v<NT, Q2>;
  for (const auto& r : rays) publish(rotate_to_world(d, r), out.rays, out.rays_enclosure);
  for (const auto& a : closed) publish(rotate_to_world(d, a), out.closed, out.closed_enclosure);
  for (const auto& a : strict) publish(rotate_to_world(d, a), out.strict, out.strict_enclosure);
  return out;
}

template <class NT>
bool in_jam(const typename Data<NT>::Jam& jam, const A3<NT>& w) {
  return satisfies(w, jam.facets, {});
}

std::string fixel_name(int i) { return "fixels[" + std::to_string(i) + "]"; }

template <class NT>
A3<NT> to_body(const Data<NT>& d, const VectorQ& w_W) {
  if (w_W.size() != 3)
    throw InputError("wrench", std::to_string(w_W.size()) + " components", "must have 3 (fx, fy, moment)");
  const A3<NT> w = lift3<NT>(w_W);
  return {d.cos * w[0] + d.sin * w[1], -d.sin * w[0] + d.cos * w[1], w[2]};
}

// "" when w_B is in J, else the reason.
template <class NT>
std::string reason(const Data<NT>& d, const A3<NT>& w) {
  if (!satisfies(w, {}, d.K_rows))
    return "can escape: -w is not strictly inside cone(W_n*), so the push does not drive the part into its seat";
  for (const auto& jam : d.jams)
    if (in_jam<NT>(jam, w))
      return fixel_name(jam.fixels[0]) + " and " + fixel_name(jam.fixels[1]) +
             " can hold the part at rest with friction under this push (it can jam short of the seat)";
  return "";
}

// The region's questions, answered for one number type (see RegionTarget).
template <class NT>
bool cone_in_J(const Data<NT>& d, const std::vector<VectorQ>& gens, RegionStats* stats) {
  std::vector<A3<NT>> g;
  for (const auto& v : gens) g.push_back(lift3<NT>(v));
  for (const auto& x : g)
    if (!satisfies(x, {}, d.K_rows)) return false;
  std::vector<A3<NT>> cone_rows;
  bool have_rows = false;
  for (const auto& jam : d.jams) {
    // Cheap certificate first: a facet of the jam cone with the whole cone strictly outside.
    bool separated = false;
    for (const auto& a : jam.facets) {
      bool all_out = true;
      for (const auto& x : g) all_out = all_out && sign(dot3(a, x)) < 0;
      if (all_out) {
        separated = true;
        break;
      }
    }
    if (separated) continue;
    if (!have_rows) {
      for (const auto& a : cone_facet_normals(gens, 3)) cone_rows.push_back(lift3<NT>(a));
      have_rows = true;
    }
    if (stats) ++stats->lp_tests;
    std::vector<Row<NT>> rows = homogeneous(cone_rows, false);
    for (const auto& r : homogeneous(jam.facets, false)) rows.push_back(r);
    rows.push_back({d.normaliser, NT(1), false});
    if (feasible(rows)) return false;
  }
  return true;
}

template <class NT>
bool cone_misses_J(const Data<NT>& d, const std::vector<VectorQ>& gens, RegionStats* stats) {
  std::vector<A3<NT>> g;
  for (const auto& v : gens) g.push_back(lift3<NT>(v));
  for (const auto& a : d.K_rows) {
    bool outside = true;
    for (const auto& x : g) outside = outside && sign(dot3(a, x)) <= 0;
    if (outside) return true;
  }
  for (const auto& jam : d.jams) {
    bool inside = true;
    for (const auto& x : g) inside = inside && in_jam<NT>(jam, x);
    if (inside) return true;
  }
  if (stats) ++stats->lp_tests;
  std::vector<A3<NT>> cone_rows;
  for (const auto& a : cone_facet_normals(gens, 3)) cone_rows.push_back(lift3<NT>(a));
  std::vector<Row<NT>> rows = homogeneous(cone_rows, false);
  for (const auto& r : homogeneous(d.K_rows, true)) rows.push_back(r);
  return !feasible(rows);
}

// The J target of the region. An undecided sign (enclosed q*) makes the
// question's answer "no", so the segment stays PARTIAL: never a wrong in/out.
class SustainedTarget final : public RegionTarget {
 public:
  explicit SustainedTarget(std::shared_ptr<const SustainedData> d) : d_(std::move(d)) {}
  const char* push_model() const override { return "sustained"; }
  const char* name() const override { return "J"; }

  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2*, const Vec2*, RegionInterval* detail) override {
    bool in = false;
    try {
      in = std::visit([&](const auto& d) { return cone_in_J(d, gens, stats); }, d_->data);
    } catch (const Undecided&) {
      return false;
    }
    if (in && detail) {
      detail->half_line = true;  // J is a cone: any magnitude
      detail->magnitudes = Magnitudes{};
    }
    return in;
  }

  bool misses(const std::vector<VectorQ>& gens) override {
    try {
      return std::visit([&](const auto& d) { return cone_misses_J(d, gens, stats); }, d_->data);
    } catch (const Undecided&) {
      return false;
    }
  }

  RegionStatus test_point(const std::vector<VectorQ>& gens, const Vec2&, const Vec2&, Magnitudes* out,
                          std::vector<Magnitudes>*) override {
    if (out) *out = Magnitudes{};
    try {
      const bool in = std::visit([&](const auto& d) { return cone_in_J(d, gens, stats); }, d_->data);
      return in ? RegionStatus::kIn : RegionStatus::kOut;
    } catch (const Undecided&) {
      return RegionStatus::kPartial;
    }
  }

 private:
  std::shared_ptr<const SustainedData> d_;
};

// Builds J's data from the columns W_n*, W_t* (frame B) and the rotation.
template <class NT>
Data<NT> build(const NT& cos, const NT& sin, const std::vector<A3<NT>>& Wn, const std::vector<A3<NT>>& Wt,
               const std::vector<Rational>& mu) {
  Data<NT> d;
  d.cos = cos;
  d.sin = sin;
  const NT det = dot3(Wn[0], cross3(Wn[1], Wn[2]));
  int sd = 0;
  try {
    sd = sign(det);
  } catch (const Undecided&) {
  }
  if (sd == 0) throw SceneError("fixels", "", "make W_n* singular at the seated pose: the seat is degenerate");
  for (int i = 0; i < 3; ++i) {
    A3<NT> row = cross3(Wn[(i + 1) % 3], Wn[(i + 2) % 3]);  // row i of adj(W_n*)
    if (sd > 0) row = neg3(row);                            // a_i = −sign(det) adj_i
    d.K_rows.push_back(row);
    d.K_rays.push_back(neg3(Wn[i]));
  }
  for (int k = 0; k < 3; ++k) d.normaliser[k] = d.K_rows[0][k] + d.K_rows[1][k] + d.K_rows[2][k];
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      typename Data<NT>::Jam jam;
      jam.fixels = {i, j};
      for (int k : {i, j}) {
        const NT m = lift_number(mu[k], static_cast<const NT*>(nullptr));
        for (int s : {1, -1}) {
          if (s == -1 && mu[k] == 0) break;
          A3<NT> g;
          for (int c = 0; c < 3; ++c) g[c] = -(Wn[k][c] + NT(s) * m * Wt[k][c]);
          jam.gens.push_back(g);
        }
      }
      jam.facets = facets_of(jam.gens, mu[i] == 0 && mu[j] == 0);
      d.jams.push_back(std::move(jam));
    }
  std::vector<A3<NT>> closed, strict;
  try {
    enumerate_pieces(d, 0, closed, strict);
  } catch (const Undecided&) {
    d.pieces.clear();
    d.pieces_decided = false;
  }
  return d;
}

template <class NT>
void fill_public(SustainedSet& J, const Data<NT>& d) {
  J.cone = cone_public(d, d.K_rays, {}, d.K_rows);
  for (const auto& jam : d.jams) J.jam_cones.push_back(JamCone{jam.fixels, cone_public(d, jam.gens, jam.facets, {})});
  for (const auto& p : d.pieces) J.pieces.push_back(cone_public(d, p.rays, p.closed, p.strict));
  J.pieces_decided = d.pieces_decided;
  J.empty = d.pieces_decided && d.pieces.empty();
  // Strong stability holds on all of J by the theorem of docs/theory.md §10.3
  // ((a) forces zero acceleration, (b) forces every contact to carry load).
  J.strongly_stable = true;
  if (!J.empty) return;
  std::vector<std::string> holders;
  for (const auto& jam : d.jams) {
    bool covers = true;
    for (const auto& r : d.K_rays) covers = covers && in_jam<NT>(jam, r);
    if (covers) {
      J.empty_reason = "every push direction that drives the part into its seat can be held at rest by " +
                       fixel_name(jam.fixels[0]) + " and " + fixel_name(jam.fixels[1]) + " with friction";
      return;
    }
    std::vector<Row<NT>> rows = homogeneous(d.K_rows, true);
    for (const auto& r : homogeneous(jam.facets, false)) rows.push_back(r);
    if (feasible(rows)) holders.push_back("(" + fixel_name(jam.fixels[0]) + ", " + fixel_name(jam.fixels[1]) + ")");
  }
  std::string list;
  for (std::size_t k = 0; k < holders.size(); ++k) list += (k ? ", " : "") + holders[k];
  J.empty_reason =
      "the pairs " + list + " can together hold every push direction that drives the part into its seat, with friction";
}

}  // namespace

}  // namespace internal

using internal::IV;
using internal::Q2;

std::unique_ptr<RegionTarget> sustained_target(const SustainedSet& J) {
  if (!J.data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  return std::make_unique<internal::SustainedTarget>(J.data);
}

bool SustainedSet::contains(const VectorQ& w_W) const { return why_not(w_W).empty(); }

std::string SustainedSet::why_not(const VectorQ& w_W) const {
  if (!data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  try {
    return std::visit([&](const auto& d) { return internal::reason(d, internal::to_body(d, w_W)); }, data->data);
  } catch (const internal::Undecided&) {
    throw UnsupportedError("wrench", "",
                           "is too close to a boundary of J to decide with the certified enclosure of q*");
  }
}

SustainedSet sustained_set(const Scene& scene, bool check_stability) {
  if (scene.body.dof != 3) throw SceneError("body.dof", "2", "the sustained-push set needs a rigid body (dof 3)");
  const int nc = scene.num_contacts();
  if (nc != 3) throw SceneError("fixels", std::to_string(nc) + " fixels", "the sustained-push set needs exactly 3");
  SustainedSet J;
  J.pose = seated_pose(scene);
  for (int i = 0; i < nc; ++i) J.mu.push_back(scene.fixels[i].mu_upper());
  auto d = std::make_shared<internal::SustainedData>();
  const Vec2& c = scene.body.p_AoCm_A;
  if (J.pose.exact) {
    std::vector<internal::A3<Q2>> Wn, Wt;
    for (int i = 0; i < nc; ++i) {
      const Q2 rx = internal::from_public(J.pose.p_BoG_B[i][0]) - Q2(c.x);
      const Q2 ry = internal::from_public(J.pose.p_BoG_B[i][1]) - Q2(c.y);
      const Vec2& n = J.pose.n_B[i];
      const Vec2 t{-n.y, n.x};
      Wn.push_back({Q2(n.x), Q2(n.y), rx * Q2(n.y) - ry * Q2(n.x)});
      Wt.push_back({Q2(t.x), Q2(t.y), rx * Q2(t.y) - ry * Q2(t.x)});
    }
    d->data = internal::build<Q2>(internal::from_public((*J.pose.exact)[2]), internal::from_public((*J.pose.exact)[3]),
                                  Wn, Wt, J.mu);
  } else {
    auto iv = [](const std::array<double, 2>& e) { return IV(e[0], e[1]); };
    std::vector<internal::A3<IV>> Wn, Wt;
    for (int i = 0; i < nc; ++i) {
      const IV rx = iv(J.pose.p_BoG_B_enclosure[i][0]) - internal::enclose(c.x);
      const IV ry = iv(J.pose.p_BoG_B_enclosure[i][1]) - internal::enclose(c.y);
      const IV Tx = iv(J.pose.tangent_B_enclosure[i][0]), Ty = iv(J.pose.tangent_B_enclosure[i][1]);
      const IV nx = -Ty, ny = Tx;   // n = rot90(T): inward on a counter-clockwise loop
      const IV tx = -Tx, ty = -Ty;  // t = rot90(n)
      Wn.push_back({nx, ny, rx * ny - ry * nx});
      Wt.push_back({tx, ty, rx * ty - ry * tx});
    }
    d->data = internal::build<IV>(iv(J.pose.cos_sin_enclosure[0]), iv(J.pose.cos_sin_enclosure[1]), Wn, Wt, J.mu);
  }
  std::visit([&](const auto& data) { internal::fill_public(J, data); }, d->data);
  J.data = d;
  J.stability_checks = check_stability ? check_strong_stability(scene, J) : 0;
  return J;
}

}  // namespace fixel