#pragma once
// The final block's short rows, eliminated before lifting
// (src/lemke_dixon_sparse.cpp, docs/theory.md §6). A row of C·x = y with
// y_a = 0 and one nonzero entry says x_j = 0; with two, α·x_i + β·x_j = 0,
// so x_i and x_j are multiples of one unknown t. The seating LCPs' friction
// rows are of this kind (three of about eight rows), and lifting's work
// grows with the cube (factoring) and the square (each step) of the size.
#include <cstdint>
#include <vector>

namespace fixel::internal {

// C·x = y reduced to C′·t = y′ with x = T·t: T has at most one nonzero per
// row, x_j = multiplier[j]·t[unknown[j]], or x_j = 0 when unknown[j] is −1.
// The rows kept are y's rows `rows` (in order), so y′_a = y[rows[a]].
// Exact: the solutions of the two systems correspond one to one, and C′ is
// nonsingular exactly when C is.
struct SparseRowReduction {
  int k = 0;                          // unknowns before
  int reduced = 0;                    // unknowns after, k′
  std::vector<std::int64_t> c_words;  // C′, row-major, k′×k′, each |entry| < 2^59
  std::vector<int> rows;              // C's rows kept
  std::vector<int> unknown;           // per x_j: its t, or −1 when x_j = 0
  std::vector<std::int64_t> multiplier;

  // Reduces C (k×k words, row-major, each |entry| < 2^59), given which rows
  // of y are zero. Eliminations that would take an entry of C′ to 2^59 or a
  // multiplier to 2^62 are not made. False when none was made (then the
  // fields mean nothing and C is solved as it is); false too for k beyond
  // kWordRows or inputs of the wrong size.
  bool reduce(int k, const std::vector<std::int64_t>& c, const std::vector<char>& zero_rhs);

 private:
  // Scratch kept from call to call: C with merged columns, and which rows
  // and columns are still on.
  enum RowState : char { kOn, kOff, kKept };  // kKept: a merge that would overflow, left in C′
  std::vector<std::int64_t> work_;
  std::vector<RowState> row_state_;
  std::vector<char> col_on_;
  std::vector<std::uint32_t> nonzero_;    // per row with y_a = 0: its nonzero columns, as bits
  std::vector<int> column_of_, columns_;  // W's column → t, and t → W's column
};

}  // namespace fixel::internal
