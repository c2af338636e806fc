// `fixel info` as text and JSON: exact values, decimals beside them, units.
#include "fixel/io_info.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fixel/internal/json_exact.h"
#include "fixel/io.h"

namespace fixel {

namespace {

using json = nlohmann::ordered_json;

std::string dec(double v) {
  if (std::abs(v) < 1e-12) v = 0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// "p/q ≈ d" (the decimal only when the value is not an integer).
std::string both(const Rational& v) {
  const std::string s = to_string(v);
  return boost::multiprecision::denominator(v) == 1 ? s : s + " ≈ " + dec(to_double(v));
}
std::string both(const Vec2& v) {
  const std::string s = "(" + to_string(v.x) + ", " + to_string(v.y) + ")";
  const bool integral = boost::multiprecision::denominator(v.x) == 1 && boost::multiprecision::denominator(v.y) == 1;
  return integral ? s : s + " ≈ (" + dec(to_double(v.x)) + ", " + dec(to_double(v.y)) + ")";
}
std::string both(const VectorQ& v) {
  std::string s = "(", d = "(";
  bool integral = true;
  for (int k = 0; k < v.size(); ++k) {
    s += (k ? ", " : "") + to_string(v[k]);
    d += (k ? ", " : "") + dec(to_double(v[k]));
    integral = integral && boost::multiprecision::denominator(v[k]) == 1;
  }
  return integral ? s + ")" : s + ") ≈ " + d + ")";
}

json quantity(const Rational& v, const char* unit) {
  return {{"exact", to_string(v)}, {"approx", to_double(v)}, {"unit", unit}};
}
json quantity(const Vec2& v, const char* unit) {
  return {{"exact", json::array({to_string(v.x), to_string(v.y)})},
          {"approx", json::array({to_double(v.x), to_double(v.y)})},
          {"unit", unit}};
}
using internal::exact_json;

}  // namespace

std::string scene_info_text(const Scene& scene, const SceneInfo& info) {
  std::ostringstream out;
  const Body& b = scene.body;
  out << "Scene \"" << scene.name << "\"\n";
  if (!scene.description.empty()) out << "  " << scene.description << "\n";
  out << "frame A: the part's body frame at the scene pose, axes along the world's; lengths in m\n";
  out << "time step h = " << both(scene.time_step) << " s\n";
  out << "body: dof " << b.dof << (b.dof == 2 ? " (point mass)" : " (planar rigid body)") << "\n";
  out << "  mass m = " << both(b.mass) << " kg" << (b.mass_from_area ? " (defaulted: the area at density 1 kg/m²)" : "")
      << "\n";
  out << "  centre of mass c = " << both(b.p_AoCm_A) << " m"
      << (b.center_of_mass_from_area ? " (the area centroid)" : (b.boundary ? " (given)" : "")) << "\n";
  if (b.dof == 3)
    out << "  inertia I = " << both(b.inertia) << " kg·m² about c"
        << (b.inertia_from_area ? " (uniform density m / area)" : " (given)") << "\n";
  out << "  velocity ν = " << both(b.velocity) << (b.dof == 3 ? " (m/s, m/s, rad/s)" : " m/s") << "\n";
  if (info.area) {
    // Straight edges apart: "Bézier pieces" alone read as curved ones.
    std::size_t edges = 0;
    std::map<int, std::size_t> curved;  // degree -> pieces
    for (const auto& p : b.boundary->pieces) p.degree() == 1 ? ++edges : ++curved[p.degree()];
    out << "  outline: " << b.boundary->curves.size() << " curve(s), ";
    if (edges > 0) out << edges << " straight edge(s)" << (curved.empty() ? "" : ", ");
    std::size_t k = 0;
    for (const auto& [degree, n] : curved) out << (k++ ? ", " : "") << n << " Bézier piece(s) of degree " << degree;
    out << ", area " << both(*info.area) << " m²\n";
  } else
    out << "  outline: none (no pushing region, push or seated pose)\n";
  out << "fixels: point p on the part at the scene pose, inward unit normal n; the fixel sits at p − ψ n\n";
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const Fixel& f = scene.fixels[i];
    out << "  " << i << ": p = " << both(f.p_AoF_A) << " m, n = " << both(f.n_A)
        << ", mu = " << (f.mu_hi ? "[" + to_string(f.mu) + ", " + to_string(*f.mu_hi) + "]" : to_string(f.mu))
        << ", gap ψ = " << both(f.gap) << " m\n";
    out << "     fixel at f = p − ψ n = " << both(info.p_AoFixel_A[i]) << " m";
    if (i < info.on_outline.size()) {
      const BoundaryFit& fit = info.on_outline[i];
      if (f.off_boundary)
        out << "; marked off_boundary ("
            << (fit.on_boundary ? "point on the outline, normal " + dec(fit.angle_degrees) + "° off"
                                : "point " + dec(fit.distance) + " m off the outline")
            << ")";
      else
        out << "; on body.boundary[" << fit.curve << "] at u = " << (fit.u ? both(*fit.u) : "≈ " + dec(fit.u_approx))
            << (fit.corner ? " (a corner)" : "");
    }
    out << "\n";
  }
  out << "pusher: mu = "
      << (scene.pusher_mu_hi ? "[" + to_string(scene.pusher_mu) + ", " + to_string(*scene.pusher_mu_hi) + "]"
                             : to_string(scene.pusher_mu))
      << "\n";
  out << "background impulse b₀ = " << both(scene.background_impulse) << (b.dof == 3 ? " (N·s, N·s, N·m·s)" : " N·s")
      << "\n";
  if (info.seated) {
    const SeatedPose& q = *info.seated;
    out << "seated configuration q* (every fixel touching): x ≈ " << dec(q.approx[0]) << " m, y ≈ " << dec(q.approx[1])
        << " m, θ ≈ " << dec(q.approx[2]) << " rad"
        << (q.at_scene_pose ? " (the scene pose: every gap is 0)"
                            : (q.exact ? " (exact in a quadratic field)" : " (certified enclosure)"))
        << "\n";
    if (q.exact && !q.at_scene_pose)
      out << "  exact: x = " << (*q.exact)[0].text() << ", y = " << (*q.exact)[1].text()
          << ", cos θ = " << (*q.exact)[2].text() << ", sin θ = " << (*q.exact)[3].text() << "\n";
  } else {
    out << "seated configuration q*: not available: " << info.seated_unavailable << "\n";
  }
  for (const auto& w : info.warnings) out << "warning: " << w << "\n";
  return out.str();
}

std::string scene_info_json(const Scene& scene, const SceneInfo& info) {
  const Body& b = scene.body;
  json doc;
  doc["scene"] = scene.name;
  doc["description"] = scene.description;
  doc["dof"] = b.dof;
  doc["time_step"] = quantity(scene.time_step, "s");
  json mass = quantity(b.mass, "kg");
  mass["from_area"] = b.mass_from_area;
  doc["mass"] = mass;
  json com = quantity(b.p_AoCm_A, "m");
  com["from_area"] = b.center_of_mass_from_area;
  doc["center_of_mass"] = com;
  if (b.dof == 3) {
    json inertia = quantity(b.inertia, "kg·m²");
    inertia["from_area"] = b.inertia_from_area;
    doc["inertia"] = inertia;
  } else {
    doc["inertia"] = nullptr;
  }
  doc["velocity"] = exact_json(b.velocity);
  doc["area"] = info.area ? quantity(*info.area, "m²") : json(nullptr);
  json fixels = json::array();
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const Fixel& f = scene.fixels[i];
    json fx = {{"point", quantity(f.p_AoF_A, "m")},
               {"normal", json::array({to_string(f.n_A.x), to_string(f.n_A.y)})},
               {"mu", f.mu_hi ? json::array({to_string(f.mu), to_string(*f.mu_hi)}) : json(to_string(f.mu))},
               {"gap", quantity(f.gap, "m")},
               {"fixel", quantity(info.p_AoFixel_A[i], "m")},
               {"off_boundary", f.off_boundary}};
    if (i < info.on_outline.size()) {
      const BoundaryFit& fit = info.on_outline[i];
      fx["on_outline"] = {{"point_on", fit.on_boundary},
                          {"normal_matches", fit.normal_matches},
                          {"curve", fit.curve},
                          {"u", fit.u ? json(to_string(*fit.u)) : json(nullptr)},
                          {"u_approx", fit.u_approx},
                          {"corner", fit.corner},
                          {"distance_approx", fit.distance},
                          {"angle_degrees_approx", fit.angle_degrees}};
    }
    fixels.push_back(fx);
  }
  doc["fixels"] = fixels;
  doc["pusher_mu"] = scene.pusher_mu_hi ? json::array({to_string(scene.pusher_mu), to_string(*scene.pusher_mu_hi)})
                                        : json(to_string(scene.pusher_mu));
  doc["background_impulse"] = exact_json(scene.background_impulse);
  if (info.seated)
    doc["seated_pose"] = json::parse(seated_pose_json(*info.seated));
  else
    doc["seated_pose"] = nullptr;
  if (!info.seated) doc["seated_pose_unavailable"] = info.seated_unavailable;
  doc["warnings"] = info.warnings;
  return doc.dump(2) + "\n";
}

}  // namespace fixel
