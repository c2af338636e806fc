// Fixture design, the search: every triple of candidates in lexicographic
// order, checked options, batches of layouts, the ranking, and the oneTBB
// thread pool (docs/design.md). TBB is used in this file only.
#include "fixel/design.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <utility>

#include "fixel/error.h"
#include "fixel/internal/design_bound.h"
#include "fixel/internal/design_detail.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

using internal::boundary_of;
using internal::evaluate;
using internal::total_length;
using internal::Verdict;

constexpr int kMaxJobs = 256;
constexpr long kBatch = 8;  // triples per unit of work of the thread pool
// The bounded search: triples scored between two checks of the K-th score
// (fixed, so that the counts do not depend on --jobs), triples bounded per
// unit of work, and the most triples it keeps a bound for (16 bytes each).
constexpr long kChunk = 32;
constexpr long kBoundBatch = 1024;
constexpr long kMaxBoundedTriples = 1L << 25;

bool better(const DesignLayout& a, const DesignLayout& b) {
  if (a.score != b.score) return a.score > b.score;
  return a.index < b.index;
}

// The next triple in lexicographic order.
void advance(std::array<int, 3>& f, long n) {
  if (f[2] + 1 < n) {
    ++f[2];
  } else if (f[1] + 2 < n) {
    ++f[1];
    f[2] = f[1] + 1;
  } else {
    ++f[0];
    f[1] = f[0] + 1;
    f[2] = f[0] + 2;
  }
}

// Counts a scored triple by its verdict; a ranked one joins `best`.
void tally(Verdict verdict, DesignLayout&& layout, std::vector<DesignLayout>& best, DesignStats& stats) {
  switch (verdict) {
    case Verdict::kSingular:
      ++stats.singular;
      return;
    case Verdict::kNoFormClosure:
      ++stats.no_form_closure;
      return;
    case Verdict::kJEmpty:
      ++stats.j_empty;
      break;
    case Verdict::kScored:
      ++stats.regions;
      break;
  }
  best.push_back(std::move(layout));
}

template <class OnLayout>
std::vector<DesignLayout> run_range(const Scene& part, const std::vector<DesignCandidate>& cands,
                                    const DesignOptions& o, long first, long count, DesignStats& stats,
                                    OnLayout&& on_layout) {
  const long n = static_cast<long>(cands.size());
  const Rational total = total_length(boundary_of(part));
  const std::vector<internal::Join> joins = internal::joins(boundary_of(part));  // one outline: made once
  std::vector<DesignLayout> best;
  std::array<int, 3> f = triple_at(n, first);
  for (long k = 0; k < count; ++k) {
    DesignLayout layout;
    layout.fixels = f;
    layout.index = first + k;
    tally(evaluate(part, cands, o, total, f, layout, &joins), std::move(layout), best, stats);
    if (static_cast<int>(best.size()) > 2 * o.top) rank_layouts(best, o.top);
    on_layout();
    if (k + 1 < count) advance(f, n);
  }
  rank_layouts(best, o.top);
  return best;
}

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

struct Ranked {
  long index;
  double upper;  // ≥ the triple's exact bound
};

// Scores the triples `chosen` in parallel and merges them, in the order
// given, into `top` (the best K) and the counts.
void score_into(const std::vector<long>& chosen, const Scene& part, const std::vector<DesignCandidate>& cands,
                const DesignOptions& o, const Rational& total, const std::vector<internal::Join>& joins,
                tbb::task_arena& arena, std::vector<DesignLayout>& top, DesignStats& stats) {
  const long n = static_cast<long>(cands.size());
  std::vector<DesignLayout> layouts(chosen.size());
  std::vector<Verdict> verdicts(chosen.size());
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chosen.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t k = r.begin(); k != r.end(); ++k) {
                          layouts[k].fixels = triple_at(n, chosen[k]);
                          layouts[k].index = chosen[k];
                          verdicts[k] = evaluate(part, cands, o, total, layouts[k].fixels, layouts[k], &joins);
                        }
                      });
  });
  for (std::size_t k = 0; k < chosen.size(); ++k) tally(verdicts[k], std::move(layouts[k]), top, stats);
  rank_layouts(top, o.top);
}

