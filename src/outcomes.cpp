#include "fixel/outcomes.h"

#include "fixel/error.h"
#include "fixel/internal/exact_lp.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/lcp.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

struct Rows {
  std::vector<VectorQ> a;
  std::vector<Rational> b;
  void add(const VectorQ& row, const Rational& rhs) {
    a.push_back(row);
    b.push_back(rhs);
  }
  MatrixQ matrix(int cols) const {
    MatrixQ A(static_cast<int>(a.size()), cols);
    for (std::size_t i = 0; i < a.size(); ++i) A.row(static_cast<int>(i)) = a[i].transpose();
    return A;
  }
  VectorQ vector() const {
    VectorQ v(static_cast<int>(b.size()));
    for (std::size_t i = 0; i < b.size(); ++i) v[static_cast<int>(i)] = b[i];
    return v;
  }
};

void check_impulse(const Scene& scene, const VectorQ& p_ext) {
  if (p_ext.size() != scene.body.dof)
    throw InputError("impulse", std::to_string(p_ext.size()) + " components",
                     "but the scene has dof " + std::to_string(scene.body.dof));
}

Outcome make_outcome(const Scene& scene, const ContactMatrices& W, const std::vector<ContactMode>& modes,
                     const VectorQ& x, bool isolated) {
  const int dof = scene.body.dof, nc = scene.num_contacts();
  Outcome o;
  o.modes = modes;
  o.velocity = x.head(dof);
  o.p_n = x.segment(dof, nc);
  o.p_t = x.segment(dof + nc, nc);
  o.gaps = VectorQ(nc);
  o.seated = true;
  for (int i = 0; i < nc; ++i) {
    o.gaps[i] = scene.fixels[i].gap + scene.time_step * W.Wn.col(i).dot(o.velocity);
    o.seated = o.seated && o.gaps[i] == 0;
  }
  o.isolated = isolated;
  return o;
}

// Whether a singular mode's solution set {A_eq x = b_eq, A_in x ≥ b_in},
// known to hold x0, holds another point too: a family. Each direction of
// A_eq's null space is tried both ways (exact LPs); the set is x0 alone
// iff no direction moves along it.
bool holds_a_family(int n, const std::vector<internal::LinearConstraint>& rows, const MatrixQ& A_eq,
                    const VectorQ& x0) {
  const MatrixQ kernel = internal::exact_lu(A_eq).kernel();
  for (int j = 0; j < kernel.cols(); ++j) {
    for (const int side : {1, -1}) {
      const VectorQ c = Rational(side) * kernel.col(j);
      if (c.isZero()) continue;  // a trivial kernel is one zero column
      const internal::LpResult lp = internal::solve_lp(n, rows, c);
      if (lp.status == internal::LpStatus::kUnbounded || lp.value != c.dot(x0)) return true;
    }
  }
  return false;
}

// x = (ν, p_n, p_t) satisfies the mode's system exactly.
bool in_mode_set(const ModeSystem& sys, const Outcome& o) {
  VectorQ x(o.velocity.size() + o.p_n.size() + o.p_t.size());
  x << o.velocity, o.p_n, o.p_t;
  return sys.A_eq * x == sys.b_eq && ((sys.A_in * x - sys.b_in).array() >= Rational(0)).all();
}

}  // namespace

std::vector<ContactMode> contact_modes(long code, int num_contacts) {
  if (num_contacts < 0 || num_contacts > 31)
    throw InputError("num_contacts", std::to_string(num_contacts), "must be in [0, 31] (codes are below 4^n_c)");
  if (code < 0 || code >= (1L << (2 * num_contacts)))
    throw InputError(
        "code", std::to_string(code),
        "must be in [0, 4^" + std::to_string(num_contacts) + ") for " + std::to_string(num_contacts) + " fixels");
  std::vector<ContactMode> modes(num_contacts);
  for (int i = 0; i < num_contacts; ++i, code /= 4) modes[i] = static_cast<ContactMode>(code % 4);
  return modes;
}

std::string to_string(ContactMode mode) {
  switch (mode) {
    case ContactMode::kOpen:
      return "open";
    case ContactMode::kSlidePlus:
      return "slide+";
    case ContactMode::kSlideMinus:
      return "slide-";
    case ContactMode::kStick:
      return "stick";
  }
  return "?";
}

