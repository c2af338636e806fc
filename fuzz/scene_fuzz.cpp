// Fuzzes the scene loader and the whole seat and region pipeline on
// arbitrary bytes. A fixel::Error is the expected answer to bad input; any
// other exception, a crash, a hang or a sanitizer report is a defect.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iostream>
#include <string>

#include "pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    fixel::fuzz::run_pipeline(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const fixel::InternalError& e) {
    std::cerr << "broken invariant: " << e.what() << "\n";
    std::terminate();
  } catch (const fixel::Error&) {
    // Bad input, reported with field and value: fine.
  } catch (const std::exception& e) {
    std::cerr << "non-fixel exception: " << e.what() << "\n";
    std::terminate();
  }
  return 0;
}
