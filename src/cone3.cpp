// Fourier–Motzkin feasibility over Q(√d) on enclosures, with exact rows
// computed only where a sign needs them (internal/cone3.h).
#include <array>
#include <deque>
#include <optional>

#include "fixel/internal/cone3.h"
#include "fixel/progress.h"

namespace fixel::internal {

namespace {

// A row of the elimination: its enclosure, and how its exact form is made
// (an input row, or wp·P + wn·N eliminating unknown j), computed on demand
// coefficient by coefficient (k = 0..2 the a's, 3 the right side b).
struct Node {
  A3<FI> a;
  FI b;
  bool strict = false;
  int p = -1, n = -1, j = -1;                // parents and the unknown eliminated (−1: an input row)
  std::array<int, 4> exact{-1, -1, -1, -1};  // index of each exact coefficient, once computed
};

// An enclosure of x (to_interval_q2: an irrational's is kept in x, and
// rows copied from J's data bring it along).
FI enclosure(const Q2& x) { return to_interval_q2(x); }

// The elimination's vectors, reused from call to call (one per thread; a
// call does not nest another).
struct Storage {
  std::vector<Node> nodes;
  std::deque<Q2> exact;  // the exact coefficients computed (a deque: references stay valid)
  std::vector<int> rows, pos, neg, next;
};

Storage& storage() {
  thread_local Storage s;
  return s;
}

class Elimination {
 public:
  explicit Elimination(const std::vector<Row<Q2>>& rows) : input_(&rows) {
    start();
    for (std::size_t r = 0; r < rows.size(); ++r) {
      add_input(rows[r].a, enclosure(rows[r].b), rows[r].strict);
      homogeneous_ = homogeneous_ && CGAL::is_zero(rows[r].b);
    }
  }
  explicit Elimination(const std::vector<RowRef<Q2>>& refs) : refs_(&refs) {
    start();
    for (const auto& r : refs) add_input(*r.a, FI(0), r.strict);
  }
  explicit Elimination(const std::vector<MixedRow>& mixed) : mixed_(&mixed) {
    start();
    for (const auto& r : mixed) {
      Node x;
      x.a = r.a;
      x.b = r.b;
      x.strict = r.strict;
      x.p = static_cast<int>(nodes_.size());
      nodes_.push_back(x);
      homogeneous_ = homogeneous_ && certain_sign(r.b) == 0;
    }
  }

  bool used_exact() const { return used_exact_; }

  // feasible() (cone3.h), step for step, on nodes.
  bool run() {
    std::vector<int>&rows = storage_.rows, &pos = storage_.pos, &neg = storage_.neg, &next = storage_.next;
    rows.resize(nodes_.size());
    for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = static_cast<int>(r);
    for (int j = 2; j >= -1; --j) {
      pos.clear();
      neg.clear();
      next.clear();
      for (const int r : rows) {
        bool zero = true;
        for (int k = 0; k <= std::max(j, 0) && zero; ++k) zero = sign_of(r, k) == 0;
        if (j < 0 || zero) {
          bool all_zero = true;
          for (int k = 0; k < 3; ++k) all_zero = all_zero && sign_of(r, k) == 0;
          if (all_zero) {
            const int sb = sign_of(r, 3);
            if (nodes_[r].strict ? sb >= 0 : sb > 0) return false;
            continue;
          }
        }
        if (j < 0) continue;
        const int s = sign_of(r, j);
        (s > 0 ? pos : (s < 0 ? neg : next)).push_back(r);
      }
      if (j < 0) return true;
      if (j == 0 && homogeneous_) {  // as in feasible(): only strictness is left
        bool strict = false;
        if (!pos.empty() && !neg.empty()) {
          for (const int r : pos) strict = strict || nodes_[r].strict;
          for (const int r : neg) strict = strict || nodes_[r].strict;
        }
        if (strict) return false;
        rows.swap(next);
        continue;
      }
      if (pos.size() * neg.size() + next.size() > kMaxRows)
        throw InternalError("sustained set: Fourier-Motzkin exceeded " + std::to_string(kMaxRows) + " rows");
      for (const int P : pos)
        for (const int N : neg) {
          Node x;
          const FI wp = -nodes_[N].a[j], wn = nodes_[P].a[j];
          for (int k = 0; k < j; ++k) x.a[k] = wp * nodes_[P].a[k] + wn * nodes_[N].a[k];
          for (int k = j; k < 3; ++k) x.a[k] = FI(0);  // eliminated, as in feasible()
          x.b = homogeneous_ ? FI(0) : wp * nodes_[P].b + wn * nodes_[N].b;
          x.strict = nodes_[P].strict || nodes_[N].strict;
          x.p = P;
          x.n = N;
          x.j = j;
          next.push_back(static_cast<int>(nodes_.size()));
          nodes_.push_back(x);
        }
      rows.swap(next);
    }
    return true;
  }

