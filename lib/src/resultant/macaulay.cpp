#include "implicitizer/resultant/macaulay.hpp"

#include <map>
#include <stdexcept>

namespace implicitizer {

namespace {

// A monomial r^a s^b t^c of the fixed degree d, identified by (b, c).
struct Exponent {
  std::int32_t r, s, t;
};

}  // namespace

MacaulayPencil macaulay_pencil(const std::array<Polynomial, 4>& wxyz, std::int32_t n) {
  if (n < 1) throw std::invalid_argument("macaulay_pencil: the degree must be at least 1");
  for (const auto& p : wxyz) {
    if (p.ring()->num_variables() != 2) throw std::invalid_argument("macaulay_pencil: two parameters expected");
    if (p.total_degree() > n) throw std::invalid_argument("macaulay_pencil: a polynomial exceeds the degree");
  }
  const std::int32_t d = 3 * n - 2;
  // The monomials of degree d, in a fixed order, and their indices.
  std::vector<Exponent> monomials;
  std::map<std::pair<std::int32_t, std::int32_t>, std::size_t> index;  // (s, t) exponents → index
  for (std::int32_t s = 0; s <= d; ++s) {
    for (std::int32_t t = 0; s + t <= d; ++t) {
      index[{s, t}] = monomials.size();
      monomials.push_back({d - s - t, s, t});
    }
  }
  const std::size_t size = monomials.size();
  MacaulayPencil result{MatrixPencil(size, 3), {}};

  const Ring& params = *wxyz[0].ring();
  for (std::size_t row = 0; row < size; ++row) {
    const Exponent mu = monomials[row];
    const bool by_r = mu.r >= n, by_s = mu.s >= n, by_t = mu.t >= n;
    if (static_cast<int>(by_r) + static_cast<int>(by_s) + static_cast<int>(by_t) >= 2) {
      result.extraneous.push_back(row);
    }
    // f_i = numerator_i − u_i·ω, u_i the i-th space variable (pencil part i).
    const std::size_t i = by_r ? 1 : by_s ? 2 : 3;
    if (!by_r && !by_s && !by_t) throw std::logic_error("macaulay_pencil: a monomial divisible by no x_i^n");
    // The shift μ / x_i^n in (s, t) exponents (r's exponent follows from the degree).
    const std::int32_t shift_s = mu.s - (i == 2 ? n : 0);
    const std::int32_t shift_t = mu.t - (i == 3 ? n : 0);
    auto place = [&](const Polynomial& f, std::size_t part, bool negate) {
      for (std::size_t term = 0; term < f.num_terms(); ++term) {
        const std::int32_t* e = params.exponents(f.monomial(term));
        // The homogenized term r^(n-a-b) s^a t^b times the shift lands on (s, t) =
        // (a + shift_s, b + shift_t) in degree d.
        const auto col = index.at({e[0] + shift_s, e[1] + shift_t});
        Integer c = to_integer(f.coefficient(term));
        result.matrix.at(part, row, col) = negate ? Integer(-c) : c;
      }
    };
    place(wxyz[i], 0, false);
    place(wxyz[0], i, true);
  }
  return result;
}

}  // namespace implicitizer
