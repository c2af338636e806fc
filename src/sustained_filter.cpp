#include "fixel/internal/sustained_filter.h"

#include <algorithm>
#include <boost/container/small_vector.hpp>

namespace fixel::internal {

namespace {

FGen enclose(const std::array<Q2, 3>& v) { return {to_interval_q2(v[0]), to_interval_q2(v[1]), to_interval_q2(v[2])}; }

// Whether every generator satisfies a·x ≥ 0 (closed) or a·x > 0 (strict):
// 1, 0, kUndecided. A conjunction: one certain failure decides it.
int all_satisfy(const FGen& a, const FGen* gens, std::size_t n, bool strict) {
  bool undecided = false;
  for (std::size_t k = 0; k < n; ++k) {
    const int s = certain_sign(dot3(a, gens[k]));
    if (s == kUndecided)
      undecided = true;
    else if (strict ? s <= 0 : s < 0)
      return 0;
  }
  return undecided ? kUndecided : 1;
}

// Whether every generator has a·x < 0 (the exact test's "strictly outside"),
// or a·x <= 0 (`closed`): 1, 0, kUndecided.
int all_outside(const FGen& a, const FGen* gens, std::size_t n, bool closed) {
  bool undecided = false;
  for (std::size_t k = 0; k < n; ++k) {
    const int s = certain_sign(dot3(a, gens[k]));
    if (s == kUndecided)
      undecided = true;
    else if (closed ? s > 0 : s >= 0)
      return 0;
  }
  return undecided ? kUndecided : 1;
}

// g_i × g_j; for a pair (d, m_i), (d, m_j) with one exact force part d, the
// exact form ((m_j − m_i) d_y, −(m_j − m_i) d_x, 0), whose zero is a point.
FGen pair_cross(const FGen* gens, std::size_t i, std::size_t j, bool paired) {
  if (!paired || i / 2 != j / 2) return cross3(gens[i], gens[j]);
  const FI dm = gens[j][2] - gens[i][2];
  return {dm * gens[i][1], -(dm * gens[i][0]), FI(0)};
}

// Closed rows of cone(gens) when it certainly has full rank: every pair's
// cross product that supports the cone, as cone_facet_normals takes them
// (duplicates do no harm to the elimination). False when the rank, a cross
// product's being nonzero or a side is not certain. Generators with one
// control point (`points`, IntervalTarget::generator_points) lie in one
// plane: a third one's side of a pair's plane is 0 by construction, and
// the plane is taken once.
bool facets(const FGen* gens, std::size_t n, bool paired, const int* points, std::vector<FGen>& out) {
  auto point_of = [&](std::size_t k) { return points ? points[k] : -1; };
  boost::container::small_vector<int, 8> planes;  // the control points whose plane was taken
  bool full_rank = false;
  for (std::size_t i = 0; i < n && !full_rank; ++i)
    for (std::size_t j = i + 1; j < n && !full_rank; ++j) {
      const FGen c = pair_cross(gens, i, j, paired);
      for (std::size_t k = j + 1; k < n && !full_rank; ++k) {
        const int s = certain_sign(dot3(c, gens[k]));
        full_rank = s == 1 || s == -1;
      }
    }
  if (!full_rank) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const int plane = point_of(i) >= 0 && point_of(i) == point_of(j) ? point_of(i) : -1;
      if (plane >= 0 && std::find(planes.begin(), planes.end(), plane) != planes.end()) continue;
      const FGen c = pair_cross(gens, i, j, paired);
      if (certain_sign(c[0]) == kUndecided && certain_sign(c[1]) == kUndecided && certain_sign(c[2]) == kUndecided)
        return false;  // possibly the zero vector, which the exact path skips
      if (plane >= 0) planes.push_back(plane);
      bool nonneg = true, nonpos = true;
      for (std::size_t k = 0; k < n; ++k) {
        if (k == i || k == j) continue;                    // on the plane by construction
        if (plane >= 0 && point_of(k) == plane) continue;  // in the plane of forces at that point
        const int s = certain_sign(dot3(c, gens[k]));
        if (s == kUndecided) return false;
        nonneg = nonneg && s >= 0;
        nonpos = nonpos && s <= 0;
      }
      if (nonneg && nonpos) return false;  // every generator on one plane: not full rank after all
      if (nonneg) out.push_back(c);
      if (nonpos) out.push_back({-c[0], -c[1], -c[2]});
    }
  return true;
}

// Whether some x ≠ 0 of cone(gens) meets the constraints (rows over x, with
// their exact forms): 1, 0, kUndecided. Up to three generators, over the
// weights λ ≥ 0 of x = Σ λ_k g_k (no facets needed, whatever the cone's
// rank); more, over x with the cone's facets when its full rank is certain.
// Either is the same question as the exact test's Fourier–Motzkin system.
// In the second, a sign the enclosures leave open among J's rows alone
// (an exact zero of J's data, such as K's rows of a symmetric layout) is
// settled on their exact forms (feasible_mixed).
int cone_meets(const FGen* gens, std::size_t n, bool paired, const int* points,
               const std::vector<MixedRow>& constraints) {
  std::vector<MixedRow> rows;
  if (n <= 3) {
    for (const auto& c : constraints) {
      MixedRow r{{FI(0), FI(0), FI(0)}, c.b, c.strict};
      for (std::size_t k = 0; k < n; ++k) r.a[k] = dot3(c.a, gens[k]);
      rows.push_back(r);
    }
    for (std::size_t k = 0; k < n; ++k) {
      MixedRow r{{FI(0), FI(0), FI(0)}, FI(0), false};
      r.a[k] = FI(1);
      rows.push_back(r);
    }
  } else {
    std::vector<FGen> cone_rows;
    if (!facets(gens, n, paired, points, cone_rows)) return kUndecided;
    for (const FGen& a : cone_rows) rows.push_back({a, FI(0), false});
    rows.insert(rows.end(), constraints.begin(), constraints.end());
  }
  try {
    return feasible_mixed(rows) ? 1 : 0;
  } catch (const Undecided&) {
    return kUndecided;
  }
}

const Q2& q2_zero() {
  static const Q2 zero(0);
  return zero;
}
const Q2& q2_one() {
  static const Q2 one(1);
  return one;
}

}  // namespace

