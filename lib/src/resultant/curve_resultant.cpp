#include "implicitizer/resultant/curve_resultant.hpp"

#include <stdexcept>

#include "implicitizer/core/stopwatch.hpp"

namespace implicitizer {

MatrixPencil curve_sylvester_pencil(const std::array<Polynomial, 3>& wxy) {
  std::int32_t n = 0;
  for (const auto& p : wxy) {
    if (p.ring()->num_variables() != 1) throw std::invalid_argument("curve_sylvester_pencil: one parameter expected");
    n = std::max(n, p.total_degree());
  }
  if (n < 1) throw std::invalid_argument("curve_sylvester_pencil: the curve must involve its parameter");
  const auto size = static_cast<std::size_t>(2 * n);
  MatrixPencil pencil(size, 2);
  const Ring& ring = *wxy[0].ring();
  // Row `row` holds t^shift·(numerator − u·ω); column c is the power t^(2n−1−c).
  auto place = [&](std::size_t row, std::int32_t shift, const Polynomial& numerator, std::size_t part) {
    auto column = [&](std::int32_t exponent) { return static_cast<std::size_t>(2 * n - 1 - (exponent + shift)); };
    for (std::size_t t = 0; t < numerator.num_terms(); ++t) {
      pencil.at(0, row, column(ring.exponents(numerator.monomial(t))[0])) = to_integer(numerator.coefficient(t));
    }
    for (std::size_t t = 0; t < wxy[0].num_terms(); ++t) {
      pencil.at(part, row, column(ring.exponents(wxy[0].monomial(t))[0])) = -to_integer(wxy[0].coefficient(t));
    }
  };
  for (std::int32_t i = 0; i < n; ++i) {
    place(static_cast<std::size_t>(i), n - 1 - i, wxy[1], 1);
    place(static_cast<std::size_t>(n + i), n - 1 - i, wxy[2], 2);
  }
  return pencil;
}

AuxiliaryResultant curve_auxiliary_resultant(const std::array<Polynomial, 3>& input, const RingPtr& plane,
                                             const AuxiliaryResultantParams& options) {
  const Stopwatch timer;
  if (plane->num_variables() != 2) throw std::invalid_argument("curve_auxiliary_resultant: the plane ring needs x, y");
  // One common integer factor for ω, ξ, η (the resultant changes by a constant).
  std::array<Polynomial, 3> wxy = input;
  scale_to_integers(wxy);

  AuxiliaryResultant result{Polynomial(plane), {}};
  auto& stats = result.stats;
  stats.formulation = AuxiliaryFormulation::sylvester;
  for (const auto& p : wxy) stats.total_degree = std::max(stats.total_degree, p.total_degree());
  if (stats.total_degree < 1) return result;  // a point
  // The pencil has 3·(2n)² integers and its determinant C(n + 2, 2) evaluations:
  // refused before it is built when they cannot end in time (n = 1000: 12 M entries).
  const auto n = static_cast<std::size_t>(stats.total_degree);
  refuse_determinants_past_deadline(2 * n, (n + 1) * (n + 2) / 2 + 1, options.budget);
  const MatrixPencil pencil = curve_sylvester_pencil(wxy);
  stats.matrix_size = pencil.size();
  stats.degree_bound = stats.total_degree;
  stats.construction_ms = timer.elapsed_ms();
  PencilDeterminantParams determinant;
  determinant.degree_bound = stats.degree_bound;
  determinant.proven_bits = pencil.determinant_coefficient_bits();
  determinant.threads = options.threads;
  determinant.budget = options.budget;
  const Stopwatch determinant_timer;
  result.resultant = pencil_determinant(pencil, plane, determinant, &stats.determinant);
  stats.determinant_ms = determinant_timer.elapsed_ms();
  return result;
}

}  // namespace implicitizer
