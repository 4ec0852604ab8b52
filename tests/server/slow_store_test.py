#!/usr/bin/env python3
"""A slow store or a full pool must not hold up what does not need them (issue 41,
items 3 and 5), against the real server on loopback:

- the SQLite job file locked by another connection (this test's `BEGIN EXCLUSIVE`),
  and a Redis stopped (SIGSTOP) under `--store redis://`: /healthz and a synchronous
  request answer while the store is held, and the store is released only after they
  answered; the job calls waiting on the store answer 503 naming it;
- both workers held by computations this test ends (by closing their connections)
  only after the queued request answered: that request answers 504 naming the wait
  for a worker, and leaves the queue.

No verdict depends on the machine's speed but one ordering, whose margin is the
store's own timeout: /healthz must answer before the job calls waiting on the held
store give up (SQLite's busy timeout, 5 s; Redis's command timeout twice, 10 s); before
the fix it answered only after them, on the network thread they blocked. The other
verdicts are orderings the test controls (the answer came while the store or the
workers were still held) or a status and message. Latencies are printed as
diagnostics only.
Usage: slow_store_test.py PATH/TO/implicitizer-server [PATH/TO/redis-server]
(without redis-server the Redis part is skipped). Registered as server.slow_store."""

import json
import os
import signal
import socket
import sqlite3
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Checks, Redis, Server, close_showing_log, error_code, run_tests  # noqa: E402

BIN = sys.argv[1]
REDIS_BIN = sys.argv[2] if len(sys.argv) > 2 else ""
CHECKS = Checks()
check = CHECKS.check

# Generous: an answer that does not come within this is a failure, however loaded the
# machine (a held store would keep it waiting for ever).
ANSWER_TIMEOUT_S = 120
SMALL = {"polynomials": ["x^2+y", "x*y-1"]}
# Minutes of Buchberger on any machine (reliability_test.py's slow request): holds a
# worker until this test closes its connection.
SLOW = {"x": "s^3+t^2*s", "y": "t^3-s", "z": "s*t^2+t^4", "method": "groebner", "timeout_ms": 60000}


class RawRequest:
    """A request sent on a raw socket (with `Connection: close`) and read only when asked,
    so that whether its answer has arrived can be seen without waiting: the server
    writes each answer before it reads the next request on the same network thread,
    and on loopback the bytes are in this socket once written. Closing it unanswered
    is a client gone: the server cancels the computation."""

    def __init__(self, server, method, path, body=None):
        data = json.dumps(body).encode() if body is not None else b""
        self.start = time.monotonic()
        self.sock = socket.create_connection(("127.0.0.1", server.port), timeout=ANSWER_TIMEOUT_S)
        self.sock.sendall(b"%s %s HTTP/1.1\r\nHost: t\r\nConnection: close\r\nContent-Type: application/json\r\n"
                          b"Content-Length: %d\r\n\r\n%s" % (method.encode(), path.encode(), len(data), data))

    def answered(self):
        """Whether any byte of an answer has arrived (without waiting)."""
        self.sock.setblocking(False)
        try:
            return len(self.sock.recv(1, socket.MSG_PEEK)) > 0
        except BlockingIOError:
            return False
        finally:
            self.sock.setblocking(True)

    def read(self):
        """(status, body, seconds since sent) once the server has answered and closed."""
        chunks = []
        try:
            while True:
                chunk = self.sock.recv(65536)
                if not chunk:
                    break
                chunks.append(chunk)
        except OSError as e:
            return None, repr(e), time.monotonic() - self.start
        seconds = time.monotonic() - self.start
        head, _, body = b"".join(chunks).partition(b"\r\n\r\n")
        try:
            status = int(head.split(b" ", 2)[1])
        except (IndexError, ValueError):
            status = None
        return status, body.decode(errors="replace"), seconds

    def close(self):
        self.sock.close()


def wait_for_metric(server, name, value):
    """Polls /metrics until `name` reads `value` (a state to reach, not a time to wait)."""
    end = time.monotonic() + ANSWER_TIMEOUT_S
    while time.monotonic() < end:
        if server.metric(name) == value:
            return True
        time.sleep(0.02)
    return False


