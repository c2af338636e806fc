// Fixture design's bounded search (docs/design.md, "The bound"): the pilot,
// the pair regions and the triples' bounds on a oneTBB arena, their order,
// and the skip and stop rules. Scoring is the caller's (design.cpp, or a
// cluster).
#include "fixel/design_search.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <mutex>

#include "fixel/error.h"
#include "fixel/internal/design_bound.h"
#include "fixel/internal/design_detail.h"
#include "fixel/internal/filtered.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

constexpr long kPilot = 32;         // triples the pilot scores
constexpr long kBoundBatch = 1024;  // triples bounded per unit of work
// Memory: the pairs' stretches (a few hundred bytes a pair) and the bounds
// kept (16 bytes a triple; only those that may beat the pilot's K-th).
constexpr long kMaxPairs = 1L << 19;  // 1,024 candidates
constexpr long kMaxKept = 1L << 25;
std::atomic<long> kept_limit{kMaxKept};  // internal::set_design_kept_limit

struct Ranked {
  long index;
  double upper;  // ≥ the triple's exact bound
};

// Polls `control` from whichever thread gets the mutex without waiting.
class SharedPoll {
 public:
  explicit SharedPoll(RunControl* control) : control_(control) {}
  void operator()(const char* task, long done, long total, const char* unit) {
    if (!control_) return;
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (lock.owns_lock()) control_->poll(task, done, total, unit);
  }

 private:
  RunControl* control_;
  std::mutex mutex_;
};

}  // namespace

void internal::set_design_kept_limit(long limit) { kept_limit = limit; }

struct DesignSearch::Impl {
  Scene part;
  std::vector<DesignCandidate> cands;
  DesignOptions options;
  long n = 0, triples = 0;
  std::vector<long> pilot;
  std::optional<internal::PairBound> bound;
  std::vector<Ranked> ranked;
  std::size_t pos = 0;
  long singular = 0;
  bool over = false;
};

DesignSearch::DesignSearch(const Scene& part, const std::vector<DesignCandidate>& candidates,
                           const DesignOptions& options)
    : impl_(std::make_unique<Impl>()) {
  check_design(part, options);
  check_candidate_list(candidates);
  check_candidates(part, candidates);
  Impl& s = *impl_;
  s.part = part;
  s.cands = candidates;
  s.options = options;
  s.n = static_cast<long>(candidates.size());
  s.triples = triple_count(s.n);
  if (applies())
    for (long k = 0; k < kPilot; ++k) s.pilot.push_back(k * s.triples / kPilot);
}

DesignSearch::~DesignSearch() = default;
DesignSearch::DesignSearch(DesignSearch&&) noexcept = default;
DesignSearch& DesignSearch::operator=(DesignSearch&&) noexcept = default;

bool DesignSearch::applies() const {
  const Impl& s = *impl_;
  return s.options.push == DesignPush::kSustained && s.options.bound && s.triples > kPilot &&
         s.n * (s.n - 1) / 2 <= kMaxPairs;
}

const std::vector<long>& DesignSearch::pilot() const { return impl_->pilot; }

long DesignSearch::singular() const { return impl_->singular; }

