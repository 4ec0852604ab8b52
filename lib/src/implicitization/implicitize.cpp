#include "implicitizer/implicitization/implicitize.hpp"

#include <chrono>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/groebner/elimination.hpp"
#include "implicitizer/implicitization/reproduce.hpp"
#include "implicitizer/implicitization/verify.hpp"
#include "implicitizer/polynomial/gcd.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {

RingPtr space_ring() {
  static const RingPtr ring = Ring::make({"x", "y", "z"}, MonomialOrder::grevlex());
  return ring;
}

ImplicitizationMethod parse_implicitization_method(const std::string& name) {
  if (name == "auto") return ImplicitizationMethod::automatic;
  if (name == "groebner") return ImplicitizationMethod::groebner;
  if (name == "resultant" || name == "interpolation") {
    throw InputError("unknown_method", "method '" + name + "' is not available in this version (use auto or groebner)");
  }
  throw InputError("unknown_method", "unknown method '" + name + "' (expected auto, groebner, resultant or interpolation)");
}

namespace {

// A name for the saturation variable that no parameter uses.
std::string fresh_name(const Ring& params) {
  std::string name = "w";
  while (params.index_of(name)) name += "_";
  return name;
}

}  // namespace

ImplicitizeResult implicitize(const Parametrization& p, const ImplicitizeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
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
  names.insert(names.end(), {"x", "y", "z"});
  RingPtr ring = Ring::make(names);
  const std::size_t offset = saturate ? 1 : 0;
  std::vector<std::size_t> param_map(k);
  for (std::size_t i = 0; i < k; ++i) param_map[i] = offset + i;

  std::vector<Polynomial> generators;
  for (std::size_t v = 0; v < 3; ++v) {
    const auto& c = p.coordinates[v];
    const Polynomial space_variable = Polynomial::variable(ring, offset + k + v);
    generators.push_back(c.denominator().map_to(ring, param_map) * space_variable - c.numerator().map_to(ring, param_map));
  }
  if (saturate) {
    generators.push_back(Polynomial::constant(ring, Rational(1)) -
                         l.map_to(ring, param_map) * Polynomial::variable(ring, 0));
  }

  const EliminationResult elimination = eliminate(generators, eliminated, options.groebner);
  const auto& gens = elimination.elimination;
  if (gens.size() != 1 || gens.front().is_constant()) {
    std::vector<std::string> printed;
    for (const auto& g : gens) printed.push_back(to_string(g.primitive_part()));
    if (gens.empty()) {
      throw NoSingleEquation("no implicit equation: the image is dense in space (the elimination ideal is zero)",
                             printed);
    }
    throw NoSingleEquation("no single implicit equation: the image is not a surface (the elimination ideal needs " +
                               std::to_string(gens.size()) + " generators)",
                           printed);
  }

  ImplicitizeResult result;
  const std::size_t identity[3] = {0, 1, 2};
  result.implicit = gens.front().map_to(space_ring(), identity).primitive_part();
  result.degree = result.implicit.total_degree();
  result.method = "groebner";
  result.stats = elimination.groebner.stats;

  const auto verify_start = std::chrono::steady_clock::now();
  result.verified = substitutes_to_zero(result.implicit, p, options.groebner.budget);
  if (!result.verified) {
    throw std::logic_error("internal error: the implicit equation " + to_string(result.implicit) +
                           " does not vanish on the parametrization");
  }
  const auto end = std::chrono::steady_clock::now();
  result.verify_ms = std::chrono::duration<double, std::milli>(end - verify_start).count();
  result.singular_script = singular_script(p);
  result.macaulay2_script = macaulay2_script(p);
  result.elapsed_ms = std::chrono::duration<double, std::milli>(end - start).count();
  return result;
}

}  // namespace implicitizer
