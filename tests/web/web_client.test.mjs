// Browser tests of the web client (clients/web): the real implicitizer-server on a
// loopback port serving clients/web, and Debian's chromium, headless, driven by
// playwright-core, with WebGL2 on SwiftShader (a software GPU). Nothing is mocked.
//
//   node --test tests/web/                    (from the repository root)
//   IMPLICITIZER_SERVER=build/bin/implicitizer-server CHROMIUM=/usr/bin/chromium node --test tests/web/
//
// What it checks: the sphere and Steiner's surface typed and picked from the menu
// give their equations, degree, method, time, verified flag and scripts; the preview
// shows exactly the GLSL POST /v1/sdf returns, and its silhouette matches the CPU
// renderer's image of the same view (POST /v1/render, IoU >= 0.9) in fast and safe
// mode; Copy GLSL puts that text on the clipboard; errors appear beside the right
// input with the server's position selected and marked; Cancel deletes the job of a
// long Gröbner computation and the server counts it cancelled (web_jobs.test.mjs tests
// the jobs themselves); without WebGL2 the page
// says so and shows the server's CPU image; examples.json matches shared/bench;
// the hyperbolic paraboloid, Enneper's surface and a bicubic patch are drawn as
// two-sided sheets (both side colours, the CPU renderer's sheet and not its solid with
// caps), and a plane curve is drawn flat, as the CPU renderer draws it.
// It saves a 1280×800 screenshot, docs/images/web_client.png for the README when that
// is missing or UPDATE_SCREENSHOT=1 (else in the temporary folder). The server and
// browser setup is harness.mjs, shared with embed_example.test.mjs.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { buildExamples, examplesPath } from '../../scripts/make-web-examples.mjs';
import {
  decodePng,
  dragPreview,
  iou,
  launchChromium,
  readPreviewCanvas,
  root,
  sharedDir,
  silhouette,
  startServer,
  stopServer,
  watchErrors,
} from './harness.mjs';

// The README's picture is (re)written when it is missing or UPDATE_SCREENSHOT=1;
// otherwise the screenshot goes to the temporary folder, so that a test run leaves
// the work tree as it was (the picture shows times and a port that change).
const docsScreenshot = path.join(root, 'docs', 'images', 'web_client.png');
const screenshotPath =
  process.env.UPDATE_SCREENSHOT === '1' || !fs.existsSync(docsScreenshot)
    ? docsScreenshot
    : path.join(os.tmpdir(), 'implicitizer-web_client.png');

const SPHERE = { x: '2*s/(1+s^2+t^2)', y: '2*t/(1+s^2+t^2)', z: '(1-s^2-t^2)/(1+s^2+t^2)' };
const IOU_MIN = 0.9;
// How long a wait for a picture may take before the test fails: a hang guard, not a
// speed requirement. The heaviest picture here (Enneper's trimmed sheet, full
// resolution on SwiftShader) came within a minute of 180 s in a fresh-clone .ci/run.
const WAIT_MS = 400000;
// The page's Resolution for the trimmed sheets (a quarter of the pixels): what they
// test is the picture's content, compared with the CPU renderer's of the same size.
const HEAVY_RESOLUTION = '0.5';

let server; // {process, url, logPath}
let browser;
let context;
let page;
const pageErrors = [];

// ------------------------------------------------------------------ helpers

async function post(pathname, body) {
  const response = await fetch(server.url + pathname, { method: 'POST', body: JSON.stringify(body) });
  return { status: response.status, headers: response.headers, body: Buffer.from(await response.arrayBuffer()) };
}

async function postJson(pathname, body) {
  const r = await post(pathname, body);
  return { status: r.status, json: JSON.parse(r.body.toString('utf8')) };
}

async function metric(name) {
  const text = await (await fetch(server.url + '/metrics')).text();
  const line = text.split('\n').find((l) => l.startsWith(name + ' ') || l.startsWith(name + '{'));
  return line ? Number(line.trim().split(/\s+/).pop()) : 0;
}

/// The preview canvas's pixels and the view it shows (harness.mjs readPreviewCanvas).
function readCanvas() {
  return readPreviewCanvas(page);
}

/// Waits until the preview has finished an image of `equation` in `mode` newer than
/// frame `after`.
async function waitForImage(equation, mode, afterFrame, timeout = WAIT_MS) {
  await withPreviewState(page.waitForFunction(
    ([eq, m, f]) => {
      const d = document.getElementById('preview').dataset;
      return d.state === 'done' && d.equation === eq && d.mode === m && Number(d.frame || 0) > f;
    },
    [equation, mode, afterFrame],
    { timeout, polling: 100 },
  ));
}

/// `waiting`, whose timeout, if it comes, says where the preview was: the state, the
/// pictures drawn and their factor, the function and status.
async function withPreviewState(waiting) {
  try {
    await waiting;
  } catch (e) {
    const state = await page.evaluate(() => {
      const { request, view, equation, ...d } = document.getElementById('preview').dataset;
      return JSON.stringify({ ...d, stats: document.getElementById('preview-stats').textContent });
    });
    e.message += `\npreview: ${state}`;
    throw e;
  }
}

