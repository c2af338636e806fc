#include "fixel/seating.h"

#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"

namespace fixel {

using internal::exact_lu;

bool SeatingSet::contains(const VectorQ& p_ext) const {
  for (const auto& h : halfspaces)
    if (!h.contains(p_ext)) return false;
  return true;
}

SeatingSet seating_set(const Scene& scene) {
  const int dof = scene.body.dof, nc = scene.num_contacts();
  const ContactMatrices W = contact_matrices(scene);
  SeatingSet S;
  S.dof = dof;

  VectorQ psi(nc);
  for (int i = 0; i < nc; ++i) psi[i] = scene.fixels[i].gap;
  const auto lu = exact_lu(W.Wn.transpose());
  if (!lu.isInvertible())
    throw SceneError("fixels", "", "make W_n singular: the fixture does not determine the motion");
  S.nu_plus = lu.solve(VectorQ(-psi / scene.time_step));
  S.tangential_velocity = W.Wt.transpose() * S.nu_plus;
  S.apex = W.M * (S.nu_plus - scene.body.velocity);

  for (int i = 0; i < nc; ++i) {
    const int sigma = sign(S.tangential_velocity[i]);
    S.sliding.push_back(sigma);
    if (sigma == 0) {
      // Sticking: the friction impulse may lie anywhere in the
      // cone, so both edges W_n ± μ W_t generate (one when μ = 0).
      for (int s : {1, -1}) {
        const VectorQ g = W.Wn.col(i) + Rational(s) * scene.fixels[i].mu * W.Wt.col(i);
        if (s == -1 && scene.fixels[i].mu == 0) break;
        S.generators.push_back(g);
        S.rays.push_back(-g);
        S.generator_fixel.push_back(i);
      }
      continue;
    }
    const VectorQ g = W.Wn.col(i) - Rational(sigma) * scene.fixels[i].mu * W.Wt.col(i);
    S.generators.push_back(g);
    S.rays.push_back(-g);
    S.generator_fixel.push_back(i);
  }
  for (const VectorQ& n : cone_facet_normals(S.rays, dof)) S.halfspaces.push_back({n, n.dot(S.apex)});
  return S;
}

namespace {

// Exact equality that also compares sizes (Eigen's == asserts on a size
// mismatch, and S may come from anywhere).
bool same(const VectorQ& a, const VectorQ& b) { return a.size() == b.size() && a == b; }

// What of S differs from the set seating_set(scene) builds, checked from
// its defining data (ν⁺ against the scene's eq. (20), then the values and
// generators derived from it, then the rows: S's facets); empty when
// nothing does.
std::string seating_set_mismatch(const Scene& scene, const SeatingSet& S) {
  const int nc = scene.num_contacts();
  const ContactMatrices W = contact_matrices(scene);
  if (S.nu_plus.size() != S.dof || S.tangential_velocity.size() != nc) return "velocity vector length";
  VectorQ psi(nc);
  for (int i = 0; i < nc; ++i) psi[i] = scene.fixels[i].gap;
  if (!same(W.Wn.transpose() * S.nu_plus, VectorQ(-psi / scene.time_step))) return "seating velocity nu_plus";
  if (!same(S.tangential_velocity, W.Wt.transpose() * S.nu_plus)) return "tangential velocity v_t";
  if (!same(S.apex, W.M * (S.nu_plus - scene.body.velocity))) return "apex";
  std::vector<VectorQ> generators;
  std::vector<int> owners;
  for (int i = 0; i < nc; ++i) {
    const int sigma = sign(S.tangential_velocity[i]);
    if (S.sliding[i] != sigma) return "sliding sign list";
    const Rational& mu = scene.fixels[i].mu;
    for (int s : sigma == 0 ? std::vector<int>{1, -1} : std::vector<int>{-sigma}) {
      if (sigma == 0 && s == -1 && mu == 0) break;
      generators.push_back(W.Wn.col(i) + Rational(s) * mu * W.Wt.col(i));
      owners.push_back(i);
    }
  }
  if (S.generators.size() != generators.size() || S.generator_fixel != owners || S.rays.size() != generators.size())
    return "generator list";
  for (std::size_t k = 0; k < generators.size(); ++k) {
    if (!same(S.generators[k], generators[k])) return "generator list";
    if (!same(S.rays[k], VectorQ(-generators[k]))) return "ray list";
  }
  // The rows are S's facets, in seating_set's order: a dropped row would
  // make S (and its region) larger without a word. At most 2 n_c rays, so
  // the facet search is small.
  const std::vector<VectorQ> normals = cone_facet_normals(S.rays, S.dof);
  if (S.halfspaces.size() != normals.size()) return "halfspace list";
  for (std::size_t k = 0; k < normals.size(); ++k)
    if (!same(S.halfspaces[k].a, normals[k]) || S.halfspaces[k].c != normals[k].dot(S.apex)) return "halfspace list";
  return "";
}

}  // namespace

void check_seating_set_of(const Scene& scene, const SeatingSet& S, const std::string& field) {
  const int dof = scene.body.dof, nc = scene.num_contacts();
  bool rows_fit = true;
  for (const auto& h : S.halfspaces) rows_fit = rows_fit && h.a.size() == dof;
  const std::string shape = "dof " + std::to_string(S.dof) + ", " + std::to_string(S.sliding.size()) + " fixels";
  if (S.dof != dof || S.apex.size() != dof || static_cast<int>(S.sliding.size()) != nc || !rows_fit)
    throw InputError(field, shape,
                     "is not this scene's seating set (dof " + std::to_string(dof) + ", " + std::to_string(nc) +
                         " fixels): build it with seating_set(scene)");
  const std::string differs = seating_set_mismatch(scene, S);
  if (!differs.empty())
    throw InputError(
        field, shape,
        "is not this scene's seating set (its " + differs + " is not this scene's): build it with seating_set(scene)");
}

SeatingSystem seating_system(const Scene& scene, const SeatingSet& S) {
  check_seating_set_of(scene, S);
  const int nc = scene.num_contacts(), n = 4 * nc;
  for (int i = 0; i < nc; ++i)
    if (S.sliding[i] == 0)
      throw UnsupportedError("fixels[" + std::to_string(i) + "]", "v_t = 0",
                             "sticks: eq. (21)-(27) assume every contact slides (use the H-form of S instead)");
  const TimeSteppingLcp lcp = build_lcp(scene);
  const std::vector<std::string> w_names = lcp.w_names(), z_names = lcp.z_names();

  SeatingSystem sys;
  sys.P = lcp.P;
  sys.a = lcp.a;
  // Which half of each friction pair survives depends on the sliding sign:
  // v_t > 0 means friction along −t, so (p_f)_2 and (ρ_f)_1 are kept.
  auto friction_index = [&](int i, bool minus_column) { return nc + 2 * i + (minus_column ? 1 : 0); };
  for (int i = 0; i < nc; ++i) sys.kept.push_back(friction_index(i, S.sliding[i] < 0));      // ρ_f (w block)
  for (int i = 0; i < nc; ++i) sys.kept.push_back(n + i);                                    // p_n
  for (int i = 0; i < nc; ++i) sys.kept.push_back(n + friction_index(i, S.sliding[i] > 0));  // p_f
  for (int i = 0; i < nc; ++i) sys.kept.push_back(n + 3 * nc + i);                           // s

  sys.K = MatrixQ(n, n);
  for (int k = 0; k < n; ++k) {
    const int j = sys.kept[k];
    if (j < n) {
      sys.K.col(k) = VectorQ::Unit(n, j);
      sys.y_names.push_back(w_names[j]);
    } else {
      sys.K.col(k) = -lcp.B.col(j - n);
      sys.y_names.push_back(z_names[j - n]);
    }
  }
  const auto lu = exact_lu(sys.K);
  if (!lu.isInvertible())
    throw UnsupportedError("fixels", "", "give linearly dependent seating generators: K of eq. (21) is singular");
  sys.K_inv = lu.inverse();
  return sys;
}

namespace {
void check_impulse_length(const MatrixQ& P, const VectorQ& p_ext) {
  if (p_ext.size() != P.cols())
    throw InputError("p_ext", std::to_string(p_ext.size()) + " components",
                     "where " + std::to_string(P.cols()) + " are needed (dof)");
}
}  // namespace

VectorQ SeatingSystem::y(const VectorQ& p_ext) const {
  check_impulse_length(P, p_ext);
  return K_inv * (P * p_ext + a);
}
VectorQ SeatingSystem::linear_part(const VectorQ& p_ext) const {
  check_impulse_length(P, p_ext);
  return K_inv * (P * p_ext);
}
VectorQ SeatingSystem::threshold() const { return -(K_inv * a); }

Magnitudes ray_magnitudes(const SeatingSet& S, const VectorQ& b0, const VectorQ& g) {
  for (const auto& [v, name] : {std::pair<const VectorQ&, const char*>{b0, "b0"}, {g, "g"}})
    if (v.size() != S.dof)
      throw InputError(name, std::to_string(v.size()) + " components", "where S has dof " + std::to_string(S.dof));
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
  if (Magnitudes::ends_cross(m.lo, m.lo_closed, m.hi, m.hi_closed)) return Magnitudes{};
  return m;
}

}  // namespace fixel
