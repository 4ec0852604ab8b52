#pragma once
/// \file
/// The machinery shared by the interpolation routes (interpolation.hpp, dense degrees;
/// sparse_interpolation.hpp, predicted supports): the parametrization's forms, their
/// values modulo a prime, the evaluation matrix on a set of monomials and its kernel.
/// Private to the implicitization module.

#include <flint/nmod_mat.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/interpolation.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/modular/crt_lift.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// The lift of the normalized kernel vector (leading coefficient 1, so each entry is
/// F_i / F_lead for the primitive equation F: the denominators all divide F_lead).
/// A value is accepted only with 20 bits to spare, so that a residue that is not yet
/// the image of a small rational is taken for one with probability about 2^-20; such
/// a false value is refuted by the next prime, and the candidate is verified anyway.
inline constexpr CrtLiftParams kLiftParams{.margin_bits = 20, .shared_denominator = true};

/// An integer polynomial as plain data. Threads read these concurrently, which they
/// could not do with Polynomial: CGAL's rationals count references without atomics.
struct IntegerPolynomial {
  std::vector<Integer> coefficients;
  std::vector<std::int32_t> exponents;  // num_variables per term
};

/// ω, ξ_1, …, ξ_n of common_denominator_form() scaled to integers (the map does not
/// change), with their first derivatives for the Jacobian.
struct MapForms {
  std::size_t parameters = 0;                            // k
  std::size_t coordinates = 0;                           // n
  std::vector<Polynomial> exact;                         // ω, ξ_1, …, ξ_n
  std::vector<IntegerPolynomial> forms;                  // the same as plain data
  std::vector<std::vector<IntegerPolynomial>> partials;  // partials[i][j] = ∂(form i)/∂(parameter j)
};

/// The forms of `p` (common_denominator_form, checked against `budget`), scaled to
/// integers, with their partials.
MapForms map_forms(const Parametrization& p, const Budget& budget);

/// Powers a_j^e of the coordinates of a point, e ≤ top[j].
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

/// An IntegerPolynomial reduced modulo a prime.
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

/// The parametrization modulo p: the image ξ(a)/ω(a) of a parameter point a, and
/// optionally the Jacobian there.
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

/// C(d + n, n): the number of monomials of degree ≤ d in n variables, as a double so
/// that bounds in the millions do not overflow.
double monomial_count(std::size_t n, std::int64_t d);

/// Monomials in decreasing grevlex (x > y > z), the contract's order: the columns of
/// the evaluation matrix, so that the first non-zero entry of a kernel vector is the
/// leading term of its polynomial.
struct MonomialBasis {
  std::int32_t degree = 0;
  std::size_t variables = 0;
  std::vector<std::int32_t> exponents;  // `variables` per monomial
  std::size_t size() const { return exponents.size() / variables; }
  const std::int32_t* at(std::size_t column) const { return exponents.data() + column * variables; }
};

/// The monomials of degree ≤ d in n variables.
MonomialBasis monomial_basis(std::size_t n, std::int32_t d);

/// The monomials `exponents` (n per monomial, distinct) as a basis: in decreasing grevlex,
/// its degree the largest total degree among them (the power tables' size).
MonomialBasis monomial_basis_of(std::size_t n, const std::vector<std::int32_t>& exponents);

/// The kernel of the evaluation matrix of `basis` modulo one prime.
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

/// The kernel modulo p of the matrix whose rows are the monomials of `basis` at
/// points ξ(a)/ω(a) of the image, a random with ω(a) ≢ 0 and pairwise distinct.
/// Checks `budget` at every row; FLINT's row reduction itself cannot be interrupted.
KernelImage kernel_modulo(const MapForms& forms, const MonomialBasis& basis, mp_limb_t p, std::uint64_t seed,
                          const Budget& budget);

/// The degree e with C(d − e + n, n) = nullity: a kernel at degree d ≥ e of the
/// equation's multiples F·(monomials of degree ≤ d − e). nullopt when no such e ≥ 1.
std::optional<std::int32_t> degree_from_nullity(std::int32_t d, std::size_t nullity, std::size_t n);

/// Returns when the image has dimension at least n − 1; throws NoSingleEquation when
/// it fills space or is smaller. The rank of the Jacobian at a point modulo a prime is
/// at most its rank over ℚ (a minor non-zero mod p is non-zero), which in
/// characteristic 0 is the image's dimension at a general point; only a deficient
/// rank needs the exact minors.
void check_image_dimension(const MapForms& m, std::uint64_t seed, const Budget& budget);

/// implicit_degree_bound() (interpolation.hpp) of the forms, before its cap.
std::int64_t degree_bound_of(const MapForms& m);

/// The polynomial with `coefficients` on the columns of `basis`, in implicit_ring(n).
Polynomial polynomial_of(const MonomialBasis& basis, const std::vector<Integer>& coefficients);

/// Whether the primitive integer polynomial `f`, on the columns of `basis`, reduced
/// modulo image.prime and scaled to a leading entry 1, is the kernel vector of `image`
/// (of nullity 1): then f mod p spans that kernel. False when a term of f is not a
/// column.
bool spans_kernel(const Polynomial& f, const MonomialBasis& basis, const KernelImage& image);

/// The exact check of the interpolation routes' candidates (substitutes_to_zero), which
/// remembers the last rejected one: a later prime that does not change a wrong
/// candidate does not pay for its substitution again.
class CandidateVerifier {
 public:
  /// Keeps references to all four, which must outlive it.
  CandidateVerifier(const Parametrization& parametrization, const MapForms& forms, const InterpolationParams& options,
                    InterpolationStats& stats)
      : parametrization_(parametrization), forms_(forms), options_(options), stats_(stats) {}

  /// Whether `candidate` vanishes on the image, after options.tamper_candidate (tests)
  /// changed it; counts a rejection in stats.rejected_candidates.
  bool vanishes(Polynomial& candidate);

 private:
  const Parametrization& parametrization_;
  const MapForms& forms_;
  const InterpolationParams& options_;
  InterpolationStats& stats_;
  std::optional<Polynomial> rejected_;
};

}  // namespace implicitizer
