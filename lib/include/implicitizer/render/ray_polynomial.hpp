#pragma once
/// \file
/// The univariate polynomial of a surface along a ray: for F(x, y, z) with rational
/// coefficients and a ray o + t·d (o, d, t exactly the doubles given),
///     q(s) = F(o + (t_begin + s·(t_end − t_begin))·d),   s ∈ [0, 1],
/// the restriction of F to the segment [t_begin, t_end] in a variable that runs over
/// [0, 1] (g(t) = F(o + t·d) itself is the segment [0, 1]). The roots of q are the
/// ray's intersections with F = 0: root_isolation.hpp finds the first one.
///
/// Two expansions, from one RayPolynomialContext built once per F (the terms in
/// nested Horner order, in double and as FLINT integers), so that a render neither
/// re-parses nor re-allocates per ray:
///  - double: nested Horner in the linear polynomials X(s), Y(s), Z(s), each step a
///    multiplication of a coefficient vector by a linear polynomial, O(terms·n) flops
///    for degree n; beside it the same program on absolute values gives the majorant
///    q̂ (the coefficients of F̂(X̂, Ŷ, Ẑ), F̂ = Σ|c|·x^m, X̂(s) = |X₀| + s·|X₁| for the
///    rounded linear polynomial X₀ + s·X₁ of the segment), and every computed
///    coefficient is within relative_error·q̂_k + band of the exact one (the bound
///    and its proof are at DoubleRayPolynomial).
///  - exact: the same Horner scheme over ℤ with FLINT's fmpz_poly. Every double is a
///    dyadic rational m·2^e, so the segment's points are (O + s·D)·2^E with integer
///    O, D and one exponent E, and 2^(−E·n)·q(s) = Σ_m c_m·2^(−E(n−|m|))·(O + sD)^m
///    has integer coefficients (c_m the integer coefficients of F's primitive part).
///    FLINT rather than the library's Polynomial/Rational because the univariate work
///    that follows (Taylor shifts, gcd for the square-free part, many small
///    multiplications) is what fmpz_poly is built for: inline small integers,
///    no rational normalisation per operation, and a fast modular gcd.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// The points o + t·d, t ∈ [t_begin, t_end], exactly the doubles given.
/// Preconditions (checked by first_ray_root, not here): all finite.
struct RaySegment {
  std::array<double, 3> origin{};     ///< o
  std::array<double, 3> direction{};  ///< d (any length; t is in units of |d|)
  double t_begin = 0;                 ///< the segment's first parameter
  double t_end = 1;                   ///< the segment's last parameter
};

/// q(s) of a segment in double, with what it takes to trust it. Here q is that of
/// F/(|c|·2^e), F = c·P with P primitive and 2^e ≥ max |P_m| the power of two of
/// P's largest coefficient (mpz_get_d_2exp): a positive multiple of F whose
/// coefficients are below 1 in magnitude, whatever F's size (1e30·sphere).
///
/// Bound. Let u = 2^−53 and γ_k = k·u/(1 − k·u). The inputs of the Horner program are
/// X₀ = fl(o_x + fl(t_begin·d_x)) and X₁ = fl(fl(t_end − t_begin)·d_x) (and the same for
/// y, z). X₁ is within γ₂ of the true slope relative to |X₁|. X₀ is treated as exact
/// and its error e, |e_x| ≤ δ_x = 2.02u(|o_x| + |t_begin·d_x|) (0 when t_begin = 0),
/// goes into an absolute `band`: F(P + e) − F(P) has coefficients bounded by those of
/// F̂(P̂ + δ) − F̂(P̂), whose sum is at most Σ_x δ_x·∂_xF̂(P̂(1) + δ) (F̂ = Σ|c|·x^m,
/// P̂(s) = |X₀| + s·|X₁|). Treating X₀ as exact keeps the majorant local: it is
/// F̂(|X₀| + s|X₁|), the size of F's terms near the segment, not near |o| + |t·d|,
/// which matters once the segment is a short piece far from o. A term c·x^i y^j z^k
/// reaches coefficient k of the result through i + j + k ≤ n multiplications by a
/// linear polynomial, each with one rounded product and at most two rounded sums,
/// plus one sum per Horner level and the truncation of c to double (< 2 ulps): at
/// most 3n + 4 roundings on products of at most n perturbed inputs, hence (Higham,
/// Accuracy and Stability of Numerical Algorithms, Lemma 3.3 and §3.1)
/// |q̃_k − q_k| ≤ γ_{5n+4}·q̂_k + band. The majorant is itself computed in double
/// from rounded non-negative values, q̂̃_k ≥ q̂_k/(1 + γ_{6n+6}), so relative_error =
/// 2·γ_{6n+6} covers both with margin. Coefficients of F below double's normal range
/// (relative to F's largest) count as 2^−1022 in the majorant.
struct DoubleRayPolynomial {
  std::vector<double> coefficients;  ///< q̃_k, k = 0 … n (n = F's total degree; high ones may be 0)
  std::vector<double> majorant;  ///< q̂̃_k, the majorant's coefficients: |q_k| ≤ (1 + relative_error)·q̂̃_k + band
  double relative_error = 0;     ///< |q̃_k − q_k| ≤ relative_error·q̂̃_k + band for every k
  double band = 0;               ///< absolute slack for the rounded start point (0 if t_begin = 0)
  /// Whether every coefficient and majorant is finite (false: out of double's range,
  /// e.g. |o| ~ 1e20 at degree 18; the caller must use the exact expansion).
  bool finite = true;
};