bool DesignSearch::start(const std::vector<DesignLayout>& top) {
  const ControlScope between_layouts(nullptr);  // as design()
  Impl& s = *impl_;
  if (!applies()) throw InputError("DesignSearch", "start", "the bound does not apply: score every triple");
  if (s.bound) throw InputError("DesignSearch", "start", "was called twice");
  // If no pilot layout scores above 0, the K-th score may well stay 0, and
  // then the bound could skip only triples whose bound is exactly 0: not
  // worth its pair regions.
  if (std::none_of(top.begin(), top.end(), [](const DesignLayout& l) { return l.score > 0; })) {
    s.over = true;
    return false;
  }
  const int jobs = s.options.jobs > 0 ? s.options.jobs : std::max(1, tbb::info::default_concurrency());
  tbb::task_arena arena(jobs);
  s.bound.emplace(s.part, s.cands, s.options);
  internal::PairBound& bound = *s.bound;
  SharedPoll poll_shared(s.options.control);
  std::atomic<long> done{0};
  const long pairs = bound.pair_count();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<long>(0, pairs, 1), [&](const tbb::blocked_range<long>& r) {
      for (long p = r.begin(); p != r.end(); ++p) {
        bound.compute_pair(p);
        poll_shared("design: pair bounds", ++done, pairs, "pairs");
      }
    });
  });
  // Each other triple's bound, in batches of consecutive indices (kept in
  // index order). When the pilot filled the top K, a triple whose bound is
  // below its K-th score can never enter (the K-th score only grows): it is
  // not kept. Filtered: an upper end below a double under that score
  // proves it; forced exact: the exact bound. Either way such a triple
  // would only ever be skipped, so the search hands out the same triples.
  const long T = s.triples, n = s.n;
  const bool full = static_cast<int>(top.size()) >= s.options.top;
  const Rational floor = full ? top[s.options.top - 1].score : Rational(0);
  double floor_below;
  {
    internal::Protect guard;
    floor_below = internal::to_interval(floor).inf();
  }
  const long batches = (T + kBoundBatch - 1) / kBoundBatch;
  std::vector<std::vector<Ranked>> ranked_in(batches);
  std::vector<long> singular_in(batches, 0);
  std::atomic<long> kept{0};
  std::atomic<bool> too_many{false};
  done = 0;
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<long>(0, batches, 1), [&](const tbb::blocked_range<long>& r) {
      for (long b = r.begin(); b != r.end() && !too_many; ++b) {
        const long first = b * kBoundBatch, count = std::min(kBoundBatch, T - first);
        std::array<int, 3> f = triple_at(n, first);
        auto next_pilot = std::lower_bound(s.pilot.begin(), s.pilot.end(), first);
        long below = 0;
        for (long k = 0; k < count; ++k, internal::next_triple(f, n)) {
          if (next_pilot != s.pilot.end() && *next_pilot == first + k) {
            ++next_pilot;  // scored already
          } else if (bound.singular(f)) {
            ++singular_in[b];
          } else {
            const double upper = bound.upper(f);
            if (full && (force_exact() ? bound.exact(f) < floor : upper < floor_below)) {
              ++below;
              continue;
            }
            ranked_in[b].push_back({first + k, upper});
          }
        }
        if (below && !force_exact()) internal::record_filter(FilterSite::kDesignBound, below, 0);
        if ((kept += static_cast<long>(ranked_in[b].size())) > kept_limit) too_many = true;
        poll_shared("design: triple bounds", done += count, T, "triples");
      }
    });
  });
  if (too_many) {  // more bounds than memory allows: score every triple
    s.over = true;
    s.bound.reset();
    return false;
  }
  for (long b = 0; b < batches; ++b) {
    s.singular += singular_in[b];
    s.ranked.insert(s.ranked.end(), ranked_in[b].begin(), ranked_in[b].end());
  }
  ranked_in.clear();
  arena.execute([&] {
    tbb::parallel_sort(s.ranked.begin(), s.ranked.end(), [](const Ranked& a, const Ranked& b) {
      return a.upper != b.upper ? a.upper > b.upper : a.index < b.index;
    });
  });
  return true;
}

std::optional<std::vector<long>> DesignSearch::next(const std::vector<DesignLayout>& top, long block) {
  const ControlScope between_layouts(nullptr);  // as design()
  Impl& s = *impl_;
  if (block < 1) throw InputError("DesignSearch.next block", std::to_string(block), "must be >= 1");
  if (!s.bound) throw InputError("DesignSearch", "next", "needs start() to have returned true");
  if (s.over) return std::nullopt;
  // Triples done: the singular ones, the pilot's and those ranked before pos.
  poll(s.options.control, "design", s.singular + kPilot + static_cast<long>(s.pos), s.triples, "layouts");
  const bool full = static_cast<int>(top.size()) >= s.options.top;
  const internal::PairBound& bound = *s.bound;
  std::vector<long> chosen;
  for (; s.pos < s.ranked.size() && static_cast<long>(chosen.size()) < block; ++s.pos) {
    const Ranked& r = s.ranked[s.pos];
    if (!full) {
      chosen.push_back(r.index);
      continue;
    }
    const DesignLayout& kth = top[s.options.top - 1];
    // Every triple left has an upper end at most this one's: when it is
    // below the K-th score, none can enter.
    if (bound.none_can_enter(r.upper, kth.score, static_cast<long>(s.ranked.size() - s.pos))) {
      s.over = true;
      break;
    }
    if (bound.can_enter(triple_at(s.n, r.index), r.index, r.upper, kth.score, kth.index)) chosen.push_back(r.index);
  }
  if (s.pos >= s.ranked.size()) s.over = true;
  if (chosen.empty()) return std::nullopt;
  return chosen;
}

}  // namespace fixel
