#include "implicitizer/implicitization/verify.hpp"

#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <array>

#include "implicitizer/modular/prime_sequence.hpp"
#include "implicitizer/polynomial/gcd.hpp"

namespace implicitizer {

bool substitutes_to_zero_symbolic(const Polynomial& implicit, const Parametrization& parametrization,
                                  const Budget& budget) {
  const RingPtr& params = parametrization.parameter_ring;
  const Ring& space = *implicit.ring();
  // Clearing denominators: F(p1/q1, p2/q2, p3/q3)·q1^a·q2^b·q3^c is a polynomial, and
  // it vanishes exactly when F vanishes on the image (the q_i are non-zero).
  std::array<std::int32_t, 3> degree{};
  for (std::size_t v = 0; v < 3; ++v) degree[v] = std::max(0, implicit.degree_in(v));
  // Power tables: numerator^e and denominator^e for each coordinate.
  std::array<std::vector<Polynomial>, 3> num_powers, den_powers;
  for (std::size_t v = 0; v < 3; ++v) {
    const auto& c = parametrization.coordinates[v];
    num_powers[v].push_back(Polynomial::constant(params, Rational(1)));
    den_powers[v].push_back(Polynomial::constant(params, Rational(1)));
    for (std::int32_t e = 1; e <= degree[v]; ++e) {
      num_powers[v].push_back(num_powers[v].back().multiply(c.numerator(), budget));
      den_powers[v].push_back(den_powers[v].back().multiply(c.denominator(), budget));
    }
  }
  std::vector<Polynomial> terms;
  terms.reserve(implicit.num_terms());
  for (std::size_t t = 0; t < implicit.num_terms(); ++t) {
    const std::int32_t* e = space.exponents(implicit.monomial(t));
    Polynomial term = Polynomial::constant(params, implicit.coefficient(t));
    for (std::size_t v = 0; v < 3; ++v) {
      term = term.multiply(num_powers[v][e[v]], budget);
      term = term.multiply(den_powers[v][degree[v] - e[v]], budget);
    }
    terms.push_back(std::move(term));
    budget.check("verification");
  }
  return sum_of(params, std::move(terms)).is_zero();
}

namespace {

// Grids larger than this are left to the symbolic check (a 3-parameter map of
// high degree); the surfaces of ../shared/bench need at most 3025 points.
constexpr double kMaxGridPoints = 4e6;

Integer integer_of(const Rational& q) {
  const mpq_class v = to_mpq(q);
  return v.get_num();
}

// ‖p‖₁ for an integer polynomial.
Integer norm1(const Polynomial& p) {
  Integer sum = 0;
  for (std::size_t t = 0; t < p.num_terms(); ++t) sum += abs(integer_of(p.coefficient(t)));
  return sum;
}

// The values of p modulo `mod` at the point `u` (residues of the parameters).
mp_limb_t evaluate_mod(const Polynomial& p, const std::vector<std::vector<mp_limb_t>>& powers, nmod_t mod,
                       const std::vector<mp_limb_t>& residues) {
  const Ring& ring = *p.ring();
  const std::size_t k = ring.num_variables();
  mp_limb_t sum = 0;
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    const std::int32_t* e = ring.exponents(p.monomial(t));
    mp_limb_t term = residues[t];
    for (std::size_t v = 0; v < k; ++v) term = nmod_mul(term, powers[v][static_cast<std::size_t>(e[v])], mod);
    sum = nmod_add(sum, term, mod);
  }
  return sum;
}

std::vector<mp_limb_t> residues_of(const Polynomial& p, mp_limb_t prime) {
  std::vector<mp_limb_t> out(p.num_terms());
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    const Integer c = integer_of(p.coefficient(t));
    out[t] = mpz_fdiv_ui(c.get_mpz_t(), prime);
  }
  return out;
}

}  // namespace

