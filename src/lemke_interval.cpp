#include "fixel/internal/lemke_interval.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace fixel::internal {

IntervalTableau::IntervalTableau(const MatrixQ& B, const VectorQ& b) : n_(static_cast<int>(b.size())), width_(n_ + 2) {
  start(true);
  for (int i = 0; i < n_; ++i) {
    for (int j = 0; j < n_; ++j)
      if (mpq_sgn(B(i, j).backend().data()) != 0) at_slot(i, j) = -enclosure(B(i, j));  // no Rational(0) temporary
    at_slot(i, n_) = FI(-1);
    at_slot(i, n_ + 1) = enclosure(b[i]);
  }
  keep_initial();
}

IntervalTableau::IntervalTableau(const IntervalRows& prepared, const VectorQ& b)
    : n_(static_cast<int>(b.size())), width_(n_ + 2), prepared_(&prepared) {
  start(false);
  const FI* row = prepared.rows.data();
  first_rhs_.resize(n_);
  for (int i = 0; i < n_; ++i, row += n_ + 1) {
    std::copy(row, row + n_ + 1, &at_slot(i, 0));
    at_slot(i, n_ + 1) = first_rhs_[i] = enclosure(b[i]);
  }
  initial_.clear();  // made when asked for (approx)
}

void IntervalRows::assign(const MatrixQ& B) {
  n = static_cast<int>(B.rows());
  rows.assign(static_cast<std::size_t>(n) * (n + 1), FI(0));
  for (int i = 0; i < n; ++i) {
    FI* row = &rows[static_cast<std::size_t>(i) * (n + 1)];
    for (int j = 0; j < n; ++j)
      if (mpq_sgn(B(i, j).backend().data()) != 0) row[j] = -IntervalTableau::enclosure(B(i, j));
    row[n] = FI(-1);
  }
}

void IntervalTableau::start(bool zeros) {
  if (zeros)
    T_.assign(static_cast<std::size_t>(n_) * width_, FI(0));
  else
    T_.resize(static_cast<std::size_t>(n_) * width_);
  basis_.resize(n_);
  for (int i = 0; i < n_; ++i) basis_[i] = i;
  slot_.assign(2 * n_ + 2, -1);
  stamp_.assign(width_, 0);
  pending_.assign(width_, -1);
  forget_pivots();
  // Slots: z_j at j, z0 at n, b at n + 1; the w's are basic.
  for (int j = 0; j <= n_; ++j) slot_[n_ + j] = j;
  slot_[rhs()] = n_ + 1;
}

void IntervalTableau::keep_initial() {
  initial_.resize(static_cast<std::size_t>(n_) * width_);  // width_ = n + 2: ApproxProblem's layout
  if (prepared_ == nullptr) {
    for (std::size_t k = 0; k < T_.size(); ++k) initial_[k] = T_[k].inf();
    return;
  }
  for (int i = 0; i < n_; ++i) {
    const FI* row = &prepared_->rows[static_cast<std::size_t>(i) * (n_ + 1)];
    for (int j = 0; j <= n_; ++j) initial_[static_cast<std::size_t>(i) * width_ + j] = row[j].inf();
    initial_[static_cast<std::size_t>(i) * width_ + n_ + 1] = first_rhs_[i].inf();
  }
}

void IntervalTableau::pivot(int r, int s) {
  const int ks = slot_[s];
  bring_up_to_date(ks);
  const int leaving = basis_[r];
  eta_.resize(static_cast<std::size_t>(pivots_ + 1) * n_);
  eta_support_start_.push_back(static_cast<int>(eta_support_.size()));
  const FI inverse = FI(1) / at_slot(r, ks);
  FI* g = &eta_[static_cast<std::size_t>(pivots_) * n_];
  for (int i = 0; i < n_; ++i) {
    const FI f = at_slot(i, ks);
    if (i == r || (f.inf() == 0 && f.sup() == 0)) continue;
    g[i] = f * inverse;
    eta_support_.push_back(i);
  }
  eta_row_.push_back(r);
  eta_inverse_.push_back(inverse);
  pending_[ks] = pivots_;  // the slot keeps T(·, s) until take_pivot_column
  stamp_[ks] = ++pivots_;
  basis_[r] = s;
  slot_[leaving] = ks;
  slot_[s] = -1;
  if (pivots_ >= 2 * n_) flush();  // bounds the pivots kept, and the work, by the eager update's
}

