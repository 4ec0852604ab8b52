#pragma once
// Private to the groebner module: the dense accumulator row of the proof over ℚ
// (rational_proof.hpp), a row of signed integers that all have the same width in
// limbs, in two's complement. Arithmetic is modulo 2^(64·width): a sum or product
// is exact as long as its true value fits, whatever the intermediate wrap-arounds,
// so the caller keeps an upper bound on the entries' size and widens the row before
// a result could pass it (ensure_bits).
//
// Why not GMP's mpz per entry: the proof's update is entry += f·c with f the same
// for a whole pivot row, a few limbs, and c mostly one limb. mpz_addmul pays for
// signs, normalisation and a possible reallocation at every call, which at these
// sizes costs more than the multiplication itself; GMP's mpn_addmul_1 into a
// fixed-width entry does only the multiplication. With entries of thousands of bits
// that differ in size within a row, one width gains nothing over mpz and takes more
// memory (docs/algorithms.md, "F4 modulo primes", item 7, has the measurements).

#include <gmp.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "int_polynomial.hpp"

namespace implicitizer::detail {

// A nonzero integer as the limbs of its magnitude (the top one nonzero) and their
// number, negated for a negative integer (as mpz_t keeps them). Two words, so that it
// is passed in registers: with a separate sign byte it went through the stack, and
// reading it back stalled the update loop.
struct LimbSpan {
  const mp_limb_t* limbs = nullptr;
  std::int64_t signed_size = 0;

  std::size_t size() const { return static_cast<std::size_t>(signed_size < 0 ? -signed_size : signed_size); }
  bool negative() const { return signed_size < 0; }
};

inline LimbSpan limb_span(mpz_srcptr x) { return {x->_mp_d, x->_mp_size}; }

// The coefficients of a list of integer polynomials, their limbs one after the other
// in one array: what LimbRow::add_multiple reads, term after term, where each mpz
// would send it to its own heap block.
class PackedCoefficients {
 public:
  explicit PackedCoefficients(const std::vector<IntPolynomial>& polynomials);

  // Most coefficients are one limb: that limb is kept in the term itself, which spares
  // a second memory access per update; longer ones are at an offset into the pool.
  struct Term {
    mp_limb_t limb_or_offset = 0;
    std::int64_t signed_size = 0;
  };

  // Polynomial i's terms, and the pool their long coefficients are in.
  const Term* terms(std::size_t i) const { return terms_.data() + first_term_[i]; }
  const mp_limb_t* pool() const { return limbs_.data(); }
  // A term's coefficient.
  static LimbSpan coefficient(const Term& term, const mp_limb_t* pool) {
    const bool one_limb = term.signed_size == 1 || term.signed_size == -1;
    return {one_limb ? &term.limb_or_offset : pool + term.limb_or_offset, term.signed_size};
  }
  // Coefficient t of polynomial i.
  LimbSpan coefficient(std::size_t i, std::size_t t) const { return coefficient(terms(i)[t], pool()); }

 private:
  std::vector<mp_limb_t> limbs_;
  std::vector<Term> terms_;
  std::vector<std::size_t> first_term_;  // per polynomial
};

class LimbRow {
 public:
  // How add_multiple takes the multiplied polynomials' coefficients.
  using Coefficients = PackedCoefficients;

  // At least `columns` entries: new ones are zero, the others keep their values.
  void reserve_columns(std::size_t columns);

  // The bits a magnitude may have: the entries hold values in (−2^capacity_bits,
  // 2^capacity_bits).
  std::size_t capacity_bits() const { return 64 * width_ - 1; }
  // Widens the row (every entry sign-extended) so that capacity_bits() ≥ bits.
  void ensure_bits(std::size_t bits);
  // Sets the width for capacity_bits() ≥ bits, narrower or wider, on a row whose
  // entries are all zero (then every limb is zero, whatever the width). A row that
  // needed many limbs would otherwise leave every later one paying for them.
  void reset_width(std::size_t bits);

  // Whether entry c was written since it was last cleared (it may still be zero).
  bool written(std::size_t c) const { return nonzero_[c] != 0; }
  bool is_zero(std::size_t c) const { return nonzero_[c] == 0 || all_zero(entry(c)); }
  // Entry c as an mpz.
  void get(std::size_t c, mpz_ptr out) const;
  // Sets entry c to v, which must fit.
  void set(std::size_t c, mpz_srcptr v);
  // Sets entry c to zero.
  void clear(std::size_t c);

  // entry(c) += f·m, f and m nonzero and the result within the capacity.
  void add_product(std::size_t c, mpz_srcptr f, mpz_srcptr m) { add_span(c, limb_span(f), limb_span(m)); }
  // entry(columns[t]) += f·(coefficient t of polynomial i) for t in [from, count):
  // a multiple of a polynomial, added by column.
  void add_multiple(const std::uint32_t* columns, std::size_t count, std::size_t from, mpz_srcptr f,
                    const PackedCoefficients& coefficients, std::size_t i);
  // entry(c) *= s, s > 0 and the result within the capacity.
  void multiply(std::size_t c, mpz_srcptr s);

  // The largest bit size of |entry| over the columns [from, to].
  std::size_t max_bits(std::size_t from, std::size_t to) const;

 private:
  static std::size_t width_for(std::size_t bits);
  mp_limb_t* entry(std::size_t c) { return limbs_.data() + c * width_; }
  const mp_limb_t* entry(std::size_t c) const { return limbs_.data() + c * width_; }
  bool all_zero(const mp_limb_t* e) const;
  void add_span(std::size_t c, LimbSpan f, LimbSpan m);
  bool negative(const mp_limb_t* e) const { return (e[width_ - 1] >> 63) != 0; }
  // e += or −= the n-limb magnitude p (n ≤ width), modulo 2^(64·width).
  void add_magnitude(mp_limb_t* e, const mp_limb_t* p, std::size_t n, bool subtract) const;

  std::size_t width_ = 1;
  std::vector<mp_limb_t> limbs_;       // columns × width_
  std::vector<std::uint8_t> nonzero_;  // per column: written since last cleared (may still be zero)
  std::vector<mp_limb_t> scratch_;
};

}  // namespace implicitizer::detail
