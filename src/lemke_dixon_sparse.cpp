#include "fixel/internal/lemke_dixon_sparse.h"

#include <cstddef>
#include <cstdlib>
#include <numeric>

#include "fixel/internal/lemke_dixon_words.h"

namespace fixel::internal {

namespace {

constexpr Int128 kEntryLimit = Int128(1) << 59;  // kWordEntry: the lifting's bound on C's entries
// Multipliers are kept as int64 (below 2^62), and a tie's β′·m (|β′| < 2^59)
// then stays within Int128 in the check that precedes it.
constexpr Int128 kMultiplierLimit = Int128(1) << 62;

static_assert(kEntryLimit == Int128(kWordEntry), "C′ must stay within the word lifting's bound");

bool within(Int128 x, Int128 limit) { return x < limit && x > -limit; }

// a·b exactly (one 64×64→128 multiplication).
Int128 product(std::int64_t a, std::int64_t b) { return static_cast<Int128>(a) * b; }

}  // namespace

bool SparseRowReduction::reduce(int size, const std::vector<std::int64_t>& c, const std::vector<char>& zero_rhs) {
  const auto entries = static_cast<std::size_t>(size) * size;
  if (size <= 0 || size > kWordRows || c.size() != entries || zero_rhs.size() != static_cast<std::size_t>(size))
    return false;
  k = size;
  // Candidates first: the rows with y_a = 0 (most rows have y_a ≠ 0, and
  // nothing is copied when none has).
  int candidates = 0;
  for (int a = 0; a < k; ++a) candidates += zero_rhs[a] != 0;
  if (candidates == 0) return false;
  // W: C with the merged columns; the eliminated rows and columns are
  // switched off rather than moved.
  work_.assign(c.begin(), c.end());
  row_state_.assign(k, kOn);
  col_on_.assign(k, 1);
  std::uint32_t columns_on = (std::uint32_t{1} << k) - 1;  // k ≤ kWordRows = 16
  const auto at = [&](int a, int j) -> std::int64_t& { return work_[static_cast<std::size_t>(a) * k + j]; };
  // Per candidate row, its nonzero columns as bits: a row's count and
  // columns without a branch per entry.
  nonzero_.assign(k, 0);
  for (int a = 0; a < k; ++a)
    if (zero_rhs[a])
      for (int j = 0; j < k; ++j) nonzero_[a] |= static_cast<std::uint32_t>(at(a, j) != 0) << j;
  unknown.resize(k);
  multiplier.assign(k, 1);
  for (int j = 0; j < k; ++j) unknown[j] = j;
  int eliminated = 0;
  // Passes over the candidate rows until one eliminates nothing; every pass
  // but the last eliminates a row, so at most k + 1 passes.
  for (bool progress = true; progress;) {
    progress = false;
    for (int a = 0; a < k; ++a) {
      if (row_state_[a] != kOn || !zero_rhs[a]) continue;
      const std::uint32_t on = nonzero_[a] & columns_on;
      if (on == 0) continue;  // a zero row: C is singular, and stays so
      const std::uint32_t rest = on & (on - 1);
      if ((rest & (rest - 1)) != 0) continue;  // three entries or more
      const int first = __builtin_ctz(on);
      if (rest == 0) {  // C(a, first)·x_first = 0
        for (int j = 0; j < k; ++j)
          if (unknown[j] == first) unknown[j] = -1;
        row_state_[a] = kOff;
        col_on_[first] = 0;
        columns_on &= ~(std::uint32_t{1} << first);
        ++eliminated;
        progress = true;
        continue;
      }
      // α·x_p + β·x_q = 0: x_p = β′·t, x_q = −α′·t with (α′, β′) = (α, β)/g;
      // t's column is β′·C(·, p) − α′·C(·, q), kept in p's place.
      const int p = first, q = __builtin_ctz(rest);
      const std::int64_t g = std::gcd(at(a, p), at(a, q));  // positive: both nonzero
      const std::int64_t alpha = at(a, p) / g, beta = at(a, q) / g;
      bool fits = true;
      for (int r = 0; r < k && fits; ++r)
        if (row_state_[r] != kOff && r != a)
          fits = within(product(beta, at(r, p)) - product(alpha, at(r, q)), kEntryLimit);
      for (int j = 0; j < k && fits; ++j) {
        if (unknown[j] == p) fits = within(product(beta, multiplier[j]), kMultiplierLimit);
        if (unknown[j] == q) fits = within(-product(alpha, multiplier[j]), kMultiplierLimit);
      }
      if (!fits) {
        row_state_[a] = kKept;  // not tried again, which bounds the passes
        continue;
      }
      for (int r = 0; r < k; ++r) {
        if (row_state_[r] == kOff) continue;
        at(r, p) = static_cast<std::int64_t>(product(beta, at(r, p)) - product(alpha, at(r, q)));
        const std::uint32_t bit = std::uint32_t{1} << p;
        nonzero_[r] = (nonzero_[r] & ~bit) | (at(r, p) != 0 ? bit : 0);
      }
      for (int j = 0; j < k; ++j) {
        if (unknown[j] == p) {
          multiplier[j] = static_cast<std::int64_t>(product(beta, multiplier[j]));
        } else if (unknown[j] == q) {
          multiplier[j] = static_cast<std::int64_t>(-product(alpha, multiplier[j]));
          unknown[j] = p;
        }
      }
      row_state_[a] = kOff;
      col_on_[q] = 0;
      columns_on &= ~(std::uint32_t{1} << q);
      ++eliminated;
      progress = true;
    }
  }
  if (eliminated == 0) return false;
  // Compact: C′ from the rows and columns still on, t numbered in order.
  column_of_.assign(k, -1);
  columns_.clear();
  for (int j = 0; j < k; ++j) {
    if (!col_on_[j]) continue;
    column_of_[j] = static_cast<int>(columns_.size());
    columns_.push_back(j);
  }
  reduced = static_cast<int>(columns_.size());
  rows.clear();
  for (int a = 0; a < k; ++a)
    if (row_state_[a] != kOff) rows.push_back(a);
  c_words.resize(static_cast<std::size_t>(reduced) * reduced);
  std::int64_t* out = c_words.data();
  for (const int a : rows)
    for (const int j : columns_) *out++ = at(a, j);
  for (int j = 0; j < k; ++j)
    if (unknown[j] >= 0) unknown[j] = column_of_[unknown[j]];
  return true;
}

}  // namespace fixel::internal
