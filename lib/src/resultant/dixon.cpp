#include "implicitizer/resultant/dixon.hpp"

#include <stdexcept>

#include "implicitizer/polynomial/gcd.hpp"

namespace implicitizer {

namespace {

// det of the 3×3 matrix whose columns are a, b, c, each given at its three rows.
Polynomial det3(const std::array<Polynomial, 3>& a, const std::array<Polynomial, 3>& b,
                const std::array<Polynomial, 3>& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) + c[0] * (a[1] * b[2] - a[2] * b[1]);
}

}  // namespace

MatrixPencil dixon_pencil(const std::array<Polynomial, 4>& wxyz, std::int32_t m, std::int32_t n) {
  if (m < 1 || n < 1) throw std::invalid_argument("dixon_pencil: the bidegree must be at least (1, 1)");
  for (const auto& p : wxyz) {
    if (p.ring()->num_variables() != 2) throw std::invalid_argument("dixon_pencil: two parameters expected");
    if (p.degree_in(0) > m || p.degree_in(1) > n) throw std::invalid_argument("dixon_pencil: a polynomial exceeds the bidegree");
  }
  // Ring of the Dixon polynomial: s, t, α, β.
  const RingPtr ring = Ring::make({"s", "t", "a", "b"});
  const std::size_t at_st[2] = {0, 1}, at_at[2] = {2, 1}, at_ab[2] = {2, 3};
  // rows[f] = f(s,t), f(α,t), f(α,β) for f = ω, ξ, η, ζ.
  std::array<std::array<Polynomial, 3>, 4> rows{{{Polynomial(ring), Polynomial(ring), Polynomial(ring)},
                                                 {Polynomial(ring), Polynomial(ring), Polynomial(ring)},
                                                 {Polynomial(ring), Polynomial(ring), Polynomial(ring)},
                                                 {Polynomial(ring), Polynomial(ring), Polynomial(ring)}}};
  for (std::size_t f = 0; f < 4; ++f) {
    rows[f] = {wxyz[f].map_to(ring, at_st), wxyz[f].map_to(ring, at_at), wxyz[f].map_to(ring, at_ab)};
  }
  const auto& [w, x, y, z] = rows;
  // det[ξ−xω, η−yω, ζ−zω] = det[ξ,η,ζ] − x·det[ω,η,ζ] − y·det[ξ,ω,ζ] − z·det[ξ,η,ω]:
  // the terms with two ω columns vanish.
  const Polynomial divisor = (Polynomial::variable(ring, 0) - Polynomial::variable(ring, 2)) *
                             (Polynomial::variable(ring, 1) - Polynomial::variable(ring, 3));
  const std::array<Polynomial, 4> parts = {
      divide_exact(det3(x, y, z), divisor),
      divide_exact(-det3(w, y, z), divisor),
      divide_exact(-det3(x, w, z), divisor),
      divide_exact(-det3(x, y, w), divisor),
  };

  // Rows: s^i t^j, i < m, j < 2n. Columns: α^k β^l, k < 2m, l < n.
  const std::size_t size = static_cast<std::size_t>(2 * m * n);
  MatrixPencil pencil(size, 3);
  for (std::size_t part = 0; part < 4; ++part) {
    const Polynomial& delta = parts[part];
    for (std::size_t term = 0; term < delta.num_terms(); ++term) {
      const std::int32_t* e = ring->exponents(delta.monomial(term));
      if (e[0] >= m || e[1] >= 2 * n || e[2] >= 2 * m || e[3] >= n) {
        throw std::logic_error("dixon_pencil: the Dixon polynomial exceeds its bidegree");
      }
      const auto row = static_cast<std::size_t>(e[0] * 2 * n + e[1]);
      const auto col = static_cast<std::size_t>(e[2] * n + e[3]);
      pencil.at(part, row, col) = to_integer(delta.coefficient(term));
    }
  }
  return pencil;
}

}  // namespace implicitizer
