/// @file
/// The filters' switch and counters (include/fixel/filter.h): forcing the
/// exact path for every decision, and how often each filter decided.

#include "bindings.h"
#include "fixel/filter.h"

namespace fixel::python {

void bind_filter(py::module_& m) {
  m.def("set_force_exact", &set_force_exact, py::arg("on"),
        "Force (True) or release (False) the exact path for every filtered decision in the process "
        "(released, the filters run only where directed_rounding_works())");
  m.def("force_exact", &force_exact,
        "Whether the exact path is forced (always, when directed_rounding_works() is False)");
  m.def("force_exact_set", &force_exact_set, "Whether set_force_exact asks for the exact path");
  m.def("directed_rounding_works", &directed_rounding_works,
        "Whether the processor honours the rounding mode, so that the filters can be used (False under valgrind)");
  m.def(
      "filter_stats",
      [] {
        const FilterStats stats = filter_stats();
        py::dict out;
        for (int s = 0; s < static_cast<int>(FilterSite::kCount); ++s) {
          const auto site = static_cast<FilterSite>(s);
          py::dict counts;
          counts["certified"] = stats.at(site).certified;
          counts["fallbacks"] = stats.at(site).fallbacks;
          out[py::str(to_string(site))] = counts;
        }
        return out;
      },
      "Per filter site: {'certified': n, 'fallbacks': m} since the last reset");
  m.def("reset_filter_stats", &reset_filter_stats, "Set every filter counter to zero");
}

}  // namespace fixel::python
