#pragma once
/// \file
/// Method `auto` of implicitize(): the rules of docs/algorithms.md ("`auto`"), tried in
/// order. Each rule either answers or passes to the next; the last always answers (or
/// throws). The measurements behind every rule are in docs/algorithms.md, keyed by
/// the rule's number.

#include "implicitizer/implicitization/implicitize.hpp"

namespace implicitizer {

/// The implicit equation by the first of auto's rules that answers, with
/// `ImplicitizeResult::route` saying which and why. Unverified where the route does not
/// prove its answer (implicitize() substitutes it). Throws what the routes throw.
ImplicitizeResult implicitize_automatically(const Parametrization& parametrization, const ImplicitizeParams& params);

}  // namespace implicitizer
