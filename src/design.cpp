// Fixture design, the search: every triple of candidates in lexicographic
// order, checked options, batches of layouts, the ranking, and the oneTBB
// thread pool (docs/design.md). TBB is used in this file only.
#include "fixel/design.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <utility>

#include "fixel/design_search.h"
#include "fixel/error.h"
#include "fixel/internal/design_detail.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

using internal::boundary_of;
using internal::evaluate;
using internal::next_triple;
using internal::total_length;
using internal::Verdict;

constexpr int kMaxJobs = 256;
constexpr long kBatch = 8;          // triples per unit of work of the thread pool
constexpr long kWindow = 1L << 14;  // batches run between two merges (about 131,000 triples)
// The bounded search: triples scored between two checks of the K-th score
// (fixed, so that the counts do not depend on --jobs).
constexpr long kChunk = 32;

bool better(const DesignLayout& a, const DesignLayout& b) {
  if (a.score != b.score) return a.score > b.score;
  return a.index < b.index;
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

// Scores triples [first, first + count), less those in `scored` (sorted:
// the pilot's, already scored).
template <class OnLayout>
std::vector<DesignLayout> run_range(const Scene& part, const std::vector<DesignCandidate>& cands,
                                    const DesignOptions& o, long first, long count, DesignStats& stats,
                                    OnLayout&& on_layout, const std::vector<long>& scored = {}) {
  const long n = static_cast<long>(cands.size());
  const Rational total = total_length(boundary_of(part));
  const std::vector<internal::Join> joins = internal::joins(boundary_of(part));  // one outline: made once
  std::vector<DesignLayout> best;
  std::array<int, 3> f = triple_at(n, first);
  auto next_scored = std::lower_bound(scored.begin(), scored.end(), first);
  for (long k = 0; k < count; ++k) {
    if (next_scored != scored.end() && *next_scored == first + k) {
      ++next_scored;
      on_layout();
      if (k + 1 < count) next_triple(f, n);
      continue;
    }
    DesignLayout layout;
    layout.fixels = f;
    layout.index = first + k;
    tally(evaluate(part, cands, o, total, f, layout, &joins), std::move(layout), best, stats);
    if (static_cast<long>(best.size()) > 2L * o.top) rank_layouts(best, o.top);  // long: top may be near INT_MAX
    on_layout();
    if (k + 1 < count) next_triple(f, n);
  }
  rank_layouts(best, o.top);
  return best;
}

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

// The sustained ranking with the pair bound (docs/design.md, "The bound"):
// the pilot, then kChunk triples at a time in the search's order until none
// left can enter the top K. False when the bound does not apply, or when the
// pilot scores nothing above 0: then `result` holds the pilot's best K and
// counts, and `pilot` its triples, for the caller to score the others.
bool run_bounded(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o,
                 tbb::task_arena& arena, DesignResult& result, std::vector<long>& pilot) {
  DesignSearch search(part, cands, o);
  if (!search.applies()) return false;
  const std::vector<internal::Join> joins = internal::joins(boundary_of(part));
  const Rational total = total_length(boundary_of(part));
  DesignStats& stats = result.stats;
  std::vector<DesignLayout>& top = result.layouts;
  score_into(search.pilot(), part, cands, o, total, joins, arena, top, stats);
  if (!search.start(top)) {
    pilot = search.pilot();
    return false;
  }
  stats.singular += search.singular();
  while (auto chosen = search.next(top, kChunk)) {
    DesignStats chunk;
    score_into(*chosen, part, cands, o, total, joins, arena, top, chunk);
    if (chunk.singular) throw InternalError("design: a triple the bound found regular is singular");
    stats.no_form_closure += chunk.no_form_closure;
    stats.j_empty += chunk.j_empty;
    stats.regions += chunk.regions;
  }
  stats.bounded = stats.triples - stats.singular - stats.no_form_closure - stats.j_empty - stats.regions;
  return true;
}

}  // namespace

long triple_count(long n) {
  if (n < 3) return 0;
  // n(n−1)(n−2)/6 with the divisions first (one factor is even, one a
  // multiple of 3), then products checked for overflow.
  long f[3] = {n, n - 1, n - 2};
  for (long& x : f)
    if (x % 3 == 0) {
      x /= 3;
      break;
    }
  for (long& x : f)
    if (x % 2 == 0) {
      x /= 2;
      break;
    }
  long count = 0;
  if (__builtin_mul_overflow(f[0], f[1], &count) || __builtin_mul_overflow(count, f[2], &count))
    throw InputError("candidates", std::to_string(n), "give more triples than a long counts");
  return count;
}

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
  if (part.body.dof != 3)
    throw SceneError("body.dof", "2", "is a point mass: fixture design needs a rigid body (dof 3)");
  boundary_of(part);
  check_scene_values(part);
  if (o.resolution <= 0) throw InputError("DesignOptions.resolution", to_string(o.resolution), "must be > 0");
  if (o.mu < 0) throw InputError("DesignOptions.mu", to_string(o.mu), "must be >= 0");
  if (o.mu_hi && *o.mu_hi < o.mu)
    throw InputError("DesignOptions.mu", to_string(o.mu) + "," + to_string(*o.mu_hi), "has lo > hi");
  if (o.pusher_mu < 0) throw InputError("DesignOptions.pusher_mu", to_string(o.pusher_mu), "must be >= 0");
  if (o.pusher_mu_lo && (*o.pusher_mu_lo < 0 || *o.pusher_mu_lo > o.pusher_mu))
    throw InputError("DesignOptions.pusher_mu", to_string(*o.pusher_mu_lo) + "," + to_string(o.pusher_mu),
                     "must be 0 <= lo <= hi");
  if (o.gap < 0) throw InputError("DesignOptions.gap", to_string(o.gap), "must be >= 0");
  if (o.top <= 0) throw InputError("DesignOptions.top", std::to_string(o.top), "must be > 0");
  if (o.jobs < 0 || o.jobs > kMaxJobs)
    throw InputError("DesignOptions.jobs", std::to_string(o.jobs), "must be between 0 (one per core) and 256");
  if (o.push == DesignPush::kStep && o.mu_hi)
    throw UnsupportedError("DesignOptions.mu", to_string(o.mu) + "," + to_string(*o.mu_hi),
                           "is an interval: the one-step ranking (push step) needs one value");
}

