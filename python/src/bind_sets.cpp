/// @file
/// Seating set S (with the eq. 27 system), guaranteed set G, the stepper and
/// the outcome enumeration, and the push plan at one boundary point. Long
/// computations release the GIL.

#include <memory>

#include "bindings.h"
#include "fixel/guaranteed.h"
#include "fixel/io.h"
#include "fixel/outcomes.h"
#include "fixel/physics.h"
#include "fixel/push_plan.h"
#include "fixel/seating.h"
#include "fixel/stepper.h"

namespace fixel::python {
namespace {

using ScenePtr = std::shared_ptr<Scene>;
using SeatingPtr = std::shared_ptr<SeatingSet>;

py::list halfspaces(const std::vector<Halfspace>& hs) {
  py::list out;
  for (const auto& h : hs) out.append(py::make_tuple(texts(h.a), to_string(h.c)));
  return out;
}

std::vector<std::string> mode_names(const std::vector<ContactMode>& modes) {
  std::vector<std::string> out;
  for (auto mode : modes) out.push_back(to_string(mode));
  return out;
}

py::dict outcome_dict(const Outcome& o) {
  py::dict d;
  d["seated"] = o.seated;
  d["modes"] = mode_names(o.modes);
  d["velocity"] = texts(o.velocity);
  d["gaps"] = texts(o.gaps);
  d["p_n"] = texts(o.p_n);
  d["p_t"] = texts(o.p_t);
  d["isolated"] = o.isolated;
  return d;
}

py::dict step_dict(const StepRecord& s) {
  py::dict d;
  d["q"] = texts(s.q);
  d["velocity"] = texts(s.velocity);
  d["gaps"] = texts(s.gaps);
  d["p_n"] = texts(s.p_n);
  d["p_f"] = texts(s.p_f);
  d["pivots"] = s.pivots;
  return d;
}

}  // namespace

const GuaranteedSet* guaranteed_of(const py::object& g, const SeatingPtr& S) {
  if (g.is_none()) return nullptr;
  const auto& handle = g.cast<const GuaranteedHandle&>();
  if (handle.S != S)
    throw InputError("guaranteed", "G",
                     "belongs to another seating set: pass the SeatingSet G was built from (G.seating), or no "
                     "seating at all");
  return &handle.G;
}

void bind_sets(py::module_& m) {
  py::class_<SeatingSet, SeatingPtr>(m, "SeatingSet")
      .def_readonly("dof", &SeatingSet::dof)
      .def_property_readonly("apex", [](const SeatingSet& S) { return texts(S.apex); })
      .def_property_readonly("rays", [](const SeatingSet& S) { return texts(S.rays); })
      .def_property_readonly("halfspaces", [](const SeatingSet& S) { return halfspaces(S.halfspaces); })
      .def_property_readonly("velocity_after", [](const SeatingSet& S) { return texts(S.nu_plus); })
      .def_property_readonly("tangential_velocity", [](const SeatingSet& S) { return texts(S.tangential_velocity); })
      .def_readonly("sliding", &SeatingSet::sliding)
      .def_readonly("generator_fixel", &SeatingSet::generator_fixel)
      .def("contains", [](const SeatingSet& S, const std::vector<std::string>& p) {
        return S.contains(exact_vector(p, S.dof, "p"));
      });

  py::class_<SeatingSystem>(m, "SeatingSystem")
      .def_readonly("y_names", &SeatingSystem::y_names)
      .def("y",
           [](const SeatingSystem& K, const std::vector<std::string>& p) {
             return texts(K.y(exact_vector(p, static_cast<int>(K.P.cols()), "p")));
           })
      .def("linear_part",
           [](const SeatingSystem& K, const std::vector<std::string>& p) {
             return texts(K.linear_part(exact_vector(p, static_cast<int>(K.P.cols()), "p")));
           })
      .def("threshold", [](const SeatingSystem& K) { return texts(K.threshold()); });

  py::class_<GuaranteedHandle, std::shared_ptr<GuaranteedHandle>>(m, "GuaranteedSet")
      .def("contains",
           [](const GuaranteedHandle& g, const std::vector<std::string>& p) {
             return g.G.contains(exact_vector(p, g.S->dof, "p"), *g.S);
           })
      .def_property_readonly("num_pieces", [](const GuaranteedHandle& g) { return g.G.pieces.size(); })
      .def_property_readonly("non_seating",
                             [](const GuaranteedHandle& g) {
                               py::list out;
                               for (const auto& n : g.G.non_seating)
                                 out.append(py::make_tuple(mode_names(n.modes), n.open_fixel));
                               return out;
                             })
      // (dimension, closed rows, strict rows) per piece, and (closed, strict)
      // per non-seating set: the JSON's "pieces" and "non_seating" rows.
      .def_property_readonly("pieces",
                             [](const GuaranteedHandle& g) {
                               py::list out;
                               for (std::size_t i = 0; i < g.G.pieces.size(); ++i)
                                 out.append(py::make_tuple(g.G.dimensions.at(i), halfspaces(g.G.pieces[i].closed),
                                                           halfspaces(g.G.pieces[i].strict)));
                               return out;
                             })
      .def_property_readonly(
          "non_seating_rows",
          [](const GuaranteedHandle& g) {
            py::list out;
            for (const auto& n : g.G.non_seating)
              out.append(py::make_tuple(halfspaces(n.impulses.closed), halfspaces(n.impulses.strict)));
            return out;
          })
      .def(
          "lost_fraction",
          [](const GuaranteedHandle& g, int grid) {
            if (grid < 1) throw InputError("grid", std::to_string(grid), "must be at least 1");
            py::gil_scoped_release release;
            return to_string(lost_fraction(*g.S, g.G, grid));
          },
          py::arg("grid") = 6);

  m.def("seating_set", [](const ScenePtr& scene) {
    py::gil_scoped_release release;
    return std::make_shared<SeatingSet>(seating_set(checked(scene, "scene")));
  });
  m.def("seating_system", [](const ScenePtr& scene, const SeatingPtr& S) {
    py::gil_scoped_release release;
    return seating_system(checked(scene, "scene"), checked(S, "seating"));
  });
  m.def("guaranteed_set", [](const ScenePtr& scene, const SeatingPtr& S, Control* control) {
    const ControlScope scope(run_control(control));  // exact steps inside poll it too
    py::gil_scoped_release release;
    return std::make_shared<GuaranteedHandle>(
        GuaranteedHandle{guaranteed_set(checked(scene, "scene"), checked(S, "seating"), run_control(control)), S});
  });
  m.def("simulate", [](const ScenePtr& scene, const std::vector<std::vector<std::string>>& impulses, int steps,
                       Control* control) {
    const ControlScope scope(run_control(control));  // exact steps inside poll it too
    std::vector<VectorQ> p;
    for (std::size_t k = 0; k < impulses.size(); ++k)
      p.push_back(exact_vector(impulses[k], checked(scene, "scene").body.dof, "impulse[" + std::to_string(k) + "]"));
    Simulation sim;
    {
      py::gil_scoped_release release;
      sim = simulate(checked(scene, "scene"), p, steps, run_control(control));
    }
    py::list out;
    for (const auto& s : sim.steps) out.append(step_dict(s));
    return py::make_tuple(sim.seated, out);
  });
  m.def("solutions", [](const ScenePtr& scene, const std::vector<std::string>& impulse, Control* control) {
    const ControlScope scope(run_control(control));  // exact steps inside poll it too
    const VectorQ p = exact_vector(impulse, checked(scene, "scene").body.dof, "impulse");
    std::vector<Outcome> outcomes;
    {
      py::gil_scoped_release release;
      outcomes = enumerate_outcomes(checked(scene, "scene"), p, run_control(control));
    }
    py::list out;
    for (const auto& o : outcomes) out.append(outcome_dict(o));
    return out;
  });
  // `fixel push-plan --json` at "K:U": per model, how hard to push there.
  m.def("push_plan", [](const ScenePtr& scene, const std::string& at, bool guaranteed, Control* control) {
    const ControlScope scope(run_control(control));  // exact steps inside poll it too
    const Scene& s = checked(scene, "scene");
    const auto point = physics::parse_curve_point(s, at, "at");
    py::gil_scoped_release release;
    return push_plan_json(s, plan_push(s, point.curve, point.u, guaranteed, run_control(control)));
  });
}

}  // namespace fixel::python
