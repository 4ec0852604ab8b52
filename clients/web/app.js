// The page: inputs → implicitize → the equation and its scripts → sdf (the parametric
// surface itself, over its domain: the patch, in the shape the server picks) → the
// live preview (preview.js: sheets two-sided, curves flat). Errors are shown beside
// the input they concern, with the server's position marked.
//
// The computations run as jobs (jobs.js, POST /v1/jobs): implicitize, the surface's
// sdf and the CPU render. Each of them can take from milliseconds to minutes on input
// the page cannot judge beforehand (the hard surfaces of shared/bench implicitize for
// many seconds, an sdf of a patch implicitizes it again and may approximate it, a CPU
// render of a heavy safe mode is slow on a busy server), so all of them take the same
// road: one code path, a progress bar fed by the job's events, and a Cancel that
// deletes the job on the server. A short job costs a submission and its first event
// (the server's event poll, docs/api.md "Jobs") more than a plain POST, which the page
// can afford against a second code path. Only the sheet's side function stays a plain
// POST /v1/sdf: a fast-mode distance function of an equation already computed, quick
// whatever the surface, which as a job would queue behind other clients' long jobs
// (--job-threads) for nothing.
import { ApiError, apiHost, checkHealth, implicitizeRequest, postJson, sdfRequest } from './api.js';
import { fillExamplesMenu, loadExamples } from './examples.js';
import { runJob } from './jobs.js';
import { ContextLostError, defaultCamera, Preview, ShaderError } from './preview.js';

const $ = (id) => document.getElementById(id);
const INITIAL_EXAMPLE = 'torus_R2_r1';
const FIELDS = ['params', 'x', 'y', 'z', 'domain', 'tolerance', 'equation', 'box'];
const DEFAULT_PARAMETERS = ['s', 't'];

const ui = {
  tabs: { parametric: $('tab-parametric'), implicit: $('tab-implicit') },
  forms: { parametric: $('form-parametric'), implicit: $('form-implicit') },
  examples: $('examples'),
  inputs: { params: $('params'), x: $('x'), y: $('y'), z: $('z'), domain: $('domain'), tolerance: $('tolerance'), equation: $('equation'), box: $('box') },
  coordinateLabels: [...document.querySelectorAll('label.coordinate .arguments')],
  domainNames: $('domain-names'),
  resultEmpty: $('result-empty'),
  previewEmpty: $('preview-empty'),
  shape: $('shape'),
  method: $('method'),
  timeout: $('timeout'),
  progress: $('progress'),
  progressText: $('progress-text'),
  progressTime: $('progress-time'),
  progressPhase: $('progress-phase'),
  jobBar: $('job-progress'),
  cancel: $('cancel'),
  submitButtons: [$('implicitize'), $('draw')],
  generalError: $('general-error'),
  result: $('result'),
  resultHeading: $('result-heading'),
  implicit: $('implicit'),
  degree: $('degree'),
  resultMethod: $('result-method'),
  resultTime: $('result-time'),
  verified: $('verified'),
  resultStats: $('result-stats'),
  substitution: $('substitution'),
  substitutionFormulas: $('substitution-formulas'),
  substitutionRational: $('substitution-rational'),
  reproduce: $('reproduce'),
  singular: $('reproduce-singular'),
  macaulay2: $('reproduce-macaulay2'),
  canvas: $('preview'),
  overlay: $('preview-overlay'),
  noWebgl: $('webgl-unavailable'),
  cpuImage: $('cpu-fallback'),
  stats: $('preview-stats'),
  approximation: $('approximation'),
  aa: $('aa'),
  resolution: $('resolution'),
  resetView: $('reset-view'),
  copyGlsl: $('copy-glsl'),
  downloadGlsl: $('download-glsl'),
  glsl: $('glsl'),
  glslSummary: $('glsl-summary'),
  toast: $('toast'),
  stageHint: $('stage-hint'),
  serverStatus: $('server-status'),
};

// The box input's placeholder as the page was loaded: a drawn surface's placeholder
// names its fitted box, and goes when that surface does.
const BOX_PLACEHOLDER = ui.inputs.box.placeholder;

const state = {
  mode: 'parametric',
  examples: [],
  busy: null, // the running request: {controller, started, timer, setLabel, job}
  drawn: null, // {source, equation, box, name, mode, shape, answerBox, dimension}: what the preview shows
  answered: null, // {source, equation, box, name}: the surface whose answer is shown (a mode switch redraws it)
  boxFromExample: false, // the box input holds the example's box (refilled when the tab changes)
  glsl: '', // the last GLSL POST /v1/sdf returned
  glslFunction: '', // its function's name, which names the downloaded file
};

// ---------------------------------------------------------------- formatting

function formatMs(ms) {
  if (!Number.isFinite(ms)) return '—';
  if (ms < 1) return `${ms.toFixed(2)} ms`;
  if (ms < 1000) return `${ms.toFixed(ms < 10 ? 1 : 0)} ms`;
  return `${(ms / 1000).toFixed(ms < 10000 ? 2 : 1)} s`;
}

function shortRenderer(name) {
  // "ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)"
  // -> "Vulkan 1.3.0 (SwiftShader Device (Subzero))"
  if (!name) return '';
  const m = /^ANGLE \((?:[^,]*), (.*), [^,]*\)$/.exec(name);
  return (m ? m[1] : name).replace(/ \(0x[0-9a-fA-F]+\)/g, '').replace(/\s+Direct3D.*$/, '');
}

// The items of a list typed as text ("a, b c"), each with its position, for the error caret.
function itemsOf(text) {
  const parts = [];
  const re = /[^\s,]+/g;
  let m;
  while ((m = re.exec(text))) parts.push({ value: m[0], position: m.index });
  return parts;
}

// The items of a list typed as text, without their positions.
function itemValues(text) {
  return itemsOf(text).map((p) => p.value);
}

/// Parses "x0, y0, z0, x1, y1, z1" or, for a curve, "x0, y0, x1, y1" (commas or
/// spaces); empty gives null (the server fits the box to a patch, else [-2, 2]^3).
/// Throws an ApiError-like object with the position of the first bad number.
function parseBox(text) {
  const parts = itemsOf(text);
  if (parts.length === 0) return null;
  const fail = (message, position) => {
    throw new ApiError({ status: 0, code: 'invalid_box', message, position, field: 'box' });
  };
  if (parts.length !== 6 && parts.length !== 4) {
    fail(`the box needs 6 numbers (x0, y0, z0, x1, y1, z1) or, for a curve, 4 (x0, y0, x1, y1), not ${parts.length}`, parts[6]?.position ?? text.length);
  }
  const numbers = parts.map((p) => {
    const v = Number(p.value);
    if (!Number.isFinite(v)) fail(`'${p.value}' is not a number`, p.position);
    return v;
  });
  const n = numbers.length / 2;
  for (let i = 0; i < n; ++i) {
    if (!(numbers[i] < numbers[i + n])) fail(`${'xyz'[i]}0 must be less than ${'xyz'[i]}1`, parts[i + n].position);
  }
  return numbers;
}

// An exact number as the server reads it: a decimal ("-1.5", "1e-3") or a fraction ("3/2").
function exactValue(text) {
  const m = /^([+-]?[0-9.eE+-]+)(?:\/([0-9.eE+-]+))?$/.exec(text);
  if (!m) return NaN;
  const v = Number(m[1]) / (m[2] === undefined ? 1 : Number(m[2]));
  return Number.isFinite(v) ? v : NaN;
}

