#pragma once
// Helpers of the filter tests: run a computation with the filters on or
// forced off, compare region JSON with the wall-clock field masked, and
// halve pieces in intervals.
#include <regex>
#include <string>
#include <vector>

#include "fixel/filter.h"
#include "fixel/internal/lazy_piece.h"
#include "fixel/io.h"
#include "fixel/region.h"
#include "fixel/scene_json.h"
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

// A square with a wedge notch on either side, each notch edge on a line
// through the centre of mass (the origin, by symmetry): along such an edge
// the push direction is perpendicular to the lever arm, so the paper cone's
// moment bound is its ⊥-angle term ±R (R ≥ |r|), which the interval
// pre-test encloses only where the point is certainly a hull vertex with
// ⊥ certainly in the arc.
inline Scene notched_square() {
  return parse_scene(R"({"time_step": "1", "body": {"dof": 3, "velocity": ["0", "0", "0"],
    "boundary": [{"type": "polyline", "points": [["-2", "-2"], ["2", "-2"], ["2", "-1"], ["1", "-1/2"],
      ["1", "1/2"], ["2", "1"], ["2", "2"], ["-2", "2"], ["-2", "1"], ["-1", "1/2"], ["-1", "-1/2"],
      ["-2", "-1"], ["-2", "-2"]]}]},
    "fixels": [{"point": ["-2", "-3/2"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10"},
               {"point": ["-1", "-2"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20"},
               {"point": ["1", "-2"], "normal": ["0", "1"], "mu": "1/10", "gap": "3/20"}],
    "pusher": {"mu": "0"}})");
}

// A whole piece halved `levels` times in intervals: its 2^levels parts in
// order.
inline std::vector<internal::LazyPiece> halved(const BezierPiece& piece, int levels) {
  std::vector<internal::LazyPiece> parts{internal::LazyPiece(piece, true)};
  for (int level = 0; level < levels; ++level) {
    std::vector<internal::LazyPiece> next;
    for (const auto& p : parts) {
      auto h = p.halves();
      next.push_back(h.first);
      next.push_back(h.second);
    }
    parts = next;
  }
  return parts;
}

}  // namespace fixel::test
