// Browser tests of the web client's parametric inputs (issue 20), on the real server in
// Debian's chromium (harness.mjs), nothing mocked:
// - the parameters field: it labels the inputs x(u,v) and the domain's numbers, every
//   request (implicitize and sdf, as jobs) carries its names in order, the domain
//   follows that order, and bad names are shown beside the field;
// - nothing on screen answers another input: a new request clears the previous
//   equation, facts, scripts, GLSL and preview (the canvas is blank), and a request that
//   fails or is cancelled leaves them empty with the reason said (data-reason);
// - the trigonometric sphere and torus and the cosh/sinh hyperboloid from the menu are
//   implicitized and drawn, with the substitution shown; a refusal (u*cos(u), cos(s*t),
//   sqrt(u), an unknown function) is shown beside its input with its code and position.
//
//   node --test --test-reporter=spec tests/web/parametric_inputs.test.mjs   (from the repository root)
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { BACKGROUND, launchChromium, root, sharedDir, startServer, stopServer, watchErrors } from './harness.mjs';

let server;
let browser;
let page;
const pageErrors = [];
const posted = []; // {path, body} of every POST the page made, in order

async function postJson(pathname, body) {
  const response = await fetch(server.url + pathname, { method: 'POST', body: JSON.stringify(body) });
  return { status: response.status, json: await response.json() };
}

/// The POSTs to `pathname` the page made after the first `from` of all.
function postsTo(pathname, from) {
  return posted.slice(from).filter((p) => p.path === pathname);
}

async function frame() {
  return page.evaluate(() => Number(document.getElementById('preview').dataset.frame || 0));
}

/// Waits for a finished image newer than frame `after` of the preview's function `fn`.
async function waitForDrawn(after, fn) {
  await page.waitForFunction(
    ([f, name]) => {
      const d = document.getElementById('preview').dataset;
      return d.state === 'done' && Number(d.frame || 0) > f && d.function === name;
    },
    [after, fn],
    { timeout: 180000, polling: 100 },
  );
}

