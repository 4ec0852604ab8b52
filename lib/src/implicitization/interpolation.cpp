#include "implicitizer/implicitization/interpolation.hpp"

#include <flint/nmod_mat.h>
#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/verify.hpp"
#include "implicitizer/modular/crt_lift.hpp"
#include "implicitizer/modular/flint_handles.hpp"
#include "implicitizer/modular/one_per_thread.hpp"

namespace implicitizer {

namespace {

// The most primes computed at once (see batch_threads).
constexpr unsigned kMaxThreads = 4;

// Rows beyond the number of columns: C(d + n, n) points in general position already
// determine the kernel; the extra ones absorb points that repeat an image point.
constexpr std::size_t kExtraRows = 8;

// A bound whose matrix has at most this many columns (degree 4 in space, 7 in the
// plane) is taken at once, without the upward search: a 39×35 kernel costs about as
// much as the setup of the smaller ones below it, and it reads the degree from its
// nullity (tp_11_rational: one kernel instead of two; tri_quadratic: one instead of
// three).
constexpr double kDirectColumns = 36;

// Kernels of at least this many columns time the row reduction for the deadline's
// prediction (refuse_kernel_past_deadline); smaller ones are mostly evaluation and
// set-up, whose cost does not grow as the cube.
constexpr double kTimedColumns = 200;

// The lift of the normalized kernel vector (leading coefficient 1, so each entry is
// F_i / F_lead for the primitive equation F: the denominators all divide F_lead).
// A value is accepted only with 20 bits to spare, so that a residue that is not yet
// the image of a small rational is taken for one with probability about 2^-20; such
// a false value is refuted by the next prime, and the candidate is verified anyway.
constexpr CrtLiftParams kLiftParams{.margin_bits = 20, .shared_denominator = true};

// ---------------------------------------------------------------- the forms

// An integer polynomial as plain data. Threads read these concurrently, which they
// could not do with Polynomial: CGAL's rationals count references without atomics.
struct IntegerPolynomial {
  std::vector<Integer> coefficients;
  std::vector<std::int32_t> exponents;  // num_variables per term
};

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

// ω, ξ_1, …, ξ_n of common_denominator_form() scaled to integers (the map does not
// change), with their first derivatives for the Jacobian.
struct MapForms {
  std::size_t parameters = 0;                            // k
  std::size_t coordinates = 0;                           // n
  std::vector<Polynomial> exact;                         // ω, ξ_1, …, ξ_n
  std::vector<IntegerPolynomial> forms;                  // the same as plain data
  std::vector<std::vector<IntegerPolynomial>> partials;  // partials[i][j] = ∂(form i)/∂(parameter j)
};

MapForms map_forms(const Parametrization& p) {
  MapForms m;
  m.parameters = p.parameter_ring->num_variables();
  m.coordinates = p.coordinates.size();
  m.exact = common_denominator_form(p);
  scale_to_integers(m.exact);
  for (const Polynomial& f : m.exact) {
    m.forms.push_back(integer_polynomial(f));
    std::vector<IntegerPolynomial> row;
    for (std::size_t j = 0; j < m.parameters; ++j) row.push_back(partial_derivative(m.forms.back(), m.parameters, j));
    m.partials.push_back(std::move(row));
  }
  return m;
}

// ---------------------------------------------------------------- modulo a prime

// Powers a_j^e of the coordinates of a point, e ≤ top[j].
class PowerTable {
 public:
  explicit PowerTable(const std::vector<std::int32_t>& top) : powers_(top.size()) {
    for (std::size_t j = 0; j < top.size(); ++j) powers_[j].resize(static_cast<std::size_t>(top[j]) + 1);
  }
  void fill(const std::vector<mp_limb_t>& point, nmod_t mod) {
    for (std::size_t j = 0; j < powers_.size(); ++j) {
      auto& row = powers_[j];
      row[0] = 1;
      for (std::size_t e = 1; e < row.size(); ++e) row[e] = nmod_mul(row[e - 1], point[j], mod);
    }
  }
  mp_limb_t at(std::size_t j, std::int32_t e) const { return powers_[j][static_cast<std::size_t>(e)]; }

