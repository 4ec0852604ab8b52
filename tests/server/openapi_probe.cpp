/// \file
/// What docs/openapi.yaml is checked against (tests/server/openapi_test.py):
///
///   openapi_probe routes                       one line per API route: PATH<TAB>ALLOW
///   openapi_probe decode implicitize|groebner|resultant|sdf|render
///                                              decodes stdin as that endpoint's body;
///                                              prints `ok`, or `error CODE<TAB>FIELD<TAB>MESSAGE`
///
/// The router and the codec are the truth; the YAML must follow them.

#include <iostream>
#include <iterator>
#include <string>
#include <string_view>

#include "implicitizer/codec/groebner_json.hpp"
#include "implicitizer/codec/implicitize_json.hpp"
#include "implicitizer/codec/render_json.hpp"
#include "implicitizer/codec/resultant_json.hpp"
#include "implicitizer/codec/sdf_json.hpp"
#include "router.hpp"

namespace {

using namespace implicitizer;

int print_routes() {
  const server::ServerConfig config;
  server::MetricsRegistry metrics;
  server::ResultCache cache(1);
  const server::Router router(server::HandlerContext{config, cache, metrics, {}});
  for (const server::RouteInfo& route : router.routes()) std::cout << route.path << '\t' << route.methods << '\n';
  return 0;
}

int decode(std::string_view endpoint) {
  const std::string body((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
  try {
    if (endpoint == "implicitize") {
      (void)decode_implicitize_request(body);
    } else if (endpoint == "groebner") {
      (void)decode_groebner_request(body);
    } else if (endpoint == "resultant") {
      (void)decode_resultant_request(body);
    } else if (endpoint == "sdf") {
      (void)decode_sdf_request(body);
    } else if (endpoint == "render") {
      (void)decode_render_request(body);
    } else {
      std::cerr << "openapi_probe: unknown endpoint " << endpoint << '\n';
      return 2;
    }
  } catch (const InputError& e) {
    std::cout << "error " << e.code() << '\t' << e.field() << '\t' << e.what() << '\n';
    return 0;
  }
  std::cout << "ok\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string_view command = argc > 1 ? argv[1] : "";
  if (command == "routes" && argc == 2) return print_routes();
  if (command == "decode" && argc == 3) return decode(argv[2]);
  std::cerr << "usage: openapi_probe routes | openapi_probe decode implicitize|groebner|resultant|sdf|render < BODY\n";
  return 2;
}
