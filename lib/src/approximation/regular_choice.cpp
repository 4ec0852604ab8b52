#include "regular_choice.hpp"

#include <Eigen/QR>
#include <algorithm>

namespace implicitizer::approximation {
namespace {

// T_k(x) and T_k'(x), k = 0 … m.
void chebyshev(double x, int m, std::vector<double>& t, std::vector<double>& dt) {
  t.assign(std::size_t(m) + 1, 0.0);
  dt.assign(std::size_t(m) + 1, 0.0);
  t[0] = 1;
  if (m >= 1) t[1] = x, dt[1] = 1;
  for (std::size_t k = 1; k < std::size_t(m); ++k) {
    t[k + 1] = 2 * x * t[k] - t[k - 1];
    dt[k + 1] = 2 * t[k] + 2 * x * dt[k] - dt[k - 1];
  }
}

// The offsets along the normal (frame units) at which q should equal the offset:
// a signed distance in the tube the trimming keeps (0.1·h each side).
constexpr std::array<double, 5> kOffsets{-0.1, -0.05, 0.0, 0.05, 0.1};

}  // namespace

std::vector<std::array<int, 3>> basis_indices(int m) {
  std::vector<std::array<int, 3>> out;
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; i + j <= m; ++j) {
      for (int k = 0; i + j + k <= m; ++k) out.push_back({i, j, k});
    }
  }
  return out;
}

namespace {

// The row of basis values φ_j(u).
Eigen::RowVectorXd basis_row(const Point& u, int degree, const std::vector<std::array<int, 3>>& indices) {
  Eigen::RowVectorXd row(Eigen::Index(indices.size()));
  std::array<std::vector<double>, 3> t, dt;
  for (std::size_t a = 0; a < 3; ++a) chebyshev(u[a], degree, t[a], dt[a]);
  for (std::size_t col = 0; col < indices.size(); ++col) {
    const auto [i, j, l] = indices[col];
    row(Eigen::Index(col)) = t[0][std::size_t(i)] * t[1][std::size_t(j)] * t[2][std::size_t(l)];
  }
  return row;
}

}  // namespace

Eigen::VectorXd regular_combination(const Eigen::MatrixXd& v, const Eigen::VectorXd& singular_values, double threshold,
                                    int degree, const PatchSamples& samples) {
  Eigen::Index r = 1;
  while (r < v.cols() && r < 24 && singular_values(r) <= threshold) ++r;
  const Eigen::MatrixXd basis = v.leftCols(r);
  if (r == 1 || samples.points.empty()) return basis.col(0);
  const std::vector<std::array<int, 3>> indices = basis_indices(degree);
  const Eigen::Index n = Eigen::Index(samples.points.size());
  Eigen::MatrixXd values(n * Eigen::Index(kOffsets.size()), v.rows());
  Eigen::VectorXd rhs(values.rows());
  for (Eigen::Index k = 0; k < n; ++k) {
    for (std::size_t o = 0; o < kOffsets.size(); ++o) {
      const double lambda = kOffsets[o];
      const Point& p = samples.points[std::size_t(k)];
      const Point& nu = samples.normals[std::size_t(k)];
      const Eigen::Index row = k * Eigen::Index(kOffsets.size()) + Eigen::Index(o);
      values.row(row) =
          basis_row({p[0] + lambda * nu[0], p[1] + lambda * nu[1], p[2] + lambda * nu[2]}, degree, indices);
      // On the patch (λ = 0) the rows weigh ten times: q = 0 there comes first.
      const double weight = lambda == 0 ? 10.0 : 1.0;
      values.row(row) *= weight;
      rhs(row) = weight * lambda;
    }
  }
  const Eigen::VectorXd c = (values * basis).colPivHouseholderQr().solve(rhs);
  const Eigen::VectorXd b = basis * c;
  return b.norm() > 0 ? Eigen::VectorXd(b / b.norm()) : Eigen::VectorXd(basis.col(0));
}

}  // namespace implicitizer::approximation
