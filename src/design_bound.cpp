// Fixture design's pair bound (include/fixel/internal/design_bound.h,
// docs/theory.md §10.6), the triples' side: the candidates' wrenches and
// grids, and per triple the length of the stretches its three rows of K
// share. The pairs' stretches are design_bound_pairs.cpp's.
#include "fixel/internal/design_bound.h"

#include <algorithm>
#include <map>

#include "fixel/error.h"
#include "fixel/internal/design_bound_impl.h"
#include "fixel/internal/design_detail.h"

namespace fixel::internal {

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
      p.c_near = near3(p.c_enclosed);
    }
}

PairBound::~PairBound() = default;
PairBound::PairBound(PairBound&&) noexcept = default;
PairBound& PairBound::operator=(PairBound&&) noexcept = default;

long PairBound::pair_count() const { return static_cast<long>(impl_->pairs.size()); }

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
