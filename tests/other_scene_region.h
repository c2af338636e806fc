#pragma once
// A region of one bundled scene, for the tests that a region is refused
// beside another scene (the polygon's).

#include "fixel/region.h"
#include "fixel/seating.h"
#include "test_util.h"

namespace fixel::test {

// example2_rounded's region against S at resolution 1/16.
inline Region rounded_region() {
  const Scene rounded = scene_file("example2_rounded");
  RegionOptions options;
  options.resolution = Rational(1, 16);
  return compute_region(rounded, seating_set(rounded), options);
}

}  // namespace fixel::test
