// Browser tests of the web client's jobs (issue 22, item 3): the page runs its
// computations through POST /v1/jobs and follows them to their end. The real
// implicitizer-server on a loopback port and Debian's chromium (harness.mjs), nothing
// of the server mocked; what is checked through the API is asked of that same server.
// - a long job (tp_33 of shared/bench/surfaces_hard.json by Gröbner bases) shows the
//   progress bar, the job's phase and its states arriving by the event stream; Cancel
//   returns the page to idle with "Cancelled after N s." and the job's status on the
//   server becomes `cancelled`;
// - a short job shows exactly what the synchronous POST /v1/implicitize answers
//   (equation, degree, method, verified, scripts), and the job holds that answer;
// - a job that fails shows the endpoint's error beside its input, with its code;
// - with the event stream cut (the browser's request to /events aborted: the stream
//   "drops"), the page follows its jobs by polling GET /v1/jobs/{id}, for a long job
//   (progress shown, Cancel cancels it) and a short one (its answer shown);
// - a server killed (SIGKILL) while a job runs: the page ends with network_error,
//   idle and usable, instead of waiting for ever.
// No assertion depends on the machine's speed: the tests wait for the page's states
// and poll the server with generous deadlines.
//
//   node --test --test-reporter=spec tests/web/web_jobs.test.mjs   (from the repository root)
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { launchChromium, sharedDir, startServer, stopServer, watchErrors } from './harness.mjs';

const LONG = 180000; // ms: a deadline for anything a loaded machine may be slow at

let server;
let browser;
let page;
const pageErrors = [];
const jobs = []; // {kind, id} of every job the page submitted, in order

const tp33 = () => {
  const hard = JSON.parse(fs.readFileSync(path.join(sharedDir, 'bench', 'surfaces_hard.json'), 'utf8')).find((s) => s.name === 'tp_33');
  assert.ok(hard, 'tp_33 in surfaces_hard.json');
  return hard;
};

async function api(method, pathname, body) {
  const response = await fetch(server.url + pathname, { method, body: body === undefined ? undefined : JSON.stringify(body) });
  const text = await response.text();
  return { status: response.status, json: text ? JSON.parse(text) : null };
}

/// The jobs of `kind` the page submitted after the first `from` of all.
function jobsOf(kind, from) {
  return jobs.slice(from).filter((j) => j.kind === kind);
}

/// Polls GET /v1/jobs/{id} until its status is `status` (or LONG has passed); returns
/// the last state read.
async function waitForJobStatus(id, status) {
  const deadline = Date.now() + LONG;
  let job = null;
  while (Date.now() < deadline) {
    job = (await api('GET', `/v1/jobs/${id}`)).json;
    if (job.status === status) break;
    await new Promise((resolve) => setTimeout(resolve, 250));
  }
  return job;
}

async function implicitizeTyped(p, { x, y, z, method = 'auto', timeout = '10000' }) {
  await p.click('#tab-parametric');
  await p.fill('#params', 's, t');
  await p.fill('#x', x);
  await p.fill('#y', y);
  await p.fill('#z', z);
  await p.fill('#domain', '');
  await p.selectOption('#method', method);
  await p.selectOption('#timeout', timeout);
  await p.click('#implicitize');
}

/// Waits until #progress shows a running job of the implicitize request whose states
/// came by `feed`, at least `updates` of them (the submission's answer counts one).
async function waitForRunningJob(p, feed, updates) {
  await p.waitForFunction(
    ([f, n]) => {
      const d = document.getElementById('progress').dataset;
      return d.state === 'busy' && d.jobStatus === 'running' && d.jobFeed === f && Number(d.jobUpdates) >= n;
    },
    [feed, updates],
    { timeout: LONG, polling: 50 },
  );
}

