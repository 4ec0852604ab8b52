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
export async function postJson(path, body, { signal } = {}) {
  let response;
  try {
    response = await fetch(base + path, {
      method: 'POST',
      headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify(body),
      signal,
      cache: 'no-store',
    });
  } catch (error) {
    if (error.name === 'AbortError') throw error;
    throw new ApiError({ status: 0, code: 'network_error', message: `could not reach the server (${error.message})` });
  }
  const text = await response.text();
  let data = null;
  try {
    data = text ? JSON.parse(text) : null;
  } catch {
    data = null;
  }
  if (!response.ok) {
    const e = data && typeof data.error === 'object' && data.error ? data.error : null;
    const { code, message, position, field, ...details } = e || {};
    throw new ApiError({
      status: response.status,
      code: code || `http_${response.status}`,
      message: message || `the server answered ${response.status} ${response.statusText}`,
      position,
      field,
      retryAfter: response.headers.get('Retry-After'),
      details,
    });
  }
  if (data === null || typeof data !== 'object') {
    throw new ApiError({ status: response.status, code: 'invalid_answer', message: 'the server did not answer JSON' });
  }
  return data;
}

/// POST /v1/render with `body` and returns the PNG as a Blob (the page's CPU fallback
/// when WebGL2 is unavailable).
export async function renderPng(body, { signal } = {}) {
  const response = await fetch(base + '/v1/render', {
    method: 'POST',
    headers: { 'Content-Type': 'application/json' },
    body: JSON.stringify(body),
    signal,
  });
  if (!response.ok) {
    let e = {};
    try {
      e = (await response.json()).error || {};
    } catch {
      e = {};
    }
    throw new ApiError({ status: response.status, code: e.code || `http_${response.status}`, message: e.message || 'render failed', field: e.field, position: e.position });
  }
  return response.blob();
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

/// POST /v1/implicitize: {x, y, z?, parameters?, method, timeout_ms} -> the implicit
/// equation. `parameters` is the list of names in order (absent: the server takes the
/// identifiers other than x, y, z in order of appearance).
export function implicitize({ x, y, z, parameters, method, timeoutMs }, options) {
  const body = { x, y };
  if (z !== undefined && z !== '') body.z = z;
  if (parameters && parameters.length) body.parameters = parameters;
  if (method) body.method = method;
  if (timeoutMs) body.timeout_ms = timeoutMs;
  return postJson('/v1/implicitize', body, options);
}

/// POST /v1/sdf for an implicit equation ({implicit}), a parametric surface or curve
/// ({x, y, z?, parameters?, domain?}: z empty for a plane curve; parameters the names
/// in order; domain a list of exact numbers, lo and hi for each parameter in that
/// order, as typed, empty for the default) or a scene ({scene}), with the
/// shape (auto, sheet, solid; not for a scene, whose leaves carry theirs), mode, box
/// (null: fitted to a patch, else the default) and name, and for a parametric surface
/// a tolerance (null: the exact equation) -> {glsl, function, shape, dimension, box
/// (the box actually used), uniforms, approximation (with a tolerance), ...}.
export function sdf({ implicit, x, y, z, parameters, domain, tolerance, scene, shape, mode, box, name, timeoutMs }, options) {
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
  return postJson('/v1/sdf', body, options);
}
