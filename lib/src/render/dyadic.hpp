#pragma once
// Private to lib/src/render: dyadic rationals m·2^e (every double is one; sums and
// products stay dyadic, so a ray's polynomial expands exactly), shared by
// ray_polynomial.cpp (exact expansion) and root_isolation.cpp (exact isolation). The
// mantissa is FLINT's fmpz, through the owners of implicitizer/modular/flint_handles.hpp.

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include <algorithm>
#include <cmath>

#include "implicitizer/modular/flint_handles.hpp"

namespace implicitizer::render_detail {

using implicitizer::Fmpz;
using implicitizer::FmpzPoly;

// mantissa·2^exponent, exactly.
struct Dyadic {
  Fmpz mantissa;
  slong exponent = 0;

  static Dyadic of(double x) {
    Dyadic d;
    if (x == 0) return d;
    int e = 0;
    const double fraction = std::frexp(x, &e);  // x = fraction·2^e, 0.5 ≤ |fraction| < 1
    fmpz_set_si(d.mantissa.get(), static_cast<slong>(std::ldexp(fraction, 53)));  // exact: 53 bits
    d.exponent = e - 53;
    return d;
  }
  bool is_zero() const { return fmpz_is_zero(mantissa.get()); }
  // The double nearest below or at this (fmpz_get_d_2exp truncates): within 1 ulp.
  double to_double() const {
    if (is_zero()) return 0;
    slong e = 0;
    const double d = fmpz_get_d_2exp(&e, mantissa.get());
    return std::ldexp(d, static_cast<int>(std::clamp<slong>(e + exponent, -1100, 1100)));
  }
};

inline Dyadic multiply(const Dyadic& a, const Dyadic& b) {
  Dyadic out;
  fmpz_mul(out.mantissa.get(), a.mantissa.get(), b.mantissa.get());
  out.exponent = a.exponent + b.exponent;
  return out;
}

inline Dyadic add(const Dyadic& a, const Dyadic& b) {
  if (a.is_zero()) return b;
  if (b.is_zero()) return a;
  Dyadic out;
  const slong e = std::min(a.exponent, b.exponent);
  Fmpz shifted;
  fmpz_mul_2exp(out.mantissa.get(), a.mantissa.get(), static_cast<ulong>(a.exponent - e));
  fmpz_mul_2exp(shifted.get(), b.mantissa.get(), static_cast<ulong>(b.exponent - e));
  fmpz_add(out.mantissa.get(), out.mantissa.get(), shifted.get());
  out.exponent = e;
  return out;
}

inline Dyadic negate(const Dyadic& a) {
  Dyadic out = a;
  fmpz_neg(out.mantissa.get(), out.mantissa.get());
  return out;
}

}  // namespace implicitizer::render_detail
