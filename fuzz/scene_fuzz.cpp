// Fuzzes the scene loader and the whole seat and region pipeline on
// arbitrary bytes. A fixel::Error is the expected answer to bad input; any
// other exception, a crash, a hang or a sanitizer report is a defect.
#include <cstddef>
#include <cstdint>
#include <string>

#include "harness.h"
#include "pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fixel::fuzz::run_checked(
      [&] { fixel::fuzz::run_pipeline(std::string(reinterpret_cast<const char*>(data), size)); });
}
