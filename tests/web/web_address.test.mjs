// Browser tests of the page's address and its Download button (issue 40, "Share and
// keep"), on the real server in Debian's chromium (harness.mjs), nothing mocked:
// - a parametric surface typed with its parameters, domain, tolerance, method, limit,
//   mode, shape and AA: the address the page writes, opened in a fresh page, fills
//   every input and setting alike and draws the same picture (the canvas's function,
//   box, mode, equation, camera and the GLSL);
// - an empty `tolerance=` asks for the exact equation (the sdf request has none);
// - the implicit tab: its equation and box make the same round trip;
// - an example stays `example=NAME` until one of its fields is edited, then the
//   address holds the fields;
// - values the page does not offer (a mode, an AA, a shape...) leave the defaults;
// - Download saves the GLSL shown as NAME_sdf.glsl.
// Every wait is on the page's state attributes, never on a fixed time.
//
//   node --test --test-reporter=spec tests/web/web_address.test.mjs   (from the repository root)
import { after, afterEach, before, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { launchChromium, startServer, stopServer, watchErrors } from './harness.mjs';

let server;
let browser;
let pages = []; // {page, errors, sdfRequests} of every page the running test opened

/// Opens `address` (a path and query on the server, or a whole URL) in a fresh page
/// (its own context: nothing shared with the page the link came from) and waits until
/// the page has read it. `sdfRequests` collects the sdf jobs' requests it posts.
async function openPage(address) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1, acceptDownloads: true });
  const opened = { page, errors: watchErrors(page, []), sdfRequests: [] };
  page.on('request', (r) => {
    if (r.method() !== 'POST' || new URL(r.url()).pathname !== '/v1/jobs') return;
    const body = JSON.parse(r.postData() || 'null');
    if (body?.kind === 'sdf') opened.sdfRequests.push(body.request);
  });
  pages.push(opened);
  await page.goto(address.startsWith('http') ? address : server.url + address);
  await page.waitForSelector('body[data-ready="true"]');
  return opened;
}

/// Waits until the request in flight has ended and the preview shows a finished image
/// of the equation the page shows (a parametric answer) or of `equation`.
async function waitForDrawn(page, equation = null) {
  await page.waitForFunction(
    (eq) => {
      const d = document.getElementById('preview').dataset;
      const shown = eq ?? document.getElementById('implicit').dataset.equation;
      return document.getElementById('progress').dataset.state === 'done' && d.state === 'done' &&
        Number(d.frame || 0) > 0 && d.equation !== undefined && d.equation === shown;
    },
    equation,
    { timeout: 240000, polling: 100 },
  );
}

/// Every input and setting of the page, and the tab shown.
async function inputs(page) {
  return page.evaluate(() => {
    const value = (id) => document.getElementById(id).value;
    const names = ['params', 'x', 'y', 'z', 'domain', 'tolerance', 'equation', 'box', 'method', 'timeout', 'shape', 'aa', 'examples'];
    return {
      ...Object.fromEntries(names.map((id) => [id, value(id)])),
      mode: document.querySelector('input[name="mode"]:checked').value,
      tab: document.body.dataset.mode,
      labels: [...document.querySelectorAll('label.coordinate')].map((l) => l.textContent.replace(/\s+/g, '')),
    };
  });
}

/// What the picture shows: the canvas's description of its image, the equation and
/// the GLSL.
async function picture(page) {
  return page.evaluate(() => {
    const d = document.getElementById('preview').dataset;
    const keys = ['state', 'function', 'box', 'mode', 'shape', 'aa', 'equation', 'dimension', 'sides', 'eye', 'target', 'request'];
    return {
      ...Object.fromEntries(keys.map((k) => [k, d[k]])),
      implicit: document.getElementById('implicit').dataset.equation,
      glsl: document.getElementById('glsl').textContent,
      approximation: document.getElementById('approximation').textContent,
    };
  });
}

