#include "dokken_matrix.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <vector>

#include "regular_choice.hpp"

namespace implicitizer::approximation {
namespace {

const char* const kWhere = "approximation: Dokken matrix";

// C(n, k) in double (exact below 2^53: n <= 56 here, bidegree m·d <= 6·4·2).
double binomial(std::size_t n, std::size_t k) {
  double r = 1;
  for (std::size_t i = 1; i <= k; ++i) r = r * double(n - k + i) / double(i);
  return std::round(r);
}

// A bivariate polynomial in the Bernstein basis of bidegree (ds, dt) of the piece, in
// double: c[i·(dt + 1) + j] multiplies B_i^ds(s)·B_j^dt(t).
struct Bernstein2 {
  std::size_t ds = 0, dt = 0;
  std::vector<double> c{1.0};
};

Bernstein2 ones(std::size_t ds, std::size_t dt) { return {ds, dt, std::vector<double>((ds + 1) * (dt + 1), 1.0)}; }

// The product of Bernstein forms: with scaled coefficients C(n,i)·c_i it is the plain
// convolution, divided back by C(n + n', k).
Bernstein2 product(const Bernstein2& a, const Bernstein2& b) {
  Bernstein2 r{a.ds + b.ds, a.dt + b.dt, {}};
  r.c.assign((r.ds + 1) * (r.dt + 1), 0.0);
  for (std::size_t i = 0; i <= a.ds; ++i) {
    for (std::size_t j = 0; j <= a.dt; ++j) {
      const double x = a.c[i * (a.dt + 1) + j] * binomial(a.ds, i) * binomial(a.dt, j);
      if (x == 0) continue;
      for (std::size_t k = 0; k <= b.ds; ++k) {
        for (std::size_t l = 0; l <= b.dt; ++l) {
          r.c[(i + k) * (r.dt + 1) + j + l] += x * b.c[k * (b.dt + 1) + l] * binomial(b.ds, k) * binomial(b.dt, l);
        }
      }
    }
  }
  for (std::size_t i = 0; i <= r.ds; ++i) {
    for (std::size_t j = 0; j <= r.dt; ++j) r.c[i * (r.dt + 1) + j] /= binomial(r.ds, i) * binomial(r.dt, j);
  }
  return r;
}

// Degree elevation: the product with 1 written at the missing degree.
Bernstein2 elevate(const Bernstein2& a, std::size_t ds, std::size_t dt) {
  if (a.ds == ds && a.dt == dt) return a;
  return product(a, ones(ds - a.ds, dt - a.dt));
}

// α·a + β·b at the larger of the two bidegrees.
Bernstein2 combine(double alpha, const Bernstein2& a, double beta, const Bernstein2& b) {
  const std::size_t ds = std::max(a.ds, b.ds), dt = std::max(a.dt, b.dt);
  Bernstein2 r = elevate(a, ds, dt);
  const Bernstein2 e = elevate(b, ds, dt);
  for (std::size_t k = 0; k < r.c.size(); ++k) r.c[k] = alpha * r.c[k] + beta * e.c[k];
  return r;
}

// The exact Bernstein coefficients of `p` over the piece, rounded to doubles; a
// constant keeps bidegree (0, 0).
Bernstein2 double_form(const Polynomial& p, std::size_t ds, std::size_t dt, const BernsteinBox& piece,
                       const Budget& budget) {
  if (p.is_constant()) return {0, 0, {p.is_zero() ? 0.0 : to_mpq(p.coefficient(0)).get_d()}};
  const BernsteinLayout layout({ds + 1, dt + 1});
  const BernsteinCoefficients exact = bernstein_coefficients(p, layout, piece, budget, kWhere);
  Bernstein2 out{ds, dt, {}};
  for (const mpq_class& x : exact) out.c.push_back(x.get_d());
  return out;
}

// H_k(a, ω) = ω^k·T_k(a/ω), k = 0 … m: H_0 = 1, H_1 = a, H_{k+1} = 2a·H_k − ω²·H_{k−1}.
std::vector<Bernstein2> homogeneous_chebyshev(const Bernstein2& a, const Bernstein2& omega, int m) {
  std::vector<Bernstein2> h{Bernstein2{}, a};
  const Bernstein2 omega2 = product(omega, omega);
  for (int k = 1; k < m; ++k) h.push_back(combine(2.0, product(a, h[k]), -1.0, product(omega2, h[k - 1])));
  h.resize(std::size_t(m) + 1);
  return h;
}

// The matrix: one column per basis index, the Bernstein coefficients of ω^m·φ(ξ/ω).
Eigen::MatrixXd dokken_matrix(const std::vector<Polynomial>& forms, const BernsteinBox& piece, const Frame& frame,
                              int m, const Budget& budget) {
  std::size_t ds = 0, dt = 0;
  for (const Polynomial& f : forms) {
    ds = std::max(ds, std::size_t(f.degree_in(0)));
    dt = std::max(dt, std::size_t(f.degree_in(1)));
  }
  const Bernstein2 omega = double_form(forms[0], ds, dt, piece, budget);
  std::array<std::vector<Bernstein2>, 3> h;
  for (std::size_t i = 0; i < 3; ++i) {
    const Bernstein2 xi = double_form(forms[i + 1], ds, dt, piece, budget);
    h[i] = homogeneous_chebyshev(combine(1 / frame.half, xi, -frame.center[i] / frame.half, omega), omega, m);
  }
  std::vector<Bernstein2> omega_powers{Bernstein2{}};
  for (int k = 0; k < m; ++k) omega_powers.push_back(product(omega_powers.back(), omega));
  const std::vector<std::array<int, 3>> indices = basis_indices(m);
  const std::size_t rows = (std::size_t(m) * ds + 1) * (std::size_t(m) * dt + 1);
  Eigen::MatrixXd d(Eigen::Index(rows), Eigen::Index(indices.size()));
  for (std::size_t col = 0; col < indices.size(); ++col) {
    budget.check(kWhere);
    const auto [i, j, k] = indices[col];
    const Bernstein2 column = elevate(product(product(h[0][std::size_t(i)], h[1][std::size_t(j)]),
                                              product(h[2][std::size_t(k)], omega_powers[std::size_t(m - i - j - k)])),
                                      std::size_t(m) * ds, std::size_t(m) * dt);
    for (std::size_t r = 0; r < rows; ++r) d(Eigen::Index(r), Eigen::Index(col)) = column.c[r];
  }
  return d;
}

// Σ b_j T_i(u)·T_j(v)·T_k(w) in x, y, z, exact, scaled so that its largest
// |coefficient| is 1.
Polynomial exact_equation(const Eigen::VectorXd& b, const Frame& frame, int m, const RingPtr& space,
                          const Budget& budget) {
  std::array<std::vector<Polynomial>, 3> t;
  for (std::size_t i = 0; i < 3; ++i) {
    const Polynomial u =
        (Polynomial::variable(space, i) - Polynomial::constant(space, to_rational(mpq_class(frame.center[i]))))
            .divided_by(to_rational(mpq_class(frame.half)));
    t[i] = {Polynomial::constant(space, Rational(1)), u};
    for (int k = 1; k < m; ++k) t[i].push_back(u.scaled(Rational(2)) * t[i][std::size_t(k)] - t[i][std::size_t(k - 1)]);
  }
  std::vector<Polynomial> parts;
  const std::vector<std::array<int, 3>> indices = basis_indices(m);
  for (std::size_t col = 0; col < indices.size(); ++col) {
    budget.check(kWhere);
    if (b(Eigen::Index(col)) == 0) continue;
    const auto [i, j, k] = indices[col];
    parts.push_back((t[0][std::size_t(i)] * t[1][std::size_t(j)] * t[2][std::size_t(k)])
                        .scaled(to_rational(mpq_class(b(Eigen::Index(col))))));
  }
  Polynomial q = sum_of(space, std::move(parts));
  mpq_class largest = 0;
  for (std::size_t k = 0; k < q.num_terms(); ++k) largest = std::max(largest, mpq_class(abs(to_mpq(q.coefficient(k)))));
  return largest == 0 ? q : q.divided_by(to_rational(largest));
}

}  // namespace

DokkenEquation dokken_equation(const std::vector<Polynomial>& forms, const BernsteinBox& piece, const Frame& frame,
                               int degree, const DokkenChoice& choice, const RingPtr& space, const Budget& budget) {
  const Eigen::MatrixXd d = dokken_matrix(forms, piece, frame, degree, budget);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(d, Eigen::ComputeFullV);
  budget.check(kWhere);
  // Ascending singular values with their right vectors; with fewer rows than
  // columns, the missing ones are 0 (the null space is not empty).
  const Eigen::Index columns = d.cols(), known = svd.singularValues().size();
  Eigen::VectorXd sigma = Eigen::VectorXd::Zero(columns);
  Eigen::MatrixXd v(columns, columns);
  for (Eigen::Index k = 0; k < columns; ++k) {
    const Eigen::Index from = columns - 1 - k;
    v.col(k) = svd.matrixV().col(from);
    sigma(k) = from < known ? svd.singularValues()(from) : 0.0;
  }
  const Eigen::VectorXd b = regular_combination(v, sigma, choice.threshold, degree, choice.samples);
  return {exact_equation(b, frame, degree, space, budget), sigma(0)};
}

}  // namespace implicitizer::approximation
