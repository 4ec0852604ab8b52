#include "implicitizer/resultant/auxiliary_resultant.hpp"

#include <optional>
#include <stdexcept>

#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/resultant/dixon.hpp"
#include "implicitizer/resultant/macaulay.hpp"

namespace implicitizer {

const char* to_string(AuxiliaryFormulation formulation) {
  switch (formulation) {
    case AuxiliaryFormulation::dixon:
      return "dixon";
    case AuxiliaryFormulation::macaulay:
      return "macaulay";
    case AuxiliaryFormulation::sylvester:
      return "sylvester";
  }
  return "?";
}

namespace {

// A candidate formulation: its pencil, minor and degree bound.
struct Candidate {
  AuxiliaryFormulation formulation;
  MatrixPencil matrix;
  std::vector<std::size_t> minor;
  std::int32_t degree_bound;
};

double cube(double n) { return n * n * n; }

}  // namespace

double AuxiliaryResultantPlan::predicted_operations() const {
  if (!formulation) return 0;
  double points = 1;  // C(D + 3, 3), the lattice
  for (int i = 1; i <= 3; ++i) points = points * (degree_bound + i) / i;
  const double primes = minor.empty() ? static_cast<double>(matrix.determinant_coefficient_bits()) / 62 + 1 : 2;
  return points * (cube(static_cast<double>(matrix.size())) + cube(static_cast<double>(minor.size()))) / 3 * primes;
}

namespace {

// Both formulations whose matrix is small enough, the smaller degree bound first;
// marks `stats.matrix_too_large` for the others. A parametrization that does not
// involve both parameters has m = 0 or n = 0: its image is not a surface and both
// resultants vanish, which the caller reports.
std::vector<Candidate> formulations(const std::array<Polynomial, 4>& wxyz, AuxiliaryResultantStats& stats) {
  const std::int32_t m = stats.bidegree_s, n = stats.bidegree_t, d = stats.total_degree;
  std::vector<Candidate> candidates;
  if (m < 1 || n < 1) return candidates;
  const auto dixon_size = static_cast<std::size_t>(2 * m * n);
  const auto macaulay_size = static_cast<std::size_t>((3 * d - 1) * 3 * d / 2);  // C(3d, 2)
  if (dixon_size <= kMaxResultantMatrixSize) {
    candidates.push_back({AuxiliaryFormulation::dixon, dixon_pencil(wxyz, m, n), {}, 2 * m * n});
  } else {
    stats.matrix_too_large = true;
  }
  if (macaulay_size <= kMaxResultantMatrixSize) {
    MacaulayPencil macaulay = macaulay_pencil(wxyz, d);
    candidates.push_back(
        {AuxiliaryFormulation::macaulay, std::move(macaulay.matrix), std::move(macaulay.extraneous), d * d});
  } else {
    stats.matrix_too_large = true;
  }
  if (candidates.size() == 2 && candidates[1].degree_bound < candidates[0].degree_bound) {
    std::swap(candidates[0], candidates[1]);
  }
  return candidates;
}

}  // namespace

AuxiliaryResultantPlan plan_auxiliary_resultant(const std::array<Polynomial, 4>& input,
                                                const AuxiliaryResultantParams& options) {
  const Stopwatch timer;
  // One common integer factor for ω, ξ, η, ζ (the resultant changes by a constant).
  std::array<Polynomial, 4> wxyz = input;
  scale_to_integers(wxyz);
  AuxiliaryResultantPlan plan;
  auto& stats = plan.stats;
  for (const auto& p : wxyz) {
    if (p.ring()->num_variables() != 2) throw std::invalid_argument("auxiliary_resultant: two parameters expected");
    stats.bidegree_s = std::max(stats.bidegree_s, p.degree_in(0));
    stats.bidegree_t = std::max(stats.bidegree_t, p.degree_in(1));
    stats.total_degree = std::max(stats.total_degree, p.total_degree());
  }
  std::vector<Candidate> candidates = formulations(wxyz, stats);
  // Every formulation is probed, even after one is found usable: which of P¹×P¹ and
  // P² carry base points is worth reporting, and a probe costs one determinant. One
  // random point modulo a 62-bit prime suffices: a non-zero polynomial of degree D
  // vanishes there with probability at most D / 2^62.
  std::optional<std::size_t> chosen;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    options.budget.check("auxiliary resultant");
    const PencilProbe probe = probe_pencil_determinant(candidates[i].matrix, candidates[i].minor, /*seed=*/0x5eed,
                                                       /*trials=*/1, options.budget);
    if (probe == PencilProbe::nonzero) {
      if (!chosen) chosen = i;
    } else if (candidates[i].formulation == AuxiliaryFormulation::dixon) {
      stats.dixon_vanishes = true;
    } else {
      // Zero, or Macaulay's extraneous minor vanishing identically: either way this
      // formulation cannot give the resultant.
      stats.macaulay_vanishes = true;
    }
  }
  if (candidates.empty() && !stats.matrix_too_large) stats.dixon_vanishes = stats.macaulay_vanishes = true;
  if (chosen) {
    Candidate& c = candidates[*chosen];
    plan.formulation = c.formulation;
    stats.formulation = c.formulation;
    stats.matrix_size = c.matrix.size();
    stats.extraneous_size = c.minor.size();
    stats.degree_bound = c.degree_bound;
    plan.degree_bound = c.degree_bound;
    plan.matrix = std::move(c.matrix);
    plan.minor = std::move(c.minor);
  }
  stats.construction_ms = timer.elapsed_ms();
  return plan;
}

AuxiliaryResultant compute_auxiliary_resultant(const AuxiliaryResultantPlan& plan, const RingPtr& space,
                                               const AuxiliaryResultantParams& options) {
  if (space->num_variables() != 3) throw std::invalid_argument("auxiliary_resultant: the space ring needs x, y, z");
  AuxiliaryResultant result{Polynomial(space), plan.stats};
  if (!plan.formulation) return result;
  PencilDeterminantParams determinant;
  determinant.degree_bound = plan.degree_bound;
  determinant.divisor_minor = plan.minor;
  if (plan.minor.empty()) determinant.proven_bits = plan.matrix.determinant_coefficient_bits();
  determinant.threads = options.threads;
  determinant.stable_primes = options.stable_primes;
  determinant.budget = options.budget;
  const Stopwatch determinant_timer;
  result.resultant = pencil_determinant(plan.matrix, space, determinant, &result.stats.determinant);
  result.stats.determinant_ms = determinant_timer.elapsed_ms();
  return result;
}

AuxiliaryResultant auxiliary_resultant(const std::array<Polynomial, 4>& wxyz, const RingPtr& space,
                                       const AuxiliaryResultantParams& options) {
  if (space->num_variables() != 3) throw std::invalid_argument("auxiliary_resultant: the space ring needs x, y, z");
  return compute_auxiliary_resultant(plan_auxiliary_resultant(wxyz, options), space, options);
}

}  // namespace implicitizer
