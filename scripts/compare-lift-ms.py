#!/usr/bin/env python3
"""Two builds of the command line side by side on the modular Gröbner basis of the
named ideals of ../shared/bench/gb/ideals.json: `groebner --modular --json`, the
binaries alternating, RUNS times each; prints the median of `stats.modular.lift_ms`
(the Chinese remaindering and reconstruction) and the counts of primes, lifted primes
and reconstructions each build used.
Usage: scripts/compare-lift-ms.py OLD/bin/implicitizer NEW/bin/implicitizer RUNS NAME...
Its run for issue 17 (one lift across primes) is in the history of docs/benchmarks.md."""

import json
import os
import statistics
import subprocess
import sys

IDEALS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "bench", "gb", "ideals.json")


def lift(binary, ideal):
    """(lift_ms, primes, lifted primes, reconstructions) of one run."""
    out = subprocess.run([binary, "groebner", "--modular", "--json", "--vars", ",".join(ideal["vars"])] + ideal["polys"],
                         capture_output=True, text=True, check=True).stdout
    m = json.loads(out)["stats"]["modular"]
    return m["lift_ms"], m["primes"], m["lifted_primes"], m["reconstructions"]


def main():
    old, new, runs, names = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
    ideals = {i["name"]: i for i in json.load(open(IDEALS))}
    for name in names:
        rows = {old: [], new: []}
        for run in range(runs):
            for binary in (old, new) if run % 2 == 0 else (new, old):
                rows[binary].append(lift(binary, ideals[name]))
        print("%s: lift_ms median %.2f old, %.2f new; (primes, lifted, reconstructions) %s old, %s new"
              % (name, statistics.median(r[0] for r in rows[old]), statistics.median(r[0] for r in rows[new]),
                 sorted(set(r[1:] for r in rows[old])), sorted(set(r[1:] for r in rows[new]))))


main()