function query(page) {
  return new URL(page.url()).searchParams;
}

before(async () => {
  server = await startServer();
  browser = await launchChromium();
});

// Each test's pages logged nothing to the console, and are closed.
afterEach(async () => {
  const opened = pages;
  pages = [];
  const logged = opened.filter((o) => o.errors.length).map((o) => `${o.page.url()}: ${o.errors.join('; ')}`);
  for (const { page } of opened) await page.close();
  assert.deepEqual(logged, []);
});

after(async () => {
  if (browser) await browser.close();
  await stopServer(server);
});

test('a typed parametric surface: the address it writes fills a fresh page alike and draws the same picture', async () => {
  // example=none: no initial example to compute, the page waits for the user.
  const { page } = await openPage('/?example=none');
  await page.fill('#params', 'u, v');
  await page.fill('#x', 'u');
  await page.fill('#y', 'v');
  await page.fill('#z', 'u^2-v^2');
  await page.fill('#domain', '-1, 1, -1/2, 1');
  await page.fill('#tolerance', '5e-3');
  await page.selectOption('#method', 'groebner');
  await page.selectOption('#timeout', '30000');
  await page.selectOption('#shape', 'sheet');
  await page.click('label:has(#mode-safe)');
  await page.selectOption('#aa', '1');
  await page.click('#implicitize');
  await waitForDrawn(page);
  const typed = await inputs(page);
  assert.equal(typed.mode, 'safe');
  const drawn = await picture(page);
  assert.equal(drawn.function, 'surface_sdf');
  assert.equal(drawn.mode, 'safe');
  assert.equal(drawn.shape, 'sheet');
  assert.equal(drawn.aa, '1');

  const link = page.url();
  const q = query(page);
  assert.equal(q.has('example'), false, `the fields, not an example: ${link}`);
  assert.deepEqual(Object.fromEntries(q), {
    params: 'u,v', x: 'u', y: 'v', z: 'u^2-v^2', domain: '-1,1,-1/2,1', tolerance: '5e-3',
    method: 'groebner', timeout: '30000', mode: 'safe', shape: 'sheet', aa: '1',
  });
  assert.match(link, /domain=-1,1,-1\/2,1/, 'commas and slashes stay readable');

  const fresh = await openPage(link);
  await waitForDrawn(fresh.page);
  assert.deepEqual(await inputs(fresh.page), typed);
  assert.deepEqual(await picture(fresh.page), drawn);
  assert.equal(fresh.page.url(), link, 'opening the link leaves it as it is');
});

test('an empty tolerance= in the address asks for the exact equation', async () => {
  const saddle = '/?params=u,v&x=u&y=v&z=u^3-3*u*v^2&domain=-1,1,-1,1&aa=1';
  const exact = await openPage(`${saddle}&tolerance=`);
  await waitForDrawn(exact.page);
  assert.equal(await exact.page.inputValue('#tolerance'), '');
  assert.equal(exact.sdfRequests.length, 1);
  assert.equal('tolerance' in exact.sdfRequests[0], false, 'no tolerance: the exact equation');
  assert.deepEqual(exact.sdfRequests[0].domain, ['-1', '1', '-1', '1']);
  assert.equal(await exact.page.textContent('#approximation'), '', 'no approximation line');
  // Without the parameter the page's default stands.
  const absent = await openPage(saddle);
  await waitForDrawn(absent.page);
  assert.equal(await absent.page.inputValue('#tolerance'), '1e-3');
  assert.equal(absent.sdfRequests[0].tolerance, 0.001);
});

