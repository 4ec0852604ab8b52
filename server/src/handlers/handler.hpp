#pragma once
/// \file
/// What every endpoint handler receives and may return. A handler is a pure
/// function of the request (plus the shared cache and metrics): it either answers
/// at once, or hands back a Computation that the session runs on the worker pool,
/// since no algebra may run on a network thread.

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "config.hpp"
#include "http_message.hpp"
#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/errors.hpp"
#include "metrics_registry.hpp"
#include "result_cache.hpp"
#include "shared_result_cache.hpp"

namespace implicitizer::server {

/// Work to run on a worker thread. `run` produces the response and may throw what
/// the library throws (the router maps it to the contract's error). `budget` is the
/// one `run` checks: cancelling it (client gone, shutdown) stops the work.
struct Computation {
  std::function<Response()> run;
  Budget budget;
};

/// A response written as it is produced (Server-Sent Events): `head` first (status
/// and headers, no length: the body ends when the connection closes), then, every
/// `interval`, whatever `next()` returns, until it says that was the last piece.
/// `next` runs on the store executor (it may read the job store), one call at a time
/// for a stream, the next `interval` after the last one's piece was written.
struct EventStream {
  Response head;
  std::chrono::milliseconds interval{250};
  /// The next bytes to write ("" for nothing yet) and whether the stream ends after them.
  std::function<std::pair<std::string, bool>()> next;
};

/// What a StoreCall answers: a response, or a stream to start.
using StoreAnswer = std::variant<Response, EventStream>;

/// Work that waits on the job store (a SQLite file another process has locked, a
/// Redis that is slow): run on the session's store executor, never on a network
/// thread, so that one slow store cannot hold up /healthz or another connection.
/// `run` must not throw (a store that cannot answer is a 503 it returns).
struct StoreCall {
  std::function<StoreAnswer()> run;
};

/// A handler's answer: a response now, a computation for the pool, a stream, or a
/// call into the job store.
using HandlerResult = std::variant<Response, Computation, EventStream, StoreCall>;

class JobManager;

/// The shared state handlers may use. Outlives every request.
struct HandlerContext {
  const ServerConfig& config;
  ResultCache& cache;
  MetricsRegistry& metrics;
  /// Reads the pool's and the cache's gauges for /metrics.
  std::function<MetricsGauges()> gauges;
  /// The jobs API's engine (null: the /v1/jobs routes answer 404).
  JobManager* jobs = nullptr;
  /// The result cache shared with other replicas (null: none; --store redis://).
  SharedResultCache* shared_cache = nullptr;
};

/// Cache keys: appends `value` length-prefixed, so that no two field sequences
/// produce the same key.
inline void append_key_field(std::string& key, const std::string& value) {
  key += std::to_string(value.size());
  key += ':';
  key += value;
}

/// Appends an optional list: '-' when absent, else its length and its items.
template <typename T>
inline void append_key_list(std::string& key, const std::optional<std::vector<T>>& list) {
  if (!list) {
    key += '-';
    return;
  }
  key += 'L';
  key += std::to_string(list->size());
  for (const T& item : *list) {
    if constexpr (std::is_same_v<T, std::string>) {
      append_key_field(key, item);
    } else {
      append_key_field(key, std::to_string(item));
    }
  }
}

/// The budget of a computation whose request asked for `requested_seconds`
/// (absent: the configured default; 0 or above the cap: the cap), with the term
/// limit of `config`. Its deadline starts now, so time spent queued counts.
Budget make_computation_budget(const std::optional<double>& requested_seconds, const ServerConfig& config);

/// The response to a body the decoder (or a check before queuing) refused: 413 for
/// `render_too_large` (a render larger than the server draws), 400 for every other
/// InputError, with the error's code, field and position.
Response make_refusal_response(const InputError& error);

/// The one decode-or-refuse path of the algebra endpoints: `decode(body, limits)` (a
/// codec's decode_*_request, possibly followed by checks that must answer before any
/// work is queued) under the configured nesting limit, then `handle(decoded)`; an
/// InputError of `decode` is answered by make_refusal_response().
template <typename Decode, typename Handle>
HandlerResult handle_decoded(const Request& request, const HandlerContext& context, Decode decode, Handle handle) {
  using Decoded = decltype(decode(request.body(), JsonParams{}));
  std::optional<Decoded> decoded;
  try {
    decoded.emplace(decode(request.body(), JsonParams{context.config.json_max_depth}));
  } catch (const InputError& e) {
    return make_refusal_response(e);
  }
  return handle(std::move(*decoded));
}

/// The shape every cached algebra endpoint shares: the cached body for `key` if there
/// is one (`X-Cache: hit`), else a Computation that, on a worker, looks in the shared
/// cache (waiting no longer than the request's deadline; a hit there is `X-Cache: hit`
/// too, and is kept in this replica's cache), else
/// runs `answer(decoded, budget)` under a budget for the request's timeout, caches the
/// body it returns in both and answers it (`X-Cache: miss`). `answer` returns the
/// encoded JSON body.
template <typename Request, typename Answer>
HandlerResult cached_computation(Request decoded, std::string key, const HandlerContext& context, Answer answer) {
  if (const auto body = context.cache.find(key)) {
    Response response = make_json_response(http::status::ok, *body);
    response.set("X-Cache", "hit");
    return response;
  }
  Computation computation;
  computation.budget = make_computation_budget(decoded.timeout_seconds, context.config);
  // The budget already holds the deadline (counted from now, queue time included);
  // a timeout left in the request would restart it when the worker begins.
  decoded.timeout_seconds.reset();
  computation.run = [decoded = std::move(decoded), key = std::move(key), budget = computation.budget,
                     cache = &context.cache, shared = context.shared_cache, answer = std::move(answer)]() {
    std::optional<std::string> body;
    if (shared != nullptr) body = shared->find(key, budget);
    const bool hit = body.has_value();
    if (!hit) {
      body = answer(decoded, budget);
      if (shared != nullptr) shared->insert(key, *body);
    }
    cache->insert(key, *body);
    Response response = make_json_response(http::status::ok, std::move(*body));
    response.set("X-Cache", hit ? "hit" : "miss");
    return response;
  };
  return computation;
}

}  // namespace implicitizer::server
