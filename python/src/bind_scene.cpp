/// @file
/// Scene bindings: parse/load with the library's own validation, the scene
/// file's text (write_scene, for scene.to_dict and save) and display-only
/// samples of the outline.

#include <cmath>
#include <memory>

#include "bindings.h"
#include "fixel/curve.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"

namespace fixel::python {
namespace {

using ScenePtr = std::shared_ptr<Scene>;

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
      // The value every analysis judges at: an interval's upper end.
      .def_property_readonly("pusher_mu", [](const Scene& s) { return to_string(s.pusher_mu_upper()); })
      .def_property_readonly("has_boundary", [](const Scene& s) { return s.body.boundary != nullptr; })
      .def_property_readonly("num_curves",
                             [](const Scene& s) { return s.body.boundary ? s.body.boundary->curves.size() : 0; })
      // The scene file's text (write_scene): fixel.Scene.to_dict parses it
      // (with_derived: the outline's mass properties written out too).
      .def(
          "to_json", [](const Scene& s, bool with_derived) { return write_scene(s, with_derived); },
          py::arg("with_derived") = true);
  m.def(
      "save_scene",
      [](const Scene& s, const std::string& path) {
        py::gil_scoped_release release;
        save_scene(s, path);
      },
      py::arg("scene"), py::arg("path"));

  m.def(
      "parse_scene",
      [](const std::string& text, const std::string& source, Control* control) {
        const ControlScope scope(run_control(control));  // exact steps inside poll it too
        py::gil_scoped_release release;
        return std::make_shared<Scene>(parse_scene(text, source, run_control(control)));
      },
      py::arg("text"), py::arg("source") = "scene", py::arg("control") = nullptr);
  m.def(
      "load_scene",
      [](const std::string& path, Control* control) {
        const ControlScope scope(run_control(control));  // exact steps inside poll it too
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
