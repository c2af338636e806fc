// The bounded search driven step by step (include/fixel/design_search.h),
// as a cluster driver does: scoring what it hands out, in blocks of any
// size, gives the layouts of scoring every triple, and with design()'s
// block size also design()'s counts.
#include "fixel/design_search.h"

#include <gtest/gtest.h>

#include <set>

#include "fixel/error.h"
#include "fixel/internal/design_detail.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::scene_file;

// Every other of the part's 24 default candidates: 12, 220 triples.
std::vector<DesignCandidate> every_other(const Scene& part) {
  std::vector<DesignCandidate> all = boundary_candidates(part, std::nullopt), out;
  for (std::size_t k = 0; k < all.size(); k += 2) out.push_back(all[k]);
  return out;
}

DesignOptions small(int top) {
  DesignOptions o;
  o.resolution = Rational(1, 32);
  o.top = top;
  o.jobs = 1;
  return o;
}

struct Driven {
  std::vector<DesignLayout> top;
  DesignStats stats;
  DesignStats handed;  // the counts of the blocks handed out alone
  long handed_out = 0;
  bool repeated = false;  // a triple handed out twice, or one of the pilot's
};

// What fixel.design's Dask driver does, with design_batch in place of a
// worker: the pilot, then `wave` blocks per round, all asked for with the
// best K known before the round.
Driven drive(const Scene& part, const std::vector<DesignCandidate>& c, const DesignOptions& o, long block, int wave) {
  Driven d;
  DesignSearch search(part, c, o);
  EXPECT_TRUE(search.applies());
  d.top = design_batch(part, c, o, search.pilot(), d.stats);
  EXPECT_TRUE(search.start(d.top));
  std::set<long> seen(search.pilot().begin(), search.pilot().end());
  d.stats.singular += search.singular();
  for (bool over = false; !over;) {
    std::vector<std::vector<long>> round;
    for (int k = 0; k < wave; ++k) {
      auto chosen = search.next(d.top, block);
      if (!chosen) {
        over = true;
        break;
      }
      if (!chosen->empty()) round.push_back(*chosen);
    }
    for (const auto& chosen : round) {
      d.handed_out += static_cast<long>(chosen.size());
      for (long index : chosen) d.repeated |= !seen.insert(index).second;
      for (auto& l : design_batch(part, c, o, chosen, d.handed)) d.top.push_back(std::move(l));
      rank_layouts(d.top, o.top);
    }
  }
  d.stats.singular += d.handed.singular;
  d.stats.no_form_closure += d.handed.no_form_closure;
  d.stats.j_empty += d.handed.j_empty;
  d.stats.regions += d.handed.regions;
  d.stats.bounded = triple_count(static_cast<long>(c.size())) - d.stats.singular - d.stats.no_form_closure -
                    d.stats.j_empty - d.stats.regions;
  return d;
}

void expect_same_ranking(const std::vector<DesignLayout>& a, const std::vector<DesignLayout>& b,
                         const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].index, b[k].index) << what << " #" << k;
    EXPECT_EQ(a[k].score, b[k].score) << what << " #" << k;
  }
}

GTEST_TEST(DesignSearch, ScoringWhatItHandsOutInBlocksOfAnySizeGivesTheLayoutsOfScoringEveryTriple) {
  int skipped = 0;
  for (const char* name : {"polygon", "blob"}) {
    const Scene part = scene_file(name);
    const std::vector<DesignCandidate> c = every_other(part);
    for (int top : {1, 3}) {
      DesignOptions o = small(top);
      o.bound = false;
      const DesignResult every = design(part, c, o);
      o.bound = true;
      for (auto [block, wave] : {std::pair<long, int>{1, 1}, {5, 3}, {64, 4}}) {
        const std::string what = std::string(name) + " top " + std::to_string(top) + " block " + std::to_string(block);
        const Driven d = drive(part, c, o, block, wave);
        expect_same_ranking(d.top, every.layouts, what);
        EXPECT_EQ(d.stats.singular, every.stats.singular) << what;
        // Only non-singular triples are bounded.
        EXPECT_LE(d.stats.bounded, every.stats.triples - every.stats.singular) << what;
        // No triple handed out is singular (the bound sorted those out), and
        // none is the pilot's or handed out twice: with every triple scored
        // once, the counts add up.
        EXPECT_EQ(d.handed.singular, 0) << what;
        EXPECT_FALSE(d.repeated) << what;
        EXPECT_EQ(d.handed_out, d.handed.no_form_closure + d.handed.j_empty + d.handed.regions) << what;
        skipped += d.stats.bounded > 0;
      }
    }
  }
  EXPECT_GE(skipped, 8);  // the bound did skip triples in most of the 12 runs
}

GTEST_TEST(DesignSearch, WithDesignsBlockOfThirtyTwoItCountsWhatDesignCounts) {
  const Scene part = scene_file("example2_rounded");
  const std::vector<DesignCandidate> c = every_other(part);
  const DesignOptions o = small(2);
  const DesignResult run = design(part, c, o);
  const Driven d = drive(part, c, o, 32, 1);
  expect_same_ranking(d.top, run.layouts, "example2_rounded");
  EXPECT_EQ(
      std::make_tuple(d.stats.singular, d.stats.no_form_closure, d.stats.j_empty, d.stats.regions, d.stats.bounded),
      std::make_tuple(run.stats.singular, run.stats.no_form_closure, run.stats.j_empty, run.stats.regions,
                      run.stats.bounded));
  EXPECT_GT(run.stats.bounded, 0);
}