/// Parses the tolerance (a fraction of the patch box's diagonal); empty gives null (the
/// exact equation). Its range (0, 0.5] is the server's to check (invalid_tolerance).
function parseTolerance(text) {
  const trimmed = text.trim();
  if (!trimmed) return null;
  const value = Number(trimmed);
  if (!Number.isFinite(value)) {
    throw new ApiError({ status: 0, code: 'invalid_tolerance', message: `'${trimmed}' is not a number`, position: text.indexOf(trimmed), field: 'tolerance' });
  }
  return value;
}

/// Parses the parameters field "u, v" (commas or spaces) into the list of names, in
/// order. Only emptiness is checked here: the names themselves are the server's to judge
/// (invalid_parameter, parameter_is_space_variable, unknown_variable), as for every client.
function parseParameters(text) {
  const names = itemValues(text);
  if (names.length === 0) {
    throw new ApiError({ status: 0, code: 'invalid_parameter', message: 'name the parameters, e.g. s, t (a curve: t)', position: 0, field: 'params' });
  }
  return names;
}

// "u₀, u₁, v₀, v₁": the domain's numbers for the parameters `names`.
function domainNames(names) {
  return names.map((n) => `${n}₀, ${n}₁`).join(', ');
}

/// Parses the parameter domain "u0, u1, v0, v1", one interval per parameter of `names`
/// in their order; empty gives null (the server's default domain). The numbers are sent
/// as typed (exact: "-3/2").
function parseDomain(text, names) {
  const parts = itemsOf(text);
  if (parts.length === 0) return null;
  const fail = (message, position) => {
    throw new ApiError({ status: 0, code: 'invalid_domain', message, position, field: 'domain' });
  };
  const parameters = names.length;
  if (parts.length !== 2 * parameters) {
    fail(`the domain needs ${2 * parameters} numbers (${domainNames(names)}), not ${parts.length}`, parts[2 * parameters]?.position ?? text.length);
  }
  const values = parts.map((p) => {
    const v = exactValue(p.value);
    if (Number.isNaN(v)) fail(`'${p.value}' is not a number`, p.position);
    return v;
  });
  for (let i = 0; i < parameters; ++i) {
    if (!(values[2 * i] < values[2 * i + 1])) fail(`${names[i]}₀ must be less than ${names[i]}₁`, parts[2 * i + 1].position);
  }
  return parts.map((p) => p.value);
}

// ---------------------------------------------------------------- errors

function clearErrors() {
  for (const name of FIELDS) {
    const input = ui.inputs[name];
    input.removeAttribute('aria-invalid');
    const box = $(`${name}-error`);
    box.hidden = true;
    box.replaceChildren();
  }
  ui.generalError.hidden = true;
  ui.generalError.replaceChildren();
}

// A two-line excerpt of `text` with the character at `position` marked and a caret
// under it, like a compiler's message; long texts are cut around the position.
function caretExcerpt(text, position) {
  const width = 56;
  let start = Math.max(0, position - Math.floor(width / 2));
  const end = Math.min(text.length, start + width);
  start = Math.max(0, Math.min(start, end - width));
  const prefix = start > 0 ? '…' : '';
  const suffix = end < text.length ? '…' : '';
  const before = text.slice(start, position);
  const at = text.slice(position, position + 1);
  const after = text.slice(position + 1, end);
  const pre = document.createElement('pre');
  pre.className = 'caret';
  pre.setAttribute('aria-hidden', 'true'); // the message says where, for screen readers
  const mark = document.createElement('mark');
  mark.textContent = at || ' ';
  const pointer = document.createElement('span');
  pointer.className = 'pointer';
  pointer.textContent = '^';
  pre.append(prefix + before, mark, after + suffix, '\n', ' '.repeat(prefix.length + before.length), pointer);
  return pre;
}

function errorText(error) {
  const fragment = document.createDocumentFragment();
  const code = document.createElement('span');
  code.className = 'code-name';
  code.textContent = error.code;
  fragment.append(code, ': ', error.message);
  if (error.hint) fragment.append(` — ${error.hint}`);
  // overloaded (503) and too_many_jobs (429) say when to come back.
  if (error.retryAfter) fragment.append(` (retry in ${error.retryAfter} s)`);
  if (Array.isArray(error.details?.generators) && error.details.generators.length) {
    const pre = document.createElement('pre');
    pre.className = 'caret';
    pre.textContent = 'generators of the elimination ideal:\n' + error.details.generators.join('\n');
    fragment.append(pre);
  }
  return fragment;
}

/// Shows `error` (ApiError) beside the input it concerns: `fieldMap` maps the
/// server's field names to this page's inputs. The input is marked invalid, the
/// offending characters are selected in it, and an excerpt with a caret is shown.
function showError(error, fieldMap) {
  // "domain[2]" (one bound) is shown beside the domain input.
  const name = error.field !== null ? fieldMap[error.field] ?? fieldMap[error.field.replace(/\[\d+\]$/, '')] : undefined;
  if (!name) {
    ui.generalError.replaceChildren(errorText(error));
    if (error.field) ui.generalError.append(` (field ${error.field})`);
    ui.generalError.hidden = false;
    return;
  }
  const input = ui.inputs[name];
  const box = $(`${name}-error`);
  input.setAttribute('aria-invalid', 'true');
  box.replaceChildren(errorText(error));
  const text = input.value;
  if (error.position !== null && error.position >= 0 && error.position <= text.length) {
    const where = document.createElement('span');
    where.className = 'sr-only';
    where.textContent = ` (at character ${error.position + 1})`;
    box.append(where, caretExcerpt(text, error.position));
    box.dataset.position = String(error.position);
    input.focus();
    input.setSelectionRange(error.position, Math.min(text.length, error.position + 1));
  } else {
    delete box.dataset.position;
    input.focus();
  }
  box.hidden = false;
}

// ---------------------------------------------------------------- busy state

function setProgress(kind, text) {
  ui.progress.dataset.state = kind;
  ui.progressText.textContent = text;
  if (kind !== 'busy') ui.progressTime.textContent = '';
}

// The label is announced to screen readers (aria-live); the ticking time is not.
function startBusy(label) {
  if (state.busy) {
    clearInterval(state.busy.timer);
    state.busy.controller.abort(); // a new request replaces the running one
  }
  const controller = new AbortController();
  const busy = { controller, started: performance.now(), timer: 0 };
  const tick = () => (ui.progressTime.textContent = `${((performance.now() - busy.started) / 1000).toFixed(1)} s`);
  busy.timer = setInterval(tick, 100);
  // A new step of the request: the previous job's phase and bar no longer apply.
  busy.setLabel = (text) => {
    setProgress('busy', text);
    hideJobProgress();
  };
  // What runJob() needs: the request's signal, and where its job's states go.
  busy.job = { signal: controller.signal, onProgress: (job, feed) => showJobProgress(busy, job, feed) };
  state.busy = busy;
  setProgress('busy', label);
  tick();
  ui.cancel.hidden = false;
  ui.cancel.disabled = false;
  for (const b of ui.submitButtons) b.disabled = true;
  ui.progress.setAttribute('aria-busy', 'true');
  return busy;
}

function endBusy(busy, kind, text) {
  if (state.busy !== busy) return false;
  clearInterval(busy.timer);
  state.busy = null;
  ui.cancel.hidden = true;
  for (const b of ui.submitButtons) b.disabled = false;
  ui.progress.removeAttribute('aria-busy');
  setProgress(kind, text);
  hideJobProgress();
  return true;
}

