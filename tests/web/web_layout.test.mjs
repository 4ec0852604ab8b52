// Browser tests of the web client's layout (issue 40, item 4), at 1280×800 as the
// user who reported it saw the page: the real implicitizer-server and Debian's
// chromium, headless (harness.mjs), nothing mocked.
// - the answer (equation, degree, method, verification) in sight without scrolling
//   after the sphere and Enneper's surface;
// - the equation's lines end between terms, never inside a number or a name;
// - every line count on the page is the shown GLSL's (Whitney's umbrella, Enneper);
// - a failure takes the fitted box's placeholder off with the answer;
// - the job's bar never goes backwards while the S-pair total grows (tp_33, Gröbner);
// - the copy toast covers nothing;
// - a plane curve (the lemniscate) framed with a margin, its hint saying what dragging
//   does in 2-D (it pans; the wheel zooms).
// No assertion depends on the machine's speed: the tests wait for the page's states.
//
//   node --test --test-reporter=spec tests/web/web_layout.test.mjs   (from the repository root)
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { dragPreview, launchChromium, readPreviewCanvas, root, sharedDir, startServer, stopServer, watchErrors } from './harness.mjs';

const LONG = 300000; // ms: a deadline for anything a loaded machine may be slow at
const VIEWPORT = { width: 1280, height: 800 };

let server;
let browser;
let page;
const pageErrors = [];

async function frameNumber() {
  return page.evaluate(() => Number(document.getElementById('preview').dataset.frame || 0));
}

/// Waits until the preview has finished an image newer than frame `frame`.
function waitForNewFrame(frame) {
  return page.waitForFunction(
    (f) => {
      const d = document.getElementById('preview').dataset;
      return d.state === 'done' && Number(d.frame || 0) > f;
    },
    frame,
    { timeout: LONG, polling: 100 },
  );
}

/// Picks `name` from the menu and waits for its answer and its finished picture; nothing
/// when the page already shows them (Enneper's sheet takes minutes on a software GPU).
async function pickExample(name) {
  const shown = await page.evaluate(
    (n) => document.getElementById('examples').value === n && document.getElementById('progress').dataset.state === 'done' && document.getElementById('preview').dataset.state === 'done',
    name,
  );
  if (shown) return;
  const frame = await frameNumber();
  await page.selectOption('#examples', name);
  await page.waitForFunction(
    (f) => {
      const d = document.getElementById('preview').dataset;
      return d.state === 'done' && Number(d.frame || 0) > f && document.getElementById('progress').dataset.state === 'done';
    },
    frame,
    { timeout: LONG, polling: 100 },
  );
}

/// The rectangles of the answer's parts and of what could hide them: the inputs
/// column's visible area (it scrolls) and the page's scroll offsets.
function answerRects() {
  return page.evaluate(() => {
    const rect = (e) => {
      const r = e.getBoundingClientRect();
      return { top: r.top, bottom: r.bottom, left: r.left, right: r.right };
    };
    const parts = Object.fromEntries(['implicit', 'degree', 'result-method', 'verified'].map((id) => [id, rect(document.getElementById(id))]));
    const column = document.querySelector('.inputs');
    return { parts, column: rect(column), columnScroll: column.scrollTop, pageScroll: window.scrollY, innerHeight: window.innerHeight };
  });
}

before(async () => {
  server = await startServer();
  browser = await launchChromium();
  page = await browser.newPage({ viewport: VIEWPORT, deviceScaleFactor: 1 });
  watchErrors(page, pageErrors);
  await page.goto(server.url + '/?aa=1');
  await page.waitForSelector('body[data-ready="true"]');
  await page.waitForSelector('#progress[data-state="done"]', { timeout: LONG });
});

after(async () => {
  if (browser) await browser.close();
  await stopServer(server);
});

for (const name of ['unit_sphere', 'enneper']) {
  test(`at 1280×800 the answer to ${name} is in sight without scrolling`, async () => {
    await pickExample(name);
    const r = await answerRects();
    assert.equal(r.pageScroll, 0);
    assert.equal(r.columnScroll, 0, 'the inputs column was not scrolled');
    for (const [id, box] of Object.entries(r.parts)) {
      assert.ok(box.bottom > box.top, `#${id} is laid out`);
      assert.ok(box.bottom <= VIEWPORT.height, `#${id} ends at ${box.bottom} <= ${VIEWPORT.height}`);
      // Not clipped by the column, which scrolls (overflow-y: auto) at its own edges.
      assert.ok(box.top >= r.column.top && box.bottom <= r.column.bottom, `#${id} (${box.top}–${box.bottom}) inside the column (${r.column.top}–${r.column.bottom})`);
    }
  });
}