def timed(server, method, path, body=None):
    start = time.monotonic()
    status, _, data = server.request(method, path, body, {"Content-Type": "application/json"}, timeout=ANSWER_TIMEOUT_S)
    return status, data.decode(errors="replace"), time.monotonic() - start


def message(body):
    try:
        return json.loads(body)["error"]["message"]
    except (ValueError, TypeError, KeyError):
        return ""


# ---- item 3: a locked SQLite file -----------------------------------------------

def test_sqlite_locked():
    directory = tempfile.mkdtemp(prefix="implicitizer-slow-store-")
    path = os.path.join(directory, "jobs.sqlite3")
    s = Server(BIN, "--store", "sqlite:" + path, "--threads", "2")
    lock = None
    try:
        status, _, body = s.post_json("/v1/jobs", {"kind": "groebner", "request": SMALL})
        check(status == 202, "a job before the lock: %s %r" % (status, body))
        job_id = body["id"]
        lock = sqlite3.connect(path, isolation_level=None, timeout=ANSWER_TIMEOUT_S)
        lock.execute("BEGIN EXCLUSIVE")
        # The reproducer: a job GET beside a submission, both waiting on the file.
        get = RawRequest(s, "GET", "/v1/jobs/" + job_id)
        post = RawRequest(s, "POST", "/v1/jobs", {"kind": "groebner", "request": SMALL})
        health = timed(s, "GET", "/healthz")
        waiting = not post.answered()
        sync = timed(s, "POST", "/v1/groebner", {"polynomials": ["x^2+y", "x*y-2"]})
        check(health[0] == 200, "/healthz answers while the SQLite file is locked: %s %s" % health[:2])
        check(waiting, "/healthz answered before the submission gave up on the locked file (%.2f s)" % health[2])
        check(sync[0] == 200, "a synchronous request answers while the SQLite file is locked: %s %s" % sync[:2])
        print("  sqlite locked: /healthz %.3f s, /v1/groebner %.3f s" % (health[2], sync[2]))
        # Still locked: a write gives up after the store's busy timeout, naming the
        # store (a read may still answer: the WAL lets readers past a writer's lock).
        get_answer = get.read()
        check(get_answer[0] == 200 or (get_answer[0] == 503 and "SQLite job store " + path in message(get_answer[1])),
              "a job GET on a locked file: its state, or 503 naming the store: %s %s" % get_answer[:2])
        post_answer = post.read()
        check(post_answer[0] == 503 and "SQLite job store " + path in message(post_answer[1])
              and "locked" in message(post_answer[1]),
              "a submission on a locked file: 503 naming the store: %s %s" % post_answer[:2])
        print("  sqlite locked: job GET %s after %.2f s; submission %s after %.2f s: %s"
              % (get_answer[0], get_answer[2], post_answer[0], post_answer[2], message(post_answer[1])))
        lock.rollback()
        lock.close()
        lock = None
        status, _, body = s.request("GET", "/v1/jobs/" + job_id)
        check(status == 200, "the job answers once the file is free: %s %r" % (status, body[:300]))
    finally:
        if lock is not None:
            lock.close()
        close_showing_log(s, CHECKS)


# ---- item 3: a stopped Redis ----------------------------------------------------

