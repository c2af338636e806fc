// Fourier–Motzkin feasibility over Q(√d) on enclosures, with exact rows
// computed only where a sign needs them (internal/cone3.h).
#include <deque>
#include <optional>

#include "fixel/internal/cone3.h"

namespace fixel::internal {

namespace {

// A row of the elimination: its enclosure, and how its exact form is made
// (an input row, or wp·P + wn·N eliminating unknown j), computed on demand.
struct Node {
  A3<FI> a;
  FI b;
  bool strict = false;
  int p = -1, n = -1, j = -1;  // parents and the unknown eliminated (−1: an input row)
  int exact = -1;              // index of the exact row, once computed
};

// An enclosure of x (to_interval_q2: an irrational's is kept in x, and
// rows copied from J's data bring it along).
FI enclosure(const Q2& x) { return to_interval_q2(x); }

// The elimination's vectors, reused from call to call (one per thread; a
// call does not nest another).
struct Storage {
  std::vector<Node> nodes;
  std::deque<Row<Q2>> exact;
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
    for (std::size_t r = 0; r < rows.size(); ++r) add_input(rows[r].a, enclosure(rows[r].b), rows[r].strict);
  }
  explicit Elimination(const std::vector<RowRef<Q2>>& refs) : refs_(&refs) {
    start();
    for (const auto& r : refs) add_input(*r.a, FI(0), r.strict);
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
      if (pos.size() * neg.size() + next.size() > kMaxRows)
        throw InternalError("sustained set: Fourier-Motzkin exceeded " + std::to_string(kMaxRows) + " rows");
      for (const int P : pos)
        for (const int N : neg) {
          Node x;
          const FI wp = -nodes_[N].a[j], wn = nodes_[P].a[j];
          for (int k = 0; k < 3; ++k) x.a[k] = wp * nodes_[P].a[k] + wn * nodes_[N].a[k];
          x.a[j] = FI(0);
          x.b = wp * nodes_[P].b + wn * nodes_[N].b;
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
  // when certain, else the exact row's.
  int sign_of(int r, int k) {
    const FI& x = k < 3 ? nodes_[r].a[k] : nodes_[r].b;
    const int s = certain_sign(x);
    if (s != kUndecided) return s;
    const Row<Q2>& e = exact(r);
    const Protect_nearest nearest(CGAL_FE_TONEAREST);  // exact signs in the default rounding mode
    return sign(k < 3 ? e.a[k] : e.b);
  }

  // The exact row r, from its parents' exact rows (memoised); its
  // enclosure is then narrowed to the exact values' (a zero becomes a
  // point), so that rows made from it later are tighter.
  const Row<Q2>& exact(int r) {
    used_exact_ = true;
    const Node x = nodes_[r];  // a copy: the parents' exact rows are made first
    if (x.j < 0 && input_) return (*input_)[x.p];
    if (x.exact >= 0) return exact_[x.exact];
    if (x.j < 0) {  // an input row by reference: copied once, now
      const RowRef<Q2>& ref = (*refs_)[x.p];
      exact_.push_back(Row<Q2>{*ref.a, Q2(0), ref.strict});
      nodes_[r].exact = static_cast<int>(exact_.size()) - 1;
      return exact_.back();
    }
    const Row<Q2>& P = exact(x.p);  // exact_ is a deque: references stay valid
    const Row<Q2>& N = exact(x.n);
    const int j = x.j;
    {
      const Protect_nearest nearest(CGAL_FE_TONEAREST);  // exact arithmetic in the default rounding mode
      const Q2 wp = -N.a[j], wn = P.a[j];
      Row<Q2> out;
      for (int k = 0; k < 3; ++k) out.a[k] = wp * P.a[k] + wn * N.a[k];
      out.a[j] = Q2(0);
      out.b = wp * P.b + wn * N.b;
      out.strict = P.strict || N.strict;
      exact_.push_back(std::move(out));
    }
    Node& y = nodes_[r];
    y.exact = static_cast<int>(exact_.size()) - 1;
    const Row<Q2>& e = exact_.back();
    for (int k = 0; k < 3; ++k) y.a[k] = enclosure(e.a[k]);
    y.b = enclosure(e.b);
    return e;
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
  Storage& storage_ = storage();
  std::vector<Node>& nodes_ = storage_.nodes;
  std::deque<Row<Q2>>& exact_ = storage_.exact;
  bool used_exact_ = false;
};

}  // namespace

std::vector<A3<Q2>> rays_of(const std::vector<A3<Q2>>& rows) {
  if (force_exact()) return rays_of<Q2>(rows);
  std::vector<A3<FI>> enclosed;
  for (const auto& a : rows) enclosed.push_back({enclosure(a[0]), enclosure(a[1]), enclosure(a[2])});
  std::vector<A3<Q2>> out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j) {
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

std::vector<A3<Q2>> facets_of(const std::vector<A3<Q2>>& gens, bool planar) {
  if (force_exact() || planar) return facets_of<Q2>(gens, planar);
  std::vector<A3<FI>> enclosed;
  for (const auto& g : gens) enclosed.push_back({enclosure(g[0]), enclosure(g[1]), enclosure(g[2])});
  std::vector<A3<Q2>> out;
  std::vector<A3<FI>> out_enclosed;
  for (std::size_t i = 0; i < gens.size(); ++i)
    for (std::size_t j = i + 1; j < gens.size(); ++j) {
      A3<FI> c_enclosed;
      {
        Protect guard;
        c_enclosed = cross3(enclosed[i], enclosed[j]);
      }
      std::optional<A3<Q2>> c;  // the exact product, made when needed
      auto exact = [&]() -> const A3<Q2>& {
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
      const A3<Q2> a = side > 0 ? exact() : neg3(exact());
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

}  // namespace fixel::internal
