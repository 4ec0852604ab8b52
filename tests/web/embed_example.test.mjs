// Browser test of the minimal embedding example, clients/web/examples/embed.html (the
// page docs/guide.md quotes): on the real server, in Debian's chromium with WebGL2 on
// SwiftShader (harness.mjs), the page asks POST /v1/sdf for a scene, pastes the GLSL
// into its own fragment shader and draws it. Checked: the server answered 200; the
// canvas shows the surface in the middle and the background grey in the corners, with
// the silhouette of POST /v1/render for the same request (the same camera); the
// uniform the answer lists reaches the shader (moving the radius slider redraws the
// middle of the picture, without a new request); no console error, no failed request
// (Chromium's own request for /favicon.ico aside).
//
//   node --test --test-reporter=spec tests/web/embed_example.test.mjs   (from the repository root)
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { BACKGROUND, decodePng, launchChromium, silhouette, startServer, stopServer, watchErrors } from './harness.mjs';

const SIZE = 256; // the page's canvas (SwiftShader is a CPU: small is quick)

let server;
let browser;
let page;
const errors = [];
let sdfRequests = 0;

/// The canvas as the page shows it (a screenshot of the element), its silhouette and
/// the number of surface pixels.
async function canvasImage() {
  const image = decodePng(await page.locator('#view').screenshot());
  assert.equal(image.width, SIZE);
  assert.equal(image.height, SIZE);
  const mask = silhouette(image.rgb, image.width, image.height);
  return { ...image, mask, surface: mask.reduce((s, v) => s + v, 0) };
}

/// Whether every pixel of the n×n square at (x0, y0) is surface (`want` 1) or exactly
/// the background grey (`want` 0).
function square(image, x0, y0, n, want) {
  for (let y = y0; y < y0 + n; ++y) {
    for (let x = x0; x < x0 + n; ++x) {
      const p = y * image.width + x;
      if (want === 1 && !image.mask[p]) return false;
      if (want === 0 && [0, 1, 2].some((k) => image.rgb[3 * p + k] !== BACKGROUND)) return false;
    }
  }
  return true;
}

async function waitForFrame(n) {
  await page.waitForFunction((f) => Number(document.getElementById('view').dataset.frame || 0) >= f, n, {
    timeout: 120000,
    polling: 100,
  });
}

before(async () => {
  server = await startServer();
  browser = await launchChromium();
  page = await browser.newPage({ viewport: { width: 800, height: 600 }, deviceScaleFactor: 1 });
  watchErrors(page, errors);
  page.on('request', (r) => {
    if (r.url().endsWith('/v1/sdf')) ++sdfRequests;
  });
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));
  page.on('response', (r) => {
    if (r.status() >= 400) errors.push(`HTTP ${r.status()}: ${r.url()}`);
  });
});

after(async () => {
  if (browser) await browser.close();
  await stopServer(server);
});

test('embed.html draws the scene POST /v1/sdf describes', async (t) => {
  const answered = page.waitForResponse((r) => r.url().endsWith('/v1/sdf'));
  await page.goto(server.url + '/examples/embed.html');
  const response = await answered;
  assert.equal(response.status(), 200);
  const answer = await response.json();
  assert.equal(answer.function, 'demo_sdf');
  assert.deepEqual(answer.uniforms, [{ name: 'ball_radius', type: 'float', default: 0.8 }]);
  await waitForFrame(1);
  assert.equal(await page.inputValue('#radius'), '0.8', "the slider starts at the uniform's default");
  assert.equal(await page.textContent('#glsl'), answer.glsl, 'the page shows the GLSL it compiled');
  assert.match(await page.textContent('#status'), /^demo_sdf\(vec3 p\), fast mode; the torus leaf: x\^4\+2\*x\^2\*y\^2\+y\^4/);
  const image = await canvasImage();
  t.diagnostic(`surface pixels: ${image.surface} of ${SIZE * SIZE}`);
  // The ball in the torus' hole is in the middle of the view; the corners see nothing.
  const c = SIZE / 2 - 16;
  assert.ok(square(image, c, c, 32, 1), 'the middle of the canvas shows the surface');
  for (const [x, y] of [[0, 0], [SIZE - 24, 0], [0, SIZE - 24], [SIZE - 24, SIZE - 24]]) {
    assert.ok(square(image, x, y, 24, 0), `the corner at (${x}, ${y}) is the background grey`);
  }
  assert.ok(image.surface > 0.1 * SIZE * SIZE && image.surface < 0.6 * SIZE * SIZE, `${image.surface} surface pixels`);

  // The page's camera is the CPU renderer's default: POST /v1/render of the same
  // request, one sample per pixel, has the same silhouette.
  const request = response.request().postDataJSON();
  const rendered = await fetch(server.url + '/v1/render', {
    method: 'POST',
    body: JSON.stringify({ ...request, width: SIZE, height: SIZE, aa: 1, timeout_ms: 300000 }),
  });
  assert.equal(rendered.status, 200);
  const cpu = decodePng(Buffer.from(await rendered.arrayBuffer()));
  const cpuMask = silhouette(cpu.rgb, cpu.width, cpu.height);
  let both = 0, either = 0;
  for (let p = 0; p < cpuMask.length; ++p) {
    both += cpuMask[p] & image.mask[p];
    either += cpuMask[p] | image.mask[p];
  }
  t.diagnostic(`silhouette IoU with POST /v1/render: ${(both / either).toFixed(4)} (X-Render-Hits ${rendered.headers.get('x-render-hits')})`);
  assert.ok(both / either >= 0.98, `IoU ${both / either} >= 0.98`);
});

test("the answer's uniform reaches the shader: a larger ball changes the middle of the picture", async (t) => {
  const small = await canvasImage();
  await page.$eval('#radius', (input) => {
    input.value = '1.4';
    input.dispatchEvent(new Event('input'));
  });
  await waitForFrame(2);
  const larger = await canvasImage();
  // The ball sits in the torus' hole, so its silhouette hardly changes; its shading does.
  let changed = 0;
  for (let p = 0; p < SIZE * SIZE; ++p) {
    if ([0, 1, 2].some((k) => Math.abs(small.rgb[3 * p + k] - larger.rgb[3 * p + k]) > 8)) ++changed;
  }
  t.diagnostic(`pixels changed by the radius 0.8 -> 1.4: ${changed}; surface pixels ${small.surface} -> ${larger.surface}`);
  assert.ok(changed > 0.02 * SIZE * SIZE, `${changed} pixels changed`);
  assert.ok(larger.surface >= small.surface, 'the blend only grows');
  const c = SIZE / 2 - 16;
  assert.ok(square(larger, c, c, 32, 1), 'the middle still shows the surface');
  assert.equal(sdfRequests, 1, 'one request to /v1/sdf: a uniform needs no new one');
  for (const [x, y] of [[0, 0], [SIZE - 24, SIZE - 24]]) assert.ok(square(larger, x, y, 24, 0), `corner (${x}, ${y})`);
});

test('no errors in the page console, no failed request', () => {
  assert.deepEqual(errors, []);
});
