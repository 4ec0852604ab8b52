#include "implicitizer/modular/crt_lift.hpp"

#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <stdexcept>
#include <utility>

namespace implicitizer {

CrtLift::CrtLift(std::size_t size, CrtLiftParams params)
    : params_(params), residues_(size), values_(size), known_(size, 0), confirmed_(size, 0) {
  if (params_.shared_denominator && params_.margin_bits == 0) {
    throw std::invalid_argument("CrtLift: a shared denominator needs a margin");
  }
  fmpz_one(modulus_.get());
  fmpz_one(denominator_.get());
}

std::size_t CrtLift::modulus_bits() const { return fmpz_bits(modulus_.get()); }

bool CrtLift::add(std::span<const mp_limb_t> residues, mp_limb_t p) {
  if (residues.size() != residues_.size()) throw std::invalid_argument("CrtLift::add: one residue per entry expected");
  if (p >> 63 != 0) throw std::invalid_argument("CrtLift::add: the prime must be below 2^63");
  check_values(residues, p);
  bool changed = false;
  if (primes_ == 0) {
    // The first prime sets the residue, symmetric.
    for (std::size_t i = 0; i < residues_.size(); ++i) {
      fmpz_set_ui(residues_[i].get(), residues[i]);
      if (residues[i] > p / 2) fmpz_sub_ui(residues_[i].get(), residues_[i].get(), p);
      changed = changed || residues[i] != 0;
    }
  } else {
    // In place, entry by entry: x ← x + M·((r − x)·M⁻¹ mod p), then into (−Mp/2,
    // Mp/2]. What FLINT's _fmpz_CRT_ui_precomp computes, without the temporary it
    // copies each entry into. The entry changes exactly when the multiple of M is not
    // zero; Mp is odd, so no entry sits on Mp/2.
    const mp_limb_t inverse = n_invmod(fmpz_fdiv_ui(modulus_.get(), p), p);
    const mp_limb_t inverse_quotient = n_mulmod_precomp_shoup(inverse, p);
    Fmpz product, half;
    fmpz_mul_ui(product.get(), modulus_.get(), p);
    fmpz_fdiv_q_2exp(half.get(), product.get(), 1);
    // An entry grows by about a limb every prime, and GMP would reallocate it to the
    // exact size each time: one without room for the next gets twice what it needs.
    const auto room = static_cast<int>(2 * (fmpz_size(product.get()) + 1));
    for (std::size_t i = 0; i < residues_.size(); ++i) {
      if (confirmed_[i]) {
        // The value stands for the integer (check_values brings it back if p refutes
        // the value); the integer of an integral value is the value itself.
        changed = changed || !fmpz_is_one(fmpq_denref(values_[i].get()));
        continue;
      }
      fmpz* x = residues_[i].get();
      const mp_limb_t difference = n_submod(residues[i], fmpz_fdiv_ui(x, p), p);
      if (difference == 0) continue;
      changed = true;
      if (COEFF_IS_MPZ(*x) && COEFF_TO_PTR(*x)->_mp_alloc < room / 2) {
        mpz_realloc2(COEFF_TO_PTR(*x), static_cast<mp_bitcnt_t>(room) * FLINT_BITS);
      }
      fmpz_addmul_ui(x, modulus_.get(), n_mulmod_shoup(inverse, difference, inverse_quotient, p));
      if (fmpz_cmp(x, half.get()) > 0) fmpz_sub(x, x, product.get());
    }
  }
  fmpz_mul_ui(modulus_.get(), modulus_.get(), p);
  ++primes_;
  return changed;
}

// A value n/d agrees with p when d ≢ 0 and n·d⁻¹ ≡ the residue; the first agreement
// confirms it (its denominator joins L).
void CrtLift::check_values(std::span<const mp_limb_t> residues, mp_limb_t p) {
  nmod_t mod;
  nmod_init(&mod, p);
  for (std::size_t i = 0; i < residues_.size(); ++i) {
    if (!known_[i]) continue;
    const fmpq* v = values_[i].get();
    // n ≡ r·d rather than n·d⁻¹ ≡ r: the same test for d ≢ 0, without an inverse.
    const mp_limb_t den = fmpz_fdiv_ui(fmpq_denref(v), p);
    const bool agrees = den != 0 && fmpz_fdiv_ui(fmpq_numref(v), p) == nmod_mul(residues[i], den, mod);
    if (agrees && !confirmed_[i]) {
      confirmed_[i] = 1;
      fmpz_lcm(denominator_.get(), denominator_.get(), fmpq_denref(v));
    }
    if (!agrees) {
      // Every prime since the value was confirmed agreed with it, and none was folded
      // into the integer: the integer is the value's.
      if (confirmed_[i]) value_modulo(i, residues_[i].get());
      known_[i] = confirmed_[i] = 0;
    }
  }
}

void CrtLift::spread(std::span<const std::size_t> positions, std::size_t new_size) {
  if (positions.size() != residues_.size()) throw std::invalid_argument("CrtLift::spread: one position per entry");
  std::vector<Fmpz> residues(new_size);
  std::vector<Fmpq> values(new_size);
  std::vector<char> known(new_size, 0), confirmed(new_size, 0);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const std::size_t to = positions[i];
    if (to >= new_size || (i > 0 && to <= positions[i - 1])) {
      throw std::invalid_argument("CrtLift::spread: positions must increase below the new size");
    }
    residues[to] = std::move(residues_[i]);
    values[to] = std::move(values_[i]);
    known[to] = known_[i];
    confirmed[to] = confirmed_[i];
  }
  residues_ = std::move(residues);
  values_ = std::move(values);
  known_ = std::move(known);
  confirmed_ = std::move(confirmed);
}

