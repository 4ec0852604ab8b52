#!/usr/bin/env python3
"""A bounded load test of job submission and polling: CLIENTS threads, each a client
of its own (X-Real-IP with --client-ip-header), submit JOBS_PER_CLIENT small distinct
Gröbner jobs as fast as the per-client cap lets them (a 429 waits for its Retry-After
and retries), poll each until done, and check every result. Prints the throughput and
the latencies; asserts only correctness (no speed: CI machines differ).
Usage: jobs_load_test.py PATH/TO/implicitizer-server [CLIENTS JOBS_PER_CLIENT [STORE]]
(STORE: a --store value; a sqlite:PATH file is removed first and after).
Registered with ctest as server.jobs_load (8 clients, 200 jobs each, in memory)."""

import http.client
import json
import os
import sys
import threading
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Checks, Server  # noqa: E402

CHECKS = Checks()
check = CHECKS.check
CAP = 8


def exchange(conn, method, path, body=None, headers=None):
    conn.request(method, path, body=body, headers=headers or {})
    response = conn.getresponse()
    return response.status, response.getheader("Retry-After"), response.read()


def run_client(port, client, jobs, out):
    """Submits `jobs` jobs as client `client`, keeping at most CAP unfinished; records
    (submit-to-done seconds, polls) per job and every wrong answer."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=120)
    header = {"X-Real-IP": client}
    pending, latencies, errors, rejected, polls = {}, [], [], 0, 0
    next_k = 0
    while next_k < jobs or pending:
        while next_k < jobs and len(pending) < CAP:
            # x^2 - k, y - x: the basis is [x^2 - k, y - x] in lex... distinct for each k.
            k = "%s%d" % (client.replace(".", ""), next_k)
            body = json.dumps({"kind": "groebner", "request": {"polynomials": ["x^2-%s" % k, "y-x"],
                                                                "order": "lex"}})
            status, retry_after, data = exchange(conn, "POST", "/v1/jobs", body, header)
            if status == 429:
                rejected += 1
                break  # the cap: poll what is pending first
            if status != 202:
                errors.append("submit %s: %s %r" % (k, status, data[:200]))
                next_k += 1
                continue
            pending[json.loads(data)["id"]] = (k, time.monotonic())
            next_k += 1
        for job_id, (k, started) in list(pending.items()):
            status, _, data = exchange(conn, "GET", "/v1/jobs/" + job_id)
            polls += 1
            state = json.loads(data)
            if state.get("status") in ("done", "failed", "cancelled"):
                del pending[job_id]
                latencies.append(time.monotonic() - started)
                if state.get("status") != "done" or state["result"]["basis"] != ["y^2-%s" % k, "x-y"]:
                    errors.append("job %s: %r" % (k, state))
        if pending:
            time.sleep(0.005)
    conn.close()
    out[client] = (latencies, errors, rejected, polls)


def main():
    binary = sys.argv[1]
    clients = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    per_client = int(sys.argv[3]) if len(sys.argv) > 3 else 200
    store = sys.argv[4] if len(sys.argv) > 4 else "memory"
    sqlite_path = store[len("sqlite:"):] if store.startswith("sqlite:") else None
    if sqlite_path and os.path.exists(sqlite_path):
        os.unlink(sqlite_path)
    s = Server(binary, "--job-threads", "1", "--max-jobs-per-client", str(CAP), "--client-ip-header", "X-Real-IP",
               "--store", store, "--quiet")
    try:
        out = {}
        started = time.monotonic()
        threads = [threading.Thread(target=run_client, args=(s.port, "10.0.0.%d" % (i + 1), per_client, out))
                   for i in range(clients)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(600)
        elapsed = time.monotonic() - started
        check(len(out) == clients, "every client finished: %d of %d" % (len(out), clients))
        latencies = sorted(x for lat, _, _, _ in out.values() for x in lat)
        errors = [e for _, errs, _, _ in out.values() for e in errs]
        rejected = sum(r for _, _, r, _ in out.values())
        polls = sum(p for _, _, _, p in out.values())
        check(not errors, "every job answered right: %r" % errors[:5])
        check(len(latencies) == clients * per_client, "%d of %d jobs done" % (len(latencies), clients * per_client))
        if latencies:
            print("jobs_load (%s): %d clients x %d jobs (cap %d each): %.1f jobs/s over %.1f s; submit-to-done "
                  "median %.0f ms, p95 %.0f ms; %d polls, %d submissions answered 429"
                  % (store, clients, per_client, CAP, len(latencies) / elapsed, elapsed,
                     1000 * latencies[len(latencies) // 2], 1000 * latencies[int(len(latencies) * 0.95)],
                     polls, rejected))
        check(s.proc.poll() is None, "the server survived")
    finally:
        s.close()
        for suffix in ("", "-wal", "-shm"):
            if sqlite_path and os.path.exists(sqlite_path + suffix):
                os.unlink(sqlite_path + suffix)
    print(CHECKS.summary())
    return 1 if CHECKS.failures else 0


if __name__ == "__main__":
    sys.exit(main())
