#pragma once
// The pipeline the fuzzer drives, shared with the regression replay test:
// scene loader, seating set, and (with a boundary) the pushing region.

#include <string>

#include "fixel/error.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"

namespace fixel::fuzz {

// Runs the pipeline on `text`. Returns normally, or throws fixel::Error for
// bad input; InternalError or any other exception is a defect.
inline void run_pipeline(const std::string& text) {
  const Scene scene = parse_scene(text, "fuzz");
  const SeatingSet S = seating_set(scene);
  for (const auto& h : S.halfspaces) (void)h.contains(S.apex);
  if (scene.body.boundary) {
    RegionOptions options;
    options.resolution = Rational(1, 8);  // bounded work per input
    (void)compute_region(scene, S, options);
  }
}

}  // namespace fixel::fuzz
