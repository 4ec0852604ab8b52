// The live preview: a WebGL2 sphere tracer around the GLSL that POST /v1/sdf returned.
//
// The fragment shader is this file's prelude, then the service's text verbatim (it
// defines `float NAME_sdf(vec3 p)` and its helpers and uniforms, GLSL ES 3.00), then
// the tracer, which calls NAME_sdf and nothing else of the surface. The tracer mirrors
// the CPU renderer (lib/src/render/: camera.cpp, march_ray.cpp, shading.cpp,
// render_image.cpp; docs/render.md §2, §3, §5) so that the two images agree:
//
// - camera: eye looking at the box centre, view-up (0, 1, 0), focal distance 1 to an
//   image plane of height 1, uv = (pixel − resolution/2)/height (vertical field of
//   view 2·atan(1/2)); default eye = centre + (3, 3, 5)·u, u = (largest half side)/2;
// - sphere tracing from t = 0: hit when f < 1e-4·u, step t += f, miss beyond
//   t_max = 100·u + |eye − centre| or after 255 steps (then background, not a hit);
// - shading: normal by the tetrahedron technique (h = 1e-3·u) turned towards the
//   viewer; Blinn-Phong with Schlick's Fresnel, one sun (−0.5, 0.8, 0.35), the
//   improved soft shadow (0.02·u to 2.5·u, k = 1.5, 64 steps), ambient occlusion
//   along the normal (4 samples at u·i/4, weights 2^−i), gamma 2.2, background grey
//   0.95; AA×AA samples at ((m + ½)/AA, (n + ½)/AA) averaged after the gamma.
//
// The one difference: the CPU renderer takes the normal of a single polynomial from
// its exact gradient (in double); the shader only has distance functions, so it uses
// the tetrahedron technique, which the CPU renderer uses for scenes.
//
// Sheets (the answer's "shape" is "sheet": an open surface, a patch) are drawn
// two-sided as the CPU renderer draws them (docs/render.md §5): warm where the side
// F > 0 faces the viewer, blue where F < 0 does. A sheet's own function is |d| ≥ 0 on
// both sides, so neither its sign nor its gradient (which always points away from the
// surface, towards whoever looks) can tell the sides apart. The page therefore asks
// POST /v1/sdf for a second function of the same equation F, in the same box, as a
// solid (shape "solid", mode fast: F/|∇F|, signed, smooth across the surface), and the
// shader takes from it what the CPU renderer takes from ∇G: the normal (tetrahedron
// technique on the signed function, since the |d| of a sheet has a kink on the
// surface, where the four samples straddle it) and the side (∇F·ray > 0: the viewer is
// where F < 0, the back). The same signed function lets the march notice a step that
// jumps across the sheet (its sign changes between two points; the crossing is
// bisected and is a hit where the sheet's value is below ε), as SheetCrossing does in
// march_ray.cpp. Choosing the gradient over the sign at a point off the surface
// avoids asking how far off: at the hit |F| is at the level of rounding, while ∇F is
// well defined wherever the surface is smooth.
//
// Plane curves (the answer's "dimension" is 2, `float NAME_sdf(vec2 p)`) are drawn
// flat by another fragment shader that mirrors render_curve.cpp: the box fills the
// canvas with its aspect kept, less a margin (defaultPlaneView), a faint grid and the
// axes, the curve a 1.5 px line antialiased from |value| in pixels, a solid curve's
// inside tinted. Drag pans, the wheel and a pinch zoom about the canvas's centre.
//
// The image is drawn progressively, in horizontal strips sized so that each takes
// about STRIP_BUDGET_MS on the GPU (measured with fences), so that a software GL or a
// heavy shader never blocks the page; while the camera moves, a low-resolution image
// with one sample per pixel is drawn instead, then refined when the motion stops.

const STRIP_BUDGET_MS = 80;
const LOW_RES_BUDGET_MS = 30;
const WORLD_UP = [0, 1, 0];

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.sqrt(dot(a, a));
const unit = (a) => scale(a, 1 / norm(a));

