/// @file
/// The sustained-push set J at the seated pose (docs/theory.md §10) and its
/// pushing region. Exact values cross as text; the JSON document of
/// `fixel seat --sustained --json` carries the cones and the seated pose.

#include <memory>
#include <optional>

#include "bindings.h"
#include "fixel/approach.h"
#include "fixel/io.h"
#include "fixel/physics.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/sustained.h"
#include "fixel/svg.h"

namespace fixel::python {

using ScenePtr = std::shared_ptr<Scene>;
using SustainedPtr = std::shared_ptr<SustainedSet>;
using ApproachPtr = std::shared_ptr<ApproachSet>;

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
  m.def("sustained_set", [](const ScenePtr& scene, Control* control) {
    const ControlScope scope(run_control(control));  // its exact steps poll it
    const Scene& s = checked(scene, "scene");
    py::gil_scoped_release release;
    return std::make_shared<SustainedSet>(sustained_set(s));
  });
  py::class_<ApproachSet, ApproachPtr>(m, "ApproachSet")
      .def_readonly("decided", &ApproachSet::decided)
      .def_readonly("undecided_reason", &ApproachSet::undecided_reason)
      .def_property_readonly("t_star", [](const ApproachSet& A) { return A.t_star.text(); })
      .def_readonly("theta_star", &ApproachSet::theta_star)
      .def_readonly("on_edges", &ApproachSet::on_edges)
      .def_readonly("edge_reason", &ApproachSet::edge_reason)
      .def_readonly("empty", &ApproachSet::empty)
      // (why_not, hold): hold is None or {"fixels", "theta", "t", "slide"} ("t" exact text or "t_star").
      // part_frame: w in frame B at the seat (ApproachSet::why_not_part_frame).
      .def("why_not", [](const ApproachSet& A, const std::vector<std::string>& w, bool part_frame, Control* control) {
        const ControlScope scope(run_control(control));  // the wrench's test polls it per pair
        const VectorQ v = exact_vector(w, 3, "wrench");
        ApproachHold hold;
        hold.fixels = {-1, -1};
        std::string reason;
        {
          py::gil_scoped_release release;
          reason = part_frame ? A.why_not_part_frame(v, &hold) : A.why_not(v, &hold);
        }
        py::object h = py::none();
        if (hold.fixels[0] >= 0) {
          py::dict d;
          d["fixels"] = py::make_tuple(hold.fixels[0], hold.fixels[1]);
          d["theta"] = hold.theta;
          d["t"] = hold.at_seat
                       ? std::string("t_star")
                       : (hold.t->is_rational() ? to_string(hold.t->lo)
                                                : certified_decimal(refined(*hold.t, parse_rational("1e-13")), 12));
          d["slide"] = hold.slide ? py::object(py::float_(*hold.slide)) : py::none();
          h = d;
        }
        return py::make_tuple(reason, h);
      });
  m.def("approach_set", [](const ScenePtr& scene, const SustainedPtr& J, Control* control) {
    const ControlScope scope(run_control(control));  // its exact steps poll it
    const Scene& s = checked(scene, "scene");
    const SustainedSet& j = checked(J, "sustained");
    py::gil_scoped_release release;
    return std::make_shared<ApproachSet>(approach_set(s, j));
  });
  m.def("sustained_json", [](const ScenePtr& scene, const SustainedPtr& J) {
    return sustained_json(checked(scene, "scene"), checked(J, "sustained"), std::nullopt);
  });
  // The Box2D check: the `fixel push --json` document (a measurement).
  m.def("push", [](const ScenePtr& scene, const std::optional<std::vector<std::string>>& wrench,
                   const std::optional<std::string>& at, const std::string& time, long steps_per_h,
                   int velocity_iterations, int position_iterations, Control* control) {
    const ControlScope scope(run_control(control));  // exact steps inside poll it too
    const Scene& s = checked(scene, "scene");
    const physics::PushOptions options =
        push_options(time, {steps_per_h, velocity_iterations, position_iterations}, control);
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
  m.def("write_sustained_region_svg",
        [](const std::string& path, const ScenePtr& scene, const SustainedPtr& J, const std::shared_ptr<Region>& r) {
          py::gil_scoped_release release;
          write_sustained_region_svg(path, checked(scene, "scene"), checked(J, "sustained"), checked(r, "region"));
        });
  m.def("compute_region_sustained",
        [](const ScenePtr& scene, const SustainedPtr& J, const std::string& resolution, const std::string& cone,
           const std::optional<std::string>& pusher_mu, bool exact, int digits,
           const std::optional<std::string>& resolution_length, const ApproachPtr& approach, Control* control) {
          const ControlScope scope(run_control(control));  // exact steps inside poll it too
          RegionOptions options = region_options(resolution, cone, pusher_mu, exact, digits, resolution_length);
          options.control = run_control(control);
          const Scene& s = checked(scene, "scene");
          const SustainedSet& j = checked(J, "sustained");
          py::gil_scoped_release release;
          // J′ (approach.h) when given, else J.
          const auto target = approach ? approach_target(*approach) : sustained_target(j);
          return std::make_shared<Region>(compute_region(s, *target, options));
        });
}

}  // namespace fixel::python
