#!/usr/bin/env python3
"""End-to-end tests of the jobs API (POST /v1/jobs, GET/DELETE /v1/jobs/{id}, its
result and events): the real implicitizer-server on an ephemeral loopback port, real
sockets, a real SQLite file. Usage: jobs_test.py PATH/TO/implicitizer-server
Registered with ctest as server.jobs (server/CMakeLists.txt).

No sleep is a synchronisation: every wait polls the server (or /proc) until a
condition holds, with deadlines generous enough for a loaded 2-core machine."""

import json
import os
import shutil
import signal
import socket
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import LOAD_ALLOWANCE_S, Checks, Server, close_showing_log, error_code, run_tests  # noqa: E402

BIN = sys.argv[1]
CHECKS = Checks()
check = CHECKS.check
failures = CHECKS.failures

# Generous: the longest computation here (cyclic-7) takes seconds alone and may take
# tens of seconds on a loaded machine.
FINISH_DEADLINE_S = 180.0
POLL_S = 0.05


def ideal(name):
    """A named ideal (tests/server/data/jobs_ideals.json, from the Gröbner benchmark's
    list) as a groebner request."""
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "jobs_ideals.json"),
              encoding="utf-8") as f:
        for entry in json.load(f):
            if entry["name"] == name:
                return {"polynomials": entry["polys"], "variables": entry["vars"]}
    raise KeyError(name)


SMALL = {"polynomials": ["x^2+y", "x*y-1"]}
# Long enough to be caught running and cancelled (seconds at least), short enough to
# finish after a restart.
LONG = ideal("cyclic7")
MEDIUM = ideal("katsura6")


def submit(s, kind, request):
    status, headers, body = s.post_json("/v1/jobs", {"kind": kind, "request": request})
    return status, headers, body


def job(s, job_id):
    status, _, data = s.request("GET", "/v1/jobs/" + job_id)
    return status, json.loads(data) if data else None


def wait_for(s, job_id, predicate, deadline_s=FINISH_DEADLINE_S):
    """Polls the job until predicate(state) holds; returns the state (None on timeout)."""
    end = time.monotonic() + deadline_s
    while time.monotonic() < end:
        status, state = job(s, job_id)
        if status == 200 and predicate(state):
            return state
        time.sleep(POLL_S)
    return None


def finished(state):
    return state["status"] in ("done", "failed", "cancelled")


def without_run_details(value):
    """The body without what depends on the run's speed, recursively: its times
    (elapsed_ms, *_ms) and its "stats" (how the work went: the modular route batches
    primes for its threads once a prime takes long enough, which changes its counts of
    primes and reconstructions, not the answer)."""
    if isinstance(value, dict):
        return {k: without_run_details(v) for k, v in value.items() if not k.endswith("_ms") and k != "stats"}
    if isinstance(value, list):
        return [without_run_details(v) for v in value]
    return value


def cpu_ticks(pid):
    """utime + stime of process `pid`, in clock ticks (/proc/PID/stat fields 14 and 15)."""
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return int(fields[11]) + int(fields[12])


# ---- submission, polling, results ---------------------------------------------

def test_done_body_equals_sync_body(s):
    status, headers, body = submit(s, "groebner", SMALL)
    check(status == 202 and body.get("status") in ("queued", "running", "done")
          and headers.get("location") == "/v1/jobs/" + body.get("id", "?"),
          "submit: 202 with id, status and Location: %s %r %r" % (status, headers.get("location"), body))
    state = wait_for(s, body["id"], finished)
    check(state is not None and state["status"] == "done" and state["http_status"] == 200
          and state["progress"]["fraction"] == 1.0, "small job done: %r" % state)
    # The job cached its answer: the synchronous endpoint now answers that very body.
    sync_status, sync_headers, sync_body = s.request("POST", "/v1/groebner", json.dumps(SMALL))
    check(sync_status == 200 and sync_headers.get("x-cache") == "hit", "sync after job hits the cache")
    check(json.loads(sync_body) == state["result"], "job result == sync body: %r vs %r" % (state["result"], sync_body))
    r_status, r_headers, r_body = s.request("GET", state["result_url"])
    check(r_status == 200 and r_body == sync_body and r_headers.get("content-type") == "application/json",
          "GET result: the sync response byte for byte: %s %r" % (r_status, r_body[:200]))