test('the equation wraps between terms, never inside a number or a name', async () => {
  await pickExample('enneper');
  const result = await page.evaluate(() => {
    const output = document.getElementById('implicit');
    // Every text node with its offset in the whole text, to map a token onto a Range.
    const nodes = [];
    let text = '';
    const walker = document.createTreeWalker(output, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      nodes.push({ node: n, start: text.length });
      text += n.data;
    }
    const at = (offset) => {
      let k = nodes.length - 1;
      while (k > 0 && nodes[k].start > offset) --k;
      return [nodes[k].node, offset - nodes[k].start];
    };
    const lines = new Set();
    const split = [];
    let tokens = 0;
    for (const m of text.matchAll(/[0-9]+|[A-Za-z_][A-Za-z0-9_]*(?:\^[0-9]+)?/g)) {
      const range = document.createRange();
      range.setStart(...at(m.index));
      range.setEnd(...at(m.index + m[0].length - 1));
      range.setEnd(range.endContainer, range.endOffset + 1);
      // The token's line boxes: its rectangles' distinct tops (rounded: one line's
      // rectangles share it).
      const tops = new Set([...range.getClientRects()].filter((r) => r.width > 0).map((r) => Math.round(r.top)));
      for (const top of tops) lines.add(top);
      if (tops.size !== 1) split.push(`${m[0]} at ${m.index} on ${tops.size} lines`);
      ++tokens;
    }
    return { text, tokens, lines: lines.size, split };
  });
  assert.ok(result.text.startsWith('64*z^9-432*x^2*z^6'), result.text.slice(0, 40));
  assert.ok(result.lines > 3, `the equation takes several lines (${result.lines}), so that wrapping is tested`);
  assert.deepEqual(result.split, [], `${result.tokens} tokens, none across two lines`);
});

// Every "N lines" and "N GLSL lines" on the page, and the line count of the GLSL shown
// (and copied: Copy GLSL copies the same text), counted as an editor does.
async function lineCounts() {
  return page.evaluate(() => {
    const glsl = document.getElementById('glsl').textContent;
    const counted = glsl.split('\n').length - (glsl.endsWith('\n') ? 1 : 0);
    // innerText: what is rendered; the GLSL's <details> is closed, its summary shown.
    const shown = [...document.body.innerText.matchAll(/(\d+) (?:GLSL )?lines?\b/g)].map((m) => Number(m[1]));
    return { counted, shown };
  });
}

for (const [name, places] of [['enneper', 2], ['whitney_umbrella', 2]]) {
  test(`one GLSL line count everywhere (${name})`, async () => {
    await pickExample(name);
    const { counted, shown } = await lineCounts();
    assert.ok(counted > 10, `the GLSL has ${counted} lines`);
    assert.ok(shown.length >= places, `the summary and the tolerance line both count lines: ${shown}`);
    assert.deepEqual(shown, shown.map(() => counted), `every count shown (${shown}) is the GLSL's ${counted}`);
  });
}

test('a failure takes the fitted box\'s placeholder off with the answer', async () => {
  const original = /<input id="box"[^>]*placeholder="([^"]*)"/.exec(fs.readFileSync(path.join(root, 'clients', 'web', 'index.html'), 'utf8'))[1];
  await pickExample('unit_sphere');
  assert.match(await page.getAttribute('#box', 'placeholder'), /^automatic \(now /, 'a drawn surface names its box');
  await page.fill('#x', 's+*t');
  await page.click('#implicitize');
  await page.waitForSelector('#progress[data-state="error"]', { timeout: LONG });
  assert.equal(await page.getAttribute('#result-empty', 'data-reason'), 'failed');
  assert.equal(await page.getAttribute('#box', 'placeholder'), original);
});

test('the job\'s bar never goes backwards while the S-pair total grows', async () => {
  const hard = JSON.parse(fs.readFileSync(path.join(sharedDir, 'bench', 'surfaces_hard.json'), 'utf8')).find((s) => s.name === 'tp_33');
  assert.ok(hard, 'tp_33 in surfaces_hard.json');
  // Each state the page shows: the bar's value (null: indeterminate) and the phase.
  await page.evaluate(() => {
    const bar = document.getElementById('job-progress');
    const progress = document.getElementById('progress');
    window.layoutProgress = [];
    const record = () => {
      if (progress.dataset.state !== 'busy' || bar.hidden) return;
      window.layoutProgress.push({
        job: progress.dataset.job,
        value: bar.hasAttribute('value') ? bar.value : null,
        phase: document.getElementById('progress-phase').textContent,
        mode: progress.dataset.jobBar,
      });
    };
    // Each state sets data-job-updates; the observer runs after the whole update.
    new MutationObserver(record).observe(progress, { attributes: true, attributeFilter: ['data-job-updates'] });
  });
  await page.fill('#params', 's, t');
  await page.fill('#x', hard.x);
  await page.fill('#y', hard.y);
  await page.fill('#z', hard.z);
  await page.fill('#domain', '');
  await page.selectOption('#method', 'groebner');
  await page.selectOption('#timeout', '60000');
  await page.click('#implicitize');
  // Until the server's own fraction (the phase's done/total) has gone down at least once.
  await page.waitForFunction(
    () => {
      let highest = 0;
      for (const s of window.layoutProgress) {
        const m = /(\d+)\/(\d+)/.exec(s.phase);
        if (!m) continue;
        const f = Number(m[1]) / Number(m[2]);
        if (f < highest) return true;
        highest = Math.max(highest, f);
      }
      return false;
    },
    null,
    { timeout: LONG, polling: 100 },
  );
  await page.click('#cancel');
  await page.waitForSelector('#progress[data-state="idle"]', { timeout: LONG });
  const states = await page.evaluate(() => window.layoutProgress);
  const job = states[states.length - 1].job;
  const values = states.filter((s) => s.job === job && s.value !== null).map((s) => s.value);
  for (let i = 1; i < values.length; ++i) assert.ok(values[i] >= values[i - 1], `the bar went from ${values[i - 1]} to ${values[i]}`);
  // Once the total moved, the counts say how far it got.
  const fallen = states.filter((s) => s.job === job && s.mode === 'counts');
  assert.ok(fallen.length > 0, 'the bar gave way to the counts');
  for (const s of fallen) assert.match(s.phase, /\d+\/\d+/);
});

