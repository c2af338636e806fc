/// @file
/// Scene bindings: parse/load with the library's own validation, an exact
/// dict view (scene.to_dict) and display-only samples of the outline.

#include <cmath>
#include <memory>

#include "bindings.h"
#include "fixel/curve.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"

namespace fixel::python {
namespace {

using ScenePtr = std::shared_ptr<Scene>;

py::list pair(const Vec2& v) {
  py::list out;
  out.append(to_string(v.x));
  out.append(to_string(v.y));
  return out;
}

py::dict curve_dict(const Curve& c) {
  py::dict d;
  py::list points;
  for (const auto& p : c.points) points.append(pair(p));
  if (c.type == Curve::Type::kPolyline) {
    d["type"] = "polyline";
    d["points"] = points;
  } else {
    d["type"] = "bspline";
    d["degree"] = c.degree;
    py::list knots;
    for (const auto& k : c.knots) knots.append(to_string(k));
    d["knots"] = knots;
    d["control_points"] = points;
  }
  return d;
}

// Every field written explicitly (derived defaults included), in the scene
// file format, so that parse_scene(to_dict) gives back the same scene.
py::dict scene_dict(const Scene& s) {
  py::dict body;
  body["dof"] = s.body.dof;
  body["mass"] = to_string(s.body.mass);
  if (s.body.dof == 3) body["inertia"] = to_string(s.body.inertia);
  body["velocity"] = texts(s.body.velocity);
  body["center_of_mass"] = pair(s.body.p_AoCm_A);
  if (s.body.boundary) {
    py::list curves;
    for (const auto& c : s.body.boundary->curves) curves.append(curve_dict(c));
    body["boundary"] = curves;
  }
  py::list fixels;
  for (const auto& f : s.fixels) {
    py::dict d;
    d["point"] = pair(f.p_AoF_A);
    d["normal"] = pair(f.n_A);
    d["mu"] = to_string(f.mu);
    d["gap"] = to_string(f.gap);
    if (f.off_boundary) d["off_boundary"] = true;
    fixels.append(d);
  }
  py::dict pusher;
  pusher["mu"] = to_string(s.pusher_mu);
  py::dict d;
  d["name"] = s.name;
  if (!s.description.empty()) d["description"] = s.description;
  d["time_step"] = to_string(s.time_step);
  d["body"] = body;
  d["fixels"] = fixels;
  d["pusher"] = pusher;
  d["background_impulse"] = texts(s.background_impulse);
  return d;
}

const Curve& curve_at(const Scene& s, int k) {
  if (!s.body.boundary) throw SceneError("body.boundary", "(none)", "is needed here: the scene has no outline");
  const auto& curves = s.body.boundary->curves;
  if (k < 0 || k >= static_cast<int>(curves.size()))
    throw InputError("curve", std::to_string(k), "is not a curve index of body.boundary");
  return curves[static_cast<std::size_t>(k)];
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<Scene, ScenePtr>(m, "Scene")
      .def_property_readonly("name", [](const Scene& s) { return s.name; })
      .def_property_readonly("dof", [](const Scene& s) { return s.body.dof; })
      .def_property_readonly("num_contacts", &Scene::num_contacts)
      .def_property_readonly("pusher_mu", [](const Scene& s) { return to_string(s.pusher_mu); })
      .def_property_readonly("has_boundary", [](const Scene& s) { return s.body.boundary != nullptr; })
      .def_property_readonly("num_curves",
                             [](const Scene& s) { return s.body.boundary ? s.body.boundary->curves.size() : 0; })
      .def("to_dict", &scene_dict);

  m.def(
      "parse_scene",
      [](const std::string& text, const std::string& source, Control* control) {
        py::gil_scoped_release release;
        return std::make_shared<Scene>(parse_scene(text, source, run_control(control)));
      },
      py::arg("text"), py::arg("source") = "scene", py::arg("control") = nullptr);
  m.def(
      "load_scene",
      [](const std::string& path, Control* control) {
        py::gil_scoped_release release;
        return std::make_shared<Scene>(load_scene(path, run_control(control)));
      },
      py::arg("path"), py::arg("control") = nullptr);

  // The core's reading of one number (fixel.exact): its exact text "p/q".
  m.def("parse_rational",
        [](const std::string& text, const std::string& field) { return to_string(parse_rational(text, field)); });
  // (u_begin, u_end) of curve k, exact.
  m.def("curve_range", [](const Scene& s, int k) {
    const Curve& c = curve_at(s, k);
    return std::make_pair(to_string(c.u_begin()), to_string(c.u_end()));
  });
  // Display only: n + 1 points at u0 + j (u1 − u0) / n, evaluated exactly, then rounded.
  m.def("sample_curve", [](const Scene& s, int k, const std::string& u0_text, const std::string& u1_text, int n) {
    const Curve& c = curve_at(s, k);
    if (n < 1) throw InputError("n", std::to_string(n), "must be at least 1");
    const Rational u0 = parse_rational(u0_text, "u0"), u1 = parse_rational(u1_text, "u1");
    if (u0 < c.u_begin() || u1 > c.u_end() || u1 < u0)
      throw InputError("u", "[" + u0_text + ", " + u1_text + "]", "is not inside the curve's parameter range");
    std::vector<std::pair<double, double>> out;
    for (int j = 0; j <= n; ++j) {
      const Vec2 p = c.point(u0 + (u1 - u0) * Rational(j, n));
      out.emplace_back(to_double(p.x), to_double(p.y));
    }
    return out;
  });
  // Display only: the frictionless push wrench (n, r × n) / |n| at the same
  // samples, n the inward normal (the loop is counter-clockwise) and r the
  // lever arm from the centre of mass; None where the tangent vanishes.
  m.def("sample_wrench", [](const Scene& s, int k, const std::string& u0_text, const std::string& u1_text, int n) {
    const Curve& c = curve_at(s, k);
    if (n < 1) throw InputError("n", std::to_string(n), "must be at least 1");
    const Rational u0 = parse_rational(u0_text, "u0"), u1 = parse_rational(u1_text, "u1");
    if (u0 < c.u_begin() || u1 > c.u_end() || u1 < u0)
      throw InputError("u", "[" + u0_text + ", " + u1_text + "]", "is not inside the curve's parameter range");
    py::list out;
    for (int j = 0; j <= n; ++j) {
      const Rational u = u0 + (u1 - u0) * Rational(j, n);
      const Vec2 p = c.point(u), t = c.derivative(u);
      const double nx = -to_double(t.y), ny = to_double(t.x), len = std::hypot(nx, ny);
      const double rx = to_double(p.x - s.body.p_AoCm_A.x), ry = to_double(p.y - s.body.p_AoCm_A.y);
      if (len == 0)
        out.append(py::none());
      else
        out.append(py::make_tuple(nx / len, ny / len, (rx * ny - ry * nx) / len));
    }
    return out;
  });
}

}  // namespace fixel::python
