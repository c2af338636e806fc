#pragma once
/// @file
/// Fixture design's bounded search, one step at a time (docs/design.md, "The
/// bound"): the order in which design() scores the triples and the rule that
/// skips them, for a caller that scores the triples itself, such as
/// fixel.design's Dask path. design() drives the same object.
#include <memory>
#include <optional>
#include <vector>

#include "fixel/design.h"

namespace fixel {

/// The bounded search of the sustained ranking. Use: score pilot(); pass its
/// best K to start(); while next() hands out a block, score the block and
/// merge it into the best K (rank_layouts). The layouts are those of
/// scoring every triple; the counts depend only on the block sizes asked
/// for, never on threads or on which worker scored what.
class DesignSearch {
 public:
  /// Checks the part and options as check_design, and the candidates as
  /// check_candidate_list and check_candidates. Nothing else is computed
  /// yet. The candidates are copied.
  DesignSearch(const Scene& part, const std::vector<DesignCandidate>& candidates, const DesignOptions& options);

  /// Whether the bound applies: the sustained ranking with
  /// DesignOptions::bound, more than 32 triples and at most 1,024 candidates
  /// (the pairs' stretches take a few hundred bytes a pair). When it does
  /// not, score every triple.
  bool applies() const;
  /// The pilot's triple indices (32 spread evenly over them, increasing);
  /// empty when the bound does not apply.
  const std::vector<long>& pilot() const;
  /// After the pilot: `top` is its best K, best first. Returns false when
  /// no pilot layout scores above 0 (the bound would skip almost nothing),
  /// or when more than 2^25 triples may still beat the pilot's K-th score
  /// (their bounds would not fit in half a gigabyte): then score every
  /// other triple. Otherwise computes every pair's stretches and every
  /// other triple's bound on DesignOptions::jobs threads, keeps those that
  /// may beat the pilot's K-th score, sorts them by decreasing bound, and
  /// returns true. Polls DesignOptions::control. Throws InputError if the
  /// bound does not apply or start() already ran.
  bool start(const std::vector<DesignLayout>& top);
  /// The next triples, at most `block`, in order of decreasing bound (ties
  /// by index) that may still enter `top` (the best K so far, best first):
  /// those whose exact bound cannot are passed over. std::nullopt when no
  /// triple left can enter: the search is over. Throws InputError for
  /// block < 1 or before start() returned true.
  std::optional<std::vector<long>> next(const std::vector<DesignLayout>& top, long block);
  /// Triples the bound found singular (never handed out; the pilot's are
  /// counted by whoever scored it).
  long singular() const;

  ~DesignSearch();
  DesignSearch(DesignSearch&&) noexcept;
  DesignSearch& operator=(DesignSearch&&) noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fixel