/// Shows the state `job` of the running request's job (docs/api.md, "Jobs"): its phase
/// and, where the server knows how far it got, a bar (indeterminate otherwise); the
/// elapsed time is the request's own clock. #progress keeps the job's id, status, the
/// road its states came by (`feed`: submit, events, polling) and how many arrived, for
/// scripts and tests.
function showJobProgress(busy, job, feed) {
  if (state.busy !== busy) return; // a state that arrived after its request ended
  const data = ui.progress.dataset;
  const updates = data.job === job.id ? Number(data.jobUpdates) + 1 : 1;
  data.job = job.id;
  data.jobStatus = job.status;
  data.jobFeed = feed;
  data.jobUpdates = String(updates);
  ui.progressPhase.textContent = describeJobProgress(job);
  ui.progressPhase.title = ui.progressPhase.textContent; // whole, where the column cuts it
  showJobBar(busy, job);
  ui.jobBar.hidden = false;
}

// The bar never goes backwards. The server's fraction is the innermost loop's done/total
// (docs/api.md, "Jobs"): the S-pair loop's total grows with the basis, so its fraction
// falls, and a loop that starts again (another prime, another phase) starts from 0. A
// fraction below the highest this job has shown makes the bar indeterminate for the
// rest of that loop; the phase beside it keeps its counts (55/107), which say how far
// it got without pretending to a share of the whole. data-job-bar says which.
function showJobBar(busy, job) {
  const p = job.progress || {};
  if (busy.bar?.job !== job.id) busy.bar = { job: job.id, highest: 0, loop: null, counts: false };
  const bar = busy.bar;
  const loop = `${p.phase}|${p.stage?.phase}|${p.stage?.done}`;
  if (loop !== bar.loop) {
    bar.loop = loop;
    bar.counts = false;
  }
  const fraction = p.fraction;
  if (Number.isFinite(fraction) && fraction < bar.highest) bar.counts = true;
  if (Number.isFinite(fraction) && !bar.counts) {
    ui.jobBar.value = fraction;
    bar.highest = fraction;
    ui.progress.dataset.jobBar = 'fraction';
  } else {
    ui.jobBar.removeAttribute('value'); // indeterminate: no total, or one that moved
    ui.progress.dataset.jobBar = bar.counts ? 'counts' : 'unknown';
  }
}

// "F4 matrix reduction 12/40 · modular Groebner basis (primes): 2": the innermost
// loop reporting with its count where it knows its total, then the outer loop's.
function describeJobProgress(job) {
  const p = job.progress || {};
  let text = p.phase || job.status;
  if (p.total) text += ` ${p.done}/${p.total}`;
  if (p.stage?.phase) text += ` · ${p.stage.phase}: ${p.stage.done}${p.stage.total ? `/${p.stage.total}` : ''}`;
  if (job.cancel_requested) text += ' · cancelling';
  return text;
}

// The bar and the phase off; #progress keeps the last job's id for scripts.
function hideJobProgress() {
  ui.jobBar.hidden = true;
  ui.jobBar.removeAttribute('value');
  ui.progressPhase.textContent = '';
  ui.progressPhase.title = '';
}

ui.cancel.addEventListener('click', () => state.busy && state.busy.controller.abort());
document.addEventListener('keydown', (e) => {
  if (e.key === 'Escape' && state.busy) state.busy.controller.abort();
});
// A job outlives the page that asked for it: leaving the page cancels it (the DELETE
// is sent with keepalive, so it goes out as the page goes away).
window.addEventListener('pagehide', () => state.busy && state.busy.controller.abort());

// ---------------------------------------------------------------- empty states

// What a request replaces is taken off the page when it starts, and stays off, with the
// reason said in its place, when it fails or is cancelled before its own answer
// arrives: nothing on screen ever answers an input other than the one typed.

/// Takes the answer (equation, facts, scripts) off the page and says why there is none:
/// `reason` is "running", "failed" or "cancelled" (data-reason), `text` the sentence.
function clearAnswer(reason, text) {
  ui.result.hidden = true;
  ui.implicit.textContent = '';
  delete ui.implicit.dataset.equation;
  for (const element of [ui.degree, ui.resultMethod, ui.resultTime, ui.verified, ui.resultStats, ui.singular, ui.macaulay2]) {
    element.textContent = '';
  }
  showSubstitution(null);
  state.answered = null;
  ui.resultEmpty.dataset.reason = reason;
  ui.resultEmpty.textContent = text;
  ui.resultEmpty.hidden = false;
}

/// Takes the surface off the preview (the canvas, or the CPU renderer's image without
/// WebGL2), with its GLSL and its approximation line, and says why the stage is empty.
function clearPreview(reason, text) {
  if (preview) {
    preview.clear();
  } else {
    ui.cpuImage.hidden = true;
    if (ui.cpuImage.src) URL.revokeObjectURL(ui.cpuImage.src);
    ui.cpuImage.removeAttribute('src');
  }
  state.drawn = null;
  state.glsl = '';
  state.glslFunction = '';
  ui.glsl.textContent = '';
  ui.glslSummary.textContent = '';
  enableGlslButtons(false);
  ui.stats.textContent = '';
  ui.inputs.box.placeholder = BOX_PLACEHOLDER;
  showApproximation(null);
  hidePreviewError();
  for (const key of ['mode', 'equation', 'request']) delete ui.canvas.dataset[key];
  ui.previewEmpty.dataset.reason = reason;
  ui.previewEmpty.textContent = text;
  ui.previewEmpty.hidden = false;
}

/// Empties what the request `busy` replaces (`scope`: "answer", a new surface, or
/// "preview", the same surface redrawn) and has not yet answered itself, saying why.
function clearReplaced(busy, scope, reason, { answer, picture }) {
  if (scope === 'answer' && !busy.answered) clearAnswer(reason, answer);
  if (!busy.drawn) clearPreview(reason, picture);
}

// ---------------------------------------------------------------- results

// One line on how the answer was computed (the response's stats).
function describeStats(result) {
  const st = result.stats || {};
  const parts = [];
  if (result.method === 'groebner' && st.basis_size) {
    const skipped = (st.product_criterion || 0) + (st.chain_criterion || 0);
    parts.push(`Gröbner basis of ${st.basis_size} polynomials`, `${st.pairs} S-pairs (${skipped} skipped by the criteria)`, `${st.reductions} reductions`);
  } else if (result.method === 'resultant' && st.resultant) {
    const r = st.resultant;
    parts.push(`${r.formulation[0].toUpperCase()}${r.formulation.slice(1)} resultant`, `${r.matrix_size}×${r.matrix_size} matrix`, `${r.primes} prime${r.primes === 1 ? '' : 's'}`);
  }
  if (Number.isFinite(st.verify_ms)) parts.push(`verified in ${formatMs(st.verify_ms)}`);
  return parts.join(' · ');
}

/// Shows the equation `text` in #implicit with lines that end only between its terms:
/// each term (split before a binary + or −) is an inline block, so a line never breaks
/// inside a number or a name (CSS alone breaks anywhere or only at spaces, which the
/// server's equations have none of); a term longer than the line breaks after a '*'
/// (<wbr>). The text content stays `text`, which scripts and tests read.
function showEquation(text) {
  // A + or − after an operand (a name, a number, a ')', spaces allowed), not the sign
  // of an exponent (1e-3).
  const terms = text.split(/(?<=[\w)]\s*)(?<![0-9.][eE])(?=[+-])/);
  ui.implicit.replaceChildren(
    ...terms.map((term) => {
      const span = document.createElement('span');
      span.className = 'term';
      term.split(/(?<=\*)/).forEach((factor, i) => span.append(...(i ? [document.createElement('wbr'), factor] : [factor])));
      return span;
    }),
  );
}

