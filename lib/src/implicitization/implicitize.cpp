#include "implicitizer/implicitization/implicitize.hpp"

#include <chrono>
#include <span>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/try_within.hpp"
#include "implicitizer/groebner/elimination.hpp"
#include "implicitizer/implicitization/reproduce.hpp"
#include "implicitizer/implicitization/verify.hpp"
#include "implicitizer/polynomial/gcd.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/resultant/curve_resultant.hpp"

namespace implicitizer {

RingPtr space_ring() {
  static const RingPtr ring = Ring::make({"x", "y", "z"}, MonomialOrder::grevlex());
  return ring;
}

RingPtr plane_ring() {
  static const RingPtr ring = Ring::make({"x", "y"}, MonomialOrder::grevlex());
  return ring;
}

ImplicitizationMethod parse_implicitization_method(const std::string& name) {
  if (name == "auto") return ImplicitizationMethod::automatic;
  if (name == "groebner") return ImplicitizationMethod::groebner;
  if (name == "resultant") return ImplicitizationMethod::resultant;
  if (name == "interpolation") return ImplicitizationMethod::interpolation;
  throw InputError("unknown_method",
                   "unknown method '" + name + "' (expected auto, groebner, resultant or interpolation)");
}

namespace {

using Clock = std::chrono::steady_clock;

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

ImplicitizationIdeal implicitization_ideal(const Parametrization& p) {
  const Ring& params = *p.parameter_ring;
  const std::size_t k = params.num_variables();

  // Theorem 1.9 with L = lcm(q1, q2, q3) instead of q1·q2·q3: V(L) = V(q1·q2·q3), so
  // saturating by L removes the same points, and L has far smaller degree (NOTES.md:
  // 9.8 s against more than 300 s in Singular on a bidegree-(2,2) patch).
  Polynomial l = Polynomial::constant(p.parameter_ring, Rational(1));
  for (const auto& c : p.coordinates) l = lcm(l, c.denominator());
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

// The generator of the elimination ideal (Theorem 1.9 with the lcm).
ImplicitizeResult by_groebner(const Parametrization& p, const ImplicitizeParams& options) {
  const ImplicitizationIdeal ideal = implicitization_ideal(p);
  const std::size_t n = p.coordinates.size();
  const BuchbergerParams buchberger{options.buchberger, options.budget};
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

// The interpolation route (interpolation.hpp) limited to degrees ≤ max_degree:
// nullopt when the degree is proven higher (never with the default, the largest
// degree there is). The route verifies what it returns.
std::optional<ImplicitizeResult> by_interpolation_up_to(const Parametrization& p, std::int32_t max_degree,
                                                        const Budget& budget) {
  InterpolationParams interpolation;
  interpolation.budget = budget;
  std::optional<InterpolationResult> answer = implicitize_by_interpolation_up_to(p, max_degree, interpolation);
  if (!answer) return std::nullopt;
  ImplicitizeResult result;
  result.implicit = std::move(answer->implicit);
  result.method = "interpolation";
  result.verified = true;  // by substitution inside the route, which returns nothing else
  result.verify_ms = answer->stats.verify_ms;
  result.interpolation_stats = answer->stats;
  return result;
}

// The whole interpolation route.
ImplicitizeResult by_interpolation(const Parametrization& p, const Budget& budget) {
  return *by_interpolation_up_to(p, kMaxTotalDegree, budget);
}

// The Gröbner route modulo primes: the elimination ideal's basis lifted alone, and
// the one generator it should have proven to be the implicit equation (exact
// substitution, and check_implicit_equation's minimality: a one-dimensional kernel of
// the monomials of its degree at points of the image, and a hypersurface image;
// interpolation.hpp has the argument). nullopt where the lifted ideal has no single
// generator or the proof does not go through: the caller then runs Buchberger over ℚ.
std::optional<ImplicitizeResult> by_modular_groebner(const Parametrization& p, const ImplicitizeParams& options) {
  const ImplicitizationIdeal ideal = implicitization_ideal(p);
  const std::size_t n = p.coordinates.size();
  ModularGroebnerParams params;
  params.buchberger = {options.buchberger, options.budget};
  params.prove = false;
  params.lift_only_free_of_first = ideal.eliminated.size();
  ModularGroebnerStats stats;
  const EliminationResult elimination =
      eliminate_modular(ideal.generators, ideal.eliminated, params, MonomialOrder::grevlex(), &stats);
  if (elimination.elimination.size() != 1 || elimination.elimination.front().is_constant()) return std::nullopt;
  ImplicitizeResult result;
  const std::size_t identity[3] = {0, 1, 2};
  result.implicit = elimination.elimination.front().map_to(implicit_ring(n), std::span(identity, n)).primitive_part();
  const auto verify_start = Clock::now();
  InterpolationParams check;
  check.budget = options.budget;
  const ImplicitEquationCheck proof = check_implicit_equation(result.implicit, p, check);
  result.verify_ms = std::chrono::duration<double, std::milli>(Clock::now() - verify_start).count();
  if (!proof.vanishes || !proof.minimal) return std::nullopt;
  result.verified = true;
  result.method = "groebner";
  result.stats = elimination.groebner.stats;
  result.modular_stats = stats;
  return result;
}

// Verifies `result.implicit` by substitution (unless the route did) and fills the
// fields every route shares.
void finish(ImplicitizeResult& result, const Parametrization& p, const Budget& budget, Clock::time_point start) {
  result.degree = result.implicit.total_degree();
  if (!result.verified) {
    const auto verify_start = Clock::now();
    result.verified = substitutes_to_zero(result.implicit, p, budget);
    result.verify_ms = std::chrono::duration<double, std::milli>(Clock::now() - verify_start).count();
    if (!result.verified) {
      throw std::logic_error("internal error: the implicit equation " + to_string(result.implicit) +
                             " does not vanish on the parametrization");
    }
  }
  result.elapsed_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

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
    const auto verify_start = Clock::now();
    result.verified = is_power && substitutes_to_zero(result.implicit, p, budget);
    result.verify_ms = std::chrono::duration<double, std::milli>(Clock::now() - verify_start).count();
    if (result.verified) return result;
    if (aux.stats.determinant.proven) break;  // exact by construction: retrying cannot help
  }
  throw std::logic_error("internal error: the auxiliary resultant does not give the implicit equation");
}

AuxiliaryResultantParams resultant_options(const Budget& budget, std::size_t stable_primes) {
  AuxiliaryResultantParams options;
  options.budget = budget;
  options.stable_primes = stable_primes;
  return options;
}

// The resultant route for a surface whose formulation `plan` chose.
std::optional<ImplicitizeResult> by_resultant(const Parametrization& p, const AuxiliaryResultantPlan& plan,
                                              const Budget& budget, std::optional<AuxiliaryResultantStats>& stats) {
  return from_resultant(p, budget, stats, [&](std::size_t stable_primes) {
    return compute_auxiliary_resultant(plan, space_ring(), resultant_options(budget, stable_primes));
  });
}

// The resultant route for any input it applies to.
std::optional<ImplicitizeResult> by_resultant(const Parametrization& p, const Budget& budget,
                                              std::optional<AuxiliaryResultantStats>& stats) {
  const std::vector<Polynomial> f = common_denominator_form(p);
  if (p.coordinates.size() == 2) {
    return from_resultant(p, budget, stats, [&](std::size_t stable_primes) {
      return curve_auxiliary_resultant({f[0], f[1], f[2]}, plane_ring(), resultant_options(budget, stable_primes));
    });
  }
  const AuxiliaryResultantPlan plan = plan_auxiliary_resultant({f[0], f[1], f[2], f[3]}, resultant_options(budget, 1));
  return by_resultant(p, plan, budget, stats);
}

// Buchberger within a work allowance of `work` units (Budget::charge_work): nullopt
// when the allowance stops it, and when the term limit does (the routes that follow
// may fit it: interpolation's kernels have one term per column). The caller's own
// deadline, memory limit and cancellation still throw.
std::optional<ImplicitizeResult> groebner_within(const Parametrization& p, const ImplicitizeParams& options,
                                                 std::uint64_t work) {
  try {
    return try_within(options.budget, work, [&](const Budget& trial) {
      ImplicitizeParams limited = options;
      limited.budget = trial;
      return by_groebner(p, limited);
    });
  } catch (const LimitExceeded& e) {
    if (e.limit() != Limit::size) throw;
    return std::nullopt;
  }
}

// Seconds per modular operation of the determinant, for AuxiliaryResultantPlan's
// prediction: enneper's plan predicts about 7·10⁶ operations, and the resultant route
// took 15–20 ms on it in the runs of docs/benchmarks.md (2–3 ns each, verification
// included); the lower end is taken so that the head start stays short.
constexpr double kSecondsPerOperation = 2e-9;

// The degree up to which `auto` tries interpolation before anything else: its kernels
// have at most 35 columns, and it answers the benchmark's surfaces of degree ≤ 4 in
// 0.04–0.3 ms where Buchberger takes 0.8–3.0 ms on the dense ones (torus, Steiner,
// tri_quadratic, tp_21) and the resultant 0.7–1.2 ms (docs/benchmarks.md); above it,
// proving the degree higher costs the kernels of degree ≤ 4, about 0.2 ms.
constexpr std::int32_t kSmallDegree = 4;

// The largest degree bound for which `auto` prefers interpolation to Macaulay's
// resultant (triangular patches of degree 9: 220 columns; see where it is used).
constexpr std::int32_t kInterpolationOverMacaulay = 9;

// Interpolation's time as a share of Macaulay's quotient's at those degrees, for
// Buchberger's head start before it: 0.40 on tri_cubic, 0.60 on tri_cubic_rational
// (docs/benchmarks.md); the lower end keeps the head start short.
constexpr double kInterpolationShareOfMacaulay = 0.4;

// Buchberger's head start before interpolation when there is no resultant, in
// milliseconds of Buchberger's work: the sparse public surfaces finish within it
// (whitney_umbrella, bicubic_graph, cone_rational), the denser ones do not (the torus,
// Steiner's surface), which interpolation answers faster (docs/algorithms.md, rule 6).
constexpr double kBaseHeadStartMs = 0.5;

}  // namespace

ImplicitizeResult implicitize(const Parametrization& p, const ImplicitizeParams& options) {
  const auto start = Clock::now();
  const Budget& budget = options.budget;
  // The resultant route eliminates one parameter per coordinate but one: a surface
  // in two parameters, or a plane curve in one.
  const std::size_t coordinates = p.coordinates.size();
  const std::size_t parameters = p.parameter_ring->num_variables();
  const bool resultant_applies = parameters + 1 == coordinates;
  std::optional<AuxiliaryResultantStats> probe;
  if (options.method == ImplicitizationMethod::interpolation) {
    ImplicitizeResult result = by_interpolation(p, budget);
    finish(result, p, budget, start);
    return result;
  }
  if (options.method == ImplicitizationMethod::resultant) {
    if (!resultant_applies) {
      throw InputError("method_not_applicable", "the resultant method needs " + std::to_string(coordinates - 1) +
                                                    " parameter" + (coordinates == 2 ? "" : "s") + " for " +
                                                    std::to_string(coordinates) + " coordinates (this has " +
                                                    std::to_string(parameters) + ")");
    }
    auto result = by_resultant(p, budget, probe);
    if (!result && probe && probe->matrix_too_large && !(probe->dixon_vanishes && probe->macaulay_vanishes)) {
      throw LimitExceeded(Limit::size, "the auxiliary resultant's matrix would exceed " +
                                           std::to_string(kMaxResultantMatrixSize) +
                                           " rows for this degree; use method groebner or auto");
    }
    if (!result && coordinates == 2) {
      throw NoSingleEquation("no implicit curve: the image is a point", {});
    }
    if (!result) {
      throw NoSingleEquation(
          "the auxiliary resultant vanishes identically: the parametrization has base points (Theorem 1.14), "
          "both as a tensor-product patch on P1xP1 and as a triangular patch on P2; use method groebner or auto",
          {}, "base_points");
    }
    finish(*result, p, budget, start);
    return *result;
  }
  if (options.method == ImplicitizationMethod::automatic && coordinates == 3) {
    // Rule 2 of docs/algorithms.md: a surface of degree ≤ kSmallDegree by
    // interpolation, which proves a higher degree cheaply.
    try {
      if (auto small = by_interpolation_up_to(p, kSmallDegree, budget)) {
        small->route = "interpolation: the degree is at most " + std::to_string(kSmallDegree) + ", tried first";
        finish(*small, p, budget, start);
        return *small;
      }
    } catch (const NoSingleEquation&) {
      // Not a surface: Buchberger lists the generators of the elimination ideal.
      ImplicitizeResult result = by_groebner(p, options);
      finish(result, p, budget, start);
      return result;
    } catch (const LimitExceeded& e) {
      if (e.limit() != Limit::size) throw;  // a term limit below 35: the other routes may fit it
    }
  }
  if (options.method == ImplicitizationMethod::automatic && resultant_applies && coordinates == 2) {
    if (auto result = by_resultant(p, budget, probe)) {
      result->route = "resultant: a plane curve (Sylvester)";
      finish(*result, p, budget, start);
      return *result;
    }
  }
  if (options.method == ImplicitizationMethod::automatic && resultant_applies && coordinates == 3) {
    // Rules 3–5 of docs/algorithms.md (rule 6, base points, below). Dixon's
    // determinant (tensor-product patches) is never measurably slower than
    // Buchberger, so it is taken at once. Macaulay's (triangular patches) loses to
    // Buchberger on sparse inputs (enneper: 17 ms against 0.8 ms) and wins by orders
    // of magnitude on dense ones (tri_cubic: 40 ms against more than 60 s), and which
    // is which shows only by running: Buchberger gets a head start of half the
    // predicted time of what follows (at least 2 ms), then interpolation (degree
    // ≤ 9) or the resultant runs.
    // Before the probe (1–3 ms on a dense triangular patch: bicubic_graph's 153×153
    // Macaulay matrix), Buchberger's short head start answers the sparse ideals.
    if (auto quick = groebner_within(p, options, buchberger_work_of_milliseconds(kBaseHeadStartMs))) {
      quick->route = "groebner: Buchberger finished within its head start, before the resultant's probe";
      finish(*quick, p, budget, start);
      return *quick;
    }
    const std::vector<Polynomial> f = common_denominator_form(p);
    const AuxiliaryResultantPlan plan =
        plan_auxiliary_resultant({f[0], f[1], f[2], f[3]}, resultant_options(budget, 1));
    probe = plan.stats;
    if (plan.formulation == AuxiliaryFormulation::macaulay) {
      // Up to degree kInterpolationOverMacaulay, interpolation beats Macaulay's
      // quotient (tri_cubic 17 against 42 ms, tri_cubic_rational 30 against 50 ms);
      // at degree 16 it loses (tri_quartic 1.6 against 0.86 s). Buchberger's head
      // start is half the predicted time of the route that follows.
      const bool interpolation_next = implicit_degree_bound(p) <= kInterpolationOverMacaulay;
      const double next_seconds = plan.predicted_operations() * kSecondsPerOperation *
                                  (interpolation_next ? kInterpolationShareOfMacaulay : 1.0);
      const double head_start_ms = std::max(2.0, 0.5 * next_seconds * 1000);
      const std::uint64_t head_start = buchberger_work_of_milliseconds(head_start_ms);
      if (auto quick = groebner_within(p, options, head_start)) {
        quick->resultant_stats = probe;
        quick->route = "groebner: finished within its head start of " + std::to_string(head_start) +
                       " work units before " + (interpolation_next ? "interpolation" : "Macaulay's resultant");
        finish(*quick, p, budget, start);
        return *quick;
      }
      if (interpolation_next) {
        try {
          ImplicitizeResult result = by_interpolation(p, budget);
          result.resultant_stats = probe;
          result.route =
              "interpolation: Buchberger did not finish within its head start, and below degree 10 "
              "interpolation is faster than Macaulay's resultant";
          finish(result, p, budget, start);
          return result;
        } catch (const LimitExceeded& e) {
          if (e.limit() != Limit::size) throw;  // a term limit below its columns: the resultant may fit
        }
      }
    }
    if (plan.formulation) {
      if (auto result = by_resultant(p, plan, budget, probe)) {
        result->route = plan.formulation == AuxiliaryFormulation::dixon
                            ? "resultant: no base points on P1xP1 (Dixon)"
                            : "resultant: Buchberger did not finish within its head start (Macaulay)";
        finish(*result, p, budget, start);
        return *result;
      }
    }
  }
  if (options.method == ImplicitizationMethod::automatic) {
    // No resultant (base points, or another number of parameters). Rule 6 of
    // docs/algorithms.md, measured on the public surfaces (before rule 2 took those
    // of degree ≤ 4, the torus and Steiner's surface among them): sparse ideals are
    // Buchberger's (whitney_umbrella 0.19 ms, bicubic_graph 0.36 ms, against 0.41 and
    // 2.1 ms by interpolation), denser ones interpolation's (the torus 0.76 ms and
    // Steiner's surface 0.90 ms, against 3.4 and 2.7 ms), and only running tells
    // them apart: Buchberger gets a head start of kBaseHeadStartMs, then
    // interpolation runs; where its matrix would be too large, the modular
    // elimination; and Buchberger over ℚ with the whole budget where neither proves
    // an answer (it also lists the generators of an ideal that is not principal).
    const std::string why = resultant_applies ? "the auxiliary resultant vanishes (base points)"
                                              : "the resultant needs one parameter fewer than coordinates";
    // (With two parameters Buchberger already had its head start before the probe.)
    if (!(resultant_applies && coordinates == 3)) {
      if (auto quick = groebner_within(p, options, buchberger_work_of_milliseconds(kBaseHeadStartMs))) {
        quick->route = "groebner: " + why + "; Buchberger finished within its head start";
        finish(*quick, p, budget, start);
        return *quick;
      }
    }
    try {
      ImplicitizeResult result = by_interpolation(p, budget);
      result.resultant_stats = probe;
      result.route = "interpolation: " + why + "; Buchberger did not finish within its head start";
      finish(result, p, budget, start);
      return result;
    } catch (const LimitExceeded& e) {
      if (e.limit() != Limit::size) throw;  // time and cancellation are the caller's
      if (auto modular = by_modular_groebner(p, options)) {
        modular->resultant_stats = probe;
        modular->route = "groebner (modular): " + why + "; the interpolation matrix would be too large";
        finish(*modular, p, budget, start);
        return *modular;
      }
    } catch (const NoSingleEquation&) {
      // Interpolation proves that there is no single equation but lists no
      // generators: Buchberger below does.
    }
  } else if (options.modular_groebner) {
    if (auto modular = by_modular_groebner(p, options)) {
      finish(*modular, p, budget, start);
      return *modular;
    }
  }
  ImplicitizeResult result = by_groebner(p, options);
  result.resultant_stats = probe;
  if (options.method == ImplicitizationMethod::automatic) {
    result.route = resultant_applies ? "groebner: the auxiliary resultant vanishes (base points)"
                                     : "groebner: the resultant needs one parameter fewer than coordinates";
  }
  finish(result, p, budget, start);
  return result;
}

}  // namespace implicitizer