void IntervalTableau::take_pivot_column(int k) {
  const int t = pending_[k];
  pending_[k] = -1;
  const int r = eta_row_[t];
  const FI inverse = eta_inverse_[t];
  at_slot(r, k) = inverse;
  const FI* g = &eta_[static_cast<std::size_t>(t) * n_];
  const int end = t + 1 < pivots_ ? eta_support_start_[t + 1] : static_cast<int>(eta_support_.size());
  for (int e = eta_support_start_[t]; e < end; ++e) {  // an exact zero stays exact
    const int i = eta_support_[e];
    at_slot(i, k) = -g[i];
  }
}

void IntervalTableau::forget_pivots() {
  eta_.clear();
  eta_row_.clear();
  eta_inverse_.clear();
  eta_support_.clear();
  eta_support_start_.clear();
}

void IntervalTableau::flush() {
  for (int k = 0; k < width_; ++k) bring_up_to_date(k);
  forget_pivots();
  pivots_ = 0;
  stamp_.assign(width_, 0);
}

namespace {

// |z| enclosed, for 0 < |z| < 2^960: mpz_get_d truncates toward zero, so
// the double above it (one ulp up) bounds |z| when it has more than 53 bits.
FI magnitude_enclosure(mpz_srcptr z) {
  const double truncated = std::abs(mpz_get_d(z));
  if (mpz_sizeinbase(z, 2) <= 53) return FI(truncated);
  return FI(truncated, std::nextafter(truncated, std::numeric_limits<double>::infinity()));
}

double from_bits(std::uint64_t bits) {
  double x = 0;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}
std::uint64_t to_bits(double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof x);
  return bits;
}
// The double next to a positive finite x, up or down: its bit pattern ± 1.
double next_up(double x) { return from_bits(to_bits(x) + 1); }
double next_down(double x) { return from_bits(to_bits(x) - 1); }

}  // namespace

FI two_limb_magnitude(mpz_srcptr z) {
  const mp_limb_t low = mpz_getlimbn(z, 0);
  const mp_limb_t high = mpz_size(z) > 1 ? mpz_getlimbn(z, 1) : 0;
  if (high == 0 && low < (mp_limb_t(1) << 53)) return FI(static_cast<double>(low));
  int shift = 0;  // |z| = (top + a fraction below 1)·2^shift
  mp_limb_t top = low;
  if (high != 0) {
    const int zeros = __builtin_clzl(high);
    shift = 64 - zeros;
    top = zeros == 0 ? high : (high << zeros) | (low >> shift);
  }
  const double v = static_cast<double>(top);  // top ≥ 2^53: v ≥ 2^53, an ulp ≥ 2
  const double scale = from_bits(static_cast<std::uint64_t>(1023 + shift) << 52);  // 2^shift, exact
  return FI(next_down(v) * scale, next_up(v) * scale);
}

FI IntervalTableau::enclosure(const Rational& q) {
  const auto* m = q.backend().data();
  const mpz_srcptr num = mpq_numref(m), den = mpq_denref(m);
  constexpr mp_limb_t kExact = mp_limb_t(1) << 53;
  if (mpz_size(num) <= 1 && mpz_size(den) == 1 && mpz_getlimbn(num, 0) < kExact && mpz_getlimbn(den, 0) < kExact) {
    const double n = static_cast<double>(mpz_getlimbn(num, 0));
    const FI quotient = FI(n) / FI(static_cast<double>(mpz_getlimbn(den, 0)));
    return mpz_sgn(num) < 0 ? -quotient : quotient;
  }
  // Long parts (b's rows often have denominators of 60 to 90 bits): each
  // part enclosed, then one interval division, rather than GMP's quotient
  // truncated to a double (a multi-limb division) and widened by an ulp
  // each way. Parts beyond double range take the shared conversion.
  if (mpz_sgn(num) != 0 && mpz_size(num) <= 2 && mpz_size(den) <= 2) {  // b's usual case
    const FI quotient = two_limb_magnitude(num) / two_limb_magnitude(den);
    return mpz_sgn(num) < 0 ? -quotient : quotient;
  }
  constexpr std::size_t kLimbs = 15;  // 960 bits
  if (mpz_sgn(num) != 0 && mpz_size(num) <= kLimbs && mpz_size(den) <= kLimbs) {
    const FI quotient = magnitude_enclosure(num) / magnitude_enclosure(den);
    return mpz_sgn(num) < 0 ? -quotient : quotient;
  }
  return to_interval(q);
}

IntervalTableau::Storage& IntervalTableau::storage() {
  thread_local Storage s;
  return s;
}

}  // namespace fixel::internal