 private:
  std::vector<std::vector<mp_limb_t>> powers_;
};

// An IntegerPolynomial reduced modulo a prime.
class ModularPolynomial {
 public:
  ModularPolynomial(const IntegerPolynomial& p, std::size_t num_variables, nmod_t mod) : k_(num_variables), mod_(mod) {
    for (std::size_t t = 0; t < p.coefficients.size(); ++t) {
      const mp_limb_t c = mpz_fdiv_ui(p.coefficients[t].get_mpz_t(), mod.n);
      if (c == 0) continue;
      coefficients_.push_back(c);
      exponents_.insert(exponents_.end(), p.exponents.begin() + static_cast<std::ptrdiff_t>(t * k_),
                        p.exponents.begin() + static_cast<std::ptrdiff_t>((t + 1) * k_));
    }
  }
  // The largest exponent of each variable.
  void raise_top(std::vector<std::int32_t>& top) const {
    for (std::size_t t = 0; t < coefficients_.size(); ++t) {
      for (std::size_t j = 0; j < k_; ++j) top[j] = std::max(top[j], exponents_[t * k_ + j]);
    }
  }
  mp_limb_t evaluate(const PowerTable& powers) const {
    mp_limb_t sum = 0;
    for (std::size_t t = 0; t < coefficients_.size(); ++t) {
      mp_limb_t term = coefficients_[t];
      for (std::size_t j = 0; j < k_; ++j) term = nmod_mul(term, powers.at(j, exponents_[t * k_ + j]), mod_);
      sum = nmod_add(sum, term, mod_);
    }
    return sum;
  }

 private:
  std::size_t k_;
  nmod_t mod_;
  std::vector<mp_limb_t> coefficients_;
  std::vector<std::int32_t> exponents_;
};

// The parametrization modulo p: the image ξ(a)/ω(a) of a parameter point a, and
// optionally the Jacobian there.
class ModularMap {
 public:
  ModularMap(const MapForms& m, nmod_t mod, bool with_partials)
      : k_(m.parameters), n_(m.coordinates), mod_(mod), values_(n_ + 1) {
    std::vector<std::int32_t> top(k_, 0);
    for (std::size_t i = 0; i <= n_; ++i) {
      forms_.emplace_back(m.forms[i], k_, mod);
      forms_.back().raise_top(top);
      if (with_partials) {
        for (std::size_t j = 0; j < k_; ++j) {
          partials_.emplace_back(m.partials[i][j], k_, mod);
          partials_.back().raise_top(top);
        }
      }
    }
    table_.emplace(top);
  }

  // Sets x to ξ(a)/ω(a); false (x unchanged) when ω(a) ≡ 0 mod p.
  bool image(const std::vector<mp_limb_t>& a, std::vector<mp_limb_t>& x) {
    if (!evaluate_forms(a)) return false;
    const mp_limb_t inverse = n_invmod(values_[0], mod_.n);
    for (std::size_t i = 0; i < n_; ++i) x[i] = nmod_mul(values_[i + 1], inverse, mod_);
    return true;
  }

  // The rank modulo p of the Jacobian of ξ/ω at a, from its numerators
  // ∂ξ_i/∂a_j·ω − ξ_i·∂ω/∂a_j (the Jacobian times ω², the same rank); nullopt when
  // ω(a) ≡ 0. Precondition: constructed with_partials.
  std::optional<std::size_t> jacobian_rank(const std::vector<mp_limb_t>& a) {
    if (!evaluate_forms(a)) return std::nullopt;
    if (k_ == 0) return 0;
    NmodMatrix j(n_, k_, mod_.n);
    for (std::size_t i = 0; i < n_; ++i) {
      for (std::size_t v = 0; v < k_; ++v) {
        const mp_limb_t d_xi = partials_[(i + 1) * k_ + v].evaluate(*table_);
        const mp_limb_t d_omega = partials_[v].evaluate(*table_);
        nmod_mat_entry(j.get(), i, v) =
            nmod_sub(nmod_mul(d_xi, values_[0], mod_), nmod_mul(values_[i + 1], d_omega, mod_), mod_);
      }
    }
    return static_cast<std::size_t>(nmod_mat_rank(j.get()));
  }

 private:
  bool evaluate_forms(const std::vector<mp_limb_t>& a) {
    table_->fill(a, mod_);
    values_[0] = forms_[0].evaluate(*table_);
    if (values_[0] == 0) return false;
    for (std::size_t i = 1; i <= n_; ++i) values_[i] = forms_[i].evaluate(*table_);
    return true;
  }

