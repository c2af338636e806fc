// Structure-aware fuzzing of the costly operations (fuzz/structured.h,
// run_operation with slow = true): every contact mode of a three-fixel step,
// the guaranteed set (with the region against it), and fixture design on a
// few boundary candidates, filtered against forced exact, on a small scene
// chosen by the bytes. 50 ms to seconds per input, so it gets its own
// target and share of the fuzzing time. A fixel::Error other than
// InternalError is the expected answer to a degenerate scene; an
// InternalError (a design whose filtered and exact answers differ is one),
// any other exception, a crash, a hang or a sanitizer report is a defect.
#include <cstddef>
#include <cstdint>

#include "harness.h"
#include "structured.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fixel::fuzz::run_checked([&] { fixel::fuzz::run_operation(data, size, true); });
}
