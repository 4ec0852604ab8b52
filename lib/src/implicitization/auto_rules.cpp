#include "auto_rules.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicit_support.hpp"
#include "implicitizer/implicitization/interpolation.hpp"
#include "implicitizer/implicitization/sparse_interpolation.hpp"
#include "routes.hpp"

namespace implicitizer {
namespace {

// The constants of the rules; docs/algorithms.md ("`auto`") has the measurements
// behind each, under the rule's number.

/// Rule 2: the degree up to which interpolation goes first (kernels of at most 35
/// columns, which also prove a higher degree cheaply).
constexpr std::int32_t kSmallDegree = 4;
/// Rule 3b: the predicted support is taken when its kernels cost at most this share of
/// the dense kernel at the degree bound (in cubed columns, the row reductions' cost):
/// at 1/7 (enneper, 4 classes of 66 against 220) Buchberger's head start of rule 5
/// answers first and faster (docs/algorithms.md).
constexpr double kSparseShareOfDense = 1.0 / 64;
/// Rules 3 and 6: Buchberger's head start, in milliseconds of its work, before the
/// probe (two parameters) or before interpolation (no resultant).
constexpr double kBaseHeadStartMs = 0.5;
/// Rule 5: the largest degree bound at which interpolation goes before Macaulay's
/// quotient.
constexpr std::int32_t kInterpolationOverMacaulay = 9;
/// Rule 5: seconds per modular operation of the determinant, for the plan's
/// prediction (the lower end of the measured range, so that head starts stay short).
constexpr double kSecondsPerOperation = 2e-9;
/// Rule 5: interpolation's time as a share of Macaulay's quotient's below
/// kInterpolationOverMacaulay (the lower end of the measured range).
constexpr double kInterpolationShareOfMacaulay = 0.4;
/// Rule 5: Buchberger's head start is this share of the predicted time of the route
/// that follows, and at least kMinHeadStartMs.
constexpr double kHeadStartShare = 0.5;
constexpr double kMinHeadStartMs = 2.0;

/// What the rules know of the input and learn as they pass.
struct AutoState {
  const Parametrization& p;
  const ImplicitizeParams& params;
  std::size_t coordinates = 0;
  bool resultant_applies = false;
  /// Rule 3's probe of a surface in two parameters: the auxiliary resultant's
  /// formulation and matrix (resultant_plan()).
  std::optional<AuxiliaryResultantPlan> plan;
  /// The probe's statistics, or those of a resultant that vanished: every later
  /// route reports them.
  std::optional<AuxiliaryResultantStats> probe;
  /// Rule 6: interpolation's matrix would pass the size limit.
  bool interpolation_too_large = false;
};

using Answer = std::optional<ImplicitizeResult>;

/// A rule answers, or passes (nullopt) to the next.
using Rule = Answer (*)(AutoState&);

Answer with_route(Answer answer, std::string route) {
  if (answer) answer->route = std::move(route);
  return answer;
}

// The routes hold different polynomials (Buchberger's intermediate ones,
// interpolation's kernels with one term per column), so a term limit that stops one
// route may not stop the next: a rule the size limit stops passes. Time, memory and
// cancellation are the caller's and stop everything.
template <typename Attempt>
Answer passing_size_limit(Attempt attempt) {
  try {
    return attempt();
  } catch (const LimitExceeded& e) {
    if (e.limit() != Limit::size) throw;
    return std::nullopt;
  }
}

/// Buchberger within a head start of `work` units (docs/algorithms.md, "Head starts
/// in units of work").
Answer buchberger_head_start(const AutoState& s, std::uint64_t work) {
  return passing_size_limit([&] { return groebner_route_within(s.p, s.params, work); });
}

bool is_surface_in_two_parameters(const AutoState& s) { return s.coordinates == 3 && s.resultant_applies; }

/// The probe (rules 3–5), made the first time a rule asks.
const AuxiliaryResultantPlan& resultant_plan(AutoState& s) {
  if (!s.plan) {
    const std::vector<Polynomial> f = common_denominator_form(s.p, s.params.budget);
    s.plan = plan_auxiliary_resultant({f[0], f[1], f[2], f[3]}, resultant_params(s.params.budget, 1));
    s.probe = s.plan->stats;
  }
  return *s.plan;
}

bool is_triangular_patch(AutoState& s) {
  return is_surface_in_two_parameters(s) && resultant_plan(s).formulation == AuxiliaryFormulation::macaulay;
}

bool interpolation_before_macaulay(const AutoState& s) {
  return implicit_degree_bound(s.p, s.params.budget) <= kInterpolationOverMacaulay;
}

std::string why_no_resultant(const AutoState& s) {
  return s.resultant_applies ? "the auxiliary resultant vanishes (base points)"
                             : "the resultant needs one parameter fewer than coordinates";
}

/// Rule 1: a plane curve by Sylvester's resultant.
Answer plane_curve_by_sylvester(AutoState& s) {
  if (s.coordinates != 2 || !s.resultant_applies) return std::nullopt;
  return with_route(resultant_route(s.p, s.params.budget, s.probe), "resultant: a plane curve (Sylvester)");
}

/// Rule 2: a surface of degree ≤ kSmallDegree by interpolation.
Answer small_degree_by_interpolation(AutoState& s) {
  if (s.coordinates != 3) return std::nullopt;
  try {
    return with_route(passing_size_limit([&] { return interpolation_route_up_to(s.p, kSmallDegree, s.params.budget); }),
                      "interpolation: the degree is at most " + std::to_string(kSmallDegree) + ", tried first");
  } catch (const NoSingleEquation&) {
    // Not a surface: Buchberger lists the generators of the elimination ideal.
    return groebner_route(s.p, s.params);
  }
}

/// Rule 3: Buchberger's short head start before the probe, which answers the sparse
/// ideals of surfaces in two parameters.
Answer buchberger_before_probe(AutoState& s) {
  if (!is_surface_in_two_parameters(s)) return std::nullopt;
  return with_route(buchberger_head_start(s, buchberger_work_of_milliseconds(kBaseHeadStartMs)),
                    "groebner: Buchberger finished within its head start, before the resultant's probe");
}

/// Rule 3b: a sparse surface in two parameters by interpolation on its predicted
/// support (implicit_support.hpp), when that is far cheaper than the dense kernels.
/// Passes when the prediction does not give the equation (a map of degree > 1).
Answer sparse_support_by_interpolation(AutoState& s) {
  if (!is_surface_in_two_parameters(s)) return std::nullopt;
  const std::optional<ImplicitSupport> support = predict_implicit_support(s.p, s.params.budget);
  if (!support || support->largest_class > InterpolationParams{}.max_columns) return std::nullopt;
  const double dense = space_monomial_count(implicit_degree_bound(s.p, s.params.budget));
  if (support->cubed_columns > std::min(kSparseMaxCubedColumns, kSparseShareOfDense * dense * dense * dense)) {
    return std::nullopt;
  }
  return with_route(passing_size_limit([&] { return sparse_interpolation_route(s.p, *support, s.params.budget); }),
                    "interpolation on the predicted support: " + std::to_string(support->classes.size()) +
                        " classes of at most " + std::to_string(support->largest_class) + " monomials instead of " +
                        std::to_string(static_cast<std::size_t>(dense)) + " dense ones");
}

/// Rule 5, first: a triangular patch gives Buchberger a head start of a share of the
/// predicted time of what follows (interpolation or Macaulay's quotient).
Answer buchberger_before_macaulay(AutoState& s) {
  if (!is_triangular_patch(s)) return std::nullopt;
  const bool interpolation_next = interpolation_before_macaulay(s);
  const double next_seconds = s.plan->predicted_operations() * kSecondsPerOperation *
                              (interpolation_next ? kInterpolationShareOfMacaulay : 1.0);
  const double head_start_ms = std::max(kMinHeadStartMs, kHeadStartShare * next_seconds * 1000);
  const std::uint64_t head_start = buchberger_work_of_milliseconds(head_start_ms);
  Answer quick = buchberger_head_start(s, head_start);
  if (quick) quick->resultant_stats = s.probe;
  return with_route(std::move(quick), "groebner: finished within its head start of " + std::to_string(head_start) +
                                          " work units before " +
                                          (interpolation_next ? "interpolation" : "Macaulay's resultant"));
}

/// Rule 5, then: interpolation for a triangular patch of low degree.
Answer triangular_patch_by_interpolation(AutoState& s) {
  if (!is_triangular_patch(s) || !interpolation_before_macaulay(s)) return std::nullopt;
  Answer result = passing_size_limit([&] { return interpolation_route(s.p, s.params.budget); });
  if (result) result->resultant_stats = s.probe;
  return with_route(std::move(result),
                    "interpolation: Buchberger did not finish within its head start, and below degree 10 "
                    "interpolation is faster than Macaulay's resultant");
}

/// Rules 4 and 5, last: the resultant, whenever some formulation does not vanish
/// (Dixon's at once, Macaulay's after the rules above).
Answer resultant_without_base_points(AutoState& s) {
  if (!is_surface_in_two_parameters(s) || !resultant_plan(s).formulation) return std::nullopt;
  const bool dixon = s.plan->formulation == AuxiliaryFormulation::dixon;
  return with_route(resultant_route(s.p, *s.plan, s.params.budget, s.probe),
                    dixon ? "resultant: no base points on P1xP1 (Dixon)"
                          : "resultant: Buchberger did not finish within its head start (Macaulay)");
}

/// Rule 6, first: without a resultant, Buchberger's short head start (with two
/// parameters it already had it, rule 3).
Answer buchberger_without_resultant(AutoState& s) {
  if (is_surface_in_two_parameters(s)) return std::nullopt;
  return with_route(buchberger_head_start(s, buchberger_work_of_milliseconds(kBaseHeadStartMs)),
                    "groebner: " + why_no_resultant(s) + "; Buchberger finished within its head start");
}

/// Rule 6, then: interpolation.
Answer interpolation_without_resultant(AutoState& s) {
  try {
    ImplicitizeResult result = interpolation_route(s.p, s.params.budget);
    result.resultant_stats = s.probe;
    result.route = "interpolation: " + why_no_resultant(s) + "; Buchberger did not finish within its head start";
    return result;
  } catch (const LimitExceeded& e) {
    if (e.limit() != Limit::size) throw;
    s.interpolation_too_large = true;
  } catch (const NoSingleEquation&) {
    // Proven not a surface, but without the generators: the last rule lists them.
  }
  return std::nullopt;
}

/// Rule 6, where interpolation's matrix is too large: the modular elimination.
Answer modular_groebner_where_interpolation_too_large(AutoState& s) {
  if (!s.interpolation_too_large) return std::nullopt;
  Answer modular = modular_groebner_route(s.p, s.params);
  if (modular) modular->resultant_stats = s.probe;
  return with_route(std::move(modular),
                    "groebner (modular): " + why_no_resultant(s) + "; the interpolation matrix would be too large");
}

/// Rule 6, last: Buchberger over ℚ with the whole budget, which also lists the
/// generators of an ideal that is not principal. Always answers or throws.
Answer buchberger_over_rationals(AutoState& s) {
  ImplicitizeResult result = groebner_route(s.p, s.params);
  result.resultant_stats = s.probe;
  result.route = "groebner: " + why_no_resultant(s);
  return result;
}

/// The rules in the order they are tried (docs/algorithms.md numbers them).
constexpr Rule kRules[] = {
    plane_curve_by_sylvester,        small_degree_by_interpolation,
    buchberger_before_probe,         sparse_support_by_interpolation,
    buchberger_before_macaulay,      triangular_patch_by_interpolation,
    resultant_without_base_points,   buchberger_without_resultant,
    interpolation_without_resultant, modular_groebner_where_interpolation_too_large,
    buchberger_over_rationals,
};

}  // namespace

ImplicitizeResult implicitize_automatically(const Parametrization& parametrization, const ImplicitizeParams& params) {
  AutoState state{
      parametrization, params, parametrization.coordinates.size(), resultant_applies(parametrization), {}, {}, false};
  for (const Rule rule : kRules) {
    if (Answer answer = rule(state)) return std::move(*answer);
  }
  throw std::logic_error("internal error: no rule of method auto answered");
}

}  // namespace implicitizer
