// Fixture design's pair bound (include/fixel/internal/design_bound.h,
// docs/theory.md §10.6): per pair of candidates, the stretches of the
// outline on either side of the plane of their normal wrenches; per triple,
// the length of the stretches its three rows of K share.
#include "fixel/internal/design_bound.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <string>

#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/design_detail.h"
#include "fixel/internal/enclosed_plane.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/region_context.h"
#include "fixel/wrench_cone.h"

namespace fixel::internal {

namespace {

struct Span {  // cells [lo, hi) of piece `piece`'s grid
  std::int32_t piece, lo, hi;
};

FGen enclose(const VectorQ& v) { return {to_interval(v[0]), to_interval(v[1]), to_interval(v[2])}; }

// Appends [lo, hi) to a list kept sorted, joining it to the last span when
// they touch on one piece.
void append(std::vector<Span>& list, const Span& s) {
  if (!list.empty() && list.back().piece == s.piece && list.back().hi == s.lo)
    list.back().hi = s.hi;
  else
    list.push_back(s);
}

// The cells of `list` not in `cut` (both sorted, disjoint runs).
std::vector<Span> minus(const std::vector<Span>& list, const std::vector<Span>& cut) {
  std::vector<Span> out;
  std::size_t j = 0;
  for (Span s : list) {
    while (j < cut.size() && (cut[j].piece < s.piece || (cut[j].piece == s.piece && cut[j].hi <= s.lo))) ++j;
    for (std::size_t k = j; k < cut.size() && cut[k].piece == s.piece && cut[k].lo < s.hi; ++k) {
      if (cut[k].lo > s.lo) append(out, {s.piece, s.lo, cut[k].lo});
      s.lo = std::max(s.lo, cut[k].hi);
      if (s.lo >= s.hi) break;
    }
    if (s.lo < s.hi) append(out, s);
  }
  return out;
}

}  // namespace

struct PairBound::Impl {
  struct Pair {
    VectorQ c;                              // W_a × W_b
    FGen c_enclosed;                        // its enclosure
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
  };
  struct Node {
    std::once_flag made;
    BezierPiece segment;
    std::vector<Cone> cones;  // per family
  };
  std::vector<std::vector<std::unique_ptr<Node>>> nodes;  // per piece, 2^(depth + 1) slots

  Impl(const Scene& p, const Rational& r, const Rational& m) : part(p), resolution(r), mu(m) {}

