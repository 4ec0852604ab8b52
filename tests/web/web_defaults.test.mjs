// The page at its defaults (issue 40): what a user gets who only picks examples.
// The real implicitizer-server and Debian's chromium, headless, WebGL2 on SwiftShader
// (harness.mjs); nothing is mocked.
//
// - Every example of the menu, at the page's default tolerance, shows the object its
//   exact equation shows (the tolerance emptied): hit masks with IoU >= 0.97, and no
//   see-through hole in a patch (a disc: its domain is a rectangle).
// - A picture comes as a ladder: whole pictures at coarse resolution first, then the
//   full resolution, then the anti-aliasing the page is set to.
// - A lost GPU context is said in red with what to do; the status never says done
//   over the lost picture; once the context is back the page draws again.
// - The Limit is "none" by default (the job runs until it is done, with Cancel), and a
//   time-limit error says what to change.
//
// One sample per pixel (?aa=1) where pictures are compared: AA smooths the edges of
// the same object and costs four times the time on a CPU rasterizer.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { examplesPath } from '../../scripts/make-web-examples.mjs';
import { BACKGROUND, iou, launchChromium, readPreviewCanvas, sharedDir, startServer, stopServer, watchErrors } from './harness.mjs';

const IOU_MIN = 0.97;
const HOLE_FRACTION_MAX = 1e-3; // of the patch's pixels: stray pixels, not a hole

let server;
let browser;
let page;
const pageErrors = [];
const jobBodies = []; // the bodies of the page's POST /v1/jobs, in order

async function frame() {
  return page.evaluate(() => Number(document.getElementById('preview').dataset.frame || 0));
}

/// Waits for a finished picture newer than frame `after`.
async function waitForDone(after) {
  await page.waitForFunction(
    (f) => {
      const d = document.getElementById('preview').dataset;
      return d.state === 'done' && Number(d.frame || 0) > f;
    },
    after,
    { timeout: 240000, polling: 100 },
  );
}

/// The finished picture as a hit mask: 1 where a pixel differs from the background grey.
async function hitMask() {
  const { width, height, rgb } = await readPreviewCanvas(page);
  const mask = new Uint8Array(width * height);
  for (let i = 0; i < mask.length; ++i) {
    mask[i] = Math.abs(rgb[3 * i] - BACKGROUND) + Math.abs(rgb[3 * i + 1] - BACKGROUND) + Math.abs(rgb[3 * i + 2] - BACKGROUND) > 6 ? 1 : 0;
  }
  return { width, height, mask };
}

/// Background pixels of `mask` that the background outside cannot reach (4-connected):
/// what a surface encloses in the picture.
function enclosed({ width, height, mask }) {
  const outside = new Uint8Array(mask.length);
  const stack = [];
  const push = (x, y) => {
    const i = y * width + x;
    if (!mask[i] && !outside[i]) {
      outside[i] = 1;
      stack.push(i);
    }
  };
  for (let x = 0; x < width; ++x) push(x, 0), push(x, height - 1);
  for (let y = 0; y < height; ++y) push(0, y), push(width - 1, y);
  while (stack.length) {
    const i = stack.pop();
    const x = i % width, y = (i - x) / width;
    if (x > 0) push(x - 1, y);
    if (x + 1 < width) push(x + 1, y);
    if (y > 0) push(x, y - 1);
    if (y + 1 < height) push(x, y + 1);
  }
  return mask.map((hit, i) => (!hit && !outside[i] ? 1 : 0));
}

before(async () => {
  server = await startServer();
  browser = await launchChromium();
  // A small page: the pictures compared are what costs (SwiftShader runs on the CPU).
  page = await browser.newPage({ viewport: { width: 760, height: 560 } });
  watchErrors(page, pageErrors);
  page.on('request', (r) => {
    if (r.method() === 'POST' && new URL(r.url()).pathname === '/v1/jobs') jobBodies.push(JSON.parse(r.postData() || '{}'));
  });
});

after(async () => {
  if (browser) await browser.close();
  await stopServer(server);
});

