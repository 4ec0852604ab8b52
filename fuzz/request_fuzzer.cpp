/// \file
/// libFuzzer target for the HTTP requests: the decoders of server/codec (one
/// *_json.hpp per endpoint) and the answers (server/service) the handlers compute from
/// what they decode.
///
/// Decoding oracle: on any bytes, decode_implicitize_request(),
/// decode_groebner_request(), decode_resultant_request(), decode_sdf_request() and
/// decode_render_request() only return or throw InputError (malformed or non-UTF-8
/// JSON, deep nesting, wrong types, unknown or duplicate fields all have their code),
/// and a decoded request's expressions go through parse_expression() under the same
/// rule.
///
/// Budget oracle (issue 16): every request that decodes is also answered, by the
/// answer_*_request() function its handler calls and with the same arguments, under
/// the budget a server with default flags would give it, its deadline shortened to
/// kAnswerSeconds. The answer returns or throws InputError, NoSingleEquation or
/// LimitExceeded (anything else escapes and libFuzzer reports it), and it ends within
/// kAnswerSeconds + kOverrunSeconds: a longer answer means a loop that does not check
/// its budget, which in the server keeps a worker (and shutdown) waiting. The target
/// then prints the endpoint, the input's size and the time, and traps.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "config.hpp"
#include "implicitizer/approximation/patch_approximation.hpp"
#include "implicitizer/codec/groebner_json.hpp"
#include "implicitizer/codec/implicitize_json.hpp"
#include "implicitizer/codec/render_json.hpp"
#include "implicitizer/codec/resultant_json.hpp"
#include "implicitizer/codec/sdf_json.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/expression.hpp"

namespace {

using namespace implicitizer;

// Short, so that libFuzzer keeps its pace; the oracle is about the overrun, not the
// length of the budget.
constexpr double kAnswerSeconds = 0.05;
// The bound: an answer may overrun its limit by at most 1 s.
constexpr double kOverrunSeconds = 1.0;

void parse_field(const std::string& text) {
  try {
    (void)parse_expression(text);
  } catch (const InputError&) {
  }
}

// What make_computation_budget() gives a request on a server with default flags
// (its term limit and count caps), with the deadline kAnswerSeconds from now. The
// memory limit is left out: sanitizer builds count no allocations.
Budget answer_budget() {
  const server::ServerConfig defaults;
  Budget budget = Budget::with_timeout(kAnswerSeconds);
  budget.set_max_terms(defaults.max_terms)
      .set_max_variables(defaults.max_variables)
      .set_max_polynomials(defaults.max_polynomials);
  return budget;
}

// Runs `answer(budget)` and checks the budget oracle. The request's own timeout has
// been removed by the caller, as the handlers do once the budget holds it.
template <typename Answer>
void answer_within_budget(const char* endpoint, std::size_t size, const Answer& answer) {
  const auto start = std::chrono::steady_clock::now();
  try {
    (void)answer(answer_budget());
  } catch (const InputError&) {
  } catch (const NoSingleEquation&) {
  } catch (const ToleranceNotMet&) {  // an approximation that cannot reach its tolerance
  } catch (const LimitExceeded&) {
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (elapsed > kAnswerSeconds + kOverrunSeconds) {
    std::fprintf(stderr,
                 "request_fuzzer: budget overrun: %s answered a %zu-byte input in %.3f s, over its %.2f s budget "
                 "+ %.0f s\n",
                 endpoint, size, elapsed, kAnswerSeconds, kOverrunSeconds);
    __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view body(reinterpret_cast<const char*>(data), size);
  try {
    ImplicitizeRequest request = decode_implicitize_request(body);
    parse_field(request.x);
    parse_field(request.y);
    if (request.z) parse_field(*request.z);
    if (request.parameters) {
      for (const std::string& name : *request.parameters) (void)is_identifier(name);
    }
    request.timeout_seconds.reset();
    answer_within_budget("/v1/implicitize", size,
                         [&request](const Budget& budget) { return answer_implicitize_request(request, budget); });
  } catch (const InputError&) {
  }
  try {
    GroebnerRequest request = decode_groebner_request(body);
    for (const std::string& polynomial : request.polynomials) parse_field(polynomial);
    request.timeout_seconds.reset();
    answer_within_budget("/v1/groebner", size,
                         [&request](const Budget& budget) { return answer_groebner_request(request, budget); });
  } catch (const InputError&) {
  }
  try {
    ResultantRequest request = decode_resultant_request(body);
    for (const std::string& polynomial : request.polynomials) parse_field(polynomial);
    (void)is_identifier(request.variable);
    request.timeout_seconds.reset();
    answer_within_budget("/v1/resultant", size,
                         [&request](const Budget& budget) { return answer_resultant_request(request, budget); });
  } catch (const InputError&) {
  }
  try {
    // Names are validated, box and domain numbers parsed in the answer, scenes
    // compiled (a parametric leaf, or a parametric request, is implicitized under the
    // budget; a plane curve's z is empty).
    SdfRequest request = decode_sdf_request(body);
    parse_field(request.implicit);
    if (request.parametric) {
      for (const std::string& coordinate : *request.parametric) parse_field(coordinate);
    }
    request.timeout_seconds.reset();
    answer_within_budget("/v1/sdf", size,
                         [&request](const Budget& budget) { return answer_sdf_request(request, budget); });
  } catch (const InputError&) {
  }
  try {
    RenderRequest request = decode_render_request(body);
    parse_field(request.implicit);
    if (request.parametric) {
      for (const std::string& coordinate : *request.parametric) parse_field(coordinate);
    }
    request.timeout_seconds.reset();
    // One render thread, as the handler asks for.
    answer_within_budget("/v1/render", size, [&request](const Budget& budget) {
      return answer_render_request(request, budget, RenderRequestParams{}, 1);
    });
  } catch (const InputError&) {
  }
  return 0;
}
