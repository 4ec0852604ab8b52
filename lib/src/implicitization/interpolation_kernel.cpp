#include "interpolation_kernel.hpp"

#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/verify.hpp"
#include "implicitizer/modular/flint_handles.hpp"
#include "implicitizer/modular/prime_sequence.hpp"

namespace implicitizer {

namespace {

// Rows beyond the number of columns: C(d + n, n) points in general position already
// determine the kernel; the extra ones absorb points that repeat an image point.
constexpr std::size_t kExtraRows = 8;

// `p`, whose coefficients are integers (precondition), as plain data.
IntegerPolynomial integer_polynomial(const Polynomial& p) {
  IntegerPolynomial out;
  const Ring& ring = *p.ring();
  const std::size_t k = ring.num_variables();
  const Integer content = p.is_zero() ? Integer(0) : to_integer(p.content());
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    out.coefficients.push_back(content * p.integer_coefficients()[t]);
    const std::int32_t* e = ring.exponents(p.monomial(t));
    out.exponents.insert(out.exponents.end(), e, e + k);
  }
  return out;
}

// ∂p/∂(variable j) of `p` in k variables, on the plain data (terms in p's order;
// only evaluated, so no order is needed): cheaper than Polynomial::derivative, which
// on a small surface cost a tenth of the route.
IntegerPolynomial partial_derivative(const IntegerPolynomial& p, std::size_t k, std::size_t j) {
  IntegerPolynomial out;
  for (std::size_t t = 0; t < p.coefficients.size(); ++t) {
    const std::int32_t* e = p.exponents.data() + t * k;
    if (e[j] == 0) continue;
    out.coefficients.push_back(p.coefficients[t] * e[j]);
    out.exponents.insert(out.exponents.end(), e, e + k);
    --out.exponents[out.exponents.size() - k + j];
  }
  return out;
}

// The kernel of a matrix in reduced row echelon form (FLINT's nmod_mat_rref) with
// one free column f: v_f = 1 and, for the pivot c of row r, v_c = −R[r][f] / R[r][c]
// (a reduced row holds only its pivot and free entries).
std::vector<mp_limb_t> kernel_vector_of_rref(const nmod_mat_struct* matrix, std::size_t rank, std::size_t columns,
                                             nmod_t mod) {
  std::vector<std::size_t> pivots(rank);
  std::vector<char> is_pivot(columns, 0);
  for (std::size_t r = 0, c = 0; r < rank; ++r) {
    while (nmod_mat_entry(matrix, r, c) == 0) ++c;
    pivots[r] = c;
    is_pivot[c] = 1;
  }
  const std::size_t free_column =
      static_cast<std::size_t>(std::find(is_pivot.begin(), is_pivot.end(), 0) - is_pivot.begin());
  std::vector<mp_limb_t> vector(columns, 0);
  vector[free_column] = 1;
  for (std::size_t r = 0; r < rank; ++r) {
    const mp_limb_t entry = nmod_mat_entry(matrix, r, free_column);
    const mp_limb_t pivot = nmod_mat_entry(matrix, r, pivots[r]);
    vector[pivots[r]] = nmod_neg(nmod_mul(entry, n_invmod(pivot, mod.n), mod), mod);
  }
  return vector;
}

// Whether every (rank)-minor of the Jacobian numerators ∂ξ_i/∂a_j·ω − ξ_i·∂ω/∂a_j
// is the zero polynomial, decided exactly (rank 1 or 2: n ≤ 3).
bool jacobian_minors_vanish(const MapForms& m, std::size_t rank, const Budget& budget) {
  const std::size_t k = m.parameters;
  const std::size_t n = m.coordinates;
  const Polynomial& omega = m.exact[0];
  std::vector<std::vector<Polynomial>> entries(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < k; ++j) {
      entries[i].push_back(m.exact[i + 1].derivative(j).multiply(omega, budget) -
                           m.exact[i + 1].multiply(omega.derivative(j), budget));
    }
  }
  if (rank == 1) {
    for (const auto& row : entries) {
      for (const auto& e : row) {
        if (!e.is_zero()) return false;
      }
    }
    return true;
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t i2 = i + 1; i2 < n; ++i2) {
      for (std::size_t j = 0; j < k; ++j) {
        for (std::size_t j2 = j + 1; j2 < k; ++j2) {
          budget.check("interpolation (Jacobian)");
          const Polynomial minor =
              entries[i][j].multiply(entries[i2][j2], budget) - entries[i][j2].multiply(entries[i2][j], budget);
          if (!minor.is_zero()) return false;
        }
      }
    }
  }
  return true;
}

}  // namespace