test("every example at the page's default tolerance shows the object of its exact equation", async (t) => {
  await page.goto(server.url + '/?aa=1');
  await page.waitForSelector('body[data-ready="true"]');
  await waitForDone(0);
  const defaultTolerance = await page.inputValue('#tolerance');
  assert.equal(defaultTolerance, '1e-3', "the page's default tolerance");
  // EXAMPLES=a,b narrows the run to those, to look at one.
  const only = process.env.EXAMPLES ? process.env.EXAMPLES.split(',') : null;
  const examples = JSON.parse(fs.readFileSync(examplesPath, 'utf8')).examples.filter((e) => !only || only.includes(e.name));
  for (const example of examples) {
    const started = Date.now();
    // As a user picks it: the menu, with whatever the tolerance field holds (the default).
    let before = await frame();
    await page.selectOption('#examples', example.name);
    await waitForDone(before);
    const withDefaults = await hitMask();
    const shotDefaults = await page.locator('#preview').screenshot();
    // Where the answer is the exact equation (the server kept it: bound 0, or no
    // tolerance applies, as for a plane curve), the picture is the exact one already.
    const bound = await page.getAttribute('#approximation', 'data-bound');
    if (bound === null || bound === '0') {
      t.diagnostic(`${example.name}: the exact equation at the default tolerance (${bound === null ? 'no tolerance applies' : 'kept by the server'}), ${Date.now() - started} ms`);
      assert.ok(withDefaults.mask.reduce((a, b) => a + b, 0) > 500, `${example.name}: the picture shows the object`);
      continue;
    }
    // The same example with the tolerance emptied: its exact equation.
    await page.fill('#tolerance', '');
    before = await frame();
    await page.click('#implicitize');
    await waitForDone(before);
    const exact = await hitMask();
    const shotExact = await page.locator('#preview').screenshot();
    await page.fill('#tolerance', defaultTolerance);
    const score = iou(withDefaults.mask, exact.mask);
    const hits = exact.mask.reduce((a, b) => a + b, 0);
    // A see-through hole: enclosed background at the defaults where the exact picture
    // has the surface.
    const holes = enclosed(withDefaults).reduce((n, e, i) => n + (e & exact.mask[i]), 0);
    t.diagnostic(`${example.name}: approximated within ${bound}; IoU ${score.toFixed(4)} with the exact picture, ${holes} hole pixels of ${hits}, ${Date.now() - started} ms`);
    if (score < IOU_MIN || (example.domain && holes > HOLE_FRACTION_MAX * hits)) {
      // The two pictures, to look at.
      for (const [which, shot] of [['defaults', shotDefaults], ['exact', shotExact]]) {
        const file = path.join(os.tmpdir(), `implicitizer-defaults-${example.name}-${which}.png`);
        fs.writeFileSync(file, shot);
        t.diagnostic(`written ${file}`);
      }
    }
    assert.ok(hits > 500, `${example.name}: the exact picture shows the object (${hits} pixels)`);
    assert.ok(score >= IOU_MIN, `${example.name}: IoU ${score.toFixed(4)} of the default picture against the exact one`);
    if (example.domain) assert.ok(holes <= HOLE_FRACTION_MAX * hits, `${example.name}: ${holes} see-through pixels in a patch`);
  }
});

test('a picture comes as whole coarse pictures, then the full resolution, then the AA', async () => {
  await page.goto(server.url + '/?example=elliptic_paraboloid'); // the page's default AA, 2×2
  await page.waitForSelector('body[data-ready="true"]');
  // Every change of the canvas's state, from the start of this surface's pictures.
  await page.evaluate(() => {
    const canvas = document.getElementById('preview');
    window.ladder = [];
    new MutationObserver(() => {
      const d = canvas.dataset;
      const last = window.ladder[window.ladder.length - 1];
      const entry = { state: d.state, pictures: Number(d.pictures || 0), factor: Number(d.pictureFactor || 0), aa: d.aa };
      if (!last || JSON.stringify(last) !== JSON.stringify(entry)) window.ladder.push(entry);
    }).observe(canvas, { attributes: true });
  });
  await waitForDone(0);
  const ladder = await page.evaluate(() => window.ladder);
  const pictures = ladder.filter((e, i) => e.pictures > 0 && (i === 0 || e.pictures !== ladder[i - 1].pictures));
  const factors = pictures.map((e) => e.factor);
  assert.ok(factors.length >= 3, `a ladder of pictures: ${JSON.stringify(factors)}`);
  assert.ok(factors[0] > 1, `the first picture is a coarse one: ${JSON.stringify(factors)}`);
  for (let i = 1; i < factors.length; ++i) assert.ok(factors[i] <= factors[i - 1], `each picture at least as fine: ${JSON.stringify(factors)}`);
  assert.deepEqual(factors.slice(-2), [1, 1], 'the full resolution, then its anti-aliasing');
  assert.ok(ladder.some((e) => e.state === 'refining'), 'the AA pass refines a complete picture');
  assert.equal(await page.getAttribute('#preview', 'data-aa'), '2');
  assert.match(await page.textContent('#preview-stats'), /AA 2×2/);
});

