#pragma once
/// \file
/// The jobs API: POST /v1/jobs, GET and DELETE /v1/jobs/{id}, GET /v1/jobs/{id}/result
/// and GET /v1/jobs/{id}/events. Thin: the JobManager decides, these only translate
/// (and answer 503 `job_store_unavailable`, naming the store, when it cannot answer).
/// Each returns a StoreCall (or 404 when the server runs no jobs): the store is never
/// waited for on a network thread.

#include <string>

#include "handlers/handler.hpp"

namespace implicitizer::server {

/// POST /v1/jobs from peer `client` (see JobManager::submit).
HandlerResult handle_job_submit(const Request& request, const std::string& client, const HandlerContext& context);

/// GET /v1/jobs/{id}: the job's state (200) or 404 `job_not_found`.
HandlerResult handle_job_status(const std::string& id, const HandlerContext& context);

/// GET /v1/jobs/{id}/result: what the synchronous endpoint answered (JobManager::result).
HandlerResult handle_job_result(const std::string& id, const HandlerContext& context);

/// DELETE /v1/jobs/{id} (JobManager::cancel).
HandlerResult handle_job_cancel(const std::string& id, const HandlerContext& context);

/// GET /v1/jobs/{id}/events: a Server-Sent Events stream (JobEventFeed) that ends
/// with the job, or 404 `job_not_found`. HEAD gets the head alone.
HandlerResult handle_job_events(const Request& request, const std::string& id, const HandlerContext& context);

}  // namespace implicitizer::server
