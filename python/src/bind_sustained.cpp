/// @file
/// The sustained-push set J at the seated pose (docs/theory.md §10) and its
/// pushing region. Exact values cross as text; the JSON document of
/// `fixel seat --sustained --json` carries the cones and the seated pose.

#include <memory>
#include <optional>

#include "bindings.h"
#include "fixel/io.h"
#include "fixel/physics.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/sustained.h"
#include "fixel/svg.h"

namespace fixel::python {

using ScenePtr = std::shared_ptr<Scene>;
using SustainedPtr = std::shared_ptr<SustainedSet>;

void bind_sustained(py::module_& m) {
  py::class_<SustainedSet, SustainedPtr>(m, "SustainedSet")
      .def_readonly("empty", &SustainedSet::empty)
      .def_readonly("empty_reason", &SustainedSet::empty_reason)
      .def_readonly("strongly_stable", &SustainedSet::strongly_stable)
      .def_readonly("pieces_decided", &SustainedSet::pieces_decided)
      .def_property_readonly("mu",
                             [](const SustainedSet& J) {
                               std::vector<std::string> out;
                               for (const auto& m : J.mu) out.push_back(to_string(m));
                               return out;
                             })
      .def("why_not", [](const SustainedSet& J, const std::vector<std::string>& w) {
        return J.why_not(exact_vector(w, 3, "wrench"));
      });
  m.def("sustained_set", [](const ScenePtr& scene) {
    const Scene& s = checked(scene, "scene");
    py::gil_scoped_release release;
    return std::make_shared<SustainedSet>(sustained_set(s));
  });
  m.def("sustained_json", [](const ScenePtr& scene, const SustainedPtr& J) {
    return sustained_json(checked(scene, "scene"), checked(J, "sustained"), std::nullopt);
  });
  // The Box2D check: the `fixel push --json` document (a measurement).
  m.def("push", [](const ScenePtr& scene, const std::optional<std::vector<std::string>>& wrench,
                   const std::optional<std::string>& at, const std::string& time, Control* control) {
    const Scene& s = checked(scene, "scene");
    physics::PushOptions options;
    options.time = parse_rational(time, "time");
    if (options.time <= 0) throw InputError("time", time, "must be > 0");
    if (options.time * options.steps_per_h > physics::kMaxPushSteps)  // the core's limit, named as Python's argument
      throw InputError("time", time,
                       "holds the push for more than " + std::to_string(physics::kMaxPushSteps) + " engine steps (" +
                           std::to_string(options.steps_per_h) + " per h)");
    options.control = run_control(control);
    physics::Wrench w;
    if (at) {
      const auto point = physics::parse_curve_point(s, *at, "at");
      const auto q = seated_pose(s).approx;
      w = physics::push_wrench_at(s, point.curve, point.u, {q[0], q[1], q[2]}, "at");
    } else if (wrench) {
      w = physics::to_wrench(exact_vector(*wrench, s.body.dof, "wrench"), s.body.dof, "wrench");
    } else {
      throw InputError("wrench", "None", "or at= is required");
    }
    py::gil_scoped_release release;
    const auto r = physics::push(s, w, options);
    return physics::push_json(s, w, r);
  });
  m.def("compute_region_sustained",
        [](const ScenePtr& scene, const SustainedPtr& J, const std::string& resolution, const std::string& cone,
           const std::optional<std::string>& pusher_mu, bool exact, int digits,
           const std::optional<std::string>& resolution_length, Control* control) {
          RegionOptions options = region_options(resolution, cone, pusher_mu, exact, digits, resolution_length);
          options.control = run_control(control);
          const Scene& s = checked(scene, "scene");
          const SustainedSet& j = checked(J, "sustained");
          py::gil_scoped_release release;
          const auto target = sustained_target(j);
          return std::make_shared<Region>(compute_region(s, *target, options));
        });
}

}  // namespace fixel::python