MapForms map_forms(const Parametrization& p, const Budget& budget) {
  MapForms m;
  m.parameters = p.parameter_ring->num_variables();
  m.coordinates = p.coordinates.size();
  m.exact = common_denominator_form(p, budget);
  scale_to_integers(m.exact);
  for (const Polynomial& f : m.exact) {
    m.forms.push_back(integer_polynomial(f));
    std::vector<IntegerPolynomial> row;
    for (std::size_t j = 0; j < m.parameters; ++j) row.push_back(partial_derivative(m.forms.back(), m.parameters, j));
    m.partials.push_back(std::move(row));
  }
  return m;
}

// C(d + n, n): the number of monomials of degree ≤ d in n variables, as a double so
// that bounds in the millions do not overflow.
double monomial_count(std::size_t n, std::int64_t d) {
  if (d < 0) return 0;
  double count = 1;
  for (std::size_t i = 1; i <= n; ++i) {
    count = count * static_cast<double>(d + static_cast<std::int64_t>(i)) / static_cast<double>(i);
  }
  return std::round(count);
}

MonomialBasis monomial_basis(std::size_t n, std::int32_t d) {
  std::vector<std::int32_t> all;
  std::vector<std::int32_t> e(n, 0);
  // Every exponent vector with entries summing to at most d, odometer style.
  for (bool more = true; more;) {
    all.insert(all.end(), e.begin(), e.end());
    more = false;
    for (std::size_t v = 0; v < n; ++v) {
      std::int32_t sum = 0;
      for (std::int32_t x : e) sum += x;
      if (sum < d) {
        ++e[v];
        more = true;
        break;
      }
      e[v] = 0;
    }
  }
  return monomial_basis_of(n, all);
}

MonomialBasis monomial_basis_of(std::size_t n, const std::vector<std::int32_t>& exponents) {
  const RingPtr ring = implicit_ring(n);
  const std::size_t w = ring->monomial_size();
  const std::size_t count = exponents.size() / n;
  std::vector<std::int32_t> encoded(count * w);
  for (std::size_t i = 0; i < count; ++i) ring->encode(exponents.data() + i * n, encoded.data() + i * w);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return ring->compare(encoded.data() + a * w, encoded.data() + b * w) > 0;
  });
  MonomialBasis basis;
  basis.variables = n;
  for (std::size_t i : order) {
    const std::int32_t* e = exponents.data() + i * n;
    basis.exponents.insert(basis.exponents.end(), e, e + n);
    std::int32_t degree = 0;
    for (std::size_t v = 0; v < n; ++v) degree += e[v];
    basis.degree = std::max(basis.degree, degree);
  }
  return basis;
}