 private:
  // Sign of coefficient k (3: the right side) of row r: its enclosure's
  // when certain, else the exact coefficient's.
  int sign_of(int r, int k) {
    const FI& x = k < 3 ? nodes_[r].a[k] : nodes_[r].b;
    const int s = certain_sign(x);
    if (s != kUndecided) return s;
    const Q2& e = exact(r, k);
    const Protect_nearest nearest(CGAL_FE_TONEAREST);  // exact signs in the default rounding mode
    return sign(e);
  }

  // Coefficient k of the exact row r: an input row's own, or
  // wp·P_k + wn·N_k with wp = −N_j, wn = P_j from its parents' exact
  // coefficients (memoised, so each is computed once); its enclosure is
  // then narrowed to the exact value's (a zero becomes a point), so that
  // rows made from it later are tighter. Row r's coefficient j is zero by
  // construction.
  const Q2& exact(int r, int k) {
    used_exact_ = true;
    const Node x = nodes_[r];  // a copy: nodes_ may not grow here, but exact() recurses
    if (x.j < 0) return input_coefficient(x.p, k);
    if (x.exact[k] >= 0) return exact_[x.exact[k]];
    if (k == x.j) {
      exact_.push_back(Q2(0));
    } else {
      poll_exact_step();  // thousands of digits make each product slow
      const Q2& pj = exact(x.p, x.j);
      const Q2& nj = exact(x.n, x.j);
      const Q2& pk = exact(x.p, k);
      const Q2& nk = exact(x.n, k);
      const Protect_nearest nearest(CGAL_FE_TONEAREST);  // exact arithmetic in the default rounding mode
      exact_.push_back(-nj * pk + pj * nk);
    }
    nodes_[r].exact[k] = static_cast<int>(exact_.size()) - 1;
    const Q2& e = exact_.back();
    (k < 3 ? nodes_[r].a[k] : nodes_[r].b) = enclosure(e);
    return e;
  }

  const Q2& input_coefficient(int p, int k) {
    if (input_) return k < 3 ? (*input_)[p].a[k] : (*input_)[p].b;
    if (mixed_) {
      const MixedRow& r = (*mixed_)[p];
      if (!r.exact_a) throw Undecided();  // an enclosure only: the sign stays open
      return k < 3 ? (*r.exact_a)[k] : *r.exact_b;
    }
    static const Q2 zero(0);  // rows by reference are homogeneous
    return k < 3 ? (*(*refs_)[p].a)[k] : zero;
  }

  void start() {
    nodes_.clear();
    exact_.clear();
  }
  void add_input(const A3<Q2>& a, const FI& b, bool strict) {
    Node x;
    for (int k = 0; k < 3; ++k) x.a[k] = enclosure(a[k]);
    x.b = b;
    x.strict = strict;
    x.p = static_cast<int>(nodes_.size());  // an input row: p indexes the input
    nodes_.push_back(x);
  }

  using Protect_nearest = CGAL::Protect_FPU_rounding<true>;

  const std::vector<Row<Q2>>* input_ = nullptr;    // the input rows, when given as rows
  const std::vector<RowRef<Q2>>* refs_ = nullptr;  // or by reference
  const std::vector<MixedRow>* mixed_ = nullptr;   // or enclosures, some with their exact rows
  Storage& storage_ = storage();
  std::vector<Node>& nodes_ = storage_.nodes;
  std::deque<Q2>& exact_ = storage_.exact;
  bool used_exact_ = false;
  bool homogeneous_ = true;  // every b exactly 0: by reference always
};

}  // namespace

std::vector<A3<Q2>> rays_of(const std::vector<A3<Q2>>& rows) {
  if (force_exact()) return rays_of<Q2>(rows);
  std::vector<A3<FI>> enclosed;
  for (const auto& a : rows) enclosed.push_back({enclosure(a[0]), enclosure(a[1]), enclosure(a[2])});
  std::vector<A3<Q2>> out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j) {
      poll_exact_step();  // as in the generic rays_of (cone3.h)
      A3<FI> c_enclosed;
      bool nonzero = false;
      {
        Protect guard;
        c_enclosed = cross3(enclosed[i], enclosed[j]);
        for (const FI& x : c_enclosed) nonzero = nonzero || (certain_sign(x) != kUndecided && certain_sign(x) != 0);
      }
      std::optional<A3<Q2>> c;  // the exact product, made when needed
      auto exact = [&]() -> const A3<Q2>& {
        if (!c) c = cross3(rows[i], rows[j]);
        return *c;
      };
      if (!nonzero && is_zero3(exact())) continue;
      for (const int side : {1, -1}) {
        bool ok = true;
        for (std::size_t k = 0; k < rows.size() && ok; ++k) {
          if (k == i || k == j) continue;
          int s = kUndecided;
          {
            Protect guard;
            s = certain_sign(dot3(enclosed[k], c_enclosed));
          }
          record_filter(FilterSite::kJam, s != kUndecided);
          if (s == kUndecided) s = sign(dot3(rows[k], exact()));
          ok = side * s >= 0;
        }
        if (ok) add_unique(out, side > 0 ? exact() : neg3(exact()));
      }
    }
  return out;
}