  std::size_t k_;
  std::size_t n_;
  nmod_t mod_;
  std::vector<ModularPolynomial> forms_;
  std::vector<ModularPolynomial> partials_;  // (form i, parameter j) at i·k + j
  std::optional<PowerTable> table_;
  std::vector<mp_limb_t> values_;  // ω(a), ξ_1(a), …
};

// ---------------------------------------------------------------- the matrix

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

// The monomials of degree ≤ d in n variables in decreasing grevlex (x > y > z), the
// contract's order: the columns of the evaluation matrix, so that the first non-zero
// entry of a kernel vector is the leading term of its polynomial.
struct MonomialBasis {
  std::int32_t degree = 0;
  std::size_t variables = 0;
  std::vector<std::int32_t> exponents;  // `variables` per monomial
  std::size_t size() const { return exponents.size() / variables; }
  const std::int32_t* at(std::size_t column) const { return exponents.data() + column * variables; }
};

MonomialBasis monomial_basis(std::size_t n, std::int32_t d) {
  const RingPtr ring = implicit_ring(n);
  const std::size_t w = ring->monomial_size();
  std::vector<std::vector<std::int32_t>> all;
  std::vector<std::int32_t> e(n, 0);
  // Every exponent vector with entries summing to at most d, odometer style.
  for (bool more = true; more;) {
    all.push_back(e);
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
  std::vector<std::int32_t> encoded(all.size() * w);
  for (std::size_t i = 0; i < all.size(); ++i) ring->encode(all[i].data(), encoded.data() + i * w);
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return ring->compare(encoded.data() + a * w, encoded.data() + b * w) > 0;
  });
  MonomialBasis basis;
  basis.degree = d;
  basis.variables = n;
  for (std::size_t i : order) basis.exponents.insert(basis.exponents.end(), all[i].begin(), all[i].end());
  return basis;
}

// The kernel of the evaluation matrix of `basis` modulo one prime.
struct KernelImage {
  mp_limb_t prime = 0;
  std::int32_t degree = 0;
  bool enough_points = true;  // false: too few parameter points with ω ≠ 0 mod p
  std::size_t nullity = 0;
  std::size_t lead = 0;           // with nullity 1: the column of the leading term
  std::vector<mp_limb_t> vector;  // with nullity 1: the kernel, vector[lead] = 1
  std::size_t rows = 0;
  std::size_t rejected_points = 0;  // points where ω vanished
};

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

// ---------------------------------------------------------------- the dimension

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

// ---------------------------------------------------------------- reconstruction

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

// ---------------------------------------------------------------- the driver

// The search for the degree and the Chinese remaindering, prime by prime.
class InterpolationDriver {
 public:
  InterpolationDriver(const Parametrization& p, const InterpolationParams& options)
      : parametrization_(p), options_(options), forms_(map_forms(p)), primes_(options.primes) {}

  // The equation, or nullopt when its degree is proven above `max_degree` (only
  // when that is below the degree bound: at the bound there is no such answer).
  std::optional<InterpolationResult> run(std::int32_t max_degree = kMaxTotalDegree) {
    const Stopwatch timer;
    const std::size_t n = forms_.coordinates;
    const std::int64_t bound = degree_bound_of(forms_);
    stats_.degree_bound = static_cast<std::int32_t>(std::min<std::int64_t>(bound, kMaxTotalDegree));
    check_image_dimension(forms_, options_.seed, options_.budget);
    // The search treats the cap as the bound: a kernel at degree D ≥ e still has
    // dimension C(D − e + n, n), whether D is the bound or not.
    const bool capped = max_degree < stats_.degree_bound;
    const std::int32_t d_max = capped ? max_degree : stats_.degree_bound;
    const double max_columns = static_cast<double>(options_.max_columns);
    stats_.search_ms += timer.elapsed_ms();

    for (;;) {
      options_.budget.check("interpolation");
      const std::int32_t current = std::max(lower_, estimate_);
      const bool searching = estimate_ < lower_;
      std::int32_t degree = current;
      if (searching) {
        if (lower_ > d_max) {
          if (capped) return std::nullopt;
          throw NoSingleEquation("no implicit equation: no polynomial of degree at most " + std::to_string(d_max) +
                                     " (the degree bound) vanishes on the image, which is dense in " +
                                     (n == 3 ? "space" : "the plane"),
                                 {});
        }
        // Upward while a kernel costs at most an eighth of the one at the bound (half
        // the columns), or when the bound's matrix is too large; else at the bound,
        // and at once when the bound's matrix is tiny (kDirectColumns).
        const double here = monomial_count(n, lower_);
        const double at_bound = monomial_count(n, d_max);
        if (at_bound <= max_columns && (2 * here > at_bound || at_bound <= kDirectColumns)) degree = d_max;
      }
      const double columns = monomial_count(n, degree);
      // The equation has at most one term per column: the budget's size limit applies.
      if (columns <= max_columns) options_.budget.check_terms(static_cast<std::size_t>(columns), "interpolation");
      if (columns > max_columns) {
        throw LimitExceeded(Limit::size, "interpolation: the implicit equation has degree at least " +
                                             std::to_string(current) + " (bound " + std::to_string(d_max) +
                                             "), whose matrix would exceed " + std::to_string(options_.max_columns) +
                                             " columns");
      }
      const MonomialBasis& basis = basis_of(degree);
      const unsigned threads = batch_threads(basis.size(), /*upward_step=*/searching && degree < d_max);
      stats_.threads = std::max(stats_.threads, threads);
      refuse_kernel_past_deadline(columns);
      const Stopwatch batch_timer;
      std::vector<KernelImage> images = run_batch(basis, threads);
      const double batch_ms = batch_timer.elapsed_ms();
      (searching ? stats_.search_ms : stats_.images_ms) += batch_ms;
      if (columns >= kTimedColumns) ms_per_cubed_column_ = batch_ms / (columns * columns * columns);
      for (KernelImage& image : images) {
        if (searching) ++stats_.degree_probes;
        if (auto answer = take(std::move(image))) {
          stats_.modulus_bits = lift_ ? lift_->modulus_bits() : 0;
          stats_.primes = lift_ ? lift_->primes() : 0;
          return InterpolationResult{std::move(*answer), stats_};
        }
      }
    }
  }

