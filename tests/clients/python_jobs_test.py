#!/usr/bin/env python3
"""End-to-end tests of the Python client's jobs API (submit, wait with a progress
callback, cancel) against the real implicitizer-server on an ephemeral loopback port.
Usage: python_jobs_test.py PATH/TO/implicitizer-server [unittest options]
Registered with ctest as clients.python_jobs (clients/python/CMakeLists.txt)."""

import json
import os
import sys
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "server"))
sys.path.insert(0, os.path.join(ROOT, "clients", "python"))
from server_harness import Server  # noqa: E402
import implicitizer_client as ic  # noqa: E402

BIN = None  # argv[1], set in __main__
server = None
client = None

SMALL = {"polynomials": ["x^2+y", "x*y-1"]}
# Seconds of F4 over many primes: long enough to be watched and cancelled.
with open(os.path.join(ROOT, "tests", "server", "data", "jobs_ideals.json"), encoding="utf-8") as f:
    _CYCLIC7 = [e for e in json.load(f) if e["name"] == "cyclic7"][0]
LONG = {"polynomials": _CYCLIC7["polys"], "variables": _CYCLIC7["vars"]}
# Generous for a loaded 2-core machine.
WAIT_S = 180


def setUpModule():
    global server, client
    server = Server(BIN, "--job-threads", "1", "--quiet")
    client = ic.Client("http://127.0.0.1:%d" % server.port, timeout=60)


def tearDownModule():
    status = server.stop()
    server.close()
    if status != 0:
        raise AssertionError("the server exited with %r after SIGTERM" % status)


class JobsTest(unittest.TestCase):
    def test_run_as_job_answers_what_the_endpoint_answers(self):
        seen = []
        answer = client.run_as_job("groebner", SMALL, progress=seen.append, poll_seconds=0.05, timeout=WAIT_S)
        self.assertEqual(answer["basis"], ["y^2+x", "x*y-1", "x^2+y"])
        # The job cached its answer: the endpoint now returns that very object.
        self.assertEqual(client.groebner(SMALL["polynomials"]), answer)
        self.assertTrue(seen and seen[-1]["status"] == "done", seen)

    def test_render_job_gives_a_png(self):
        result = client.run_as_job("render", {"implicit": "x^2+y^2+z^2-1", "width": 16, "height": 16},
                                   poll_seconds=0.05, timeout=WAIT_S)
        self.assertIsInstance(result, ic.RenderResult)
        self.assertEqual(result.png[:8], b"\x89PNG\r\n\x1a\n")
        self.assertEqual(result.stats["width"], 16)

    def test_refusals(self):
        with self.assertRaises(ic.ImplicitizerError) as sync:
            client.groebner(["x"], order="magic")
        with self.assertRaises(ic.ImplicitizerError) as job:
            client.submit("groebner", {"polynomials": ["x"], "order": "magic"})
        self.assertEqual((job.exception.status, job.exception.error), (sync.exception.status, sync.exception.error))
        with self.assertRaises(ic.ImplicitizerError) as unknown:
            client.submit("factor", {})
        self.assertEqual((unknown.exception.status, unknown.exception.code), (400, "unknown_job_kind"))
        with self.assertRaises(ic.ImplicitizerError) as missing:
            client.job("0" * 32)
        self.assertEqual((missing.exception.status, missing.exception.code), (404, "job_not_found"))

    def test_failed_job_raises_the_endpoint_error(self):
        job_id = client.submit("groebner", {"polynomials": ["x^^2"]})["id"]
        with self.assertRaises(ic.ImplicitizerError) as failed:
            client.wait(job_id, poll_seconds=0.05, timeout=WAIT_S)
        self.assertEqual((failed.exception.status, failed.exception.code), (400, "exponent_not_integer"))
        self.assertIsNone(client.cancel(job_id))  # a finished job is removed
        with self.assertRaises(ic.ImplicitizerError):
            client.job(job_id)

    def test_cancel_from_the_progress_callback(self):
        job_id = client.submit("groebner", LONG)["id"]
        phases = []

        def on_progress(state):
            phases.append(state["progress"]["phase"])
            # Cancel once the computation reports its own phase, not just "running".
            if state["status"] == "running" and state["progress"]["phase"] != "running" \
                    and not state["cancel_requested"]:
                self.assertTrue(client.cancel(job_id)["cancel_requested"])

        with self.assertRaises(ic.ImplicitizerError) as cancelled:
            client.wait(job_id, progress=on_progress, poll_seconds=0.05, timeout=WAIT_S)
        self.assertEqual(cancelled.exception.code, "cancelled")
        self.assertTrue(any(p not in ("queued", "running", "cancelled") for p in phases), phases)
        self.assertEqual(client.job(job_id)["status"], "cancelled")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    BIN = sys.argv.pop(1)
    unittest.main()