function showParametricResult(result, roundTripMs) {
  const curve = Array.isArray(result.variables) && result.variables.length === 2;
  ui.resultHeading.textContent = curve ? 'Implicit curve' : 'Implicit equation';
  showEquation(`${result.implicit} = 0`);
  ui.implicit.dataset.equation = result.implicit;
  ui.degree.textContent = String(result.degree);
  ui.resultMethod.textContent = result.method === 'groebner' ? 'Gröbner' : result.method;
  ui.resultMethod.title = result.stats?.route ? `route: ${result.stats.route}` : '';
  ui.resultTime.textContent = formatMs(result.elapsed_ms);
  ui.resultTime.title = `${formatMs(result.elapsed_ms)} on the server, ${formatMs(roundTripMs)} round trip`;
  ui.verified.textContent = result.verified ? '✓ yes' : '✗ no';
  ui.verified.className = result.verified ? 'yes' : 'no';
  ui.verified.title = 'the parametrization substituted into the equation in exact arithmetic gives 0';
  ui.resultStats.textContent = describeStats(result);
  ui.resultStats.title = result.stats?.route ? `route: ${result.stats.route}` : '';
  ui.singular.textContent = result.reproduce?.singular || '';
  ui.macaulay2.textContent = result.reproduce?.macaulay2 || '';
  ui.reproduce.hidden = !result.reproduce;
  showSubstitution(result);
  ui.result.hidden = false;
  ui.resultEmpty.hidden = true;
}

/// How the server made a trigonometric or hyperbolic input rational (the answer's
/// `substitution` and `rational_parametrization`, docs/api.md): the formulas
/// (t_u = tan(u/2), e_w = exp(w)) and the rational parametrization the equation was
/// computed from, which the scripts start from. Nothing for a rational input (or null).
function showSubstitution(result) {
  const substitution = result?.substitution;
  const rational = result?.rational_parametrization;
  const shown = Array.isArray(substitution) && substitution.length > 0 && rational;
  ui.substitution.hidden = !shown;
  if (!shown) {
    ui.substitutionFormulas.textContent = '';
    ui.substitutionRational.textContent = '';
    return;
  }
  ui.substitutionFormulas.textContent = substitution.map((s) => s.formula).join(', ');
  ui.substitutionRational.textContent = result.variables.map((c) => `${c} = ${rational[c]}`).join('\n');
}

function showImplicitResult(equation, answer, roundTripMs) {
  ui.resultHeading.textContent = 'Implicit equation (given)';
  showEquation(`${equation} = 0`);
  ui.implicit.dataset.equation = equation;
  ui.degree.textContent = String(answer.degree);
  ui.resultMethod.textContent = 'given';
  ui.resultMethod.title = '';
  ui.resultTime.textContent = formatMs(roundTripMs);
  ui.resultTime.title = 'POST /v1/sdf and the compilation of the shader';
  ui.verified.textContent = '—';
  ui.verified.className = '';
  ui.verified.title = 'nothing to verify: the equation was typed';
  ui.resultStats.textContent = `Distance function ${answer.function} in ${answer.mode} mode.`;
  ui.resultStats.title = '';
  ui.reproduce.hidden = true;
  showSubstitution(null);
  ui.result.hidden = false;
  ui.resultEmpty.hidden = true;
}

/// The lines of `glsl` as an editor counts them: a final newline ends the last line and
/// does not start another. Every line count the page shows is this one, of the GLSL it
/// shows and copies.
function glslLineCount(glsl) {
  if (!glsl) return 0;
  return glsl.split('\n').length - (glsl.endsWith('\n') ? 1 : 0);
}

function showGlsl(answer) {
  state.glsl = answer.glsl;
  state.glslFunction = answer.function;
  ui.glsl.textContent = answer.glsl;
  const lines = glslLineCount(answer.glsl);
  const shape = answer.shape ? ` · ${answer.shape}` : '';
  ui.glslSummary.textContent = `${answer.function}(${answer.dimension === 2 ? 'vec2' : 'vec3'} p) · ${answer.mode} mode${shape} · ${lines} lines`;
  enableGlslButtons(true);
}

// Copy and Download act on the GLSL shown: off while there is none.
function enableGlslButtons(enabled) {
  ui.copyGlsl.disabled = !enabled;
  ui.downloadGlsl.disabled = !enabled;
}

// ---------------------------------------------------------------- preview

const preview = Preview.create(ui.canvas, { onStatus: previewStatus });
ui.canvas.dataset.webgl2 = preview ? 'yes' : 'no';
if (!preview) {
  ui.canvas.hidden = true;
  ui.noWebgl.hidden = false;
  ui.resetView.disabled = true;
  ui.stageHint.hidden = true;
  ui.previewEmpty.classList.add('below'); // under the message that WebGL2 is missing
}

function previewStatus(s) {
  if (s.state === 'compiling') ui.stats.textContent = 'Compiling the shader…';
  else if (s.state === 'rendering') {
    const rung = s.factor > 1 ? `quick picture at 1/${s.factor} of the resolution` : 'full resolution';
    ui.stats.textContent = `Rendering… ${rung}, ${Math.round((s.progress || 0) * 100)}%`;
  } else if (s.state === 'refining') {
    ui.stats.textContent = `Anti-aliasing ${s.aa}×${s.aa}… ${Math.round((s.progress || 0) * 100)}% (the picture is complete; AA refines it)`;
  }
  else if (s.state === 'done') {
    const gpu = shortRenderer(s.renderer);
    ui.stats.textContent = `${s.width}×${s.height} px · AA ${s.aa}×${s.aa} · ${currentMode()} mode · ${formatMs(s.ms)}${gpu ? ' · ' + gpu : ''}`;
    ui.stats.title = s.renderer || '';
  } else if (s.state === 'lost') {
    showContextLost(s.restored);
  } else if (s.state === 'error' && s.message) ui.stats.textContent = s.message;
  else if (s.state === 'empty') ui.stats.textContent = '';
}

// The picture went with the GPU context: said in red on the stage, with what makes the
// shader lighter, and in the status line, which must not keep an earlier "done".
function showContextLost(restored) {
  const what = 'The GPU gave up on this shader (the WebGL context was lost): it costs too much per frame here.';
  const todo = 'A lighter picture: set a tolerance (e.g. 1e-3) for low-degree pieces, or choose Resolution ½ or ¼ and AA 1×1, then draw again.';
  showPreviewError(`${what}\n${restored ? 'The GPU is back. ' : 'Waiting for the GPU to come back… '}${todo}`);
  ui.stats.textContent = restored ? 'GPU context restored: nothing drawn.' : 'GPU context lost.';
  if (!state.busy) setProgress('error', 'No picture: the GPU context was lost.');
  if (restored) state.drawn = null; // a mode switch must not redraw what cost the context
}

function currentMode() {
  return document.querySelector('input[name="mode"]:checked').value;
}

function showPreviewError(message, log) {
  ui.overlay.hidden = false;
  ui.overlay.className = 'stage-overlay error';
  ui.overlay.textContent = log ? `${message}\n${log}` : message;
}

