/// @file
/// The _fixel extension module: typed exceptions and the exact-text helpers.
/// The bindings themselves live in bind_*.cpp, one group of concepts each.

#include <chrono>
#include <cmath>
#include <exception>

#include "bindings.h"
#include "fixel/error.h"
#include "fixel/progress.h"

namespace fixel::python {

std::vector<std::string> texts(const VectorQ& v) {
  std::vector<std::string> out;
  out.reserve(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(to_string(v[i]));
  return out;
}

std::vector<std::vector<std::string>> texts(const std::vector<VectorQ>& vs) {
  std::vector<std::vector<std::string>> out;
  out.reserve(vs.size());
  for (const auto& v : vs) out.push_back(texts(v));
  return out;
}

VectorQ exact_vector(const std::vector<std::string>& text, int size, const std::string& field) {
  if (size >= 0 && static_cast<int>(text.size()) != size) {
    std::string shown = "(";
    for (std::size_t i = 0; i < text.size(); ++i) shown += (i ? ", " : "") + text[i];
    throw InputError(field, shown + ")",
                     "has " + std::to_string(text.size()) + " entries but dof " + std::to_string(size) + " needs " +
                         std::to_string(size));
  }
  VectorQ v(static_cast<Eigen::Index>(text.size()));
  for (std::size_t i = 0; i < text.size(); ++i)
    v[static_cast<Eigen::Index>(i)] = parse_rational(text[i], field + "[" + std::to_string(i) + "]");
  return v;
}

namespace {

std::unique_ptr<Control> make_control(const std::optional<double>& max_seconds) {
  auto c = std::make_unique<Control>();
  if (max_seconds) c->run.set_time_limit(*max_seconds, "max_seconds");
  c->run.interval = std::chrono::milliseconds(100);
  Control* p = c.get();
  c->run.on_progress = [p](const char* task, long done, long total, const char* unit) {
    std::lock_guard<std::mutex> lock(p->mutex);
    p->task = task;
    p->unit = unit;
    p->done = done;
    p->total = total;
  };
  return c;
}

}  // namespace

void bind_control(py::module_& m) {
  py::class_<Control>(m, "Control")
      .def(py::init(&make_control), py::arg("max_seconds") = py::none())
      .def("cancel", [](Control& c) { c.run.cancel = true; })
      .def("snapshot", [](Control& c) {
        std::lock_guard<std::mutex> lock(c.mutex);
        return py::make_tuple(c.task, c.done, c.total, c.unit);
      });
}

namespace {

// Raises fixel.errors.<name>(message, field, value); the classes are defined
// in Python so that they carry .field and .value and subclass ValueError.
void raise(const char* name, const std::string& message, const std::string& field, const std::string& value) {
  try {
    py::object cls = py::module_::import("fixel.errors").attr(name);
    py::object exc = cls(message, field, value);
    PyErr_SetObject(cls.ptr(), exc.ptr());
  } catch (py::error_already_set&) {
    // Used without the fixel package: still an exception, never a crash.
    PyErr_SetString(PyExc_ValueError, message.c_str());
  }
}

// The core names an option by its C++ home ("RegionOptions.resolution",
// "simulate(steps)"); Python callers know it by its argument name
// ("resolution", "steps"). JSON paths (fixels[1].normal) stay as they are.
std::string argument_name(const std::string& field) {
  std::string name;
  if (const auto dot = field.find("Options."); dot != std::string::npos && field.find('(') == std::string::npos)
    name = field.substr(dot + 8);
  else if (const auto open = field.find('('); open != std::string::npos && !field.empty() && field.back() == ')')
    name = field.substr(open + 1, field.size() - open - 2);
  else
    return field;
  if (name == "points_per_curve") return "points";  // fixel.sample(scene, points)
  if (field == "plan_push(curve)") return "at";     // fixel.push_plan(scene, at="K:U")
  return name;
}

// raise() with the field, and the message's leading field, as Python names it.
void raise_input(const char* name, const InputError& e) {
  const std::string field = argument_name(e.field());
  std::string message = e.what();
  if (field != e.field() && message.rfind(e.field(), 0) == 0) message = field + message.substr(e.field().size());
  raise(name, message, field, e.value());
}

void translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const UnsupportedError& e) {
    raise_input("UnsupportedError", e);
  } catch (const SceneError& e) {
    raise_input("SceneError", e);
  } catch (const ParseError& e) {
    raise_input("ParseError", e);
  } catch (const InputError& e) {
    raise_input("InputError", e);
  } catch (const StoppedError& e) {
    raise("StoppedError", e.what(), "", "");
  } catch (const Error& e) {
    raise("Error", e.what(), "", "");
  }
}

}  // namespace
}  // namespace fixel::python

PYBIND11_MODULE(_fixel, m) {
  m.doc() = "fixel's exact C++ core; use the fixel package, not this module";
  m.attr("__version__") = FIXEL_VERSION;
  pybind11::register_exception_translator(&fixel::python::translate);
  fixel::python::bind_control(m);
  fixel::python::bind_scene(m);
  fixel::python::bind_sets(m);
  fixel::python::bind_region(m);
  fixel::python::bind_sustained(m);
  fixel::python::bind_design(m);
  fixel::python::bind_filter(m);
}