/// Cancel pressed on the running job `id`: the page is idle and usable at once, and
/// the job's status on the server becomes `cancelled`.
async function cancelAndCheck(id) {
  await page.click('#cancel');
  await page.waitForSelector('#progress[data-state="idle"]', { timeout: 30000 });
  assert.match(await page.textContent('#progress-text'), /^Cancelled after \d+\.\d s\.$/);
  assert.equal(await page.isHidden('#cancel'), true);
  assert.equal(await page.isHidden('#job-progress'), true, 'the bar is gone');
  assert.equal(await page.isEnabled('#implicitize'), true);
  assert.equal(await page.getAttribute('#result-empty', 'data-reason'), 'cancelled');
  const job = await waitForJobStatus(id, 'cancelled');
  assert.equal(job.status, 'cancelled', `the job on the server: ${JSON.stringify(job)}`);
}

/// Asserts that the page shows what the synchronous answer `reference` (POST
/// /v1/implicitize) says, as the page showed it before jobs.
async function assertShowsAnswer(reference) {
  assert.equal(await page.textContent('#implicit'), `${reference.implicit} = 0`);
  assert.equal(await page.textContent('#degree'), String(reference.degree));
  assert.equal(await page.textContent('#result-method'), reference.method === 'groebner' ? 'Gröbner' : reference.method);
  assert.equal(await page.textContent('#verified'), reference.verified ? '✓ yes' : '✗ no');
  assert.equal(await page.textContent('#reproduce-singular'), reference.reproduce.singular);
  assert.equal(await page.textContent('#reproduce-macaulay2'), reference.reproduce.macaulay2);
}

/// Runs the parametrization `surface` on the page (a new one: no cached answer, so
/// that its job really runs) and checks the answer against the synchronous endpoint's.
async function implicitizeShortAndCompare(surface) {
  const from = jobs.length;
  await implicitizeTyped(page, surface);
  await page.waitForSelector('#progress[data-state="done"]', { timeout: LONG });
  const reference = await api('POST', '/v1/implicitize', { ...surface, parameters: ['s', 't'] });
  assert.equal(reference.status, 200);
  await assertShowsAnswer(reference.json);
  const [submitted] = jobsOf('implicitize', from);
  assert.ok(submitted, 'the page submitted an implicitize job');
  const job = (await api('GET', `/v1/jobs/${submitted.id}`)).json;
  assert.equal(job.status, 'done');
  assert.equal(job.http_status, 200);
  assert.equal(job.result.implicit, reference.json.implicit);
  assert.equal(jobsOf('sdf', from).length, 1, 'the patch\'s distance function ran as a job too');
}