bool feasible_filtered(const std::vector<Row<Q2>>& rows) {
  if (force_exact()) return feasible(rows);
  Protect guard;  // the enclosures' arithmetic; exact rows switch back to nearest
  Elimination e(rows);
  const bool answer = e.run();
  record_filter(FilterSite::kFeasibility, !e.used_exact());
  return answer;
}

bool feasible_filtered(const std::vector<RowRef<Q2>>& refs) {
  if (force_exact()) {
    std::vector<Row<Q2>> rows;
    for (const auto& r : refs) rows.push_back({*r.a, Q2(0), r.strict});
    return feasible(std::move(rows));
  }
  Protect guard;
  Elimination e(refs);
  const bool answer = e.run();
  record_filter(FilterSite::kFeasibility, !e.used_exact());
  return answer;
}

bool feasible_mixed(const std::vector<MixedRow>& rows) {
  Protect guard;
  Elimination e(rows);
  const bool answer = e.run();
  record_filter(FilterSite::kFeasibility, !e.used_exact());
  return answer;
}

// facets_of over Q(√d) or Q, filtered (cone3.h).
template <class NT>
std::vector<A3<NT>> facets_filtered(const std::vector<A3<NT>>& gens, bool planar) {
  if (force_exact() || planar) return facets_of<NT>(gens, planar);
  std::vector<A3<FI>> enclosed;
  for (const auto& g : gens) enclosed.push_back({enclosure_of(g[0]), enclosure_of(g[1]), enclosure_of(g[2])});
  std::vector<A3<NT>> out;
  std::vector<A3<FI>> out_enclosed;
  for (std::size_t i = 0; i < gens.size(); ++i)
    for (std::size_t j = i + 1; j < gens.size(); ++j) {
      poll_exact_step();
      A3<FI> c_enclosed;
      {
        Protect guard;
        c_enclosed = cross3(enclosed[i], enclosed[j]);
      }
      std::optional<A3<NT>> c;  // the exact product, made when needed
      auto exact = [&]() -> const A3<NT>& {
        if (!c) c = cross3(gens[i], gens[j]);
        return *c;
      };
      // supporting_side (cone3.h), each sign on enclosures first.
      bool nonneg = true, nonpos = true;
      for (std::size_t k = 0; k < gens.size() && (nonneg || nonpos); ++k) {
        if (k == i || k == j) continue;
        int s = kUndecided;
        {
          Protect guard;
          s = certain_sign(dot3(c_enclosed, enclosed[k]));
        }
        record_filter(FilterSite::kJam, s != kUndecided);
        if (s == kUndecided) s = sign(dot3(exact(), gens[k]));
        nonneg = nonneg && s >= 0;
        nonpos = nonpos && s <= 0;
      }
      const int side = nonneg ? 1 : (nonpos ? -1 : 0);
      if (side == 0) continue;
      const A3<NT> a = side > 0 ? exact() : neg3(exact());
      const A3<FI> a_enclosed = side > 0 ? c_enclosed : A3<FI>{-c_enclosed[0], -c_enclosed[1], -c_enclosed[2]};
      // add_unique (cone3.h): a repeat is a positive multiple of a facet
      // kept; a certainly nonzero cross product rules one out.
      bool repeat = false;
      for (std::size_t q = 0; q < out.size() && !repeat; ++q) {
        bool apart = false;
        {
          Protect guard;
          for (const FI& x : cross3(out_enclosed[q], a_enclosed)) {
            const int sx = certain_sign(x);
            apart = apart || (sx != kUndecided && sx != 0);
          }
        }
        if (apart) continue;
        try {
          repeat = is_zero3(cross3(out[q], a)) && sign_dot3(out[q], a) > 0;
        } catch (const Undecided&) {
        }
      }
      if (repeat) continue;
      out.push_back(a);
      out_enclosed.push_back(a_enclosed);
    }
  return out;
}

std::vector<A3<Q2>> facets_of(const std::vector<A3<Q2>>& gens, bool planar) { return facets_filtered(gens, planar); }
std::vector<A3<Rational>> facets_of(const std::vector<A3<Rational>>& gens, bool planar) {
  return facets_filtered(gens, planar);
}

}  // namespace fixel::internal
