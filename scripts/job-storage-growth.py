#!/usr/bin/env python3
"""Issue 41's storage reproducer: one client posts N groebner jobs of about 1 MB each
that fail at once (the expression does not parse), each polled until it ends, then
prints the server's RSS before and after and, with a SQLite store, the size of its
file and WAL. Not a test (tests/server/jobs_test.py asserts the bound); docs/api.md
("Reliability") has a run.
Usage: scripts/job-storage-growth.py build/bin/implicitizer-server N [STORE [FLAG ...]]"""

import json
import os
import sys
import tempfile
import time

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "server"))
from server_harness import Server  # noqa: E402


def rss_mib(server):
    with open("/proc/%d/status" % server.proc.pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return -1.0


binary, count = sys.argv[1], int(sys.argv[2])
store = sys.argv[3] if len(sys.argv) > 3 else "memory"
base = tempfile.mkdtemp(prefix="job-storage-growth-")
path = os.path.join(base, "jobs.sqlite3")
server = Server(binary, "--quiet", "--cache-size", "0", "--store", "sqlite:" + path if store == "sqlite" else store,
                *sys.argv[4:])
body = json.dumps({"kind": "groebner", "request": {"polynomials": ["x" + " " * 1_000_000 + "+"]}})
try:
    before, start, refused = rss_mib(server), time.monotonic(), 0
    for _ in range(count):
        status, _, data = server.request("POST", "/v1/jobs", body, {"Content-Type": "application/json"})
        if status != 202:
            refused += 1
            continue
        job_id = json.loads(data)["id"]
        while json.loads(server.request("GET", "/v1/jobs/" + job_id)[2])["status"] in ("queued", "running"):
            time.sleep(0.01)
    print("%d jobs in %.1f s (%d refused): RSS %.0f -> %.0f MiB" % (count, time.monotonic() - start, refused, before,
                                                                   rss_mib(server)))
    if store == "sqlite":
        sizes = {suffix or "file": os.path.getsize(path + suffix) for suffix in ("", "-wal")
                 if os.path.exists(path + suffix)}
        print("sqlite sizes (bytes): %r" % sizes)
finally:
    server.close()
    for name in os.listdir(base):
        os.unlink(os.path.join(base, name))
    os.rmdir(base)
