#!/usr/bin/env python3
"""Two replicas sharing one Redis (`--store redis://HOST:PORT`): a real redis-server on a
loopback port, two real implicitizer-server processes. One queue and one result store:
a job submitted to one replica is read, cancelled and finished through the other; a
replica killed (-9) while it runs a job loses nothing: the other takes the job over
when its lease expires and finishes it.
Usage: jobs_redis_test.py PATH/TO/implicitizer-server PATH/TO/redis-server
Exits 77 (skipped) when no redis-server is given. Registered as server.jobs_redis."""

import json
import os
import signal
import socket
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Checks, Redis, Server, error_code, run_tests  # noqa: E402
from jobs_test import FINISH_DEADLINE_S, LONG, MEDIUM, SMALL, cpu_ticks, finished, job, submit, wait_for  # noqa: E402

CHECKS = Checks()
check = CHECKS.check
LEASE_S = 2


def replica(binary, redis):
    return Server(binary, "--store", "redis://127.0.0.1:%d" % redis.port, "--job-lease-seconds", str(LEASE_S),
                  "--job-threads", "1", "--quiet")


def busy(pid, window=0.5):
    """Whether process `pid` burns CPU over `window` seconds: at least 3 ticks (30 ms),
    which a computing replica gets even on a machine loaded several times over, and
    an idle one (a claim poll a second) does not spend."""
    start = cpu_ticks(pid)
    time.sleep(window)
    return cpu_ticks(pid) - start >= 3


def test_shared_results(a, b):
    _, _, body = submit(a, "groebner", SMALL)
    state = wait_for(b, body["id"], finished)
    check(state is not None and state["status"] == "done" and state["result"]["basis"] == ["y^2+x", "x*y-1", "x^2+y"],
          "a job submitted to A is finished and read through B: %r" % state)
    status, _, data = b.request("GET", "/v1/jobs/%s/result" % body["id"])
    check(status == 200 and b"basis" in data, "its result through B: %s" % status)


def test_shared_result_cache(redis, a, b):
    """A synchronous answer computed on A is a cache hit on B."""
    request = {"polynomials": ["x^3-y", "y^2-x*z", "z^2-x"], "order": "lex"}
    stored = redis.count_keys("implicitizer:cache:*")
    status_a, headers_a, body_a = a.request("POST", "/v1/groebner", json.dumps(request))
    # A stores its answer after sending it, on the tier's own thread: B asks once it is there.
    end = time.monotonic() + FINISH_DEADLINE_S
    while redis.count_keys("implicitizer:cache:*") == stored and time.monotonic() < end:
        time.sleep(0.01)
    # A lookup waits 30 ms for Redis before it counts as a miss (B then computes the
    # answer itself), which a loaded machine may pass once: a few tries.
    for attempt in range(1, 6):
        status_b, headers_b, body_b = b.request("POST", "/v1/groebner", json.dumps(request))
        if headers_b.get("x-cache") == "hit":
            break
    check(status_a == status_b == 200 and headers_a.get("x-cache") == "miss" and headers_b.get("x-cache") == "hit"
          and body_a == body_b, "the result cache is shared: A %s %s, B %s %s (try %d)" % (
              status_a, headers_a.get("x-cache"), status_b, headers_b.get("x-cache"), attempt))


def test_cap_across_replicas(a, b):
    """The per-client cap counts the jobs a client has on every replica."""
    cap = 16  # the replicas' default --max-jobs-per-client
    ids = []
    for i in range(cap):
        status, _, body = submit(a if i % 2 else b, "groebner", LONG)
        check(status == 202, "job %d of the cap accepted: %s %r" % (i, status, body))
        if status == 202:
            ids.append(body["id"])
    status_a, headers, body = submit(a, "groebner", LONG)
    status_b, _, _ = submit(b, "groebner", LONG)
    check(status_a == status_b == 429 and headers.get("retry-after"), "over the cap on both replicas: %s %s"
          % (status_a, status_b))
    for job_id in ids:
        a.request("DELETE", "/v1/jobs/" + job_id)
    for job_id in ids:
        check(wait_for(b, job_id, finished) is not None, "job %s cancelled" % job_id)


def test_cancel_through_the_other_replica(binary, redis, a, servers):
    """A runs the job (B is started only once A has claimed it, and added to
    `servers`); B shows its progress and cancels it."""
    _, _, body = submit(a, "groebner", LONG)
    running = wait_for(a, body["id"], lambda j: j["status"] == "running")
    check(running is not None, "A runs the long job")
    b = replica(binary, redis)
    servers.append(b)
    seen = wait_for(b, body["id"], lambda j: j["progress"]["phase"] not in ("queued", "running"))
    check(seen is not None and seen["status"] == "running",
          "B shows the progress A publishes: %r" % (seen and seen["progress"]))
    status, _, _ = b.request("DELETE", "/v1/jobs/" + body["id"])
    check(status == 202, "DELETE through B: %s" % status)
    state = wait_for(b, body["id"], finished)
    check(state is not None and state["status"] == "cancelled", "cancelled on A from B: %r" % state)
    # A's CPU goes flat: the computation stopped there.
    end = time.monotonic() + FINISH_DEADLINE_S
    while busy(a.proc.pid) and time.monotonic() < end:
        pass
    check(not busy(a.proc.pid), "A stopped computing")


