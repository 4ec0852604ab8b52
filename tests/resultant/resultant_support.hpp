#pragma once
/// \file
/// Helpers shared by the resultant tests: parsing an auxiliary system and the
/// independent check that a polynomial in x, y, z vanishes on a parametrization.

#include <array>
#include <string>

#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer::testing {

inline RingPtr parameter_ring() { return Ring::make({"s", "t"}); }
inline RingPtr space_ring() { return Ring::make({"x", "y", "z"}); }

/// ω, ξ, η, ζ parsed in (s, t).
inline std::array<Polynomial, 4> auxiliary_system(const std::string& w, const std::string& x, const std::string& y,
                                                  const std::string& z) {
  const RingPtr r = parameter_ring();
  return {parse_polynomial(w, r), parse_polynomial(x, r), parse_polynomial(y, r), parse_polynomial(z, r)};
}

/// ω^d·F(ξ/ω, η/ω, ζ/ω), expanded term by term (d = deg F).
inline Polynomial substituted(const Polynomial& f, const std::array<Polynomial, 4>& wxyz) {
  const RingPtr& r = wxyz[0].ring();
  const Ring& space = *f.ring();
  const std::int32_t d = f.total_degree();
  Polynomial sum(r);
  for (std::size_t i = 0; i < f.num_terms(); ++i) {
    const std::int32_t* e = space.exponents(f.monomial(i));
    Polynomial term = Polynomial::constant(r, f.coefficient(i)) * wxyz[0].pow(static_cast<unsigned>(d - e[0] - e[1] - e[2]));
    for (std::size_t v = 0; v < 3; ++v) term *= wxyz[v + 1].pow(static_cast<unsigned>(e[v]));
    sum += term;
  }
  return sum;
}

}  // namespace implicitizer::testing