async function currentFrame() {
  return page.evaluate(() => Number(document.getElementById('preview').dataset.frame || 0));
}

/// Waits until the preview has finished an image newer than frame `afterFrame` whose
/// canvas attributes satisfy `predicate(dataset, arg)` (run in the page: it sees only
/// its arguments).
async function waitForFrame(afterFrame, predicate, arg = null, timeout = WAIT_MS) {
  await withPreviewState(page.waitForFunction(
    ([f, source, a]) => {
      const d = document.getElementById('preview').dataset;
      // eslint-disable-next-line no-new-func
      return d.state === 'done' && Number(d.frame || 0) > f && new Function('d', 'a', `return (${source})(d, a);`)(d, a);
    },
    [afterFrame, predicate.toString(), arg],
    { timeout, polling: 100 },
  ));
}

/// POST /v1/render of the view on the canvas (its object, shape, box, eye, target,
/// size, AA), with `overrides`; returns the decoded PNG.
async function renderSameView(view, overrides = {}, t = null) {
  const request = {
    ...JSON.parse(view.request),
    mode: view.mode,
    box: JSON.parse(view.box),
    width: Number(view.width),
    height: Number(view.height),
    aa: Number(view.aa),
    method: 'sphere',
    timeout_ms: 300000,
    ...overrides,
  };
  if (view.eye) {
    request.eye = JSON.parse(view.eye);
    request.target = JSON.parse(view.target);
  }
  const started = Date.now();
  const r = await post('/v1/render', request);
  assert.equal(r.status, 200, r.body.toString('utf8').slice(0, 300));
  assert.equal(r.headers.get('content-type'), 'image/png');
  if (t) t.diagnostic(`CPU render (${JSON.stringify(overrides)}) ${Date.now() - started} ms`);
  return decodePng(r.body);
}

/// Compares the canvas with POST /v1/render of the same view; returns the IoU.
async function compareWithCpuRenderer(equation, mode, t) {
  const canvas = await readCanvas();
  const v = canvas.view;
  assert.equal(v.function !== undefined, true, 'the canvas says which function it draws');
  assert.equal(v.mode, mode);
  const started = Date.now();
  const png = await renderSameView(v);
  assert.equal(png.width, canvas.width);
  assert.equal(png.height, canvas.height);
  const gpuMask = silhouette(canvas.rgb, canvas.width, canvas.height);
  const cpuMask = silhouette(png.rgb, png.width, png.height);
  const gpuCount = gpuMask.reduce((s, v) => s + v, 0);
  const cpuCount = cpuMask.reduce((s, v) => s + v, 0);
  const score = iou(gpuMask, cpuMask);
  // The shading too: the mean and the 99th percentile of |GPU − CPU| over the channels
  // of the pixels both call surface.
  const diffs = [];
  for (let p = 0; p < gpuMask.length; ++p) {
    if (!(gpuMask[p] && cpuMask[p])) continue;
    for (let k = 0; k < 3; ++k) diffs.push(Math.abs(canvas.rgb[3 * p + k] - png.rgb[3 * p + k]));
  }
  diffs.sort((a, b) => a - b);
  const meanDiff = diffs.reduce((s, v) => s + v, 0) / Math.max(1, diffs.length);
  const p99 = diffs.length ? diffs[Math.floor(0.99 * (diffs.length - 1))] : 0;
  const line = `${equation} (${mode}, ${canvas.width}x${canvas.height}, AA ${v.aa}): IoU ${score.toFixed(4)}, ` +
    `surface pixels GPU ${gpuCount} / CPU ${cpuCount}, colour |GPU - CPU| mean ${meanDiff.toFixed(2)} p99 ${p99} ` +
    `(of 255), CPU render ${Date.now() - started} ms`;
  t.diagnostic(line);
  // "Shows the surface": a real share of the image, and the centre row is not blank.
  assert.ok(gpuCount > 0.02 * canvas.width * canvas.height, `the canvas shows the surface (${gpuCount} pixels)`);
  assert.ok(score >= IOU_MIN, `IoU ${score} >= ${IOU_MIN}`);
  // Same shading model: a loose bound (the normals differ, docs: clients/web/README.md).
  assert.ok(meanDiff < 2, `mean colour difference ${meanDiff} < 2 of 255`);
  return score;
}

/// The surface pixels of an image by side colour: warm (a sheet's front, or a solid)
/// where red exceeds blue by more than 16, blue (a sheet's back) where blue exceeds red
/// by more than 16 (the two albedos, (0.80, 0.52, 0.30) and (0.25, 0.42, 0.80), keep
/// that order under any grey light and the gamma).
function sideCounts(rgb, mask) {
  let warm = 0, blue = 0;
  for (let p = 0; p < mask.length; ++p) {
    if (!mask[p]) continue;
    const r = rgb[3 * p], b = rgb[3 * p + 2];
    if (r > b + 16) ++warm;
    else if (b > r + 16) ++blue;
  }
  return { warm, blue };
}