/// How many pixels of the preview canvas differ from the background grey.
async function drawnPixels() {
  return page.evaluate((background) => {
    const canvas = document.getElementById('preview');
    const gl = canvas.getContext('webgl2');
    const rgba = new Uint8Array(canvas.width * canvas.height * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, canvas.width, canvas.height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    let count = 0;
    for (let i = 0; i < rgba.length; i += 4) {
      if (rgba[i] !== background || rgba[i + 1] !== background || rgba[i + 2] !== background) ++count;
    }
    return count;
  }, BACKGROUND);
}

/// Asserts that no answer and no picture is on the page, and that both places say why
/// (`reason`: running, failed, cancelled; `pattern` matches the sentence shown).
async function assertEmpty(reason, pattern) {
  assert.equal(await page.isHidden('#result'), true, 'the answer is hidden');
  assert.equal(await page.textContent('#implicit'), '', 'no equation');
  assert.equal(await page.textContent('#degree'), '', 'no degree');
  assert.equal(await page.textContent('#verified'), '', 'no verified flag');
  assert.equal(await page.textContent('#reproduce-singular'), '', 'no script');
  assert.equal(await page.getAttribute('#result-empty', 'data-reason'), reason);
  assert.equal(await page.isVisible('#result-empty'), true, 'the answer\'s place says why it is empty');
  assert.match(await page.textContent('#result-empty'), pattern);
  await assertPreviewEmpty(reason, pattern);
}

async function assertPreviewEmpty(reason, pattern) {
  assert.equal(await page.getAttribute('#preview', 'data-state'), 'empty');
  assert.equal(await page.getAttribute('#preview', 'data-function'), null, 'no function described');
  assert.equal(await page.getAttribute('#preview', 'data-equation'), null);
  assert.equal(await drawnPixels(), 0, 'the canvas is blank');
  assert.equal(await page.textContent('#glsl'), '', 'no GLSL');
  assert.equal(await page.isDisabled('#copy-glsl'), true);
  assert.equal(await page.getAttribute('#preview-empty', 'data-reason'), reason);
  assert.equal(await page.isVisible('#preview-empty'), true, 'the stage says why it is empty');
  assert.match(await page.textContent('#preview-empty'), pattern);
}

async function labels() {
  return page.$$eval('label.coordinate', (all) => all.map((l) => l.textContent.replace(/\s+/g, '')));
}

async function implicitizeTyped({ params, x, y, z = '', domain = '' }) {
  await page.click('#tab-parametric');
  await page.fill('#params', params);
  await page.fill('#x', x);
  await page.fill('#y', y);
  await page.fill('#z', z);
  await page.fill('#domain', domain);
  await page.click('#implicitize');
}

before(async () => {
  server = await startServer();
  browser = await launchChromium();
  page = await browser.newPage({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
  watchErrors(page, pageErrors);
  // The page runs its computations as jobs: POST /v1/jobs {kind, request} is recorded
  // as the endpoint's own POST with its body, which is what these tests look at.
  page.on('request', (r) => {
    if (r.method() !== 'POST') return;
    const pathname = new URL(r.url()).pathname;
    const body = JSON.parse(r.postData() || 'null');
    posted.push(pathname === '/v1/jobs' ? { path: `/v1/${body.kind}`, body: body.request } : { path: pathname, body });
  });
  await page.goto(server.url + '/?aa=1');
  await page.waitForSelector('body[data-ready="true"]');
  // The initial example (the torus in s, t) is drawn first.
  await waitForDrawn(0, 'torus_R2_r1_sdf');
  // The exact equation (the approximation's search would only slow these tests down).
  await page.fill('#tolerance', '');
});

after(async () => {
  if (browser) await browser.close();
  await stopServer(server);
});

test('the parameters field labels the inputs and every request carries its names, in order', async () => {
  assert.equal(await page.inputValue('#params'), 's, t', 'the default');
  assert.deepEqual(await labels(), ['x(s,t)=', 'y(s,t)=', 'z(s,t)=']);
  for (const p of postsTo('/v1/implicitize', 0).concat(postsTo('/v1/sdf', 0))) {
    assert.deepEqual(p.body.parameters, ['s', 't'], `${p.path} of the initial example names s, t`);
  }
  await page.fill('#params', 'b a');
  assert.deepEqual(await labels(), ['x(b,a)=', 'y(b,a)=', 'z(b,a)=']);
  assert.equal(await page.textContent('#domain-names'), 'b₀, b₁, a₀, a₁');
  assert.equal(await page.inputValue('#examples'), '', 'an edited parametrization is no longer the example');

  // b in [0, 1/2], a in [-1, 1]: the domain's intervals follow the field's order.
  const from = posted.length;
  const before = await frame();
  await implicitizeTyped({ params: 'b, a', x: 'a', y: 'b', z: 'a^2-b^2', domain: '0, 1/2, -1, 1' });
  await waitForDrawn(before, 'surface_sdf');
  const reference = await postJson('/v1/implicitize', { x: 'a', y: 'b', z: 'a^2-b^2', parameters: ['b', 'a'] });
  assert.equal(reference.status, 200);
  assert.equal(await page.getAttribute('#implicit', 'data-equation'), reference.json.implicit);
  const [implicitize] = postsTo('/v1/implicitize', from);
  const [sdf] = postsTo('/v1/sdf', from);
  assert.deepEqual(implicitize.body.parameters, ['b', 'a']);
  assert.deepEqual(sdf.body.parameters, ['b', 'a']);
  assert.deepEqual(sdf.body.domain, ['0', '1/2', '-1', '1']);
  // The patch's box: x = a over [-1, 1], y = b over [0, 1/2] (the other order would
  // give x over [0, 1/2]).
  const box = JSON.parse(await page.getAttribute('#preview', 'data-box'));
  assert.ok(box[0] < -0.9 && box[3] > 0.9, `x spans [-1, 1]: ${box}`);
  assert.ok(box[1] > -0.2 && box[4] < 0.7, `y spans [0, 1/2]: ${box}`);
  assert.deepEqual(JSON.parse(await page.getAttribute('#preview', 'data-request')).parameters, ['b', 'a']);
});

test('bad parameters are shown beside the field, with the code', async () => {
  // A name the field does not list: the server's unknown_variable, beside x, at its position.
  await implicitizeTyped({ params: 's', x: 's', y: 't', z: 's*t' });
  await page.waitForSelector('#y-error:not([hidden])');
  const unknown = await postJson('/v1/implicitize', { x: 's', y: 't', z: 's*t', parameters: ['s'] });
  assert.equal(unknown.json.error.code, 'unknown_variable');
  assert.match(await page.textContent('#y-error'), /unknown_variable: .* — the parameters field lists the names/);
  assert.equal(await page.getAttribute('#y-error', 'data-position'), String(unknown.json.error.position));
  // A space variable as a parameter: the server's error names the field "parameters".
  await implicitizeTyped({ params: 's, x', x: 's', y: 's^2', z: 's^3' });
  await page.waitForSelector('#params-error:not([hidden])');
  assert.match(await page.textContent('#params-error'), /parameter_is_space_variable/);
  assert.equal(await page.getAttribute('#params', 'aria-invalid'), 'true');
  // No name at all: said by the page, before any request.
  const from = posted.length;
  await implicitizeTyped({ params: ' ', x: 's', y: 't', z: 's*t' });
  await page.waitForSelector('#params-error:not([hidden])');
  assert.match(await page.textContent('#params-error'), /invalid_parameter: name the parameters/);
  assert.equal(postsTo('/v1/implicitize', from).length, 0);
  // Typing in the field clears its error.
  await page.fill('#params', 's, t');
  assert.equal(await page.isHidden('#params-error'), true);
});

test('a new request clears the answer and the preview; cancelled, they stay empty and say so', async () => {
  let before = await frame();
  await implicitizeTyped({ params: 's, t', x: '2*s/(1+s^2+t^2)', y: '2*t/(1+s^2+t^2)', z: '(1-s^2-t^2)/(1+s^2+t^2)' });
  await waitForDrawn(before, 'surface_sdf');
  assert.equal(await page.textContent('#implicit'), 'x^2+y^2+z^2-1 = 0');
  assert.ok((await drawnPixels()) > 1000, 'the sphere is on the canvas');
  assert.equal(await page.isHidden('#result-empty'), true);
  assert.equal(await page.isHidden('#preview-empty'), true);

  // A long computation: while it runs nothing of the sphere is shown.
  const hard = JSON.parse(fs.readFileSync(path.join(sharedDir, 'bench', 'surfaces_hard.json'), 'utf8')).find((s) => s.name === 'tp_33');
  await page.selectOption('#method', 'groebner');
  await page.selectOption('#timeout', '60000');
  await implicitizeTyped({ params: 's, t', x: hard.x, y: hard.y, z: hard.z });
  await page.waitForSelector('#progress[data-state="busy"]');
  await assertEmpty('running', /request is running/);
  await page.click('#cancel');
  await page.waitForSelector('#progress[data-state="idle"]', { timeout: 30000 });
  await assertEmpty('cancelled', /cancelled after \d+\.\d s/);
  await page.selectOption('#method', 'auto');
  await page.selectOption('#timeout', '0'); // back to the page's default
});

test('a failed request leaves the answer and the preview empty, with the reason', async () => {
  let before = await frame();
  await page.selectOption('#examples', 'elliptic_paraboloid');
  await waitForDrawn(before, 'elliptic_paraboloid_sdf');
  const bad = '2*t*(1-s^2-t^2)/(1+s^2+t^2';
  const reference = await postJson('/v1/implicitize', { x: bad, y: 's', z: 't', parameters: ['s', 't'] });
  assert.equal(reference.status, 400);
  await implicitizeTyped({ params: 's, t', x: bad, y: 's', z: 't' });
  await page.waitForSelector('#x-error:not([hidden])');
  await assertEmpty('failed', new RegExp(reference.json.error.code));

  // The equation answers, the distance function does not (a tolerance above 0.5): the
  // equation stays, it answers this input; the preview is empty and says why.
  before = await frame();
  await page.selectOption('#examples', 'elliptic_paraboloid');
  await waitForDrawn(before, 'elliptic_paraboloid_sdf');
  await page.fill('#tolerance', '0.75');
  await page.click('#implicitize');
  await page.waitForSelector('#tolerance-error:not([hidden])');
  assert.match(await page.textContent('#tolerance-error'), /invalid_tolerance/);
  assert.equal(await page.isVisible('#result'), true, 'the equation of this input stays');
  assert.equal(await page.isHidden('#result-empty'), true);
  await assertPreviewEmpty('failed', /invalid_tolerance/);
  await page.fill('#tolerance', '');
});

// The page sends the trigonometric text as typed, with its parameters; the server
// (helper T's part of issue 20, branch i20-trig) makes it rational. The equation is the
// server's, which the expected answers (and lib's and the CLI's tests, with
// Singular on the rational forms) pin down; here the page must show it, with the
// substitution and the rational parametrization, and draw the surface.
const examples = JSON.parse(fs.readFileSync(path.join(root, 'clients', 'web', 'examples.json'), 'utf8')).examples;

/// Asserts that the page shows `reference` (the server's answer to the same request):
/// the equation, verified, and its substitution with the rational parametrization.
async function assertRationalized(reference, t, label) {
  assert.equal(await page.getAttribute('#implicit', 'data-equation'), reference.implicit, label);
  assert.equal(await page.textContent('#verified'), '✓ yes');
  assert.equal(await page.isVisible('#substitution'), true, `${label}: the substitution is shown`);
  const shown = await page.textContent('#substitution');
  t.diagnostic(`${label}: ${reference.implicit}; ${shown.replace(/\s+/g, ' ')}`);
  assert.ok(reference.substitution.length > 0, 'the server made a substitution');
  for (const s of reference.substitution) assert.ok(shown.includes(s.formula), `${s.formula} is shown`);
  for (const c of reference.variables) {
    assert.ok(shown.includes(`${c} = ${reference.rational_parametrization[c]}`), `the rational ${c} is shown`);
  }
}

test('the trigonometric sphere and torus and the cosh/sinh hyperboloid from the menu', async (t) => {
  // The substitution of each parameter: tan(θ/2) for an angle, exp for cosh/sinh.
  const kinds = {
    sphere_trig: ['half_angle', 'half_angle'],
    torus_trig: ['half_angle', 'half_angle'],
    hyperboloid_cosh: ['exponential', 'half_angle'],
  };
  // As a user gets them: at the default tolerance (each keeps its exact equation: the
  // closed ones over the whole plane, the hyperboloid's patch because its degree-2
  // equation is shorter GLSL than any approximation).
  await page.fill('#tolerance', '1e-3');
  for (const name of ['sphere_trig', 'torus_trig', 'hyperboloid_cosh']) {
    const example = examples.find((e) => e.name === name);
    const before = await frame();
    await page.selectOption('#examples', name);
    assert.equal(await page.inputValue('#params'), 'u, v');
    assert.deepEqual(await labels(), ['x(u,v)=', 'y(u,v)=', 'z(u,v)=']);
    await waitForDrawn(before, `${name}_sdf`);
    const reference = await postJson('/v1/implicitize', { x: example.x, y: example.y, z: example.z, parameters: ['u', 'v'] });
    assert.equal(reference.status, 200, JSON.stringify(reference.json));
    assert.equal(reference.json.implicit, example.implicit, `examples.json holds ${name}'s equation`);
    await assertRationalized(reference.json, t, name);
    assert.deepEqual(reference.json.substitution.map((x) => [x.parameter, x.kind]), [['u', kinds[name][0]], ['v', kinds[name][1]]]);
    assert.equal(await page.textContent('#substitution-formulas'), reference.json.substitution.map((x) => x.formula).join(', '));
    assert.ok((await drawnPixels()) > 1000, `${name} is drawn`);
  }
  await page.fill('#tolerance', '');
});

test('the issue\'s trigonometric curves typed in: cos(2t), sin(t) and the astroid', async (t) => {
  const curves = [
    { x: 'cos(2*t)', y: 'sin(t)', expected: '2*y^2+x-1' },
    { x: 'cos(t)^3', y: 'sin(t)^3', expected: 'x^6+3*x^4*y^2+3*x^2*y^4+y^6-3*x^4+21*x^2*y^2-3*y^4+3*x^2+3*y^2-1' },
  ];
  for (const c of curves) {
    const before = await frame();
    await implicitizeTyped({ params: 't', x: c.x, y: c.y });
    assert.deepEqual(await labels(), ['x(t)=', 'y(t)=', 'z(t)=']);
    await waitForDrawn(before, 'surface_sdf');
    const reference = await postJson('/v1/implicitize', { x: c.x, y: c.y, parameters: ['t'] });
    assert.equal(reference.status, 200, JSON.stringify(reference.json));
    assert.equal(reference.json.implicit, c.expected);
    await assertRationalized(reference.json, t, `${c.x}, ${c.y}`);
    assert.equal(await page.getAttribute('#preview', 'data-dimension'), '2');
  }
});

test('refusals are shown beside the input with their code, the function and its position', async (t) => {
  const cases = [
    { params: 'u, v', x: 'u*cos(u)', y: 'sin(v)', z: 'v', field: 'x', name: 'cos' },
    { params: 's, t', x: 's', y: 'cos(s*t)', z: 't', field: 'y', name: 'cos' },
    { params: 'u, v', x: 'cos(u/2)', y: 'v', z: 'sin(v)', field: 'x', name: 'cos' },
    { params: 'u, v', x: 'u', y: 'v', z: 'sqrt(u)', field: 'z', name: 'sqrt' },
    { params: 'u, v', x: 'u', y: 'exp(v)', z: 'v', field: 'y', name: 'exp' },
    { params: 'u, v', x: 'log(u)', y: 'v', z: 'u', field: 'x', name: 'log' },
    { params: 'u, v', x: 'u', y: 'bessel(v)', z: 'v', field: 'y', name: 'bessel' },
  ];
  for (const c of cases) {
    const reference = await postJson('/v1/implicitize', { x: c.x, y: c.y, z: c.z, parameters: c.params.split(', ') });
    assert.equal(reference.status, 400, JSON.stringify(reference.json));
    const { code, position, field, message } = reference.json.error;
    t.diagnostic(`${c[c.field]}: ${code} at ${position}: ${message}`);
    assert.equal(field, c.field);
    assert.notEqual(code, 'missing_operator');
    assert.ok(message.includes(c.name), `${message} names ${c.name}`);
    await implicitizeTyped(c);
    await page.waitForSelector(`#${c.field}-error:not([hidden])`);
    const text = await page.textContent(`#${c.field}-error`);
    assert.ok(text.includes(code) && text.includes(c.name), text);
    assert.equal(await page.getAttribute(`#${c.field}-error`, 'data-position'), String(position));
    await assertEmpty('failed', new RegExp(code));
  }
});

test('no errors in the page console', () => {
  assert.deepEqual(pageErrors, []);
});
