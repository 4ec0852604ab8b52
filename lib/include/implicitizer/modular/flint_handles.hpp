#pragma once
/// \file
/// RAII owners of FLINT's integers, rationals, integer polynomials and matrices
/// modulo a word prime: one set for every module that calls FLINT directly (the modular Gröbner
/// bases, the resultant's determinants, interpolation, the renderer's exact root
/// isolation), so that each value is cleared exactly once.

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/nmod_mat.h>

#include <cstddef>

namespace implicitizer {

/// An fmpz_t, initialized to 0; copies are deep, moves swap (so that vectors of them
/// grow without copying the digits).
class Fmpz {
 public:
  Fmpz() { fmpz_init(v_); }
  ~Fmpz() { fmpz_clear(v_); }
  Fmpz(const Fmpz& other) {
    fmpz_init(v_);
    fmpz_set(v_, other.v_);
  }
  Fmpz(Fmpz&& other) noexcept {
    fmpz_init(v_);
    fmpz_swap(v_, other.v_);
  }
  Fmpz& operator=(const Fmpz& other) {
    fmpz_set(v_, other.v_);
    return *this;
  }
  Fmpz& operator=(Fmpz&& other) noexcept {
    fmpz_swap(v_, other.v_);
    return *this;
  }
  /// The FLINT value.
  fmpz* get() { return v_; }
  /// The FLINT value.
  const fmpz* get() const { return v_; }

 private:
  fmpz_t v_;
};

/// An fmpq_t, initialized to 0/1; moves swap, no copies.
class Fmpq {
 public:
  Fmpq() { fmpq_init(v_); }
  ~Fmpq() { fmpq_clear(v_); }
  Fmpq(const Fmpq&) = delete;
  Fmpq(Fmpq&& other) noexcept {
    fmpq_init(v_);
    fmpq_swap(v_, other.v_);
  }
  Fmpq& operator=(const Fmpq&) = delete;
  Fmpq& operator=(Fmpq&& other) noexcept {
    fmpq_swap(v_, other.v_);
    return *this;
  }
  /// The FLINT value.
  fmpq* get() { return v_; }
  /// The FLINT value.
  const fmpq* get() const { return v_; }

 private:
  fmpq_t v_;
};

/// An fmpz_poly_t, initialized to 0; not copyable.
class FmpzPoly {
 public:
  FmpzPoly() { fmpz_poly_init(p_); }
  ~FmpzPoly() { fmpz_poly_clear(p_); }
  FmpzPoly(const FmpzPoly&) = delete;
  FmpzPoly& operator=(const FmpzPoly&) = delete;
  /// The FLINT value.
  fmpz_poly_struct* get() { return p_; }
  /// The FLINT value.
  const fmpz_poly_struct* get() const { return p_; }

 private:
  fmpz_poly_t p_;
};

/// An nmod_mat_t of rows × columns entries modulo p, initialized to 0; not copyable.
class NmodMatrix {
 public:
  NmodMatrix(std::size_t rows, std::size_t columns, mp_limb_t p) {
    nmod_mat_init(m_, static_cast<slong>(rows), static_cast<slong>(columns), p);
  }
  ~NmodMatrix() { nmod_mat_clear(m_); }
  NmodMatrix(const NmodMatrix&) = delete;
  NmodMatrix& operator=(const NmodMatrix&) = delete;
  /// The FLINT value.
  nmod_mat_struct* get() { return m_; }

 private:
  nmod_mat_t m_;
};

}  // namespace implicitizer