function hidePreviewError() {
  ui.overlay.hidden = true;
  ui.overlay.textContent = '';
}

/// The CPU renderer's image of the same surface, for browsers without WebGL2.
async function drawOnServer(drawn, mode, busy) {
  // As large as the space under the message allows (at most 800×600).
  const rect = ui.noWebgl.getBoundingClientRect();
  const top = ui.noWebgl.querySelector('p').getBoundingClientRect().bottom - rect.top + 14;
  const width = Math.max(64, Math.min(800, Math.round(rect.width - 54)));
  const height = Math.max(64, Math.min(600, Math.round(rect.height - top - 24)));
  const body = { ...requestObject(drawn.source), shape: drawn.shape, box: drawn.answerBox, mode, width, height, aa: Number(ui.aa.value), timeout_ms: 60000 };
  if (drawn.dimension !== 2) {
    const camera = defaultCamera(drawn.answerBox, width / height);
    body.eye = camera.eye;
    body.target = camera.target;
  }
  const blob = await runJob('render', body, busy.job);
  if (ui.cpuImage.src) URL.revokeObjectURL(ui.cpuImage.src);
  ui.cpuImage.src = URL.createObjectURL(blob);
  ui.cpuImage.hidden = false;
}

// The object of a request: {implicit} or {x, y, z?, parameters?, domain?, tolerance?}
// (the wire's field names).
function requestObject(source) {
  if (source.implicit !== undefined) return { implicit: source.implicit };
  const object = { x: source.x, y: source.y };
  if (source.z) object.z = source.z;
  if (source.parameters) object.parameters = source.parameters;
  if (source.domain) object.domain = source.domain;
  if (source.tolerance !== null && source.tolerance !== undefined) object.tolerance = source.tolerance;
  return object;
}

// The server's reason for keeping the exact equation, without its line counts: they
// count the leaf's own function against the pieces' (PolynomialLeaf::glsl_lines), not
// the GLSL the page shows, and beside the one count the page gives they read as three
// disagreeing numbers. A parenthesis holding a count goes, then any clause (between
// colons) still holding one.
function reasonWithoutLineCounts(reason) {
  const count = /\b\d+ lines?\b/;
  return reason
    .replace(/ \([^()]*\b\d+ lines?\b[^()]*\)/g, '')
    .split(': ')
    .filter((clause) => !count.test(clause))
    .join(': ');
}

// Beside the preview: how an approximated patch was built and the bound it reached
// (docs/api.md, "approximation"), or nothing without a tolerance; `lines` is the
// shown GLSL's line count (glslLineCount). The line keeps its height when empty (hiding
// it would resize the canvas, and redraw it). data-reason keeps the server's reason whole.
function showApproximation(a, lines) {
  if (!a) {
    ui.approximation.textContent = '';
    ui.approximation.title = '';
    delete ui.approximation.dataset.bound;
    delete ui.approximation.dataset.reason;
    return;
  }
  const bound = (b) => `${Number(b.bound.toPrecision(2))} (${b.method}${b.method === 'measured' ? ` on ${b.samples} points` : ''})`;
  const size = `degree ${a.degree} × ${a.pieces} piece${a.pieces === 1 ? '' : 's'} · ${lines} GLSL lines`;
  if (a.exact) {
    ui.approximation.dataset.reason = a.reason;
    ui.approximation.textContent = `Tolerance ${a.tolerance}: exact, error 0 — ${reasonWithoutLineCounts(a.reason)} · ${size}`;
  } else {
    delete ui.approximation.dataset.reason;
    ui.approximation.textContent = `Tolerance ${a.tolerance} of the box diagonal: patch → surface ≤ ${bound(a.patch_to_surface)}, ` +
      `surface → patch ≤ ${bound(a.surface_to_patch)} · ${size}`;
  }
  ui.approximation.title = ui.approximation.textContent; // whole, where the line is cut short
  ui.approximation.dataset.bound = String(Math.max(a.patch_to_surface.bound, a.surface_to_patch.bound));
}

/// POST /v1/sdf for `source` ({implicit} or {x, y, z, domain}) in the current mode,
/// shape and box, then compiles it into the preview. A sheet in space also gets its
/// equation F as a signed solid (the side function, preview.js says why). `equation`
/// is F as the page shows it. `busy` is the current request (its label is updated).
/// Throws ApiError, ShaderError or AbortError.
async function drawSurface(source, equation, box, name, busy) {
  busy.setLabel('Building the distance function…');
  const mode = currentMode();
  const shape = ui.shape.value;
  const signal = busy.controller.signal;
  const timeoutMs = Number(ui.timeout.value);
  const answer = await runJob('sdf', sdfRequest({ ...source, shape, mode, box, name, timeoutMs }), busy.job);
  // An answer that arrived as the request was cancelled or replaced is not drawn.
  signal.throwIfAborted();
  const dimension = answer.dimension === 2 ? 2 : 3;
  const answerBox = Array.isArray(answer.box) ? answer.box : box;
  let side = null;
  // An approximation brings its own side function (the signed estimate of its nearest
  // piece): the exact equation would cost what the tolerance is there to avoid.
  const approximated = answer.approximation && !answer.approximation.exact;
  if (answer.shape === 'sheet' && dimension === 3 && approximated && answer.side) {
    side = { glsl: answer.side.glsl, functionName: answer.side.function };
  } else if (answer.shape === 'sheet' && dimension === 3 && !approximated) {
    busy.setLabel('Building the sheet\'s side function…');
    // A scene of one implicit leaf rather than {implicit}: a scene is in space even
    // when F has no z (a cylinder over a curve), where {implicit} would be a plane curve.
    const implicit = answer.leaves?.[0]?.implicit || equation;
    const scene = { type: 'implicit', equation: implicit, shape: 'solid' };
    // A plain POST, not a job: the comment at the top of this file says why.
    const signed = await postJson('/v1/sdf', sdfRequest({ scene, mode: 'fast', box: answerBox, name: `${name}_side`, timeoutMs }), { signal });
    signal.throwIfAborted();
    side = { glsl: signed.glsl, functionName: signed.function };
  }
  showGlsl(answer);
  showApproximation(answer.approximation, glslLineCount(answer.glsl));
  hidePreviewError();
  ui.inputs.box.placeholder = `automatic (now ${answerBox.map((v) => Number(v.toPrecision(6))).join(', ')})`;
  const drawn = { source, equation, box, name, mode, shape, answerBox, dimension };
  if (!preview) {
    busy.setLabel('Rendering on the server…');
    await drawOnServer(drawn, mode, busy);
    showDrawn(busy, drawn);
    return answer;
  }
  // Cancel during the compilation keeps the previous surface on the canvas.
  busy.setLabel('Compiling the shader…');
  const onAbort = () => preview.cancelPending();
  signal.addEventListener('abort', onAbort, { once: true });
  try {
    await preview.setSurface({
      glsl: answer.glsl,
      functionName: answer.function,
      box: answerBox,
      uniforms: answer.uniforms || [],
      dimension,
      shape: answer.shape || 'solid',
      side,
    });
  } finally {
    signal.removeEventListener('abort', onAbort);
  }
  // What the canvas draws from now on (its first image is drawn after this).
  showDrawn(busy, drawn);
  ui.canvas.dataset.mode = mode;
  ui.canvas.dataset.equation = equation;
  // The object as sent, so that the same view can be asked of POST /v1/render.
  ui.canvas.dataset.request = JSON.stringify({ ...requestObject(source), shape });
  return answer;
}

