#include "router.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "jobs/job_manager.hpp"
#include "jobs/memory_job_store.hpp"

namespace implicitizer::server {
namespace {

// The router alone, without sockets or threads: computations are run inline here.
class RouterTest : public ::testing::Test {
 protected:
  explicit RouterTest(ServerConfig config = ServerConfig()) : config_(std::move(config)) {}

  static Request post(const std::string& target, std::string body) {
    Request request(http::verb::post, target, 11);
    request.body() = std::move(body);
    request.prepare_payload();
    return request;
  }
  static Request get(const std::string& target) { return Request(http::verb::get, target, 11); }

  // Routes `request`, running a computation inline; `computed` tells which it was.
  Response answer(const Request& request, bool* computed = nullptr) {
    Routed routed = router_.route(request);
    if (computed != nullptr) *computed = std::holds_alternative<Computation>(routed.result);
    if (auto* response = std::get_if<Response>(&routed.result)) return std::move(*response);
    return std::get<Computation>(routed.result).run();
  }

  ServerConfig config_;
  MetricsRegistry metrics_;
  ResultCache cache_{8};
  Router router_{HandlerContext{config_, cache_, metrics_, {}}};
};

TEST_F(RouterTest, Healthz) {
  const Response response = answer(get("/healthz"));
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_EQ(response.body(), R"({"status":"ok"})");
  EXPECT_EQ(response[http::field::content_type], "application/json");
}

TEST_F(RouterTest, HeadHasTheLengthOfGetAndNoBody) {
  Request request = get("/healthz");
  request.method(http::verb::head);
  const Response response = answer(request);
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_TRUE(response.body().empty());
  EXPECT_EQ(response[http::field::content_length], "15");
}

TEST_F(RouterTest, ImplicitizeRunsOnThePoolThenComesFromTheCache) {
  const Request request = post("/v1/implicitize", R"({"x": "s", "y": "t", "z": "s^2+t^2"})");
  bool computed = false;
  const Response first = answer(request, &computed);
  EXPECT_TRUE(computed) << "algebra must not run on the network thread";
  EXPECT_EQ(first.result(), http::status::ok);
  EXPECT_NE(first.body().find(R"("implicit":"x^2+y^2-z")"), std::string::npos) << first.body();
  EXPECT_NE(first.body().find(R"("verified":true)"), std::string::npos);
  EXPECT_EQ(first["X-Cache"], "miss");

  // Same request, other spelling and timeout: same canonical key.
  const Response second =
      answer(post("/v1/implicitize", R"({"timeout_ms": 5000, "z":"s^2+t^2","y":"t","x":"s"})"), &computed);
  EXPECT_FALSE(computed);
  EXPECT_EQ(second.body(), first.body());
  EXPECT_EQ(second["X-Cache"], "hit");
  EXPECT_EQ(cache_.hits(), 1u);
}

TEST_F(RouterTest, Groebner) {
  const Response response = answer(post("/v1/groebner", R"({"polynomials": ["x^2+y^2-1", "x-y"], "order": "lex"})"));
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_NE(response.body().find(R"("basis":["y^2-1/2","x-y"])"), std::string::npos) << response.body();
}

TEST_F(RouterTest, Resultant) {
  Response response = answer(post("/v1/resultant", R"({"polynomials": ["t^2+x", "y*t+1"], "variable": "t"})"));
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_EQ(response.body().rfind(R"({"resultant":"x*y^2+1","variables":["x","y"],"degree":3,)", 0), 0u)
      << response.body();
  // A wrong count is refused by the decoder, before any worker is involved.
  response = answer(post("/v1/resultant", R"({"polynomials": ["t"], "variable": "t"})"));
  EXPECT_EQ(response.result(), http::status::bad_request);
  EXPECT_NE(response.body().find(R"("code":"wrong_number_of_polynomials")"), std::string::npos) << response.body();
  // An unknown variable is found while answering: still 400, naming the field.
  response = answer(post("/v1/resultant", R"({"polynomials": ["t", "x"], "variable": "s"})"));
  EXPECT_EQ(response.result(), http::status::bad_request);
  EXPECT_NE(response.body().find(R"("field":"variable")"), std::string::npos) << response.body();
}

TEST_F(RouterTest, InputErrorsAre400WithCodeAndPosition) {
  Response response = answer(post("/v1/implicitize", R"({"x": "s", "y":)"));
  EXPECT_EQ(response.result(), http::status::bad_request);
  EXPECT_NE(response.body().find(R"("code":"invalid_json")"), std::string::npos) << response.body();
  EXPECT_NE(response.body().find(R"("position":)"), std::string::npos);

  response = answer(post("/v1/implicitize", R"({"x": 1, "y": "t", "z": "s"})"));
  EXPECT_EQ(response.result(), http::status::bad_request);
  EXPECT_NE(response.body().find(R"("code":"wrong_type")"), std::string::npos);

  response = answer(post("/v1/implicitize", R"({"x": "s+", "y": "t", "z": "s"})"));
  EXPECT_EQ(response.result(), http::status::bad_request);
  EXPECT_NE(response.body().find(R"("position":2)"), std::string::npos) << response.body();
  EXPECT_NE(response.body().find(R"("field":"x")"), std::string::npos);

  response = answer(post("/v1/groebner", R"({"polynomials": ["x"], "colour": "red"})"));
  EXPECT_EQ(response.result(), http::status::bad_request);
  EXPECT_NE(response.body().find(R"("code":"unknown_field")"), std::string::npos);

  response = answer(post("/v1/groebner", std::string(100, '[') + std::string(100, ']')));
  EXPECT_EQ(response.result(), http::status::bad_request);
  EXPECT_NE(response.body().find(R"("code":"json_too_deep")"), std::string::npos);
}

TEST_F(RouterTest, NoSingleEquationIs422) {
  const Response response = answer(post("/v1/implicitize", R"({"x": "t", "y": "t^2", "z": "t^3"})"));
  EXPECT_EQ(response.result(), http::status::unprocessable_entity);
  EXPECT_NE(response.body().find(R"("code":"no_single_equation")"), std::string::npos);
}

TEST_F(RouterTest, TimeLimitIs504AndSizeLimitIs413) {
  Response response =
      answer(post("/v1/implicitize", R"({"x": "s^3+t^2*s", "y": "t^3-s", "z": "s*t^2+t^4", "timeout_ms": 50})"));
  EXPECT_EQ(response.result(), http::status::gateway_timeout);
  EXPECT_NE(response.body().find(R"("code":"time_limit_exceeded")"), std::string::npos);

  config_.max_terms = 3;
  response = answer(post("/v1/groebner", R"({"polynomials": ["(x+y+z+1)^4"]})"));
  EXPECT_EQ(response.result(), http::status::payload_too_large);
  EXPECT_NE(response.body().find(R"("code":"size_limit_exceeded")"), std::string::npos) << response.body();
}

TEST_F(RouterTest, TimeoutIsCappedAndDefaulted) {
  config_.default_timeout = std::chrono::milliseconds(1000);
  config_.max_timeout = std::chrono::milliseconds(2000);
  // timeout_seconds() is what was set; seconds_left() may only have shrunk since.
  for (const auto& [requested, expected] : std::vector<std::pair<std::optional<double>, double>>{
           {std::nullopt, 1.0}, {0.5, 0.5}, {600.0, 2.0}, {0.0, 2.0}}) {
    const Budget budget = make_computation_budget(requested, config_);
    EXPECT_EQ(budget.timeout_seconds(), expected);
    EXPECT_LE(budget.seconds_left(), expected);
  }
}

TEST_F(RouterTest, CancelledComputationAnswersCancelled) {
  Routed routed = router_.route(post("/v1/implicitize", R"({"x": "s", "y": "t", "z": "s^3+t"})"));
  Computation& computation = std::get<Computation>(routed.result);
  computation.budget.cancel();
  const Response response = computation.run();
  EXPECT_EQ(response.result(), http::status::service_unavailable);
  EXPECT_NE(response.body().find(R"("code":"cancelled")"), std::string::npos);
  EXPECT_EQ(metrics_.cancelled_computations(), 1u);
}

TEST_F(RouterTest, UnknownPathIs404AndWrongMethodIs405WithAllow) {
  Response response = answer(get("/v1/nope"));
  EXPECT_EQ(response.result(), http::status::not_found);
  EXPECT_NE(response.body().find(R"("code":"not_found")"), std::string::npos);
  EXPECT_EQ(answer(get("/index.html")).result(), http::status::not_found) << "no static directory configured";

  response = answer(get("/v1/implicitize"));
  EXPECT_EQ(response.result(), http::status::method_not_allowed);
  EXPECT_EQ(response[http::field::allow], "POST, OPTIONS");
  response = answer(post("/healthz", ""));
  EXPECT_EQ(response.result(), http::status::method_not_allowed);
  EXPECT_EQ(response[http::field::allow], "GET, HEAD, OPTIONS");
}

TEST_F(RouterTest, CorsAnyOriginByDefault) {
  Request preflight(http::verb::options, "/v1/implicitize", 11);
  preflight.set(http::field::origin, "https://example.org");
  preflight.set(http::field::access_control_request_method, "POST");
  preflight.set(http::field::access_control_request_headers, "content-type");
  Response response = answer(preflight);
  EXPECT_EQ(response.result(), http::status::no_content);
  EXPECT_EQ(response[http::field::access_control_allow_origin], "*");
  EXPECT_EQ(response[http::field::access_control_allow_methods], "POST, OPTIONS");
  EXPECT_EQ(response[http::field::access_control_allow_headers], "Content-Type");

  Request request = get("/healthz");
  request.set(http::field::origin, "https://example.org");
  EXPECT_EQ(answer(request)[http::field::access_control_allow_origin], "*");
  EXPECT_EQ(answer(get("/healthz")).count(http::field::access_control_allow_origin), 0u) << "no Origin, no CORS";
}

class RouterWithOriginListTest : public RouterTest {
 protected:
  RouterWithOriginListTest() : RouterTest(with_origins()) {}
  static ServerConfig with_origins() {
    ServerConfig config;
    config.cors_origins = {"https://good.example"};
    return config;
  }
};

TEST_F(RouterWithOriginListTest, OnlyListedOriginsAreAllowed) {
  Request preflight(http::verb::options, "/v1/groebner", 11);
  preflight.set(http::field::access_control_request_method, "POST");
  preflight.set(http::field::origin, "https://evil.example");
  EXPECT_EQ(answer(preflight).result(), http::status::forbidden);
  preflight.set(http::field::origin, "https://good.example");
  const Response response = answer(preflight);
  EXPECT_EQ(response.result(), http::status::no_content);
  EXPECT_EQ(response[http::field::access_control_allow_origin], "https://good.example");
  EXPECT_EQ(response[http::field::vary], "Origin");
}

TEST_F(RouterTest, OverloadIs503WithRetryAfter) {
  const Response response = router_.make_overloaded_response(post("/v1/implicitize", "{}"), "computation");
  EXPECT_EQ(response.result(), http::status::service_unavailable);
  EXPECT_EQ(response[http::field::retry_after], "1");
  EXPECT_NE(response.body().find(R"("code":"overloaded")"), std::string::npos);
}

TEST_F(RouterTest, MetricsExposeRequestsAndCache) {
  metrics_.record_request("/healthz", 200, 0.002);
  cache_.find("nothing");
  const Response response = answer(get("/metrics"));
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_NE(response.body().find(R"(implicitizer_http_requests_total{endpoint="/healthz",status="200"} 1)"),
            std::string::npos)
      << response.body();
  EXPECT_NE(
      response.body().find(R"(implicitizer_http_request_duration_seconds_bucket{endpoint="/healthz",le="0.0025"} 1)"),
      std::string::npos);
  EXPECT_NE(response.body().find("# TYPE implicitizer_cache_hits_total counter"), std::string::npos);
}

TEST_F(RouterTest, KnowsItsRoutes) {
  std::vector<std::string> paths;
  for (const RouteInfo& route : router_.routes()) paths.push_back(route.path);
  EXPECT_EQ(paths, (std::vector<std::string>{"/healthz", "/metrics", "/v1/implicitize", "/v1/groebner", "/v1/resultant",
                                             "/v1/sdf", "/v1/render", "/v1/jobs", "/v1/jobs/{id}",
                                             "/v1/jobs/{id}/result", "/v1/jobs/{id}/events"}));
}

TEST_F(RouterTest, JobPathsTakeOneSegmentForTheirId) {
  // No JobManager here: a job path that matches answers "no jobs", one that does not is unknown.
  for (const char* path : {"/v1/jobs/abc", "/v1/jobs/abc/result", "/v1/jobs/abc/events"}) {
    const Response response = answer(get(path));
    EXPECT_EQ(response.result(), http::status::not_found) << path;
    EXPECT_NE(response.body().find("runs no jobs"), std::string::npos) << path << response.body();
  }
  for (const char* path : {"/v1/jobs/", "/v1/jobs//result", "/v1/jobs/abc/def", "/v1/jobs/abc/result/x"}) {
    const Response response = answer(get(path));
    EXPECT_EQ(response.result(), http::status::not_found) << path;
    EXPECT_NE(response.body().find("no such endpoint"), std::string::npos) << path << response.body();
  }
  Request put = get("/v1/jobs/abc");
  put.method(http::verb::put);
  const Response refused = answer(put);
  EXPECT_EQ(refused.result(), http::status::method_not_allowed);
  EXPECT_EQ(refused[http::field::allow], "GET, HEAD, DELETE, OPTIONS");
}

// The router with a JobManager over the memory store: the jobs API without sockets.
class RouterJobsTest : public RouterTest {
 protected:
  std::string submit(const std::string& body) {
    const Response response = answer(post("/v1/jobs", body));
    EXPECT_EQ(response.result(), http::status::accepted) << response.body();
    const std::size_t at = response.body().find(R"("id":")");
    return at == std::string::npos ? std::string() : response.body().substr(at + 6, 32);
  }
  // Polls GET /v1/jobs/{id} until its body holds `text` (generous deadline).
  Response wait_for(const std::string& id, const std::string& text) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    Response response;
    do {
      response = answer(get("/v1/jobs/" + id));
      if (response.body().find(text) != std::string::npos) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    } while (std::chrono::steady_clock::now() < deadline);
    return response;
  }