 private:
  const MonomialBasis& basis_of(std::int32_t degree) {
    auto it = bases_.find(degree);
    if (it == bases_.end()) it = bases_.emplace(degree, monomial_basis(forms_.coordinates, degree)).first;
    return it->second;
  }

  // FLINT's row reduction cannot be interrupted, and at 3000 columns one takes seconds:
  // a kernel that would end past the deadline is refused before it starts, so that
  // the answer comes within the time limit (issue 16: 4.5 s on a 3 s budget). Its
  // time is predicted from the last large kernel's, measured on this run (so under
  // this load), scaled by the cube of the growth in columns (the row reduction's
  // cost; the upward search grows them by at most a third a step from 200 columns on).
  void refuse_kernel_past_deadline(double columns) const {
    if (ms_per_cubed_column_ <= 0) return;
    const double predicted_seconds = ms_per_cubed_column_ * columns * columns * columns / 1000;
    const double left = options_.budget.seconds_left();
    if (predicted_seconds <= left) return;
    std::ostringstream message;
    message.precision(2);
    message << "time limit of " << options_.budget.timeout_seconds()
            << " s exceeded during interpolation: the kernel of " << static_cast<std::size_t>(columns)
            << " columns would take about " << predicted_seconds << " s and " << std::max(0.0, left) << " s are left";
    throw LimitExceeded(Limit::time, message.str());
  }

  // A prime per thread when a kernel is large enough to pay for starting one. A step
  // of the upward search runs alone: below the degree a second prime at the same
  // degree tells nothing new. At most kMaxThreads: the benchmark's equations need 1
  // to 4 primes, so more threads would mostly compute primes that are not needed.
  unsigned batch_threads(std::size_t columns, bool upward_step) const {
    if (options_.threads != 0) return options_.threads;
    if (upward_step || columns < kParallelColumns) return 1;
    return std::clamp(std::thread::hardware_concurrency(), 1u, kMaxThreads);
  }

  // The kernels of one batch, a prime per thread, in prime order so that the result
  // does not depend on scheduling.
  std::vector<KernelImage> run_batch(const MonomialBasis& basis, unsigned threads) {
    std::vector<mp_limb_t> batch(threads);
    for (auto& p : batch) p = primes_.next();
    taken_ += threads;
    if (taken_ > options_.max_primes) {
      throw LimitExceeded(Limit::size,
                          "interpolation: more than " + std::to_string(options_.max_primes) + " primes needed");
    }
    std::vector<KernelImage> images(threads);
    run_one_per_thread(threads, [&](std::size_t i) {
      images[i] = kernel_modulo(forms_, basis, batch[i], options_.seed, options_.budget);
    });
    return images;
  }

