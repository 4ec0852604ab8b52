#!/usr/bin/env python3
"""What counting a computation's memory costs: `implicitize --json` on three hard
surfaces, with and without --max-memory (an account attached: every allocation of
the computation's threads is measured and charged), interleaved, five runs each; it
prints the median elapsed_ms of both and their ratio.
Usage: scripts/memory-accounting-cost.py build/bin/implicitizer [SHARED_DIR]
docs/benchmarks.md ("Memory accounting") has a run."""

import json
import os
import statistics
import subprocess
import sys

binary = sys.argv[1]
shared = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                                               "shared")
with open(os.path.join(shared, "bench", "surfaces_hard.json")) as f:
    hard = {s["name"]: s for s in json.load(f)}
# tp_22 by Buchberger (allocation-heavy: big integers), tp_33 by Dixon's resultant,
# tri_cubic by interpolation (two threads charging one account).
for name, extra in (("tp_22", ["--method", "groebner"]), ("tp_33", []), ("tri_cubic", [])):
    s = hard[name]
    base = [binary, "implicitize", "--x", s["x"], "--y", s["y"], "--z", s["z"], "--json"] + extra
    runs = {False: [], True: []}
    for _ in range(5):
        for counted in (False, True):
            out = subprocess.run(base + (["--max-memory", "8G"] if counted else []), capture_output=True, text=True)
            runs[counted].append(json.loads(out.stdout)["elapsed_ms"])
    plain, counted = statistics.median(runs[False]), statistics.median(runs[True])
    print("%-10s %s  no account %8.1f ms  counted %8.1f ms  ratio %.3f"
          % (name, " ".join(extra) or "auto", plain, counted, counted / plain))