// The request `busy` has put `drawn` on the stage: the stage is no longer empty.
function showDrawn(busy, drawn) {
  state.drawn = drawn;
  busy.drawn = true;
  ui.previewEmpty.hidden = true;
  // What dragging does here (preview.js #attachInput): a curve pans, a surface orbits.
  ui.stageHint.textContent = `${drawn.dimension === 2 ? 'drag to pan' : 'drag to orbit'} · scroll or pinch to zoom · double-click to reset`;
}

function surfaceName() {
  const selected = state.examples.find((e) => e.name === ui.examples.value);
  return selected ? selected.name : 'surface';
}

/// Runs one request: busy state, cancellation, error display. `scope` is what it
/// replaces: "answer" (a new surface: its equation, facts and preview) or "preview" (the
/// same surface in another mode or shape: its picture); that is cleared as it starts and
/// stays cleared, with the reason, if it fails or is cancelled before answering.
async function run(label, body, scope = 'answer') {
  clearErrors();
  const busy = startBusy(label);
  clearReplaced(busy, scope, 'running', {
    answer: `No answer yet: the request is running (${label}).`,
    picture: scope === 'answer' ? 'Nothing to draw yet: the request is running.' : `Redrawing: ${label}`,
  });
  try {
    const summary = await body(busy);
    endBusy(busy, 'done', summary);
    // The mode was switched while this ran, after its distance function was asked for.
    if (state.drawn && (state.drawn.mode !== currentMode() || state.drawn.shape !== ui.shape.value)) redrawInMode();
  } catch (error) {
    if (error.name === 'AbortError') {
      if (state.busy !== busy) return; // replaced by a newer request, which cleared the page
      const seconds = ((performance.now() - busy.started) / 1000).toFixed(1);
      endBusy(busy, 'idle', `Cancelled after ${seconds} s.`);
      clearReplaced(busy, scope, 'cancelled', {
        answer: `No answer: the request was cancelled after ${seconds} s.`,
        picture: `Nothing to draw: the request was cancelled after ${seconds} s.`,
      });
      return;
    }
    if (!endBusy(busy, 'error', 'Failed.')) return;
    const why = error instanceof ApiError ? `${error.code}: ${error.message}` : error instanceof ShaderError ? 'the GPU refused the shader' : error instanceof ContextLostError ? 'the GPU context was lost' : String(error.message || error);
    clearReplaced(busy, scope, 'failed', { answer: `No answer: the request failed (${why}).`, picture: `Nothing to draw: ${why}.` });
    showFailure(error);
  }
}

// What to change when a computation stopped at its time limit: the Limit the page
// sent, then what makes the phase named in the message cheaper.
function timeLimitHint(error) {
  const steps = [];
  if (Number(ui.timeout.value)) steps.push('choose a larger Limit, or none (the job then runs until it is done, with its progress and Cancel)');
  else steps.push("the server's job limit stopped it");
  if (/approximation/.test(error.message)) steps.push('or empty the tolerance for the exact equation, or raise it for fewer pieces');
  else if (/distance function|sdf|glsl/i.test(error.message)) steps.push('or set a tolerance for low-degree pieces');
  else if (ui.method.value !== 'auto') steps.push('or try the Method auto');
  return steps.join('; ');
}

// Shows why a request failed: beside its input, under the inputs, or on the stage.
function showFailure(error) {
  if (error instanceof ApiError) {
    if (error.code === 'time_limit_exceeded' && !error.hint) error.hint = timeLimitHint(error);
    showError(error, error.fieldMap || {});
    setProgress('error', error.status ? `Error ${error.status} · ${error.code}` : `Error · ${error.code}`);
    if (error.status === 0 && error.code === 'network_error') updateServerStatus(false);
  } else if (error instanceof ShaderError) {
    showPreviewError('The GPU refused the shader:', error.log);
    setProgress('error', 'The shader did not compile.');
  } else if (error instanceof ContextLostError) {
    showContextLost(!preview.contextLost);
    setProgress('error', 'No picture: the GPU context was lost.');
  } else {
    ui.generalError.textContent = String(error.message || error);
    ui.generalError.hidden = false;
    console.error(error);
  }
}

// The server's field names -> this page's inputs ("parameters" is the params input).
const PARAMETRIC_FIELDS = { params: 'params', parameters: 'params', x: 'x', y: 'y', z: 'z', domain: 'domain', tolerance: 'tolerance', box: 'box' };

function submitParametric() {
  // Sent as typed (the parser skips spaces), so that error positions index the input.
  const x = ui.inputs.x.value;
  const y = ui.inputs.y.value;
  const z = ui.inputs.z.value.trim() ? ui.inputs.z.value : '';
  const name = surfaceName();
  return run('Implicitizing…', async (busy) => {
    let box, domain, parameters, tolerance = null;
    try {
      parameters = parseParameters(ui.inputs.params.value);
      box = parseBox(ui.inputs.box.value);
      domain = parseDomain(ui.inputs.domain.value, parameters);
      // Surfaces only: a plane curve is always exact.
      if (z) tolerance = parseTolerance(ui.inputs.tolerance.value);
    } catch (e) {
      e.fieldMap = PARAMETRIC_FIELDS;
      throw e;
    }
    const started = performance.now();
    let result;
    try {
      const request = implicitizeRequest({ x, y, z, parameters, method: ui.method.value, timeoutMs: Number(ui.timeout.value) });
      result = await runJob('implicitize', request, busy.job);
    } catch (e) {
      if (e instanceof ApiError) e.fieldMap = PARAMETRIC_FIELDS;
      // A name the field does not list: most likely the field is still s, t.
      if (e.code === 'unknown_variable') e.hint = 'the parameters field lists the names the coordinates may use';
      throw e;
    }
    busy.controller.signal.throwIfAborted(); // cancelled as the answer arrived
    showParametricResult(result, performance.now() - started);
    const source = { x, y, z, parameters, domain, tolerance };
    busy.answered = true;
    state.answered = { source, equation: result.implicit, box, name };
    try {
      // The patch itself (its domain, its shape), not the whole algebraic surface.
      await drawSurface(source, result.implicit, box, name, busy);
    } catch (e) {
      // The equation is fine; its distance function or shader is not.
      if (e instanceof ApiError) e.fieldMap = PARAMETRIC_FIELDS;
      throw e;
    }
    return `Degree ${result.degree} by ${result.method === 'groebner' ? 'Gröbner' : result.method} in ${formatMs(result.elapsed_ms)}${result.verified ? ', verified' : ''}.`;
  });
}

function submitImplicit() {
  const equation = ui.inputs.equation.value;
  const name = surfaceName();
  return run('Building the distance function…', async (busy) => {
    let box;
    try {
      box = parseBox(ui.inputs.box.value);
    } catch (e) {
      e.fieldMap = { box: 'box' };
      throw e;
    }
    const started = performance.now();
    let answer;
    try {
      answer = await drawSurface({ implicit: equation }, equation, box, name, busy);
    } catch (e) {
      if (e instanceof ApiError) e.fieldMap = { implicit: 'equation', box: 'box' };
      throw e;
    }
    showImplicitResult(equation, answer, performance.now() - started);
    busy.answered = true;
    state.answered = { source: { implicit: equation }, equation, box, name };
    return `Distance function of degree ${answer.degree} (${answer.mode} mode, ${answer.shape || 'solid'}).`;
  });
}