test('a lost GPU context is said with what to do, and the page draws again when it is back', async () => {
  const lose = (what) =>
    page.evaluate((w) => {
      // Taken while the context lives: a lost context gives no extensions.
      window.loseContext ??= document.getElementById('preview').getContext('webgl2').getExtension('WEBGL_lose_context');
      if (w === 'lose') window.loseContext.loseContext();
      else window.loseContext.restoreContext();
    }, what);
  await page.goto(server.url + '/?example=plane&aa=1');
  await page.waitForSelector('body[data-ready="true"]');
  await waitForDone(0);
  await lose('lose');
  await page.waitForSelector('#preview-overlay.error:not([hidden])');
  assert.match(await page.textContent('#preview-overlay'), /context was lost[\s\S]*tolerance[\s\S]*Resolution/);
  assert.equal(await page.getAttribute('#progress', 'data-state'), 'error', 'the status does not stay done over a lost picture');
  assert.equal(await page.getAttribute('#preview', 'data-state'), 'lost');
  await lose('restore');
  await page.waitForFunction(() => /GPU is back/.test(document.getElementById('preview-overlay').textContent));
  // The tab is usable: a lighter setting and another surface draw.
  await page.selectOption('#resolution', '0.5');
  const before = await frame();
  await page.selectOption('#examples', 'elliptic_paraboloid');
  await waitForDone(before);
  assert.equal(await page.isHidden('#preview-overlay'), true, 'the message goes with a new picture');
  const width = Number(await page.getAttribute('#preview', 'width'));
  const shown = await page.evaluate(() => document.getElementById('preview').getBoundingClientRect().width);
  assert.ok(Math.abs(width - shown / 2) <= 1, `half the resolution: ${width} px drawn for ${shown} shown`);
  await page.selectOption('#resolution', '1');
});

test('the Limit is none by default and a time-limit error says what to change', async () => {
  await page.goto(server.url + '/?example=plane&aa=1');
  await page.waitForSelector('body[data-ready="true"]');
  await waitForDone(0);
  assert.equal(await page.inputValue('#timeout'), '0');
  const hard = JSON.parse(fs.readFileSync(path.join(sharedDir, 'bench', 'surfaces_beyond.json'), 'utf8')).find((s) => s.name === 'tp_55');
  const typeHard = async () => {
    await page.fill('#x', hard.x);
    await page.fill('#y', hard.y);
    await page.fill('#z', hard.z);
    await page.fill('#domain', '');
    await page.click('#implicitize');
  };
  // At the default the job asks for no limit of its own (the server's job limit holds).
  const from = jobBodies.length;
  await typeHard();
  await page.waitForFunction(() => document.getElementById('progress').dataset.jobStatus === 'running', null, { timeout: 60000 });
  const submitted = jobBodies.slice(from).find((b) => b.kind === 'implicitize');
  assert.ok(submitted, 'the implicitization ran as a job');
  assert.equal(submitted.request.timeout_ms, undefined, 'no timeout_ms at the default Limit');
  await page.click('#cancel');
  await page.waitForSelector('#progress[data-state="idle"]', { timeout: 60000 });
  // tp_55 (degree 50) takes minutes: 2 s stops it anywhere.
  await page.selectOption('#timeout', '2000');
  await typeHard();
  await page.waitForSelector('#progress[data-state="error"]', { timeout: 120000 });
  const message = await page.textContent('#general-error');
  assert.match(message, /time_limit_exceeded/);
  assert.match(message, /choose a larger Limit, or none/);
  await page.selectOption('#timeout', '0');
});

test('no errors in the page console', () => {
  assert.deepEqual(pageErrors, []);
});
