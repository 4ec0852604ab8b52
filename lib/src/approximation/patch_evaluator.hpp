#pragma once
// Double-precision evaluation for the measured half of approximate implicitization:
// a polynomial with its gradient, and a patch X = ξ/ω with its two partial
// derivatives. The exact half (certificate.cpp) never uses these.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer::approximation {

using Point = std::array<double, 3>;

/// A polynomial in double: value and first partial derivatives.
class DoublePolynomial {
 public:
  DoublePolynomial() = default;
  /// Rounds every coefficient of `p` to the nearest double.
  explicit DoublePolynomial(const Polynomial& p);
  /// p(x) (x has one entry per variable).
  double value(const double* x) const;
  /// p(x) and ∂p/∂x_v into gradient[0..variables).
  double value_and_gradient(const double* x, double* gradient) const;

 private:
  // Calls `use(powers)` with powers[v·stride_ + k] = x_v^k, k = 0 … stride_ − 1:
  // every term then costs multiplications only (std::pow took four fifths of an
  // approximation's time).
  template <typename Use>
  double with_powers(const double* x, Use use) const;
  // value_and_gradient's sum over the terms, for V variables (0: variables_).
  template <std::size_t V>
  double terms_and_gradient(const double* powers, double* gradient) const;

  std::size_t variables_ = 0;
  std::size_t stride_ = 1;  // the largest exponent + 1
  std::vector<double> coefficients_;
  std::vector<std::int32_t> exponents_;  // variables_ per term
  // v·stride_ + e_v per term and variable: where value() reads each factor's power.
  std::vector<std::uint32_t> power_index_;
};

/// Frame coordinates u = (x − center)/half, dyadic (exact doubles).
struct Frame {
  std::array<double, 3> center{};
  double half = 1;
};

/// q(x, y, z) evaluated as Q(u) = q(center + half·u) at u = (x − center)/half: Q's
/// coefficients are computed exactly, then rounded, so that the double evaluation
/// near the piece does not cancel (q's power basis in x, y, z far from the origin
/// would lose most digits).
class FramedPolynomial {
 public:
  FramedPolynomial(const Polynomial& q, const Frame& frame);
  /// q(x).
  double value(const Point& x) const;
  /// q(x) and ∇q(x) (with respect to x, y, z).
  double value_and_gradient(const Point& x, Point& gradient) const;

 private:
  DoublePolynomial q_;
  Frame frame_;
};

/// A surface patch X(s, t) = ξ(s, t)/ω(s, t) in double.
class PatchEvaluator {
 public:
  /// `forms`: ω, ξ_x, ξ_y, ξ_z (common_denominator_form()).
  explicit PatchEvaluator(const std::vector<Polynomial>& forms);
  /// X(s, t); false where ω = 0.
  bool point(double s, double t, Point& x) const;
  /// X(s, t) and its partial derivatives; false where ω = 0.
  bool point_and_derivatives(double s, double t, Point& x, Point& ds, Point& dt) const;

 private:
  std::array<DoublePolynomial, 4> forms_;  // ω, ξ_x, ξ_y, ξ_z
};

/// ‖a − b‖.
double distance(const Point& a, const Point& b);

}  // namespace implicitizer::approximation
