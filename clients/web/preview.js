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
// The image is drawn progressively (#startImage): complete pictures at 1/16, 1/4 ... of
// the resolution first, the coarsest drawn within QUICK_BUDGET_MS, then the
// full resolution, then the page's anti-aliasing, in horizontal strips sized so that
// each takes about STRIP_BUDGET_MS on the GPU (measured with fences). A software GL or
// a heavy shader thus shows a whole picture early and never blocks the page or holds
// the GPU long enough for the browser to take the context away; while the camera
// moves, only the quick picture is drawn, then refined when the motion stops.

const STRIP_BUDGET_MS = 80;
const QUICK_BUDGET_MS = 30;
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

// The corners of a box [x0, y0, z0, x1, y1, z1] moved in by `fraction` of its largest side.
function insetBox(box, fraction) {
  const d = fraction * Math.max(box[3] - box[0], box[4] - box[1], box[5] - box[2]);
  return [[box[0] + d, box[1] + d, box[2] + d], [box[3] - d, box[4] - d, box[5] - d]];
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

/// The GPU context was lost (or is not back yet) while a surface was being set: the
/// picture is gone, through no fault of the shader's text.
export class ContextLostError extends Error {
  constructor() {
    super('the GPU context was lost');
    this.name = 'ContextLostError';
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

// The tetrahedron technique on `fn` (docs/render.md §5): N = Σ k_i f(p + h k_i) = 4h∇f + O(h²),
// k_i from pv_tetrahedron. A loop the compiler cannot unroll (it starts at the uniform
// pv_zero, always 0) keeps one copy of `fn` instead of four: a GPU compiler inlines every
// call, and compiling is what a heavy surface's first picture waits for (SwiftShader
// compiles at the first draw).
function tetrahedronNormal(name, fn) {
  return `vec3 ${name}(vec3 p) {
  float h = 1e-3 * pv_unit;
  vec3 n = vec3(0.0);
  for (int i = pv_zero; i < 4; ++i) {
    vec3 k = pv_tetrahedron(i);
    n += k * ${fn}(p + h * k);
  }
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
uniform int pv_zero; // always 0: loops that start at it are not unrolled (tetrahedronNormal)
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
// The tetrahedron's vertices k_i = (1, −1, −1), (−1, −1, 1), (−1, 1, −1), (1, 1, 1).
vec3 pv_tetrahedron(int i) {
  return 2.0 * vec3(float(((i + 3) >> 1) & 1), float((i >> 1) & 1), float(i & 1)) - 1.0;
}
${side ? `float pv_signed(vec3 p) { return ${side.functionName}(p); }
${tetrahedronNormal('pv_signed_normal', 'pv_signed')}
// The side's sign where the march asks for it: at p pulled into the sheet's box (less a
// hair). A distance function is positive outside its box, so the sign would also change
// on the box's faces, and a fast step that crosses a face and the sheet would see the
// same sign at both ends and miss the sheet. Pulled in, the sign field is continuous
// across the faces and changes only where the side does, inside the box.
uniform vec3 pv_side_lo;
uniform vec3 pv_side_hi;
float pv_side_sign(vec3 p) { return sign(pv_signed(clamp(p, pv_side_lo, pv_side_hi))); }` : ''}

// Blinn-Phong with Schlick's Fresnel, one sun, gamma 2.2 (shading.cpp shade_hit); a
// sheet's back (the side where F < 0 faces the viewer) in blue (ShadingParams::back_albedo).
// What shading asks of the surface (its normal where no side function gives one,
// ambient occlusion along the normal with 4 samples, the improved soft shadow with
// k = 1.5 from 0.02u to 2.5u) runs in one loop with one call of it: each call site is
// a copy of the surface's code to compile, and with the march's this makes two instead
// of four. The march keeps its own loop: one loop for everything compiled faster still
// but drew several times slower (docs/benchmarks.md, "The page: first pictures on
// SwiftShader").
vec3 pv_shade(vec3 p, vec3 rd) {
  vec3 albedo = vec3(0.80, 0.52, 0.30);
${side ? `  vec3 n = pv_signed_normal(p);
  if (dot(n, rd) > 0.0) albedo = vec3(0.25, 0.42, 0.80);` : `  vec3 n = vec3(0.0);`}
  int phase = n == vec3(0.0) ? 0 : 1;  // 0 the surface's normal, 1 occlusion, 2 shadow
  if (phase == 1 && dot(n, rd) > 0.0) n = -n;
  vec3 sum = vec3(0.0);
  int k = 0;
  float h = 1e-3 * pv_unit;
  float occluded = 0.0, weight = 0.5;
  vec3 colour = vec3(0.0);
  vec3 l = normalize(vec3(-0.5, 0.8, 0.35));
  float diffuse = 0.0, highlight = 0.0, st = 0.0, res = 1.0;
  for (int i = pv_zero; i < 4 + 4 + 64; ++i) {
    vec3 q = phase == 0 ? p + h * pv_tetrahedron(k) : phase == 1 ? p + (pv_unit * float(k + 1) / 4.0) * n : p + st * l;
    float f = pv_map(q);
    if (phase == 0) {
      sum += pv_tetrahedron(k) * f;
      if (++k < 4) continue;
      float len = length(sum);
      n = len > 0.0 ? sum / len : vec3(0.0);
      if (dot(n, rd) > 0.0) n = -n;
      phase = 1;
      k = 0;
      continue;
    }
    if (phase == 1) {
      occluded += weight * (pv_unit * float(k + 1) / 4.0 - f) / pv_unit;
      weight *= 0.5;
      if (++k < 4) continue;
      colour = vec3(0.20, 0.22, 0.26) * albedo * clamp(1.0 - occluded, 0.0, 1.0);
      diffuse = max(0.0, dot(n, l));
      if (diffuse <= 0.0) break;
      vec3 halfway = normalize(l - rd);
      float fresnel = 0.04 + 0.96 * pow(clamp(1.0 - dot(halfway, l), 0.0, 1.0), 5.0);
      highlight = pow(max(0.0, dot(n, halfway)), 32.0) * fresnel;
      phase = 2;
      st = 0.02 * pv_unit;
      k = 0;
      continue;
    }
    res = min(res, 1.5 * f / st);
    st += max(abs(f), 1e-4 * pv_unit);
    if (res >= -1.0 && ++k < 64 && st <= 2.5 * pv_unit) continue;
    colour += vec3(1.0, 0.96, 0.9) * smoothstep(-1.0, 1.0, max(res, -1.0)) * diffuse * (albedo + 0.5 * highlight);
    break;
  }
  return pow(clamp(colour, 0.0, 1.0), vec3(1.0 / 2.2));
}
${side ? `
// Sphere tracing of a sheet (march_ray.cpp march_sphere with SheetCrossing): a step
// whose ends lie on different sides of F = 0 (the signed function's sign) is scanned
// in 16 parts, and each part whose ends differ is bisected on the sign in turn, the
// first crossing where the sheet's value is below eps a hit; a crossing off the drawn
// sheet (its untrimmed continuation) lets the scan go on. All of it is one loop whose
// every pass evaluates the sheet and the sign once, rather than loops nested in the
// march: the surface's code then appears once here, where a GPU compiler inlines every
// call (tetrahedronNormal says why that matters).
float pv_march_sheet(vec3 ro, vec3 rd, float eps) {
  float t = 0.0;                      // marching: the current point
  float lastT = 0.0, lastSign = 0.0;  // the last point with a sign, and that sign
  int phase = 0;                      // 0 marching, 1 scanning [lastT, endT], 2 bisecting [a, b]
  int steps = 0, part = 0, halvings = 0;
  float endT = 0.0, endSign = 0.0;    // the step being scanned: its far end and side
  float scanT = 0.0, scanSign = 0.0;  // the scan's position and its side
  float a = 0.0, b = 0.0, sb = 0.0;   // the part being bisected; scanSign at a, sb at b
  for (int i = 0; i < 1024; ++i) {
    float q = phase == 0 ? t : phase == 1 ? mix(lastT, endT, float(part) / 16.0) : 0.5 * (a + b);
    vec3 p = ro + q * rd;
    float f = pv_map(p);
    float s = pv_side_sign(p);
    if (phase == 0) {
      if (f < eps) return t;
      if (s != 0.0 && lastSign != 0.0 && s != lastSign) {
        phase = 1;
        endT = t;
        endSign = s;
        scanT = lastT;
        scanSign = lastSign;
        part = 1;
        continue;
      }
      if (s != 0.0) { lastSign = s; lastT = t; }
      t += f;
      if (t > pv_tmax || ++steps >= 255) return -1.0;
    } else if (phase == 1) {
      if (s != 0.0 && s != scanSign) {
        phase = 2;
        a = scanT;
        b = q;
        sb = s;
        halvings = 0;
        continue;
      }
      if (s != 0.0) { scanT = q; scanSign = s; }
      if (++part > 16) {
        // No crossing on the sheet in this step: march on from its far end.
        phase = 0;
        lastT = endT;
        lastSign = endSign;
        t = endT;
      }
    } else {
      float m = q;
      if (s == 0.0 || m <= a || m >= b) { a = m; b = m; }
      else if (s == scanSign) a = m;
      else b = m;
      if (b - a <= 1e-3 * eps || ++halvings >= 40) {
        if (f < eps) return m;
        // A crossing off the sheet: the scan goes on from the part's end (evaluated
        // again, with the side it had, so the scan's own step moves past it).
        phase = 1;
        scanT = b;
        scanSign = sb;
      }
    }
  }
  return -1.0;
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
${side ? `      float t = pv_march_sheet(pv_eye, rd, eps);
      bool hit = t >= 0.0;` : `      float t = 0.0;
      bool hit = false;
      for (int i = 0; i < 255; ++i) {
        float f = pv_map(pv_eye + t * rd);
        if (f < eps) { hit = true; break; }
        t += f;
        if (t > pv_tmax) break;
      }`}
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
    this.work = null; // the picture being drawn: {factor, aa, rung, nextRow, lastRows, started, finishing}
    this.fence = null;
    this.rafPending = false;
    this.dragging = false;
    this.interactUntil = 0;
    this.rowCost = undefined; // ms of one full-width row at one sample per pixel, as last measured
    this.lowRes = null; // {fbo, texture, width, height}
    this.vao = gl.createVertexArray();
    this.contextLost = false;
    this.resolution = 1; // the fraction of the canvas's pixels drawn (setResolution)
    this.#attachInput();
    this.#attachResize();
    // A lost context (the browser's watchdog took the GPU back from a draw or a
    // compilation that ran too long, or the GPU reset) takes the picture with it: the
    // state says so (data-lost counts the losses) until a surface is drawn again. When
    // the context is restored, the surface that was up is not redrawn by itself, since
    // it may be what cost the context; the page offers what to change.
    this.losses = 0;
    canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault(); // asks for the context back
      this.contextLost = true;
      this.program = null;
      this.lowRes = null;
      this.fence = null;
      this.work = null;
      this.losses += 1;
      canvas.dataset.lost = String(this.losses);
      this.#setState('lost', { restored: false });
    });
    canvas.addEventListener('webglcontextrestored', () => {
      this.contextLost = false;
      this.vao = gl.createVertexArray();
      this.#setState('lost', { restored: true });
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
    if (this.contextLost) throw new ContextLostError();
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
    if (this.contextLost || gl.isContextLost()) throw new ContextLostError();
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
    if (surface.side && surface.dimension !== 2) {
      const [lo, hi] = insetBox(surface.box, 1e-5);
      gl.uniform3fv(gl.getUniformLocation(program, 'pv_side_lo'), lo);
      gl.uniform3fv(gl.getUniformLocation(program, 'pv_side_hi'), hi);
    }
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
    this.rowCost = undefined; // another shader: its first quick pass measures it
    this.canvas.dataset.pictures = '0';
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

  /// Draws `scale` (1, 1/2, 1/4) of the canvas's pixels in each direction, stretched
  /// by the browser: a heavy shader on a slow GPU at a quarter of the cost per halving.
  setResolution(scale) {
    this.resolution = Math.max(0.125, Math.min(1, Number(scale) || 1));
    this.applySize();
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

  // Begins a new image. `preview` (a new surface, camera or canvas size): a ladder of
  // complete pictures, each at four times the resolution of the last (one sample per pixel,
  // stretched over the canvas), from the coarsest that fits QUICK_BUDGET_MS, to the full
  // resolution; then, when the page asks for AA×AA > 1, the full resolution again at
  // AA×AA (state "refining" until then). Each picture is counted in data-pictures (its
  // factor in data-picture-factor); the finished one makes the state "done" and counts in
  // data-frame. While the camera moves, only the first rung is drawn. Without `preview`
  // (another AA), only the last pass is drawn over the picture already there.
  #startImage(preview) {
    this.work = preview ? { factor: this.#quickFactor(), aa: 1, rung: 0 } : { factor: 1, aa: this.aa, rung: 0 };
    this.#setState('rendering', { progress: 0, factor: this.work.factor });
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
  // strip of the current picture. Every batch is measured (#adapt) and the next one
  // sized to STRIP_BUDGET_MS by it, so that no single draw of a heavy shader holds the
  // GPU for long: a draw of seconds is what makes a browser take the context away.
  #tick() {
    const gl = this.gl;
    if (this.contextLost || !this.program || !this.work) return;
    if (this.fence) {
      const status = gl.getSyncParameter(this.fence.sync, gl.SYNC_STATUS);
      if (status !== gl.SIGNALED) return this.#schedule();
      gl.deleteSync(this.fence.sync);
      this.#adapt(this.fence, performance.now() - this.fence.submitted);
      this.fence = null;
    }
    const work = this.work;
    if (work.finishing) return; // the last strip's fence is awaited by finish()
    const { width, height } = this.canvas;
    const target = this.#target(work.factor, width, height);
    if (work.nextRow === undefined) {
      // A moving camera keeps its first rung until it stops.
      if (work.rung > 0 && this.#interacting()) return this.#schedule();
      work.nextRow = target.height;
      work.started ??= performance.now();
      if (work.factor === 1) this.#publishView(width, height, work.aa);
    }
    // Rows of the picture being drawn (1/factor of the canvas), from the top down; a
    // surface not yet measured draws its first, coarsest picture at once.
    const perRow = this.rowCost === undefined ? 0 : (this.rowCost * work.aa * work.aa) / work.factor;
    const fit = perRow > 0 ? Math.round(STRIP_BUDGET_MS / perRow) : work.nextRow;
    const rows = Math.max(1, Math.min(work.nextRow, fit, work.lastRows ? 2 * work.lastRows : fit));
    const y0 = work.nextRow - rows;
    work.lastRows = rows;
    this.#draw(target.framebuffer, target.width, target.height, work.aa, [0, y0, target.width, rows]);
    this.#fenceAfter(rows, work.factor, work.aa);
    work.nextRow = y0;
    if (y0 > 0) {
      this.#setState(work.aa > 1 && work.rung > 0 ? 'refining' : 'rendering', { progress: 1 - y0 / target.height, factor: work.factor, aa: work.aa });
      return this.#schedule();
    }
    // Last strip submitted: the picture counts when the GPU has drawn it.
    work.finishing = true;
    const finish = () => {
      if (this.work !== work) return;
      if (this.fence) {
        if (gl.getSyncParameter(this.fence.sync, gl.SYNC_STATUS) !== gl.SIGNALED) return requestAnimationFrame(finish);
        gl.deleteSync(this.fence.sync);
        this.#adapt(this.fence, performance.now() - this.fence.submitted);
        this.fence = null;
      }
      if (work.factor > 1) this.#showLowRes(width, height);
      this.#pictureDone(work, width, height);
    };
    requestAnimationFrame(finish);
  }

  // A complete picture is on the canvas: count it, then climb to the next rung (four
  // times the resolution each way, or straight to the finest that fits the quick
  // budget: the rungs below the full resolution then cost a fifteenth of it), then to
  // the page's AA, or finish.
  #pictureDone(work, width, height) {
    const d = this.canvas.dataset;
    d.pictures = String(Number(d.pictures || 0) + 1);
    d.pictureFactor = String(work.factor);
    const ms = performance.now() - work.started;
    const next = { rung: work.rung + 1, started: work.started };
    if (work.factor > 1) {
      Object.assign(next, { factor: Math.max(1, Math.min(work.factor / 4, this.#quickFactor())), aa: 1 });
    } else if (work.aa < this.aa) {
      Object.assign(next, { factor: 1, aa: this.aa });
    } else {
      this.work = null;
      this.frame += 1;
      d.frame = String(this.frame);
      this.#setState('done', { ms, width, height, aa: work.aa, renderer: this.rendererName });
      this.canvas.dispatchEvent(new CustomEvent('previewframe', { detail: { frame: this.frame } }));
      return;
    }
    this.work = next;
    this.#setState(next.aa > 1 ? 'refining' : 'rendering', { progress: 0, factor: next.factor, aa: next.aa, ms, pictureFactor: work.factor });
    this.#schedule();
  }

  #fenceAfter(rows, factor, aa) {
    const gl = this.gl;
    const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.flush();
    this.fence = { sync, rows, factor, aa, submitted: performance.now() };
  }

  // Measures a batch: this.rowCost, the time of one full-width row at one sample per
  // pixel, from a strip of `rows` rows of a picture at 1/factor of the canvas's size
  // and AA×AA samples. The measure includes up to a frame of latency, which errs on the
  // safe side.
  #adapt(fence, elapsed) {
    this.rowCost = (Math.max(elapsed, 1) * fence.factor) / (fence.rows * fence.aa * fence.aa);
  }

  // The coarsest rung: the smallest power of two (1 to 16) by which the canvas shrunk
  // draws in about QUICK_BUDGET_MS by the last measure; 16 before this surface's first.
  #quickFactor() {
    if (this.rowCost === undefined) return 16;
    const ideal = Math.sqrt((this.rowCost * this.canvas.height) / QUICK_BUDGET_MS);
    return Math.min(16, 2 ** Math.max(0, Math.ceil(Math.log2(Math.max(ideal, 1)))));
  }

  // Where a picture at 1/factor of the canvas is drawn: the canvas itself at factor 1,
  // else an offscreen framebuffer of that size, shown when complete (#showLowRes), so
  // that the canvas only ever changes by whole pictures or by strips of the finest.
  #target(factor, width, height) {
    if (factor === 1) return { framebuffer: null, width, height };
    const gl = this.gl;
    const w = Math.max(1, Math.ceil(width / factor));
    const h = Math.max(1, Math.ceil(height / factor));
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
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      this.lowRes = { fbo, texture, width: w, height: h };
    }
    return { framebuffer: this.lowRes.fbo, width: w, height: h };
  }

  // The offscreen picture, stretched over the canvas.
  #showLowRes(width, height) {
    const gl = this.gl;
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.lowRes.fbo);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    gl.blitFramebuffer(0, 0, this.lowRes.width, this.lowRes.height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.LINEAR);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
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

  #publishView(width, height, aa) {
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
    d.aa = String(aa);
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
      let ratio = Math.min(window.devicePixelRatio || 1, 2) * this.resolution;
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
    this.applySize = apply;
    apply();
  }
}