JEnclosure::JEnclosure(const Data<Q2>& d) : data_(&d) {
  Protect guard;
  for (const auto& a : d.K_rows) k_rows_.push_back(enclose(a));
  normaliser_ = enclose(d.normaliser);
  for (const auto& jam : d.jams) {
    auto& f = jam_facets_.emplace_back();
    for (const auto& a : jam.facets) f.push_back(enclose(a));
  }
}

// cone_in_J (sustained_target.cpp), step by step.
int JEnclosure::cone_in(const FGen* gens, std::size_t n, bool paired, const int* points, long& lp_tests) const {
  Protect guard;
  bool undecided = false;
  for (const FGen& a : k_rows_) {  // every generator strictly inside K
    const int s = all_satisfy(a, gens, n, true);
    if (s == 0) return 0;
    undecided = undecided || s == kUndecided;
  }
  if (undecided) return kUndecided;
  for (std::size_t j = 0; j < jam_facets_.size(); ++j) {
    const std::vector<FGen>& jam = jam_facets_[j];
    // Separated: some facet of the jam cone with the whole cone strictly outside.
    bool separated = false, open = false;
    for (const FGen& a : jam) {
      const int s = all_outside(a, gens, n, false);
      separated = separated || s == 1;
      open = open || s == kUndecided;
    }
    if (separated) continue;
    if (open) return kUndecided;
    ++lp_tests;  // the exact test's system: the cone, the jam cone, normaliser·x ≥ 1
    const auto& exact_jam = data_->jams[j].facets;
    std::vector<MixedRow> rows;
    for (std::size_t f = 0; f < jam.size(); ++f) rows.push_back({jam[f], FI(0), false, &exact_jam[f], &q2_zero()});
    rows.push_back({normaliser_, FI(1), false, &data_->normaliser, &q2_one()});
    const int meets = cone_meets(gens, n, paired, points, rows);
    if (meets != 0) return meets == 1 ? 0 : kUndecided;
  }
  return 1;
}

// cone_misses_J (sustained_target.cpp), step by step.
int JEnclosure::cone_misses(const FGen* gens, std::size_t n, bool paired, const int* points, long& lp_tests) const {
  Protect guard;
  bool undecided = false;
  for (const FGen& a : k_rows_) {  // the cone outside int K
    const int s = all_outside(a, gens, n, true);
    if (s == 1) return 1;
    undecided = undecided || s == kUndecided;
  }
  for (const auto& jam : jam_facets_) {  // the cone inside one jam cone
    bool inside = true, open = false;
    for (const FGen& a : jam) {
      const int s = all_satisfy(a, gens, n, false);
      inside = inside && s == 1;
      open = open || s == kUndecided;
      if (s == 0) {
        inside = false;
        open = false;
        break;
      }
    }
    if (inside) return 1;
    undecided = undecided || open;
  }
  if (undecided) return kUndecided;
  ++lp_tests;  // the exact test's system: the cone and int K
  std::vector<MixedRow> rows;
  for (std::size_t k = 0; k < k_rows_.size(); ++k)
    rows.push_back({k_rows_[k], FI(0), true, &data_->K_rows[k], &q2_zero()});
  const int meets = cone_meets(gens, n, paired, points, rows);
  return meets == kUndecided ? kUndecided : (meets == 1 ? 0 : 1);
}

}  // namespace fixel::internal