async function setMode(mode) {
  await page.click(`label:has(#mode-${mode})`);
  assert.equal(await page.isChecked(`#mode-${mode}`), true);
}

// ------------------------------------------------------------------ setup

before(async () => {
  server = await startServer();
  browser = await launchChromium();
  context = await browser.newContext({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1, hasTouch: true });
  await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: server.url });
  page = await context.newPage();
  watchErrors(page, pageErrors);
});

after(async () => {
  if (browser) await browser.close();
  await stopServer(server);
});

// ------------------------------------------------------------------ tests

test('examples.json matches shared/bench (scripts/make-web-examples.mjs)', (t) => {
  if (!fs.existsSync(path.join(sharedDir, 'bench', 'surfaces_public.json'))) {
    t.skip(`no ${sharedDir}/bench`);
    return;
  }
  assert.equal(fs.readFileSync(examplesPath, 'utf8'), buildExamples(sharedDir), 'run node scripts/make-web-examples.mjs');
});

test('the page loads with WebGL2, lists every public surface and draws the first example', async () => {
  // One sample per pixel for the comparisons (SwiftShader is a CPU); the screenshot
  // switches to 2×2 below.
  await page.goto(server.url + '/?aa=1');
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.getAttribute('#preview', 'data-webgl2'), 'yes', 'WebGL2 is available to the page');
  assert.equal(await page.inputValue('#aa'), '1');
  const names = await page.$$eval('#examples option', (options) => options.map((o) => o.value).filter(Boolean));
  const expected = JSON.parse(fs.readFileSync(examplesPath, 'utf8')).examples.map((e) => e.name);
  assert.deepEqual(names, expected);
  await page.waitForSelector('#server-status[data-state="ok"]');
  // The initial example (the torus) is implicitized and drawn.
  await page.waitForFunction(() => Number(document.getElementById('preview').dataset.frame || 0) >= 1, null, { timeout: 120000 });
  assert.match(await page.textContent('#implicit'), /^x\^4\+2\*x\^2\*y\^2/);
});

test('the sphere: equation, facts, scripts, the GLSL of /v1/sdf, and the silhouette of the CPU renderer', async (t) => {
  await page.click('#tab-parametric');
  const frame = await currentFrame();
  await page.fill('#x', SPHERE.x);
  await page.fill('#y', SPHERE.y);
  await page.fill('#z', SPHERE.z);
  await page.fill('#box', '-2, -2, -2, 2, 2, 2');
  await setMode('fast'); // already fast: no new request
  await page.press('#z', 'Enter'); // Enter submits
  await page.waitForFunction(() => document.getElementById('implicit').dataset.equation === 'x^2+y^2+z^2-1', null, { timeout: 30000 });
  assert.equal(await page.textContent('#implicit'), 'x^2+y^2+z^2-1 = 0');
  assert.equal(await page.textContent('#degree'), '2');
  assert.equal(await page.textContent('#result-method'), 'interpolation'); // degree ≤ 4: auto's first rule
  assert.match(await page.textContent('#result-time'), /^\d+(\.\d+)? (ms|s)$/);
  assert.equal(await page.textContent('#verified'), '✓ yes');
  assert.match(await page.textContent('#reproduce-singular'), /eliminate/);
  assert.match(await page.textContent('#reproduce-macaulay2'), /eliminate/);
  // The page shows, and the shader contains, exactly what POST /v1/sdf answers.
  // The page posts the parametric surface itself, with the shape it asks for (auto).
  const reference = await postJson('/v1/sdf', { ...SPHERE, shape: 'auto', mode: 'fast', box: [-2, -2, -2, 2, 2, 2], name: 'surface' });
  assert.equal(reference.status, 200);
  await page.waitForFunction((g) => document.getElementById('glsl').textContent === g, reference.json.glsl, { timeout: 30000 });
  await waitForImage('x^2+y^2+z^2-1', 'fast', frame);
  assert.equal(await page.getAttribute('#preview', 'data-function'), 'surface_sdf');
  await compareWithCpuRenderer('x^2+y^2+z^2-1', 'fast', t);
  // Copy GLSL puts that text on the clipboard.
  // (The toast hides itself after 1.8 s: its text, not its visibility, is checked.)
  await page.click('#copy-glsl');
  await page.waitForFunction((g) => navigator.clipboard.readText().then((text) => text === g), reference.json.glsl,
                             { timeout: 30000 });
  assert.equal(await page.textContent('#toast'), 'GLSL copied to the clipboard');
});

