#include "fixel/guaranteed.h"

#include <algorithm>
#include <functional>

#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/scene_differs.h"
#include "fixel/lcp.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

Polyhedron as_polyhedron(const SeatingSet& S) {
  Polyhedron P;
  P.dim = S.dof;
  P.closed = S.halfspaces;
  return P;
}

// The non-seating set of (modes, open fixel i) in impulse space: lift the
// mode system to (x, p), add gap_i > 0, project x out.
Polyhedron non_seating_impulses(const Scene& scene, const std::vector<ContactMode>& modes, int i) {
  const int dof = scene.body.dof, nc = scene.num_contacts(), nx = dof + 2 * nc;
  const ModeSystem m = mode_system(scene, modes, VectorQ::Zero(dof));  // p enters the Newton rows' right side
  const ContactMatrices W = contact_matrices(scene);
  LiftedSystem s;
  s.nx = nx;
  s.np = dof;
  s.A_eq = MatrixQ::Zero(m.A_eq.rows(), nx + dof);
  s.A_eq.leftCols(nx) = m.A_eq;
  s.A_eq.block(0, nx, dof, dof) = -MatrixQ::Identity(dof, dof);  // Newton rows come first
  s.b_eq = m.b_eq;
  s.A_in = MatrixQ::Zero(m.A_in.rows() + 1, nx + dof);
  s.A_in.topLeftCorner(m.A_in.rows(), nx) = m.A_in;
  s.b_in = VectorQ(m.A_in.rows() + 1);
  s.b_in.head(m.A_in.rows()) = m.b_in;
  s.strict_in.assign(m.A_in.rows() + 1, false);
  // gap_i^{ℓ+1} > 0  ⇔  W_n,iᵀ ν⁺ > −ψ_i / h.
  s.A_in.row(m.A_in.rows()).head(dof) = W.Wn.col(i).transpose();
  s.b_in[m.A_in.rows()] = -scene.fixels[i].gap / scene.time_step;
  s.strict_in.back() = true;
  return project_out_x(s);
}

}  // namespace

std::vector<Magnitudes> ray_magnitudes(const GuaranteedSet& G, const SeatingSet& S, const VectorQ& b0,
                                       const VectorQ& g) {
  std::vector<Magnitudes> parts;
  const Magnitudes in_s = ray_magnitudes(S, b0, g);
  if (!in_s.empty) parts.push_back(in_s);
  for (const auto& n : G.non_seating) {
    const Magnitudes cut = ray_magnitudes(n.impulses, b0, g);
    if (cut.empty) continue;
    std::vector<Magnitudes> next;
    for (const auto& part : parts)
      for (const auto& rest : part.subtract(cut)) next.push_back(rest);
    parts = std::move(next);
  }
  std::sort(parts.begin(), parts.end(), [](const Magnitudes& a, const Magnitudes& b) { return a.lo < b.lo; });
  return parts;
}

bool GuaranteedSet::contains(const VectorQ& p, const SeatingSet& S) const {
  if (!S.contains(p)) return false;
  for (const auto& n : non_seating)
    if (n.impulses.contains(p)) return false;
  return true;
}

void check_guaranteed_set_of(const Scene& scene, const SeatingSet& S, const GuaranteedSet& G) {
  check_seating_set_of(scene, S);
  // The one-step model's inputs (not the outline: G lives in impulse space).
  internal::check_same_scene(
      G.built_from.get(), scene,
      internal::kReadsStep | internal::kReadsMass | internal::kReadsFixels | internal::kReadsFixelLowerMu, "G");
}