void rank_layouts(std::vector<DesignLayout>& layouts, int top) {
  std::sort(layouts.begin(), layouts.end(), better);
  if (top >= 0 && static_cast<int>(layouts.size()) > top) layouts.resize(top);
}

std::vector<DesignLayout> design_batch(const Scene& part, const std::vector<DesignCandidate>& cands,
                                       const DesignOptions& o, long first, long count, DesignStats& stats) {
  const ControlScope between_layouts(nullptr);  // see design()
  check_design(part, o);
  const long total = triple_count(static_cast<long>(cands.size()));
  if (first < 0 || count < 0 || first + count > total)
    throw InputError("batch", std::to_string(first) + "+" + std::to_string(count),
                     "is outside the " + std::to_string(total) + " triples");
  if (count == 0) return {};
  check_candidate_list(cands);
  check_candidates(part, cands);  // the sustained filter reads every candidate, not only the triple's
  long done = 0;
  return run_range(part, cands, o, first, count, stats, [&] { poll(o.control, "design", ++done, count, "layouts"); });
}

std::vector<DesignLayout> design_batch(const Scene& part, const std::vector<DesignCandidate>& cands,
                                       const DesignOptions& o, const std::vector<long>& indices, DesignStats& stats) {
  const ControlScope between_layouts(nullptr);  // see design()
  check_design(part, o);
  const long n = static_cast<long>(cands.size());
  for (std::size_t k = 0; k < indices.size(); ++k)
    if (indices[k] < 0 || indices[k] >= triple_count(n))
      throw InputError("batch[" + std::to_string(k) + "]", std::to_string(indices[k]),
                       "is outside the " + std::to_string(triple_count(n)) + " triples");
  if (!indices.empty()) {
    check_candidate_list(cands);
    check_candidates(part, cands);
  }
  const Rational total = total_length(boundary_of(part));
  const std::vector<internal::Join> joins = internal::joins(boundary_of(part));
  std::vector<DesignLayout> best;
  long done = 0;
  for (long index : indices) {
    DesignLayout layout;
    layout.fixels = triple_at(n, index);
    layout.index = index;
    tally(evaluate(part, cands, o, total, layout.fixels, layout, &joins), std::move(layout), best, stats);
    if (static_cast<long>(best.size()) > 2L * o.top) rank_layouts(best, o.top);  // long: top may be near INT_MAX
    poll(o.control, "design", ++done, static_cast<long>(indices.size()), "layouts");
  }
  rank_layouts(best, o.top);
  return best;
}

DesignResult design(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o) {
  // The search polls between layouts, from any of its threads; a layout's
  // own exact steps do not poll the caller's ControlScope, so a stop names
  // the layouts done.
  const ControlScope between_layouts(nullptr);
  check_design(part, o);
  check_candidate_list(cands);
  check_candidates(part, cands);
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
  std::vector<long> pilot;  // scored already when the bound gives up after its pilot
  if (run_bounded(part, cands, o, arena, result, pilot)) {
    complete_layouts(part, cands, o, result.layouts);
    result.no_layout = no_layout_reason(result.stats, result.layouts.size());
    result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  const long T = result.stats.triples;
  const long batches = (T + kBatch - 1) / kBatch;
  std::atomic<long> done{0};
  std::mutex poll_mutex;
  auto on_layout = [&] {
    const long d = ++done;
    if (!o.control) return;
    std::unique_lock<std::mutex> lock(poll_mutex, std::try_to_lock);
    if (lock.owns_lock()) o.control->poll("design", d, T, "layouts");
  };
  // A window of batches at a time, so that memory does not grow with the
  // triples (C(n, 3) / 8 slots would not fit for thousands of candidates).
  std::vector<std::vector<DesignLayout>> best(std::min(batches, kWindow));
  std::vector<DesignStats> counts(best.size());
  for (long window = 0; window < batches; window += kWindow) {
    const long size = std::min(kWindow, batches - window);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<long>(0, size, 1), [&](const tbb::blocked_range<long>& r) {
        for (long w = r.begin(); w != r.end(); ++w) {
          const long first = (window + w) * kBatch, count = std::min(kBatch, T - first);
          counts[w] = DesignStats{};
          best[w] = run_range(part, cands, o, first, count, counts[w], on_layout, pilot);
        }
      });
    });
    for (long w = 0; w < size; ++w) {
      for (auto& l : best[w]) result.layouts.push_back(std::move(l));
      result.stats.singular += counts[w].singular;
      result.stats.no_form_closure += counts[w].no_form_closure;
      result.stats.j_empty += counts[w].j_empty;
      result.stats.regions += counts[w].regions;
    }
    rank_layouts(result.layouts, o.top);
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
