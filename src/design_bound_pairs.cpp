// Fixture design's pair bound, the pairs' side (docs/theory.md §10.6,
// "Cones shared by every pair"): each grid node's wrench cones, made once,
// and each pair's stretches by a walk of filtered signs over them.
#include <algorithm>

#include "fixel/cone.h"
#include "fixel/internal/design_bound_impl.h"

namespace fixel::internal {

namespace {

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

// Signs of a · g for the generators g of a node's cone: the static filter,
// then the enclosures (one rounding-mode scope per node, only when the
// static filter left a sign open), else exact. Counts its decisions for one
// batched record_filter per pair.
struct Signs {
  long certified = 0, fallbacks = 0;
  const int* of(const VectorQ& a, const FGen& a_enclosed, const Near3& a_near, const PairBound::Impl::Cone& cone) {
    const std::size_t n = cone.gens.size();
    signs.resize(n);
    if (!force_exact()) {
      bool open = false;
      for (std::size_t k = 0; k < n; ++k) {
        signs[k] = static_dot_sign(a_near, cone.near[k]);
        open = open || signs[k] == kUndecided;
      }
      if (open) {
        Protect guard;
        for (std::size_t k = 0; k < n; ++k) {
          if (signs[k] != kUndecided) continue;
          const FGen& g = cone.enclosed[k];
          signs[k] = certain_sign(a_enclosed[0] * g[0] + a_enclosed[1] * g[1] + a_enclosed[2] * g[2]);
        }
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
  const int* s = signs.of(p.c, p.c_enclosed, p.c_near, cone);
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
               const std::vector<Near3>& facets_near, const PairBound::Impl::Cone& cone, Signs& signs) {
  if (!cone.pointed) return Side::kPartial;
  bool all_in = true;
  for (std::size_t j = 0; j < facets.size(); ++j) {
    const int* s = signs.of(facets[j], facets_enclosed[j], facets_near[j], cone);
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
  std::vector<Near3> facets_near;
  for (const auto& a : facets) {
    facets_enclosed.push_back(enclose(a));
    facets_near.push_back(near3(facets_enclosed.back()));
  }
  // The list "not held": no family's cone is IN the jam cone. A cell left
  // unknown is not known to be held, so it stays.
  const auto free = [&](const Impl::Node& node, std::array<Member, 1>& not_held) {
    bool all_out = true;
    for (const auto& cone : node.cones) {
      const Side side = cone_side(facets, facets_enclosed, facets_near, cone, signs);
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

const PairBound::Impl::Node& PairBound::Impl::node(int piece, std::size_t i) const {
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
        for (const auto& g : cone.gens) {
          cone.enclosed.push_back(enclose(g));
          cone.near.push_back(near3(cone.enclosed.back()));
        }
      }
    }
  });
  return node;
}

}  // namespace fixel::internal
