// implicitizer's browser frame time: what a page pays to draw the GLSL POST /v1/sdf
// returns, exact against approximate (issue 19's "a browser frame at least 5x faster").
// A benchmark, not a test: it asserts nothing about speed and is not run by ctest.
//
// For each surface (shared/bench) and each tolerance (0 = the exact equation) on
// D = [0, 1]², mode fast: the answer's GLSL is pasted into a fragment shader that
// sphere-traces it (the camera of clients/web/examples/embed.html, 255 steps, hit at
// 1e-4 of the box unit) in Debian's chromium with WebGL2 on SwiftShader (the browser
// tests' set-up, tests/web/harness.mjs); printed: GLSL lines, the shader's compile and
// link time, and the time of one full frame (draw + readPixels, which waits for it),
// the best of --frames frames. The requests ask for a 60 s budget (timeout_ms): the
// approximation of tp_33 at 1e-3 takes about the default 10 s on a loaded machine.
// Only ratios within one run mean anything: SwiftShader runs on the machine's cores,
// shared with whatever else runs.
//
//   node bench/web/frame_time.mjs [--surface tp_33] [--tolerance 0,1e-3] [--size 128] [--frames 2]
//   node bench/web/frame_time.mjs --requests "$(cat bench/web/page_patches.json)"
//   (from the repository root, after the build and tests/web's npm ci; --requests
//   measures the given /v1/sdf requests instead: page_patches.json holds the page's
//   patch examples in their boxes, each also as the solid of its equation)
import fs from 'node:fs';
import path from 'node:path';
import { launchChromium, sharedDir, startServer, stopServer } from '../../tests/web/harness.mjs';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i > 0 && i + 1 < process.argv.length ? process.argv[i + 1] : fallback;
}
const requests = JSON.parse(option('--requests', '[]'));
const surfaces = option('--surface', 'tp_33').split(',');
const tolerances = option('--tolerance', '0,1e-3').split(',').map(Number);
const size = Number(option('--size', '128'));
const frames = Number(option('--frames', '2'));

const suite = [
  ...JSON.parse(fs.readFileSync(path.join(sharedDir, 'bench', 'surfaces_public.json'), 'utf8')),
  ...JSON.parse(fs.readFileSync(path.join(sharedDir, 'bench', 'surfaces_hard.json'), 'utf8')),
];

// Runs in the page: asks for the GLSL, compiles the tracer around it, times frames.
async function measureInPage({ request, size, frames }) {
  const response = await fetch('/v1/sdf', { method: 'POST', body: JSON.stringify(request) });
  const answer = await response.json();
  if (answer.error) return { error: `${answer.error.code}: ${answer.error.message}` };
  const fragment = `#version 300 es
precision highp float;
uniform vec3 cam_eye, cam_target;
uniform float cam_unit;
uniform vec2 cam_size;
out vec4 colour;
${answer.glsl}
void main() {
  vec3 f = normalize(cam_target - cam_eye), r = normalize(cross(f, vec3(0, 1, 0))), up = cross(r, f);
  vec2 uv = (gl_FragCoord.xy - 0.5 * cam_size) / cam_size.y;
  vec3 rd = normalize(uv.x * r + uv.y * up + f);
  float t = 0.0, tmax = 100.0 * cam_unit + length(cam_eye - cam_target);
  for (int i = 0; i < 255 && t < tmax; ++i) {
    float d = ${answer.function}(cam_eye + t * rd);
    if (d < 1e-4 * cam_unit) { colour = vec4(0.8, 0.5, 0.3, 1.0); return; }
    t += d;
  }
  colour = vec4(vec3(0.95), 1.0);
}`;
  const vertex = `#version 300 es
void main() { gl_Position = vec4(float(gl_VertexID % 2) * 4.0 - 1.0, float(gl_VertexID / 2) * 4.0 - 1.0, 0.0, 1.0); }`;
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  document.body.appendChild(canvas);
  const gl = canvas.getContext('webgl2');
  const started = performance.now();
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, vertex], [gl.FRAGMENT_SHADER, fragment]]) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) return { error: gl.getShaderInfoLog(shader) };
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) return { error: gl.getProgramInfoLog(program) };
  const compileMs = performance.now() - started;
  gl.useProgram(program);
  const box = answer.box;
  const centre = [0, 1, 2].map((i) => (box[i] + box[i + 3]) / 2);
  const away = (Math.hypot(box[3] - box[0], box[4] - box[1], box[5] - box[2]) / 2) * Math.sqrt(5) / Math.hypot(3, 3, 5);
  gl.uniform3fv(gl.getUniformLocation(program, 'cam_target'), centre);
  gl.uniform3fv(gl.getUniformLocation(program, 'cam_eye'), centre.map((c, i) => c + [3, 3, 5][i] * away));
  gl.uniform1f(gl.getUniformLocation(program, 'cam_unit'), Math.max(box[3] - box[0], box[4] - box[1], box[5] - box[2]) / 4);
  gl.uniform2f(gl.getUniformLocation(program, 'cam_size'), size, size);
  const pixels = new Uint8Array(4 * size * size);
  let best = Infinity;
  let surfacePixels = 0;
  for (let k = 0; k < frames; ++k) {
    const t0 = performance.now();
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    best = Math.min(best, performance.now() - t0);
  }
  for (let p = 0; p < size * size; ++p) surfacePixels += pixels[4 * p + 2] < 200 ? 1 : 0;
  canvas.remove();
  return {
    lines: answer.glsl.split('\n').length,
    compileMs,
    frameMs: best,
    surfacePixels,
    approximation: answer.approximation ?? null,
  };
}

const server = await startServer();
const browser = await launchChromium();
try {
  const page = await browser.newPage();
  await page.goto(server.url + '/');
  page.setDefaultTimeout(0);
  console.log('| surface | EPS | GLSL lines | compile + link (ms) | frame (ms) | surface pixels |');
  console.log('|---|---|---|---|---|---|');
  for (const request of requests) {
    const r = await page.evaluate(measureInPage, { request: { mode: 'fast', timeout_ms: 60000, ...request }, size, frames });
    if (r.error) console.log(`| ${request.name} | request | error: ${r.error.slice(0, 200)} | | | |`);
    else console.log(`| ${request.name} | request | ${r.lines} | ${r.compileMs.toFixed(0)} | ${r.frameMs.toFixed(0)} | ${r.surfacePixels} |`);
  }
  for (const name of requests.length ? [] : surfaces) {
    const s = suite.find((e) => e.name === name);
    if (!s) throw new Error(`no surface ${name}`);
    for (const tolerance of tolerances) {
      const request = { name: 'bench', mode: 'fast', x: s.x, y: s.y, z: s.z, domain: [0, 1, 0, 1], timeout_ms: 60000 };
      if (tolerance > 0) request.tolerance = tolerance;
      const r = await page.evaluate(measureInPage, { request, size, frames });
      const eps = tolerance > 0 ? tolerance.toExponential(0) : 'exact';
      if (r.error) console.log(`| ${name} | ${eps} | error: ${r.error.slice(0, 200)} | | | |`);
      else console.log(`| ${name} | ${eps} | ${r.lines} | ${r.compileMs.toFixed(0)} | ${r.frameMs.toFixed(0)} | ${r.surfacePixels} |`);
    }
  }
} finally {
  await browser.close();
  await stopServer(server);
}
