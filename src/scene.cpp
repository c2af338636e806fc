#include "fixel/scene.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "fixel/curve.h"
#include "fixel/on_boundary.h"

namespace fixel {

namespace {

const Fixel& fixel_at(const std::vector<Fixel>& fixels, int i, const char* what) {
  if (i < 0 || i >= static_cast<int>(fixels.size()))
    throw InputError(what, std::to_string(i),
                     "is not a fixel index (the scene has " + std::to_string(fixels.size()) + " fixels)");
  return fixels[static_cast<std::size_t>(i)];
}

}  // namespace

Vec2 Scene::lever_arm(int i) const {
  const Vec2& p = fixel_at(fixels, i, "lever_arm(i)").p_AoF_A;
  return {p.x - body.p_AoCm_A.x, p.y - body.p_AoCm_A.y};
}

Vec2 Scene::tangent(int i) const {
  const Vec2& n = fixel_at(fixels, i, "tangent(i)").n_A;
  return {-n.y, n.x};
}

void check_positive(const Rational& v, const std::string& path) {
  if (v <= 0) throw SceneError(path, to_string(v), "must be > 0");
}

void check_nonnegative(const Rational& v, const std::string& path) {
  if (v < 0) throw SceneError(path, to_string(v), "must be >= 0");
}

void check_unit_normal(const Vec2& n_A, const std::string& path) {
  if (n_A.x * n_A.x + n_A.y * n_A.y != 1)
    throw SceneError(path, "(" + to_string(n_A.x) + ", " + to_string(n_A.y) + ")",
                     "is not of unit length (x²+y² must be exactly 1, e.g. (3/5, 4/5))");
}

namespace {

void check_friction(const Rational& lo, const std::optional<Rational>& hi, const std::string& path) {
  check_nonnegative(lo, hi ? path + "[0]" : path);
  if (hi && *hi < lo) throw SceneError(path, "[" + to_string(lo) + ", " + to_string(*hi) + "]", "has lo > hi");
}

void check_length(const VectorQ& v, int dof, const std::string& path) {
  if (v.size() != dof)
    throw SceneError(path, std::to_string(v.size()) + " entries", "but the body has dof " + std::to_string(dof));
}

}  // namespace

namespace {

// Display: six significant digits, and float noise below 1e-9 shown as 0.
std::string num(double v) {
  if (std::abs(v) < 1e-9) v = 0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
std::string pair_text(double x, double y) { return "(" + num(x) + ", " + num(y) + ")"; }
std::string exact_text(const Vec2& v) { return "(" + to_string(v.x) + ", " + to_string(v.y) + ")"; }

}  // namespace

namespace {

// A Boundary assembled by hand rather than by make_boundary: what every
// use of it indexes (pieces, their curves, the mass) must be there. The
// geometry itself is make_boundary's to check.
void check_boundary_shape(const Boundary& boundary) {
  const std::string how = ": build it with make_boundary";
  if (boundary.curves.empty()) throw SceneError("body.boundary", "0 curves", "has no curves" + how);
  if (boundary.pieces.empty()) throw SceneError("body.boundary", "0 pieces", "has no Bezier pieces" + how);
  std::vector<bool> covered(boundary.curves.size(), false);
  for (const auto& piece : boundary.pieces) {
    if (piece.curve < 0 || piece.curve >= static_cast<int>(boundary.curves.size()) || piece.control.size() < 2)
      throw SceneError("body.boundary", "a piece of curve " + std::to_string(piece.curve),
                       "does not match the curves" + how);
    covered[static_cast<std::size_t>(piece.curve)] = true;
  }
  for (std::size_t k = 0; k < covered.size(); ++k)
    if (!covered[k])
      throw SceneError("body.boundary[" + std::to_string(k) + "]", "no pieces", "has no Bezier pieces" + how);
  if (!(boundary.mass.area > 0))
    throw SceneError("body.boundary", "area " + to_string(boundary.mass.area), "must be positive" + how);
}

}  // namespace

void check_fixels_on_boundary(const Scene& scene) {
  if (!scene.body.boundary) return;
  check_boundary_shape(*scene.body.boundary);
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const Fixel& f = scene.fixels[i];
    if (f.off_boundary) continue;
    const std::string path = "fixels[" + std::to_string(i) + "]";
    const BoundaryFit fit = fit_to_boundary(*scene.body.boundary, f.p_AoF_A, &f.n_A);
    const std::string where = "body.boundary[" + std::to_string(fit.curve) + "] at u ≈ " + num(fit.u_approx);
    if (!fit.on_boundary)
      throw SceneError(path + ".point", exact_text(f.p_AoF_A),
                       "is not on the part's outline: it is " + num(fit.distance) + " m from it (nearest point ≈ " +
                           pair_text(fit.nearest[0], fit.nearest[1]) + " on " + where + ", where the inward normal ≈ " +
                           pair_text(fit.inward_normal_approx[0], fit.inward_normal_approx[1]) + " is " +
                           num(fit.angle_degrees) +
                           "° from this fixel's normal). The point is the contact point on the part at the "
                           "scene pose (the fixel sits at point − gap·normal): move it onto the outline, or set " +
                           path + ".off_boundary: true");
    if (!fit.normal_matches)
      throw SceneError(path + ".normal", exact_text(f.n_A),
                       std::string("is not the outline's inward normal at ") + path + ".point (on " + where +
                           (fit.corner ? ", a corner: the normal must lie between the two edges' inward normals, "
                                         "around "
                                       : ", where it is ") +
                           pair_text(fit.inward_normal_approx[0], fit.inward_normal_approx[1]) +
                           "): " + num(fit.angle_degrees) + "° apart. Give \"normal\": \"boundary\", or set " + path +
                           ".off_boundary: true");
  }
}

void validate_scene(const Scene& scene) {
  check_scene_values(scene);
  for (std::size_t i = 0; i < scene.fixels.size(); ++i)
    check_unit_normal(scene.fixels[i].n_A, "fixels[" + std::to_string(i) + "].normal");
  check_fixels_on_boundary(scene);
}

void check_scene_values(const Scene& scene) {
  check_positive(scene.time_step, "time_step");
  const Body& b = scene.body;
  if (b.dof != 2 && b.dof != 3)
    throw SceneError("body.dof", std::to_string(b.dof), "must be 2 (point mass) or 3 (planar rigid body)");
  check_positive(b.mass, "body.mass");
  if (b.dof == 3) check_positive(b.inertia, "body.inertia");
  check_length(b.velocity, b.dof, "body.velocity");
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const std::string path = "fixels[" + std::to_string(i) + "]";
    const Fixel& f = scene.fixels[i];
    check_friction(f.mu, f.mu_hi, path + ".mu");
    check_nonnegative(f.gap, path + ".gap");
    // Unit length is not checked here (design's scenes are not unit), but no
    // analysis means anything with a zero normal.
    if (f.n_A.x == 0 && f.n_A.y == 0) throw SceneError(path + ".normal", "(0, 0)", "must not be zero");
  }
  check_friction(scene.pusher_mu, scene.pusher_mu_hi, "pusher.mu");
  check_length(scene.background_impulse, b.dof, "background_impulse");
  if (b.boundary) check_boundary_shape(*b.boundary);
}

}  // namespace fixel
