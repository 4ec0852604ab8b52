// The page as a user meets it: for each example of the menu (and tp_33 of shared/bench
// typed in, over [0, 1]², with and without the tolerance), at the page's defaults, the
// time from choosing it to the answer (the equation shown), to the shader compiled
// (drawing starts), to the first complete
// picture (any resolution), to the first at half the resolution or finer, to the full
// resolution at one sample per pixel, and to the finished picture (the AA the page is
// set to), and whether the GPU context was lost on the way. Debian's chromium, headless, WebGL2 on
// SwiftShader (tests/web/harness.mjs). A benchmark, not a test: it asserts nothing
// about speed and is not run by ctest; times depend on the machine's load.
//
//   node bench/web/page_pictures.mjs [--examples enneper,bicubic_patch] [--typed tp_33] [--size 1280x800]
import fs from 'node:fs';
import path from 'node:path';
import { launchChromium, sharedDir, startServer, stopServer } from '../../tests/web/harness.mjs';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i > 0 && i + 1 < process.argv.length ? process.argv[i + 1] : fallback;
}
const menu = JSON.parse(fs.readFileSync(new URL('../../clients/web/examples.json', import.meta.url), 'utf8')).examples;
const examples = option('--examples', menu.map((e) => e.name).join(',')).split(',').filter(Boolean);
const typed = option('--typed', 'tp_33').split(',').filter(Boolean);
const [width, height] = option('--size', '1280x800').split('x').map(Number);
const limitMs = Number(option('--limit-s', '300')) * 1000;
const hard = JSON.parse(fs.readFileSync(path.join(sharedDir, 'bench', 'surfaces_hard.json'), 'utf8'));

// Resolves the page's milestones, in ms from `t0` (performance.now() in the page).
async function milestones(page, t0) {
  return page.evaluate(
    ({ t0, limitMs }) =>
      new Promise((resolve) => {
        const canvas = document.getElementById('preview');
        const result = { answer: null, compiled: null, first: null, half: null, full: null, done: null, lost: false, state: '', stats: '' };
        const poll = () => {
          const now = performance.now() - t0;
          const d = canvas.dataset;
          if (result.answer === null && !document.getElementById('result').hidden) result.answer = now;
          if (result.compiled === null && result.answer !== null && (d.state === 'rendering' || d.state === 'refining')) result.compiled = now;
          const pictured = Number(d.pictures || 0) > 0;
          if (result.first === null && pictured) result.first = now;
          if (result.half === null && pictured && Number(d.pictureFactor) <= 2) result.half = now;
          if (result.full === null && pictured && Number(d.pictureFactor) === 1) result.full = now;
          if (d.lost === 'true' || /lost/i.test(document.getElementById('preview-stats').textContent)) result.lost = true;
          const failed = document.getElementById('progress').dataset.state === 'error';
          if (d.state === 'done' || failed || now > limitMs) {
            if (d.state === 'done') result.done = now;
            result.state = failed ? 'error' : d.state;
            result.stats = `${document.getElementById('preview-stats').textContent} | ${document.getElementById('progress-text').textContent}`;
            return resolve(result);
          }
          setTimeout(poll, 25);
        };
        poll();
      }),
    { t0, limitMs },
  );
}

const seconds = (ms) => (ms === null ? '—' : (ms / 1000).toFixed(1));
const server = await startServer();
const browser = await launchChromium();
console.log('| surface | answer (s) | drawing (s) | first picture (s) | ½ resolution (s) | full, AA 1 (s) | finished (s) | context lost | last state |');
console.log('|---|---|---|---|---|---|---|---|---|');
try {
  const cases = [
    ...examples.map((name) => ({ label: name, url: `/?example=${name}` })),
    ...typed.flatMap((name) => ['1e-3', ''].map((tolerance) => ({ label: `${name}, tolerance ${tolerance || 'empty'}`, typed: hard.find((e) => e.name === name), tolerance }))),
  ];
  for (const c of cases) {
    const page = await browser.newPage({ viewport: { width, height } });
    let t0;
    if (c.url) {
      await page.goto(server.url + c.url);
      t0 = await page.evaluate(() => performance.timeOrigin - performance.timeOrigin); // navigation start
    } else {
      await page.goto(server.url + '/?example=plane');
      await page.waitForFunction(() => document.getElementById('preview').dataset.state === 'done', null, { timeout: limitMs });
      for (const [field, value] of [['x', c.typed.x], ['y', c.typed.y], ['z', c.typed.z], ['domain', '0, 1, 0, 1'], ['tolerance', c.tolerance]]) {
        await page.fill(`#${field}`, value);
      }
      t0 = await page.evaluate(() => {
        document.getElementById('preview').dataset.pictures = '0';
        document.getElementById('form-parametric').requestSubmit();
        return performance.now();
      });
    }
    const m = await milestones(page, t0);
    console.log(`| ${c.label} | ${seconds(m.answer)} | ${seconds(m.compiled)} | ${seconds(m.first)} | ${seconds(m.half)} | ${seconds(m.full)} | ${seconds(m.done)} | ${m.lost ? 'yes' : 'no'} | ${m.state}: ${m.stats} |`);
    await page.close();
  }
} finally {
  await browser.close();
  await stopServer(server);
}
