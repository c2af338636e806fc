#pragma once
// What the two files of fixture design's pair bound share
// (design_bound.cpp: the triples' side; design_bound_pairs.cpp: the pairs'
// stretches on shared cones): the grid runs and PairBound's state.

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "fixel/curve.h"
#include "fixel/filter.h"
#include "fixel/internal/design_bound.h"
#include "fixel/internal/enclosed_plane.h"
#include "fixel/internal/filtered.h"
#include "fixel/wrench_cone.h"

namespace fixel::internal {

struct Span {  // cells [lo, hi) of piece `piece`'s grid
  std::int32_t piece, lo, hi;
};

inline FGen enclose(const VectorQ& v) { return {to_interval(v[0]), to_interval(v[1]), to_interval(v[2])}; }

struct PairBound::Impl {
  struct Pair {
    VectorQ c;                              // W_a × W_b
    FGen c_enclosed;                        // its enclosure
    Near3 c_near;                           // doubles near it, for the static filter
    std::array<std::vector<Span>, 2> side;  // [0]: c · w > 0 may hold; [1]: c · w < 0 may
  };

  const Scene& part;
  Rational resolution;
  Rational mu;  // the fixels' friction J is judged at
  int n = 0;
  std::vector<VectorQ> wrench;
  std::vector<VectorQ> tangent_wrench;  // (t, r ⊗ t), t the normal turned +90°
  std::vector<FGen> wrench_enclosed;
  std::vector<int> depth;      // per piece
  std::vector<int> cls;        // per piece: its cell length's class
  std::vector<Rational> unit;  // per class: a cell's parameter length over the outline's
  std::vector<FI> unit_enclosed;
  std::vector<Pair> pairs;

  // The pusher's edge families at its friction: the normal alone for 0,
  // else the fan's two edges n ± μ_p t (an IN point's whole fan is in J).
  Rational pusher_mu;
  std::vector<EdgeFamily> families;

  // A node of a piece's subdivision (heap order: node 1 is the piece, node
  // i's halves are 2i and 2i + 1): its exact sub-piece and, per family, the
  // tight wrench cone there, made once, on first use, by whichever pair's
  // thread gets there first, then shared by every pair.
  struct Cone {
    bool pointed = false;        // false: no cone (the directions turn by π), always split
    std::vector<VectorQ> gens;   // generators
    std::vector<FGen> enclosed;  // their enclosures
    std::vector<Near3> near;     // doubles near them, for the static filter
  };
  struct Node {
    std::once_flag made;
    BezierPiece segment;
    std::vector<Cone> cones;  // per family
  };
  std::vector<std::vector<std::unique_ptr<Node>>> nodes;  // per piece, 2^(depth + 1) slots

  Impl(const Scene& p, const Rational& r, const Rational& m) : part(p), resolution(r), mu(m) {}

  // Node i of piece `piece`, made on first use (design_bound_pairs.cpp).
  const Node& node(int piece, std::size_t i) const;

  long pair_index(int a, int b) const {  // a < b
    return static_cast<long>(a) * (2L * n - a - 1) / 2 + (b - a - 1);
  }
  std::vector<std::pair<int, int>> pair_of;  // index → (a, b)
  int first_of(long p) const { return pair_of[p].first; }
  int second_of(long p) const { return pair_of[p].second; }

  // Sign of det W_n = W_f0 · (W_f1 × W_f2): the enclosures, else exact.
  int det_sign(const std::array<int, 3>& f) const {
    const Pair& p = pairs[pair_index(f[1], f[2])];
    if (!force_exact()) {
      int s;
      {
        Protect guard;
        const FGen& w = wrench_enclosed[f[0]];
        s = certain_sign(w[0] * p.c_enclosed[0] + w[1] * p.c_enclosed[1] + w[2] * p.c_enclosed[2]);
      }
      record_filter(FilterSite::kDesignBound, s != kUndecided);
      if (s != kUndecided) return s;
    }
    return sign(wrench[f[0]].dot(p.c));
  }

  // K's rows a_k = −sign(det)·adj(W_n)_k (docs/theory.md §10.2): row 0 is
  // ±(W_f1 × W_f2), row 1 ∓(W_f0 × W_f2), row 2 ±(W_f0 × W_f1).
  std::array<const std::vector<Span>*, 3> rows_of(const std::array<int, 3>& f) const {
    const int s = det_sign(f) > 0 ? -1 : 1;
    const auto side = [&](int a, int b, int coefficient) {
      return &pairs[pair_index(a, b)].side[coefficient > 0 ? 0 : 1];
    };
    return {side(f[1], f[2], s), side(f[0], f[2], -s), side(f[0], f[1], s)};
  }

  // Cells in all three of the triple's lists, per class.
  template <class Add>
  void shared_cells(const std::array<int, 3>& f, Add&& add) const {
    const auto rows = rows_of(f);
    const std::vector<Span>&A = *rows[0], &B = *rows[1], &C = *rows[2];
    std::size_t i = 0, j = 0, k = 0;
    while (i < A.size() && j < B.size() && k < C.size()) {
      const Span &a = A[i], &b = B[j], &c = C[k];
      // The latest start among the three; a list whose span ends before it advances.
      const auto before = [](const Span& x, const Span& y) {
        return x.piece < y.piece || (x.piece == y.piece && x.hi <= y.lo);
      };
      if (before(a, b) || before(a, c)) {
        ++i;
        continue;
      }
      if (before(b, a) || before(b, c)) {
        ++j;
        continue;
      }
      if (before(c, a) || before(c, b)) {
        ++k;
        continue;
      }
      // All three on one piece and pairwise overlapping: they share
      // [max lo, min hi).
      const std::int32_t lo = std::max(a.lo, std::max(b.lo, c.lo)), hi = std::min(a.hi, std::min(b.hi, c.hi));
      add(cls[a.piece], static_cast<std::int64_t>(hi - lo));
      if (a.hi == hi)
        ++i;
      else if (b.hi == hi)
        ++j;
      else
        ++k;
    }
  }
};

}  // namespace fixel::internal
