// The tests of wrenches and cones against J: a wrench escapes (−w not
// strictly inside cone(W_n*)) or jams (held at rest by two fixels with
// friction), and J as the pushing region's target (exact, or undecided
// with an enclosed q*).
#include <algorithm>
#include <optional>
#include <variant>

#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/sustained_core.h"
#include "fixel/internal/sustained_data.h"
#include "fixel/internal/sustained_filter.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"
#include "fixel/sustained.h"

namespace fixel {

namespace internal {

namespace {

template <class NT>
A3<NT> to_body(const Data<NT>& d, const VectorQ& w_W) {
  if (w_W.size() != 3)
    throw InputError("wrench", std::to_string(w_W.size()) + " components", "must have 3 (fx, fy, moment)");
  const A3<NT> w = lift3<NT>(w_W);
  return {d.cos * w[0] + d.sin * w[1], -d.sin * w[0] + d.cos * w[1], w[2]};
}

// "" when w_B is in J, else the reason.
template <class NT>
std::string reason(const Data<NT>& d, const A3<NT>& w) {
  if (!satisfies(w, {}, d.K_rows))
    return "can escape: -w is not strictly inside cone(W_n*), so the push does not drive the part into its seat";
  for (const auto& jam : d.jams)
    if (in_jam<NT>(jam, w))
      return fixel_name(jam.fixels[0]) + " and " + fixel_name(jam.fixels[1]) +
             " can hold the part at rest with friction under this push (it can jam short of the seat)";
  return "";
}

// The region's questions, answered for one number type (see RegionTarget).
template <class NT>
bool cone_in_J(const Data<NT>& d, const std::vector<VectorQ>& gens, RegionStats* stats) {
  std::vector<A3<NT>> g;
  for (const auto& v : gens) g.push_back(lift3<NT>(v));
  for (const auto& x : g)
    if (!satisfies(x, {}, d.K_rows)) return false;
  std::vector<A3<NT>> cone_rows;
  bool have_rows = false;
  for (const auto& jam : d.jams) {
    // Cheap certificate first: a facet of the jam cone with the whole cone strictly outside.
    bool separated = false;
    for (const auto& a : jam.facets) {
      bool all_out = true;
      for (const auto& x : g) all_out = all_out && sign_dot3(a, x) < 0;
      if (all_out) {
        separated = true;
        break;
      }
    }
    if (separated) continue;
    if (!have_rows) {
      for (const auto& a : cone_facet_normals(gens, 3)) cone_rows.push_back(lift3<NT>(a));
      have_rows = true;
    }
    if (stats) ++stats->lp_tests;
    std::vector<Row<NT>> rows = homogeneous(cone_rows, false);
    for (const auto& r : homogeneous(jam.facets, false)) rows.push_back(r);
    rows.push_back({d.normaliser, NT(1), false});
    if (feasible_filtered(rows)) return false;
  }
  return true;
}

template <class NT>
bool cone_misses_J(const Data<NT>& d, const std::vector<VectorQ>& gens, RegionStats* stats) {
  std::vector<A3<NT>> g;
  for (const auto& v : gens) g.push_back(lift3<NT>(v));
  for (const auto& a : d.K_rows) {
    bool outside = true;
    for (const auto& x : g) outside = outside && sign_dot3(a, x) <= 0;
    if (outside) return true;
  }
  for (const auto& jam : d.jams) {
    bool inside = true;
    for (const auto& x : g) inside = inside && in_jam<NT>(jam, x);
    if (inside) return true;
  }
  if (stats) ++stats->lp_tests;
  std::vector<A3<NT>> cone_rows;
  for (const auto& a : cone_facet_normals(gens, 3)) cone_rows.push_back(lift3<NT>(a));
  std::vector<RowRef<NT>> rows;
  append_refs(cone_rows, false, rows);
  append_refs(d.K_rows, true, rows);
  return !feasible_filtered(rows);
}

// A polynomial with coefficients in Q(√d): A(s) + √d B(s).
struct PolyQ2 {
  Polynomial A, B;
};

PolyQ2 row_dot_q2(const A3<Q2>& a, const std::array<Polynomial, 3>& w, Rational& root) {
  PolyQ2 out;
  for (int k = 0; k < 3; ++k) {
    out.A = padd(out.A, pscale(w[k], a[k].a0()));
    if (a[k].is_extended() && a[k].a1() != 0) {
      if (root == 0)
        root = a[k].root();
      else if (root != a[k].root())
        throw InternalError("sustained set: coefficients from two quadratic fields");
      out.B = padd(out.B, pscale(w[k], a[k].a1()));
    }
  }
  return out;
}

// (A1 + √d B1)(A2 + √d B2) − (A3 + √d B3)(A4 + √d B4).
PolyQ2 det_q2(const PolyQ2& x1, const PolyQ2& y2, const PolyQ2& y1, const PolyQ2& x2, const Rational& d) {
  auto mul = [&](const PolyQ2& p, const PolyQ2& q) {
    return PolyQ2{padd(pmul(p.A, q.A), pscale(pmul(p.B, q.B), d)), padd(pmul(p.A, q.B), pmul(p.B, q.A))};
  };
  const PolyQ2 a = mul(x1, y2), b = mul(y1, x2);
  return {psub(a.A, b.A), psub(a.B, b.B)};
}

// A rational polynomial whose real roots include those of A + √d B: the
// norm A² − d B² (the product with the conjugate).
Polynomial norm_q2(const PolyQ2& p, const Rational& d) {
  if (p.B.empty()) return p.A;
  if (p.A.empty()) return p.B;
  return psub(pmul(p.A, p.A), pscale(pmul(p.B, p.B), d));
}

// The cone and jam-cone conditions of J along a piece (docs/theory.md §12):
// a_k·w_j(s) for the rows of int K and every jam facet f, and, for a fan of
// two generators (frictional pusher), (f·w_1)(f'·w_2) − (f·w_2)(f'·w_1) for
// every pair of facets of one jam cone. Whether the fan {λ1 w_1 + λ2 w_2}
// meets a jam cone off 0 is a one-dimensional system in λ2/(λ1 + λ2) whose
// answer depends only on those signs.
std::vector<Polynomial> j_polynomials(const Data<Q2>& d, const std::vector<std::array<Polynomial, 3>>& gens_in) {
  std::vector<std::array<Polynomial, 3>> gens;
  for (const auto& g : gens_in)
    if (std::find(gens.begin(), gens.end(), g) == gens.end()) gens.push_back(g);
  Rational root = 0;
  std::vector<PolyQ2> q2;
  for (const auto& g : gens)
    for (const auto& a : d.K_rows) q2.push_back(row_dot_q2(a, g, root));
  for (const auto& jam : d.jams) {
    std::vector<std::vector<PolyQ2>> x(gens.size());
    for (std::size_t j = 0; j < gens.size(); ++j)
      for (const auto& f : jam.facets) {
        x[j].push_back(row_dot_q2(f, gens[j], root));
        q2.push_back(x[j].back());
      }
    if (gens.size() == 2)
      for (std::size_t m = 0; m < jam.facets.size(); ++m)
        for (std::size_t l = m + 1; l < jam.facets.size(); ++l)
          q2.push_back(det_q2(x[0][m], x[1][l], x[1][m], x[0][l], root));
  }
  std::vector<Polynomial> out;
  for (const auto& p : q2) out.push_back(norm_q2(p, root));
  return out;
}

std::vector<Polynomial> j_polynomials(const Data<IV>&, const std::vector<std::array<Polynomial, 3>>&) {
  throw UnsupportedError("RegionOptions.exact", "",
                         "needs an exact seated pose q*: with curved contacts q* is only enclosed "
                         "(docs/theory.md §10.1), so J's rows are not exact numbers");
}

// The J target of the region. An undecided sign (enclosed q*) makes the
// question's answer "no", so the segment stays PARTIAL: never a wrong in/out.
// For J′ (approach_target.cpp) the IN questions read `d_` (J's rows plus
// outer cones of the swept jam cones) and the OUT questions `out_` (J's rows
// plus jam cones at sampled poses): both answers stay exact, and what
// neither settles is PARTIAL.
class SustainedTarget final : public RegionTarget, public IntervalTarget {
 public:
  explicit SustainedTarget(std::shared_ptr<const SustainedData> d, std::shared_ptr<const SustainedData> out = nullptr,
                           bool empty = false)
      : d_(std::move(d)), out_(std::move(out)), empty_(empty) {
    if (const auto* exact = std::get_if<Data<Q2>>(&d_->data)) enclosed_.emplace(*exact);
    if (out_)
      if (const auto* exact = std::get_if<Data<Q2>>(&out_->data)) enclosed_out_.emplace(*exact);
  }
  const char* push_model() const override { return "sustained"; }
  const char* name() const override { return out_ || empty_ ? "J'" : "J"; }
  void check_scene(const Scene& scene) const override { check_built_from(*d_, scene, name()); }

