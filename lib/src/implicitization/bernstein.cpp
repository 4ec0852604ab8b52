#include "implicitizer/implicitization/bernstein.hpp"

namespace implicitizer {

BernsteinLayout::BernsteinLayout(std::vector<std::size_t> e) : extents(std::move(e)), strides(extents.size()) {
  for (std::size_t j = extents.size(); j-- > 0;) {
    strides[j] = size;
    size *= extents[j];
  }
}

std::size_t BernsteinLayout::corner(std::size_t mask) const {
  std::size_t index = 0;
  for (std::size_t j = 0; j < extents.size(); ++j) {
    if ((mask >> j) & 1U) index += (extents[j] - 1) * strides[j];
  }
  return index;
}

// The power-basis coefficients of `p` as a dense tensor of `layout`.
BernsteinCoefficients dense_coefficients(const Polynomial& p, const BernsteinLayout& layout) {
  BernsteinCoefficients c(layout.size);
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    const std::vector<std::int32_t> e = p.exponents(t);
    std::size_t index = 0;
    for (std::size_t j = 0; j < e.size(); ++j) index += static_cast<std::size_t>(e[j]) * layout.strides[j];
    c[index] = to_mpq(p.coefficient(t));
  }
  return c;
}

// Rewrites power-basis coefficients in parameter `axis` as Bernstein coefficients
// on [a, b]: p(t) = q(u) with t = a + (b − a)·u (Taylor shift, then scaling), then
// b_k = Σ_{i ≤ k} C(k,i)/C(n,i)·q_i, the Bernstein form of q on [0, 1].
void to_bernstein_along(BernsteinCoefficients& c, const BernsteinLayout& layout, std::size_t axis, const mpq_class& a,
                        const mpq_class& b, const Budget& budget, const char* where) {
  const std::size_t n = layout.extents[axis] - 1;
  if (n == 0) return;
  const mpq_class h = b - a;
  // ratio[k][i] = C(k,i)/C(n,i).
  std::vector<std::vector<mpq_class>> ratio(n + 1, std::vector<mpq_class>(n + 1));
  {
    std::vector<std::vector<mpz_class>> binomial(n + 1, std::vector<mpz_class>(n + 1));
    for (std::size_t k = 0; k <= n; ++k) {
      budget.check(where);
      binomial[k][0] = 1;
      for (std::size_t i = 1; i <= k; ++i) binomial[k][i] = binomial[k - 1][i - 1] + (i < k ? binomial[k - 1][i] : 0);
    }
    for (std::size_t k = 0; k <= n; ++k) {
      budget.check(where);
      for (std::size_t i = 0; i <= k; ++i) {
        ratio[k][i] = mpq_class(binomial[k][i], binomial[n][i]);
        ratio[k][i].canonicalize();
      }
    }
  }
  std::vector<mpq_class> q(n + 1);
  layout.for_each_fiber(axis, [&](std::size_t first, std::size_t stride) {
    budget.check(where);
    for (std::size_t i = 0; i <= n; ++i) q[i] = c[first + i * stride];
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = n; k-- > i;) q[k] += a * q[k + 1];
    }
    mpq_class power = h;
    for (std::size_t i = 1; i <= n; ++i, power *= h) q[i] *= power;
    for (std::size_t k = 0; k <= n; ++k) {
      mpq_class sum = 0;
      for (std::size_t i = 0; i <= k; ++i) sum += ratio[k][i] * q[i];
      c[first + k * stride] = sum;
    }
  });
}

// Splits Bernstein coefficients at the midpoint of parameter `axis` (de Casteljau
// with weight 1/2): the coefficients of the lower and of the upper half.
std::pair<BernsteinCoefficients, BernsteinCoefficients> split_along(const BernsteinCoefficients& c,
                                                                    const BernsteinLayout& layout, std::size_t axis,
                                                                    const Budget& budget, const char* where) {
  const std::size_t n = layout.extents[axis] - 1;
  BernsteinCoefficients lower(c.size()), upper(c.size());
  std::vector<mpq_class> work(n + 1);
  layout.for_each_fiber(axis, [&](std::size_t first, std::size_t stride) {
    budget.check(where);
    for (std::size_t i = 0; i <= n; ++i) work[i] = c[first + i * stride];
    lower[first] = work[0];
    upper[first + n * stride] = work[n];
    for (std::size_t r = 1; r <= n; ++r) {
      for (std::size_t k = 0; k + r <= n; ++k) {
        work[k] += work[k + 1];
        mpq_div_2exp(work[k].get_mpq_t(), work[k].get_mpq_t(), 1);
      }
      lower[first + r * stride] = work[0];
      upper[first + (n - r) * stride] = work[n - r];
    }
  });
  return {std::move(lower), std::move(upper)};
}

BernsteinCoefficients bernstein_coefficients(const Polynomial& p, const BernsteinLayout& layout,
                                             const BernsteinBox& box, const Budget& budget, const char* where) {
  BernsteinCoefficients c = dense_coefficients(p, layout);
  for (std::size_t j = 0; j < layout.extents.size(); ++j) {
    to_bernstein_along(c, layout, j, box[j].first, box[j].second, budget, where);
  }
  return c;
}

}  // namespace implicitizer