def test_fresh_results_equal_sync(s):
    # Computed by the job (no cache: --cache-size 0), then by the endpoint: equal answers.
    cases = [("implicitize", {"x": "t^2-1", "y": "t^3-t"}, "/v1/implicitize"),
             ("resultant", {"polynomials": ["x^2+t^2-1", "t*y-1"], "variable": "t"}, "/v1/resultant"),
             ("sdf", {"implicit": "x^2+y^2+z^2-1"}, "/v1/sdf"),
             ("groebner", MEDIUM, "/v1/groebner")]
    for kind, request, path in cases:
        status, _, body = submit(s, kind, request)
        check(status == 202, "%s submit: %s %r" % (kind, status, body))
        state = wait_for(s, body["id"], finished)
        sync_status, _, sync_body = s.post_json(path, request)
        check(state is not None and state["http_status"] == sync_status == 200
              and without_run_details(state["result"]) == without_run_details(sync_body),
              "%s: job result equals the endpoint's (times and stats aside): %r vs %r" % (kind, state, sync_body))


def test_render_result_is_the_png(s):
    request = {"implicit": "x^2+y^2+z^2-1", "width": 32, "height": 24}
    status, _, body = submit(s, "render", request)
    state = wait_for(s, body["id"], finished)
    check(state is not None and state["status"] == "done" and "result" not in state,
          "render job done, a PNG is not embedded: %r" % state)
    r_status, r_headers, png = s.request("GET", "/v1/jobs/%s/result" % body["id"])
    sync_status, sync_headers, sync_png = s.request("POST", "/v1/render", json.dumps(request))
    check(r_status == sync_status == 200 and r_headers.get("content-type") == "image/png"
          and png[:8] == b"\x89PNG\r\n\x1a\n" and r_headers.get("x-render-width") == "32",
          "render result is the endpoint's PNG with its headers: %s %r" % (r_status, r_headers))
    check(png == sync_png, "render: the job's PNG equals the endpoint's")


def test_failure_is_the_sync_error(s):
    # Refused while computing, not at decoding: the job fails with the endpoint's error.
    request = {"polynomials": ["x^^2"]}
    status, _, body = submit(s, "groebner", request)
    check(status == 202, "a body that decodes is accepted: %s %r" % (status, body))
    state = wait_for(s, body["id"], finished)
    sync_status, _, sync_body = s.post_json("/v1/groebner", request)
    check(state is not None and state["status"] == "failed" and state["http_status"] == sync_status == 400
          and state["result"] == sync_body, "failed job answers the sync error: %r vs %r" % (state, sync_body))


# ---- bad input ----------------------------------------------------------------

def test_bad_submissions(s):
    status, _, body = s.post_json("/v1/jobs", {"kind": "factorize", "request": {}})
    check(status == 400 and error_code(body) == "unknown_job_kind", "unknown kind: %s %r" % (status, body))
    for wrapper, code in [({"request": {}}, "missing_field"), ({"kind": "groebner"}, "missing_field"),
                          ({"kind": "groebner", "request": [1]}, "wrong_type"),
                          ({"kind": 3, "request": {}}, "wrong_type"),
                          ({"kind": "groebner", "request": {}, "priority": 1}, "unknown_field")]:
        status, _, body = s.post_json("/v1/jobs", wrapper)
        check(status == 400 and error_code(body) == code, "%r: %s %r" % (wrapper, status, body))
    status, _, data = s.request("POST", "/v1/jobs", "{not json")
    check(status == 400 and error_code(json.loads(data)) == "invalid_json", "invalid JSON: %s %r" % (status, data))
    # A body the endpoint refuses at once: the same status and the same error, at submission.
    for kind, request in [("groebner", {"polynomials": "x"}), ("groebner", {}),
                          ("implicitize", {"x": "s", "y": "t", "method": "magic"}),
                          ("resultant", {"polynomials": ["x"], "variable": "t"}),
                          ("render", {"implicit": "x^2+y^2+z^2-1", "width": 100000, "height": 100000}),
                          ("sdf", {"implicit": "x^2", "mode": "exact"})]:
        status, _, body = submit(s, kind, request)
        sync_status, _, sync_body = s.post_json("/v1/" + kind, request)
        check(status == sync_status and status >= 400 and body == sync_body,
              "%s %r: job %s %r, sync %s %r" % (kind, request, status, body, sync_status, sync_body))


