#include "patch_evaluator.hpp"

#include <algorithm>
#include <cmath>

#include "implicitizer/core/rational.hpp"

namespace implicitizer::approximation {

DoublePolynomial::DoublePolynomial(const Polynomial& p) : variables_(p.ring()->num_variables()) {
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    coefficients_.push_back(to_mpq(p.coefficient(t)).get_d());
    const std::vector<std::int32_t> e = p.exponents(t);
    exponents_.insert(exponents_.end(), e.begin(), e.end());
    for (std::int32_t k : e) stride_ = std::max(stride_, std::size_t(k) + 1);
  }
  power_index_.reserve(exponents_.size());
  for (std::size_t i = 0; i < exponents_.size(); ++i) {
    power_index_.push_back(static_cast<std::uint32_t>((i % variables_) * stride_ + std::size_t(exponents_[i])));
  }
}

namespace {

// Σ c_t·Π_v powers[index[t·n + v]] over n variables (n = V, or `variables` when V is
// 0), the factors multiplied in the order of the variables whatever V: with V known,
// the compiler unrolls the product (the approximation's measurements evaluate in
// three variables and the patch in two).
template <std::size_t V>
double sum_of_terms(const std::vector<double>& coefficients, const std::uint32_t* index, const double* powers,
                    std::size_t variables) {
  const std::size_t n = V == 0 ? variables : V;
  double sum = 0;
  for (std::size_t t = 0; t < coefficients.size(); ++t) {
    double term = coefficients[t];
    for (std::size_t v = 0; v < n; ++v) term *= powers[index[t * n + v]];
    sum += term;
  }
  return sum;
}

}  // namespace

template <typename Use>
double DoublePolynomial::with_powers(const double* x, Use use) const {
  constexpr std::size_t kInline = 96;
  double inline_powers[kInline];
  std::vector<double> heap;
  const std::size_t size = variables_ * stride_;
  double* powers = size <= kInline ? inline_powers : (heap.resize(size), heap.data());
  for (std::size_t v = 0; v < variables_; ++v) {
    double* row = powers + v * stride_;
    row[0] = 1;
    for (std::size_t k = 1; k < stride_; ++k) row[k] = row[k - 1] * x[v];
  }
  return use(static_cast<const double*>(powers));
}

double DoublePolynomial::value(const double* x) const {
  return with_powers(x, [&](const double* powers) {
    const std::uint32_t* index = power_index_.data();
    if (variables_ == 3) return sum_of_terms<3>(coefficients_, index, powers, 3);
    if (variables_ == 2) return sum_of_terms<2>(coefficients_, index, powers, 2);
    return sum_of_terms<0>(coefficients_, index, powers, variables_);
  });
}

double DoublePolynomial::value_and_gradient(const double* x, double* gradient) const {
  for (std::size_t v = 0; v < variables_; ++v) gradient[v] = 0;
  return with_powers(x, [&](const double* powers) {
    if (variables_ == 3) return terms_and_gradient<3>(powers, gradient);
    if (variables_ == 2) return terms_and_gradient<2>(powers, gradient);
    return terms_and_gradient<0>(powers, gradient);
  });
}

template <std::size_t V>
double DoublePolynomial::terms_and_gradient(const double* powers, double* gradient) const {
  // V = 0: any number of variables, read at run time.
  const std::size_t n = V == 0 ? variables_ : V;
  const std::uint32_t* index = power_index_.data();
  double sum = 0;
  for (std::size_t t = 0; t < coefficients_.size(); ++t) {
    const std::int32_t* e = exponents_.data() + t * n;
    const std::uint32_t* at = index + t * n;
    double term = coefficients_[t];
    for (std::size_t v = 0; v < n; ++v) term *= powers[at[v]];
    sum += term;
    for (std::size_t v = 0; v < n; ++v) {
      if (e[v] == 0) continue;
      // ∂/∂x_v of c·Π x^e: the same product with x_v^(e_v − 1), times e_v.
      double d = coefficients_[t] * e[v] * powers[at[v] - 1];
      for (std::size_t w = 0; w < n; ++w) {
        if (w != v) d *= powers[at[w]];
      }
      gradient[v] += d;
    }
  }
  return sum;
}

FramedPolynomial::FramedPolynomial(const Polynomial& q, const Frame& frame) : frame_(frame) {
  const RingPtr& space = q.ring();
  std::vector<Polynomial> x;
  for (std::size_t i = 0; i < 3; ++i) {
    x.push_back(Polynomial::constant(space, to_rational(mpq_class(frame.center[i]))) +
                Polynomial::variable(space, i).scaled(to_rational(mpq_class(frame.half))));
  }
  q_ = DoublePolynomial(q.compose(space, x));
}

double FramedPolynomial::value(const Point& x) const {
  const Point u = {(x[0] - frame_.center[0]) / frame_.half, (x[1] - frame_.center[1]) / frame_.half,
                   (x[2] - frame_.center[2]) / frame_.half};
  return q_.value(u.data());
}

double FramedPolynomial::value_and_gradient(const Point& x, Point& gradient) const {
  const Point u = {(x[0] - frame_.center[0]) / frame_.half, (x[1] - frame_.center[1]) / frame_.half,
                   (x[2] - frame_.center[2]) / frame_.half};
  const double value = q_.value_and_gradient(u.data(), gradient.data());
  for (double& g : gradient) g /= frame_.half;
  return value;
}

PatchEvaluator::PatchEvaluator(const std::vector<Polynomial>& forms) {
  for (std::size_t i = 0; i < 4; ++i) forms_[i] = DoublePolynomial(forms[i]);
}

bool PatchEvaluator::point(double s, double t, Point& x) const {
  const double st[2] = {s, t};
  const double w = forms_[0].value(st);
  if (w == 0) return false;
  for (std::size_t i = 0; i < 3; ++i) x[i] = forms_[i + 1].value(st) / w;
  return true;
}

bool PatchEvaluator::point_and_derivatives(double s, double t, Point& x, Point& ds, Point& dt) const {
  const double st[2] = {s, t};
  double dw[2], dxi[2];
  const double w = forms_[0].value_and_gradient(st, dw);
  if (w == 0) return false;
  for (std::size_t i = 0; i < 3; ++i) {
    const double xi = forms_[i + 1].value_and_gradient(st, dxi);
    x[i] = xi / w;
    // (ξ/ω)' = (ξ' − x·ω')/ω.
    ds[i] = (dxi[0] - x[i] * dw[0]) / w;
    dt[i] = (dxi[1] - x[i] * dw[1]) / w;
  }
  return true;
}

double distance(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace implicitizer::approximation
