// J, the sustained-push wrench set at the seated pose q* (docs/theory.md
// §10): int K minus the jam cones of each pair of fixels, cut into disjoint
// convex pieces, and its public form in the world frame.
#include "fixel/sustained.h"

#include <variant>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/internal/cone3.h"
#include "fixel/internal/scene_differs.h"
#include "fixel/internal/sustained_core.h"
#include "fixel/internal/sustained_data.h"
#include "fixel/progress.h"

namespace fixel {

namespace internal {

namespace {

// J's convex pieces: int K minus each jam cone, choosing for each jam cone
// the first facet it violates (so the pieces are disjoint); empty ones are
// pruned as soon as a prefix is infeasible. With `first_only`, stops at the
// first piece (returns true then): J is not empty.
template <class NT>
bool enumerate_pieces(Data<NT>& d, std::size_t jam, std::vector<A3<NT>>& closed, std::vector<A3<NT>>& strict,
                      bool with_rays, bool first_only) {
  poll_exact_step();
  std::vector<RowRef<NT>> rows;
  append_refs(d.K_rows, true, rows);
  append_refs(closed, false, rows);
  append_refs(strict, true, rows);
  if (!feasible_filtered(rows)) return false;
  if (jam == d.jams.size()) {
    typename Data<NT>::Piece p;
    p.closed = closed;
    p.strict = d.K_rows;
    for (const auto& a : strict) p.strict.push_back(a);
    if (with_rays) {
      std::vector<A3<NT>> all = p.closed;
      for (const auto& a : p.strict) all.push_back(a);
      p.rays = rays_of(all);
    }
    d.pieces.push_back(std::move(p));
    return first_only;
  }
  const auto& facets = d.jams[jam].facets;
  for (std::size_t r = 0; r < facets.size(); ++r) {
    const std::size_t c0 = closed.size();
    for (std::size_t s = 0; s < r; ++s) closed.push_back(facets[s]);
    strict.push_back(neg3(facets[r]));  // violate row r: a·x < 0
    cache_enclosures(strict.back());
    const bool stop = enumerate_pieces(d, jam + 1, closed, strict, with_rays, first_only);
    strict.pop_back();
    closed.resize(c0);
    if (stop) return true;
  }
  return false;
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

// J's rows from the columns W_n*, W_t* (frame B) and the rotation: K's
// rows and rays, the normaliser, the jam cones' generators and facets.
template <class NT>
Data<NT> rows(const NT& cos, const NT& sin, const std::vector<A3<NT>>& Wn, const std::vector<A3<NT>>& Wt,
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
  return d;
}

// J's pieces from its rows; with `first_only`, only the first (enumerate_pieces).
template <class NT>
void add_pieces(Data<NT>& d, bool with_rays, bool first_only) {
  for (const auto& a : d.K_rows) cache_enclosures(a);
  cache_enclosures(d.normaliser);
  for (const auto& jam : d.jams)
    for (const auto& a : jam.facets) cache_enclosures(a);
  std::vector<A3<NT>> closed, strict;
  try {
    enumerate_pieces(d, 0, closed, strict, with_rays, first_only);
  } catch (const Undecided&) {
    d.pieces.clear();
    d.pieces_decided = false;
  }
}

// Builds J's data from the columns W_n*, W_t* (frame B) and the rotation.
template <class NT>
Data<NT> build(const NT& cos, const NT& sin, const std::vector<A3<NT>>& Wn, const std::vector<A3<NT>>& Wt,
               const std::vector<Rational>& mu, bool with_rays, bool first_only) {
  Data<NT> d = rows(cos, sin, Wn, Wt, mu);
  add_pieces(d, with_rays, first_only);
  return d;
}

A3<Q2> lift(const A3<Rational>& v) { return {Q2(v[0]), Q2(v[1]), Q2(v[2])}; }
std::vector<A3<Q2>> lift(const std::vector<A3<Rational>>& vs) {
  std::vector<A3<Q2>> out;
  out.reserve(vs.size());
  for (const auto& v : vs) out.push_back(lift(v));
  return out;
}

// At a rational seat (every design layout: q* = 0): the same rows made in
// rationals, which are cheaper than Q(√d) numbers with no root, then
// lifted; the same values, so the same J.
Data<Q2> build_rational(const Rational& cos, const Rational& sin, const std::vector<A3<Rational>>& Wn,
                        const std::vector<A3<Rational>>& Wt, const std::vector<Rational>& mu, bool with_rays,
                        bool first_only) {
  const Data<Rational> r = rows(cos, sin, Wn, Wt, mu);
  Data<Q2> d;
  d.cos = Q2(r.cos);
  d.sin = Q2(r.sin);
  d.K_rows = lift(r.K_rows);
  d.K_rays = lift(r.K_rays);
  d.normaliser = lift(r.normaliser);
  for (const auto& jam : r.jams) d.jams.push_back({jam.fixels, lift(jam.gens), lift(jam.facets)});
  add_pieces(d, with_rays, first_only);
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
    std::vector<RowRef<NT>> rows;
    append_refs(d.K_rows, true, rows);
    append_refs(jam.facets, false, rows);
    if (feasible_filtered(rows))
      holders.push_back("(" + fixel_name(jam.fixels[0]) + ", " + fixel_name(jam.fixels[1]) + ")");
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

void require_sustained_fixture(const Scene& scene) {
  if (scene.body.dof != 3)
    throw SceneError("body.dof", std::to_string(scene.body.dof),
                     "is a point mass: the sustained-push set needs a rigid body (dof 3)");
  const int nc = scene.num_contacts();
  if (nc != 3)
    throw SceneError("fixels", std::to_string(nc) + " fixels", "are not 3: the sustained-push set needs exactly 3");
}

namespace {

void check_scene(const Scene& scene) {
  check_scene_values(scene);  // a scene built in code: a SceneError, not a crash
  require_sustained_fixture(scene);
}

// J's data at the seated pose, in the body frame; over Q(√d) the pieces'
// extreme rays only `with_rays` (exact, they never leave a sign open), and
// without them only the first piece: J's emptiness, which is all that
// sustained_core reports (the region against J reads K and the jam cones).
std::shared_ptr<internal::SustainedData> make_data(const Scene& scene, const SeatedPose& pose,
                                                   const std::vector<Rational>& mu, bool with_rays) {
  const int nc = scene.num_contacts();
  auto d = std::make_shared<internal::SustainedData>();
  const Vec2& c = scene.body.p_AoCm_A;
  const auto& exact = pose.exact;
  bool rational = exact && (*exact)[2].b == 0 && (*exact)[3].b == 0;
  for (int i = 0; i < nc && rational; ++i) rational = pose.p_BoG_B[i][0].b == 0 && pose.p_BoG_B[i][1].b == 0;
  if (rational) {
    std::vector<internal::A3<Rational>> Wn, Wt;
    for (int i = 0; i < nc; ++i) {
      const Rational rx = pose.p_BoG_B[i][0].a - c.x, ry = pose.p_BoG_B[i][1].a - c.y;
      const Vec2& n = pose.n_B[i];
      const Vec2 t{-n.y, n.x};
      Wn.push_back({n.x, n.y, rx * n.y - ry * n.x});
      Wt.push_back({t.x, t.y, rx * t.y - ry * t.x});
    }
    d->data = internal::build_rational((*exact)[2].a, (*exact)[3].a, Wn, Wt, mu, with_rays, !with_rays);
  } else if (pose.exact) {
    std::vector<internal::A3<Q2>> Wn, Wt;
    for (int i = 0; i < nc; ++i) {
      const Q2 rx = internal::from_public(pose.p_BoG_B[i][0]) - Q2(c.x);
      const Q2 ry = internal::from_public(pose.p_BoG_B[i][1]) - Q2(c.y);
      const Vec2& n = pose.n_B[i];
      const Vec2 t{-n.y, n.x};
      Wn.push_back({Q2(n.x), Q2(n.y), rx * Q2(n.y) - ry * Q2(n.x)});
      Wt.push_back({Q2(t.x), Q2(t.y), rx * Q2(t.y) - ry * Q2(t.x)});
    }
    d->data = internal::build<Q2>(internal::from_public((*pose.exact)[2]), internal::from_public((*pose.exact)[3]), Wn,
                                  Wt, mu, with_rays, !with_rays);
  } else {
    auto iv = [](const std::array<double, 2>& e) { return IV(e[0], e[1]); };
    std::vector<internal::A3<IV>> Wn, Wt;
    for (int i = 0; i < nc; ++i) {
      const IV rx = iv(pose.p_BoG_B_enclosure[i][0]) - internal::enclose(c.x);
      const IV ry = iv(pose.p_BoG_B_enclosure[i][1]) - internal::enclose(c.y);
      const IV Tx = iv(pose.tangent_B_enclosure[i][0]), Ty = iv(pose.tangent_B_enclosure[i][1]);
      const IV nx = -Ty, ny = Tx;   // n = rot90(T): inward on a counter-clockwise loop
      const IV tx = -Tx, ty = -Ty;  // t = rot90(n)
      Wn.push_back({nx, ny, rx * ny - ry * nx});
      Wt.push_back({tx, ty, rx * ty - ry * tx});
    }
    // On intervals the rays are always made: a sign they leave open makes
    // the pieces undecided, which J's answers (and so sustained_core's)
    // must show; they cost little there.
    d->data =
        internal::build<IV>(iv(pose.cos_sin_enclosure[0]), iv(pose.cos_sin_enclosure[1]), Wn, Wt, mu, true, false);
  }
  return d;
}

std::vector<Rational> fixel_mu(const Scene& scene) {
  std::vector<Rational> mu;
  for (int i = 0; i < scene.num_contacts(); ++i) mu.push_back(scene.fixels[i].mu_upper());
  return mu;
}

}  // namespace

SustainedSet sustained_set(const Scene& scene, bool check_stability) {
  const internal::ExactTask task("sustained set J");
  check_scene(scene);
  SustainedSet J;
  J.pose = seated_pose(scene);
  J.mu = fixel_mu(scene);
  auto d = make_data(scene, J.pose, J.mu, true);
  d->built_from = std::make_shared<const Scene>(scene);  // the outline is shared, not copied
  std::visit([&](const auto& data) { internal::fill_public(J, data); }, d->data);
  J.data = d;
  J.stability_checks = check_stability ? check_strong_stability(scene, J) : 0;
  return J;
}

namespace internal {

void check_built_from(const SustainedData& data, const Scene& scene, const char* field) {
  check_same_scene(data.built_from.get(), scene, kReadsOutline | kReadsMass | kReadsFixels, field);
}

SustainedCore sustained_core(const Scene& scene) {
  const ExactTask task("sustained set J");
  check_scene(scene);
  SustainedCore out;
  out.data = make_data(scene, seated_pose(scene), fixel_mu(scene), false);
  std::visit(
      [&](const auto& data) {
        out.pieces_decided = data.pieces_decided;
        out.empty = data.pieces_decided && data.pieces.empty();
      },
      out.data->data);
  return out;
}

}  // namespace internal

}  // namespace fixel