// Blocks asked for with an older K-th layout skip less: a wider round never
// scores fewer triples, and still the same layouts.
GTEST_TEST(DesignSearch, AWiderRoundScoresAtLeastAsManyTriples) {
  const Scene part = scene_file("polygon");
  const std::vector<DesignCandidate> c = every_other(part);
  const DesignOptions o = small(3);
  const Driven one = drive(part, c, o, 8, 1), four = drive(part, c, o, 8, 4);
  expect_same_ranking(one.top, four.top, "polygon");
  EXPECT_LE(one.stats.regions + one.stats.j_empty + one.stats.no_form_closure,
            four.stats.regions + four.stats.j_empty + four.stats.no_form_closure);
}

GTEST_TEST(DesignSearch, APilotThatScoresNothingAboveZeroEndsTheSearch) {
  const Scene part = scene_file("nonunique_part");
  std::vector<DesignCandidate> all = boundary_candidates(part, std::nullopt), c;
  for (std::size_t k = 0; k < all.size(); k += 3) c.push_back(all[k]);  // 8 candidates, 56 triples
  const DesignOptions o = small(5);
  DesignSearch search(part, c, o);
  ASSERT_TRUE(search.applies());
  DesignStats stats;
  const std::vector<DesignLayout> top = design_batch(part, c, o, search.pilot(), stats);
  ASSERT_FALSE(top.empty());
  EXPECT_EQ(top.front().score, 0);
  EXPECT_FALSE(search.start(top));
  EXPECT_THROW(search.next(top, 32), InputError);  // nothing to hand out: score every triple
}

// With more bounds to keep than memory allows (here, more than 5), the
// search gives up after the pilot and design() scores every other triple:
// the exhaustive layouts and counts, the pilot's triples scored once.
GTEST_TEST(DesignSearch, TooManyBoundsToKeepSendTheRunToTheExhaustiveSearch) {
  const Scene part = scene_file("polygon");
  const std::vector<DesignCandidate> c = every_other(part);
  DesignOptions o = small(3);
  o.bound = false;
  const DesignResult every = design(part, c, o);
  o.bound = true;
  internal::set_design_kept_limit(5);
  DesignSearch search(part, c, o);
  DesignStats stats;
  const std::vector<DesignLayout> top = design_batch(part, c, o, search.pilot(), stats);
  const bool started = search.start(top);
  const DesignResult run = design(part, c, o);
  internal::set_design_kept_limit(1L << 25);
  EXPECT_FALSE(started);
  EXPECT_EQ(search.singular(), 0);  // nothing counted from the abandoned pass
  expect_same_ranking(run.layouts, every.layouts, "polygon");
  EXPECT_EQ(
      std::make_tuple(run.stats.singular, run.stats.no_form_closure, run.stats.j_empty, run.stats.regions,
                      run.stats.bounded),
      std::make_tuple(every.stats.singular, every.stats.no_form_closure, every.stats.j_empty, every.stats.regions, 0L));
  // Without the switch the same run keeps its bounds and skips triples.
  EXPECT_GT(design(part, c, o).stats.bounded, 0);
}

GTEST_TEST(DesignSearch, ThePilotIsThirtyTwoSpreadTriplesAndOnlyWhenTheBoundApplies) {
  const Scene part = scene_file("polygon");
  const std::vector<DesignCandidate> c = every_other(part);  // 220 triples
  DesignSearch search(part, c, small(5));
  ASSERT_TRUE(search.applies());
  ASSERT_EQ(search.pilot().size(), 32u);
  EXPECT_EQ(search.pilot()[0], 0);
  EXPECT_EQ(search.pilot()[1], 220 / 32);
  EXPECT_EQ(search.pilot()[31], 31 * 220 / 32);
  DesignOptions step = small(5);
  step.push = DesignPush::kStep;
  DesignOptions off = small(5);
  off.bound = false;
  const std::vector<DesignCandidate> few(c.begin(), c.begin() + 6);  // 20 triples: the pilot would be all
  for (const auto& [cands, o] : {std::make_pair(c, step), std::make_pair(c, off), std::make_pair(few, small(5))}) {
    const DesignSearch s(part, cands, o);
    EXPECT_FALSE(s.applies());
    EXPECT_TRUE(s.pilot().empty());
  }
}

GTEST_TEST(DesignSearch, CallsOutOfOrderAndBadBlocksAreInputErrors) {
  const Scene part = scene_file("polygon");
  const std::vector<DesignCandidate> c = every_other(part);
  const DesignOptions o = small(2);
  DesignSearch search(part, c, o);
  EXPECT_THROW(search.next({}, 8), InputError);  // before start()
  DesignStats stats;
  const std::vector<DesignLayout> top = design_batch(part, c, o, search.pilot(), stats);
  ASSERT_TRUE(search.start(top));
  EXPECT_THROW(search.start(top), InputError);
  try {
    search.next(top, 0);
    ADD_FAILURE() << "block 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.value(), "0");
  }
  DesignOptions step = o;
  step.push = DesignPush::kStep;
  DesignSearch not_bounded(part, c, step);
  EXPECT_THROW(not_bounded.start(top), InputError);
  try {
    design_batch(part, c, o, std::vector<long>{3, 220}, stats);
    ADD_FAILURE() << "index 220 of 220 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "batch[1]");
    EXPECT_EQ(e.value(), "220");
  }
  EXPECT_THROW(DesignSearch(part, c, small(0)), InputError);
}

}  // namespace
}  // namespace fixel
