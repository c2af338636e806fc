// Fixture design, scores: the exact filters of one layout (W_n nonsingular,
// form closure with a pushing finger) and its scores, the fraction of the
// outline where a push seats the part (one-step and sustained).
#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "fixel/design.h"
#include "fixel/error.h"
#include "fixel/internal/design_detail.h"
#include "fixel/internal/region_context.h"
#include "fixel/internal/region_filter.h"
#include "fixel/internal/sustained_core.h"
#include "fixel/lcp.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"
#include "fixel/seated_pose.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"

namespace fixel {

namespace {

// The normal wrench (d, r ⊗ d) of a push or contact at `point` along `d`.
VectorQ wrench_at(const Scene& part, const Vec2& point, const Vec2& d) {
  return contact_wrench(sub(point, part.body.p_AoCm_A), d, 3);
}

// Rows a_k with w ∈ int K ⇔ a_k · w > 0 for every k, where
// K = {w : −w ∈ int cone(W_n)} (docs/theory.md §10.2); none if W_n is singular.
std::optional<std::array<VectorQ, 3>> k_rows(const std::array<VectorQ, 3>& Wn) {
  const Rational det = Wn[0].dot(internal::cross3(Wn[1], Wn[2]));
  if (det == 0) return std::nullopt;
  std::array<VectorQ, 3> rows;
  for (int i = 0; i < 3; ++i) {
    rows[i] = internal::cross3(Wn[(i + 1) % 3], Wn[(i + 2) % 3]);  // row i of adj(W_n)
    if (det > 0) rows[i] = -rows[i];
  }
  return rows;
}

bool in_open_k(const std::array<VectorQ, 3>& rows, const VectorQ& w) {
  for (const auto& a : rows)
    if (a.dot(w) <= 0) return false;
  return true;
}

// A polyhedral cone as a region target: {w : a_k · w > 0 for every row}
// (open) or {w : a_k · w ≥ 0} (closed). With K's three rows, open ("−w
// strictly inside cone(W_n)"), a frictionless finger's point is IN when its
// push and the three fixels' normal wrenches are in form closure; with one
// row it is an open half-space, and closed with a jam cone's facets it
// holds the pushes a pair of fixels can hold (both for the pair bound,
// design_bound.cpp). `misses` is conservative (one separating row; exact
// for one row), so an undecided stretch stays PARTIAL and is never counted
// as OUT.
class ConeTarget final : public RegionTarget, public internal::IntervalTarget {
 public:
  ConeTarget(std::vector<VectorQ> rows, bool open, const char* name)
      : rows_(std::move(rows)), open_(open), name_(name) {
    for (const auto& a : rows_) {
      internal::FGen e;
      for (int k = 0; k < 3; ++k) e[k] = internal::to_interval(a[k]);
      rows_enclosed_.push_back(e);
    }
  }
  const char* push_model() const override { return "form closure"; }
  const char* name() const override { return name_; }
  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2*, const Vec2*, RegionInterval* detail) override {
    for (const auto& g : gens)
      for (const auto& a : rows_)
        if (!inside(sign(a.dot(g)))) return false;
    if (detail) detail->half_line = true;
    return true;
  }
  bool misses(const std::vector<VectorQ>& gens) override {
    for (const auto& a : rows_) {
      bool outside = true;
      for (const auto& g : gens) outside = outside && !inside(sign(a.dot(g)));
      if (outside) return true;
    }
    return false;
  }

  // The region's interval pre-test (internal/region_filter.h): the same
  // signs of a·g on enclosures. The target is a cone: an IN answer has no
  // magnitudes.
  internal::IntervalTarget* interval_target() override { return this; }
  bool in_answers_have_magnitudes() const override { return false; }
  int interval_ray_hits(const internal::FGen& g) const override {
    bool undecided = false;
    for (const auto& a : rows_enclosed_) {
      const int s = sign_of_dot(a, g);
      if (s == internal::kUndecided)
        undecided = true;
      else if (!inside(s))
        return 0;
    }
    return undecided ? internal::kUndecided : 1;
  }
  // misses(): a row with a·g ≤ 0 for every generator (no LP: none counted).
  int certify_out_test(const internal::FGen* gens, std::size_t n) override {
    bool open = false;
    for (const auto& a : rows_enclosed_) {
      bool outside = true, row_open = false;
      for (std::size_t k = 0; k < n && outside; ++k) {
        const int s = sign_of_dot(a, gens[k]);
        if (s == internal::kUndecided)
          row_open = true;
        else if (inside(s))
          outside = false;
      }
      if (outside && !row_open) return 1;
      open = open || (outside && row_open);
    }
    return open ? internal::kUndecided : 0;
  }
  bool interval_magnitudes(const internal::FGen&, internal::FMagnitudes&) const override { return false; }