// The sustained ranking with the pair bound (docs/design.md, "The bound").
// A pilot first: kChunk triples spread evenly over the indices are scored.
// If none of them scores above 0, the K-th score may well stay 0, and then
// the bound could skip only triples whose bound is exactly 0: not worth
// its pair regions, so the caller scores every triple (false is returned).
// Otherwise every pair's half-space region, every other triple's bound,
// then those triples in order of decreasing bound, kChunk at a time, until
// none left can enter the top K. False too when there are too many triples
// to keep a bound for each.
bool run_bounded(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o,
                 tbb::task_arena& arena, DesignResult& result) {
  const long n = static_cast<long>(cands.size()), T = triple_count(n);
  if (T > kMaxBoundedTriples || T <= kChunk) return false;
  const std::vector<internal::Join> joins = internal::joins(boundary_of(part));
  const Rational total = total_length(boundary_of(part));
  DesignStats& stats = result.stats;
  std::vector<long> pilot;
  for (long k = 0; k < kChunk; ++k) pilot.push_back(k * T / kChunk);
  std::vector<DesignLayout> top;
  DesignStats pilot_stats;
  score_into(pilot, part, cands, o, total, joins, arena, top, pilot_stats);
  if (std::none_of(top.begin(), top.end(), [](const DesignLayout& l) { return l.score > 0; })) return false;
  stats.singular = pilot_stats.singular;
  stats.no_form_closure = pilot_stats.no_form_closure;
  stats.j_empty = pilot_stats.j_empty;
  stats.regions = pilot_stats.regions;
  internal::PairBound bound(part, cands, o);
  SharedPoll poll_shared(o.control);
  std::atomic<long> done{0};
  const long pairs = bound.pair_count();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<long>(0, pairs, 1), [&](const tbb::blocked_range<long>& r) {
      for (long p = r.begin(); p != r.end(); ++p) {
        bound.compute_pair(p, joins);
        poll_shared("design: pair bounds", ++done, pairs, "pairs");
      }
    });
  });
  // Each other triple's bound, in batches of consecutive indices (kept in index order).
  const long batches = (T + kBoundBatch - 1) / kBoundBatch;
  std::vector<std::vector<Ranked>> ranked_in(batches);
  std::vector<long> singular_in(batches, 0);
  done = 0;
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<long>(0, batches, 1), [&](const tbb::blocked_range<long>& r) {
      for (long b = r.begin(); b != r.end(); ++b) {
        const long first = b * kBoundBatch, count = std::min(kBoundBatch, T - first);
        std::array<int, 3> f = triple_at(n, first);
        auto next_pilot = std::lower_bound(pilot.begin(), pilot.end(), first);
        for (long k = 0; k < count; ++k, advance(f, n)) {
          if (next_pilot != pilot.end() && *next_pilot == first + k) {
            ++next_pilot;  // scored already
          } else if (bound.singular(f)) {
            ++singular_in[b];
          } else {
            ranked_in[b].push_back({first + k, bound.upper(f)});
          }
        }
        poll_shared("design: triple bounds", done += count, T, "triples");
      }
    });
  });
  std::vector<Ranked> ranked;
  for (long b = 0; b < batches; ++b) {
    stats.singular += singular_in[b];
    ranked.insert(ranked.end(), ranked_in[b].begin(), ranked_in[b].end());
  }
  ranked_in.clear();
  arena.execute([&] {
    tbb::parallel_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
      return a.upper != b.upper ? a.upper > b.upper : a.index < b.index;
    });
  });
  for (std::size_t pos = 0; pos < ranked.size(); pos += kChunk) {
    // Triples done: the singular ones, the pilot's and those ranked before pos.
    poll(o.control, "design", stats.singular + kChunk + static_cast<long>(pos), T, "layouts");
    const bool full = static_cast<int>(top.size()) == o.top;
    // Every triple left has an upper end at most this one's: when it is
    // below the K-th score, none can enter.
    if (full && bound.none_can_enter(ranked[pos].upper, top.back().score, static_cast<long>(ranked.size() - pos)))
      break;
    std::vector<long> chosen;
    for (std::size_t k = pos; k < std::min(ranked.size(), pos + kChunk); ++k)
      if (!full || bound.can_enter(triple_at(n, ranked[k].index), ranked[k].index, ranked[k].upper, top.back().score,
                                   top.back().index))
        chosen.push_back(ranked[k].index);
    DesignStats chunk;
    score_into(chosen, part, cands, o, total, joins, arena, top, chunk);
    if (chunk.singular) throw InternalError("design: a triple the bound found regular is singular");
    stats.no_form_closure += chunk.no_form_closure;
    stats.j_empty += chunk.j_empty;
    stats.regions += chunk.regions;
  }
  stats.bounded = T - stats.singular - stats.no_form_closure - stats.j_empty - stats.regions;
  result.layouts = std::move(top);
  return true;
}

}  // namespace

long triple_count(long n) { return n < 3 ? 0 : n * (n - 1) / 2 * (n - 2) / 3; }

std::array<int, 3> triple_at(long n, long index) {
  if (index < 0 || index >= triple_count(n))
    throw InputError("triple index", std::to_string(index), "is out of range for " + std::to_string(n) + " candidates");
  std::array<int, 3> f{};
  long r = index;
  int i = 0;
  for (;; ++i) {  // triples whose first entry is i: C(n − 1 − i, 2)
    const long m = n - 1 - i;
    const long c = m * (m - 1) / 2;
    if (r < c) break;
    r -= c;
  }
  int j = i + 1;
  for (;; ++j) {
    const long c = n - 1 - j;
    if (r < c) break;
    r -= c;
  }
  f = {i, j, static_cast<int>(j + 1 + r)};
  return f;
}

