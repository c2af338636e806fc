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
  ordered body;
  body["dof"] = s.body.dof;
  // A value the outline gave (uniform density) is left out, so that reading
  // the file derives it again, exactly, and says so ("from_area", info's
  // warning on a defaulted mass).
  const bool outline = s.body.boundary != nullptr && !with_derived;
  if (!(outline && s.body.mass_from_area)) body["mass"] = to_string(s.body.mass);
  if (s.body.dof == 3 && !(outline && s.body.inertia_from_area)) body["inertia"] = to_string(s.body.inertia);
  body["velocity"] = texts(s.body.velocity);
  if (!(outline && s.body.center_of_mass_from_area)) body["center_of_mass"] = pair(s.body.p_AoCm_A);
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