 private:
  static int sign_of_dot(const internal::FGen& a, const internal::FGen& g) {
    internal::Protect guard;
    return internal::certain_sign(a[0] * g[0] + a[1] * g[1] + a[2] * g[2]);
  }

  // A row's side of a·g (a certified sign) holds the cone.
  bool inside(int s) const { return open_ ? s > 0 : s >= 0; }

  std::vector<VectorQ> rows_;
  std::vector<internal::FGen> rows_enclosed_;
  bool open_;
  const char* name_;
};

Rational in_fraction(const Region& r, const Rational& total) {
  Rational in = 0;
  for (const auto& iv : r.intervals)
    if (iv.status == RegionStatus::kIn) in += iv.u1 - iv.u0;
  return in / total;
}

RegionOptions region_options(const DesignOptions& o, const Rational& pusher_mu) {
  RegionOptions ro;
  ro.resolution = o.resolution;
  ro.pusher_mu = pusher_mu;
  return ro;
}

// Solid angle (fraction of the sphere) of J's pieces, with the moment scaled
// by 1/ρ (ρ the radius of gyration) so that force and moment weigh alike.
// Display only: doubles.
double j_width(const Scene& part, const SustainedSet& J) {
  const double rho = std::sqrt(to_double(part.body.inertia) / to_double(part.body.mass));
  double total = 0;
  for (const auto& piece : J.pieces) {
    std::vector<std::array<double, 3>> rays;
    for (const auto& r : piece.rays) {
      std::array<double, 3> v{r[0].approx(), r[1].approx(), r[2].approx() / rho};
      const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (n == 0) continue;
      for (auto& x : v) x /= n;
      rays.push_back(v);
    }
    if (rays.size() < 3) continue;
    std::array<double, 3> c{0, 0, 0};
    for (const auto& v : rays)
      for (int k = 0; k < 3; ++k) c[k] += v[k];
    // Order the rays around c, then sum the fan's spherical triangles
    // (Van Oosterom and Strackee).
    std::array<double, 3> e1{0, 0, 0}, e2;
    const int ax = std::abs(c[0]) < std::abs(c[1]) ? (std::abs(c[0]) < std::abs(c[2]) ? 0 : 2)
                                                   : (std::abs(c[1]) < std::abs(c[2]) ? 1 : 2);
    e1[ax] = 1;
    auto crs = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    auto dt = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    e1 = crs(c, e1);
    e2 = crs(c, e1);
    std::sort(rays.begin(), rays.end(), [&](const auto& a, const auto& b) {
      return std::atan2(dt(a, e2), dt(a, e1)) < std::atan2(dt(b, e2), dt(b, e1));
    });
    for (std::size_t k = 1; k + 1 < rays.size(); ++k) {
      const auto &a = rays[0], &b = rays[k], &d = rays[k + 1];
      const double num = std::abs(dt(a, crs(b, d)));
      const double den = 1 + dt(a, b) + dt(b, d) + dt(d, a);
      total += 2 * std::atan2(num, den);
    }
  }
  return total / (4 * M_PI);
}

// The smallest singular value of W_n with its moment row divided by ρ (the
// radius of gyration), so that force and moment weigh alike: near 0 when the
// three normal lines nearly meet in one point. Display only: doubles.
double conditioning(const Scene& s) {
  const MatrixQ W = normal_wrench_matrix(s);
  if (W.rows() != 3 || W.cols() != 3) return std::nan("");
  const double rho = std::sqrt(to_double(s.body.inertia) / to_double(s.body.mass));
  Eigen::Matrix3d A;
  for (int c = 0; c < 3; ++c) {
    // Unit normals: a layout's scene may carry the candidates' normals unnormalised.
    const double length = std::hypot(to_double(s.fixels[c].n_A.x), to_double(s.fixels[c].n_A.y));
    for (int r = 0; r < 3; ++r) A(r, c) = to_double(W(r, c)) / (r == 2 ? rho : 1.0) / length;
  }
  // σ_min² is AᵀA's least eigenvalue (ascending order).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(A.transpose() * A, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, eigen.eigenvalues()(0)));
}

// The sustained score of a scene with three fixels: J and, if J is not
// empty, the region against it.
// With `width` false (ranking every triple) J is built without its pieces'
// rays and public form, which only J's width (display) reads; the reported
// layouts get it in complete_layouts.
void score_sustained(const Scene& scene, const DesignOptions& o, const Rational& total, DesignLayout& out, bool width,
                     const std::vector<internal::Join>* joins = nullptr) {
  std::shared_ptr<const internal::SustainedData> data;
  if (width) {
    const SustainedSet J = sustained_set(scene, false);  // strong stability: by the theorem
    out.sustained_empty = J.empty;
    out.j_width = J.empty ? 0 : j_width(scene, J);
    data = J.data;
  } else {
    const internal::SustainedCore J = internal::sustained_core(scene);
    out.sustained_empty = J.empty;
    out.j_width = 0;
    data = J.data;
  }
  if (*out.sustained_empty) {
    out.sustained_score = Rational(0);
    return;
  }
  const auto target = internal::sustained_target(data);
  out.sustained_score =
      in_fraction(internal::compute_region_joined(scene, *target, region_options(o, o.pusher_mu), joins, false), total);
}

void score_step(const Scene& scene, const DesignOptions& o, const Rational& total, DesignLayout& out,
                const std::vector<internal::Join>* joins = nullptr) {
  const SeatingSet S = seating_set(scene);
  const auto target = internal::step_target(scene, S, nullptr);
  out.step_score =
      in_fraction(internal::compute_region_joined(scene, *target, region_options(o, o.pusher_mu), joins, false), total);
}

}  // namespace