test("Steiner's surface from the examples menu, in safe mode: equation and silhouette", async (t) => {
  const steiner = JSON.parse(fs.readFileSync(examplesPath, 'utf8')).examples.find((e) => e.name === 'steiner_roman');
  await setMode('safe'); // redraws the sphere in safe mode
  let frame = await currentFrame();
  await waitForImage('x^2+y^2+z^2-1', 'safe', frame - 1);
  frame = await currentFrame();
  await page.selectOption('#examples', 'steiner_roman');
  assert.equal(await page.inputValue('#x'), steiner.x);
  // The patch's box is fitted by the server (the box input stays empty), its domain the
  // default (the whole plane: the parametrization is bounded on it).
  assert.equal(await page.inputValue('#box'), '');
  assert.equal(await page.inputValue('#domain'), '');
  const equation = 'x^2*y^2+x^2*z^2+y^2*z^2-x*y*z';
  await page.waitForFunction((eq) => document.getElementById('implicit').dataset.equation === eq, equation, { timeout: 30000 });
  assert.equal(await page.textContent('#degree'), '4');
  assert.equal(await page.textContent('#verified'), '✓ yes');
  await waitForImage(equation, 'safe', frame);
  assert.equal(await page.getAttribute('#preview', 'data-function'), 'steiner_roman_sdf');
  assert.match(await page.textContent('#glsl-summary'), /steiner_roman_sdf\(vec3 p\) · safe mode/);
  await compareWithCpuRenderer(equation, 'safe', t);
  // The picture for the README: Steiner's surface at 2×2 samples per pixel, with its
  // equation and scripts. The AA switch redraws without a new request.
  frame = await currentFrame();
  await page.selectOption('#aa', '2');
  await waitForImage(equation, 'safe', frame);
  assert.equal(await page.getAttribute('#preview', 'data-aa'), '2');
  // Closer, with the keyboard (+ on the focused canvas).
  frame = await currentFrame();
  await page.focus('#preview');
  for (let i = 0; i < 4; ++i) await page.keyboard.press('+');
  await waitForImage(equation, 'safe', frame);
  await page.mouse.move(0, 0);
  fs.mkdirSync(path.dirname(screenshotPath), { recursive: true });
  await page.screenshot({ path: screenshotPath });
  t.diagnostic(`screenshot: ${screenshotPath}`);
  // Back to the default view and one sample per pixel for the next tests.
  frame = await currentFrame();
  await page.selectOption('#aa', '1');
  await page.click('#reset-view');
  await waitForImage(equation, 'safe', frame);
});

test('orbit and zoom by mouse and touch change the eye around the target', async () => {
  const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  const view = async () => ({
    eye: JSON.parse(await page.getAttribute('#preview', 'data-eye')),
    target: JSON.parse(await page.getAttribute('#preview', 'data-target')),
  });
  const settled = async (f) =>
    page.waitForFunction((n) => {
      const d = document.getElementById('preview').dataset;
      return d.state === 'done' && Number(d.frame) > n;
    }, f, { timeout: 120000 });
  const start = await view();
  const box = await page.locator('#preview').boundingBox();
  const cx = box.x + box.width / 2, cy = box.y + box.height / 2;

  // Mouse: drag to orbit, wheel down to move away.
  let frame = await currentFrame();
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  await page.mouse.move(cx + 80, cy + 30, { steps: 4 });
  await page.mouse.up();
  await page.mouse.wheel(0, 200);
  await settled(frame);
  const mouse = await view();
  assert.deepEqual(mouse.target, start.target, 'the target stays');
  assert.notDeepEqual(mouse.eye, start.eye, 'the eye moved');
  assert.ok(dist(mouse.eye, mouse.target) > dist(start.eye, start.target) * 1.1, 'the wheel moved the eye away');

  // Touch (real touch events through the DevTools protocol): pinch out 40 -> 120 px
  // brings the eye 3 times closer; one finger orbits at a constant distance.
  const cdp = await context.newCDPSession(page);
  const fingers = (d) => [{ x: cx - d, y: cy, id: 1 }, { x: cx + d, y: cy, id: 2 }];
  frame = await currentFrame();
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: fingers(20) });
  for (let d = 25; d <= 60; d += 5) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: fingers(d) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await settled(frame);
  const pinched = await view();
  const ratio = dist(mouse.eye, mouse.target) / dist(pinched.eye, pinched.target);
  assert.ok(Math.abs(ratio - 3) < 0.05, `pinching 40 -> 120 px zooms 3 times (${ratio})`);
  frame = await currentFrame();
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: cx, y: cy, id: 3 }] });
  for (let d = 10; d <= 60; d += 10) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: cx + d, y: cy, id: 3 }] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await settled(frame);
  const dragged = await view();
  assert.notDeepEqual(dragged.eye, pinched.eye, 'one finger orbits');
  assert.ok(Math.abs(dist(dragged.eye, dragged.target) - dist(pinched.eye, pinched.target)) < 1e-9, 'at the same distance');
  await cdp.detach();

  await page.click('#reset-view');
  await page.waitForFunction((b) => document.getElementById('preview').dataset.eye === JSON.stringify(b), start.eye);
});

