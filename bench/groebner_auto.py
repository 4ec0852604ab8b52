#!/usr/bin/env python3
"""Measures what `groebner --method auto`'s head start should be: every ideal by
Buchberger over Q alone and by the proven multi-modular F4 alone, and what auto
would take with each candidate head start.

    python3 bench/groebner_auto.py [--timeout S] [--bin build/bin/implicitizer]
        [--head-starts 0,10,25,50,100]

The ideals: the classic ones of ../shared/bench/gb/ideals.json (grevlex), and the
elimination ideal of every public and hard surface as `implicitize --json` writes it
into its Singular script (`ideal I`, eliminating w, s, t), which is what a
mathematician checking an elimination posts to /v1/groebner. Each run is a whole
process. Buchberger's head start is an allowance of work units
(buchberger_work_of_milliseconds), so auto with head start H answers by Buchberger
when its whole work W fits in H's allowance, and otherwise after spending the
allowance, taken as the fraction allowance/W of Buchberger's measured time, plus F4's
time. Prints a Markdown table, then the worst and total ratio of each candidate to
the better of the two methods (docs/benchmarks.md records it with the command).
"""

import argparse
import json
import os
import re
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(ROOT, "..", "shared", "bench")
if not os.path.exists(SHARED):
    SHARED = "/work/shared/bench"

def run(command, timeout):
    start = time.time()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout + 5)
    except subprocess.TimeoutExpired:
        return None, None
    seconds = time.time() - start
    if done.returncode != 0:
        return None, None
    return seconds, json.loads(done.stdout)


def classic_ideals():
    with open(os.path.join(SHARED, "gb", "ideals.json")) as f:
        for ideal in json.load(f):
            yield ideal["name"], ideal["vars"], ideal["polys"], []


def surface_ideals(binary):
    for suite in ("public", "hard"):
        with open(os.path.join(SHARED, "surfaces_%s.json" % suite)) as f:
            surfaces = json.load(f)
        for s in surfaces:
            command = [binary, "implicitize", "--x", s["x"], "--y", s["y"], "--z", s["z"], "--json", "--timeout", "60"]
            _, answer = run(command, 60)
            if answer is None:
                continue
            script = answer["reproduce"]["singular"]
            ring = re.search(r"ring r = 0, \(([^)]*)\)", script).group(1).split(",")
            body = re.search(r"ideal I = (.*?);\n", script, re.S).group(1)
            polys = [p.strip() for p in body.split(",\n")]
            eliminated = re.search(r"eliminate\(I, ([^)]*)\)", script).group(1).split("*")
            yield s["name"], ring, polys, eliminated


def ours(binary, variables, polys, eliminated, method, timeout):
    command = [binary, "groebner", "--vars", ",".join(variables), "--method", method, "--json", "--timeout",
               str(timeout)]
    command += ["--eliminate", ",".join(eliminated)] if eliminated else ["--order", "grevlex"]
    return run(command + polys, timeout)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--timeout", type=float, default=20)
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin", "implicitizer"))
    parser.add_argument("--head-starts", default="0,10,25,50,100")
    # kWorkPerMillisecond of lib/src/groebner/buchberger.cpp, the head start's units.
    parser.add_argument("--work-per-ms", type=float, default=350000)
    args = parser.parse_args()
    head_starts = [float(h) for h in args.head_starts.split(",")]
    print("| ideal | Buchberger over Q | its work | F4, proven | auto | " +
          " | ".join("auto, %g ms (predicted)" % h for h in head_starts) + " |")
    print("|---" * (5 + len(head_starts)) + "|")
    ratios = {h: [] for h in head_starts}
    for name, variables, polys, eliminated in list(classic_ideals()) + list(surface_ideals(args.bin)):
        tb, b = ours(args.bin, variables, polys, eliminated, "buchberger", args.timeout)
        tf, _ = ours(args.bin, variables, polys, eliminated, "f4", args.timeout)
        ta, _ = ours(args.bin, variables, polys, eliminated, "auto", args.timeout)
        work = b["stats"]["work"] if b is not None else None
        cells = []
        best = min(t for t in (tb, tf) if t is not None) if (tb, tf) != (None, None) else None
        for h in head_starts:
            allowance = h * args.work_per_ms
            if work is not None and work <= allowance:
                predicted = tb
            elif tf is None:
                predicted = None
            else:
                spent = h / 1000 if work is None else tb * allowance / work
                predicted = spent + tf
            cells.append("%.3f s" % predicted if predicted is not None else "> %g s" % args.timeout)
            if predicted is not None and best is not None:
                ratios[h].append((predicted / best, predicted, best))
        show = lambda t: "%.3f s" % t if t is not None else "> %g s" % args.timeout
        print("| %s | %s | %s | %s | %s | %s |" % (name, show(tb), work if work is not None else "", show(tf),
                                                  show(ta), " | ".join(cells)), flush=True)
    print()
    for h in head_starts:
        r = ratios[h]
        print("- head start %g ms: worst ratio to the better method %.2f, total %.2f s against %.2f s" % (
            h, max(x[0] for x in r), sum(x[1] for x in r), sum(x[2] for x in r)))


if __name__ == "__main__":
    main()