def test_unknown_ids(s):
    for method, path in [("GET", "/v1/jobs/0123456789abcdef0123456789abcdef"), ("DELETE", "/v1/jobs/nope"),
                         ("GET", "/v1/jobs/nope/result"), ("GET", "/v1/jobs/nope/events")]:
        status, _, data = s.request(method, path)
        check(status == 404 and error_code(json.loads(data)) == "job_not_found", "%s %s: %s %r" % (method, path, status, data))
    status, headers, _ = s.request("PUT", "/v1/jobs/abc")
    check(status == 405 and "DELETE" in headers.get("allow", ""), "PUT on a job: %s %r" % (status, headers))


def test_ttl_expires_results(binary):
    s = Server(binary, "--job-ttl", "1", "--quiet")
    try:
        status, _, body = submit(s, "groebner", SMALL)
        state = wait_for(s, body["id"], finished)
        check(state is not None and state["status"] == "done", "ttl: job done")
        end = time.monotonic() + 30
        status = 200
        while status == 200 and time.monotonic() < end:
            status, _ = job(s, body["id"])
            time.sleep(POLL_S)
        check(status == 404, "a result older than --job-ttl is gone (404): %s" % status)
    finally:
        s.close()


# ---- cap, cancellation, events ---------------------------------------------------

def test_cap_and_cancel(binary):
    s = Server(binary, "--job-threads", "1", "--max-jobs-per-client", "2", "--retry-after", "7", "--quiet")
    try:
        status, _, first = submit(s, "groebner", LONG)
        status2, _, second = submit(s, "groebner", LONG)
        check(status == status2 == 202, "two jobs accepted: %s %s" % (status, status2))
        status, headers, body = submit(s, "groebner", SMALL)
        check(status == 429 and error_code(body) == "too_many_jobs" and headers.get("retry-after") == "7",
              "third job over the cap: %s %r %r" % (status, headers.get("retry-after"), body))
        # The second waits behind the first: cancelling it frees a place at once.
        status, _, body = s.request("DELETE", "/v1/jobs/" + second["id"])
        state = json.loads(body)
        check(status == 202 and state["status"] == "cancelled", "queued job cancelled at once: %s %r" % (status, state))
        status, _, body = submit(s, "groebner", SMALL)
        check(status == 202, "under the cap again after a cancel: %s %r" % (status, body))
        measure_cancellation(s, first["id"])
        # The small job runs once the long one has stopped.
        state = wait_for(s, body["id"], finished)
        check(state is not None and state["status"] == "done", "the next job runs after a cancel: %r" % state)
        status, _, data = s.request("GET", "/v1/jobs/%s/result" % first["id"])
        check(status == 409 and error_code(json.loads(data)) == "job_cancelled", "a cancelled job has no result")
        status, _, _ = s.request("DELETE", "/v1/jobs/" + first["id"])
        check(status == 204 and job(s, first["id"])[0] == 404, "DELETE of a finished job removes it")
    finally:
        s.close()


def test_cap_per_proxied_client(binary):
    # Behind a proxy every peer is the proxy: --client-ip-header names the client.
    s = Server(binary, "--job-threads", "1", "--max-jobs-per-client", "1", "--client-ip-header", "X-Real-IP",
               "--quiet")
    try:
        body = json.dumps({"kind": "groebner", "request": LONG})
        ids = []
        for client, expected in [("10.0.0.1", 202), ("10.0.0.1", 429), ("10.0.0.2", 202)]:
            status, _, data = s.request("POST", "/v1/jobs", body, {"X-Real-IP": client})
            check(status == expected, "client %s: %s, expected %s" % (client, status, expected))
            if status == 202:
                ids.append(json.loads(data)["id"])
        for job_id in ids:
            s.request("DELETE", "/v1/jobs/" + job_id)
    finally:
        s.close()