namespace internal {

VectorQ cross3(const VectorQ& a, const VectorQ& b) {
  VectorQ c(3);
  c << a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0];
  return c;
}

std::unique_ptr<RegionTarget> form_closure_target(const std::array<VectorQ, 3>& Wn) {
  const auto rows = k_rows(Wn);
  if (!rows) return nullptr;
  return std::make_unique<ConeTarget>(std::vector<VectorQ>(rows->begin(), rows->end()), true, "K");
}

std::unique_ptr<RegionTarget> open_half_space_target(const VectorQ& a) {
  return std::make_unique<ConeTarget>(std::vector<VectorQ>{a}, true, "H");
}

std::unique_ptr<RegionTarget> closed_cone_target(std::vector<VectorQ> rows) {
  return std::make_unique<ConeTarget>(std::move(rows), false, "jam");
}

// Filters and scores one triple by the ranking push model.
Verdict evaluate(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o,
                 const Rational& total, const std::array<int, 3>& f, DesignLayout& out,
                 const std::vector<Join>* joins) {
  std::array<VectorQ, 3> Wn;
  for (int i = 0; i < 3; ++i) Wn[i] = wrench_at(part, cands[f[i]].point, cands[f[i]].normal);
  const auto rows = k_rows(Wn);
  if (!rows) return Verdict::kSingular;
  if (o.push == DesignPush::kStep) {
    // No form-closure filter here: a one-step IN point does not need it, so
    // a triple without it can still have a positive one-step score.
    double err = 0;
    const Scene step = build_layout_scene(part, cands, f, o, true, &err);
    out.normal_angle_error = err;
    score_step(step, o, total, out, joins);
    out.score = *out.step_score;
    return Verdict::kScored;
  }
  const Scene scene = build_layout_scene(part, cands, f, o, false);
  // Form closure with a frictionless finger: a candidate whose push is in
  // int K proves it; otherwise the region against int K decides.
  bool closure = false;
  for (const auto& c : cands)
    if (in_open_k(*rows, wrench_at(part, c.point, c.normal))) {
      closure = true;
      break;
    }
  if (!closure) {  // some interval of the region against int K is not OUT (the first found is enough)
    ConeTarget target(std::vector<VectorQ>(rows->begin(), rows->end()), true, "K");
    closure = region_reaches(scene, target, region_options(o, Rational(0)), joins);
  }
  if (!closure) return Verdict::kNoFormClosure;
  score_sustained(scene, o, total, out, false, joins);
  out.score = *out.sustained_score;
  return *out.sustained_empty ? Verdict::kJEmpty : Verdict::kScored;
}

}  // namespace internal