/// F (scaled as in DoubleRayPolynomial) at one point of a ray, in double, with a
/// bound. The point p = o + t·d (t, o, d exact doubles) is split without error into
/// p = s + r (Dekker's two_product and Knuth's two_sum: s = fl(o + fl(t·d)), r the
/// rounding errors, |r| ≈ u·|p|, itself rounded by u·(its parts)), and
///     F(p) ≈ F(s) + ∇F(s)·r,
/// F(s) and ∇F(s) by nested Horner with forward-mode derivatives. The bound adds
///  - a running error bound of F(s) (Higham, Accuracy and Stability, §5.1: every
///    operation adds u·|result|, a product by v scales the error so far by |v|, a
///    coefficient brings its truncation 2u·|c|): the actual cancellation at s, not a
///    worst case;
///  - the first-order term's errors, γ_{8n+8}·∇F̂(|s|)·|r| + ∇F̂(|s|)·|r̃ − r|;
///  - the Taylor remainder ½ Σ_ij |r_i||r_j| ∂_ijF̂(|s| + |r|) ≤ ½ (Σ|r_j|/h)·Σ_i
///    |r_i|·∂_iF̂(|s| + |r| + h), h = max_i(|s_i| + |r_i|) (for a polynomial G with
///    non-negative coefficients, ∂_j G(y) ≤ G(y + h·e_j)/h), F̂ = Σ|c|·x^m;
///  - γ₄ of the final sums;
/// times 1.01 for the bound's own rounding. Without the split, rounding p alone
/// would move F by up to |∇F|·2u·(|o| + |t·d|): for tp_33 seen from 55 units away,
/// 16 times the running error (measured at the first ray of the degree-18 test),
/// and 14 of its 24 test rays could not be pinned in double instead of 2.
struct RayPointValue {
  double value = 0;       ///< F̃(s) + ∇F̃(s)·r̃ ≈ F(o + t·d)
  double derivative = 0;  ///< d/dt F(o + t·d) ≈ ∇F̃(s)·d (for Newton's step; not bounded)
  double error = 0;       ///< |value − F(o + t·d)| ≤ error (exact t, o, d)
};

/// F pre-expanded for many rays: nested Horner order, double coefficients scaled by
/// F's largest coefficient (sign-preserving: q's roots do not change), and the
/// integer coefficients of F's primitive part. Immutable after construction, so
/// one context serves every thread of a render.
class RayPolynomialContext {
 public:
  /// Prepares `f`. Throws InputError `invalid_variables` (field "equation") unless
  /// f's ring has exactly three variables (x, y, z in ring order), and
  /// `constant_polynomial` when f is constant (no surface, or all of space).
  explicit RayPolynomialContext(const Polynomial& f);
  ~RayPolynomialContext();
  RayPolynomialContext(RayPolynomialContext&&) noexcept;
  RayPolynomialContext& operator=(RayPolynomialContext&&) noexcept;
  RayPolynomialContext(const RayPolynomialContext&) = delete;
  RayPolynomialContext& operator=(const RayPolynomialContext&) = delete;

  /// F's total degree n ≥ 1: q has at most degree n.
  std::int32_t degree() const { return degree_; }
  /// Number of terms of F.
  std::size_t num_terms() const;

  /// Writes q̃, q̂̃ and the error bound of `segment` into `out`, reusing its vectors
  /// (no allocation once they have n + 1 entries). Thread-safe.
  void expand_double(const RaySegment& segment, DoubleRayPolynomial& out) const;

  /// F at o + t·d with its error bound (RayPointValue). Thread-safe, no allocation.
  RayPointValue evaluate_double(const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                                double t) const;

  /// The exact q(s) times a positive rational, as a primitive integer polynomial,
  /// coefficient k of s^k at index k (trailing zeros removed; empty when q ≡ 0, i.e.
  /// the segment lies in the surface). Positive scaling keeps q's signs, so its
  /// roots and the sign pattern between them are q's. Checks `budget` per term.
  std::vector<Integer> expand_exact(const RaySegment& segment, const Budget& budget = Budget()) const;

 private:
  struct Terms;  // the Horner layout, doubles and FLINT integers (in the .cpp)
  std::int32_t degree_ = 0;
  std::unique_ptr<Terms> terms_;
};

}  // namespace implicitizer
