#include "limb_row.hpp"

#include <algorithm>
#include <bit>

namespace implicitizer::detail {

namespace {

// Up to this many limbs in the shorter factor, a product is added limb by limb into
// the entry (no scratch product, no separate addition).
constexpr std::size_t kShortFactorLimbs = 4;

// The bits of an n-limb magnitude (0 for zero).
std::size_t magnitude_bits(const mp_limb_t* p, std::size_t n) {
  while (n > 0 && p[n - 1] == 0) --n;
  return n == 0 ? 0 : 64 * (n - 1) + static_cast<std::size_t>(std::bit_width(p[n - 1]));
}

// Carries (or borrows) `carry` into the `rest` limbs at `at`, modulo their width:
// the tail of every multiply-and-add into an entry.
void carry_into(mp_limb_t* at, mp_size_t rest, mp_limb_t carry, bool subtract) {
  if (carry == 0 || rest <= 0) return;
  if (subtract) {
    mpn_sub_1(at, at, rest, carry);
  } else {
    mpn_add_1(at, at, rest, carry);
  }
}

}  // namespace

PackedCoefficients::PackedCoefficients(const std::vector<IntPolynomial>& polynomials) {
  for (const IntPolynomial& p : polynomials) {
    first_term_.push_back(terms_.size());
    for (const Integer& c : p.coefficients) {
      const LimbSpan span = limb_span(c.get_mpz_t());
      if (span.size() == 1) {
        terms_.push_back({span.limbs[0], span.signed_size});
      } else {
        terms_.push_back({limbs_.size(), span.signed_size});
        limbs_.insert(limbs_.end(), span.limbs, span.limbs + span.size());
      }
    }
  }
}

void LimbRow::reserve_columns(std::size_t columns) {
  if (columns <= nonzero_.size()) return;
  limbs_.resize(columns * width_, 0);
  nonzero_.resize(columns, 0);
}

// Limbs for a capacity of `bits`, with a quarter more: the bound grows a little at
// most steps, and each widening copies the whole row.
std::size_t LimbRow::width_for(std::size_t bits) { return ((bits + 1) + (bits + 1) / 4 + 63) / 64; }

void LimbRow::reset_width(std::size_t bits) {
  width_ = width_for(bits);
  if (limbs_.size() < nonzero_.size() * width_) limbs_.resize(nonzero_.size() * width_, 0);
}

void LimbRow::ensure_bits(std::size_t bits) {
  if (bits <= capacity_bits()) return;
  const std::size_t width = width_for(bits);
  std::vector<mp_limb_t> limbs(nonzero_.size() * width, 0);
  for (std::size_t c = 0; c < nonzero_.size(); ++c) {
    if (nonzero_[c] == 0) continue;
    const mp_limb_t* from = entry(c);
    mp_limb_t* to = limbs.data() + c * width;
    std::copy(from, from + width_, to);
    if (negative(from)) std::fill(to + width_, to + width, ~mp_limb_t{0});
  }
  limbs_ = std::move(limbs);
  width_ = width;
}

bool LimbRow::all_zero(const mp_limb_t* e) const {
  for (std::size_t i = 0; i < width_; ++i) {
    if (e[i] != 0) return false;
  }
  return true;
}

void LimbRow::get(std::size_t c, mpz_ptr out) const {
  const mp_limb_t* e = entry(c);
  const bool minus = negative(e);
  mp_limb_t* to = mpz_limbs_write(out, static_cast<mp_size_t>(width_));
  if (minus) {
    mpn_neg(to, e, static_cast<mp_size_t>(width_));
  } else {
    std::copy(e, e + width_, to);
  }
  const auto size = static_cast<mp_size_t>(width_);
  mpz_limbs_finish(out, minus ? -size : size);
}

void LimbRow::set(std::size_t c, mpz_srcptr v) {
  mp_limb_t* e = entry(c);
  std::fill(e, e + width_, 0);
  const std::size_t n = mpz_size(v);
  const mp_limb_t* p = mpz_limbs_read(v);
  std::copy(p, p + std::min(n, width_), e);
  if (mpz_sgn(v) < 0) mpn_neg(e, e, static_cast<mp_size_t>(width_));
  nonzero_[c] = 1;
}

void LimbRow::clear(std::size_t c) {
  if (nonzero_[c] == 0) return;
  mp_limb_t* e = entry(c);
  std::fill(e, e + width_, 0);
  nonzero_[c] = 0;
}

void LimbRow::add_magnitude(mp_limb_t* e, const mp_limb_t* p, std::size_t n, bool subtract) const {
  const auto w = static_cast<mp_size_t>(width_);
  const auto k = static_cast<mp_size_t>(n);
  const mp_limb_t carry = subtract ? mpn_sub_n(e, e, p, k) : mpn_add_n(e, e, p, k);
  carry_into(e + k, w - k, carry, subtract);
}

void LimbRow::add_span(std::size_t c, LimbSpan f, LimbSpan m) {
  mp_limb_t* e = entry(c);
  nonzero_[c] = 1;
  const bool subtract = f.negative() != m.negative();
  std::size_t fn = f.size(), mn = m.size();
  const mp_limb_t* fp = f.limbs;
  const mp_limb_t* mp = m.limbs;
  if (fn < mn) {
    std::swap(fn, mn);
    std::swap(fp, mp);
  }
  if (mn <= kShortFactorLimbs) {
    // The usual case: one pass of GMP's multiply-and-add over the longer factor per
    // limb of the shorter, into the entry itself. Limbs past the width only add
    // multiples of 2^(64·width).
    for (std::size_t j = 0; j < mn && j < width_; ++j) {
      const std::size_t n = std::min(fn, width_ - j);
      mp_limb_t* at = e + j;
      const auto k = static_cast<mp_size_t>(n);
      const mp_limb_t carry = subtract ? mpn_submul_1(at, fp, k, mp[j]) : mpn_addmul_1(at, fp, k, mp[j]);
      carry_into(at + k, static_cast<mp_size_t>(width_ - j - n), carry, subtract);
    }
    return;
  }
  scratch_.resize(fn + mn);
  mpn_mul(scratch_.data(), fp, static_cast<mp_size_t>(fn), mp, static_cast<mp_size_t>(mn));
  // The true result fits, so the product's limbs beyond the width are zero or wrap.
  add_magnitude(e, scratch_.data(), std::min(fn + mn, width_), subtract);
}

void LimbRow::add_multiple(const std::uint32_t* columns, std::size_t count, std::size_t from, mpz_srcptr f,
                           const PackedCoefficients& coefficients, std::size_t i) {
  const LimbSpan factor = limb_span(f);
  // Read once: the updates write memory the compiler cannot tell apart from these.
  const PackedCoefficients::Term* terms = coefficients.terms(i);
  const mp_limb_t* pool = coefficients.pool();
  const std::size_t fn = factor.size();
  if (fn > width_) {
    for (std::size_t t = from; t < count; ++t)
      add_span(columns[t], factor, PackedCoefficients::coefficient(terms[t], pool));
    return;
  }
  const auto n = static_cast<mp_size_t>(fn);
  const auto rest = static_cast<mp_size_t>(width_ - fn);
  for (std::size_t t = from; t < count; ++t) {
    const PackedCoefficients::Term& term = terms[t];
    if (term.signed_size != 1 && term.signed_size != -1) {
      add_span(columns[t], factor, PackedCoefficients::coefficient(term, pool));
      continue;
    }
    // The usual case, as add_span does it, without the call and the size tests.
    mp_limb_t* e = entry(columns[t]);
    nonzero_[columns[t]] = 1;
    const bool subtract = factor.negative() != (term.signed_size < 0);
    const mp_limb_t carry = subtract ? mpn_submul_1(e, factor.limbs, n, term.limb_or_offset)
                                     : mpn_addmul_1(e, factor.limbs, n, term.limb_or_offset);
    carry_into(e + n, rest, carry, subtract);
  }
}

void LimbRow::multiply(std::size_t c, mpz_srcptr s) {
  mp_limb_t* e = entry(c);
  const auto w = static_cast<mp_size_t>(width_);
  const std::size_t sn = mpz_size(s);
  const mp_limb_t* sp = mpz_limbs_read(s);
  if (sn == 1) {
    // Two's complement times a positive number, modulo 2^(64·width): the low limbs
    // of the unsigned product.
    mpn_mul_1(e, e, w, sp[0]);
    return;
  }
  scratch_.resize(width_ + sn);
  if (width_ >= sn) {
    mpn_mul(scratch_.data(), e, w, sp, static_cast<mp_size_t>(sn));
  } else {
    mpn_mul(scratch_.data(), sp, static_cast<mp_size_t>(sn), e, w);
  }
  std::copy(scratch_.begin(), scratch_.begin() + static_cast<long>(width_), e);
}

std::size_t LimbRow::max_bits(std::size_t from, std::size_t to) const {
  std::size_t bits = 0;
  std::vector<mp_limb_t> magnitude(width_);
  for (std::size_t c = from; c <= to && c < nonzero_.size(); ++c) {
    if (nonzero_[c] == 0) continue;
    const mp_limb_t* e = entry(c);
    if (negative(e)) {
      mpn_neg(magnitude.data(), e, static_cast<mp_size_t>(width_));
      bits = std::max(bits, magnitude_bits(magnitude.data(), width_));
    } else {
      bits = std::max(bits, magnitude_bits(e, width_));
    }
  }
  return bits;
}

}  // namespace implicitizer::detail