// Mode fast/safe: the same surface, the other distance function. A running request
// is not interrupted: it asks for the new mode, or run() redraws when it is done.
function redrawInMode() {
  if (!state.answered || state.busy) return;
  const { source, equation, box, name } = state.answered;
  run('Building the distance function…', async (busy) => {
    try {
      await drawSurface(source, equation, box, name, busy);
    } catch (e) {
      if (e instanceof ApiError) e.fieldMap = source.implicit !== undefined ? { implicit: 'equation', box: 'box' } : PARAMETRIC_FIELDS;
      throw e;
    }
    return `Distance function in ${currentMode()} mode (shape ${ui.shape.value}).`;
  }, 'preview');
}

// ---------------------------------------------------------------- parameters

/// Labels the coordinates x(u,v), y(u,v), z(u,v) and the domain's numbers (u₀, u₁, v₀,
/// v₁) with the names in the parameters field, as typed.
function labelParameters() {
  const names = itemValues(ui.inputs.params.value);
  for (const label of ui.coordinateLabels) {
    label.replaceChildren();
    names.forEach((name, i) => {
      const v = document.createElement('var');
      v.textContent = name;
      label.append(...(i ? [',', v] : [v]));
    });
  }
  ui.domainNames.textContent = domainNames(names);
}

// ---------------------------------------------------------------- tabs, examples

function setMode(mode, { focus = false } = {}) {
  state.mode = mode;
  for (const [name, tab] of Object.entries(ui.tabs)) {
    const selected = name === mode;
    tab.setAttribute('aria-selected', String(selected));
    tab.tabIndex = selected ? 0 : -1;
    ui.forms[name].hidden = !selected;
  }
  $('implicitize').hidden = mode !== 'parametric';
  $('draw').hidden = mode !== 'implicit';
  if (mode === 'implicit' && !ui.inputs.equation.value && ui.implicit.dataset.equation) {
    ui.inputs.equation.value = ui.implicit.dataset.equation;
  }
  // An example's box frames its implicit equation; its patch gets a fitted box.
  const example = state.examples.find((e) => e.name === ui.examples.value);
  if (example && state.boxFromExample) ui.inputs.box.value = exampleBox(example, mode);
  if (focus) ui.tabs[mode].focus();
  document.body.dataset.mode = mode;
}

for (const [name, tab] of Object.entries(ui.tabs)) {
  tab.addEventListener('click', () => setMode(name));
  tab.addEventListener('keydown', (e) => {
    if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
      e.preventDefault();
      setMode(name === 'parametric' ? 'implicit' : 'parametric', { focus: true });
    }
  });
}

// The box input for `example` in tab `mode`: its box for the implicit equation (the
// algebraic surface needs one), empty for the parametric patch (fitted by the server).
function exampleBox(example, mode) {
  return mode === 'implicit' && example.box ? example.box.join(', ') : '';
}

function applyExample(name, { submit = true } = {}) {
  const example = state.examples.find((e) => e.name === name);
  if (!example) return;
  ui.examples.value = name;
  ui.inputs.params.value = (example.parameters || DEFAULT_PARAMETERS).join(', ');
  labelParameters();
  ui.inputs.x.value = example.x;
  ui.inputs.y.value = example.y;
  ui.inputs.z.value = example.z || '';
  ui.inputs.domain.value = (example.domain || []).join(', ');
  if (example.implicit) ui.inputs.equation.value = example.implicit;
  ui.inputs.box.value = exampleBox(example, state.mode);
  state.boxFromExample = true;
  if (submit) submitShown();
}

// Submits the tab shown; an example without an equation of its own is implicitized
// from its parametrization in either tab.
function submitShown() {
  const example = state.examples.find((e) => e.name === ui.examples.value);
  if (state.mode === 'implicit' && (!example || example.implicit)) submitImplicit();
  else submitParametric();
}

ui.examples.addEventListener('change', () => applyExample(ui.examples.value));
// Editing an expression makes it a surface of one's own: the menu says so.
ui.inputs.tolerance.addEventListener('input', () => {
  if (ui.inputs.tolerance.getAttribute('aria-invalid')) {
    ui.inputs.tolerance.removeAttribute('aria-invalid');
    $('tolerance-error').hidden = true;
  }
});
for (const name of ['params', 'x', 'y', 'z', 'domain', 'equation']) {
  ui.inputs[name].addEventListener('input', () => {
    ui.examples.value = '';
    if (ui.inputs[name].getAttribute('aria-invalid')) {
      ui.inputs[name].removeAttribute('aria-invalid');
      $(`${name}-error`).hidden = true;
    }
  });
}
ui.inputs.params.addEventListener('input', labelParameters);
ui.inputs.box.addEventListener('input', () => {
  state.boxFromExample = false;
  ui.inputs.box.removeAttribute('aria-invalid');
  $('box-error').hidden = true;
});
// Enter in the box field submits the visible form.
ui.inputs.box.addEventListener('keydown', (e) => {
  if (e.key === 'Enter') {
    e.preventDefault();
    if (!state.busy) ui.forms[state.mode].requestSubmit();
  }
});

ui.forms.parametric.addEventListener('submit', (e) => {
  e.preventDefault();
  submitParametric();
});
ui.forms.implicit.addEventListener('submit', (e) => {
  e.preventDefault();
  submitImplicit();
});

for (const radio of document.querySelectorAll('input[name="mode"]')) radio.addEventListener('change', redrawInMode);
ui.shape.addEventListener('change', redrawInMode);
ui.aa.addEventListener('change', () => {
  if (preview) preview.setAntialiasing(Number(ui.aa.value));
  else if (state.drawn) run('Rendering on the server…', async (busy) => (await drawOnServer(state.drawn, currentMode(), busy), 'Rendered on the server.'));
});
ui.resolution.addEventListener('change', () => preview && preview.setResolution(Number(ui.resolution.value)));
ui.resetView.addEventListener('click', () => preview && preview.resetView());

// ---------------------------------------------------------------- copying

function toast(text) {
  ui.toast.textContent = text;
  ui.toast.hidden = false;
  clearTimeout(toast.timer);
  toast.timer = setTimeout(() => (ui.toast.hidden = true), 1800);
}

/// Puts `text` on the clipboard: the asynchronous clipboard API where the page is a
/// secure context (loopback counts), else a hidden textarea and execCommand('copy').
async function copyText(text) {
  try {
    if (navigator.clipboard && window.isSecureContext) {
      await navigator.clipboard.writeText(text);
      return true;
    }
  } catch {
    // fall through to the fallback
  }
  const area = document.createElement('textarea');
  area.value = text;
  area.setAttribute('readonly', '');
  area.style.position = 'fixed';
  area.style.opacity = '0';
  document.body.append(area);
  area.select();
  let ok = false;
  try {
    ok = document.execCommand('copy');
  } catch {
    ok = false;
  }
  area.remove();
  return ok;
}

ui.copyGlsl.addEventListener('click', async () => {
  if (!state.glsl) return;
  if (await copyText(state.glsl)) {
    toast('GLSL copied to the clipboard');
    return;
  }
  // No clipboard: show the text selected, ready for Ctrl+C.
  $('glsl-details').open = true;
  window.getSelection().selectAllChildren(ui.glsl);
  toast('Could not copy: the GLSL is selected below');
});

/// Saves `text` as the file `filename` (text/plain): a Blob behind an <a download>,
/// clicked. The address is freed later, not at once: the browser reads the Blob after
/// the click returns.
function downloadText(text, filename) {
  const url = URL.createObjectURL(new Blob([text], { type: 'text/plain' }));
  const link = document.createElement('a');
  link.href = url;
  link.download = filename;
  link.hidden = true;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 60000);
}

