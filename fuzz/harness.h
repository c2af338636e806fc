#pragma once
// The verdict every fuzz target applies: a fixel::Error other than
// InternalError is the expected answer to bad input (rejected with field and
// value, or stopped by the time budget); an InternalError (broken invariant)
// or any other exception is a defect, reported and turned into a crash so
// that libFuzzer keeps the input.
#include <exception>
#include <iostream>

#include "fixel/error.h"

namespace fixel::fuzz {

template <class Run>
int run_checked(Run&& run) {
  try {
    run();
  } catch (const InternalError& e) {
    std::cerr << "broken invariant: " << e.what() << "\n";
    std::terminate();
  } catch (const Error&) {
  } catch (const std::exception& e) {
    std::cerr << "non-fixel exception: " << e.what() << "\n";
    std::terminate();
  }
  return 0;
}

}  // namespace fixel::fuzz