// The kernel modulo p of the matrix whose rows are the monomials of `basis` at
// points ξ(a)/ω(a) of the image, a random with ω(a) ≢ 0 and pairwise distinct.
// Checks `budget` at every row; FLINT's row reduction itself cannot be interrupted.
KernelImage kernel_modulo(const MapForms& forms, const MonomialBasis& basis, mp_limb_t p, std::uint64_t seed,
                          const Budget& budget) {
  KernelImage out;
  out.prime = p;
  out.degree = basis.degree;
  nmod_t mod;
  nmod_init(&mod, p);
  ModularMap map(forms, mod, /*with_partials=*/false);
  const std::size_t k = forms.parameters;
  const std::size_t n = forms.coordinates;
  const std::size_t columns = basis.size();
  out.rows = columns + kExtraRows;
  NmodMatrix matrix(out.rows, columns, p);

  ResidueStream stream(seed ^ (p * 0x9e3779b97f4a7c15ULL) ^ static_cast<std::uint64_t>(basis.degree));
  std::set<std::vector<mp_limb_t>> used;
  std::vector<mp_limb_t> a(k), x(n);
  PowerTable powers(std::vector<std::int32_t>(n, basis.degree));
  // Tiny primes (tests) may not have enough points: give up after many misses.
  const std::size_t max_attempts = 4 * out.rows + 64;
  std::size_t attempts = 0;
  for (std::size_t row = 0; row < out.rows;) {
    if (attempts++ >= max_attempts) {
      out.enough_points = false;
      return out;
    }
    for (auto& v : a) v = stream.next(p);
    if (!used.insert(a).second) continue;
    if (!map.image(a, x)) {
      ++out.rejected_points;
      continue;
    }
    budget.check("interpolation (evaluation)");
    powers.fill(x, mod);
    mp_limb_t* entries = nmod_mat_entry_ptr(matrix.get(), static_cast<slong>(row), 0);
    for (std::size_t c = 0; c < columns; ++c) {
      const std::int32_t* e = basis.at(c);
      mp_limb_t value = powers.at(0, e[0]);
      for (std::size_t v = 1; v < n; ++v) value = nmod_mul(value, powers.at(v, e[v]), mod);
      entries[c] = value;
    }
    ++row;
  }

  const std::size_t rank = static_cast<std::size_t>(nmod_mat_rref(matrix.get()));
  out.nullity = columns - rank;
  if (out.nullity != 1) return out;
  out.vector = kernel_vector_of_rref(matrix.get(), rank, columns, mod);
  out.lead = static_cast<std::size_t>(
      std::find_if(out.vector.begin(), out.vector.end(), [](mp_limb_t v) { return v != 0; }) - out.vector.begin());
  const mp_limb_t inverse = n_invmod(out.vector[out.lead], p);
  _nmod_vec_scalar_mul_nmod(out.vector.data(), out.vector.data(), static_cast<slong>(columns), inverse, mod);
  return out;
}

// The degree e with C(d − e + n, n) = nullity: a kernel at degree d ≥ e of the
// equation's multiples F·(monomials of degree ≤ d − e). nullopt when no such e ≥ 1.
std::optional<std::int32_t> degree_from_nullity(std::int32_t d, std::size_t nullity, std::size_t n) {
  for (std::int32_t j = 0; j < d; ++j) {
    const double count = monomial_count(n, j);
    if (count == static_cast<double>(nullity)) return d - j;
    if (count > static_cast<double>(nullity)) break;
  }
  return std::nullopt;
}

// Returns when the image has dimension at least n − 1; throws NoSingleEquation when
// it fills space or is smaller. The rank of the Jacobian at a point modulo a prime is
// at most its rank over ℚ (a minor non-zero mod p is non-zero), which in
// characteristic 0 is the image's dimension at a general point; only a deficient
// rank needs the exact minors.
void check_image_dimension(const MapForms& m, std::uint64_t seed, const Budget& budget) {
  const std::size_t k = m.parameters;
  const std::size_t n = m.coordinates;
  const std::string kind = n == 3 ? "surface" : "curve";
  const std::string not_generated =
      "; method interpolation does not compute the generators of its ideal (method groebner lists them)";
  if (k + 1 < n) {
    throw NoSingleEquation("no single implicit equation: " + std::to_string(k) + " parameter" + (k == 1 ? "" : "s") +
                               " cannot give a " + kind + " (the image is a curve or a point)" + not_generated,
                           {});
  }
  // A point where ω ≢ 0: a few tries per prime, and another prime when ω's scaled
  // coefficients are all divisible by this one (an input can have it as a factor).
  PrimeSequence primes(/*skip=*/11);
  ResidueStream stream(seed ^ 0x6a09e667f3bcc909ULL);
  std::vector<mp_limb_t> a(k);
  std::optional<std::size_t> rank;
  for (int prime = 0; prime < 8 && !rank; ++prime) {
    const mp_limb_t p = primes.next();
    nmod_t mod;
    nmod_init(&mod, p);
    ModularMap map(m, mod, /*with_partials=*/true);
    for (int attempt = 0; attempt < 8 && !rank; ++attempt) {
      for (auto& v : a) v = stream.next(p);
      rank = map.jacobian_rank(a);
    }
  }
  if (!rank) throw std::logic_error("interpolation: the common denominator vanishes at 64 random points");
  const std::string space = n == 3 ? "space" : "the plane";
  if (*rank == n) {
    throw NoSingleEquation(
        "no implicit equation: the image is dense in " + space + " (its Jacobian has rank " + std::to_string(n) + ")",
        {});
  }
  if (*rank + 1 == n || !jacobian_minors_vanish(m, n - 1, budget)) return;
  throw NoSingleEquation("no single implicit equation: the image is not a " + kind +
                             " (the Jacobian of the parametrization has rank below " + std::to_string(n - 1) +
                             " everywhere)" + not_generated,
                         {});
}