  const Node& node(int piece, std::size_t i) const {
    Node& node = *nodes[piece][i];
    std::call_once(node.made, [&] {
      const auto& pieces = part.body.boundary->pieces;
      if (i == 1) {
        node.segment = pieces[piece];
      } else {
        auto halves = this->node(piece, i / 2).segment.split(Rational(1, 2));
        node.segment = std::move(i % 2 == 0 ? halves.first : halves.second);
      }
      const SegmentBounds bounds = segment_bounds(node.segment, false);
      for (EdgeFamily family : families) {
        Cone& cone = node.cones.emplace_back();
        if (auto c = segment_wrench_cone(bounds, part.body.p_AoCm_A, family, pusher_mu, ConeMethod::kTight,
                                         /*with_facets=*/false)) {
          cone.pointed = true;
          cone.gens = std::move(c->generators);
          for (const auto& g : cone.gens) cone.enclosed.push_back(enclose(g));
        }
      }
    });
    return node;
  }

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

PairBound::PairBound(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& options)
    : impl_(std::make_unique<Impl>(part, std::max(options.resolution, total_length(boundary_of(part)) / kCells),
                                   options.mu_hi.value_or(options.mu))) {
  Impl& m = *impl_;
  const Boundary& b = boundary_of(part);
  m.pusher_mu = options.pusher_mu;
  if (m.pusher_mu == 0)
    m.families = {EdgeFamily::kNormal};
  else
    m.families = {EdgeFamily::kMinus, EdgeFamily::kPlus};
  m.n = static_cast<int>(cands.size());
  for (const auto& c : cands) {
    const Vec2 r = sub(c.point, part.body.p_AoCm_A);
    m.wrench.push_back(contact_wrench(r, c.normal, 3));
    m.wrench_enclosed.push_back(enclose(m.wrench.back()));
    m.tangent_wrench.push_back(contact_wrench(r, Vec2{-c.normal.y, c.normal.x}, 3));
  }
  const Rational total = total_length(b);
  std::map<Rational, int> classes;
  for (const auto& piece : b.pieces) {
    const Rational width = piece.u1 - piece.u0;
    // The subdivision's deepest level: at most log2(kCells) + 1, since the
    // resolution is at least the outline's length over kCells.
    int d = 0;
    Rational cell = width;
    while (cell > m.resolution) {
      if (++d > 16) throw InternalError("design bound: a piece's grid is deeper than 16 levels");
      cell /= 2;
    }
    m.depth.push_back(d);
    const auto [it, fresh] = classes.emplace(cell / total, static_cast<int>(classes.size()));
    if (fresh) {
      m.unit.push_back(it->first);
      m.unit_enclosed.push_back(to_interval(it->first));
    }
    m.cls.push_back(it->second);
  }
  for (int d : m.depth) {
    m.nodes.emplace_back(std::size_t(2) << d);
    for (auto& slot : m.nodes.back()) slot = std::make_unique<Impl::Node>();
  }
  m.pairs.resize(static_cast<std::size_t>(m.n) * (m.n - 1) / 2);
  for (int a = 0; a < m.n; ++a)
    for (int c = a + 1; c < m.n; ++c) {
      m.pair_of.emplace_back(a, c);
      auto& p = m.pairs[m.pair_index(a, c)];
      p.c = cross3(m.wrench[a], m.wrench[c]);
      p.c_enclosed = enclose(p.c);
    }
}

PairBound::~PairBound() = default;
PairBound::PairBound(PairBound&&) noexcept = default;
PairBound& PairBound::operator=(PairBound&&) noexcept = default;

long PairBound::pair_count() const { return static_cast<long>(impl_->pairs.size()); }

namespace {

// Signs of a · g for the generators g of a node's cone: the enclosures
// (one rounding-mode scope per node), else exact. Counts its decisions for
// one batched record_filter per pair.
struct Signs {
  long certified = 0, fallbacks = 0;
  const int* of(const VectorQ& a, const FGen& a_enclosed, const PairBound::Impl::Cone& cone) {
    const std::size_t n = cone.gens.size();
    signs.resize(n);
    if (!force_exact()) {
      Protect guard;
      for (std::size_t k = 0; k < n; ++k) {
        const FGen& g = cone.enclosed[k];
        signs[k] = certain_sign(a_enclosed[0] * g[0] + a_enclosed[1] * g[1] + a_enclosed[2] * g[2]);
      }
    } else {
      std::fill(signs.begin(), signs.end(), kUndecided);
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (signs[k] != kUndecided) {
        ++certified;
        continue;
      }
      if (!force_exact()) ++fallbacks;
      signs[k] = sign(a.dot(cone.gens[k]));
    }
    return signs.data();
  }
  ~Signs() {
    if (certified + fallbacks > 0) record_filter(FilterSite::kDesignBound, certified, fallbacks);
  }
  std::vector<int> signs;
};

enum class Side { kIn, kOut, kPartial };

// The open half-space c · w > 0 against a cone: IN when every generator is
// in it, OUT when none is (the cone lies in c · w ≤ 0), else partial. This
// is the region's segment test for that target (docs/theory.md §10.6).
Side half_space_side(const PairBound::Impl::Pair& p, const PairBound::Impl::Cone& cone, Signs& signs) {
  if (!cone.pointed) return Side::kPartial;
  const int* s = signs.of(p.c, p.c_enclosed, cone);
  bool all_in = true, none_in = true;
  for (std::size_t k = 0; k < cone.gens.size(); ++k) {
    all_in = all_in && s[k] > 0;
    none_in = none_in && s[k] <= 0;
  }
  return all_in ? Side::kIn : none_in ? Side::kOut : Side::kPartial;
}

// The closed cone {w : a · w ≥ 0 for every facet a} against a cone: IN when
// every generator is in it; OUT when one facet has every generator
// strictly outside (no sub-piece can be IN then either); else partial.
Side cone_side(const std::vector<VectorQ>& facets, const std::vector<FGen>& facets_enclosed,
               const PairBound::Impl::Cone& cone, Signs& signs) {
  if (!cone.pointed) return Side::kPartial;
  bool all_in = true;
  for (std::size_t j = 0; j < facets.size(); ++j) {
    const int* s = signs.of(facets[j], facets_enclosed[j], cone);
    bool all_out = true;
    for (std::size_t k = 0; k < cone.gens.size(); ++k) {
      all_in = all_in && s[k] >= 0;
      all_out = all_out && s[k] < 0;
    }
    if (all_out) return Side::kOut;
  }
  return all_in ? Side::kIn : Side::kPartial;
}

// Whether a node's cells belong to a list: certainly, certainly not, or
// not known at this node (split it; a cell of the grid left unknown
// belongs).
enum class Member { kYes, kNo, kMaybe };

// Walks piece `piece`'s subdivision from node i (at `level`) down to the
// grid. `decide(node, lists)` settles each list still kMaybe at the node;
// a settled list holds for the node's sub-pieces too. A node is split while
// a list is kMaybe; each settled node or grid cell goes to `take(span,
// lists)` with kMaybe read as kYes.
template <std::size_t L, class Decide, class Take>
void walk(const PairBound::Impl& m, int piece, std::size_t i, int level, std::array<Member, L> lists, Decide&& decide,
          Take&& take) {
  decide(m.node(piece, i), lists);
  const int d = m.depth[piece];
  const bool settled = std::none_of(lists.begin(), lists.end(), [](Member x) { return x == Member::kMaybe; });
  if (settled || level == d) {
    const std::int32_t first = static_cast<std::int32_t>(i - (std::size_t(1) << level)) << (d - level);
    std::array<bool, L> in{};
    for (std::size_t k = 0; k < L; ++k) in[k] = lists[k] != Member::kNo;
    take(Span{piece, first, first + (std::int32_t(1) << (d - level))}, in);
    return;
  }
  walk(m, piece, 2 * i, level + 1, lists, decide, take);
  walk(m, piece, 2 * i + 1, level + 1, lists, decide, take);
}

}  // namespace

void PairBound::compute_pair(long index) {
  Impl& m = *impl_;
  Impl::Pair& p = m.pairs.at(index);
  if (p.c.isZero()) return;  // parallel wrenches: every triple with both is singular
  const int pieces = static_cast<int>(m.depth.size());
  Signs signs;
  // Side 0, "c · w > 0 may hold for every family": no family's cone is OUT.
  // Side 1, "c · w < 0 may hold for every family": none is IN.
  const auto halves = [&](const Impl::Node& node, std::array<Member, 2>& lists) {
    bool all_in = true, all_out = true;
    for (const auto& cone : node.cones) {
      const Side side = half_space_side(p, cone, signs);
      if (side == Side::kOut) lists[0] = Member::kNo;
      if (side == Side::kIn) lists[1] = Member::kNo;
      all_in = all_in && side == Side::kIn;
      all_out = all_out && side == Side::kOut;
    }
    if (all_in && lists[0] == Member::kMaybe) lists[0] = Member::kYes;
    if (all_out && lists[1] == Member::kMaybe) lists[1] = Member::kYes;
  };
  for (int k = 0; k < pieces; ++k)
    walk<2>(m, k, 1, 0, {Member::kMaybe, Member::kMaybe}, halves, [&](const Span& span, const std::array<bool, 2>& in) {
      if (in[0]) append(p.side[0], span);
      if (in[1]) append(p.side[1], span);
    });
  if (m.mu == 0) return;  // the jam cone is a plane's wedge: it holds no stretch's pushes
  // Stretches where one family's every push the pair can hold, −(FC_a +
  // FC_b), have no point of J's region (docs/theory.md §10.6): off both sides.
  std::vector<VectorQ> jam;
  for (int i : {m.first_of(index), m.second_of(index)})
    for (int s : {1, -1}) jam.push_back(-(m.wrench[i] + Rational(s) * m.mu * m.tangent_wrench[i]));
  const std::vector<VectorQ> facets = cone_facet_normals(jam, 3);
  std::vector<FGen> facets_enclosed;
  for (const auto& a : facets) facets_enclosed.push_back(enclose(a));
  // The list "not held": no family's cone is IN the jam cone. A cell left
  // unknown is not known to be held, so it stays.
  const auto free = [&](const Impl::Node& node, std::array<Member, 1>& not_held) {
    bool all_out = true;
    for (const auto& cone : node.cones) {
      const Side side = cone_side(facets, facets_enclosed, cone, signs);
      if (side == Side::kIn) {
        not_held[0] = Member::kNo;
        return;
      }
      all_out = all_out && side == Side::kOut;
    }
    if (all_out) not_held[0] = Member::kYes;
  };
  std::vector<Span> held;
  for (int k = 0; k < pieces; ++k)
    walk<1>(m, k, 1, 0, {Member::kMaybe}, free, [&](const Span& span, const std::array<bool, 1>& not_held) {
      if (!not_held[0]) append(held, span);
    });
  if (held.empty()) return;
  for (auto& side : p.side) side = minus(side, held);
}

bool PairBound::singular(const std::array<int, 3>& f) const { return impl_->det_sign(f) == 0; }

double PairBound::upper(const std::array<int, 3>& f) const {
  const Impl& m = *impl_;
  Protect guard;
  FI sum(0);
  m.shared_cells(f, [&](int c, std::int64_t cells) { sum += FI(static_cast<double>(cells)) * m.unit_enclosed[c]; });
  return sum.sup();
}

Rational PairBound::exact(const std::array<int, 3>& f) const {
  const Impl& m = *impl_;
  std::vector<std::int64_t> cells(m.unit.size(), 0);
  m.shared_cells(f, [&](int c, std::int64_t count) { cells[c] += count; });
  Rational sum(0);
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (cells[c]) sum += Rational(static_cast<long>(cells[c])) * m.unit[c];
  return sum;
}

bool PairBound::can_enter(const std::array<int, 3>& f, long index, double upper, const Rational& kth_score,
                          long kth_index) const {
  if (!force_exact()) {
    const bool below = Rational(upper) < kth_score;
    record_filter(FilterSite::kDesignBound, below);
    if (below) return false;
  }
  const Rational b = exact(f);
  return b > kth_score || (b == kth_score && index < kth_index);
}

bool PairBound::none_can_enter(double upper, const Rational& kth_score, long left) const {
  if (force_exact() || !(Rational(upper) < kth_score)) return false;
  record_filter(FilterSite::kDesignBound, left, 0);
  return true;
}

}  // namespace fixel::internal
