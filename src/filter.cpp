#include "fixel/filter.h"

#include <atomic>
#include <cstdlib>

#include "fixel/internal/filtered.h"

namespace fixel {

namespace {

bool initial_force_exact() {
  const char* v = std::getenv("FIXEL_FORCE_EXACT");
  return v && *v && std::string(v) != "0";
}

std::atomic<bool> g_force_exact{initial_force_exact()};

constexpr int kSites = static_cast<int>(FilterSite::kCount);
std::atomic<long> g_certified[kSites];
std::atomic<long> g_fallbacks[kSites];

}  // namespace

std::string to_string(FilterSite site) {
  switch (site) {
    case FilterSite::kLemke:
      return "lemke";
    case FilterSite::kLemkeTie:
      return "lemke tie";
    case FilterSite::kRayTest:
      return "ray test";
    case FilterSite::kOutTest:
      return "out test";
    case FilterSite::kOrientation:
      return "orientation";
    case FilterSite::kCone:
      return "cone";
    case FilterSite::kMembership:
      return "membership";
    case FilterSite::kJam:
      return "jam test";
    case FilterSite::kRegionTest:
      return "region test";
    case FilterSite::kInMagnitudes:
      return "in magnitudes";
    case FilterSite::kFeasibility:
      return "feasibility";
    case FilterSite::kDesignBound:
      return "design bound";
    case FilterSite::kApproach:
      return "approach";
    case FilterSite::kCount:
      break;
  }
  return "?";
}

long FilterStats::total_fallbacks() const {
  long t = 0;
  for (const auto& s : site) t += s.fallbacks;
  return t;
}

long FilterStats::total_certified() const {
  long t = 0;
  for (const auto& s : site) t += s.certified;
  return t;
}

namespace {

std::atomic<bool> g_assume_rounding_ignored{false};

}  // namespace

bool directed_rounding_works() {
  static const bool works = internal::intervals_enclose_in(CGAL_FE_UPWARD);
  return works && !g_assume_rounding_ignored.load(std::memory_order_relaxed);
}

void set_force_exact(bool on) { g_force_exact.store(on, std::memory_order_relaxed); }
bool force_exact_set() { return g_force_exact.load(std::memory_order_relaxed); }
bool force_exact() { return force_exact_set() || !directed_rounding_works(); }

namespace internal {

// 1.1·10.1, 1/10 and 1 + 2⁻⁶⁰ (none a double) must come out as intervals
// of two distinct ends. Valgrind, for one, ignores the SSE rounding mode
// and rounds to nearest: then both ends are the same double, on one side
// of the exact value.
bool intervals_enclose_in(CGAL::FPU_CW_t mode) {
  const CGAL::FPU_CW_t previous = CGAL::FPU_get_and_set_cw(mode);
  volatile double a = 1.1, b = 10.1, one = 1, ten = 10, tiny = 0x1p-60;  // not constants: computed in `mode`
  const FI product = FI(a) * FI(b);
  const FI quotient = FI(one) / FI(ten);
  const FI sum = FI(one) + FI(tiny);
  CGAL::FPU_set_cw(previous);
  return product.inf() < product.sup() && quotient.inf() < quotient.sup() && sum.inf() < sum.sup();
}

void assume_directed_rounding_ignored(bool on) { g_assume_rounding_ignored.store(on, std::memory_order_relaxed); }
}  // namespace internal

FilterStats filter_stats() {
  FilterStats s;
  for (int i = 0; i < kSites; ++i) {
    s.site[i].certified = g_certified[i].load(std::memory_order_relaxed);
    s.site[i].fallbacks = g_fallbacks[i].load(std::memory_order_relaxed);
  }
  return s;
}

void reset_filter_stats() {
  for (int i = 0; i < kSites; ++i) {
    g_certified[i].store(0, std::memory_order_relaxed);
    g_fallbacks[i].store(0, std::memory_order_relaxed);
  }
}

namespace internal {

void record_filter(FilterSite site, bool certified) {
  (certified ? g_certified : g_fallbacks)[static_cast<int>(site)].fetch_add(1, std::memory_order_relaxed);
}

void record_filter(FilterSite site, long certified, long fallbacks) {
  if (certified) g_certified[static_cast<int>(site)].fetch_add(certified, std::memory_order_relaxed);
  if (fallbacks) g_fallbacks[static_cast<int>(site)].fetch_add(fallbacks, std::memory_order_relaxed);
}

}  // namespace internal

}  // namespace fixel