def measure_cancellation(s, job_id):
    """Cancels a running job and checks that the server's CPU stops growing within a
    second (plus the load allowance): the computation really stopped."""
    state = wait_for(s, job_id, lambda j: j["status"] == "running" and j["progress"]["phase"] != "running")
    check(state is not None, "the long job runs and reports a phase")
    if state is None:
        return
    check(state["progress"]["fraction"] is None or 0 <= state["progress"]["fraction"] <= 1,
          "fraction in [0, 1]: %r" % state["progress"])
    pid = s.proc.pid
    ticks_per_s = os.sysconf("SC_CLK_TCK")
    window = 0.25
    # First the computation must be seen burning CPU, or a flat CPU afterwards would prove nothing.
    busy = False
    end = time.monotonic() + FINISH_DEADLINE_S
    while not busy and time.monotonic() < end:
        start = cpu_ticks(pid)
        time.sleep(window)
        busy = cpu_ticks(pid) - start >= 5
    check(busy, "the running job uses CPU before it is cancelled")
    before = cpu_ticks(pid)
    deleted = time.monotonic()
    status, _, _ = s.request("DELETE", "/v1/jobs/" + job_id)
    check(status == 202, "DELETE of a running job: %s" % status)
    # The CPU has stopped when half a second adds at most two ticks (the idle threads'
    # wake-ups; a thread that still computes gets far more, even on a loaded machine);
    # the start of the first such half second bounds the stop time from above.
    stopped_at = None
    samples = [(deleted, before)]
    end = deleted + 1 + LOAD_ALLOWANCE_S
    while stopped_at is None and time.monotonic() < end:
        time.sleep(0.05)
        now_t, now_ticks = time.monotonic(), cpu_ticks(pid)
        samples.append((now_t, now_ticks))
        old = [(t, k) for t, k in samples if t <= now_t - 0.5]
        if old and now_ticks - old[-1][1] <= 2:
            stopped_at = old[-1][0]
    last = samples[-1][1]
    check(stopped_at is not None, "CPU stopped growing within 1 s (+%g s load allowance) of DELETE" % LOAD_ALLOWANCE_S)
    if stopped_at is not None:
        print("cancellation: CPU flat %.2f s after DELETE (%.2f CPU-s spent from DELETE to then)"
              % (stopped_at - deleted, (last - before) / ticks_per_s))
    state = wait_for(s, job_id, finished)
    check(state is not None and state["status"] == "cancelled" and state["cancel_requested"] is True,
          "cancelled job's state: %r" % state)


def read_events(port, path, on_event, timeout=FINISH_DEADLINE_S):
    """Reads the SSE stream at `path` until the server closes it; calls on_event(name,
    data) for each event. Returns (status line, headers text, events)."""
    events = []
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as conn:
        conn.sendall(("GET %s HTTP/1.1\r\nHost: x\r\nAccept: text/event-stream\r\n\r\n" % path).encode())
        data = b""
        while b"\r\n\r\n" not in data:
            chunk = conn.recv(4096)
            if not chunk:
                break
            data += chunk
        head, _, rest = data.partition(b"\r\n\r\n")
        buffer = rest.decode()
        while True:
            while "\n\n" in buffer:
                block, buffer = buffer.split("\n\n", 1)
                name, payload = "message", ""
                for line in block.split("\n"):
                    if line.startswith("event: "):
                        name = line[7:]
                    elif line.startswith("data: "):
                        payload += line[6:]
                if payload:
                    events.append((name, json.loads(payload)))
                    on_event(name, events[-1][1])
            chunk = conn.recv(4096)
            if not chunk:
                break
            buffer += chunk.decode()
    lines = head.decode().split("\r\n")
    return lines[0], "\n".join(lines[1:]).lower(), events


