#pragma once
/// @file
/// The built-in verification suite behind `fixel verify`: the paper's
/// examples, checked exactly.

#include <string>
#include <vector>

#include "fixel/rational.h"

namespace fixel {

/// One named check and its outcome.
struct VerificationCheck {
  std::string name;
  bool passed = false;
  std::string detail;  ///< What was compared, or what differed.
};

/// Runs every check; never throws (an exception inside a check fails it).
std::vector<VerificationCheck> run_verification();

/// The most places round_decimal takes.
constexpr int kMaxRoundDecimals = 10000;

/// `x` rounded half away from zero to `decimals` places, exactly, as a
/// rational (for comparing against tables printed to that many places).
/// Throws InputError unless 0 <= decimals <= kMaxRoundDecimals.
Rational round_decimal(const Rational& x, int decimals);

}  // namespace fixel