std::int64_t degree_bound_of(const MapForms& m) {
  const std::size_t k = m.parameters;
  const std::size_t n = m.coordinates;
  if (k + 1 < n) return 0;
  std::int64_t total = 0;
  std::vector<std::int64_t> partial(k, 0);
  for (const Polynomial& f : m.exact) {
    total = std::max<std::int64_t>(total, f.total_degree());
    for (std::size_t j = 0; j < k; ++j) partial[j] = std::max<std::int64_t>(partial[j], f.degree_in(j));
  }
  std::int64_t bound = 1;
  for (std::size_t i = 0; i + 1 < n; ++i) bound *= total;
  if (k == 2 && n == 3) bound = std::min(bound, 2 * partial[0] * partial[1]);
  return bound;
}

// The polynomial with `coefficients` on the columns of `basis`, in implicit_ring(n).
Polynomial polynomial_of(const MonomialBasis& basis, const std::vector<Integer>& coefficients) {
  const RingPtr ring = implicit_ring(basis.variables);
  const std::size_t w = ring->monomial_size();
  std::vector<Integer> terms;
  std::vector<std::int32_t> monomials;
  std::vector<std::int32_t> encoded(w);
  for (std::size_t c = 0; c < basis.size(); ++c) {
    if (coefficients[c] == 0) continue;
    terms.push_back(coefficients[c]);
    ring->encode(basis.at(c), encoded.data());
    monomials.insert(monomials.end(), encoded.begin(), encoded.end());
  }
  return Polynomial::from_terms(ring, Rational(1), std::move(terms), std::move(monomials)).primitive_part();
}

bool spans_kernel(const Polynomial& f, const MonomialBasis& basis, const KernelImage& image) {
  if (image.nullity != 1) return false;
  const std::size_t n = basis.variables;
  std::map<std::vector<std::int32_t>, std::size_t> column_of;
  for (std::size_t c = 0; c < basis.size(); ++c) {
    column_of.emplace(std::vector<std::int32_t>(basis.at(c), basis.at(c) + n), c);
  }
  std::vector<mp_limb_t> residues(basis.size(), 0);
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const auto it = column_of.find(f.exponents(t));
    if (it == column_of.end()) return false;
    residues[it->second] = mpz_fdiv_ui(to_integer(f.coefficient(t)).get_mpz_t(), image.prime);
  }
  if (residues[image.lead] == 0) return false;
  nmod_t mod;
  nmod_init(&mod, image.prime);
  const mp_limb_t inverse = n_invmod(residues[image.lead], image.prime);
  _nmod_vec_scalar_mul_nmod(residues.data(), residues.data(), static_cast<slong>(residues.size()), inverse, mod);
  return residues == image.vector;
}

bool CandidateVerifier::vanishes(Polynomial& candidate) {
  if (options_.tamper_candidate) options_.tamper_candidate(candidate);
  if (rejected_ && candidate == *rejected_) return false;  // the same wrong answer again
  if (substitutes_to_zero(candidate, parametrization_, forms_.exact, options_.budget)) return true;
  ++stats_.rejected_candidates;
  rejected_ = candidate;
  return false;
}

}  // namespace implicitizer
