#include "routes.hpp"

#include <span>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/core/try_within.hpp"
#include "implicitizer/groebner/elimination.hpp"
#include "implicitizer/implicitization/sparse_interpolation.hpp"
#include "implicitizer/implicitization/verify.hpp"
#include "implicitizer/polynomial/gcd.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/resultant/curve_resultant.hpp"

namespace implicitizer {

namespace {

// A name for the saturation variable that no parameter uses.
std::string fresh_name(const Ring& params) {
  std::string name = "w";
  while (params.index_of(name)) name += "_";
  return name;
}

// The ideal of Theorem 1.9 (with the lcm of the denominators) in [w?, params, x, y, z]
// and the variables to eliminate.
struct ImplicitizationIdeal {
  std::vector<Polynomial> generators;
  std::vector<std::string> eliminated;
};

ImplicitizationIdeal implicitization_ideal(const Parametrization& p, const Budget& budget) {
  const Ring& params = *p.parameter_ring;
  const std::size_t k = params.num_variables();

  // Theorem 1.9 with L = lcm(q1, q2, q3) instead of q1·q2·q3: V(L) = V(q1·q2·q3), so
  // saturating by L removes the same points, and L has far smaller degree (NOTES.md:
  // 9.8 s against more than 300 s in Singular on a bidegree-(2,2) patch).
  const Polynomial l = common_denominator(p, budget);
  const bool saturate = !l.is_constant();

  // Ring [w?, parameters, x, y, z]; eliminate() orders it by an elimination order for
  // w and the parameters (Singular's (a(1,..,1,0,0,0),dp)).
  std::vector<std::string> names;
  std::vector<std::string> eliminated;
  if (saturate) names.push_back(fresh_name(params));
  names.insert(names.end(), params.variables().begin(), params.variables().end());
  eliminated = names;
  const std::size_t n = p.coordinates.size();
  for (const auto& v : coordinate_names(n)) names.push_back(v);
  RingPtr ring = Ring::make(names);
  const std::size_t offset = saturate ? 1 : 0;
  std::vector<std::size_t> param_map(k);
  for (std::size_t i = 0; i < k; ++i) param_map[i] = offset + i;

  std::vector<Polynomial> generators;
  for (std::size_t v = 0; v < n; ++v) {
    const auto& c = p.coordinates[v];
    const Polynomial space_variable = Polynomial::variable(ring, offset + k + v);
    generators.push_back(c.denominator().map_to(ring, param_map) * space_variable -
                         c.numerator().map_to(ring, param_map));
  }
  if (saturate) {
    generators.push_back(Polynomial::constant(ring, Rational(1)) -
                         l.map_to(ring, param_map) * Polynomial::variable(ring, 0));
  }
  return {std::move(generators), std::move(eliminated)};
}

}  // namespace

bool resultant_applies(const Parametrization& p) {
  return p.parameter_ring->num_variables() + 1 == p.coordinates.size();
}

ImplicitizeResult groebner_route(const Parametrization& p, const ImplicitizeParams& params) {
  const ImplicitizationIdeal ideal = implicitization_ideal(p, params.budget);
  const std::size_t n = p.coordinates.size();
  const BuchbergerParams buchberger{params.buchberger, params.budget};
  const EliminationResult elimination = eliminate(ideal.generators, ideal.eliminated, buchberger);
  const auto& gens = elimination.elimination;
  if (gens.size() != 1 || gens.front().is_constant()) {
    std::vector<std::string> printed;
    for (const auto& g : gens) printed.push_back(to_string(g.primitive_part()));
    const std::string space = n == 3 ? "space" : "the plane";
    const std::string kind = n == 3 ? "a surface" : "a curve";
    if (gens.empty()) {
      throw NoSingleEquation(
          "no implicit equation: the image is dense in " + space + " (the elimination ideal is zero)", printed);
    }
    throw NoSingleEquation("no single implicit equation: the image is not " + kind + " (the elimination ideal needs " +
                               std::to_string(gens.size()) + " generators)",
                           printed);
  }

  ImplicitizeResult result;
  const std::size_t identity[3] = {0, 1, 2};
  result.implicit = gens.front().map_to(implicit_ring(n), std::span(identity, n)).primitive_part();
  result.method = "groebner";
  result.stats = elimination.groebner.stats;
  return result;
}

std::optional<ImplicitizeResult> groebner_route_within(const Parametrization& p, const ImplicitizeParams& params,
                                                       std::uint64_t work) {
  return try_within(params.budget, work, [&](const Budget& trial) {
    ImplicitizeParams limited = params;
    limited.budget = trial;
    return groebner_route(p, limited);
  });
}

std::optional<ImplicitizeResult> modular_groebner_route(const Parametrization& p, const ImplicitizeParams& params) {
  const ImplicitizationIdeal ideal = implicitization_ideal(p, params.budget);
  const std::size_t n = p.coordinates.size();
  ModularGroebnerParams modular;
  modular.buchberger = {params.buchberger, params.budget};
  modular.prove = false;
  // F4 modulo each prime: faster than Buchberger modulo p on every surface that takes
  // more than a second (the run is in the history of docs/benchmarks.md).
  modular.algorithm = ModularAlgorithm::f4;
  modular.lift_only_free_of_first = ideal.eliminated.size();
  ModularGroebnerStats stats;
  const EliminationResult elimination =
      eliminate_modular(ideal.generators, ideal.eliminated, modular, MonomialOrder::grevlex(), &stats);
  if (elimination.elimination.size() != 1 || elimination.elimination.front().is_constant()) return std::nullopt;
  ImplicitizeResult result;
  const std::size_t identity[3] = {0, 1, 2};
  result.implicit = elimination.elimination.front().map_to(implicit_ring(n), std::span(identity, n)).primitive_part();
  const Stopwatch verify_timer;
  InterpolationParams check;
  check.budget = params.budget;
  const ImplicitEquationCheck proof = check_implicit_equation(result.implicit, p, check);
  result.verify_ms = verify_timer.elapsed_ms();
  if (!proof.vanishes || !proof.minimal) return std::nullopt;
  result.verified = true;
  result.method = "groebner";
  result.stats = elimination.groebner.stats;
  result.modular_stats = stats;
  return result;
}

namespace {

// An interpolation route's answer, which the route verified (it returns nothing else).
std::optional<ImplicitizeResult> from_interpolation(std::optional<InterpolationResult> answer) {
  if (!answer) return std::nullopt;
  ImplicitizeResult result;
  result.implicit = std::move(answer->implicit);
  result.method = "interpolation";
  result.verified = true;
  result.verify_ms = answer->stats.verify_ms;
  result.interpolation_stats = answer->stats;
  return result;
}

}  // namespace

std::optional<ImplicitizeResult> interpolation_route_up_to(const Parametrization& p, std::int32_t max_degree,
                                                           const Budget& budget) {
  InterpolationParams interpolation;
  interpolation.budget = budget;
  return from_interpolation(implicitize_by_interpolation_up_to(p, max_degree, interpolation));
}

std::optional<ImplicitizeResult> sparse_interpolation_route(const Parametrization& p, const ImplicitSupport& support,
                                                            const Budget& budget) {
  InterpolationParams interpolation;
  interpolation.budget = budget;
  return from_interpolation(implicitize_by_sparse_interpolation(p, support, interpolation));
}

ImplicitizeResult interpolation_route(const Parametrization& p, const Budget& budget) {
  // Where the dense matrix at the degree bound would pass its column limit (the dense
  // route may still find a lower degree below it, or refuse), a predicted support
  // that fits is tried first: sparse_s7t7 (degree 49) answers in 0.3 s instead of a
  // refusal.
  const std::size_t max_columns = InterpolationParams{}.max_columns;
  if (p.coordinates.size() == 3 &&
      space_monomial_count(implicit_degree_bound(p, budget)) > static_cast<double>(max_columns)) {
    const std::optional<ImplicitSupport> support = predict_implicit_support(p, budget);
    if (support && support->largest_class <= max_columns && support->cubed_columns <= kSparseMaxCubedColumns) {
      if (auto sparse = sparse_interpolation_route(p, *support, budget)) return std::move(*sparse);
    }
  }
  // Never nullopt: no degree is above the largest there is.
  return *interpolation_route_up_to(p, kMaxTotalDegree, budget);
}

namespace {

// Theorem 1.13: Res_aux = c·f^l, so f is the square-free part, taken with respect to
// a variable Res_aux involves. `compute(stable_primes)` computes Res_aux. Returns
// nullopt (with the stats in `stats`) when Res_aux vanishes identically.
template <typename Compute>
std::optional<ImplicitizeResult> from_resultant(const Parametrization& p, const Budget& budget,
                                                std::optional<AuxiliaryResultantStats>& stats, Compute compute) {
  // Macaulay's quotient stops at the first prime that confirms the previous ones;
  // if the answer then fails Theorem 1.12 or the substitution, it is recomputed
  // with more confirming primes before anything is called a bug.
  for (std::size_t stable_primes : {std::size_t{1}, std::size_t{4}}) {
    const AuxiliaryResultant aux = compute(stable_primes);
    stats = aux.stats;
    if (aux.resultant.is_zero()) return std::nullopt;
    const Polynomial& r = aux.resultant;
    if (r.is_constant()) {
      throw NoSingleEquation("no implicit equation: the auxiliary resultant is a non-zero constant", {});
    }
    std::size_t var = 0;
    while (!r.involves(var)) ++var;
    ImplicitizeResult result;
    result.implicit = square_free_part(r, var);
    result.method = "resultant";
    result.resultant_stats = aux.stats;
    result.map_degree = r.total_degree() / result.implicit.total_degree();
    // Theorem 1.12: Res_aux is exactly c·f^l.
    const bool is_power =
        result.implicit.pow(static_cast<unsigned>(result.map_degree), budget).primitive_part() == r.primitive_part();
    const Stopwatch verify_timer;
    result.verified = is_power && substitutes_to_zero(result.implicit, p, budget);
    result.verify_ms = verify_timer.elapsed_ms();
    if (result.verified) return result;
    if (aux.stats.determinant.proven) break;  // exact by construction: retrying cannot help
  }
  throw std::logic_error("internal error: the auxiliary resultant does not give the implicit equation");
}

}  // namespace

AuxiliaryResultantParams resultant_params(const Budget& budget, std::size_t stable_primes) {
  AuxiliaryResultantParams options;
  options.budget = budget;
  options.stable_primes = stable_primes;
  return options;
}

std::optional<ImplicitizeResult> resultant_route(const Parametrization& p, const AuxiliaryResultantPlan& plan,
                                                 const Budget& budget, std::optional<AuxiliaryResultantStats>& stats) {
  return from_resultant(p, budget, stats, [&](std::size_t stable_primes) {
    return compute_auxiliary_resultant(plan, space_ring(), resultant_params(budget, stable_primes));
  });
}

std::optional<ImplicitizeResult> resultant_route(const Parametrization& p, const Budget& budget,
                                                 std::optional<AuxiliaryResultantStats>& stats) {
  const std::vector<Polynomial> f = common_denominator_form(p, budget);
  if (p.coordinates.size() == 2) {
    return from_resultant(p, budget, stats, [&](std::size_t stable_primes) {
      return curve_auxiliary_resultant({f[0], f[1], f[2]}, plane_ring(), resultant_params(budget, stable_primes));
    });
  }
  const AuxiliaryResultantPlan plan = plan_auxiliary_resultant({f[0], f[1], f[2], f[3]}, resultant_params(budget, 1));
  return resultant_route(p, plan, budget, stats);
}

}  // namespace implicitizer
