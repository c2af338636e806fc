// Fuzzes the scene loader and the whole seat and region pipeline on
// arbitrary bytes. A fixel::Error is the expected answer to bad input; any
// other exception, a crash, a hang or a sanitizer report is a defect.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iostream>
#include <string>

#include "fixel/error.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/seating.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const fixel::Scene scene = fixel::parse_scene(text, "fuzz");
    const fixel::SeatingSet S = fixel::seating_set(scene);
    for (const auto& h : S.halfspaces) (void)h.contains(S.apex);
    if (scene.body.boundary) {
      fixel::RegionOptions options;
      options.resolution = fixel::Rational(1, 8);  // bounded work per input
      (void)fixel::compute_region(scene, S, options);
    }
  } catch (const fixel::Error&) {
    // Bad input, reported with field and value: fine.
  } catch (const std::exception& e) {
    std::cerr << "non-fixel exception: " << e.what() << "\n";
    std::terminate();
  }
  return 0;
}