bool substitutes_to_zero(const Polynomial& implicit, const Parametrization& parametrization, const Budget& budget) {
  if (implicit.is_zero()) return true;
  const RingPtr& params = parametrization.parameter_ring;
  const std::size_t k = params->num_variables();
  const std::int32_t d = implicit.total_degree();

  // ω = lcm of the denominators, ξ_i = p_i·(ω / q_i); all scaled to integers (G only
  // changes by a non-zero constant).
  Polynomial w = Polynomial::constant(params, Rational(1));
  for (const auto& c : parametrization.coordinates) w = lcm(w, c.denominator());
  std::array<Polynomial, 4> wxyz = {w, w, w, w};
  for (std::size_t v = 0; v < 3; ++v) {
    const auto& c = parametrization.coordinates[v];
    wxyz[v + 1] = c.numerator() * divide_exact(w, c.denominator());
  }
  Integer denominator = 1;
  for (const auto& p : wxyz) {
    if (!p.is_zero()) {
      mpz_lcm(denominator.get_mpz_t(), denominator.get_mpz_t(), to_mpq(p.content()).get_den().get_mpz_t());
    }
  }
  for (auto& p : wxyz) p = p.scaled(to_rational(denominator));
  const Polynomial f = implicit.primitive_part();

  std::vector<std::int32_t> grid(k, 1);
  double points = 1;
  for (std::size_t j = 0; j < k; ++j) {
    std::int32_t m = 0;
    for (const auto& p : wxyz) m = std::max(m, p.degree_in(j));
    grid[j] = d * m + 1;
    points *= grid[j];
  }
  if (points > kMaxGridPoints) return substitutes_to_zero_symbolic(implicit, parametrization, budget);

  // B = Σ |f_α| ‖ξ‖^a ‖η‖^b ‖ζ‖^c ‖ω‖^(d−|α|) bounds every coefficient of G.
  std::array<Integer, 4> norms;
  for (std::size_t i = 0; i < 4; ++i) norms[i] = norm1(wxyz[i]);
  const Ring& space = *f.ring();
  Integer bound = 0;
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const std::int32_t* e = space.exponents(f.monomial(t));
    Integer term = abs(integer_of(f.coefficient(t)));
    Integer factor;
    mpz_pow_ui(factor.get_mpz_t(), norms[0].get_mpz_t(), static_cast<unsigned long>(d - e[0] - e[1] - e[2]));
    term *= factor;
    for (std::size_t v = 0; v < 3; ++v) {
      mpz_pow_ui(factor.get_mpz_t(), norms[v + 1].get_mpz_t(), static_cast<unsigned long>(e[v]));
      term *= factor;
    }
    bound += term;
  }
  const std::size_t needed_bits = mpz_sizeinbase(bound.get_mpz_t(), 2) + 1;

  PrimeSequence primes(/*skip=*/3);
  std::size_t modulus_bits = 0;
  std::vector<mp_limb_t> u(k);
  std::vector<std::vector<mp_limb_t>> powers(k);
  while (modulus_bits <= needed_bits) {
    const mp_limb_t p = primes.next();
    modulus_bits += FLINT_BIT_COUNT(p) - 1;  // p > 2^(bits-1): a lower bound on the product
    nmod_t mod;
    nmod_init(&mod, p);
    std::array<std::vector<mp_limb_t>, 4> coefficient_residues;
    for (std::size_t i = 0; i < 4; ++i) coefficient_residues[i] = residues_of(wxyz[i], p);
    const std::vector<mp_limb_t> f_residues = residues_of(f, p);
    std::vector<std::size_t> index(k, 0);
    for (bool more = true; more;) {
      // The grid point: parameter j takes the value index[j] (distinct modulo p).
      for (std::size_t j = 0; j < k; ++j) {
        const std::int32_t top = std::max({wxyz[0].degree_in(j), wxyz[1].degree_in(j), wxyz[2].degree_in(j),
                                           wxyz[3].degree_in(j), 0});
        powers[j].assign(static_cast<std::size_t>(top) + 1, 1);
        for (std::size_t e = 1; e < powers[j].size(); ++e) powers[j][e] = nmod_mul(powers[j][e - 1], index[j], mod);
      }
      std::array<std::vector<mp_limb_t>, 4> value_powers;
      for (std::size_t i = 0; i < 4; ++i) {
        const mp_limb_t value = evaluate_mod(wxyz[i], powers, mod, coefficient_residues[i]);
        value_powers[i].assign(static_cast<std::size_t>(d) + 1, 1);
        for (std::size_t e = 1; e <= static_cast<std::size_t>(d); ++e) {
          value_powers[i][e] = nmod_mul(value_powers[i][e - 1], value, mod);
        }
      }
      mp_limb_t g = 0;
      for (std::size_t t = 0; t < f.num_terms(); ++t) {
        const std::int32_t* e = space.exponents(f.monomial(t));
        mp_limb_t term = nmod_mul(f_residues[t], value_powers[0][static_cast<std::size_t>(d - e[0] - e[1] - e[2])], mod);
        for (std::size_t v = 0; v < 3; ++v) term = nmod_mul(term, value_powers[v + 1][static_cast<std::size_t>(e[v])], mod);
        g = nmod_add(g, term, mod);
      }
      if (g != 0) return false;  // G mod p ≠ 0, so G ≠ 0
      // Next grid point (last parameter fastest); a budget check per grid line.
      more = false;
      for (std::size_t j = k; j-- > 0;) {
        if (++index[j] < static_cast<std::size_t>(grid[j])) {
          more = true;
          break;
        }
        index[j] = 0;
        if (j == k - 1) budget.check("verification");
      }
    }
  }
  return true;
}

}  // namespace implicitizer
