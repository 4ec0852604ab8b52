#pragma once
/// \file
/// The routes of implicitize(): each turns a parametrization into an implicit equation
/// its own way. implicitize.cpp dispatches an explicit method to one of them; auto's
/// rules (auto_rules.hpp) choose among them. A route proves its own answer where it
/// says so (`verified`); implicitize() substitutes the others.

#include <cstdint>
#include <optional>

#include "implicitizer/implicitization/implicit_support.hpp"
#include "implicitizer/implicitization/implicitize.hpp"

namespace implicitizer {

/// Whether the resultant route applies: one parameter fewer than coordinates (a
/// surface in two parameters, a plane curve in one).
bool resultant_applies(const Parametrization& parametrization);

/// The generator of the elimination ideal (Theorem 1.9 with the lcm of the
/// denominators), by Buchberger over ℚ. Throws NoSingleEquation, listing the
/// generators, when the ideal is zero or needs several.
ImplicitizeResult groebner_route(const Parametrization& parametrization, const ImplicitizeParams& params);

/// groebner_route() within a work allowance of `work` units of `params.budget`
/// (try_within): nullopt when the allowance runs out; every other limit propagates.
std::optional<ImplicitizeResult> groebner_route_within(const Parametrization& parametrization,
                                                       const ImplicitizeParams& params, std::uint64_t work);

/// The Gröbner route modulo primes: the elimination ideal's basis lifted alone, and
/// its one generator proven to be the implicit equation (exact substitution and
/// check_implicit_equation's minimality; interpolation.hpp has the argument).
/// nullopt where the lifted ideal has no single generator or the proof does not go
/// through: the caller then runs Buchberger over ℚ.
std::optional<ImplicitizeResult> modular_groebner_route(const Parametrization& parametrization,
                                                        const ImplicitizeParams& params);

/// The interpolation route (interpolation.hpp) limited to degrees ≤ `max_degree`:
/// nullopt when the degree is proven higher. Verified by the route itself.
std::optional<ImplicitizeResult> interpolation_route_up_to(const Parametrization& parametrization,
                                                           std::int32_t max_degree, const Budget& budget);

/// The interpolation route on a predicted support (sparse_interpolation.hpp): nullopt
/// when the prediction does not give the equation. Verified and proven by the route.
std::optional<ImplicitizeResult> sparse_interpolation_route(const Parametrization& parametrization,
                                                            const ImplicitSupport& support, const Budget& budget);

/// The whole interpolation route; where the dense matrix at the degree bound would
/// pass its column limit, first the predicted support (when its classes fit and cost
/// at most kSparseMaxCubedColumns), then the dense route if that falls back.
ImplicitizeResult interpolation_route(const Parametrization& parametrization, const Budget& budget);

/// The resultant route (Theorem 1.13: the square-free part of the auxiliary resultant,
/// checked against Theorem 1.12 and by substitution) for any input it applies to.
/// nullopt when the auxiliary resultant vanishes identically; `stats` receives the
/// auxiliary resultant's statistics either way.
std::optional<ImplicitizeResult> resultant_route(const Parametrization& parametrization, const Budget& budget,
                                                 std::optional<AuxiliaryResultantStats>& stats);

/// The resultant route for a surface whose formulation `plan` chose.
std::optional<ImplicitizeResult> resultant_route(const Parametrization& parametrization,
                                                 const AuxiliaryResultantPlan& plan, const Budget& budget,
                                                 std::optional<AuxiliaryResultantStats>& stats);

/// The parameters of the auxiliary resultant under `budget`.
AuxiliaryResultantParams resultant_params(const Budget& budget, std::size_t stable_primes);

}  // namespace implicitizer