  JobManager jobs_{config_, std::make_unique<MemoryJobStore>(), cache_, metrics_};
  Router jobs_router_{HandlerContext{config_, cache_, metrics_, {}, &jobs_}};
  // Routes `request` and runs its store call inline: every jobs route must hand its
  // store work to the store executor, never answer on the network thread.
  StoreAnswer call_store(const Request& request) {
    Routed routed = jobs_router_.route(request, "192.0.2.1");
    auto* call = std::get_if<StoreCall>(&routed.result);
    if (call == nullptr) {
      ADD_FAILURE() << request.target() << " answered without a store call";
      return Response(http::status::internal_server_error, 11);
    }
    return call->run();
  }
  Response answer(const Request& request) {
    StoreAnswer answered = call_store(request);
    if (auto* response = std::get_if<Response>(&answered)) return std::move(*response);
    return Response(http::status::internal_server_error, 11);  // no stream expected here
  }
};

TEST_F(RouterJobsTest, SubmitPollResult) {
  const std::string id =
      submit(R"({"kind": "groebner", "request": {"polynomials": ["x^2+y^2-1", "x-y"], "order": "lex"}})");
  const Response done = wait_for(id, R"("status":"done")");
  EXPECT_NE(done.body().find(R"("result":{"basis":["y^2-1/2","x-y"])"), std::string::npos) << done.body();
  const Response result = answer(get("/v1/jobs/" + id + "/result"));
  EXPECT_EQ(result.result(), http::status::ok);
  EXPECT_EQ(result.body().find(R"({"basis":["y^2-1/2","x-y"])"), 0U) << result.body();
  EXPECT_EQ(result["X-Cache"], "miss");
}

TEST_F(RouterJobsTest, EventsAreAStream) {
  const std::string id =
      submit(R"({"kind": "resultant", "request": {"polynomials": ["x-t", "y-t^2"], "variable": "t"}})");
  wait_for(id, R"("status":"done")");
  StoreAnswer answered = call_store(get("/v1/jobs/" + id + "/events"));
  auto* stream = std::get_if<EventStream>(&answered);
  ASSERT_NE(stream, nullptr);
  EXPECT_EQ(stream->head[http::field::content_type], "text/event-stream");
  EXPECT_FALSE(stream->head.keep_alive()) << "the stream's body ends with the connection";
  const auto [text, last] = stream->next();
  EXPECT_TRUE(last);
  EXPECT_EQ(text.rfind("event: end\ndata: {", 0), 0U) << text;
}

TEST_F(RouterTest, RenderRunsOnThePoolAndAnswersPng) {
  bool computed = false;
  const Response png =
      answer(post("/v1/render", R"({"implicit": "x^2+y^2+z^2-1", "width": 16, "height": 8, "aa": 1})"), &computed);
  EXPECT_TRUE(computed) << "rendering must not run on the network thread";
  EXPECT_EQ(png.result(), http::status::ok);
  EXPECT_EQ(png[http::field::content_type], "image/png");
  EXPECT_EQ(png.body().substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png["X-Render-Rays"], "128");
  EXPECT_EQ(png["X-Render-Method"], "sphere");

  const Response json = answer(
      post("/v1/render", R"({"implicit": "x^2+y^2+z^2-1", "width": 16, "height": 8, "format": "json"})"), &computed);
  EXPECT_EQ(json.result(), http::status::ok);
  EXPECT_EQ(json[http::field::content_type], "application/json");
  EXPECT_NE(json.body().find(R"("rays":512,)"), std::string::npos) << json.body();
  EXPECT_NE(json.body().find(R"("png_base64":"iVBORw0KGgo)"), std::string::npos);

  // Sizes are checked before anything is queued.
  const Response large =
      answer(post("/v1/render", R"({"implicit": "x", "width": 2048, "height": 2048, "aa": 2})"), &computed);
  EXPECT_FALSE(computed);
  EXPECT_EQ(large.result(), http::status::payload_too_large);
  EXPECT_NE(large.body().find("render_too_large"), std::string::npos);
  const Response bad = answer(post("/v1/render", R"({"implicit": "x", "width": 0})"), &computed);
  EXPECT_FALSE(computed);
  EXPECT_EQ(bad.result(), http::status::bad_request);
  EXPECT_NE(bad.body().find("invalid_size"), std::string::npos);
  const Response exact = answer(post("/v1/render", R"({"scene": {"type": "sphere", "radius": 1}, "method": "exact"})"));
  EXPECT_EQ(exact.result(), http::status::bad_request);
  EXPECT_NE(exact.body().find("method_not_applicable"), std::string::npos);
}

}  // namespace
}  // namespace implicitizer::server
