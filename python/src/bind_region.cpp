/// @file
/// The pushing region (compute_region, sample_region) and the file writers
/// (OFF dump, region SVG). The region runs with the GIL released so that a
/// Python thread can report progress meanwhile (fixel/_progress.py).

#include <memory>
#include <optional>

#include "bindings.h"
#include "fixel/guaranteed.h"
#include "fixel/io.h"
#include "fixel/physics.h"
#include "fixel/region.h"
#include "fixel/sustained.h"
#include "fixel/svg.h"

namespace fixel::python {
namespace {

using ScenePtr = std::shared_ptr<Scene>;
using SeatingPtr = std::shared_ptr<SeatingSet>;
using RegionPtr = std::shared_ptr<Region>;

py::object magnitudes(const Magnitudes& m) {
  if (m.empty) return py::none();
  return py::make_tuple(to_string(m.lo), m.lo_closed, m.hi ? py::cast(to_string(*m.hi)) : py::none(),
                        m.hi.has_value() && m.hi_closed);
}

// An irrational end of the exact region: (poly, (lo, hi), approx), the
// integer coefficients c0, c1, … and the isolating interval as exact text.
py::object algebraic_end(const std::optional<AlgebraicReal>& x) {
  if (!x) return py::none();
  py::list poly;
  for (const auto& c : x->poly) poly.append(c.str());
  return py::make_tuple(poly, py::make_tuple(to_string(x->lo), to_string(x->hi)), x->approx());
}

py::dict interval_dict(const RegionInterval& r) {
  py::dict d;
  d["curve"] = r.curve;
  d["u0"] = to_string(r.u0);
  d["u1"] = to_string(r.u1);
  d["status"] = to_string(r.status);
  d["half_line"] = r.half_line;
  // As in `fixel region --json`: magnitudes only on IN intervals.
  d["magnitudes"] = r.status == RegionStatus::kIn ? magnitudes(r.magnitudes) : py::none();
  py::list set;  // as the CLI's "magnitude_intervals": values on IN intervals only
  for (const auto& m : r.magnitude_set) set.append(r.status == RegionStatus::kIn ? magnitudes(m) : py::none());
  d["magnitude_set"] = set;
  d["exact_u0"] = algebraic_end(r.exact_u0);
  d["exact_u1"] = algebraic_end(r.exact_u1);
  return d;
}

py::dict stats_dict(const RegionStats& s) {
  py::dict d;
  d["cone_tests"] = s.cone_tests;
  d["lp_tests"] = s.lp_tests;
  d["point_tests"] = s.point_tests;
  d["depth"] = s.depth;
  d["partial_length"] = to_string(s.partial_length);
  d["roots"] = s.roots;
  d["seconds"] = s.seconds;
  return d;
}

std::optional<Rational> optional_rational(const std::optional<std::string>& text, const std::string& field) {
  if (!text) return std::nullopt;
  return parse_rational(*text, field);
}

}  // namespace

RegionOptions region_options(const std::string& resolution, const std::string& cone,
                             const std::optional<std::string>& pusher_mu, bool exact, int digits,
                             const std::optional<std::string>& resolution_length) {
  RegionOptions options;
  options.exact = exact;
  options.digits = digits;
  options.resolution = parse_rational(resolution, "resolution");
  options.resolution_length = optional_rational(resolution_length, "resolution_length");
  if (cone != "tight" && cone != "paper") throw InputError("cone", cone, "is not a cone method (tight or paper)");
  options.cone = cone == "paper" ? ConeMethod::kPaper : ConeMethod::kTight;
  options.pusher_mu = optional_rational(pusher_mu, "pusher_mu");
  return options;
}

void bind_region(py::module_& m) {
  py::class_<Region, RegionPtr>(m, "Region")
      .def_property_readonly("meaning", [](const Region& r) { return in_meaning(r); })
      .def_property_readonly("intervals",
                             [](const Region& r) {
                               py::list out;
                               for (const auto& i : r.intervals) out.append(interval_dict(i));
                               return out;
                             })
      // (curve, u, status) of each corner listed in Region::corners.
      .def_property_readonly("corners",
                             [](const Region& r) {
                               py::list out;
                               for (const auto& c : r.corners)
                                 out.append(py::make_tuple(c.curve, to_string(c.u), to_string(c.status)));
                               return out;
                             })
      .def_property_readonly("pusher_mu", [](const Region& r) { return to_string(r.pusher_mu); })
      .def_property_readonly("stats", [](const Region& r) { return stats_dict(r.stats); });

  m.def("compute_region",
        [](const ScenePtr& scene, const SeatingPtr& S, const std::string& resolution, const std::string& cone,
           const std::optional<std::string>& pusher_mu, const py::object& G, bool exact, int digits,
           const std::optional<std::string>& resolution_length, Control* control) {
          const ControlScope scope(run_control(control));  // exact steps inside poll it too
          RegionOptions options = region_options(resolution, cone, pusher_mu, exact, digits, resolution_length);
          options.guaranteed = guaranteed_of(G, S);
          options.control = run_control(control);
          py::gil_scoped_release release;
          return std::make_shared<Region>(compute_region(checked(scene, "scene"), checked(S, "seating"), options));
        });
  m.def("sample_region", [](const ScenePtr& scene, const SeatingPtr& S, int points,
                            const std::optional<std::string>& pusher_mu, const py::object& G, Control* control) {
    const ControlScope scope(run_control(control));  // exact steps inside poll it too
    if (points < 1) throw InputError("points", std::to_string(points), "must be at least 1");
    const auto mu = optional_rational(pusher_mu, "pusher_mu");
    const GuaranteedSet* g = guaranteed_of(G, S);
    py::gil_scoped_release release;
    return std::make_shared<Region>(
        sample_region(checked(scene, "scene"), checked(S, "seating"), points, mu, g, run_control(control)));
  });
  // `sustained`: the SustainedSet of a sustained region (its seated pose), or None.
  m.def(
      "region_json",
      [](const ScenePtr& scene, const RegionPtr& r, const py::object& sustained) {
        const SeatedPose* seat = sustained.is_none() ? nullptr : &sustained.cast<const SustainedSet&>().pose;
        return region_json(checked(scene, "scene"), checked(r, "region"), seat);
      },
      py::arg("scene"), py::arg("region"), py::arg("sustained") = py::none());
  // `fixel region --json --validate N --time T` of a computed region: its
  // IN intervals pushed in Box2D (docs/physics.md), as the CLI does.
  // `seating`: the region's SeatingSet (one-step push) or SustainedSet (J).
  m.def("validate_region_json", [](const ScenePtr& scene, const RegionPtr& region, const py::object& seating,
                                   int pushes, const std::string& time, long steps_per_h, int velocity_iterations,
                                   int position_iterations, Control* control) {
    const ControlScope scope(run_control(control));
    const Scene& s = checked(scene, "scene");
    const Region& r = checked(region, "region");
    const physics::PushOptions options =
        push_options(time, {steps_per_h, velocity_iterations, position_iterations}, control);
    if (pushes < 1) throw InputError("pushes", std::to_string(pushes), "must be >= 1");
    if (r.target == "J" || r.target == "J'") {  // J' refines J: the same held push is validated
      const SustainedSet& J = seating.cast<const SustainedSet&>();
      physics::RegionValidation v;
      {
        py::gil_scoped_release release;
        v = physics::validate_region(s, r, physics::seated_push_model(s), pushes, 1, options);
      }
      v.model = "sustained push: the unit wrench at q* held for T";  // as the CLI names it
      return physics::add_validation_json(region_json(s, r, &J.pose), v);
    }
    if (r.exact)
      throw InputError("pushes", std::to_string(pushes),
                       "needs the certified magnitudes of subdivision: exact=True gives none for the one-step push "
                       "(use push=\"sustained\", or exact=False)");
    const SeatingSet& S = seating.cast<const SeatingSet&>();
    py::gil_scoped_release release;
    const auto v = physics::validate_region(s, r, physics::one_step_push_model(s, S, r.pusher_mu), pushes, 1, options);
    return physics::add_validation_json(region_json(s, r), v);
  });
  m.def("write_region_svg", [](const std::string& path, const ScenePtr& scene, const SeatingPtr& S, const RegionPtr& r,
                               const py::object& G) {
    const GuaranteedSet* g = guaranteed_of(G, S);
    py::gil_scoped_release release;
    write_region_svg(path, checked(scene, "scene"), checked(S, "seating"), checked(r, "region"), g);
  });
  m.def("write_guaranteed_svg",
        [](const std::string& path, const ScenePtr& scene, const SeatingPtr& S, const py::object& G,
           const std::string& theta, const std::optional<std::vector<std::string>>& impulse) {
          const GuaranteedSet* g = guaranteed_of(G, S);
          if (!g) throw py::type_error("guaranteed: None is not a fixel object");
          const Rational t = parse_rational(theta, "theta");
          std::optional<VectorQ> p;
          if (impulse) p = exact_vector(*impulse, checked(S, "seating").dof, "impulse");
          py::gil_scoped_release release;
          write_guaranteed_svg(path, checked(scene, "scene"), checked(S, "seating"), g, t, p);
        });
  m.def("dump_off", [](const ScenePtr& scene, const SeatingPtr& S, const std::string& dir, const std::string& length,
                       const py::object& G) {
    const Rational len = parse_rational(length, "length");
    const GuaranteedSet* g = guaranteed_of(G, S);
    py::gil_scoped_release release;
    return dump_off(checked(scene, "scene"), checked(S, "seating"), dir, len, g);
  });
}

}  // namespace fixel::python
