#pragma once
// Helpers of the filter tests: run a computation with the filters on or
// forced off, and compare region JSON with the wall-clock field masked.
#include <regex>
#include <string>

#include "fixel/filter.h"
#include "fixel/io.h"
#include "fixel/region.h"
#include "fixel/seating.h"

namespace fixel::test {

// Wall-clock time is the one field allowed to differ.
inline std::string masked(const std::string& json) {
  return std::regex_replace(json, std::regex("\"seconds\": [0-9.e+-]+"), "\"seconds\": X");
}

template <typename F>
auto run(bool exact, F f) {
  ForceExactScope scope(exact);
  return f();
}

inline std::string region_json_of(const Scene& scene, const SeatingSet& S, const RegionOptions& opt) {
  const Region r = compute_region(scene, S, opt);
  return masked(region_json(scene, r));
}

}  // namespace fixel::test
