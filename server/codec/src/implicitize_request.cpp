#include "implicitizer/codec/implicitize_request.hpp"

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer {

ImplicitizeAnswer answer_implicitize_request(const ImplicitizeRequest& request, BuchbergerParams params) {
  ImplicitizeParams options;
  try {
    options.method = parse_implicitization_method(request.method);
  } catch (const InputError& e) {
    throw e.in_field("method");
  }
  // The deadline starts here, so that parsing a huge input counts against it too.
  if (request.timeout_seconds) params.budget.set_timeout(*request.timeout_seconds);
  std::vector<std::string> coordinates = {request.x, request.y};
  if (request.z) coordinates.push_back(*request.z);
  const Parametrization parametrization = parse_parametrization(coordinates, request.parameters, params.budget);
  options.budget = std::move(params.budget);
  options.buchberger = params.variant;
  options.modular_groebner = request.modular;
  ImplicitizeResult result = implicitize(parametrization, options);
  return {std::move(result), reproduce_scripts(parametrization)};
}

}  // namespace implicitizer