test('errors: shown beside the input, with the code and the position marked', async () => {
  await page.click('#tab-parametric');
  const bad = '2*s/(1+s^2+';
  const reference = await postJson('/v1/implicitize', { x: bad, y: SPHERE.y, z: SPHERE.z });
  assert.equal(reference.status, 400);
  const { code, position, field } = reference.json.error;
  assert.equal(field, 'x');
  assert.ok(Number.isInteger(position));
  await page.fill('#x', bad);
  await page.fill('#y', SPHERE.y);
  await page.fill('#z', SPHERE.z);
  await page.click('#implicitize');
  await page.waitForSelector('#x-error:not([hidden])');
  const message = await page.textContent('#x-error');
  assert.ok(message.includes(code), `the code ${code} is shown: ${message}`);
  assert.equal(await page.getAttribute('#x-error', 'data-position'), String(position));
  assert.equal(await page.getAttribute('#x', 'aria-invalid'), 'true');
  assert.equal(await page.isHidden('#y-error'), true);
  const selection = await page.evaluate(() => {
    const x = document.getElementById('x');
    return [document.activeElement === x, x.selectionStart];
  });
  assert.deepEqual(selection, [true, position], 'the position is selected in the input');
  assert.equal(await page.locator('#x-error .caret .pointer').count(), 1, 'a caret marks the position');
  assert.equal(await page.getAttribute('#progress', 'data-state'), 'error');
  // Editing the input clears its error.
  await page.fill('#x', SPHERE.x);
  assert.equal(await page.isHidden('#x-error'), true);

  // An implicit equation with an error, in the implicit mode.
  await page.click('#tab-implicit');
  const badEquation = 'x^2+y^2+z^2-1)';
  const ref2 = await postJson('/v1/sdf', { implicit: badEquation, mode: 'safe', box: [-1, -1, -1, 1, 1, 1], name: 'surface' });
  assert.equal(ref2.status, 400);
  await page.fill('#equation', badEquation);
  await page.press('#equation', 'Enter');
  await page.waitForSelector('#equation-error:not([hidden])');
  assert.ok((await page.textContent('#equation-error')).includes(ref2.json.error.code));
  assert.equal(await page.getAttribute('#equation-error', 'data-position'), String(ref2.json.error.position));

  // A parametrization whose image is a curve: no single equation, generators listed.
  await page.click('#tab-parametric');
  await page.fill('#x', 't');
  await page.fill('#y', 't^2');
  await page.fill('#z', 't^3');
  await page.click('#implicitize');
  await page.waitForSelector('#general-error:not([hidden])');
  const general = await page.textContent('#general-error');
  assert.ok(general.includes('no_single_equation'), general);
  assert.ok(general.includes('generators'), general);
});

test('typing an implicit equation directly draws it', async () => {
  await page.click('#tab-implicit');
  const frame = await currentFrame();
  const torus = '(x^2+y^2+z^2+3)^2-16*(x^2+y^2)';
  await page.fill('#equation', torus);
  await page.fill('#box', '-3, -3, -1, 3, 3, 1');
  await page.click('#draw');
  await waitForImage(torus, 'safe', frame);
  assert.equal(await page.textContent('#implicit'), `${torus} = 0`);
  assert.equal(await page.textContent('#degree'), '4');
  assert.equal(await page.isHidden('#equation-error'), true);
});