// The file is named after the function it holds (NAME_sdf.glsl), what a shader
// that includes it calls.
ui.downloadGlsl.addEventListener('click', () => {
  if (!state.glsl) return;
  const filename = `${state.glslFunction}.glsl`;
  downloadText(state.glsl, filename);
  toast(`GLSL saved as ${filename}`);
});
$('copy-implicit').addEventListener('click', async () => {
  const text = ui.implicit.dataset.equation || '';
  toast((await copyText(text)) ? 'Equation copied' : 'Could not copy');
});
for (const button of document.querySelectorAll('[data-copy]')) {
  button.addEventListener('click', async () => {
    const text = $(button.dataset.copy).textContent;
    toast((await copyText(text)) ? 'Script copied' : 'Could not copy');
  });
}

// ---------------------------------------------------------------- the address

// The address holds the input and the view, so that a copied link draws the same
// surface: the example's name while its fields are as it set them (example=NAME),
// else the fields themselves (params, x, y, z, domain; input=implicit with equation),
// then box, tolerance, mode, shape and aa, and method and timeout where they are not
// the defaults. It follows the user (a submission, a setting, an edited field) by
// history.replaceState: a link is a state to share, not a step to go back to.

const PARAMETRIC_INPUTS = ['params', 'x', 'y', 'z', 'domain'];
const LISTS = ['params', 'domain', 'box']; // written u,v: the items as the parsers see them

/// The address's parameters for what the page shows now (`api` kept as it came).
function addressParameters() {
  const params = new URLSearchParams();
  const api = new URLSearchParams(window.location.search).get('api');
  if (api) params.set('api', api);
  if (state.mode === 'implicit') params.set('input', 'implicit');
  addSurface(params);
  if (state.mode === 'parametric') {
    params.set('tolerance', ui.inputs.tolerance.value.trim()); // empty: the exact equation
    for (const select of [ui.method, ui.timeout]) if (!select.selectedOptions[0]?.defaultSelected) params.set(select.id, select.value);
  }
  params.set('mode', currentMode());
  params.set('shape', ui.shape.value);
  params.set('aa', ui.aa.value);
  return params;
}

// The surface: the example's name while its fields are as it set them, else the tab's
// fields; the box where it is not the example's, or not empty.
function addSurface(params) {
  if (ui.examples.value) {
    params.set('example', ui.examples.value);
    if (!state.boxFromExample) params.set('box', fieldForAddress('box'));
    return;
  }
  for (const name of state.mode === 'implicit' ? ['equation'] : PARAMETRIC_INPUTS) params.set(name, fieldForAddress(name));
  if (ui.inputs.box.value.trim()) params.set('box', fieldForAddress('box'));
}

function fieldForAddress(name) {
  const text = ui.inputs[name].value;
  return LISTS.includes(name) ? itemValues(text).join(',') : text;
}

function fieldFromAddress(name, value) {
  ui.inputs[name].value = LISTS.includes(name) ? itemValues(value).join(', ') : value;
}

// URLSearchParams would write every comma and slash as %2C and %2F: a link of a domain
// "0,1/2,-1,1" and of "2*s/(1+s^2)" stays readable with them as they are (both are
// allowed in a query).
function queryOf(params) {
  const encode = (text) => encodeURIComponent(text).replace(/%2C/g, ',').replace(/%2F/g, '/').replace(/%20/g, '+');
  return [...params].map(([key, value]) => `${key}=${encode(value)}`).join('&');
}

/// Rewrites the address for what the page shows now, without a new history entry.
function writeAddress() {
  const query = queryOf(addressParameters());
  if (query !== window.location.search.slice(1)) history.replaceState(history.state, '', `?${query}${window.location.hash}`);
}

// Selects `value` in `select` if it is one of its options: a value from the address
// that the page does not offer leaves the default.
function chooseOption(select, value) {
  if ([...select.options].some((o) => o.value === value)) select.value = value;
}

// The address's settings (mode, shape, aa, method, timeout, tolerance) onto the page; a
// value the page does not offer is ignored.
function applySettings(params) {
  for (const select of [ui.aa, ui.shape, ui.method, ui.timeout]) chooseOption(select, params.get(select.id));
  const mode = params.get('mode');
  if (mode === 'fast' || mode === 'safe') $(`mode-${mode}`).checked = true;
  if (params.has('tolerance')) ui.inputs.tolerance.value = params.get('tolerance');
  if (preview) preview.setAntialiasing(Number(ui.aa.value));
}

/// Applies the address's settings and returns its surface: {example, input, fields,
/// box}, `fields` the inputs it gives (null: none, an example then, by default the
/// initial one) and `box` null when absent.
function readAddress() {
  const params = new URLSearchParams(window.location.search);
  applySettings(params);
  const input = params.get('input') === 'implicit' ? 'implicit' : 'parametric';
  const names = input === 'implicit' ? ['equation'] : PARAMETRIC_INPUTS;
  const given = names.some((name) => params.has(name));
  // An absent field is empty, but for the parameters: s, t as on a fresh page.
  const absent = (name) => (name === 'params' ? DEFAULT_PARAMETERS.join(',') : '');
  const fields = given ? Object.fromEntries(names.map((name) => [name, params.get(name) ?? absent(name)])) : null;
  const example = params.get('example') ?? (given ? null : INITIAL_EXAMPLE);
  return { example, input, fields, box: params.get('box') };
}

/// Fills the inputs with the address's surface (an example or its fields) and submits
/// it; nothing when the address names an unknown example and gives no fields.
function showAddressed(address) {
  if (state.examples.some((e) => e.name === address.example)) {
    applyExample(address.example, { submit: false });
  } else if (address.fields) {
    for (const [name, value] of Object.entries(address.fields)) fieldFromAddress(name, value);
    labelParameters();
    ui.examples.value = ''; // a surface of one's own
    ui.inputs.box.value = '';
  } else {
    return;
  }
  if (address.box !== null) {
    fieldFromAddress('box', address.box);
    state.boxFromExample = false;
  }
  submitShown();
}

// The user's changes (a field, a menu, a mode; `change` bubbles up to here), tab and
// submission rewrite the address. The page's own filling at the start does not: the
// address it came with stays until the user works.
document.querySelector('main').addEventListener('change', writeAddress);
for (const form of Object.values(ui.forms)) form.addEventListener('submit', writeAddress);
for (const tab of Object.values(ui.tabs)) {
  tab.addEventListener('click', writeAddress);
  tab.addEventListener('keydown', writeAddress);
}

// ---------------------------------------------------------------- start

function updateServerStatus(ok) {
  ui.serverStatus.dataset.state = ok ? 'ok' : 'down';
  ui.serverStatus.querySelector('.text').textContent = ok ? `server ok · ${apiHost}` : `server unreachable · ${apiHost}`;
}

async function start() {
  labelParameters(); // the field may hold what the browser restored
  const address = readAddress();
  setMode(address.input);
  checkHealth().then(updateServerStatus);
  try {
    state.examples = await loadExamples();
    fillExamplesMenu(ui.examples, state.examples);
  } catch (error) {
    ui.generalError.textContent = `Could not load the examples: ${error.message}`;
    ui.generalError.hidden = false;
  }
  showAddressed(address);
  document.body.dataset.ready = 'true';
}

start();
