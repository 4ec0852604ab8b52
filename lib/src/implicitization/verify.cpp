#include "implicitizer/implicitization/verify.hpp"

#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <stdexcept>

#include "implicitizer/modular/prime_sequence.hpp"

namespace implicitizer {

namespace {

void check_rings(const Polynomial& implicit, const Parametrization& parametrization) {
  if (implicit.ring()->num_variables() != parametrization.coordinates.size()) {
    throw std::invalid_argument("substitutes_to_zero: one variable per coordinate expected");
  }
}

}  // namespace

bool substitutes_to_zero_symbolic(const Polynomial& implicit, const Parametrization& parametrization,
                                  const Budget& budget) {
  check_rings(implicit, parametrization);
  const RingPtr& params = parametrization.parameter_ring;
  const Ring& space = *implicit.ring();
  const std::size_t n = parametrization.coordinates.size();
  // Clearing denominators: F(p1/q1, p2/q2, p3/q3)·q1^a·q2^b·q3^c is a polynomial, and
  // it vanishes exactly when F vanishes on the image (the q_i are non-zero).
  std::vector<std::int32_t> degree(n);
  for (std::size_t v = 0; v < n; ++v) degree[v] = std::max(0, implicit.degree_in(v));
  // Power tables: numerator^e and denominator^e for each coordinate.
  std::vector<std::vector<Polynomial>> num_powers(n), den_powers(n);
  for (std::size_t v = 0; v < n; ++v) {
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
    for (std::size_t v = 0; v < n; ++v) {
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

// ‖p‖₁ for an integer polynomial.
Integer norm1(const Polynomial& p) {
  Integer sum = 0;
  for (std::size_t t = 0; t < p.num_terms(); ++t) sum += abs(to_integer(p.coefficient(t)));
  return sum;
}

// The coefficients of an integer polynomial modulo `prime`: its content's residue
// times those of its primitive coefficients (no rational is built per term).
std::vector<mp_limb_t> residues_of(const Polynomial& p, mp_limb_t prime) {
  nmod_t mod;
  nmod_init(&mod, prime);
  const mp_limb_t content = mpz_fdiv_ui(to_integer(p.content()).get_mpz_t(), prime);
  std::vector<mp_limb_t> out(p.num_terms());
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    out[t] = nmod_mul(mpz_fdiv_ui(p.integer_coefficients()[t].get_mpz_t(), prime), content, mod);
  }
  return out;
}

// p modulo `mod` at the point whose coordinate powers are `powers` (powers[v][e]).
mp_limb_t evaluate_mod(const Polynomial& p, const std::vector<mp_limb_t>& residues,
                       const std::vector<std::vector<mp_limb_t>>& powers, nmod_t mod) {
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

}  // namespace

bool substitutes_to_zero(const Polynomial& implicit, const Parametrization& parametrization, const Budget& budget) {
  check_rings(implicit, parametrization);
  if (implicit.is_zero()) return true;
  // ω = lcm of the denominators and ξ_v = p_v·(ω / q_v), in `forms` as ω, ξ_1, …, ξ_n;
  // all scaled to integers (G only changes by a non-zero constant).
  std::vector<Polynomial> forms = common_denominator_form(parametrization, budget);
  scale_to_integers(forms);
  return substitutes_to_zero(implicit, parametrization, forms, budget);
}

namespace {

// The grid of the header's argument: d·m_j + 1 points along parameter j, of which
// only those whose indices sum to at most d·N are used (N the largest total degree
// among the forms): G's exponents lie in that lower set, and its points determine G.
struct SubstitutionGrid {
  std::vector<std::int32_t> degrees;  ///< m_j: the largest degree in parameter j among the forms
  std::vector<std::size_t> sides;     ///< d·m_j + 1
  std::size_t index_sum_bound = 0;    ///< d·N
  double points = 1;                  ///< ∏ sides, the whole box
};

SubstitutionGrid substitution_grid(std::span<const Polynomial> forms, std::size_t k, std::int32_t d) {
  SubstitutionGrid grid;
  grid.degrees.assign(k, 0);
  grid.sides.resize(k);
  std::int32_t total = 0;
  for (const auto& p : forms) total = std::max(total, p.total_degree());
  grid.index_sum_bound = static_cast<std::size_t>(d) * static_cast<std::size_t>(total);
  for (std::size_t j = 0; j < k; ++j) {
    for (const auto& p : forms) grid.degrees[j] = std::max(grid.degrees[j], p.degree_in(j));
    grid.sides[j] = static_cast<std::size_t>(d * grid.degrees[j]) + 1;
    grid.points *= static_cast<double>(grid.sides[j]);
  }
  return grid;
}

// B = Σ |f_α|·‖ω‖^(d−|α|)·Π ‖ξ_v‖^α_v bounds every coefficient of G.
Integer coefficient_bound(const Polynomial& f, std::span<const Polynomial> forms, std::int32_t d) {
  std::vector<Integer> norms;
  for (const auto& p : forms) norms.push_back(norm1(p));
  const Ring& space = *f.ring();
  const std::size_t n = space.num_variables();
  Integer bound = 0;
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const std::int32_t* e = space.exponents(f.monomial(t));
    std::int32_t degree = 0;
    for (std::size_t v = 0; v < n; ++v) degree += e[v];
    Integer term = abs(to_integer(f.coefficient(t)));
    Integer factor;
    mpz_pow_ui(factor.get_mpz_t(), norms[0].get_mpz_t(), static_cast<unsigned long>(d - degree));
    term *= factor;
    for (std::size_t v = 0; v < n; ++v) {
      mpz_pow_ui(factor.get_mpz_t(), norms[v + 1].get_mpz_t(), static_cast<unsigned long>(e[v]));
      term *= factor;
    }
    bound += term;
  }
  return bound;
}

// G = ω^d·F(ξ/ω) modulo one prime, evaluated at grid points without expanding it.
class SubstitutionModulo {
 public:
  SubstitutionModulo(const Polynomial& f, std::span<const Polynomial> forms, const SubstitutionGrid& grid,
                     mp_limb_t prime)
      : f_(f), forms_(forms), grid_(grid), d_(f.total_degree()), f_residues_(residues_of(f, prime)) {
    nmod_init(&mod_, prime);
    for (const auto& form : forms) form_residues_.push_back(residues_of(form, prime));
    parameter_powers_.resize(grid.degrees.size());
    value_powers_.assign(forms.size(), std::vector<mp_limb_t>(static_cast<std::size_t>(d_) + 1));
  }

  // G mod p at the grid point `index` (parameter j taking the value index[j]).
  mp_limb_t value_at(const std::vector<std::size_t>& index) {
    for (std::size_t j = 0; j < index.size(); ++j) {
      parameter_powers_[j].assign(static_cast<std::size_t>(grid_.degrees[j]) + 1, 1);
      for (std::size_t e = 1; e < parameter_powers_[j].size(); ++e) {
        parameter_powers_[j][e] = nmod_mul(parameter_powers_[j][e - 1], index[j], mod_);
      }
    }
    for (std::size_t i = 0; i < forms_.size(); ++i) {
      const mp_limb_t value = evaluate_mod(forms_[i], form_residues_[i], parameter_powers_, mod_);
      value_powers_[i][0] = 1;
      for (std::size_t e = 1; e <= static_cast<std::size_t>(d_); ++e) {
        value_powers_[i][e] = nmod_mul(value_powers_[i][e - 1], value, mod_);
      }
    }
    const Ring& space = *f_.ring();
    const std::size_t n = space.num_variables();
    mp_limb_t g = 0;
    for (std::size_t t = 0; t < f_.num_terms(); ++t) {
      const std::int32_t* e = space.exponents(f_.monomial(t));
      std::int32_t degree = 0;
      mp_limb_t term = f_residues_[t];
      for (std::size_t v = 0; v < n; ++v) {
        term = nmod_mul(term, value_powers_[v + 1][static_cast<std::size_t>(e[v])], mod_);
        degree += e[v];
      }
      term = nmod_mul(term, value_powers_[0][static_cast<std::size_t>(d_ - degree)], mod_);
      g = nmod_add(g, term, mod_);
    }
    return g;
  }

 private:
  const Polynomial& f_;
  std::span<const Polynomial> forms_;
  const SubstitutionGrid& grid_;
  std::int32_t d_;
  nmod_t mod_;
  std::vector<mp_limb_t> f_residues_;
  std::vector<std::vector<mp_limb_t>> form_residues_;
  std::vector<std::vector<mp_limb_t>> parameter_powers_;  // [j][e]: the value of parameter j to the e
  std::vector<std::vector<mp_limb_t>> value_powers_;      // [i][e]: form i's value to the e
};

// Whether G ≡ 0 modulo the prime of `g`: it vanishes at every point of the grid's lower
// set. Parameter j takes the values 0, 1, …, sides[j] − 1 (distinct modulo p).
bool vanishes_on_grid(SubstitutionModulo& g, const SubstitutionGrid& grid, const Budget& budget) {
  const std::size_t k = grid.sides.size();
  std::vector<std::size_t> index(k, 0);
  std::size_t index_sum = 0;
  for (bool more = true; more;) {
    // Outside the lower set there is nothing to evaluate.
    if (index_sum <= grid.index_sum_bound && g.value_at(index) != 0) return false;
    // The next grid point (last parameter fastest); a budget check per grid line.
    more = false;
    for (std::size_t j = k; j-- > 0;) {
      if (++index[j] < grid.sides[j]) {
        ++index_sum;
        more = true;
        break;
      }
      index_sum -= index[j] - 1;
      index[j] = 0;
      if (j == k - 1) budget.check("verification");
    }
  }
  return true;
}

}  // namespace

bool substitutes_to_zero(const Polynomial& implicit, const Parametrization& parametrization,
                         std::span<const Polynomial> forms, const Budget& budget) {
  check_rings(implicit, parametrization);
  if (implicit.is_zero()) return true;
  const std::size_t k = parametrization.parameter_ring->num_variables();
  const std::size_t n = parametrization.coordinates.size();
  if (forms.size() != n + 1) throw std::invalid_argument("substitutes_to_zero: ω and one form per coordinate expected");
  const Polynomial f = implicit.primitive_part();
  const SubstitutionGrid grid = substitution_grid(forms, k, f.total_degree());
  if (grid.points > kMaxGridPoints) return substitutes_to_zero_symbolic(implicit, parametrization, budget);

  // G = 0 exactly when G ≡ 0 modulo primes whose product exceeds 2B.
  const std::size_t needed_bits = mpz_sizeinbase(coefficient_bound(f, forms, f.total_degree()).get_mpz_t(), 2) + 1;
  PrimeSequence primes(/*skip=*/3);
  for (std::size_t modulus_bits = 0; modulus_bits <= needed_bits;) {
    const mp_limb_t p = primes.next();
    modulus_bits += FLINT_BIT_COUNT(p) - 1;  // p > 2^(bits−1): a lower bound on the product's size
    SubstitutionModulo g(f, forms, grid, p);
    if (!vanishes_on_grid(g, grid, budget)) return false;  // G mod p ≠ 0, so G ≠ 0
  }
  return true;
}

}  // namespace implicitizer