// Issue 18: open surfaces and patches are sheets, drawn two-sided (SURFER's colours:
// warm where F > 0 faces the viewer, blue where F < 0 does), not solids cut by their
// box. Each example is picked from the menu (its patch over its domain, shape auto); the
// page's picture must show both side colours, match the CPU renderer's sheet of the
// same view (POST /v1/render, IoU >= 0.9), and not its solid (shape "solid": the
// algebraic surface's solid F <= 0 clipped to the same box, with its caps): IoU with
// that below 0.9, and the sheet has no pixel the box's caps would add.
test('the hyperbolic paraboloid, Enneper\'s surface and a bicubic patch are two-sided sheets', async (t) => {
  await page.click('#tab-parametric');
  await setMode('fast');
  t.after(() => page.selectOption('#resolution', '1'));
  await page.selectOption('#resolution', HEAVY_RESOLUTION);
  // Their exact equations (a tolerance draws an approximation: next test).
  await page.fill('#tolerance', '');
  for (const name of ['hyperbolic_paraboloid', 'enneper', 'bicubic_patch']) {
    const frame = await currentFrame();
    await page.selectOption('#examples', name);
    await waitForFrame(frame, (d, n) => d.function === `${n}_sdf` && d.sides === 'two' && d.mode === 'fast', name);
    assert.equal(await page.getAttribute('#preview', 'data-function'), `${name}_sdf`);
    assert.equal(await page.getAttribute('#preview', 'data-shape'), 'sheet', `${name} is a sheet`);
    assert.match(await page.textContent('#glsl-summary'), new RegExp(`${name}_sdf\\(vec3 p\\) · fast mode · sheet`));
    const canvas = await readCanvas();
    const mask = silhouette(canvas.rgb, canvas.width, canvas.height);
    const surface = mask.reduce((s, v) => s + v, 0);
    const sides = sideCounts(canvas.rgb, mask);
    t.diagnostic(`${name}: ${surface} surface pixels, ${sides.warm} warm (F > 0 side), ${sides.blue} blue (F < 0 side)`);
    assert.ok(surface > 0.02 * canvas.width * canvas.height, `${name}: the canvas shows the surface (${surface} pixels)`);
    // 0.5 %: the default view sees the bicubic patch almost only from its F > 0 side
    // (its F < 0 side shows at a fold, 0.8 % of the surface); a one-sided shader shows none.
    assert.ok(sides.warm > 0.005 * surface, `${name}: the F > 0 side appears (${sides.warm} of ${surface})`);
    assert.ok(sides.blue > 0.005 * surface, `${name}: the F < 0 side appears (${sides.blue} of ${surface})`);

    const sheet = await renderSameView(canvas.view, {}, t);
    const sheetMask = silhouette(sheet.rgb, sheet.width, sheet.height);
    const cpuSides = sideCounts(sheet.rgb, sheetMask);
    const withSheet = iou(mask, sheetMask);
    const implicit = await page.getAttribute('#implicit', 'data-equation');
    const solid = await renderSameView(canvas.view, { x: undefined, y: undefined, z: undefined, domain: undefined, implicit, shape: 'solid' }, t);
    const solidMask = silhouette(solid.rgb, solid.width, solid.height);
    const withSolid = iou(mask, solidMask);
    let capOnly = 0;
    for (let p = 0; p < mask.length; ++p) if (solidMask[p] && !sheetMask[p]) ++capOnly;
    t.diagnostic(`${name}: IoU with the CPU sheet ${withSheet.toFixed(4)} (CPU: ${cpuSides.warm} warm, ${cpuSides.blue} blue), ` +
      `with the CPU solid ${withSolid.toFixed(4)}; ${capOnly} pixels only the solid's caps cover`);
    assert.ok(withSheet >= IOU_MIN, `${name}: the page draws the CPU renderer's sheet (IoU ${withSheet})`);
    assert.ok(Math.abs(cpuSides.blue - sides.blue) <= 0.1 * surface, `${name}: the same share of blue as the CPU renderer`);
    assert.ok(withSolid < IOU_MIN, `${name}: not the solid cut by its box (IoU ${withSolid})`);
    let gpuOnCaps = 0;
    for (let p = 0; p < mask.length; ++p) if (mask[p] && solidMask[p] && !sheetMask[p]) ++gpuOnCaps;
    assert.ok(gpuOnCaps <= 0.02 * capOnly + 20, `${name}: nothing drawn where only the caps would be (${gpuOnCaps} of ${capOnly})`);
  }
});

