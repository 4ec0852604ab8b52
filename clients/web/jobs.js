// The page's computations as jobs (docs/api.md, "Jobs"): POST /v1/jobs, then the job
// followed to its end through its Server-Sent Events (GET /v1/jobs/{id}/events), or,
// when that stream cannot be had or drops, by polling GET /v1/jobs/{id} with back-off.
// Cancelling (the caller's AbortSignal) sends DELETE /v1/jobs/{id}: a job outlives
// the connection that asked for it, so closing a connection no longer stops it.
// The answer is what the synchronous endpoint would have answered: its JSON, its
// PNG, or its error as an ApiError with the endpoint's own status and code.
import { ApiError, apiErrorFrom, cancelJob, getBlob, getJob, openJobEvents, submitJob } from './api.js';

const FINISHED = new Set(['done', 'failed', 'cancelled']);

// Polling, when the events cannot be had: the first look soon (most jobs the page
// asks for end within a second), then less and less often, since a job that has run
// for a while will run a while longer.
const POLL_FIRST_MS = 250;
const POLL_MAX_MS = 4000;
// Consecutive failed polls (the server unreachable or overloaded) before the page
// gives up with the last error: bounded, so a dead server never leaves it waiting.
const POLL_FAILURES_MAX = 5;

/// Whether the job state `job` is final (done, failed or cancelled).
export function isFinished(job) {
  return FINISHED.has(job.status);
}

/// Runs `request` (the body of the endpoint `kind`: implicitize, sdf, render, ...) as
/// a job and returns the endpoint's answer: its decoded JSON, or for a render the PNG
/// as a Blob. `onProgress(job, feed)` gets each state the server sends (`feed`:
/// "submit", "events" or "polling"). Aborting `signal` cancels the job on the server
/// and rejects at once with the DOMException "AbortError". Rejects with ApiError for
/// a refused submission, a failed job (the endpoint's error), an unknown job, or a
/// server that stopped answering.
export async function runJob(kind, request, { signal, onProgress = () => {} }) {
  // Submitted without the signal: an abort during the POST would leave a job whose id
  // the page never learned running on the server; it is cancelled just below instead.
  const submitted = await submitJob(kind, request);
  const cancel = () => cancelJob(submitted.id).catch((e) => console.warn(`DELETE of job ${submitted.id} failed: ${e.message}`));
  if (signal.aborted) {
    cancel();
    signal.throwIfAborted();
  }
  signal.addEventListener('abort', cancel, { once: true });
  try {
    onProgress(submitted, 'submit');
    const final = isFinished(submitted) ? submitted : await followJob(submitted.id, signal, onProgress);
    return await answerOf(final, signal);
  } finally {
    signal.removeEventListener('abort', cancel);
  }
}

// The final state of job `id`: from its events while they last, then by polling.
async function followJob(id, signal, onProgress) {
  const final = await followEvents(id, signal, onProgress);
  return final || pollJob(id, signal, onProgress);
}

/// Follows job `id` through its event stream: resolves to the final state from the
/// `end` event, or to null when the stream failed or ended before the job did (the
/// stream's own time limit), so that the caller polls instead. EventSource would
/// reconnect by itself after an error, and after the server closes the stream at its
/// end; it is closed at once in both cases, since the job's state is what matters.
function followEvents(id, signal, onProgress) {
  return new Promise((resolve, reject) => {
    const source = openJobEvents(id);
    const finish = (settle, value) => {
      source.close();
      signal.removeEventListener('abort', onAbort);
      settle(value);
    };
    const onAbort = () => finish(reject, signal.reason);
    signal.addEventListener('abort', onAbort, { once: true });
    source.addEventListener('progress', (e) => onProgress(JSON.parse(e.data), 'events'));
    source.addEventListener('end', (e) => {
      const data = JSON.parse(e.data);
      if (data.error) return finish(reject, endError(data));
      onProgress(data, 'events');
      finish(resolve, isFinished(data) ? data : null);
    });
    source.addEventListener('error', () => finish(resolve, null));
  });
}

// The error an `end` event carries instead of a state: the job is unknown (expired or
// removed), or the store cannot answer, as GET /v1/jobs/{id} would have said.
function endError(data) {
  return apiErrorFrom(data.error.code === 'job_not_found' ? 404 : 503, data);
}

/// Polls GET /v1/jobs/{id} until the job is finished, waiting POLL_FIRST_MS, then twice
/// as long each time up to POLL_MAX_MS. A network error or a 502/503/504 is retried
/// (POLL_FAILURES_MAX in a row at most); any other error (404: the job is gone) ends it.
async function pollJob(id, signal, onProgress) {
  let delay = POLL_FIRST_MS;
  let failures = 0;
  for (;;) {
    await sleep(delay, signal);
    delay = Math.min(2 * delay, POLL_MAX_MS);
    let job;
    try {
      job = await getJob(id, { signal });
    } catch (e) {
      if (!isTransient(e) || ++failures >= POLL_FAILURES_MAX) throw e;
      continue;
    }
    failures = 0;
    onProgress(job, 'polling');
    if (isFinished(job)) return job;
  }
}

function isTransient(error) {
  return error instanceof ApiError && [0, 502, 503, 504].includes(error.status);
}

// Resolves after `ms`, or rejects with the signal's reason when it is aborted first.
function sleep(ms, signal) {
  signal.throwIfAborted();
  return new Promise((resolve, reject) => {
    const onAbort = () => {
      clearTimeout(timer);
      reject(signal.reason);
    };
    const timer = setTimeout(() => {
      signal.removeEventListener('abort', onAbort);
      resolve();
    }, ms);
    signal.addEventListener('abort', onAbort, { once: true });
  });
}

/// What the synchronous endpoint would have answered, from the final state `job`: its
/// JSON (`result`), or its body fetched from `result_url` when it is not JSON (a PNG);
/// a failed job's error as the ApiError the endpoint's answer would have made.
async function answerOf(job, signal) {
  if (job.status === 'cancelled') {
    // Not this page's Cancel (that rejected already): another client, or the server
    // shutting down.
    throw new ApiError({ status: 409, code: 'job_cancelled', message: `job ${job.id} was cancelled on the server` });
  }
  const status = job.http_status || 0;
  if (status >= 400 || job.status === 'failed') throw apiErrorFrom(status, job.result || null);
  if (job.result) return job.result;
  return getBlob(job.result_url, { signal });
}