GuaranteedSet guaranteed_set(const Scene& scene, const SeatingSet& S, RunControl* control) {
  const internal::ControlScopeIfGiven scope(control);  // its exact steps poll it too
  const int nc = scene.num_contacts();
  if (nc != scene.body.dof) throw InputError("fixels", std::to_string(nc), "must number dof for the guaranteed set");
  check_seating_set_of(scene, S);
  const Polyhedron s_poly = as_polyhedron(S);
  GuaranteedSet G;
  long total = 1;
  for (int i = 0; i < nc; ++i) total *= 4;
  for (long code = 0; code < total; ++code) {
    poll(control, "guaranteed set", code, total, "contact modes");
    const std::vector<ContactMode> modes = contact_modes(code, nc);
    for (int i = 0; i < nc; ++i) {
      if (modes[i] != ContactMode::kOpen) continue;
      Polyhedron N = non_seating_impulses(scene, modes, i);
      if (is_empty(N.intersect(s_poly))) continue;
      G.non_seating.push_back({modes, i, std::move(N)});
    }
  }
  G.pieces = {s_poly};
  const long sets = static_cast<long>(G.non_seating.size());
  for (long k = 0; k < sets; ++k) {
    poll(control, "guaranteed set", k, sets, "non-seating sets subtracted");
    const auto& n = G.non_seating[static_cast<std::size_t>(k)];
    std::vector<Polyhedron> next;
    for (const auto& piece : G.pieces) {
      if (is_empty(piece.intersect(n.impulses))) {  // untouched: do not fragment it
        next.push_back(piece);
        continue;
      }
      for (auto& rest : subtract(piece, n.impulses)) next.push_back(std::move(rest));
    }
    G.pieces = std::move(next);
  }
  for (const auto& piece : G.pieces) G.dimensions.push_back(affine_dimension(piece));
  G.built_from = std::make_shared<const Scene>(scene);
  return G;
}

Rational lost_fraction(const SeatingSet& S, const GuaranteedSet& G, int grid) {
  if (grid < 1) throw InputError("grid", std::to_string(grid), "must be >= 1");
  const int k = static_cast<int>(S.rays.size());
  // The grid's points, C(grid + k − 1, k − 1), times 5 magnitudes: bounded
  // (ten million), since each is an exact membership test.
  double points = 5;
  for (int j = 1; j < k; ++j) points = points * (grid + j) / j;
  if (points > 1e7)
    throw InputError("grid", std::to_string(grid),
                     "gives about " + std::to_string(static_cast<long long>(points)) + " sample points for " +
                         std::to_string(k) + " rays of S; at most 10,000,000");
  long lost = 0, total = 0;
  std::vector<int> w(k, 0);
  // Enumerate weight vectors with Σ w = grid (compositions).
  std::function<void(int, int)> visit = [&](int j, int left) {
    if (j == k - 1) {
      w[j] = left;
      VectorQ dir = VectorQ::Zero(S.dof);
      for (int r = 0; r < k; ++r) dir += Rational(w[r], grid) * S.rays[r];
      for (const Rational& t : {Rational(1, 4), Rational(1, 2), Rational(1), Rational(2), Rational(4)}) {
        ++total;
        if (!G.contains(VectorQ(S.apex + t * dir), S)) ++lost;
      }
      return;
    }
    for (int a = 0; a <= left; ++a) {
      w[j] = a;
      visit(j + 1, left - a);
    }
  };
  if (k > 0) visit(0, grid);
  return total ? Rational(lost, total) : Rational(0);
}

std::vector<Halfspace> stability_cone(const Scene& scene) {
  const ContactMatrices W = contact_matrices(scene);
  std::vector<VectorQ> rays;
  for (int i = 0; i < scene.num_contacts(); ++i)
    for (int s : {1, -1}) rays.push_back(VectorQ(-(W.Wn.col(i) + Rational(s) * scene.fixels[i].mu * W.Wt.col(i))));
  std::vector<Halfspace> out;
  for (const auto& a : cone_facet_normals(rays, scene.body.dof)) out.push_back({a, Rational(0)});
  return out;  // h·C_stab = C_stab: scaling a cone by h > 0 leaves it unchanged
}

Polyhedron seat_and_stay(const Scene& scene, const SeatingSet& S) {
  check_seating_set_of(scene, S);
  Polyhedron P = as_polyhedron(S);
  for (const auto& h : stability_cone(scene)) P.closed.push_back(h);
  return P;
}

}  // namespace fixel