void check_design(const Scene& part, const DesignOptions& o) {
  if (part.body.dof != 3) throw SceneError("body.dof", "2", "fixture design needs a rigid body (dof 3)");
  boundary_of(part);
  if (o.resolution <= 0) throw InputError("DesignOptions.resolution", to_string(o.resolution), "must be > 0");
  if (o.mu < 0) throw InputError("DesignOptions.mu", to_string(o.mu), "must be >= 0");
  if (o.mu_hi && *o.mu_hi < o.mu)
    throw InputError("DesignOptions.mu", to_string(o.mu) + "," + to_string(*o.mu_hi), "has lo > hi");
  if (o.pusher_mu < 0) throw InputError("DesignOptions.pusher_mu", to_string(o.pusher_mu), "must be >= 0");
  if (o.gap < 0) throw InputError("DesignOptions.gap", to_string(o.gap), "must be >= 0");
  if (o.top <= 0) throw InputError("DesignOptions.top", std::to_string(o.top), "must be > 0");
  if (o.jobs < 0 || o.jobs > kMaxJobs)
    throw InputError("DesignOptions.jobs", std::to_string(o.jobs), "must be between 0 (one per core) and 256");
  if (o.push == DesignPush::kStep && o.mu_hi)
    throw UnsupportedError("DesignOptions.mu", to_string(o.mu) + "," + to_string(*o.mu_hi),
                           "is an interval: the one-step ranking (--push step) needs one value");
}

void rank_layouts(std::vector<DesignLayout>& layouts, int top) {
  std::sort(layouts.begin(), layouts.end(), better);
  if (top >= 0 && static_cast<int>(layouts.size()) > top) layouts.resize(top);
}

std::vector<DesignLayout> design_batch(const Scene& part, const std::vector<DesignCandidate>& cands,
                                       const DesignOptions& o, long first, long count, DesignStats& stats) {
  check_design(part, o);
  const long total = triple_count(static_cast<long>(cands.size()));
  if (first < 0 || count < 0 || first + count > total)
    throw InputError("batch", std::to_string(first) + "+" + std::to_string(count),
                     "is outside the " + std::to_string(total) + " triples");
  if (count == 0) return {};
  long done = 0;
  return run_range(part, cands, o, first, count, stats, [&] { poll(o.control, "design", ++done, count, "layouts"); });
}

DesignResult design(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o) {
  check_design(part, o);
  const auto start = std::chrono::steady_clock::now();
  DesignResult result;
  result.candidates = cands;
  const long n = static_cast<long>(cands.size());
  result.stats.candidates = n;
  result.stats.triples = triple_count(n);
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1, tbb::info::default_concurrency());
  result.stats.jobs = jobs;
  if (n < 3) {
    result.no_layout = no_layout_reason(result.stats, 0);
    return result;
  }
  tbb::task_arena arena(jobs);
  if (o.push == DesignPush::kSustained && o.bound && run_bounded(part, cands, o, arena, result)) {
    complete_layouts(part, cands, o, result.layouts);
    result.no_layout = no_layout_reason(result.stats, result.layouts.size());
    result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  const long T = result.stats.triples;
  const long batches = (T + kBatch - 1) / kBatch;
  std::vector<std::vector<DesignLayout>> best(batches);
  std::vector<DesignStats> counts(batches);
  std::atomic<long> done{0};
  std::mutex poll_mutex;
  auto on_layout = [&] {
    const long d = ++done;
    if (!o.control) return;
    std::unique_lock<std::mutex> lock(poll_mutex, std::try_to_lock);
    if (lock.owns_lock()) o.control->poll("design", d, T, "layouts");
  };
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<long>(0, batches, 1), [&](const tbb::blocked_range<long>& r) {
      for (long b = r.begin(); b != r.end(); ++b) {
        const long first = b * kBatch, count = std::min(kBatch, T - first);
        best[b] = run_range(part, cands, o, first, count, counts[b], on_layout);
      }
    });
  });
  for (long b = 0; b < batches; ++b) {
    for (auto& l : best[b]) result.layouts.push_back(std::move(l));
    result.stats.singular += counts[b].singular;
    result.stats.no_form_closure += counts[b].no_form_closure;
    result.stats.j_empty += counts[b].j_empty;
    result.stats.regions += counts[b].regions;
  }
  rank_layouts(result.layouts, o.top);
  complete_layouts(part, cands, o, result.layouts);
  result.no_layout = no_layout_reason(result.stats, result.layouts.size());
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string no_layout_reason(const DesignStats& stats, std::size_t layouts) {
  if (stats.candidates < 3)
    return "only " + std::to_string(stats.candidates) + " candidate" + (stats.candidates == 1 ? "" : "s") +
           ": a layout needs three fixels";
  if (layouts > 0) return "";
  return "every one of the " + std::to_string(stats.triples) + " triples was dropped (" +
         std::to_string(stats.singular) + " with W_n singular, " + std::to_string(stats.no_form_closure) +
         " without form closure)";
}

}  // namespace fixel
