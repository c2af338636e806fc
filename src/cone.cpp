#include "fixel/cone.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost_mp.h>

#include <array>
#include <optional>

#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/filtered.h"

namespace fixel {

namespace {

using Kernel = CGAL::Simple_cartesian<Rational>;  // exact: every predicate on Rational
using Vector3 = Kernel::Vector_3;

Vector3 to_cgal(const VectorQ& v) { return Vector3(v[0], v[1], v[2]); }
VectorQ from_cgal(const Vector3& v) {
  VectorQ out(3);
  out << v.x(), v.y(), v.z();
  return out;
}

// Planar analogue of the cross product: the normal of the line spanned by r,
// rotated +90°.
VectorQ perp2(const VectorQ& r) {
  VectorQ out(2);
  out << -r[1], r[0];
  return out;
}

// +1 if every ray has a·r >= 0, -1 if every ray has a·r <= 0, 0 otherwise.
// Both would mean a is orthogonal to every ray; callers exclude that case.
int supporting_side(const VectorQ& a, const std::vector<VectorQ>& rays) {
  bool nonneg = true, nonpos = true;
  for (const auto& r : rays) {
    const int s = sign(a.dot(r));
    nonneg = nonneg && s >= 0;
    nonpos = nonpos && s <= 0;
  }
  return nonneg ? 1 : (nonpos ? -1 : 0);
}

// Appends p, already primitive, unless it is in out.
void add_primitive(std::vector<VectorQ>& out, VectorQ&& p) {
  for (const auto& q : out)
    if (q == p) return;
  out.push_back(std::move(p));
}

void add_unique(std::vector<VectorQ>& out, const VectorQ& a) { add_primitive(out, primitive_direction(a)); }

// Integer vectors in GMP: a ray scaled to integers, and the cross products
// of such rays, with no rational canonicalisation per operation.
struct Int3 {
  std::array<Integer, 3> v;
};

// A positive multiple of r (three entries) with integer entries.
Int3 integer_multiple(const VectorQ& r) {
  Int3 out;
  Integer lcm = 1;
  for (int k = 0; k < 3; ++k) {
    const mpz_srcptr den = mpq_denref(r[k].backend().data());
    if (mpz_cmp_ui(den, 1) != 0) mpz_lcm(lcm.backend().data(), lcm.backend().data(), den);
  }
  for (int k = 0; k < 3; ++k) {
    const mpq_srcptr q = r[k].backend().data();
    mpz_ptr x = out.v[k].backend().data();
    mpz_divexact(x, lcm.backend().data(), mpq_denref(q));
    mpz_mul(x, x, mpq_numref(q));
  }
  return out;
}

Int3 cross_integers(const Int3& a, const Int3& b) {
  Int3 c;
  Integer t;
  auto z = [](auto& x) { return x.backend().data(); };
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mpz_mul(z(c.v[k]), z(a.v[i]), z(b.v[j]));
    mpz_mul(z(t), z(a.v[j]), z(b.v[i]));
    mpz_sub(z(c.v[k]), z(c.v[k]), z(t));
  }
  return c;
}

bool is_zero(const Int3& x) {
  return mpz_sgn(x.v[0].backend().data()) == 0 && mpz_sgn(x.v[1].backend().data()) == 0 &&
         mpz_sgn(x.v[2].backend().data()) == 0;
}

int sign_of_dot(const Int3& a, const Int3& b) {
  Integer sum, t;
  for (int k = 0; k < 3; ++k) {
    mpz_mul(t.backend().data(), a.v[k].backend().data(), b.v[k].backend().data());
    mpz_add(sum.backend().data(), sum.backend().data(), t.backend().data());
  }
  return mpz_sgn(sum.backend().data());
}

// x divided by the gcd of its entries (x ≠ 0), as rationals.
VectorQ primitive_of_integers(const Int3& x) {
  Integer g;
  for (int k = 0; k < 3; ++k) mpz_gcd(g.backend().data(), g.backend().data(), x.v[k].backend().data());
  VectorQ out(3);
  for (int k = 0; k < 3; ++k) {
    const mpz_srcptr e = x.v[k].backend().data();
    mpz_ptr num = mpq_numref(out[k].backend().data());
    if (mpz_cmp_ui(g.backend().data(), 1) != 0)
      mpz_divexact(num, e, g.backend().data());
    else
      mpz_set(num, e);
  }
  return out;
}

// Adds a (or -a) if it supports the cone; a must not be orthogonal to every ray.
void add_if_supporting(std::vector<VectorQ>& out, const VectorQ& a, const std::vector<VectorQ>& rays) {
  const int side = supporting_side(a, rays);
  if (side != 0) add_unique(out, side > 0 ? a : VectorQ(-a));
}

void add_equality(std::vector<VectorQ>& out, const VectorQ& a) {
  add_unique(out, a);
  add_unique(out, -a);
}

std::vector<VectorQ> nonzero(const std::vector<VectorQ>& rays) {
  std::vector<VectorQ> out;
  for (const auto& r : rays)
    if (!r.isZero()) out.push_back(r);
  return out;
}

VectorQ unit(int dim, int k) {
  VectorQ e = VectorQ::Zero(dim);
  e[k] = 1;
  return e;
}

std::vector<VectorQ> facets3(const std::vector<VectorQ>& rays, int rank) {
  std::vector<VectorQ> out;
  if (rank == 0) {
    for (int k = 0; k < 3; ++k) add_equality(out, unit(3, k));
    return out;
  }
  if (rank == 1) {
    const Vector3 u = to_cgal(rays.front());
    // Two independent normals of u: cross with the axis least aligned to it.
    const Vector3 axis = CGAL::abs(u.x()) <= CGAL::abs(u.y()) && CGAL::abs(u.x()) <= CGAL::abs(u.z())
                             ? Vector3(1, 0, 0)
                             : (CGAL::abs(u.y()) <= CGAL::abs(u.z()) ? Vector3(0, 1, 0) : Vector3(0, 0, 1));
    const Vector3 n1 = CGAL::cross_product(u, axis), n2 = CGAL::cross_product(u, n1);
    add_equality(out, from_cgal(n1));
    add_equality(out, from_cgal(n2));
    add_if_supporting(out, from_cgal(u), rays);  // absent when the rays span the whole line
    return out;
  }
  if (rank == 2) {
    Vector3 n = CGAL::NULL_VECTOR;
    for (std::size_t i = 0; i < rays.size() && n == CGAL::NULL_VECTOR; ++i)
      for (std::size_t j = i + 1; j < rays.size() && n == CGAL::NULL_VECTOR; ++j)
        n = CGAL::cross_product(to_cgal(rays[i]), to_cgal(rays[j]));
    add_equality(out, from_cgal(n));
    for (const auto& r : rays) add_if_supporting(out, from_cgal(CGAL::cross_product(n, to_cgal(r))), rays);
    return out;
  }
  // Full rank: every facet plane contains two independent rays.
  for (std::size_t i = 0; i < rays.size(); ++i)
    for (std::size_t j = i + 1; j < rays.size(); ++j) {
      const Vector3 c = CGAL::cross_product(to_cgal(rays[i]), to_cgal(rays[j]));
      if (c != CGAL::NULL_VECTOR) add_if_supporting(out, from_cgal(c), rays);
    }
  return out;
}

std::vector<VectorQ> facets2(const std::vector<VectorQ>& rays, int rank) {
  std::vector<VectorQ> out;
  if (rank == 0) {
    add_equality(out, unit(2, 0));
    add_equality(out, unit(2, 1));
    return out;
  }
  if (rank == 1) {
    add_equality(out, perp2(rays.front()));
    add_if_supporting(out, rays.front(), rays);
    return out;
  }
  for (const auto& r : rays) add_if_supporting(out, perp2(r), rays);
  return out;
}

// facets3 of rays of full rank on enclosures (docs/theory.md §8): the same
// pairs in the same order, each supporting test decided by the signs of
// c·r_k with c = r_i × r_j enclosed, and an exact sign only where an
// enclosure holds zero (c·r_i and c·r_j are zero by construction and not
// asked). The exact c is made for the supporting pairs, and for a pair
// whose c may be zero. Empty (not decided) when rank 3 is not certified:
// some c·r_k certainly nonzero.
std::optional<std::vector<VectorQ>> facets3_filtered(const std::vector<VectorQ>& rays) {
  using internal::certain_sign;
  using internal::FI;
  using internal::kUndecided;
  using F3 = std::array<FI, 3>;
  internal::Protect guard;
  std::vector<F3> f;
  f.reserve(rays.size());
  for (const auto& r : rays)
    f.push_back({internal::to_interval(r[0]), internal::to_interval(r[1]), internal::to_interval(r[2])});
  auto fcross = [](const F3& a, const F3& b) -> F3 {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto fdot = [](const F3& a, const F3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const std::size_t m = rays.size();
  bool full = false;
  for (std::size_t i = 0; i < m && !full; ++i)
    for (std::size_t j = i + 1; j < m && !full; ++j) {
      const F3 c = fcross(f[i], f[j]);
      for (std::size_t k = j + 1; k < m && !full; ++k) {
        const int s = certain_sign(fdot(c, f[k]));
        full = s != kUndecided && s != 0;
      }
    }
  if (!full) return std::nullopt;
  bool exact_signs = false;
  std::vector<VectorQ> out;
  // Exact values in integers: each ray scaled to integers once, when first
  // needed, and c_ij = r_i × r_j from those, a positive multiple of the
  // rational cross product (the same signs, the same primitive direction).
  std::vector<std::optional<Int3>> integer_rays(m);
  auto integer_ray = [&](std::size_t k) -> const Int3& {
    if (!integer_rays[k]) integer_rays[k] = integer_multiple(rays[k]);
    return *integer_rays[k];
  };
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) {
      const F3 fc = fcross(f[i], f[j]);
      std::optional<Int3> c;  // the exact cross product, made when needed
      auto exact = [&]() -> const Int3& {
        if (!c) c = cross_integers(integer_ray(i), integer_ray(j));
        return *c;
      };
      bool nonzero = false;
      for (const FI& x : fc) nonzero = nonzero || (certain_sign(x) != kUndecided && certain_sign(x) != 0);
      if (!nonzero) {
        exact_signs = true;
        if (is_zero(exact())) continue;
      }
      bool nonneg = true, nonpos = true;
      for (std::size_t k = 0; k < m && (nonneg || nonpos); ++k) {
        if (k == i || k == j) continue;  // on the plane by construction
        int s = certain_sign(fdot(fc, f[k]));
        if (s == kUndecided) {
          exact_signs = true;
          s = sign_of_dot(exact(), integer_ray(k));
        }
        nonneg = nonneg && s >= 0;
        nonpos = nonpos && s <= 0;
      }
      if (!nonneg && !nonpos) continue;
      VectorQ normal = primitive_of_integers(exact());
      if (!nonneg) normal = -normal;
      add_primitive(out, std::move(normal));
    }
  internal::record_filter(FilterSite::kCone, !exact_signs);
  return out;
}

}  // namespace

int internal::exact_rank(const std::vector<VectorQ>& rays, int dim) {
  if (rays.empty()) return 0;
  MatrixQ A(dim, static_cast<int>(rays.size()));
  for (std::size_t k = 0; k < rays.size(); ++k) A.col(static_cast<int>(k)) = rays[k];
  return static_cast<int>(internal::exact_lu(A).rank());
}

VectorQ primitive_direction(const VectorQ& v) {
  if (v.isZero()) return v;
  // In GMP integers: the lcm L of the denominators, the entries times L, and
  // their gcd g (positive); each entry is then (numerator · L/den) / g.
  Integer lcm = 1, g, x;
  auto z = [](auto& i) { return i.backend().data(); };
  for (int k = 0; k < v.size(); ++k) {
    const mpz_srcptr den = mpq_denref(v[k].backend().data());
    if (mpz_cmp_ui(den, 1) != 0) mpz_lcm(z(lcm), z(lcm), den);
  }
  VectorQ out(v.size());
  for (int k = 0; k < v.size(); ++k) {
    const mpq_srcptr q = v[k].backend().data();
    mpz_divexact(z(x), z(lcm), mpq_denref(q));
    mpz_mul(z(x), z(x), mpq_numref(q));
    mpq_set_z(out[k].backend().data(), z(x));
    mpz_gcd(z(g), z(g), z(x));
  }
  if (mpz_cmp_ui(z(g), 1) != 0)
    for (int k = 0; k < v.size(); ++k) {
      mpz_ptr num = mpq_numref(out[k].backend().data());
      mpz_divexact(num, num, z(g));
    }
  return out;
}

std::vector<VectorQ> cone_facet_normals(const std::vector<VectorQ>& rays, int dim) {
  if (dim != 2 && dim != 3) throw InputError("dim", std::to_string(dim), "must be 2 or 3");
  for (std::size_t k = 0; k < rays.size(); ++k)
    if (rays[k].size() != dim)
      throw InputError("rays[" + std::to_string(k) + "]", std::to_string(rays[k].size()) + " entries",
                       "but the cone lives in dimension " + std::to_string(dim));
  const std::vector<VectorQ> live = nonzero(rays);
  if (dim == 3 && !force_exact())
    if (auto facets = facets3_filtered(live)) return std::move(*facets);
  const int rank = internal::exact_rank(live, dim);
  return dim == 3 ? facets3(live, rank) : facets2(live, rank);
}

bool Halfspace::contains(const VectorQ& p) const { return internal::affine_sign_filtered(a, c, p) >= 0; }

}  // namespace fixel
