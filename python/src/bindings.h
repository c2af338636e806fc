#pragma once
/// @file
/// Shared helpers of the _fixel module (docs/python.md). Exact numbers cross
/// the boundary as text ("p/q", fixel::to_string): the Python layer turns
/// them into fractions.Fraction and back, so no value is ever rounded here.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/physics.h"
#include "fixel/progress.h"
#include "fixel/rational.h"
#include "fixel/region.h"
#include "fixel/seating.h"

namespace fixel::python {

namespace py = pybind11;

/// Exact text of every entry.
std::vector<std::string> texts(const VectorQ& v);
std::vector<std::vector<std::string>> texts(const std::vector<VectorQ>& vs);

/// Parses exact texts into a vector of length `size` (any length if size < 0).
/// Throws InputError naming `field` for a wrong length (a mismatched length
/// would otherwise reach Eigen unchecked) and ParseError for a bad number.
VectorQ exact_vector(const std::vector<std::string>& text, int size, const std::string& field);

/// *p, or TypeError for None: pybind11 turns None into an empty holder, and
/// dereferencing it would crash the interpreter.
template <class T>
T& checked(const std::shared_ptr<T>& p, const char* name) {
  if (!p) throw py::type_error(std::string(name) + ": None is not a fixel object");
  return *p;
}

/// A run's control from Python (`_fixel.Control`): cancel() from any
/// thread, an optional time limit, and the last progress report, read by
/// the caller's thread while the core runs in a worker (fixel/_worker.py).
/// Functions that take one accept None.
struct Control {
  RunControl run;
  std::mutex mutex;
  std::string task, unit;
  long done = 0, total = 0;
};

/// &control->run, or nullptr for None.
inline RunControl* run_control(Control* control) { return control ? &control->run : nullptr; }

/// The engine's accuracy as Python passes it: dt = h/steps_per_h and Box2D's
/// solver iterations (docs/physics.md, "Engine settings").
struct EngineSettings {
  long steps_per_h = physics::PushOptions{}.steps_per_h;
  int velocity_iterations = physics::PushOptions{}.velocity_iterations;
  int position_iterations = physics::PushOptions{}.position_iterations;
};

/// The engine's options for a push held `time` time steps h (Python's
/// `time` argument, exact text), polling `control`: InputError naming
/// `time` when it is not > 0 or asks for more engine steps than the core
/// runs (physics::kMaxPushSteps), and the engine settings by their argument
/// names when out of range (physics::check_push_options).
inline physics::PushOptions push_options(const std::string& time, const EngineSettings& engine, Control* control) {
  physics::PushOptions options;
  options.time = parse_rational(time, "time");
  if (options.time <= 0) throw InputError("time", time, "must be > 0");
  options.steps_per_h = engine.steps_per_h;
  options.velocity_iterations = engine.velocity_iterations;
  options.position_iterations = engine.position_iterations;
  physics::check_push_options(options);  // ranges and the step limit, named as Python's arguments
  options.control = run_control(control);
  return options;
}

/// G's membership test needs S, so the binding keeps both alive together.
struct GuaranteedHandle {
  GuaranteedSet G;
  std::shared_ptr<SeatingSet> S;
};

/// G of `S` from a Python object (None gives nullptr); InputError if G was
/// built for another seating set.
const GuaranteedSet* guaranteed_of(const py::object& g, const std::shared_ptr<SeatingSet>& S);

/// The region options of compute_region and compute_region_sustained, from
/// their keyword arguments (exact texts); InputError names a bad field.
RegionOptions region_options(const std::string& resolution, const std::string& cone,
                             const std::optional<std::string>& pusher_mu, bool exact, int digits,
                             const std::optional<std::string>& resolution_length);

void bind_control(py::module_& m);
void bind_scene(py::module_& m);
void bind_sets(py::module_& m);
void bind_region(py::module_& m);
void bind_sustained(py::module_& m);
void bind_design(py::module_& m);
void bind_filter(py::module_& m);

}  // namespace fixel::python