  // Takes the kernel of one prime into the state; returns the verified equation
  // when this prime completes it.
  //
  // lower_ is proven (a zero kernel at degree d proves e > d) and estimate_ too, as
  // long as the image is a hypersurface: a kernel modulo p contains the reduction of
  // the true one, so the degree read from its nullity is never above e. A kernel
  // that contradicts them, or the leading monomial of the best prime, is unlucky.
  std::optional<Polynomial> take(KernelImage image) {
    stats_.rejected_points += image.rejected_points;
    if (!image.enough_points) {
      ++stats_.unlucky_primes;
      return std::nullopt;
    }
    if (image.nullity == 0) {
      // This refutes the degree the probes above it read: their primes were unlucky.
      if (estimate_ > 0 && image.degree >= estimate_) {
        stats_.unlucky_primes += estimate_probes_;
        estimate_probes_ = 0;
      }
      lower_ = std::max(lower_, image.degree + 1);
      settle_degree();
      return std::nullopt;
    }
    const std::optional<std::int32_t> read = degree_from_nullity(image.degree, image.nullity, forms_.coordinates);
    if (!read || *read < std::max(lower_, estimate_)) {
      ++stats_.unlucky_primes;
      return std::nullopt;
    }
    if (*read > estimate_) estimate_probes_ = 0;
    estimate_ = std::max(estimate_, *read);
    settle_degree();
    // A probe above e holds F's multiples and only tells the degree. At e the
    // nullity is 1 (read = degree) and the vector has degree exactly e: were it of
    // degree < e, its products with x, y, z would be further kernel vectors.
    if (image.degree != lift_degree_) {
      ++estimate_probes_;
      return std::nullopt;
    }
    if (image.nullity != 1) throw std::logic_error("interpolation: a kernel of dimension > 1 at the degree found");
    if (lead_ && image.lead > *lead_) {  // p divides F's leading coefficient
      ++stats_.unlucky_primes;
      return std::nullopt;
    }
    if (lead_ && image.lead < *lead_) {  // so did every prime so far
      stats_.unlucky_primes += lift_->primes();
      lift_.emplace(image.vector.size(), kLiftParams);
    }
    lead_ = image.lead;
    // The candidate is verified as soon as every coefficient has a value, without
    // waiting for a prime that changes none: that prime costs as much as the
    // verification or more (tp_33: 1.3 s against 0.3 s), the verification is needed
    // anyway, and a value is wrong only with probability about 2^-20 (kLiftParams).
    const Stopwatch reconstruction_timer;
    lift_->add(image.vector, image.prime);
    const bool complete = lift_->reconstruct();
    std::optional<Polynomial> candidate;
    if (complete) candidate = polynomial_of(basis_of(lift_degree_), lift_->integer_values());
    stats_.reconstruction_ms += reconstruction_timer.elapsed_ms();
    if (!candidate) return std::nullopt;
    stats_.degree = lift_degree_;
    stats_.rows = image.rows;
    stats_.columns = image.vector.size();
    return verified(std::move(*candidate));
  }

  // Points the reconstruction at the degree lower_ and estimate_ now give, starting
  // over when it changed (images at another degree are of no use).
  void settle_degree() {
    const std::int32_t degree = std::max(lower_, estimate_);
    if (estimate_ < lower_ || degree == lift_degree_) return;
    // Images at a degree below e come from unlucky primes only: a good one has no
    // kernel there.
    if (lift_) stats_.unlucky_primes += lift_->primes();
    lift_degree_ = degree;
    lift_.emplace(basis_of(degree).size(), kLiftParams);
    lead_.reset();
  }

  std::optional<Polynomial> verified(Polynomial candidate) {
    if (options_.tamper_candidate) options_.tamper_candidate(candidate);
    if (rejected_ && candidate == *rejected_) return std::nullopt;  // the same wrong answer again
    const Stopwatch verify_timer;
    const bool vanishes = substitutes_to_zero(candidate, parametrization_, forms_.exact, options_.budget);
    stats_.verify_ms += verify_timer.elapsed_ms();
    if (vanishes) return candidate;
    ++stats_.rejected_candidates;
    rejected_ = std::move(candidate);
    return std::nullopt;
  }