before(async () => {
  server = await startServer();
  browser = await launchChromium();
  page = await browser.newPage({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
  watchErrors(page, pageErrors);
  page.on('response', async (r) => {
    if (r.request().method() !== 'POST' || new URL(r.url()).pathname !== '/v1/jobs' || r.status() !== 202) return;
    const { kind } = JSON.parse(r.request().postData());
    jobs.push({ kind, id: (await r.json()).id });
  });
  await page.goto(server.url + '/?aa=1');
  await page.waitForSelector('body[data-ready="true"]');
  // The initial example (the torus) runs first, as jobs.
  await page.waitForSelector('#progress[data-state="done"]', { timeout: LONG });
  await page.fill('#tolerance', ''); // the exact equation: no approximation to wait for
});

after(async () => {
  if (browser) await browser.close();
  await stopServer(server);
});

test('the initial example ran as jobs: implicitize, then its distance function', () => {
  assert.deepEqual(jobs.map((j) => j.kind).slice(0, 2), ['implicitize', 'sdf']);
});

test('a long job shows its progress from the events; Cancel cancels it on the server', async () => {
  const from = jobs.length;
  const hard = tp33();
  await implicitizeTyped(page, { x: hard.x, y: hard.y, z: hard.z, method: 'groebner', timeout: '60000' });
  // Two events at least after the submission's answer: states arrive while it runs.
  await waitForRunningJob(page, 'events', 3);
  const [submitted] = jobsOf('implicitize', from);
  assert.equal(await page.getAttribute('#progress', 'data-job'), submitted.id);
  assert.equal(await page.textContent('#progress-text'), 'Implicitizing…');
  assert.equal(await page.isVisible('#job-progress'), true, 'the bar is shown');
  const phase = await page.textContent('#progress-phase');
  assert.ok(phase && phase !== 'queued', `the job's phase is shown: '${phase}'`);
  // The bar: the fraction where the server knows one, else indeterminate (position -1).
  const bar = await page.$eval('#job-progress', (b) => ({ value: b.hasAttribute('value') ? b.value : null, position: b.position }));
  assert.ok(bar.value === null ? bar.position === -1 : bar.value >= 0 && bar.value <= 1, `bar ${JSON.stringify(bar)}`);
  assert.match(await page.textContent('#progress-time'), /^\d+\.\d s$/);
  await cancelAndCheck(submitted.id);
});

test('a short job shows what the synchronous answer shows', async () => {
  // x² + y² + z²/4 = 1 scaled: a sphere stretched along z, new to this server's cache.
  await implicitizeShortAndCompare({ x: '2*s/(1+s^2+t^2)', y: '2*t/(1+s^2+t^2)', z: '2*(1-s^2-t^2)/(1+s^2+t^2)' });
  assert.equal(await page.isHidden('#job-progress'), true, 'no bar once done');
});

test('a failed job shows the endpoint\'s error beside its input, with its code', async () => {
  const from = jobs.length;
  const bad = { x: 's+*t', y: 's', z: 't' };
  const reference = await api('POST', '/v1/implicitize', { ...bad, parameters: ['s', 't'] });
  assert.equal(reference.status, 400);
  await implicitizeTyped(page, bad);
  await page.waitForSelector('#x-error:not([hidden])', { timeout: LONG });
  const { code, position } = reference.json.error;
  assert.match(await page.textContent('#x-error'), new RegExp(`^${code}: `));
  assert.equal(await page.getAttribute('#x-error', 'data-position'), String(position));
  assert.equal(await page.textContent('#progress-text'), `Error 400 · ${code}`);
  // Refused at submission (the endpoint's decoder) or failed as a job: the same error.
  const [submitted] = jobsOf('implicitize', from);
  if (submitted) {
    const job = (await api('GET', `/v1/jobs/${submitted.id}`)).json;
    assert.equal(job.status, 'failed');
    assert.deepEqual(job.result, reference.json);
  }
});

test('with the event stream cut, the page polls: progress, Cancel, and a short answer', async () => {
  // The browser's requests to the events fail as a dropped connection would.
  const cut = (route) => route.abort('connectionreset');
  await page.route('**/v1/jobs/*/events', cut);
  try {
    const from = jobs.length;
    const hard = tp33();
    await implicitizeTyped(page, { x: hard.x, y: hard.y, z: hard.z, method: 'groebner', timeout: '60000' });
    await waitForRunningJob(page, 'polling', 2);
    assert.ok((await page.textContent('#progress-phase')).length > 0, 'the phase is shown');
    const [submitted] = jobsOf('implicitize', from);
    await cancelAndCheck(submitted.id);
    await implicitizeShortAndCompare({ x: '3*s/(1+s^2+t^2)', y: '2*t/(1+s^2+t^2)', z: '(1-s^2-t^2)/(1+s^2+t^2)' });
  } finally {
    await page.unroute('**/v1/jobs/*/events', cut);
  }
});

test('a server killed while its job runs ends the request with network_error, not a wait', async () => {
  const doomed = await startServer();
  const other = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  try {
    // No example: nothing else runs on this page.
    await other.goto(doomed.url + '/?aa=1&example=none');
    await other.waitForSelector('body[data-ready="true"]');
    const hard = tp33();
    await implicitizeTyped(other, { x: hard.x, y: hard.y, z: hard.z, method: 'groebner', timeout: '60000' });
    await waitForRunningJob(other, 'events', 2);
    doomed.process.kill('SIGKILL');
    // The stream drops, the polls fail a bounded number of times, and the page says so.
    await other.waitForSelector('#progress[data-state="error"]', { timeout: LONG });
    assert.equal(await other.textContent('#progress-text'), 'Error · network_error');
    assert.match(await other.textContent('#general-error'), /^network_error: could not reach the server/);
    assert.equal(await other.isEnabled('#implicitize'), true, 'usable again');
    assert.equal(await other.isHidden('#cancel'), true);
  } finally {
    doomed.process.kill('SIGKILL');
    await other.close();
  }
});

test('no errors in the page console', () => {
  assert.deepEqual(pageErrors, []);
});
