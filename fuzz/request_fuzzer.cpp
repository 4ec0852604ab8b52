/// \file
/// libFuzzer target for the HTTP request decoders (server/codec's json_codec.hpp).
///
/// On any bytes, decode_implicitize_request(), decode_groebner_request() and
/// decode_resultant_request() may only return or throw InputError: malformed or
/// non-UTF-8 JSON, deep nesting, wrong types, unknown or duplicate fields all have
/// their code. A decoded request's expressions
/// then go through parse_expression(), as the handlers do, under the same rule. The
/// algebra itself is not run (it is bounded by time, not by input size).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "implicitizer/codec/json_codec.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/expression.hpp"

namespace {

using namespace implicitizer;

void parse_field(const std::string& text) {
  try {
    (void)parse_expression(text);
  } catch (const InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view body(reinterpret_cast<const char*>(data), size);
  try {
    const ImplicitizeRequest request = decode_implicitize_request(body);
    parse_field(request.x);
    parse_field(request.y);
    if (request.z) parse_field(*request.z);
    if (request.parameters) {
      for (const std::string& name : *request.parameters) (void)is_identifier(name);
    }
  } catch (const InputError&) {
  }
  try {
    const GroebnerRequest request = decode_groebner_request(body);
    for (const std::string& polynomial : request.polynomials) parse_field(polynomial);
  } catch (const InputError&) {
  }
  try {
    const ResultantRequest request = decode_resultant_request(body);
    for (const std::string& polynomial : request.polynomials) parse_field(polynomial);
    (void)is_identifier(request.variable);
  } catch (const InputError&) {
  }
  try {
    // The whole answer, not only the decoding: names are validated and box numbers
    // parsed there, scenes compiled (a parametric leaf is implicitized under the
    // budget), and the polynomial is small enough after the fuzzer's size cap.
    (void)answer_sdf_request(decode_sdf_request(body), Budget::with_timeout(0.05));
  } catch (const InputError&) {
  } catch (const NoSingleEquation&) {
  } catch (const LimitExceeded&) {
  }
  try {
    // Decoding only: a render is seconds of marching, far beyond a fuzz iteration;
    // its sizes and names are checked here, its scene by the sdf branch above.
    const RenderRequest request = decode_render_request(body);
    parse_field(request.implicit);
    if (request.parametric) {
      for (const std::string& coordinate : *request.parametric) parse_field(coordinate);
    }
  } catch (const InputError&) {
  }
  return 0;
}