// Issue 19: a tolerance draws Enneper's surface from its approximation (at 1e-2 one
// low-degree piece is shorter GLSL than the exact equation of degree 9), two-sided from
// the side function its answer carries (issue 39); the bound
// reached is shown beside the preview, and the image is the CPU renderer's of the same
// request, and close to the exact patch's. The bicubic patch keeps its exact equation
// at the page's default 1e-3 (shorter than any approximation) and says so.
test('Enneper\'s surface with a tolerance renders its approximation and shows the bound', async (t) => {
  await page.click('#tab-parametric');
  await setMode('fast');
  t.after(() => page.selectOption('#resolution', '1'));
  await page.selectOption('#resolution', HEAVY_RESOLUTION);
  await page.fill('#tolerance', '1e-2');
  let frame = await currentFrame();
  const started = Date.now();
  await page.selectOption('#examples', 'enneper');
  await waitForFrame(frame, (d) => d.function === 'enneper_sdf' && d.mode === 'fast' && d.sides === 'two');
  t.diagnostic(`enneper at 1e-2: request to finished image ${Date.now() - started} ms`);
  const text = await page.textContent('#approximation');
  t.diagnostic(text);
  assert.match(text, /^Tolerance 0\.01 of the box diagonal: patch → surface ≤ \S+ \((certified|measured)/);
  assert.match(text, /surface → patch ≤ \S+ \((certified|measured)/);
  assert.match(text, /degree \d+ × \d+ pieces? · \d+ GLSL lines$/);
  const bound = Number(await page.getAttribute('#approximation', 'data-bound'));
  assert.ok(bound > 0 && bound <= 1e-2, `the bound reached ${bound} <= 1e-2`);
  const request = JSON.parse(await page.getAttribute('#preview', 'data-request'));
  assert.equal(request.tolerance, 0.01, 'the preview draws the approximation');
  const canvas = await readCanvas();
  const mask = silhouette(canvas.rgb, canvas.width, canvas.height);
  const surface = mask.reduce((s, v) => s + v, 0);
  assert.ok(surface > 0.02 * canvas.width * canvas.height, `the canvas shows the patch (${surface} pixels)`);
  const same = await renderSameView(canvas.view, {}, t);
  const withSame = iou(mask, silhouette(same.rgb, same.width, same.height));
  const exact = await renderSameView(canvas.view, { tolerance: undefined }, t);
  const withExact = iou(mask, silhouette(exact.rgb, exact.width, exact.height));
  t.diagnostic(`IoU with the CPU renderer's approximation ${withSame.toFixed(4)}, with its exact patch ${withExact.toFixed(4)}`);
  assert.ok(withSame >= IOU_MIN, `the CPU renderer's image of the same request (IoU ${withSame})`);
  assert.ok(withExact >= IOU_MIN, `close to the exact patch (IoU ${withExact})`);

  await page.fill('#tolerance', '1e-3');
  frame = await currentFrame();
  await page.selectOption('#examples', 'bicubic_patch');
  await waitForFrame(frame, (d) => d.function === 'bicubic_patch_sdf' && d.mode === 'fast');
  assert.match(await page.textContent('#approximation'),
    /^Tolerance 0\.001: exact, error 0 — the exact equation's GLSL is (shorter|no longer)/);
  assert.equal(await page.getAttribute('#approximation', 'data-bound'), '0', 'the exact equation: bound 0');
});

// A plane curve (no z) is drawn flat: `NAME_sdf(vec2 p)`, a 2-D picture of the box with
// its grid and the curve as a line, the same picture as the CPU renderer's.
test('a plane curve is drawn in 2-D, as the CPU renderer draws it', async (t) => {
  await page.click('#tab-parametric');
  const frame = await currentFrame();
  await page.selectOption('#examples', 'lemniscate');
  assert.equal(await page.inputValue('#z'), '');
  await waitForFrame(frame, (d) => d.function === 'lemniscate_sdf' && d.dimension === '2');
  assert.equal(await page.textContent('#implicit'), 'x^4+2*x^2*y^2+y^4-x^2+y^2 = 0');
  assert.match(await page.textContent('#glsl-summary'), /lemniscate_sdf\(vec2 p\)/);
  assert.match(await page.textContent('#glsl'), /float lemniscate_sdf\(vec2 p\)/);
  const canvas = await readCanvas();
  const v = canvas.view;
  assert.equal(v.eye, undefined, 'no camera: a flat view');
  const box = JSON.parse(v.box);
  assert.equal(box.length, 4, 'a curve\'s box is x0, y0, x1, y1');
  // The line's pixels: dark blue (the curve colour (0.09, 0.20, 0.55) at full cover).
  const line = (rgb, p) => rgb[3 * p + 2] > rgb[3 * p] + 60 && rgb[3 * p] < 150;
  const { width, height } = canvas;
  let gpuLine = 0, light = 0;
  const gpuMask = new Uint8Array(width * height), cpuMask = new Uint8Array(width * height);
  for (let p = 0; p < width * height; ++p) {
    if (line(canvas.rgb, p)) (gpuMask[p] = 1), ++gpuLine;
    // Light: the paper (0.98), the margin (0.90) and a closed curve's tint (0.99, 0.87, 0.72),
    // whose darkest channel is 184 of 255; a shaded 3-D solid is far darker.
    if (Math.min(canvas.rgb[3 * p], canvas.rgb[3 * p + 1], canvas.rgb[3 * p + 2]) > 175) ++light;
  }
  t.diagnostic(`lemniscate: ${gpuLine} line pixels, ${light} light (paper, grid, tint) of ${width * height}`);
  assert.ok(light > 0.8 * width * height, 'a light 2-D picture, not a shaded solid');
  // The figure eight is 5.24 units long (a = 1): at least 3 units of it in line pixels.
  const scale = JSON.parse(v.view).scale;
  assert.ok(gpuLine > 3 * scale, `the curve is drawn (${gpuLine} line pixels, ${scale} px per unit)`);
  // The page frames the box with a margin of m pixels (preview.js defaultPlaneView): its
  // view is the CPU renderer's of a (width − 2m) × (height − 2m) image, centred. m is
  // what the limiting side leaves, (side − scale · box side)/2, the smaller of the two.
  const m = Math.round(Math.min(width - scale * (box[2] - box[0]), height - scale * (box[3] - box[1])) / 2);
  assert.ok(m > 0, `a margin around the box (${m} px)`);
  const png = await renderSameView(v, { width: width - 2 * m, height: height - 2 * m }, t);
  assert.equal(png.width, width - 2 * m);
  let cpuLine = 0, diff = 0;
  for (let y = 0; y < png.height; ++y) {
    for (let x = 0; x < png.width; ++x) {
      const c = y * png.width + x, p = (y + m) * width + x + m;
      if (line(png.rgb, c)) (cpuMask[p] = 1), ++cpuLine;
      for (let k = 0; k < 3; ++k) diff += Math.abs(png.rgb[3 * c + k] - canvas.rgb[3 * p + k]);
    }
  }
  // Only the CPU's picture is compared: the line's antialiased edge spills past the box
  // into the page's margin, where the CPU's image has no pixels.
  for (let p = 0; p < width * height; ++p) {
    const x = p % width, y = Math.floor(p / width);
    if (x < m || x >= width - m || y < m || y >= height - m) gpuMask[p] = 0;
  }
  const score = iou(gpuMask, cpuMask);
  const meanDiff = diff / (3 * png.width * png.height);
  t.diagnostic(`lemniscate: line pixels GPU ${gpuLine} / CPU ${cpuLine}, IoU ${score.toFixed(4)}, mean |GPU - CPU| ${meanDiff.toFixed(3)} of 255`);
  assert.ok(score >= 0.9, `the page's line is the CPU renderer's (IoU ${score})`);
  assert.ok(meanDiff < 2, `the same picture (mean difference ${meanDiff} of 255)`);
  // Dragging pans the view.
  const before = JSON.parse(v.view);
  const f = await currentFrame();
  await dragPreview(page, 40, 0);
  await waitForFrame(f, (d) => d.dimension === '2');
  const after = JSON.parse(await page.getAttribute('#preview', 'data-view'));
  assert.ok(after.centre[0] < before.centre[0], 'dragging right moves the view left');
  assert.equal(after.scale, before.scale);
  await page.click('#reset-view');
});

test('a long request shows its elapsed time and Cancel stops it, here and on the server', async () => {
  const hard = JSON.parse(fs.readFileSync(path.join(sharedDir, 'bench', 'surfaces_hard.json'), 'utf8')).find((s) => s.name === 'tp_33');
  assert.ok(hard, 'tp_33 in surfaces_hard.json');
  const cancelledBefore = await metric('implicitizer_computations_cancelled_total');
  await page.click('#tab-parametric');
  await page.fill('#params', 's, t'); // the last example, a plane curve, named only t
  await page.fill('#x', hard.x);
  await page.fill('#y', hard.y);
  await page.fill('#z', hard.z);
  await page.selectOption('#method', 'groebner');
  await page.selectOption('#timeout', '60000');
  await page.click('#implicitize');
  await page.waitForSelector('#progress[data-state="busy"]');
  assert.equal(await page.isVisible('#cancel'), true);
  assert.equal(await page.isDisabled('#implicitize'), true);
  assert.equal(await page.textContent('#progress-text'), 'Implicitizing…');
  const first = await page.textContent('#progress-time');
  // Wait for the clock to move, however long the page takes to get a turn.
  await page.waitForFunction((before) => document.getElementById('progress-time').textContent !== before, first,
                             { timeout: 30000 });
  const second = await page.textContent('#progress-time');
  assert.match(second, /^\d+\.\d s$/);
  assert.notEqual(first, second, 'the elapsed time ticks');
  await page.click('#cancel');
  await page.waitForSelector('#progress[data-state="idle"]', { timeout: 30000 });
  assert.match(await page.textContent('#progress-text'), /^Cancelled after \d+\.\d s\.$/);
  assert.equal(await page.isHidden('#cancel'), true);
  assert.equal(await page.isEnabled('#implicitize'), true);
  // The page deleted its job (DELETE /v1/jobs/{id}) and the server cancelled the computation.
  const deadline = Date.now() + 15000;
  let cancelled = cancelledBefore;
  while (Date.now() < deadline && cancelled <= cancelledBefore) {
    await new Promise((resolve) => setTimeout(resolve, 250));
    cancelled = await metric('implicitizer_computations_cancelled_total');
  }
  assert.ok(cancelled > cancelledBefore, `implicitizer_computations_cancelled_total went from ${cancelledBefore} to ${cancelled}`);
  await page.selectOption('#method', 'auto');
  await page.selectOption('#timeout', '0'); // back to the page's default
});

test('without WebGL2 the page says so and shows the CPU renderer instead', async () => {
  const plain = await launchChromium(['--disable-webgl', '--disable-3d-apis']);
  try {
    const p = await plain.newPage({ viewport: { width: 1280, height: 800 } });
    // aa=1: the page's default 2x2 antialiasing makes this a CPU render of up to 1.9
    // million rays, which on a loaded 2-core machine can take most of a minute.
    await p.goto(server.url + '/?aa=1');
    await p.waitForSelector('body[data-ready="true"]');
    assert.equal(await p.getAttribute('#preview', 'data-webgl2'), 'no');
    await p.waitForSelector('#webgl-unavailable:not([hidden])');
    assert.match(await p.textContent('#webgl-unavailable'), /WebGL2 is not available/);
    assert.equal(await p.isHidden('#preview'), true);
    // The initial example still gets its equation, and the server's image appears.
    await p.waitForFunction(() => {
      const img = document.getElementById('cpu-fallback');
      return !img.hidden && img.complete && img.naturalWidth > 0;
    }, null, { timeout: 300000 });
    assert.match(await p.textContent('#implicit'), /^x\^4/);
  } finally {
    await plain.close();
  }
});

test('no errors in the page console', () => {
  assert.deepEqual(pageErrors, []);
});
