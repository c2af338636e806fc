// Structure-aware fuzzing: the bytes choose the numbers of a scene that
// always parses, and the whole library runs on it (seat, outcomes, simulate,
// seat-and-stay, region, sample, the guaranteed set). A fixel::Error other
// than InternalError is the expected answer to a degenerate scene; an
// InternalError, any other exception, a crash, a hang or a sanitizer report
// is a defect.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iostream>

#include "structured.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    fixel::fuzz::run_structured(data, size);
  } catch (const fixel::InternalError& e) {
    std::cerr << "broken invariant: " << e.what() << "\n";
    std::terminate();
  } catch (const fixel::Error&) {
    // Rejected with a message, or stopped by the time budget: fine.
  } catch (const std::exception& e) {
    std::cerr << "non-fixel exception: " << e.what() << "\n";
    std::terminate();
  }
  return 0;
}
