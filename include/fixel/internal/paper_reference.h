#pragma once
// Reference data from the paper (Egan, Berard & Trinkle, "Toward sensorless
// acquisition of multiple contact points between planar parts"), shared by
// `fixel verify` and the tests. Exact values come from
// data/reference/derive_paper_examples.py, an independent derivation that
// also checks them against the paper's printed 4-decimal table.

#include <array>

namespace fixel::internal::paper {

// Example 1 (§3.1): unit point mass, h = 1, gaps (3/10, 1/5); fixel 1 has
// normal (1, 0) and μ₁ = 1/5, fixel 2 normal (0, 1) and μ₂ = 1/10.
inline constexpr const char* kExample1Scene = R"({
  "name": "example1", "time_step": "1",
  "body": {"dof": 2, "mass": "1", "velocity": ["0", "0"]},
  "fixels": [
    {"point": ["0", "0"], "normal": ["1", "0"], "mu": "1/5", "gap": "3/10"},
    {"point": ["0", "0"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/5"}]})";

// Example 2 (§3.2): the rectangle, m = I = h = 1, μ = 1/10, ψ = (0.1, 0.05, 0.2).
inline constexpr const char* kExample2Scene = R"({
  "name": "example2", "time_step": "1",
  "body": {"dof": 3, "mass": "1", "inertia": "1", "velocity": ["0", "0", "0"],
           "center_of_mass": ["0", "0"]},
  "fixels": [
    {"point": ["-1", "0"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10"},
    {"point": ["0", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20"},
    {"point": ["1", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/5"}]})";

// The paper's printed B of Example 2 with μ = 1/10, row 10 corrected: the
// paper prints (μ₁ 0 0 0 −1 −1 0 …), shifting −E^T one column right; eq. (17)
// and rows 11–12 give (μ₁ 0 0 −1 −1 0 …).
inline constexpr std::array<std::array<const char*, 12>, 12> kExample2B = {{
    {"1", "0", "0", "0", "0", "-1", "1", "-1", "1", "0", "0", "0"},
    {"0", "1", "1", "1", "-1", "0", "0", "0", "0", "0", "0", "0"},
    {"0", "1", "2", "0", "0", "-1", "1", "-1", "1", "0", "0", "0"},
    {"0", "1", "0", "2", "-2", "1", "-1", "1", "-1", "1", "0", "0"},
    {"0", "-1", "0", "-2", "2", "-1", "1", "-1", "1", "1", "0", "0"},
    {"-1", "0", "-1", "1", "-1", "2", "-2", "2", "-2", "0", "1", "0"},
    {"1", "0", "1", "-1", "1", "-2", "2", "-2", "2", "0", "1", "0"},
    {"-1", "0", "-1", "1", "-1", "2", "-2", "2", "-2", "0", "0", "1"},
    {"1", "0", "1", "-1", "1", "-2", "2", "-2", "2", "0", "0", "1"},
    {"1/10", "0", "0", "-1", "-1", "0", "0", "0", "0", "0", "0", "0"},
    {"0", "1/10", "0", "0", "0", "-1", "-1", "0", "0", "0", "0", "0"},
    {"0", "0", "1/10", "0", "0", "0", "0", "-1", "-1", "0", "0", "0"},
}};

// The paper's printed P and a of Example 2.
inline constexpr std::array<std::array<const char*, 3>, 12> kExample2P = {{
    {"1", "0", "0"},
    {"0", "1", "0"},
    {"0", "1", "1"},
    {"0", "1", "-1"},
    {"0", "-1", "1"},
    {"-1", "0", "-1"},
    {"1", "0", "1"},
    {"-1", "0", "-1"},
    {"1", "0", "1"},
    {"0", "0", "0"},
    {"0", "0", "0"},
    {"0", "0", "0"},
}};
inline constexpr std::array<const char*, 12> kExample2a = {"1/10", "1/20", "1/5", "0", "0", "0",
                                                           "0",    "0",    "0",   "0", "0", "0"};

// The paper's s^{ℓ+1} = v_t^{ℓ+1} = (0.10, 0.25, 0.25).
inline constexpr std::array<const char*, 3> kExample2SlideSpeed = {"1/10", "1/4", "1/4"};

// Eq. (27) at p = (−1, −1, −1): the paper's printed 4-decimal table and the
// exact values.
inline constexpr std::array<const char*, 3> kExample2Impulse = {"-1", "-1", "-1"};
inline constexpr std::array<const char*, 12> kExample2LinearPrinted = {"0.0000", "0.0000", "0.0000", "0.8911",
                                                                       "0.2871", "0.8020", "0.0891", "0.0287",
                                                                       "0.0802", "0.0000", "0.0000", "0.0000"};
inline constexpr std::array<const char*, 12> kExample2ThresholdPrinted = {"-0.2000", "-0.5000", "-0.5000", "0.0941",
                                                                          "-0.0752", "0.1347",  "0.0094",  "-0.0075",
                                                                          "0.0135",  "-0.1000", "-0.2500", "-0.2500"};
inline constexpr std::array<const char*, 12> kExample2LinearExact = {
    "0", "0", "0", "90/101", "29/101", "81/101", "9/101", "29/1010", "81/1010", "0", "0", "0"};
inline constexpr std::array<const char*, 12> kExample2ThresholdExact = {
    "-1/5", "-1/2", "-1/2", "19/202", "-38/505", "68/505", "19/2020", "-19/2525", "34/2525", "-1/10", "-1/4", "-1/4"};

}  // namespace fixel::internal::paper
