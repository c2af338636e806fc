// Writing a scene in the scene-file format (docs/formats.md): the inverse of
// parse_scene, every number an exact string.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/internal/file_write.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"

namespace fixel {

namespace {

using ordered = nlohmann::ordered_json;  // the file's fields in the documented order

ordered pair(const Vec2& v) { return ordered::array({to_string(v.x), to_string(v.y)}); }

ordered texts(const VectorQ& v) {
  ordered out = ordered::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(to_string(v[i]));
  return out;
}

ordered friction(const Rational& lo, const std::optional<Rational>& hi) {
  if (hi) return ordered::array({to_string(lo), to_string(*hi)});
  return to_string(lo);
}

ordered curve(const Curve& c) {
  ordered d;
  ordered points = ordered::array();
  for (const auto& p : c.points) points.push_back(pair(p));
  if (c.type == Curve::Type::kPolyline) {
    d["type"] = "polyline";
    d["points"] = std::move(points);
    return d;
  }
  d["type"] = "bspline";
  d["degree"] = c.degree;
  ordered knots = ordered::array();
  for (const auto& k : c.knots) knots.push_back(to_string(k));
  d["knots"] = std::move(knots);
  d["control_points"] = std::move(points);
  return d;
}

}  // namespace

std::string write_scene(const Scene& s, bool with_derived) {
  check_scene_values(s);  // no file that parse_scene would refuse (an empty velocity set in code)
  ordered body;
  body["dof"] = s.body.dof;
  // A value the outline gave (uniform density) is left out, so that reading
  // the file derives it again, exactly, and says so ("from_area", info's
  // warning on a defaulted mass). Only while it still is what reading would
  // derive: a value set in code after loading (the flags are plain fields)
  // is written.
  const Body& b = s.body;
  const MassProperties* derived = b.boundary != nullptr && !with_derived ? &b.boundary->mass : nullptr;
  const bool omit_mass = derived && b.mass_from_area && b.mass == derived->area;
  const bool omit_com = derived && b.center_of_mass_from_area && b.p_AoCm_A.x == derived->centroid.x &&
                        b.p_AoCm_A.y == derived->centroid.y;
  const bool omit_inertia = derived && b.dof == 3 && b.inertia_from_area && derived->area != 0 &&
                            b.inertia == b.mass / derived->area * derived->polar_moment_about(b.p_AoCm_A);
  if (!omit_mass) body["mass"] = to_string(b.mass);
  if (b.dof == 3 && !omit_inertia) body["inertia"] = to_string(b.inertia);
  body["velocity"] = texts(b.velocity);
  if (!omit_com) body["center_of_mass"] = pair(b.p_AoCm_A);
  if (s.body.boundary) {
    ordered curves = ordered::array();
    for (const auto& c : s.body.boundary->curves) curves.push_back(curve(c));
    body["boundary"] = std::move(curves);
  }
  ordered fixels = ordered::array();
  for (const auto& f : s.fixels) {
    ordered d;
    d["point"] = pair(f.p_AoF_A);
    d["normal"] = pair(f.n_A);
    d["mu"] = friction(f.mu, f.mu_hi);
    d["gap"] = to_string(f.gap);
    if (f.off_boundary) d["off_boundary"] = true;
    fixels.push_back(std::move(d));
  }
  ordered d;
  d["name"] = s.name;
  if (!s.description.empty()) d["description"] = s.description;
  d["time_step"] = to_string(s.time_step);
  d["body"] = std::move(body);
  d["fixels"] = std::move(fixels);
  d["pusher"] = {{"mu", friction(s.pusher_mu, s.pusher_mu_hi)}};
  d["background_impulse"] = texts(s.background_impulse);
  // A name set in code may hold invalid UTF-8: replaced, not thrown.
  return d.dump(1, ' ', false, ordered::error_handler_t::replace) + "\n";
}

void save_scene(const Scene& scene, const std::string& path) {
  const std::string text = write_scene(scene);
  // A scene is read back: a FIFO or device is refused, not written into.
  internal::write_file(
      path, "save_scene(path)", [&](std::ostream& out) { out << text; }, internal::SpecialFile::kRefuse);
}

}  // namespace fixel
