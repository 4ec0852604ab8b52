#!/usr/bin/env python3
"""Buchberger's work per millisecond on the benchmark surfaces: the calibration of
buchberger_work_of_milliseconds (lib/src/groebner/buchberger.cpp), which turns auto's
head starts, measured in time, into allowances of work. For each public and hard
surface it runs `implicitize --method groebner --json` three times (a 5 s limit each),
keeps the fastest run, and prints stats.work, stats.groebner_ms and their ratio, then
the median ratio of the runs that took at least 0.4 ms (shorter ones are fixed costs).
Usage: scripts/buchberger-work-rate.py build/bin/implicitizer [SHARED_DIR]
docs/algorithms.md ("Head starts in units of work") has a run."""

import json
import os
import statistics
import subprocess
import sys

binary = sys.argv[1]
shared = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                                               "shared")
rates = []
for suite in ("public", "hard"):
    with open(os.path.join(shared, "bench", "surfaces_%s.json" % suite)) as f:
        surfaces = json.load(f)
    for s in surfaces:
        args = [binary, "implicitize", "--x", s["x"], "--y", s["y"], "--method", "groebner", "--json",
                "--timeout", "5"]
        if s.get("z"):
            args += ["--z", s["z"]]
        best = None
        for _ in range(3):
            run = subprocess.run(args, capture_output=True, text=True)
            stats = json.loads(run.stdout).get("stats") if run.stdout.startswith("{") else None
            if stats is None:
                break
            if best is None or stats["groebner_ms"] < best["groebner_ms"]:
                best = stats
        if best is None:
            print("%-22s more than 5 s" % s["name"])
            continue
        rate = best["work"] / best["groebner_ms"] if best["groebner_ms"] > 0 else 0
        print("%-22s work %12d  Buchberger %10.3f ms  %10.0f units/ms" % (s["name"], best["work"],
                                                                           best["groebner_ms"], rate))
        if best["groebner_ms"] >= 0.4:
            rates.append(rate)
print("median units/ms over the runs of at least 0.4 ms: %.0f (%d runs, %.0f to %.0f)"
      % (statistics.median(rates), len(rates), min(rates), max(rates)))
