#pragma once
/// \file
/// POST /v1/render: a PNG preview of an implicit surface, a parametric surface or a
/// scene (docs/api.md, docs/render.md).

#include "handlers/handler.hpp"

namespace implicitizer::server {

/// Decodes the body (decode_render_request) and checks its size at once: a bad body
/// is 400, more than RenderRequestParams::max_rays rays 413 (`render_too_large`). The
/// render runs on the worker pool under the request's budget, on that worker's
/// thread alone (the pool, sized to the cores, is what spreads renders over them;
/// a render that started its own threads would oversubscribe a busy server). The
/// answer is `image/png` with the statistics in X-Render-* headers (Width, Height,
/// Method, Mode, Rays, Hits, Out-Of-Steps, Mean-Evaluations, Max-Evaluations,
/// Elapsed-Ms), or with `"format": "json"` the JSON of encode_render_response with
/// the PNG in base64. Not cached: images are large and cheap to redo.
HandlerResult handle_render(const Request& request, const HandlerContext& context);

}  // namespace implicitizer::server
