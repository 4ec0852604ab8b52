#!/usr/bin/env python3
"""Two builds of the command line side by side on the benchmark surfaces: for every
public and hard surface (tri_quartic left out: seconds per run) by `auto`, and for a
few by `--method groebner`, five interleaved runs of `implicitize --json` with each
binary; prints a Markdown row per case with the method each chose, the median
elapsed_ms of each and their ratio (NEW / OLD). Interleaving puts both under the
same load; compare ratios, not times across runs.
Usage: scripts/compare-cli.py OLD/bin/implicitizer NEW/bin/implicitizer [SHARED_DIR]
docs/benchmarks.md has a run (issue 16: before and after the work-based head starts)."""

import json
import os
import statistics
import subprocess
import sys

old, new = sys.argv[1], sys.argv[2]
shared = sys.argv[3] if len(sys.argv) > 3 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                                               "shared")


def load(suite):
    with open(os.path.join(shared, "bench", "surfaces_%s.json" % suite)) as f:
        return json.load(f)


public, hard = load("public"), load("hard")
cases = [(s, []) for s in public + hard if s["name"] != "tri_quartic"]
by_groebner = ("tri_quadratic", "tp_21", "tp_22", "torus_R2_r1", "steiner_roman", "enneper", "biquadratic_patch")
cases += [(s, ["--method", "groebner"]) for s in public + hard if s["name"] in by_groebner]

print("| surface | method asked | old: route | old ms | new: route | new ms | new / old |")
print("|---|---|---|---|---|---|---|")
for s, extra in cases:
    args = ["implicitize", "--x", s["x"], "--y", s["y"]] + (["--z", s["z"]] if s.get("z") else []) + ["--json"] + extra
    times = {old: [], new: []}
    method = {}
    for _ in range(5):
        for binary in (old, new):
            answer = json.loads(subprocess.run([binary] + args, capture_output=True, text=True).stdout)
            times[binary].append(answer["elapsed_ms"])
            method[binary] = answer["method"]
    a, b = statistics.median(times[old]), statistics.median(times[new])
    print("| %s | %s | %s | %.2f | %s | %.2f | %.2f |"
          % (s["name"], " ".join(extra) or "auto", method[old], a, method[new], b, b / a))
