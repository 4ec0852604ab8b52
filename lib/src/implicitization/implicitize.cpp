#include "implicitizer/implicitization/implicitize.hpp"

#include <stdexcept>
#include <string>

#include "auto_rules.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/implicitization/verify.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "routes.hpp"

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

// Method groebner: modulo primes when asked and the proof goes through, else over ℚ.
ImplicitizeResult by_groebner_method(const Parametrization& p, const ImplicitizeParams& params) {
  if (params.modular_groebner) {
    if (auto modular = modular_groebner_route(p, params)) return std::move(*modular);
  }
  return groebner_route(p, params);
}

// Method resultant: the route, or the error that says why it cannot answer.
ImplicitizeResult by_resultant_method(const Parametrization& p, const Budget& budget) {
  const std::size_t coordinates = p.coordinates.size();
  const std::size_t parameters = p.parameter_ring->num_variables();
  if (!resultant_applies(p)) {
    throw InputError("method_not_applicable", "the resultant method needs " + std::to_string(coordinates - 1) +
                                                  " parameter" + (coordinates == 2 ? "" : "s") + " for " +
                                                  std::to_string(coordinates) + " coordinates (this has " +
                                                  std::to_string(parameters) + ")");
  }
  std::optional<AuxiliaryResultantStats> stats;
  if (auto result = resultant_route(p, budget, stats)) return std::move(*result);
  if (stats && stats->matrix_too_large && !(stats->dixon_vanishes && stats->macaulay_vanishes)) {
    throw LimitExceeded(Limit::size, "the auxiliary resultant's matrix would exceed " +
                                         std::to_string(kMaxResultantMatrixSize) +
                                         " rows for this degree; use method groebner or auto");
  }
  if (coordinates == 2) throw NoSingleEquation("no implicit curve: the image is a point", {});
  throw NoSingleEquation(
      "the auxiliary resultant vanishes identically: the parametrization has base points (Theorem 1.14), "
      "both as a tensor-product patch on P1xP1 and as a triangular patch on P2; use method groebner or auto",
      {}, "base_points");
}

ImplicitizeResult by_method(const Parametrization& p, const ImplicitizeParams& params) {
  switch (params.method) {
    case ImplicitizationMethod::automatic:
      return implicitize_automatically(p, params);
    case ImplicitizationMethod::groebner:
      return by_groebner_method(p, params);
    case ImplicitizationMethod::resultant:
      return by_resultant_method(p, params.budget);
    case ImplicitizationMethod::interpolation:
      return interpolation_route(p, params.budget);
  }
  throw std::logic_error("internal error: unknown implicitization method");
}

// Verifies `result.implicit` by substitution (unless the route did) and fills the
// fields every route shares.
void finish(ImplicitizeResult& result, const Parametrization& p, const Budget& budget, const Stopwatch& timer) {
  result.degree = result.implicit.total_degree();
  if (!result.verified) {
    const Stopwatch verify_timer;
    result.verified = substitutes_to_zero(result.implicit, p, budget);
    result.verify_ms = verify_timer.elapsed_ms();
    if (!result.verified) {
      throw std::logic_error("internal error: the implicit equation " + to_string(result.implicit) +
                             " does not vanish on the parametrization");
    }
  }
  result.elapsed_ms = timer.elapsed_ms();
}

}  // namespace

ImplicitizeResult implicitize(const Parametrization& parametrization, const ImplicitizeParams& params) {
  const Stopwatch timer;
  ImplicitizeResult result = by_method(parametrization, params);
  finish(result, parametrization, params.budget, timer);
  return result;
}

}  // namespace implicitizer