def test_redis_stopped():
    if not REDIS_BIN:
        print("  no redis-server: the Redis part is skipped")
        return
    redis = Redis(REDIS_BIN)
    s = Server(BIN, "--store", "redis://127.0.0.1:%d" % redis.port, "--threads", "2")
    stopped = False
    try:
        status, _, body = s.post_json("/v1/jobs", {"kind": "groebner", "request": SMALL})
        check(status == 202, "a job before Redis stops: %s %r" % (status, body))
        job_id = body["id"]
        # Held for as long as this test needs, unlike DEBUG SLEEP's fixed time.
        redis.proc.send_signal(signal.SIGSTOP)
        stopped = True
        get = RawRequest(s, "GET", "/v1/jobs/" + job_id)
        post = RawRequest(s, "POST", "/v1/jobs", {"kind": "groebner", "request": SMALL})
        health = timed(s, "GET", "/healthz")
        waiting = not (get.answered() or post.answered())
        # A miss in this replica's cache, so the shared cache is asked first. The old
        # lookup waited up to 10 s for Redis and the request answered 504 naming
        # "polynomial multiplication"; now it is a miss after a short wait.
        sync = timed(s, "POST", "/v1/groebner", {"polynomials": ["x^2+y", "x*y-3"], "timeout_ms": 3000})
        check(health[0] == 200, "/healthz answers while Redis is stopped: %s %s" % health[:2])
        check(waiting, "/healthz answered before the job calls gave up on Redis (%.2f s)" % health[2])
        check(sync[0] == 200, "a synchronous request answers while Redis is stopped: %s %s" % sync[:2])
        # A deadline shorter than the lookup's wait: the 504 names the lookup (or, on a
        # loaded machine, the wait for a worker before it), never a computation that
        # never ran.
        short = timed(s, "POST", "/v1/groebner", {"polynomials": ["x^2+y", "x*y-4"], "timeout_ms": 10})
        check(short[0] == 504 and ("during the shared result cache lookup" in message(short[1])
                                   or "during the wait for a worker" in message(short[1])),
              "a 10 ms request while Redis is stopped: 504 naming the lookup: %s %s" % short[:2])
        print("  redis stopped: /healthz %.3f s, /v1/groebner %.3f s; with timeout_ms 10: %s after %.3f s: %s"
              % (health[2], sync[2], short[0], short[2], message(short[1])))
        get_answer = get.read()
        check(get_answer[0] == 503 and "Redis job store 127.0.0.1:%d" % redis.port in message(get_answer[1])
              and "timeout" in message(get_answer[1]),
              "a job GET while Redis is stopped: 503 naming the store and the timeout: %s %s" % get_answer[:2])
        print("  redis stopped: job GET %s after %.2f s: %s" % (get_answer[0], get_answer[2], message(get_answer[1])))
        post_answer = post.read()
        check(post_answer[0] == 503 and "Redis job store" in message(post_answer[1]),
              "a submission while Redis is stopped: 503 naming the store: %s %s" % post_answer[:2])
        redis.proc.send_signal(signal.SIGCONT)
        stopped = False
        status, _, _ = s.request("GET", "/v1/jobs/" + job_id, timeout=ANSWER_TIMEOUT_S)
        check(status == 200, "the job answers once Redis is back: %s" % status)
    finally:
        if stopped:
            redis.proc.send_signal(signal.SIGCONT)
        close_showing_log(s, CHECKS)
        redis.close()


# ---- item 5: a deadline that passes in the queue --------------------------------

def test_deadline_in_the_queue():
    s = Server(BIN, "--threads", "2", "--cache-size", "0", "--quiet")
    holders = []
    try:
        holders = [RawRequest(s, "POST", "/v1/implicitize", dict(SLOW, timeout_ms=60000 - i)) for i in range(2)]
        check(wait_for_metric(s, "implicitizer_workers_busy", 2), "both workers hold a slow computation")
        status, body, seconds = timed(s, "POST", "/v1/groebner", dict(SMALL, timeout_ms=1000))
        still_held = not any(h.answered() for h in holders)
        depth = s.metric("implicitizer_queue_depth")
        check(still_held, "the workers were still held when the queued request answered")
        check(status == 504 and error_code(json.loads(body)) == "time_limit_exceeded"
              and "the wait for a worker" in message(body),
              "a deadline passed in the queue: 504 naming the wait: %s %s" % (status, body))
        check(depth == 0, "the timed-out request left the queue: depth %s" % depth)
        print("  queued behind two busy workers, timeout_ms 1000: %s after %.2f s: %s"
              % (status, seconds, message(body)))
    finally:
        for h in holders:
            h.close()
        close_showing_log(s, CHECKS)


def main():
    run_tests(CHECKS, [test_sqlite_locked, test_redis_stopped, test_deadline_in_the_queue])
    print(CHECKS.summary())
    return 1 if CHECKS.failures else 0


if __name__ == "__main__":
    sys.exit(main())