test('the implicit tab: equation and box make the same round trip', async () => {
  const { page } = await openPage('/?example=none&aa=1');
  await page.click('#tab-implicit');
  assert.equal(query(page).get('input'), 'implicit', 'the tab is in the address at once');
  await page.fill('#equation', 'x^2+y^2/4+z^2-1');
  await page.fill('#box', '-1.5, -2.5, -1.5, 1.5, 2.5, 1.5');
  await page.click('#draw');
  await waitForDrawn(page, 'x^2+y^2/4+z^2-1');
  const link = page.url();
  assert.deepEqual(Object.fromEntries(query(page)), {
    input: 'implicit', equation: 'x^2+y^2/4+z^2-1', box: '-1.5,-2.5,-1.5,1.5,2.5,1.5', mode: 'fast', shape: 'auto', aa: '1',
  });
  const typed = await inputs(page);
  const drawn = await picture(page);
  assert.equal(drawn.box, '[-1.5,-2.5,-1.5,1.5,2.5,1.5]');

  const fresh = await openPage(link);
  await waitForDrawn(fresh.page, 'x^2+y^2/4+z^2-1');
  assert.equal(await fresh.page.getAttribute('#tab-implicit', 'aria-selected'), 'true');
  const reopened = await inputs(fresh.page);
  for (const key of ['equation', 'box', 'tab', 'mode', 'shape', 'aa', 'examples']) assert.equal(reopened[key], typed[key], key);
  assert.deepEqual(await picture(fresh.page), drawn);
});

test('an example stays example=NAME until one of its fields is edited', async () => {
  const { page } = await openPage('/?example=none&aa=1&tolerance=');
  await page.selectOption('#examples', 'elliptic_paraboloid');
  assert.deepEqual(Object.fromEntries(query(page)), { example: 'elliptic_paraboloid', tolerance: '', mode: 'fast', shape: 'auto', aa: '1' });
  await waitForDrawn(page);
  // The example's link draws it again.
  const example = await openPage(page.url());
  await waitForDrawn(example.page);
  assert.equal(await example.page.inputValue('#examples'), 'elliptic_paraboloid');
  assert.deepEqual(await picture(example.page), await picture(page));

  // An edited field makes it a surface of one's own: the address holds the fields.
  await page.fill('#z', 's^2+2*t^2');
  await page.press('#z', 'Tab'); // the edit is done (change)
  const q = query(page);
  assert.equal(q.has('example'), false);
  assert.equal(q.get('z'), 's^2+2*t^2');
  assert.equal(q.get('params'), 's,t');
  assert.equal(q.get('domain'), '-1,1,-1,1');
});

test('values the page does not offer are ignored: the defaults stand', async () => {
  const { page, errors } = await openPage('/?example=unit_sphere&mode=bogus&aa=7&shape=cube&method=magic&timeout=5&input=sideways&tolerance=');
  await waitForDrawn(page);
  const shown = await inputs(page);
  assert.equal(shown.mode, 'fast');
  assert.equal(shown.aa, '2');
  assert.equal(shown.shape, 'auto');
  assert.equal(shown.method, 'auto');
  assert.equal(shown.timeout, '0', 'the Limit stays none');
  assert.equal(shown.tab, 'parametric');
  assert.equal(shown.examples, 'unit_sphere');
  assert.equal(await page.getAttribute('#preview', 'data-function'), 'unit_sphere_sdf');
  assert.deepEqual(errors, []);
});

test('Download saves the GLSL shown as NAME_sdf.glsl', async () => {
  const { page } = await openPage('/?example=none&aa=1&tolerance=');
  assert.equal(await page.isDisabled('#download-glsl'), true, 'nothing to save before a surface is drawn');
  await page.selectOption('#examples', 'hyperbolic_paraboloid');
  await waitForDrawn(page);
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 60000 }), page.click('#download-glsl')]);
  const name = await page.getAttribute('#preview', 'data-function');
  assert.equal(name, 'hyperbolic_paraboloid_sdf');
  assert.equal(download.suggestedFilename(), `${name}.glsl`);
  const saved = fs.readFileSync(await download.path(), 'utf8');
  const shown = await page.textContent('#glsl');
  assert.ok(shown.includes(`float ${name}(`), 'the GLSL shown defines the function');
  assert.equal(saved, shown);
});
