// Structure-aware fuzzing: the first byte picks one operation (seat,
// outcomes, simulate, seat-and-stay, region, exact region, sample, a point
// test, the guaranteed set, the seated pose, the sustained set, the region
// against it, a Box2D push), the rest the numbers of a small scene that
// always parses (fuzz/structured.h). A fixel::Error other
// than InternalError is the expected answer to a degenerate scene; an
// InternalError, any other exception, a crash, a hang or a sanitizer report
// is a defect.
#include <cstddef>
#include <cstdint>

#include "harness.h"
#include "structured.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fixel::fuzz::run_checked([&] { fixel::fuzz::run_operation(data, size); });
}