def test_events(s):
    status, _, body = submit(s, "groebner", LONG)
    job_id = body["id"]
    cancelled = []

    def cancel_once_progress_is_known(name, data):
        # The stream must show the computation's own progress before it is cancelled.
        if not cancelled and name == "progress" and data["progress"]["phase"] not in ("queued", "running"):
            cancelled.append(s.request("DELETE", "/v1/jobs/" + job_id)[0])

    status_line, headers, events = read_events(s.port, "/v1/jobs/%s/events" % job_id, cancel_once_progress_is_known)
    check(status_line.startswith("HTTP/1.1 200") and "content-type: text/event-stream" in headers,
          "events: 200 text/event-stream: %r %r" % (status_line, headers))
    progress = [d for n, d in events if n == "progress"]
    check(any(d["status"] == "running" and d["progress"]["phase"] not in ("queued", "running") for d in progress),
          "events: progress with the computation's phase: %r" % progress[-3:])
    fractions = [d["progress"]["fraction"] for d in progress if d["progress"]["fraction"] is not None]
    check(all(0 <= f <= 1 for f in fractions), "events: fractions in [0, 1]")
    check(cancelled == [202], "events: the job was cancelled while streaming: %r" % cancelled)
    check(events and events[-1][0] == "end" and events[-1][1]["status"] == "cancelled",
          "events: the last is `end` with the final state: %r" % (events[-1:],))
    # A finished job's stream is its final event alone.
    _, _, events = read_events(s.port, "/v1/jobs/%s/events" % job_id, lambda n, d: None, timeout=30)
    check(len(events) == 1 and events[0][0] == "end", "events of a finished job: one end event: %r" % events)


# ---- the SQLite store ------------------------------------------------------------------

def test_sqlite_keeps_results_and_requeues(binary):
    base = tempfile.mkdtemp(prefix="implicitizer-jobs-")
    path = os.path.join(base, "jobs.sqlite3")
    flags = ("--store", "sqlite:" + path, "--job-threads", "1", "--cache-size", "0", "--quiet")
    s = Server(binary, *flags)
    try:
        _, _, body = submit(s, "groebner", SMALL)
        done = wait_for(s, body["id"], finished)
        check(done is not None and done["status"] == "done", "sqlite: job done")
        check(s.stop() == 0, "sqlite: clean stop")
        s = Server(binary, *flags)
        status, again = job(s, body["id"])
        check(status == 200 and again == done, "sqlite: the result survives a restart: %r vs %r" % (again, done))
        # A job running and one queued behind it when the process is killed (-9)...
        _, _, running = submit(s, "groebner", LONG)
        _, _, queued = submit(s, "groebner", MEDIUM)
        state = wait_for(s, running["id"], lambda j: j["status"] == "running")
        check(state is not None and job(s, queued["id"])[1]["status"] == "queued", "sqlite: one running, one queued")
        s.proc.send_signal(signal.SIGKILL)
        s.proc.wait()
        # ...are queued again by the next process and finish there.
        s = Server(binary, *flags)
        for job_id in (running["id"], queued["id"]):
            state = wait_for(s, job_id, finished)
            check(state is not None and state["status"] == "done" and state["http_status"] == 200
                  and len(state["result"]["basis"]) > 0, "sqlite: requeued job %s finished: %r" % (job_id, state))
    finally:
        close_showing_log(s, CHECKS)
        shutil.rmtree(base, ignore_errors=True)


def rss_mib(pid):
    """The resident memory of process `pid` in MiB (VmRSS of /proc/PID/status)."""
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return 0.0


# A groebner request of about 1 MB that the submission accepts (its shape is right)
# and the job fails at once (the expression does not parse).
FAILING_1MB = {"polynomials": ["x" + " " * 1_000_000 + "+"]}