def test_kill_9_takeover(a, b):
    _, _, long_job = submit(a, "groebner", LONG)
    _, _, medium_job = submit(a, "groebner", MEDIUM)
    check(wait_for(a, long_job["id"], lambda j: j["status"] == "running") is not None, "the long job runs")
    # The replica that runs it is the one burning CPU once the medium job is done.
    check(wait_for(a, medium_job["id"], finished) is not None, "the medium job finishes")
    runner = None
    end = time.monotonic() + FINISH_DEADLINE_S
    while runner is None and time.monotonic() < end:
        runner = a if busy(a.proc.pid) else b if busy(b.proc.pid) else None
    check(runner is not None, "one replica computes the long job")
    if runner is None:
        return
    survivor = b if runner is a else a
    runner.proc.send_signal(signal.SIGKILL)
    runner.proc.wait()
    killed_at = time.monotonic()
    state = wait_for(survivor, long_job["id"], finished)
    check(state is not None and state["status"] == "done" and state["http_status"] == 200
          and len(state["result"]["basis"]) > 0, "the survivor finished the dead replica's job: %r" % state)
    taken_over = wait_for(survivor, medium_job["id"], finished)
    check(taken_over is not None and taken_over["status"] == "done", "nothing else was lost")
    if state is not None:
        print("kill -9 takeover: done %.1f s after the kill (lease %d s)" % (time.monotonic() - killed_at, LEASE_S))


def redis_keys(redis, pattern):
    """The keys of `redis` matching `pattern` (KEYS over RESP)."""
    with socket.create_connection(("127.0.0.1", redis.port), timeout=30) as c:
        c.sendall(("*2\r\n$4\r\nKEYS\r\n$%d\r\n%s\r\n" % (len(pattern), pattern)).encode())
        data = b""
        while True:
            chunk = c.recv(65536)
            data += chunk
            lines = data.split(b"\r\n")
            if chunk == b"" or (lines[0].startswith(b"*") and len(lines) >= 2 * int(lines[0][1:]) + 2):
                break
    lines = data.split(b"\r\n")
    return [lines[2 + 2 * i].decode() for i in range(int(lines[0][1:]))]


def test_storage_bounded(binary, redis_binary):
    """Issue 41 with a shared store: finished jobs past the per-client cap are evicted
    from Redis itself (through either replica), and queued requests past the byte
    cap are refused with 507."""
    redis = Redis(redis_binary)
    flags = ("--store", "redis://127.0.0.1:%d" % redis.port, "--job-threads", "1", "--quiet",
             "--max-finished-jobs-per-client", "4", "--max-job-bytes-per-client", "1000000")
    replicas = [Server(binary, *flags), Server(binary, *flags)]
    try:
        failing = {"polynomials": ["x" + " " * 200_000 + "+"]}
        ids = []
        for i in range(10):
            status, _, body = submit(replicas[i % 2], "groebner", failing)
            check(status == 202, "redis: failing job %d accepted: %s" % (i, status))
            if status != 202:
                return
            ids.append(body["id"])
            state = wait_for(replicas[(i + 1) % 2], body["id"], finished)
            check(state is not None and state["status"] == "failed", "redis: job %d failed: %r" % (i, state))
        kept = [job_id for job_id in ids if job(replicas[0], job_id)[0] == 200]
        check(kept == ids[-4:], "redis: the 4 newest finished jobs are kept: %d kept" % len(kept))
        check(len(redis_keys(redis, "implicitizer:job:*")) == 4, "redis: the evicted jobs' hashes are gone")
        _, _, running = submit(replicas[0], "groebner", LONG)
        _, _, running2 = submit(replicas[1], "groebner", LONG)
        check(all(wait_for(replicas[0], r["id"], lambda j: j["status"] == "running") is not None
                  for r in (running, running2)), "redis: both replicas run a long job")
        big = {"polynomials": ["x" + " " * 600_000 + "+y"]}
        status, _, queued = submit(replicas[0], "groebner", big)
        check(status == 202, "redis: 600 kB queued: %s" % status)
        status, _, body = submit(replicas[1], "groebner", big)
        check(status == 507 and error_code(body) == "job_storage_full"
              and "--max-job-bytes-per-client" in body["error"]["message"],
              "redis: a second 600 kB queued request through the other replica: %s %r" % (status, body))
        for job_id in (queued["id"], running["id"], running2["id"]):
            replicas[0].request("DELETE", "/v1/jobs/" + job_id)
    finally:
        for s in replicas:
            s.close()
        redis.close()


def main():
    if len(sys.argv) < 3 or not sys.argv[2]:
        print("no redis-server: skipped")
        return 77
    binary, redis_binary = sys.argv[1], sys.argv[2]
    redis = Redis(redis_binary)
    servers = []
    try:
        a = replica(binary, redis)
        servers.append(a)
        run_tests(CHECKS, [
            lambda: test_cancel_through_the_other_replica(binary, redis, a, servers),
            lambda: test_shared_results(a, servers[1]),
            lambda: test_shared_result_cache(redis, a, servers[1]),
            lambda: test_cap_across_replicas(a, servers[1]),
            lambda: test_kill_9_takeover(a, servers[1]),
            lambda: test_storage_bounded(binary, redis_binary),
        ])
        # Unknown store addresses stop the start, with a message.
        result = subprocess.run([binary, "--port", "0", "--store", "redis://127.0.0.1:1"], capture_output=True,
                                text=True, timeout=60)
        check(result.returncode == 1 and "redis" in result.stderr, "no Redis there: exit 1: %r" % result.stderr)
    finally:
        if CHECKS.failures:
            for s in servers:
                print("---- replica log (tail) ----")
                print(s.log_text()[-2000:])
        for s in servers:
            s.close()
        redis.close()
    print(CHECKS.summary())
    return 1 if CHECKS.failures else 0


if __name__ == "__main__":
    sys.exit(main())