  const Parametrization& parametrization_;
  const InterpolationParams& options_;
  MapForms forms_;
  PrimeSequence primes_;
  std::size_t taken_ = 0;
  // The last large kernel's milliseconds per cubed column (0 until one ran).
  double ms_per_cubed_column_ = 0;
  InterpolationStats stats_;
  std::map<std::int32_t, MonomialBasis> bases_;
  std::int32_t lower_ = 1;           // proven: e ≥ lower_
  std::int32_t estimate_ = 0;        // the largest degree read from a non-zero kernel (0: none)
  std::size_t estimate_probes_ = 0;  // kernels above estimate_ that read it
  std::int32_t lift_degree_ = 0;
  std::optional<CrtLift> lift_;
  std::optional<std::size_t> lead_;
  std::optional<Polynomial> rejected_;
};

}  // namespace

std::int32_t implicit_degree_bound(const Parametrization& parametrization) {
  return static_cast<std::int32_t>(
      std::min<std::int64_t>(degree_bound_of(map_forms(parametrization)), kMaxTotalDegree));
}

InterpolationResult implicitize_by_interpolation(const Parametrization& parametrization,
                                                 const InterpolationParams& options) {
  const std::size_t n = parametrization.coordinates.size();
  if (n != 2 && n != 3) throw std::invalid_argument("implicitize_by_interpolation: two or three coordinates expected");
  return *InterpolationDriver(parametrization, options).run();
}

std::optional<InterpolationResult> implicitize_by_interpolation_up_to(const Parametrization& parametrization,
                                                                      std::int32_t max_degree,
                                                                      const InterpolationParams& options) {
  const std::size_t n = parametrization.coordinates.size();
  if (n != 2 && n != 3) {
    throw std::invalid_argument("implicitize_by_interpolation_up_to: two or three coordinates expected");
  }
  if (max_degree < 1) throw std::invalid_argument("implicitize_by_interpolation_up_to: max_degree ≥ 1 expected");
  return InterpolationDriver(parametrization, options).run(max_degree);
}

ImplicitEquationCheck check_implicit_equation(const Polynomial& candidate, const Parametrization& parametrization,
                                              const InterpolationParams& options) {
  ImplicitEquationCheck check;
  const MapForms forms = map_forms(parametrization);
  const std::size_t n = forms.coordinates;
  if (candidate.ring()->num_variables() != n) {
    throw std::invalid_argument("check_implicit_equation: one variable per coordinate expected");
  }
  check.vanishes = substitutes_to_zero(candidate, parametrization, options.budget);
  if (candidate.is_constant() || forms.parameters + 1 < n) return check;

  const std::int32_t d = candidate.total_degree();
  const MonomialBasis basis = monomial_basis(n, d);
  if (static_cast<double>(basis.size()) > static_cast<double>(options.max_columns)) {
    throw LimitExceeded(Limit::size, "check_implicit_equation: the matrix would exceed " +
                                         std::to_string(options.max_columns) + " columns");
  }
  PrimeSequence primes = options.primes;
  const mp_limb_t p = primes.next();
  nmod_t mod;
  nmod_init(&mod, p);
  const KernelImage image = kernel_modulo(forms, basis, p, options.seed, options.budget);
  if (!image.enough_points || image.nullity != 1) return check;

  // The candidate modulo p on the columns, scaled like the kernel vector.
  const Polynomial f = candidate.primitive_part();
  std::map<std::vector<std::int32_t>, std::size_t> column_of;
  for (std::size_t c = 0; c < basis.size(); ++c) {
    column_of.emplace(std::vector<std::int32_t>(basis.at(c), basis.at(c) + n), c);
  }
  std::vector<mp_limb_t> residues(basis.size(), 0);
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    residues[column_of.at(f.exponents(t))] = mpz_fdiv_ui(to_integer(f.coefficient(t)).get_mpz_t(), p);
  }
  if (residues[image.lead] == 0) return check;
  const mp_limb_t inverse = n_invmod(residues[image.lead], p);
  _nmod_vec_scalar_mul_nmod(residues.data(), residues.data(), static_cast<slong>(residues.size()), inverse, mod);
  if (residues != image.vector) return check;

  // A hypersurface: the Jacobian has rank n − 1 at a point modulo the same prime.
  ModularMap map(forms, mod, /*with_partials=*/true);
  ResidueStream stream(options.seed ^ 0x3c6ef372fe94f82bULL);
  std::vector<mp_limb_t> a(forms.parameters);
  for (int attempt = 0; attempt < 16; ++attempt) {
    for (auto& v : a) v = stream.next(p);
    if (const auto rank = map.jacobian_rank(a)) {
      check.minimal = *rank + 1 == n;
      break;
    }
  }
  return check;
}

}  // namespace implicitizer