def test_finished_jobs_are_bounded(binary):
    # Issue 41: one client posting 1 MB requests that fail at once grew the server by
    # its requests (519 jobs: 11 to 513 MB), each kept --job-ttl.
    cap, jobs = 60, 120
    s = Server(binary, "--job-threads", "1", "--cache-size", "0", "--max-finished-jobs-per-client", str(cap),
               "--quiet")
    try:
        ids, before = [], rss_mib(s.proc.pid)
        for _ in range(jobs):
            status, _, body = submit(s, "groebner", FAILING_1MB)
            check(status == 202, "a 1 MB job is accepted: %s %r" % (status, body))
            if status != 202:
                return
            ids.append(body["id"])
            state = wait_for(s, body["id"], finished)
            check(state is not None and state["status"] == "failed", "the 1 MB job fails: %r" % state)
        after = rss_mib(s.proc.pid)
        kept = [job_id for job_id in ids if job(s, job_id)[0] == 200]
        check(kept == ids[-cap:], "the %d newest finished jobs are kept, the older evicted: %d kept, newest %s"
              % (cap, len(kept), kept == ids[-len(kept):]))
        # Kept with their requests (or their buffers), the 60 kept would hold 60 MB and
        # all 120 without a cap 120 MB; a finished job keeps none (16 MiB measured).
        check(after - before < 50, "RSS grew %.0f MiB over %d finished 1 MB jobs" % (after - before, jobs))
        print("bounded jobs: %d failing 1 MB jobs, %d kept, RSS %.0f -> %.0f MiB" % (jobs, len(kept), before, after))
    finally:
        close_showing_log(s, CHECKS)


def test_storage_full_names_the_cap(binary):
    # Only queued and running requests can fill the store: past the byte cap a
    # submission is refused, naming the cap and its flag.
    s = Server(binary, "--job-threads", "1", "--max-job-bytes-per-client", "1000000", "--retry-after", "3", "--quiet")
    try:
        _, _, running = submit(s, "groebner", LONG)
        state = wait_for(s, running["id"], lambda j: j["status"] == "running")
        check(state is not None, "storage: the long job runs")
        big = {"polynomials": ["x" + " " * 600_000 + "+y"]}
        status, _, queued = submit(s, "groebner", big)
        check(status == 202, "storage: 600 kB queued: %s %r" % (status, queued))
        status, headers, body = submit(s, "groebner", big)
        check(status == 507 and error_code(body) == "job_storage_full" and headers.get("retry-after") == "3"
              and "--max-job-bytes-per-client" in body["error"]["message"] and "1000000" in body["error"]["message"],
              "storage: a second 600 kB queued request passes the cap: %s %r" % (status, body))
        status, _, body = submit(s, "groebner", SMALL)
        check(status == 202, "storage: a small one still fits: %s %r" % (status, body))
        for job_id in (queued["id"], body["id"], running["id"]):
            s.request("DELETE", "/v1/jobs/" + job_id)
    finally:
        close_showing_log(s, CHECKS)


def test_sqlite_second_server_is_refused(binary):
    # Issue 41: a second server on the file requeued the first one's running job and
    # claimed it: both ran it.
    import subprocess
    base = tempfile.mkdtemp(prefix="implicitizer-jobs-")
    path = os.path.join(base, "jobs.sqlite3")
    s = Server(binary, "--store", "sqlite:" + path, "--job-threads", "1", "--quiet")
    try:
        _, _, running = submit(s, "groebner", LONG)
        state = wait_for(s, running["id"], lambda j: j["status"] == "running")
        check(state is not None, "sqlite owner: the job runs")
        try:
            second = subprocess.run([binary, "--port", "0", "--store", "sqlite:" + path, "--quiet"],
                                    capture_output=True, text=True, timeout=60)
            check(second.returncode == 1 and path in second.stderr and ("pid %d" % s.proc.pid) in second.stderr,
                  "a second server on the file exits 1 naming the file and the owner: %s %r"
                  % (second.returncode, second.stderr))
        except subprocess.TimeoutExpired:
            check(False, "a second server on the file started")
        status, state = job(s, running["id"])
        check(status == 200 and state["status"] == "running", "the owner still runs its job: %r" % state)
        s.request("DELETE", "/v1/jobs/" + running["id"])
    finally:
        close_showing_log(s, CHECKS)
        shutil.rmtree(base, ignore_errors=True)