  // The region's interval pre-test (exact q* only): segments and points
  // decided on enclosures of J's rows and of the wrench cone, with the
  // exact test's steps and LP count. An IN answer has no magnitudes (J is
  // a cone), so nothing waits for the exact path.
  IntervalTarget* interval_target() override { return enclosed_ && !empty_ ? this : nullptr; }
  bool in_answers_have_magnitudes() const override { return false; }
  bool interval_magnitudes(const FGen&, FMagnitudes&) const override { return false; }
  int interval_ray_hits(const FGen&) const override { return kUndecided; }  // unused: the tests below take cones
  bool out_test_sees_hits() const override { return true; }
  bool answers_points() const override { return !out_; }  // J′'s points can be PARTIAL
  int interval_contains(const FGen* gens, const int*, std::size_t n) const override {
    long lp = 0;
    const int in = enclosed_->cone_in(gens, n, paired_generators, generator_points, lp);
    if (in != kUndecided && stats) stats->lp_tests += lp;
    return in;
  }
  int certify_out_test(const FGen* gens, std::size_t n) override {
    if (out_ && !enclosed_out_) return kUndecided;
    long lp = 0;
    const JEnclosure& e = out_ ? *enclosed_out_ : *enclosed_;
    const int missed = e.cone_misses(gens, n, paired_generators, generator_points, lp);
    if (missed != kUndecided && stats) stats->lp_tests += lp;
    return missed;
  }

  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2*, const Vec2*, RegionInterval* detail) override {
    if (empty_) return false;
    bool in = false;
    try {
      in = std::visit([&](const auto& d) { return cone_in_J(d, gens, stats); }, d_->data);
    } catch (const Undecided&) {
      return false;
    }
    if (in && detail) {
      detail->half_line = true;  // J is a cone: any magnitude
      detail->magnitudes = Magnitudes{};
    }
    return in;
  }

