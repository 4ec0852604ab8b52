// The HTTP API of implicitizer-server (docs/api.md), as the page uses it: JSON in,
// JSON out, every error turned into an ApiError carrying the server's code, message,
// position and field. Same origin by default; `?api=http://host:port` in the page's
// address points the page at another server (the server answers CORS for any origin
// by default).

const base = (() => {
  const given = new URLSearchParams(window.location.search).get('api');
  return given ? given.replace(/\/+$/, '') : '';
})();

/// The server the page talks to, as host:port.
export const apiHost = (() => {
  try {
    return base ? new URL(base).host : window.location.host;
  } catch {
    return base;
  }
})();

/// An error answered by the server ({"error": {...}}), or a transport failure
/// (status 0, code "network_error"). `position` is a 0-based character index into the
/// text of `field` ("x", "implicit", ...) when the server knows it.
export class ApiError extends Error {
  constructor({ status, code, message, position = null, field = null, retryAfter = null, details = {} }) {
    super(message);
    this.name = 'ApiError';
    this.status = status;
    this.code = code;
    this.position = Number.isInteger(position) ? position : null;
    this.field = typeof field === 'string' ? field : null;
    this.retryAfter = retryAfter;
    this.details = details;
  }
}

/// POSTs `body` as JSON to `path` and returns the decoded answer. `signal` (an
/// AbortSignal) cancels the request; the server then cancels the computation (a closed
/// connection cancels its budget). Rejects with ApiError, or with the DOMException
/// "AbortError" when cancelled.
export function postJson(path, body, { signal } = {}) {
  return requestJson('POST', path, { body: JSON.stringify(body), headers: { 'Content-Type': 'application/json' }, signal });
}

/// GETs `path` and returns the decoded JSON answer; rejects as postJson does.
export function getJson(path, { signal } = {}) {
  return requestJson('GET', path, { signal });
}

// One request whose answer is JSON: the answer decoded, or an ApiError built from the
// server's {"error": {...}}.
async function requestJson(method, path, { body, headers, signal, keepalive = false }) {
  const response = await send(method, path, { body, headers, signal, keepalive });
  const text = await response.text();
  let data = null;
  try {
    data = text ? JSON.parse(text) : null;
  } catch {
    data = null;
  }
  if (!response.ok) throw apiErrorFrom(response.status, data, { statusText: response.statusText, retryAfter: response.headers.get('Retry-After') });
  if (data === null || typeof data !== 'object') {
    throw new ApiError({ status: response.status, code: 'invalid_answer', message: 'the server did not answer JSON' });
  }
  return data;
}

// fetch() with the transport's failures as ApiError (status 0, network_error); an
// abort stays the DOMException "AbortError".
async function send(method, path, { body, headers, signal, keepalive = false }) {
  try {
    return await fetch(base + path, { method, headers, body, signal, keepalive, cache: 'no-store' });
  } catch (error) {
    if (error.name === 'AbortError') throw error;
    throw new ApiError({ status: 0, code: 'network_error', message: `could not reach the server (${error.message})` });
  }
}

/// The ApiError of an answer with HTTP status `status` whose decoded body is `data`
/// ({"error": {code, message, position?, field?, ...}}, or anything else when the
/// server did not say: the code is then http_STATUS). A failed job's result is such a
/// body too, which is why this is not private to requestJson.
export function apiErrorFrom(status, data, { statusText = '', retryAfter = null } = {}) {
  const e = data && typeof data.error === 'object' && data.error ? data.error : null;
  const { code, message, position, field, ...details } = e || {};
  return new ApiError({
    status,
    code: code || `http_${status}`,
    message: message || `the server answered ${status} ${statusText}`.trim(),
    position,
    field,
    retryAfter,
    details,
  });
}

/// GETs `path` (a render job's result, image/png) and returns it as a Blob; rejects
/// as postJson does.
export async function getBlob(path, { signal } = {}) {
  const response = await send('GET', path, { signal });
  if (!response.ok) {
    let data = null;
    try {
      data = await response.json();
    } catch {
      data = null;
    }
    throw apiErrorFrom(response.status, data, { statusText: response.statusText });
  }
  return response.blob();
}

// ---------------------------------------------------------------- jobs

/// POST /v1/jobs {kind, request}: the job's first state ({id, status, progress, ...};
/// a request the result cache answers is already `done`, with its result). What the
/// endpoint `kind` refuses before computing is refused here, with its own error.
export function submitJob(kind, request) {
  return postJson('/v1/jobs', { kind, request });
}

/// GET /v1/jobs/{id}: the job's state (status, progress; once finished http_status,
/// result when JSON, result_url).
export function getJob(id, { signal } = {}) {
  return getJson(`/v1/jobs/${encodeURIComponent(id)}`, { signal });
}

/// DELETE /v1/jobs/{id}: cancels a queued or running job (a finished one is removed).
/// `keepalive` lets the request outlive the page (sent as the page is left).
export function cancelJob(id) {
  return send('DELETE', `/v1/jobs/${encodeURIComponent(id)}`, { keepalive: true });
}

/// An EventSource on GET /v1/jobs/{id}/events (`progress` events, then one `end`).
export function openJobEvents(id) {
  return new EventSource(`${base}/v1/jobs/${encodeURIComponent(id)}/events`);
}

/// GET /healthz: true when the server answers {"status":"ok"}.
export async function checkHealth() {
  try {
    const response = await fetch(base + '/healthz', { cache: 'no-store' });
    if (!response.ok) return false;
    const data = await response.json();
    return data && data.status === 'ok';
  } catch {
    return false;
  }
}

/// The body of POST /v1/implicitize: {x, y, z?, parameters?, method, timeout_ms}, whose
/// answer is the implicit equation. `parameters` is the list of names in order (absent:
/// the server takes the identifiers other than x, y, z in order of appearance).
export function implicitizeRequest({ x, y, z, parameters, method, timeoutMs }) {
  const body = { x, y };
  if (z !== undefined && z !== '') body.z = z;
  if (parameters && parameters.length) body.parameters = parameters;
  if (method) body.method = method;
  if (timeoutMs) body.timeout_ms = timeoutMs;
  return body;
}

/// The body of POST /v1/sdf for an implicit equation ({implicit}), a parametric surface or curve
/// ({x, y, z?, parameters?, domain?}: z empty for a plane curve; parameters the names
/// in order; domain a list of exact numbers, lo and hi for each parameter in that
/// order, as typed, empty for the default) or a scene ({scene}), with the
/// shape (auto, sheet, solid; not for a scene, whose leaves carry theirs), mode, box
/// (null: fitted to a patch, else the default) and name, and for a parametric surface
/// a tolerance (null: the exact equation). Its answer: {glsl, function, shape,
/// dimension, box (the box actually used), uniforms, approximation (with a tolerance), ...}.
export function sdfRequest({ implicit, x, y, z, parameters, domain, tolerance, scene, shape, mode, box, name, timeoutMs }) {
  const body = { mode, name };
  if (scene !== undefined) {
    body.scene = scene;
  } else if (implicit !== undefined) {
    body.implicit = implicit;
  } else {
    body.x = x;
    body.y = y;
    if (z) body.z = z;
    if (parameters && parameters.length) body.parameters = parameters;
    if (domain && domain.length) body.domain = domain;
    if (tolerance !== null && tolerance !== undefined) body.tolerance = tolerance;
  }
  if (shape) body.shape = shape;
  if (box) body.box = box;
  if (timeoutMs) body.timeout_ms = timeoutMs;
  return body;
}
