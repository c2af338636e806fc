#include "fixel/verify.h"

#include <functional>

#include "fixel/internal/paper_reference.h"
#include "fixel/lcp.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"

namespace fixel {

namespace internal {
std::vector<VerificationCheck> sustained_checks();  // verify_sustained.cpp
VerificationCheck run_check(const std::string& name, const std::string& what,
                            const std::function<std::string()>& check);
}  // namespace internal

namespace {

namespace paper = internal::paper;

std::string vec_text(const VectorQ& v) {
  std::string s = "(";
  for (int k = 0; k < v.size(); ++k) s += (k ? ", " : "") + to_string(v[k]);
  return s + ")";
}

template <std::size_t N>
VectorQ vec(const std::array<const char*, N>& a) {
  VectorQ v(static_cast<int>(N));
  for (std::size_t k = 0; k < N; ++k) v[static_cast<int>(k)] = parse_rational(a[k]);
  return v;
}

using Check = std::function<std::string()>;  // returns "" on success, else what differed

VerificationCheck run(const std::string& name, const std::string& what, const Check& check) {
  VerificationCheck result{name, false, what};
  try {
    const std::string diff = check();
    result.passed = diff.empty();
    if (!diff.empty()) result.detail = diff;
  } catch (const std::exception& e) {
    result.detail = std::string("threw: ") + e.what();
  }
  return result;
}

std::string expect_equal(const std::string& what, const VectorQ& got, const VectorQ& want) {
  if (got.size() == want.size() && got == want) return "";
  return what + " is " + vec_text(got) + ", expected " + vec_text(want);
}

}  // namespace

Rational round_decimal(const Rational& x, int decimals) {
  if (decimals < 0 || decimals > kMaxRoundDecimals)
    throw InputError("decimals", std::to_string(decimals), "must be 0 to " + std::to_string(kMaxRoundDecimals));
  const Integer scale = boost::multiprecision::pow(Integer(10), static_cast<unsigned>(decimals));
  const Rational scaled = boost::multiprecision::abs(x) * Rational(scale);
  const Integer q = boost::multiprecision::numerator(scaled), d = boost::multiprecision::denominator(scaled);
  Integer rounded = (2 * q + d) / (2 * d);  // floor(scaled + 1/2)
  if (x < 0) rounded = -rounded;
  return Rational(rounded, scale);
}

VerificationCheck internal::run_check(const std::string& name, const std::string& what,
                                      const std::function<std::string()>& check) {
  return run(name, what, check);
}

std::vector<VerificationCheck> run_verification() {
  std::vector<VerificationCheck> out;

  out.push_back(run("example1.apex", "apex of S is -psi = (-3/10, -1/5) (paper eq. 26 prints +psi)", [] {
    const SeatingSet S = seating_set(parse_scene(paper::kExample1Scene, "example1"));
    VectorQ want(2);
    want << Rational(-3, 10), Rational(-1, 5);
    return expect_equal("apex", S.apex, want);
  }));
  out.push_back(run("example1.rays", "rays of S are -(1, mu1) and -(mu2, 1) with mu1 = 1/5, mu2 = 1/10", [] {
    const SeatingSet S = seating_set(parse_scene(paper::kExample1Scene, "example1"));
    VectorQ r1(2), r2(2);
    r1 << Rational(-1), Rational(-1, 5);
    r2 << Rational(-1, 10), Rational(-1);
    if (S.rays.size() != 2) return std::string("S has ") + std::to_string(S.rays.size()) + " rays";
    const std::string d = expect_equal("ray 1", S.rays[0], r1);
    return d.empty() ? expect_equal("ray 2", S.rays[1], r2) : d;
  }));
  out.push_back(run("example2.B", "B of eq. (17) equals the paper's printed matrix (row 10 corrected)", [] {
    const TimeSteppingLcp lcp = build_lcp(parse_scene(paper::kExample2Scene, "example2"));
    for (int r = 0; r < 12; ++r)
      for (int c = 0; c < 12; ++c)
        if (lcp.B(r, c) != parse_rational(paper::kExample2B[r][c]))
          return "B(" + std::to_string(r + 1) + "," + std::to_string(c + 1) + ") is " + to_string(lcp.B(r, c)) +
                 ", paper has " + paper::kExample2B[r][c];
    return std::string();
  }));
  out.push_back(run("example2.P_a", "P and a of eq. (19) equal the paper's", [] {
    const TimeSteppingLcp lcp = build_lcp(parse_scene(paper::kExample2Scene, "example2"));
    for (int r = 0; r < 12; ++r)
      for (int c = 0; c < 3; ++c)
        if (lcp.P(r, c) != parse_rational(paper::kExample2P[r][c]))
          return "P(" + std::to_string(r + 1) + "," + std::to_string(c + 1) + ") differs";
    return expect_equal("a", lcp.a, vec(paper::kExample2a));
  }));
  out.push_back(run("example2.slide_speeds", "v_t = s = (0.10, 0.25, 0.25), all sliding +t", [] {
    const SeatingSet S = seating_set(parse_scene(paper::kExample2Scene, "example2"));
    return expect_equal("v_t", S.tangential_velocity, vec(paper::kExample2SlideSpeed));
  }));
  out.push_back(
      run("example2.eq27_exact",
          "K^-1 P p and -K^-1 a at p = (-1,-1,-1) equal the exact values of an independent derivation "
          "(data/reference/derive_paper_examples.py)",
          [] {
            const Scene scene = parse_scene(paper::kExample2Scene, "example2");
            const SeatingSystem sys = seating_system(scene, seating_set(scene));
            const VectorQ p = vec(paper::kExample2Impulse);
            const std::string d = expect_equal("K^-1 P p", sys.linear_part(p), vec(paper::kExample2LinearExact));
            return d.empty() ? expect_equal("-K^-1 a", sys.threshold(), vec(paper::kExample2ThresholdExact)) : d;
          }));
  out.push_back(run("example2.eq27_printed", "the same values rounded to 4 decimals equal the paper's table", [] {
    const Scene scene = parse_scene(paper::kExample2Scene, "example2");
    const SeatingSystem sys = seating_system(scene, seating_set(scene));
    const VectorQ p = vec(paper::kExample2Impulse);
    const VectorQ lin = sys.linear_part(p), thr = sys.threshold();
    for (int k = 0; k < 12; ++k) {
      if (round_decimal(lin[k], 4) != parse_rational(paper::kExample2LinearPrinted[k]))
        return "K^-1 P p entry " + std::to_string(k + 1) + " = " + to_string(lin[k]) + " does not round to " +
               paper::kExample2LinearPrinted[k];
      if (round_decimal(thr[k], 4) != parse_rational(paper::kExample2ThresholdPrinted[k]))
        return "-K^-1 a entry " + std::to_string(k + 1) + " = " + to_string(thr[k]) + " does not round to " +
               paper::kExample2ThresholdPrinted[k];
    }
    return std::string();
  }));
  out.push_back(run("example2.contains", "p = (-1,-1,-1) is in S, by the H-form and by eq. (27) (y >= 0)", [] {
    const Scene scene = parse_scene(paper::kExample2Scene, "example2");
    const SeatingSet S = seating_set(scene);
    const VectorQ p = vec(paper::kExample2Impulse);
    if (!S.contains(p)) return std::string("H-form says p is not in S");
    const VectorQ y = seating_system(scene, S).y(p);
    for (int k = 0; k < y.size(); ++k)
      if (y[k] < 0) return "y[" + std::to_string(k) + "] = " + to_string(y[k]) + " < 0";
    return std::string();
  }));
  out.push_back(run("example2.facets", "every facet of S is tight at the apex and on exactly two rays", [] {
    const SeatingSet S = seating_set(parse_scene(paper::kExample2Scene, "example2"));
    if (S.halfspaces.size() != 3) return "S has " + std::to_string(S.halfspaces.size()) + " facets, expected 3";
    for (const auto& h : S.halfspaces) {
      if (h.a.dot(S.apex) != h.c) return std::string("a facet misses the apex");
      int tight = 0;
      for (const auto& r : S.rays) tight += h.a.dot(r) == 0 ? 1 : 0;
      if (tight != 2) return "a facet is tight on " + std::to_string(tight) + " rays";
    }
    return std::string();
  }));
  for (auto& c : internal::sustained_checks()) out.push_back(std::move(c));
  return out;
}

}  // namespace fixel