void CrtLift::value_modulo(std::size_t i, fmpz_t out) const {
  const fmpq* v = values_[i].get();
  if (!fmpz_invmod(out, fmpq_denref(v), modulus_.get())) {
    throw std::logic_error("CrtLift: a confirmed denominator shares a factor with the modulus");
  }
  fmpz_mul(out, out, fmpq_numref(v));
  fmpz_smod(out, out, modulus_.get());
}

Integer CrtLift::integer(std::size_t i) const {
  Integer out;
  if (!confirmed_[i]) {
    fmpz_get_mpz(out.get_mpz_t(), residues_[i].get());
  } else {
    Fmpz x;
    value_modulo(i, x.get());
    fmpz_get_mpz(out.get_mpz_t(), x.get());
  }
  return out;
}

bool CrtLift::reconstruct() {
  fmpz_fdiv_q_2exp(bound_.get(), modulus_.get(), params_.margin_bits + 1);
  fmpz_sqrt(bound_.get(), bound_.get());
  bool complete = true;
  for (std::size_t i = 0; i < residues_.size(); ++i) {
    if (!known_[i]) known_[i] = reconstruct_entry(i);
    complete = complete && known_[i];
    if (!complete && !params_.shared_denominator) return false;
  }
  if (!complete) complete = reconstruct_with_trial_denominator();
  return complete;
}

bool CrtLift::reconstruct_entry(std::size_t i) {
  const fmpz* m = modulus_.get();
  if (params_.shared_denominator) {
    fmpz_mul(scratch_.get(), residues_[i].get(), denominator_.get());
    fmpz_smod(scratch_.get(), scratch_.get(), m);
    if (fmpz_bits(scratch_.get()) + params_.margin_bits < fmpz_bits(m)) {
      fmpq_set_fmpz_frac(values_[i].get(), scratch_.get(), denominator_.get());
      return true;
    }
  }
  // FLINT needs positive bounds (below 2^(margin+1) only the test above can accept)
  // and the residue in [0, M). For odd M and no margin the bound is
  // fmpq_reconstruct_fmpz's, ⌊√((M − 1)/2)⌋.
  if (fmpz_is_zero(bound_.get())) return false;
  const fmpz* a = residues_[i].get();
  if (fmpz_sgn(a) < 0) {
    fmpz_add(scratch_.get(), a, m);
    a = scratch_.get();
  }
  return fmpq_reconstruct_fmpz_2(values_[i].get(), a, m, bound_.get(), bound_.get()) != 0;
}

// The second test of CrtLiftParams::shared_denominator with a trial L: the lcm of
// every denominator found so far, confirmed or not. All those values share one
// entry's divisors as denominators, so the balanced bound is what fails on a vector
// with a small leading coefficient and large others (tri_quadratic's equation: 2209
// and 2^28; a 62-bit M allows 2^20 for both), while every a·L is then small. A wrong
// trial L passes for an entry with probability about 2^-margin_bits.
bool CrtLift::reconstruct_with_trial_denominator() {
  Fmpz trial(denominator_);
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (known_[i]) fmpz_lcm(trial.get(), trial.get(), fmpq_denref(values_[i].get()));
  }
  const fmpz* m = modulus_.get();
  bool complete = !fmpz_equal(trial.get(), denominator_.get());  // else the first test already failed
  for (std::size_t i = 0; complete && i < residues_.size(); ++i) {
    if (known_[i]) continue;
    fmpz_mul(scratch_.get(), residues_[i].get(), trial.get());
    fmpz_smod(scratch_.get(), scratch_.get(), m);
    complete = fmpz_bits(scratch_.get()) + params_.margin_bits < fmpz_bits(m);
  }
  if (!complete) return false;
  for (std::size_t i = 0; i < residues_.size(); ++i) {
    if (known_[i]) continue;
    fmpz_mul(scratch_.get(), residues_[i].get(), trial.get());
    fmpz_smod(scratch_.get(), scratch_.get(), m);
    fmpq_set_fmpz_frac(values_[i].get(), scratch_.get(), trial.get());
    known_[i] = 1;
  }
  return true;
}

Fmpz CrtLift::lcm_of_denominators() const {
  Fmpz l;
  fmpz_one(l.get());
  for (const Fmpq& v : values_) fmpz_lcm(l.get(), l.get(), fmpq_denref(v.get()));
  return l;
}

Integer CrtLift::common_denominator() const {
  Integer out;
  fmpz_get_mpz(out.get_mpz_t(), lcm_of_denominators().get());
  return out;
}

std::vector<Integer> CrtLift::integer_values() const {
  const Fmpz l = lcm_of_denominators();
  Fmpz c;
  std::vector<Integer> out(values_.size());
  for (std::size_t i = 0; i < values_.size(); ++i) {
    fmpz_divexact(c.get(), l.get(), fmpq_denref(values_[i].get()));
    fmpz_mul(c.get(), c.get(), fmpq_numref(values_[i].get()));
    fmpz_get_mpz(out[i].get_mpz_t(), c.get());
  }
  return out;
}

}  // namespace implicitizer