/// The renderer's default camera for a box [x0, y0, z0, x1, y1, z1] (render_image.cpp
/// default_camera): target the centre, eye along (3, 3, 5) at the distance R/sin(α) at
/// which the box's bounding sphere (R: half its diagonal) fits the narrower half-angle α
/// of the view (atan(1/2) vertically, atan(aspect/2) across an image narrower than
/// tall). `unit` is half the largest half side (the length unit of the defaults).
/// Returns {target, eye, unit}.
export function defaultCamera(box, aspect = 1) {
  const centre = [(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2];
  const half = Math.max(box[3] - box[0], box[4] - box[1], box[5] - box[2]) / 2;
  const radius = 0.5 * Math.hypot(box[3] - box[0], box[4] - box[1], box[5] - box[2]);
  const extent = Number.isFinite(aspect) && aspect > 0 ? Math.min(1, aspect) / 2 : 0.5;
  const distance = radius / (extent / Math.hypot(extent, 1));
  const direction = unit([3, 3, 5]);
  return { target: centre, eye: add(centre, scale(direction, distance)), unit: half / 2 };
}

// The margin around a curve's box, a share of the canvas's smaller side: the fitted box
// is the curve's own bounding box, so without it the line touches the canvas's edges.
const PLANE_MARGIN = 0.05;

/// The 2-D view of a curve's box [x0, y0, x1, y1] in a width × height image: the box's
/// centre, pixels per unit, the grid step's extent. It is render_curve.cpp curve_view
/// of a (width − 2m) × (height − 2m) image, m = round(PLANE_MARGIN · min(width, height))
/// pixels, centred: the CPU renderer's picture at that size, framed by m pixels of margin.
export function defaultPlaneView(box, width, height) {
  const [x0, y0, x1, y1] = box;
  const extent = Math.max(x1 - x0, y1 - y0);
  const m = Math.round(PLANE_MARGIN * Math.min(width, height));
  const scale = Math.min(Math.max(1, width - 2 * m) / (x1 - x0), Math.max(1, height - 2 * m) / (y1 - y0));
  return { centre: [(x0 + x1) / 2, (y0 + y1) / 2], scale, extent };
}

/// The grid step of render_curve.cpp: the smallest 1, 2 or 5 × 10^k ≥ extent/10.
export function gridStep(extent) {
  const target = extent / 10;
  const base = Math.pow(10, Math.floor(Math.log10(target)));
  for (const m of [1, 2, 5, 10]) if (m * base >= target * (1 - 1e-12)) return m * base;
  return 10 * base;
}

/// The camera frame of docs/render.md §2 (camera.cpp): forward towards the target,
/// right = normalize(forward × up), up = right × forward.
export function cameraFrame(eye, target) {
  const forward = unit(sub(target, eye));
  const right = unit(cross(forward, WORLD_UP));
  return { forward, right, up: cross(right, forward) };
}

/// Whether this browser can create a WebGL2 context at all.
export function webgl2Available() {
  try {
    return !!document.createElement('canvas').getContext('webgl2');
  } catch {
    return false;
  }
}

/// A shader that failed to compile or link; `log` is the driver's message.
export class ShaderError extends Error {
  constructor(message, log) {
    super(message);
    this.name = 'ShaderError';
    this.log = log;
  }
}

const VERTEX_SHADER = `#version 300 es
// One triangle that covers the viewport.
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
`;

// The tetrahedron technique on `fn` (docs/render.md §5): N = Σ k_i f(p + h k_i) = 4h∇f + O(h²).
function tetrahedronNormal(name, fn) {
  return `vec3 ${name}(vec3 p) {
  float h = 1e-3 * pv_unit;
  const vec3 k0 = vec3(1.0, -1.0, -1.0);
  const vec3 k1 = vec3(-1.0, -1.0, 1.0);
  const vec3 k2 = vec3(-1.0, 1.0, -1.0);
  const vec3 k3 = vec3(1.0, 1.0, 1.0);
  vec3 n = k0 * ${fn}(p + h * k0) + k1 * ${fn}(p + h * k1) + k2 * ${fn}(p + h * k2) + k3 * ${fn}(p + h * k3);
  float len = length(n);
  return len > 0.0 ? n / len : vec3(0.0);
}`;
}

// The 3-D tracer around the service's GLSL. `surface.side`, when present, is the
// signed companion of a sheet ({glsl, functionName}: the same F as a fast solid).
function fragmentShader(surface) {
  const side = surface.side || null;
  return `#version 300 es
precision highp float;
precision highp int;
uniform vec3 pv_eye;
uniform vec3 pv_right;
uniform vec3 pv_up;
uniform vec3 pv_forward;
uniform vec2 pv_resolution;
uniform int pv_aa;
uniform float pv_unit;
uniform float pv_tmax;
out vec4 pv_colour;

// ---- the GLSL returned by POST /v1/sdf, unchanged ----
${surface.glsl}
// ---- end of the service's GLSL ----
${side ? `
// ---- the sheet's equation as a fast solid (POST /v1/sdf, shape "solid"): its sign is F's ----
${side.glsl}
// ---- end ----
` : ''}
float pv_map(vec3 p) { return ${surface.functionName}(p); }
${tetrahedronNormal('pv_normal', 'pv_map')}
${side ? `float pv_signed(vec3 p) { return ${side.functionName}(p); }
${tetrahedronNormal('pv_signed_normal', 'pv_signed')}` : ''}

// The improved soft shadow (shading.cpp soft_shadow): k = 1.5, from 0.02u to 2.5u.
float pv_shadow(vec3 p, vec3 l) {
  float t = 0.02 * pv_unit;
  float tmax = 2.5 * pv_unit;
  float res = 1.0;
  for (int i = 0; i < 64; ++i) {
    if (t > tmax) break;
    float f = pv_map(p + t * l);
    res = min(res, 1.5 * f / t);
    if (res < -1.0) break;
    t += max(abs(f), 1e-4 * pv_unit);
  }
  return smoothstep(-1.0, 1.0, max(res, -1.0));
}

// Ambient occlusion along the normal (shading.cpp ambient_occlusion), 4 samples.
float pv_occlusion(vec3 p, vec3 n) {
  float occluded = 0.0;
  float weight = 0.5;
  for (int i = 1; i <= 4; ++i) {
    float d = pv_unit * float(i) / 4.0;
    occluded += weight * (d - pv_map(p + d * n)) / pv_unit;
    weight *= 0.5;
  }
  return clamp(1.0 - occluded, 0.0, 1.0);
}

// Blinn-Phong with Schlick's Fresnel, one sun, gamma 2.2 (shading.cpp shade_hit); a
// sheet's back (the side where F < 0 faces the viewer) in blue (ShadingParams::back_albedo).
vec3 pv_shade(vec3 p, vec3 rd) {
  vec3 albedo = vec3(0.80, 0.52, 0.30);
${side ? `  vec3 n = pv_signed_normal(p);
  if (dot(n, rd) > 0.0) albedo = vec3(0.25, 0.42, 0.80);
  if (n == vec3(0.0)) n = pv_normal(p);` : `  vec3 n = pv_normal(p);`}
  if (dot(n, rd) > 0.0) n = -n;
  vec3 view = -rd;
  vec3 colour = vec3(0.20, 0.22, 0.26) * albedo * pv_occlusion(p, n);
  vec3 l = normalize(vec3(-0.5, 0.8, 0.35));
  float diffuse = max(0.0, dot(n, l));
  if (diffuse > 0.0) {
    vec3 h = normalize(l + view);
    float fresnel = 0.04 + 0.96 * pow(clamp(1.0 - dot(h, l), 0.0, 1.0), 5.0);
    float highlight = pow(max(0.0, dot(n, h)), 32.0) * fresnel;
    float shadow = pv_shadow(p, l);
    colour += vec3(1.0, 0.96, 0.9) * shadow * diffuse * (albedo + 0.5 * highlight);
  }
  return pow(clamp(colour, 0.0, 1.0), vec3(1.0 / 2.2));
}
${side ? `
// A step across the sheet (march_ray.cpp SheetCrossing): the signed function's sign
// changed between a and b; bisect on it and return the crossing when the sheet's
// value there is below eps, else -1.
float pv_crossing(vec3 ro, vec3 rd, float a, float b, float sa, float eps) {
  for (int i = 0; i < 40; ++i) {
    if (b - a <= 1e-3 * eps) break;
    float m = 0.5 * (a + b);
    float sm = sign(pv_signed(ro + m * rd));
    if (sm == 0.0) { a = m; b = m; break; }
    if (sm == sa) a = m; else b = m;
  }
  float c = 0.5 * (a + b);
  return pv_map(ro + c * rd) < eps ? c : -1.0;
}
` : ''}
void main() {
  vec2 corner = floor(gl_FragCoord.xy);  // the pixel's lower-left corner
  float eps = 1e-4 * pv_unit;
  vec3 sum = vec3(0.0);
  for (int sy = 0; sy < pv_aa; ++sy) {
    for (int sx = 0; sx < pv_aa; ++sx) {
      vec2 pixel = corner + (vec2(float(sx), float(sy)) + 0.5) / float(pv_aa);
      vec2 uv = (pixel - 0.5 * pv_resolution) / pv_resolution.y;
      vec3 rd = normalize(uv.x * pv_right + uv.y * pv_up + pv_forward);
      // Sphere tracing (march_ray.cpp march_sphere): signed hit rule, 255 steps.
      float t = 0.0;
      bool hit = false;
${side ? `      float lastT = 0.0, lastSign = 0.0;` : ''}
      for (int i = 0; i < 255; ++i) {
        float f = pv_map(pv_eye + t * rd);
        if (f < eps) { hit = true; break; }
${side ? `        float s = sign(pv_signed(pv_eye + t * rd));
        if (s != 0.0 && lastSign != 0.0 && s != lastSign) {
          float c = pv_crossing(pv_eye, rd, lastT, t, lastSign, eps);
          if (c >= 0.0) { t = c; hit = true; break; }
        }
        if (s != 0.0) { lastSign = s; lastT = t; }` : ''}
        t += f;
        if (t > pv_tmax) break;
      }
      sum += hit ? pv_shade(pv_eye + t * rd, rd) : vec3(0.95);
    }
  }
  pv_colour = vec4(sum / float(pv_aa * pv_aa), 1.0);
}
`;
}

// The flat picture of a plane curve (render_curve.cpp): one value per pixel at its
// centre, coverage clamp(w/2 + 1/2 − distance in pixels, 0, 1) for the line (w = 1.5),
// the grid (w = 1) and the inside's edge; colours of CurveStyle.
function planeShader(surface) {
  const solid = surface.shape === 'solid';
  return `#version 300 es
precision highp float;
precision highp int;
uniform vec2 pv_centre;   // the point at the canvas's centre
uniform float pv_scale;   // pixels per unit
uniform float pv_step;    // the grid's step
uniform vec4 pv_box;      // x0, y0, x1, y1
uniform vec2 pv_resolution;
out vec4 pv_colour;

// ---- the GLSL returned by POST /v1/sdf, unchanged ----
${surface.glsl}
// ---- end of the service's GLSL ----

float pv_line(float distance, float width) { return clamp(width / 2.0 + 0.5 - distance, 0.0, 1.0); }
float pv_grid(float v) { float k = v / pv_step; return abs(k - floor(k + 0.5)) * pv_step * pv_scale; }

void main() {
  // gl_FragCoord's rows count from the bottom: y grows upwards, as on the CPU's image.
  vec2 p = pv_centre + (gl_FragCoord.xy - 0.5 * pv_resolution) / pv_scale;
  bool inBox = p.x >= pv_box.x && p.x <= pv_box.z && p.y >= pv_box.y && p.y <= pv_box.w;
  vec3 colour = inBox ? vec3(0.98, 0.98, 0.97) : vec3(0.90, 0.90, 0.89);
  float value = ${surface.functionName}(p);
  bool finite = !(isnan(value) || isinf(value));
${solid ? `  if (finite) colour = mix(colour, vec3(0.99, 0.87, 0.72), clamp(0.5 - value * pv_scale, 0.0, 1.0));` : ''}
  if (inBox) {
    colour = mix(colour, vec3(0.86, 0.87, 0.89), max(pv_line(pv_grid(p.x), 1.0), pv_line(pv_grid(p.y), 1.0)));
    colour = mix(colour, vec3(0.62, 0.64, 0.68), max(pv_line(abs(p.x) * pv_scale, 1.0), pv_line(abs(p.y) * pv_scale, 1.0)));
  }
  if (finite) colour = mix(colour, vec3(0.09, 0.20, 0.55), pv_line(abs(value) * pv_scale, 1.5));
  pv_colour = vec4(colour, 1.0);
}
`;
}

/// The preview on one canvas. Create it with Preview.create(canvas) (null when WebGL2
/// is unavailable), give it a surface with setSurface(), and it redraws by itself
/// when the camera, the size or the settings change. The canvas's data- attributes
/// say what is on it (data-state: idle, compiling, rendering, done, error, empty;
/// data-frame counts finished images; data-eye, data-target (a curve: data-view, its
/// centre and pixels per unit), data-width, data-height, data-aa, data-function,
/// data-box, data-dimension, data-shape and data-sides ("two": a sheet drawn
/// two-sided) describe the last one), so that anyone (the browser test, a user's
/// script) can redo the same view elsewhere. Each finished image also dispatches a
/// `previewframe` event on the canvas (detail: {frame}).
export class Preview {
  static create(canvas, options = {}) {
    const gl = canvas.getContext('webgl2', {
      antialias: false, // AA is the tracer's own supersampling
      alpha: false,
      depth: false,
      stencil: false,
      preserveDrawingBuffer: true, // strips accumulate across frames
      powerPreference: 'high-performance',
    });
    if (!gl) return null;
    return new Preview(canvas, gl, options);
  }

  constructor(canvas, gl, { onStatus = () => {} } = {}) {
    this.canvas = canvas;
    this.gl = gl;
    this.onStatus = onStatus;
    this.parallelCompile = gl.getExtension('KHR_parallel_shader_compile');
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    this.rendererName = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
    this.surface = null; // {glsl, functionName, box, uniforms}
    this.lastView = null; // {dimension, box} of the last surface set, cleared or not
    this.program = null;
    this.locations = null;
    this.generation = 0;
    this.aa = 2;
    this.camera = null; // {target, eye, unit, centre}: the 3-D view
    this.plane = null; // {centre: [x, y], scale, defaultScale, extent}: the 2-D view of a curve
    this.frame = 0;
    this.work = null; // the image being drawn: {kind: 'low' | 'wait' | 'full' | 'finishing', nextRow}
    this.fence = null;
    this.rafPending = false;
    this.dragging = false;
    this.interactUntil = 0;
    this.stripRows = 32;
    this.lowResFactor = 4;
    this.lowRes = null; // {fbo, texture, width, height}
    this.vao = gl.createVertexArray();
    this.contextLost = false;
    this.#attachInput();
    this.#attachResize();
    canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault();
      this.contextLost = true;
      this.program = null;
      this.lowRes = null;
      this.fence = null;
      this.work = null;
      this.#setState('error', { message: 'The GPU context was lost; restoring it…' });
    });
    canvas.addEventListener('webglcontextrestored', () => {
      this.contextLost = false;
      this.vao = gl.createVertexArray();
      if (this.surface) this.setSurface(this.surface, { keepCamera: true }).catch(() => {});
    });
  }

  /// Compiles the service's GLSL into the tracer and draws it. `surface`:
  /// {glsl, functionName, box: [x0, y0, z0, x1, y1, z1] (a curve: [x0, y0, x1, y1]),
  /// uniforms: [{name, type, default}], dimension: 3 or 2, shape: "solid" or "sheet",
  /// side: {glsl, functionName} (a sheet's equation as a signed solid) or null}. Resolves when the program is linked (the image then draws
  /// progressively); rejects with ShaderError when the driver refuses it, or with
  /// an Error named "AbortError" when a newer surface replaced this one first.
  async setSurface(surface, { keepCamera = false } = {}) {
    const generation = ++this.generation;
    const gl = this.gl;
    this.work = null;
    this.#setState('compiling');
    const program = gl.createProgram();
    const vs = this.#shader(gl.VERTEX_SHADER, VERTEX_SHADER);
    const fs = this.#shader(gl.FRAGMENT_SHADER, surface.dimension === 2 ? planeShader(surface) : fragmentShader(surface));
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    gl.linkProgram(program);
    if (this.parallelCompile) {
      while (!gl.getProgramParameter(program, this.parallelCompile.COMPLETION_STATUS_KHR)) {
        await new Promise((resolve) => setTimeout(resolve, 20));
        if (generation !== this.generation || this.contextLost) break;
      }
    }
    if (generation !== this.generation) {
      gl.deleteProgram(program);
      throw Object.assign(new Error('replaced by a newer surface'), { name: 'AbortError' });
    }
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      const log = [gl.getShaderInfoLog(fs), gl.getShaderInfoLog(vs), gl.getProgramInfoLog(program)]
        .filter((s) => s && s.trim())
        .join('\n');
      gl.deleteProgram(program);
      if (this.program) gl.deleteProgram(this.program);
      this.program = null; // the last image stays on the canvas
      this.#setState('error', { message: 'The GPU could not compile the shader' });
      throw new ShaderError('the GPU could not compile the shader', log);
    }
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (this.program) gl.deleteProgram(this.program);
    this.program = program;
    const names =
      surface.dimension === 2
        ? ['pv_centre', 'pv_scale', 'pv_step', 'pv_box', 'pv_resolution']
        : ['pv_eye', 'pv_right', 'pv_up', 'pv_forward', 'pv_resolution', 'pv_aa', 'pv_unit', 'pv_tmax'];
    this.locations = Object.fromEntries(names.map((n) => [n, gl.getUniformLocation(program, n)]));
    gl.useProgram(program);
    // The scene's own uniforms at their defaults (docs/sdf.md, "Uniforms").
    for (const u of surface.uniforms || []) {
      const location = gl.getUniformLocation(program, u.name);
      if (!location) continue;
      if (u.type === 'vec3' && Array.isArray(u.default)) gl.uniform3fv(location, u.default);
      else if (typeof u.default === 'number') gl.uniform1f(location, u.default);
    }
    // The camera stays for a surface in the same box as the last one, even across a clear().
    const sameBox =
      this.lastView &&
      this.lastView.dimension === surface.dimension &&
      JSON.stringify(this.lastView.box) === JSON.stringify(surface.box);
    this.surface = surface;
    this.lastView = { dimension: surface.dimension, box: surface.box };
    if (!(keepCamera || sameBox) || !(surface.dimension === 2 ? this.plane : this.camera)) this.resetView({ redraw: false });
    this.#startImage(true);
  }

  /// Gives up the surface being compiled, if any (its setSurface rejects with
  /// AbortError), and finishes the image of the current one.
  cancelPending() {
    this.generation += 1;
    if (this.program && !this.work) this.#startImage(false);
  }

  /// Takes the surface off the canvas, so that it never shows a picture that does not
  /// answer the page's current input: a surface being compiled is given up (its
  /// setSurface rejects with AbortError), the image in progress stops, and the canvas
  /// is filled with the tracer's background grey. data-state becomes "empty" and the
  /// attributes that described the last image (data-function, data-box, data-eye, ...)
  /// are removed; data-frame keeps counting.
  clear() {
    const gl = this.gl;
    this.generation += 1;
    this.work = null;
    if (this.program) gl.deleteProgram(this.program);
    this.program = null;
    this.surface = null;
    if (!this.contextLost) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.disable(gl.SCISSOR_TEST);
      gl.clearColor(0.95, 0.95, 0.95, 1); // the shaders' background (fragmentShader)
      gl.clear(gl.COLOR_BUFFER_BIT);
    }
    const d = this.canvas.dataset;
    for (const key of ['dimension', 'shape', 'sides', 'view', 'eye', 'target', 'width', 'height', 'aa', 'function', 'box']) delete d[key];
    this.#setState('empty');
  }

  /// AA×AA samples per pixel (1 to 8).
  setAntialiasing(aa) {
    this.aa = Math.max(1, Math.min(8, aa | 0));
    if (this.program) this.#startImage(false);
  }

  /// Back to the default camera of the surface's box (a curve: the box filling the canvas
  /// but for a margin).
  resetView({ redraw = true } = {}) {
    if (!this.surface) return;
    const { width, height } = this.canvas;
    if (this.surface.dimension === 2) {
      const v = defaultPlaneView(this.surface.box, width, height);
      this.plane = { centre: v.centre, scale: v.scale, defaultScale: v.scale, extent: v.extent };
    } else {
      const c = defaultCamera(this.surface.box, width / height);
      this.camera = { target: c.target, eye: c.eye, unit: c.unit, centre: c.target, defaultDistance: norm(sub(c.eye, c.target)) };
    }
    if (redraw && this.program) this.#startImage(true);
  }

  /// Turns the eye around the target by `dAzimuth` (about the up axis) and
  /// `dElevation` radians, and moves it `zoom` times as far (1: unchanged). On a
  /// curve: zooms by 1/`zoom` about the canvas's centre.
  orbit(dAzimuth, dElevation, zoom = 1) {
    if (this.surface && this.surface.dimension === 2) {
      // The arrow keys' turns pan by a twentieth of the canvas per 5°.
      const step = (this.canvas.width / 20) * ((180 / Math.PI) / 5);
      if (dAzimuth || dElevation) return this.panPlane(dAzimuth * step, -dElevation * step);
      return this.zoomPlane(zoom);
    }
    if (!this.camera) return;
    const offset = sub(this.camera.eye, this.camera.target);
    let r = norm(offset);
    let azimuth = Math.atan2(offset[0], offset[2]);
    let elevation = Math.asin(Math.max(-1, Math.min(1, offset[1] / r)));
    azimuth += dAzimuth;
    elevation = Math.max(-1.45, Math.min(1.45, elevation + dElevation));
    const d = this.camera.defaultDistance;
    r = Math.max(0.1 * d, Math.min(20 * d, r * zoom));
    const ce = Math.cos(elevation);
    this.camera.eye = add(this.camera.target, [r * ce * Math.sin(azimuth), r * Math.sin(elevation), r * ce * Math.cos(azimuth)]);
    this.#startImage(true);
  }

  /// A curve's view: moves by (dx, dy) canvas pixels (the picture follows the pointer).
  panPlane(dx, dy) {
    if (!this.plane) return;
    const c = this.plane.centre;
    this.plane.centre = [c[0] - dx / this.plane.scale, c[1] + dy / this.plane.scale];
    this.#startImage(true);
  }

  /// A curve's view: `zoom` times as far (1/zoom as many pixels per unit, within
  /// 1/20 to 1000 times the default) about the canvas's centre.
  zoomPlane(zoom) {
    if (!this.plane) return;
    const d = this.plane.defaultScale;
    this.plane.scale = Math.max(d / 20, Math.min(1000 * d, this.plane.scale / zoom));
    this.#startImage(true);
  }

  #shader(type, source) {
    const gl = this.gl;
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    return shader;
  }

  #setState(state, extra = {}) {
    this.canvas.dataset.state = state;
    this.onStatus({ state, ...extra });
  }

  // Begins a new image: a quick low-resolution pass first when `preview` (a new
  // surface or camera), then the full image in strips.
  #startImage(preview) {
    this.work = { kind: preview ? 'low' : 'full' };
    this.#setState('rendering', { progress: 0 });
    this.#schedule();
  }

  #schedule() {
    if (this.rafPending) return;
    this.rafPending = true;
    requestAnimationFrame(() => {
      this.rafPending = false;
      this.#tick();
    });
  }

  #interacting() {
    return this.dragging || performance.now() < this.interactUntil;
  }

  // One animation frame: waits for the previous GPU batch (fence), then draws the next
  // piece of work and measures it, adapting strip sizes to the GPU's speed.
  #tick() {
    const gl = this.gl;
    if (this.contextLost || !this.program || !this.work) return;
    if (this.fence) {
      const status = gl.getSyncParameter(this.fence.sync, gl.SYNC_STATUS);
      if (status !== gl.SIGNALED) return this.#schedule();
      gl.deleteSync(this.fence.sync);
      const elapsed = performance.now() - this.fence.submitted;
      this.#adapt(this.fence.kind, elapsed);
      this.fence = null;
    }
    const work = this.work;
    if (work.kind === 'finishing') return; // the last strip's fence is awaited below
    const { width, height } = this.canvas;
    if (work.kind === 'low') {
      const lowRows = this.#drawLowRes(width, height);
      this.#fenceAfter('low', lowRows);
      work.kind = this.#interacting() ? 'wait' : 'full';
      return this.#schedule();
    }
    if (work.kind === 'wait') {
      // The camera is still moving: keep the quick image until it stops.
      if (!this.#interacting()) work.kind = 'full';
      return this.#schedule();
    }
    // work.kind === 'full': the next strip, from the top row down.
    if (work.nextRow === undefined) {
      work.nextRow = height;
      work.fullStarted = performance.now();
      this.#publishView(width, height);
    }
    const rows = Math.max(1, Math.min(work.nextRow, Math.round(this.stripRows)));
    const y0 = work.nextRow - rows;
    this.#draw(null, width, height, this.aa, [0, y0, width, rows]);
    this.#fenceAfter('full', rows);
    work.nextRow = y0;
    if (y0 > 0) {
      this.#setState('rendering', { progress: 1 - y0 / height });
      return this.#schedule();
    }
    // Last strip submitted: finish when the GPU has drawn it.
    work.kind = 'finishing';
    const finish = () => {
      if (this.work !== work) return;
      if (this.fence) {
        if (gl.getSyncParameter(this.fence.sync, gl.SYNC_STATUS) !== gl.SIGNALED) return requestAnimationFrame(finish);
        gl.deleteSync(this.fence.sync);
        this.#adapt(this.fence.kind, performance.now() - this.fence.submitted);
        this.fence = null;
      }
      this.work = null;
      this.frame += 1;
      this.canvas.dataset.frame = String(this.frame);
      const ms = performance.now() - work.fullStarted;
      this.#setState('done', { ms, width, height, aa: this.aa, renderer: this.rendererName });
      this.canvas.dispatchEvent(new CustomEvent('previewframe', { detail: { frame: this.frame } }));
    };
    requestAnimationFrame(finish);
  }

  #fenceAfter(kind, rows) {
    const gl = this.gl;
    const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.flush();
    this.fence = { sync, kind, rows, factor: this.lowResFactor, aa: this.aa, submitted: performance.now() };
  }

  // Sizes the next strip so that it takes about STRIP_BUDGET_MS, from the last strip
  // or from the quick pass (a row of it costs 1/(factor·AA²) of a full row), and the
  // quick pass's factor so that it takes about LOW_RES_BUDGET_MS. The measure
  // includes up to a frame of latency, which errs on the small side.
  #adapt(kind, elapsed) {
    const f = this.fence;
    const height = this.canvas.height;
    if (kind === 'full') {
      const perRow = Math.max(elapsed, 1) / f.rows;
      this.stripRows = Math.max(1, Math.min(height, STRIP_BUDGET_MS / perRow, this.stripRows * 2));
    } else {
      const perRow = (Math.max(elapsed, 1) / f.rows) * f.factor * f.aa * f.aa;
      this.stripRows = Math.max(1, Math.min(height, STRIP_BUDGET_MS / perRow));
      if (elapsed > 2 * LOW_RES_BUDGET_MS && this.lowResFactor < 16) this.lowResFactor *= 2;
      else if (elapsed < LOW_RES_BUDGET_MS / 3 && this.lowResFactor > 2) this.lowResFactor /= 2;
    }
  }

  #draw(framebuffer, width, height, aa, scissor) {
    const gl = this.gl;
    const L = this.locations;
    gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    gl.viewport(0, 0, width, height);
    if (scissor) {
      gl.enable(gl.SCISSOR_TEST);
      gl.scissor(scissor[0], scissor[1], scissor[2], scissor[3]);
    } else {
      gl.disable(gl.SCISSOR_TEST);
    }
    gl.useProgram(this.program);
    if (this.surface.dimension === 2) {
      // A smaller framebuffer (the quick pass) sees the same view at fewer pixels per unit.
      const v = this.plane;
      const s = v.scale * (height / this.canvas.height);
      gl.uniform2f(L.pv_centre, v.centre[0], v.centre[1]);
      gl.uniform1f(L.pv_scale, s);
      gl.uniform1f(L.pv_step, gridStep(v.extent * (v.defaultScale / v.scale)));
      gl.uniform4f(L.pv_box, ...this.surface.box);
      gl.uniform2f(L.pv_resolution, width, height);
    } else {
      const cam = this.camera;
      const frame = cameraFrame(cam.eye, cam.target);
      gl.uniform3fv(L.pv_eye, cam.eye);
      gl.uniform3fv(L.pv_right, frame.right);
      gl.uniform3fv(L.pv_up, frame.up);
      gl.uniform3fv(L.pv_forward, frame.forward);
      gl.uniform2f(L.pv_resolution, width, height);
      gl.uniform1i(L.pv_aa, aa);
      gl.uniform1f(L.pv_unit, cam.unit);
      gl.uniform1f(L.pv_tmax, 100 * cam.unit + norm(sub(cam.eye, cam.centre)));
    }
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.disable(gl.SCISSOR_TEST);
  }

  // One sample per pixel at 1/lowResFactor of the size, stretched over the canvas.
  #drawLowRes(width, height) {
    const gl = this.gl;
    const w = Math.max(1, Math.ceil(width / this.lowResFactor));
    const h = Math.max(1, Math.ceil(height / this.lowResFactor));
    if (!this.lowRes || this.lowRes.width !== w || this.lowRes.height !== h) {
      if (this.lowRes) {
        gl.deleteFramebuffer(this.lowRes.fbo);
        gl.deleteTexture(this.lowRes.texture);
      }
      const texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, w, h);
      const fbo = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
      this.lowRes = { fbo, texture, width: w, height: h };
    }
    this.#draw(this.lowRes.fbo, w, h, 1, null);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.lowRes.fbo);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    gl.blitFramebuffer(0, 0, w, h, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.LINEAR);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return h;
  }

  #publishView(width, height) {
    const d = this.canvas.dataset;
    d.dimension = String(this.surface.dimension);
    d.shape = this.surface.shape || '';
    d.sides = this.surface.side ? 'two' : 'one';
    if (this.surface.dimension === 2) {
      d.view = JSON.stringify({ centre: this.plane.centre, scale: this.plane.scale });
      delete d.eye;
      delete d.target;
    } else {
      d.eye = JSON.stringify(this.camera.eye);
      d.target = JSON.stringify(this.camera.target);
      delete d.view;
    }
    d.width = String(width);
    d.height = String(height);
    d.aa = String(this.aa);
    d.function = this.surface.functionName;
    d.box = JSON.stringify(this.surface.box);
  }

  // Drag to orbit, wheel or pinch to zoom, keys on the focused canvas.
  #attachInput() {
    const canvas = this.canvas;
    const pointers = new Map();
    let pinch = 0;
    const spread = () => {
      const [a, b] = [...pointers.values()];
      return Math.hypot(a.x - b.x, a.y - b.y);
    };
    canvas.addEventListener('pointerdown', (e) => {
      try {
        canvas.setPointerCapture(e.pointerId); // keep the drag when it leaves the canvas
      } catch {
        // not an active pointer (a synthetic event): no capture needed
      }
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      if (pointers.size === 2) pinch = spread();
      this.dragging = true;
    });
    canvas.addEventListener('pointermove', (e) => {
      const p = pointers.get(e.pointerId);
      if (!p) return;
      const dx = e.clientX - p.x, dy = e.clientY - p.y;
      p.x = e.clientX;
      p.y = e.clientY;
      if (pointers.size === 1) {
        if (!(dx || dy)) return;
        // Pointer moves are in CSS pixels; the plane's scale is in canvas pixels.
        const ratio = this.canvas.width / Math.max(1, this.canvas.getBoundingClientRect().width);
        if (this.surface && this.surface.dimension === 2) this.panPlane(dx * ratio, dy * ratio);
        else this.orbit(-dx * 0.008, dy * 0.008);
      } else if (pointers.size === 2) {
        const s = spread();
        if (pinch > 0 && s > 0) this.orbit(0, 0, pinch / s);
        pinch = s;
      }
    });
    const release = (e) => {
      pointers.delete(e.pointerId);
      if (pointers.size < 2) pinch = 0;
      if (pointers.size === 0) {
        this.dragging = false;
        this.interactUntil = performance.now() + 120;
        this.#schedule();
      }
    };
    canvas.addEventListener('pointerup', release);
    canvas.addEventListener('pointercancel', release);
    canvas.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        const lines = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1;
        this.interactUntil = performance.now() + 200;
        this.orbit(0, 0, Math.exp(e.deltaY * lines * 0.0015));
      },
      { passive: false },
    );
    canvas.addEventListener('dblclick', () => this.resetView());
    canvas.addEventListener('keydown', (e) => {
      const step = (5 * Math.PI) / 180;
      const actions = {
        ArrowLeft: () => this.orbit(step, 0),
        ArrowRight: () => this.orbit(-step, 0),
        ArrowUp: () => this.orbit(0, step),
        ArrowDown: () => this.orbit(0, -step),
        '+': () => this.orbit(0, 0, 1 / 1.15),
        '=': () => this.orbit(0, 0, 1 / 1.15),
        '-': () => this.orbit(0, 0, 1.15),
        Home: () => this.resetView(),
        0: () => this.resetView(),
      };
      const action = actions[e.key];
      if (action) {
        e.preventDefault();
        action();
      }
    });
  }

  // The drawing buffer follows the canvas's size on screen (device pixels, at most
  // 2 per CSS pixel and about 2.4 megapixels).
  #attachResize() {
    const apply = () => {
      const rect = this.canvas.getBoundingClientRect();
      let ratio = Math.min(window.devicePixelRatio || 1, 2);
      const maxPixels = 2.4e6;
      if (rect.width * rect.height * ratio * ratio > maxPixels) ratio = Math.sqrt(maxPixels / (rect.width * rect.height));
      const width = Math.max(1, Math.round(rect.width * ratio));
      const height = Math.max(1, Math.round(rect.height * ratio));
      if (width === this.canvas.width && height === this.canvas.height) return;
      this.canvas.width = width;
      this.canvas.height = height;
      if (this.program) this.#startImage(true);
    };
    new ResizeObserver(apply).observe(this.canvas);
    apply();
  }
}