using internal::boundary_of;
using internal::total_length;

void complete_layouts(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o,
                      std::vector<DesignLayout>& layouts) {
  const Rational total = total_length(boundary_of(part));
  for (const auto& l : layouts) internal::check_layout(part, cands, l.fixels);  // thrown, not a note
  for (auto& l : layouts) {
    try {
      const Scene s = layout_scene(part, cands, l.fixels, o, false);
      l.conditioning = conditioning(s);
      l.curved_contacts = internal::curved_contacts(part, cands, l.fixels);
      if (!l.sustained_score)
        score_sustained(s, o, total, l, true);
      else if (l.sustained_empty.has_value() && !*l.sustained_empty)  // ranked without J's width
        l.j_width = j_width(s, sustained_set(s, false));
    } catch (const StoppedError&) {
      throw;  // the run's stop (its ControlScope), not this layout's failure
    } catch (const Error& e) {
      l.note += std::string(l.note.empty() ? "" : "; ") + "sustained score: " + e.what();
    }
    if (o.mu_hi) {
      if (!l.step_score)
        l.note += std::string(l.note.empty() ? "" : "; ") + "no one-step score: it needs one fixel mu, not an interval";
      continue;
    }
    try {
      double err = 0;
      const Scene step = layout_scene(part, cands, l.fixels, o, true, &err);
      l.normal_angle_error = err;
      if (!l.step_score) score_step(step, o, total, l);
      // With a gap the fixels may be where no pose closes them all: then
      // the one-step score is of a fixture the part cannot seat in.
      if (o.gap > 0) {
        try {
          seated_pose(step);
        } catch (const StoppedError&) {
          throw;
        } catch (const Error& e) {
          l.step_seat = e.what();
        }
      }
    } catch (const StoppedError&) {
      throw;
    } catch (const Error& e) {
      l.note += std::string(l.note.empty() ? "" : "; ") + "one-step score: " + e.what();
    }
  }
}

std::optional<DesignLayout> shipped_layout(const Scene& scene, const DesignOptions& options) {
  if (scene.num_contacts() != 3) return std::nullopt;
  try {
    return score_scene_layout(scene, options);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

DesignLayout score_scene_layout(const Scene& scene, const DesignOptions& o) {
  check_design(scene, o);
  const Rational total = total_length(boundary_of(scene));
  Scene s = scene;
  for (auto& f : s.fixels) {
    f.mu = o.mu;
    f.mu_hi = o.mu_hi;
  }
  s.pusher_mu = o.pusher_mu;
  s.pusher_mu_hi.reset();
  DesignLayout out;
  out.index = -1;
  try {
    out.conditioning = conditioning(s);
    score_sustained(s, o, total, out, true);
  } catch (const InputError& e) {
    out.note = std::string("no sustained score: ") + e.what();
  }
  if (!o.mu_hi) {
    try {
      score_step(s, o, total, out);
    } catch (const InputError& e) {
      out.note += std::string(out.note.empty() ? "" : "; ") + "no one-step score: " + e.what();
    }
  }
  out.score = (o.push == DesignPush::kSustained ? out.sustained_score : out.step_score).value_or(Rational(0));
  return out;
}

Region layout_region(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f,
                     const DesignOptions& o) {
  if (o.push == DesignPush::kSustained) {
    const Scene s = layout_scene(part, cands, f, o, false);
    const SustainedSet J = sustained_set(s, false);
    const auto target = sustained_target(J);
    return compute_region(s, *target, region_options(o, o.pusher_mu));
  }
  const Scene s = layout_scene(part, cands, f, o, true);
  return compute_region(s, seating_set(s), region_options(o, o.pusher_mu));
}

}  // namespace fixel
