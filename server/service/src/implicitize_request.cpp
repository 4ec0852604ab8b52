#include "implicitizer/service/implicitize_request.hpp"

#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {

ImplicitizeAnswer answer_implicitize_request(const ImplicitizeRequest& request, Budget budget,
                                             const BuchbergerVariant& variant) {
  // The deadline starts here, so that parsing a huge input counts against it too.
  if (request.timeout_seconds) budget.set_timeout(*request.timeout_seconds);
  std::vector<std::string> coordinates = {request.x, request.y};
  if (request.z) coordinates.push_back(*request.z);
  const Parametrization parametrization = parse_parametrization(coordinates, request.parameters, budget);
  ImplicitizeParams options;
  options.method = request.method;
  options.budget = std::move(budget);
  options.buchberger = variant;
  options.modular_groebner = request.modular;
  ImplicitizeAnswer answer{implicitize(parametrization, options), reproduce_scripts(parametrization), {}, {}, {}};
  if (!parametrization.substitutions.empty()) {
    answer.substitutions = parametrization.substitutions;
    answer.rational_parameters = parametrization.parameter_ring->variables();
    for (const auto& c : parametrization.coordinates) answer.rational_coordinates.push_back(to_string(c));
  }
  return answer;
}

}  // namespace implicitizer
