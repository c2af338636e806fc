// The example of docs/library.md: load a scene, build the seating set S,
// test an impulse exactly, and classify one boundary segment.
#include <fixel/error.h>
#include <fixel/region.h>
#include <fixel/scene.h>
#include <fixel/scene_json.h>
#include <fixel/seating.h>

#include <iostream>

int main() {
  // The paper's Example 2 with a square outline [-1, 1]² (exact numbers).
  const char* scene_json = R"({
    "name": "consumer", "time_step": "1",
    "body": {"dof": 3, "mass": "1", "inertia": "1", "center_of_mass": ["0", "0"],
             "boundary": [{"type": "polyline",
                           "points": [["-1","-1"], ["1","-1"], ["1","1"], ["-1","1"], ["-1","-1"]]}]},
    "fixels": [{"point": ["-1", "0"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10"},
               {"point": ["0", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20"},
               {"point": ["1", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/5"}]})";
  try {
    const fixel::Scene scene = fixel::parse_scene(scene_json, "consumer");
    const fixel::SeatingSet S = fixel::seating_set(scene);

    // An exact membership test: (-1, -1, -1) is the paper's impulse.
    const fixel::VectorQ p = fixel::parse_impulse("-1,-1,-1", scene.body.dof);
    std::cout << "impulse (-1, -1, -1) is " << (S.contains(p) ? "in" : "not in") << " S\n";

    // Classify the right edge (curve 0, u in [1, 2]) without subdividing.
    fixel::RegionOptions options;
    options.resolution = 1;
    const fixel::Region region = fixel::compute_region(scene, S, options);
    for (const auto& interval : region.intervals)
      if (interval.u0 <= 1 && interval.u1 >= 2)
        std::cout << "right edge: " << fixel::to_string(interval.status) << "\n";
    return S.contains(p) ? 0 : 1;
  } catch (const fixel::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
