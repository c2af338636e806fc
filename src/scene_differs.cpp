#include "fixel/internal/scene_differs.h"

#include "fixel/curve.h"
#include "fixel/error.h"

namespace fixel::internal {

namespace {

bool same(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }

std::string text(const Vec2& v) { return "(" + to_string(v.x) + ", " + to_string(v.y) + ")"; }

std::string text(const VectorQ& v) {
  std::string out = "(";
  for (int i = 0; i < v.size(); ++i) out += (i ? ", " : "") + to_string(v[i]);
  return out + ")";
}

std::string text(const std::optional<Rational>& v) { return v ? to_string(*v) : "none"; }

template <class T>
std::string differs(const std::string& field, const T& here, const T& there) {
  return field + " is " + text(here) + " here, " + text(there) + " in the scene it was built from";
}

std::string differs(const std::string& field, const Rational& here, const Rational& there) {
  return field + " is " + to_string(here) + " here, " + to_string(there) + " in the scene it was built from";
}

bool same_vector(const VectorQ& a, const VectorQ& b) { return a.size() == b.size() && a == b; }

std::string outline_difference(const Scene& a, const Scene& b) {
  const auto &p = a.body.boundary, &q = b.body.boundary;
  if (p == q) return "";
  if (!p || !q)
    return std::string("body.boundary is ") + (q ? "given" : "absent") + " here, " + (p ? "given" : "absent") +
           " in the scene it was built from";
  if (p->pieces.size() != q->pieces.size())
    return "body.boundary has " + std::to_string(q->pieces.size()) + " Bezier pieces here, " +
           std::to_string(p->pieces.size()) + " in the scene it was built from";
  for (std::size_t k = 0; k < p->pieces.size(); ++k) {
    const BezierPiece &x = p->pieces[k], &y = q->pieces[k];
    bool same_piece = x.curve == y.curve && x.u0 == y.u0 && x.u1 == y.u1 && x.control.size() == y.control.size();
    for (std::size_t j = 0; same_piece && j < x.control.size(); ++j) same_piece = same(x.control[j], y.control[j]);
    if (!same_piece)
      return "body.boundary's Bezier piece " + std::to_string(k) + " (curve " + std::to_string(y.curve) +
             ") differs from the scene it was built from";
  }
  return "";
}

}  // namespace

std::string scene_difference(const Scene& a, const Scene& b, unsigned reads) {
  if ((reads & (kReadsOutline | kReadsStep)) && a.body.dof != b.body.dof)
    return "body.dof is " + std::to_string(b.body.dof) + " here, " + std::to_string(a.body.dof) +
           " in the scene it was built from";
  if (reads & kReadsOutline) {
    const std::string outline = outline_difference(a, b);
    if (!outline.empty()) return outline;
  }
  if (reads & kReadsStep) {
    if (a.time_step != b.time_step) return differs("time_step", b.time_step, a.time_step);
    if (!same_vector(a.body.velocity, b.body.velocity))
      return differs("body.velocity", b.body.velocity, a.body.velocity);
  }
  if (reads & kReadsMass) {
    if (a.body.mass != b.body.mass) return differs("body.mass", b.body.mass, a.body.mass);
    if (a.body.inertia != b.body.inertia) return differs("body.inertia", b.body.inertia, a.body.inertia);
    if (!same(a.body.p_AoCm_A, b.body.p_AoCm_A))
      return differs("body.center_of_mass", b.body.p_AoCm_A, a.body.p_AoCm_A);
  }
  if (reads & (kReadsFixels | kReadsFixelLowerMu)) {
    if (a.fixels.size() != b.fixels.size())
      return "fixels has " + std::to_string(b.fixels.size()) + " fixels here, " + std::to_string(a.fixels.size()) +
             " in the scene it was built from";
    for (std::size_t i = 0; i < a.fixels.size(); ++i) {
      const Fixel &f = a.fixels[i], &g = b.fixels[i];
      const std::string at = "fixels[" + std::to_string(i) + "]";
      if (reads & kReadsFixels) {
        if (!same(f.p_AoF_A, g.p_AoF_A)) return differs(at + ".point", g.p_AoF_A, f.p_AoF_A);
        if (!same(f.n_A, g.n_A)) return differs(at + ".normal", g.n_A, f.n_A);
        if (f.gap != g.gap) return differs(at + ".gap", g.gap, f.gap);
        if (f.mu_upper() != g.mu_upper())
          return differs(at + (f.mu_hi || g.mu_hi ? ".mu (its upper end)" : ".mu"), g.mu_upper(), f.mu_upper());
      }
      if ((reads & kReadsFixelLowerMu) && f.mu != g.mu) return differs(at + ".mu (its lower end)", g.mu, f.mu);
    }
  }
  if ((reads & kReadsBackground) && !same_vector(a.background_impulse, b.background_impulse))
    return differs("background_impulse", b.background_impulse, a.background_impulse);
  if (reads & kReadsPusher) {
    if (a.pusher_mu != b.pusher_mu) return differs("pusher.mu", b.pusher_mu, a.pusher_mu);
    if (a.pusher_mu_hi != b.pusher_mu_hi) return differs("pusher.mu (its upper end)", b.pusher_mu_hi, a.pusher_mu_hi);
  }
  return "";
}

unsigned region_reads(const std::string& target) {
  if (target == "J" || target == "J'") return kReadsOutline | kReadsMass | kReadsFixels;
  return kReadsAll & ~kReadsPusher;
}

void check_same_scene(const Scene* built_from, const Scene& given, unsigned reads, const std::string& set_name) {
  if (built_from == nullptr) return;
  const std::string difference = scene_difference(*built_from, given, reads);
  if (difference.empty()) return;
  throw InputError(
      set_name, "built from scene \"" + built_from->name + "\"",
      "belongs to another scene than \"" + given.name + "\": " + difference + "; build it from this scene");
}

}  // namespace fixel::internal