def test_sqlite_deleted_file_is_503(binary):
    # Issue 41: deleting the file and its -wal/-shm went unnoticed until a restart lost every job.
    base = tempfile.mkdtemp(prefix="implicitizer-jobs-")
    path = os.path.join(base, "jobs.sqlite3")
    s = Server(binary, "--store", "sqlite:" + path, "--job-threads", "1", "--retry-after", "2")
    try:
        _, _, body = submit(s, "groebner", SMALL)
        check(wait_for(s, body["id"], finished) is not None, "sqlite delete: the job finished")
        for suffix in ("", "-wal", "-shm"):
            if os.path.exists(path + suffix):
                os.unlink(path + suffix)
        status, headers, data = s.request("GET", "/v1/jobs/" + body["id"])
        check(status == 503 and error_code(json.loads(data)) == "job_store_unavailable"
              and headers.get("retry-after") == "2", "a deleted store answers 503: %s %r" % (status, data))
        status, _, data = submit(s, "groebner", SMALL)
        check(status == 503 and error_code(data) == "job_store_unavailable", "and refuses jobs: %s %r" % (status, data))
        check("was deleted or replaced" in s.log_text(), "the log says the file went")
        # The job threads' claims fail once a second from now on: their log names the
        # store, once, and counts the repeats instead of writing each.
        def claim_lines():
            return [line for line in s.log_text().splitlines()
                    if line.startswith("implicitizer-server: job threads: SQLite job store " + path)
                    and "was deleted or replaced" in line]
        end = time.monotonic() + FINISH_DEADLINE_S
        while not claim_lines() and time.monotonic() < end:
            time.sleep(0.05)
        time.sleep(3.5)  # room for three more claims to fail (fewer on a slow machine)
        check(len(claim_lines()) == 1, "the job threads log the lost file once: %r" % claim_lines())
    finally:
        close_showing_log(s, CHECKS)
        shutil.rmtree(base, ignore_errors=True)


def test_bad_store_flag(binary):
    import subprocess
    result = subprocess.run([binary, "--store", "redis"], capture_output=True, text=True, timeout=30)
    check(result.returncode == 2 and "--store" in result.stderr, "--store redis is a usage error: %r" % result.stderr)
    result = subprocess.run([binary, "--port", "0", "--store", "sqlite:/nonexistent-dir/x.sqlite3"],
                            capture_output=True, text=True, timeout=30)
    check(result.returncode == 1 and "job store" in result.stderr,
          "an unopenable SQLite file stops the start: %s %r" % (result.returncode, result.stderr))


def main():
    s = Server(BIN, "--threads", "2", "--job-threads", "1", "--quiet")
    fresh = Server(BIN, "--threads", "2", "--job-threads", "1", "--cache-size", "0", "--quiet")
    tests = [
        lambda: test_done_body_equals_sync_body(s),
        lambda: test_fresh_results_equal_sync(fresh),
        lambda: test_render_result_is_the_png(fresh),
        lambda: test_failure_is_the_sync_error(fresh),
        lambda: test_bad_submissions(s),
        lambda: test_unknown_ids(s),
        lambda: test_events(s),
        lambda: test_ttl_expires_results(BIN),
        lambda: test_cap_and_cancel(BIN),
        lambda: test_cap_per_proxied_client(BIN),
        lambda: test_sqlite_keeps_results_and_requeues(BIN),
        lambda: test_finished_jobs_are_bounded(BIN),
        lambda: test_storage_full_names_the_cap(BIN),
        lambda: test_sqlite_second_server_is_refused(BIN),
        lambda: test_sqlite_deleted_file_is_503(BIN),
        lambda: test_bad_store_flag(BIN),
    ]
    try:
        run_tests(CHECKS, tests)
        check(s.proc.poll() is None and fresh.proc.poll() is None, "the servers survived everything")
        check(s.stop() == 0 and fresh.stop() == 0, "the servers exit 0 on SIGTERM")
    finally:
        close_showing_log(s, CHECKS)
        fresh.close()
    print(CHECKS.summary())
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