ModeSystem mode_system(const Scene& scene, const std::vector<ContactMode>& modes, const VectorQ& p_ext) {
  check_impulse(scene, p_ext);
  const int dof = scene.body.dof, nc = scene.num_contacts(), n = dof + 2 * nc;
  if (static_cast<int>(modes.size()) != nc)
    throw InputError("modes", std::to_string(modes.size()) + " modes",
                     "must have one mode per fixel (" + std::to_string(nc) + ")");
  const ContactMatrices W = contact_matrices(scene);
  auto nu = [&](const VectorQ& w) {  // the row w·ν
    VectorQ row = VectorQ::Zero(n);
    row.head(dof) = w;
    return row;
  };
  auto pn = [&](int i) { return VectorQ(VectorQ::Unit(n, dof + i)); };
  auto pt = [&](int i) { return VectorQ(VectorQ::Unit(n, dof + nc + i)); };

  Rows eq, in;
  // Newton, eq. (10): M ν⁺ − W_n p_n − W_t p_t = M ν^ℓ + p_ext.
  const VectorQ newton_rhs = W.M * scene.body.velocity + p_ext;
  for (int k = 0; k < dof; ++k) {
    VectorQ row = VectorQ::Zero(n);
    row.head(dof) = W.M.row(k).transpose();
    for (int i = 0; i < nc; ++i) {
      row[dof + i] = -W.Wn(k, i);
      row[dof + nc + i] = -W.Wt(k, i);
    }
    eq.add(row, newton_rhs[k]);
  }
  for (int i = 0; i < nc; ++i) {
    const Rational closing = -scene.fixels[i].gap / scene.time_step;  // W_n,iᵀ ν⁺ for gap 0
    const Rational mu = scene.fixels[i].mu;
    switch (modes.at(i)) {
      case ContactMode::kOpen:
        eq.add(pn(i), 0);
        eq.add(pt(i), 0);
        in.add(nu(W.Wn.col(i)), closing);
        break;
      case ContactMode::kSlidePlus:
      case ContactMode::kSlideMinus: {
        const Rational sigma = modes[i] == ContactMode::kSlidePlus ? 1 : -1;
        eq.add(nu(W.Wn.col(i)), closing);
        eq.add(VectorQ(pt(i) + sigma * mu * pn(i)), 0);
        in.add(pn(i), 0);
        in.add(VectorQ(sigma * nu(W.Wt.col(i))), 0);
        break;
      }
      case ContactMode::kStick:
        eq.add(nu(W.Wn.col(i)), closing);
        eq.add(nu(W.Wt.col(i)), 0);
        in.add(pn(i), 0);
        in.add(VectorQ(mu * pn(i) - pt(i)), 0);
        in.add(VectorQ(mu * pn(i) + pt(i)), 0);
        break;
    }
  }
  return {eq.matrix(n), eq.vector(), in.matrix(n), in.vector()};
}

