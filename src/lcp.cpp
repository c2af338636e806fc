#include "fixel/lcp.h"

#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"

namespace fixel {

MatrixQ normal_wrench_matrix(const Scene& scene) {
  check_scene_values(scene);  // a scene built in code: a SceneError, not a crash
  const int dof = scene.body.dof, nc = scene.num_contacts();
  MatrixQ Wn(dof, nc);
  for (int i = 0; i < nc; ++i) Wn.col(i) = contact_wrench(scene.lever_arm(i), scene.fixels[i].n_A, dof);
  return Wn;
}

namespace {

std::string pair_text(const Vec2& v) { return "(" + to_string(v.x) + ", " + to_string(v.y) + ")"; }

}  // namespace

void require_determined_fixture(const Scene& scene) {
  check_scene_values(scene);
  const int dof = scene.body.dof, nc = scene.num_contacts();
  if (nc != dof)
    throw SceneError(
        "fixels", std::to_string(nc) + " fixels",
        "but dof is " + std::to_string(dof) + ": the seating analysis needs exactly dof fixels (n_c == dof)");
  // Name the first fixel whose normal wrench lies in the span of the earlier
  // ones, so that the message points at something the user can change.
  const MatrixQ Wn = normal_wrench_matrix(scene);
  if (internal::exact_lu(Wn).isInvertible()) return;
  for (int j = 1; j <= nc; ++j)
    if (internal::exact_lu(Wn.leftCols(j)).rank() < j)
      throw SceneError("fixels[" + std::to_string(j - 1) + "]", pair_text(scene.fixels[j - 1].p_AoF_A),
                       "makes W_n singular: its normal wrench is a combination of the earlier fixels', "
                       "so the fixture does not determine the motion");
}

void require_single_friction(const Scene& scene) {
  // The one-step model is not monotone in μ: an interval has no single
  // robust answer there (docs/theory.md §10), only in the sustained set.
  for (int i = 0; i < scene.num_contacts(); ++i)
    if (scene.fixels[i].mu_hi)
      throw UnsupportedError("fixels[" + std::to_string(i) + "].mu",
                             "[" + to_string(scene.fixels[i].mu) + ", " + to_string(*scene.fixels[i].mu_hi) + "]",
                             "is an interval: the one-step model needs one value (friction intervals are "
                             "accepted by the sustained-push set J and its approach-aware J', by the physics "
                             "push and by fixture design ranked by the sustained push)");
}

ContactMatrices contact_matrices(const Scene& scene) {
  check_scene_values(scene);  // a scene built in code: a SceneError, not a crash
  require_determined_fixture(scene);
  require_single_friction(scene);
  const int dof = scene.body.dof, nc = scene.num_contacts();
  ContactMatrices W;
  W.M = MatrixQ::Zero(dof, dof);
  W.M(0, 0) = scene.body.mass;
  W.M(1, 1) = scene.body.mass;
  if (dof == 3) W.M(2, 2) = scene.body.inertia;
  W.Wn = normal_wrench_matrix(scene);
  W.Wt = MatrixQ(dof, nc);
  W.Wf = MatrixQ(dof, 2 * nc);
  W.E = MatrixQ::Zero(2 * nc, nc);
  W.U = MatrixQ::Zero(nc, nc);
  for (int i = 0; i < nc; ++i) {
    W.Wt.col(i) = contact_wrench(scene.lever_arm(i), scene.tangent(i), dof);
    W.Wf.col(2 * i) = W.Wt.col(i);
    W.Wf.col(2 * i + 1) = -W.Wt.col(i);
    W.E(2 * i, i) = 1;
    W.E(2 * i + 1, i) = 1;
    W.U(i, i) = scene.fixels[i].mu;
  }
  return W;
}

TimeSteppingLcp build_lcp(const Scene& scene) {
  const int dof = scene.body.dof, nc = scene.num_contacts();
  TimeSteppingLcp lcp;
  lcp.W = contact_matrices(scene);
  const ContactMatrices& W = lcp.W;
  // M is diagonal with positive entries, so its inverse is exact and cheap.
  MatrixQ Minv = MatrixQ::Zero(dof, dof);
  for (int k = 0; k < dof; ++k) Minv(k, k) = Rational(1) / W.M(k, k);

  const int n = 4 * nc;
  lcp.B = MatrixQ::Zero(n, n);
  lcp.B.block(0, 0, nc, nc) = W.Wn.transpose() * Minv * W.Wn;
  lcp.B.block(0, nc, nc, 2 * nc) = W.Wn.transpose() * Minv * W.Wf;
  lcp.B.block(nc, 0, 2 * nc, nc) = W.Wf.transpose() * Minv * W.Wn;
  lcp.B.block(nc, nc, 2 * nc, 2 * nc) = W.Wf.transpose() * Minv * W.Wf;
  lcp.B.block(nc, 3 * nc, 2 * nc, nc) = W.E;
  lcp.B.block(3 * nc, 0, nc, nc) = W.U;
  lcp.B.block(3 * nc, nc, nc, 2 * nc) = -W.E.transpose();

  lcp.P = MatrixQ::Zero(n, dof);
  lcp.P.topRows(nc) = W.Wn.transpose() * Minv;
  lcp.P.middleRows(nc, 2 * nc) = W.Wf.transpose() * Minv;

  set_lcp_state(lcp, scene);
  return lcp;
}

void set_lcp_state(TimeSteppingLcp& lcp, const Scene& scene) {
  const int nc = scene.num_contacts();
  const ContactMatrices& W = lcp.W;
  // What the state is read from, checked cheaply (this runs at every step).
  if (nc != W.U.rows())
    throw SceneError("fixels", std::to_string(nc) + " fixels",
                     "but the LCP was built for " + std::to_string(W.U.rows()) + " (the same fixels are needed)");
  if (scene.body.velocity.size() != W.Wn.rows())
    throw SceneError("body.velocity", std::to_string(scene.body.velocity.size()) + " entries",
                     "but the LCP was built for dof " + std::to_string(W.Wn.rows()));
  if (!(scene.time_step > 0)) throw SceneError("time_step", to_string(scene.time_step), "must be > 0");
  VectorQ psi(nc);
  for (int i = 0; i < nc; ++i) psi[i] = scene.fixels[i].gap;
  lcp.a = VectorQ::Zero(4 * nc);
  lcp.a.head(nc) = W.Wn.transpose() * scene.body.velocity + psi / scene.time_step;
  lcp.a.segment(nc, 2 * nc) = W.Wf.transpose() * scene.body.velocity;
}

VectorQ TimeSteppingLcp::b(const VectorQ& p_ext) const {
  if (p_ext.size() != P.cols())
    throw InputError("p_ext", std::to_string(p_ext.size()) + " components",
                     "where " + std::to_string(P.cols()) + " are needed (dof)");
  return P * p_ext + a;
}

namespace {
std::vector<std::string> names(int nc, const char* normal, const char* friction, const char* slack) {
  std::vector<std::string> out;
  for (int i = 0; i < nc; ++i) out.push_back(std::string(normal) + "[" + std::to_string(i) + "]");
  for (int i = 0; i < nc; ++i) {
    out.push_back(std::string(friction) + "[" + std::to_string(i) + "]+");
    out.push_back(std::string(friction) + "[" + std::to_string(i) + "]-");
  }
  for (int i = 0; i < nc; ++i) out.push_back(std::string(slack) + "[" + std::to_string(i) + "]");
  return out;
}
}  // namespace

std::vector<std::string> TimeSteppingLcp::w_names() const {
  return names(static_cast<int>(W.U.rows()), "rho_n", "rho_f", "sigma");
}
std::vector<std::string> TimeSteppingLcp::z_names() const {
  return names(static_cast<int>(W.U.rows()), "p_n", "p_f", "s");
}

}  // namespace fixel