  bool misses(const std::vector<VectorQ>& gens) override {
    if (empty_) return true;
    try {
      return std::visit([&](const auto& d) { return cone_misses_J(d, gens, stats); }, (out_ ? out_ : d_)->data);
    } catch (const Undecided&) {
      return false;
    }
  }

  std::vector<Polynomial> sign_polynomials(const std::vector<std::array<Polynomial, 3>>& gens) const override {
    if (out_ || empty_)
      throw UnsupportedError("RegionOptions.exact", "",
                             "is not available for J': its jam cones sweep with the pose, so J' is not a finite "
                             "union of polyhedral cones (docs/theory.md §10.7)");
    return std::visit([&](const auto& d) { return j_polynomials(d, gens); }, d_->data);
  }

  RegionStatus test_point(const std::vector<VectorQ>& gens, const Vec2& d_first, const Vec2& d_last, Magnitudes* out,
                          std::vector<Magnitudes>*) override {
    if (out) *out = Magnitudes{};
    if (out_ || empty_) {
      if (contains_cone(gens, &d_first, &d_last, nullptr)) return RegionStatus::kIn;
      if (misses(gens)) return RegionStatus::kOut;
      // A point is IN only when every push of its cone is: one edge ray
      // certainly outside J′ makes it OUT, as a ray outside J does for J.
      for (const VectorQ& g : gens)
        if (misses({g})) return RegionStatus::kOut;
      return RegionStatus::kPartial;
    }
    try {
      const bool in = std::visit([&](const auto& d) { return cone_in_J(d, gens, stats); }, d_->data);
      return in ? RegionStatus::kIn : RegionStatus::kOut;
    } catch (const Undecided&) {
      // The enclosure of q* cannot show the cone inside J. One ray of it
      // certainly outside J (the region's OUT test, on that ray) still makes
      // the point OUT; without this the point stayed PARTIAL where the
      // region, testing whole segments, proved OUT.
      for (const VectorQ& g : gens)
        if (misses({g})) return RegionStatus::kOut;
      return RegionStatus::kPartial;
    }
  }

 private:
  std::shared_ptr<const SustainedData> d_, out_;
  bool empty_ = false;
  std::optional<JEnclosure> enclosed_, enclosed_out_;
};

}  // namespace

}  // namespace internal

std::unique_ptr<RegionTarget> sustained_target(const SustainedSet& J) {
  const internal::ExactTask task("sustained set J (its region target)");
  if (!J.data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  return std::make_unique<internal::SustainedTarget>(J.data);
}

std::unique_ptr<RegionTarget> internal::sustained_target(std::shared_ptr<const SustainedData> data) {
  if (!data) throw InputError("J", "", "has no data");
  return std::make_unique<SustainedTarget>(std::move(data));
}

std::unique_ptr<RegionTarget> internal::sustained_target(std::shared_ptr<const SustainedData> in,
                                                         std::shared_ptr<const SustainedData> out, bool empty) {
  if (!in || !out) throw InputError("J'", "", "has no data");
  return std::make_unique<SustainedTarget>(std::move(in), std::move(out), empty);
}

std::string internal::why_not_in_frame_B(const SustainedSet& J, const VectorQ& w_B) {
  if (!J.data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  if (w_B.size() != 3)
    throw InputError("wrench", std::to_string(w_B.size()) + " components", "must have 3 (fx, fy, moment)");
  try {
    return std::visit([&](const auto& d) { return reason(d, lift3<typename std::decay_t<decltype(d)>::NT>(w_B)); },
                      J.data->data);
  } catch (const Undecided&) {
    throw UnsupportedError("wrench", "",
                           "is too close to a boundary of J to decide with the certified enclosure of q*");
  }
}

bool SustainedSet::contains(const VectorQ& w_W) const { return why_not(w_W).empty(); }

std::string SustainedSet::why_not(const VectorQ& w_W) const {
  if (!data) throw InputError("J", "", "has no data (default-constructed SustainedSet)");
  try {
    return std::visit([&](const auto& d) { return internal::reason(d, internal::to_body(d, w_W)); }, data->data);
  } catch (const internal::Undecided&) {
    throw UnsupportedError("wrench", "",
                           "is too close to a boundary of J to decide with the certified enclosure of q*");
  }
}

}  // namespace fixel