std::vector<Outcome> enumerate_outcomes(const Scene& scene, const VectorQ& p_ext, RunControl* control) {
  const internal::ControlScopeIfGiven scope(control);  // its exact steps poll it too
  check_scene_values(scene);                           // the scene before the impulse measured against it
  check_impulse(scene, p_ext);
  const int nc = scene.num_contacts(), n = scene.body.dof + 2 * nc;
  const ContactMatrices W = contact_matrices(scene);
  std::vector<Outcome> out;
  std::vector<ModeSystem> families;  // the singular modes holding two or more points
  long total = 1;
  for (int i = 0; i < nc; ++i) total *= 4;
  const internal::ExactTask task("outcomes of one step");  // for a caller's scope (seat --impulse)
  for (long code = 0; code < total; ++code) {
    poll(control, "solutions", code, total, "contact modes");
    internal::poll_exact_step();
    const std::vector<ContactMode> modes = contact_modes(code, nc);
    const ModeSystem sys = mode_system(scene, modes, p_ext);

    VectorQ x;
    bool isolated = true;
    const auto lu = internal::exact_lu(sys.A_eq);
    if (sys.A_eq.rows() == n && lu.isInvertible()) {
      x = lu.solve(sys.b_eq);
      if (((sys.A_in * x - sys.b_in).array() < Rational(0)).any()) continue;
    } else {
      // Singular mode: a family of outcomes or none; the exact LP finds one.
      std::vector<internal::LinearConstraint> rows;
      for (int r = 0; r < sys.A_eq.rows(); ++r)
        rows.push_back({sys.A_eq.row(r).transpose(), internal::Relation::kEqual, sys.b_eq[r]});
      for (int r = 0; r < sys.A_in.rows(); ++r)
        rows.push_back({sys.A_in.row(r).transpose(), internal::Relation::kGreaterEqual, sys.b_in[r]});
      const internal::LpResult lp = internal::solve_lp(n, rows);
      if (lp.status == internal::LpStatus::kInfeasible) continue;
      x = lp.x;
      // Singular equations may still leave one point, pinned by the
      // inequalities; only a set of two or more is a family.
      isolated = !holds_a_family(n, rows, sys.A_eq, x);
      if (!isolated) families.push_back(sys);
      // A family may hold seating and non-seating outcomes: for each open
      // contact, maximise its gap W_n,iᵀν⁺ (exact LP) and report a point
      // where it is positive, so that no non-seating outcome is missed.
      for (int i = 0; i < nc; ++i) {
        if (modes[i] != ContactMode::kOpen) continue;
        VectorQ objective = VectorQ::Zero(n);
        objective.head(scene.body.dof) = -W.Wn.col(i);  // minimise −gap
        const internal::LpResult best = internal::solve_lp(n, rows, objective);
        VectorQ y = best.x;
        if (best.status == internal::LpStatus::kUnbounded) {
          // Unbounded gap: add gap_i >= 1 (beyond the closing value) to get a point.
          auto bounded = rows;
          VectorQ g = VectorQ::Zero(n);
          g.head(scene.body.dof) = W.Wn.col(i);
          bounded.push_back(
              {g, internal::Relation::kGreaterEqual, Rational(1) - scene.fixels[i].gap / scene.time_step});
          y = internal::solve_lp(n, bounded).x;
        }
        if (y.size() == 0) continue;
        Outcome o = make_outcome(scene, W, modes, y, isolated);
        if (o.seated) continue;
        bool seen = false;
        for (const auto& prev : out) seen = seen || same_outcome(prev, o);
        if (!seen) out.push_back(std::move(o));
      }
    }
    Outcome o = make_outcome(scene, W, modes, x, isolated);
    bool seen = false;
    for (const auto& prev : out) seen = seen || same_outcome(prev, o);
    if (!seen) out.push_back(std::move(o));
  }
  // An outcome lying in a family's set, whichever mode listed it (a family
  // meets regular modes' outcomes at its ends), is not isolated.
  for (auto& o : out)
    for (const auto& family : families) o.isolated = o.isolated && !in_mode_set(family, o);
  return out;
}

Outcome outcome_from_lcp_solution(const Scene& scene, const VectorQ& p_ext, const VectorQ& z) {
  check_impulse(scene, p_ext);
  const int dof = scene.body.dof, nc = scene.num_contacts();
  if (z.size() != 4 * nc) throw InputError("z", std::to_string(z.size()) + " entries", "must have 4 n_c entries");
  const ContactMatrices W = contact_matrices(scene);
  VectorQ x(dof + 2 * nc);
  const VectorQ p_n = z.head(nc);
  VectorQ p_t(nc);
  for (int i = 0; i < nc; ++i) p_t[i] = z[nc + 2 * i] - z[nc + 2 * i + 1];
  const VectorQ rhs = W.Wn * p_n + W.Wt * p_t + p_ext;
  VectorQ nu = scene.body.velocity;
  for (int k = 0; k < dof; ++k) nu[k] += rhs[k] / W.M(k, k);
  x << nu, p_n, p_t;
  // The modes are not recorded for an LCP solution; report them from signs.
  std::vector<ContactMode> modes(nc);
  for (int i = 0; i < nc; ++i) {
    const Rational vt = W.Wt.col(i).dot(nu);
    modes[i] = p_n[i] == 0
                   ? ContactMode::kOpen
                   : (vt > 0 ? ContactMode::kSlidePlus : (vt < 0 ? ContactMode::kSlideMinus : ContactMode::kStick));
  }
  return make_outcome(scene, W, modes, x, true);
}

bool same_outcome(const Outcome& a, const Outcome& b) {
  return a.velocity == b.velocity && a.p_n == b.p_n && a.p_t == b.p_t;
}

OutcomeCount count_outcomes(const std::vector<Outcome>& outcomes) {
  OutcomeCount c;
  c.total = static_cast<int>(outcomes.size());
  for (const auto& o : outcomes) c.seating += o.seated ? 1 : 0;
  return c;
}

}  // namespace fixel