test('the copy toast covers nothing', async () => {
  await pickExample('unit_sphere');
  // Measured as it appears (it hides itself after a while): what lies under it, at a
  // grid of its points, must be the toast itself or what contains it.
  const result = await page.evaluate(
    () =>
      new Promise((resolve) => {
        const toast = document.getElementById('toast');
        new MutationObserver((_, observer) => {
          if (toast.hidden) return;
          observer.disconnect();
          const r = toast.getBoundingClientRect();
          const covered = new Set();
          for (let i = 0; i <= 4; ++i) {
            for (let j = 0; j <= 2; ++j) {
              const x = r.left + 1 + ((r.width - 2) * i) / 4, y = r.top + 1 + ((r.height - 2) * j) / 2;
              for (const e of document.elementsFromPoint(x, y)) {
                if (!toast.contains(e) && !e.contains(toast)) covered.add(e.id || e.className || e.tagName);
              }
            }
          }
          const summary = document.querySelector('#glsl-details > summary').getBoundingClientRect();
          const overlaps = !(r.right <= summary.left || summary.right <= r.left || r.bottom <= summary.top || summary.bottom <= r.top);
          resolve({ text: toast.textContent, width: r.width, covered: [...covered], overlaps });
        }).observe(toast, { attributes: true, attributeFilter: ['hidden'] });
        document.getElementById('copy-glsl').click();
      }),
  );
  assert.ok(result.width > 0, `the toast is shown: '${result.text}'`);
  assert.equal(result.overlaps, false, 'the toast is off the summary line');
  assert.deepEqual(result.covered, [], `'${result.text}' covers nothing`);
});

test('a plane curve is framed with a margin, and its hint says what dragging does', async () => {
  await pickExample('lemniscate');
  assert.equal(await page.getAttribute('#preview', 'data-dimension'), '2');
  const { width, height, rgb, view } = await readPreviewCanvas(page);
  // The line's pixels: the curve's dark blue (web_client.test.mjs tests the picture).
  let left = width, right = -1, top = height, bottom = -1;
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width; ++x) {
      const p = 3 * (y * width + x);
      if (!(rgb[p + 2] > rgb[p] + 60 && rgb[p] < 150)) continue;
      left = Math.min(left, x);
      right = Math.max(right, x);
      top = Math.min(top, y);
      bottom = Math.max(bottom, y);
    }
  }
  assert.ok(right > left, 'the curve is drawn');
  const margin = Math.round(0.03 * Math.min(width, height));
  const gaps = { left, right: width - 1 - right, top, bottom: height - 1 - bottom };
  for (const [edge, gap] of Object.entries(gaps)) assert.ok(gap >= margin, `${gap} px of background at the ${edge} edge (>= ${margin})`);
  // The hint says what the 2-D view does, and it does that: a drag pans (the centre
  // moves, the scale stays), the wheel zooms (the scale changes).
  const hint = await page.textContent('#stage-hint');
  assert.match(hint, /drag to pan/);
  assert.doesNotMatch(hint, /orbit/);
  assert.match(hint, /zoom/);
  const before = JSON.parse(view.view);
  let frame = await frameNumber();
  await dragPreview(page, 40, 20);
  await waitForNewFrame(frame);
  const panned = JSON.parse(await page.getAttribute('#preview', 'data-view'));
  assert.ok(panned.centre[0] < before.centre[0] && panned.centre[1] > before.centre[1], 'the drag panned');
  assert.equal(panned.scale, before.scale);
  frame = await frameNumber();
  await page.mouse.wheel(0, -200); // the pointer is still over the canvas
  await waitForNewFrame(frame);
  const zoomed = JSON.parse(await page.getAttribute('#preview', 'data-view'));
  assert.ok(zoomed.scale > panned.scale, 'the wheel zoomed in');
  // A surface's hint speaks of orbiting again.
  await pickExample('unit_sphere');
  assert.match(await page.textContent('#stage-hint'), /drag to orbit/);
});

test('no errors in the page console', () => {
  assert.deepEqual(pageErrors, []);
});
