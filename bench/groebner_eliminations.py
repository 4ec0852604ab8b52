#!/usr/bin/env python3
"""Times the proven elimination a mathematician posts to /v1/groebner: `groebner
--method f4 --eliminate` on the elimination ideal of each public and hard surface
(the `ideal I` of `implicitize --json`'s Singular script, as bench/groebner_auto.py
reads it), with the split of the route's time from its JSON.

    python3 bench/groebner_eliminations.py [--timeout S] [--min-seconds S]
        [--bin build/bin/implicitizer] [--before OTHER/build/bin/implicitizer]
        [--proofs exact,random_primes] [--ideals tp_32,tri_cubic_rational]

Ideals that take under --min-seconds with --bin (and the first of --proofs) are left
out of the table (the public surfaces take milliseconds); --ideals keeps only those
named. With --before, each ideal
also runs with that binary (another commit's build), just before ours. --proofs runs
each binary once per `--proof` value (random_primes: the labelled unproven mode). Each run is a whole process; a
run past --timeout prints "> T". Prints a Markdown table (docs/benchmarks.md records
it with the command).
"""

import argparse
import json
import os
import subprocess
import time

from groebner_auto import ROOT, surface_ideals


def eliminate(binary, proof, variables, polys, eliminated, timeout):
    """(seconds, the JSON's modular stats) of one run, or (None, None) past the timeout."""
    command = [binary, "groebner", "--vars", ",".join(variables), "--method", "f4", "--eliminate",
               ",".join(eliminated), "--proof", proof, "--json", "--timeout", str(timeout)] + polys
    start = time.monotonic()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout + 5)
    except subprocess.TimeoutExpired:
        return None, None
    if done.returncode != 0:
        return None, None
    return time.monotonic() - start, json.loads(done.stdout)["stats"]["modular"]


def cell(seconds, modular, timeout):
    if seconds is None:
        return "> %g s" % timeout
    return "%.2f s (%d primes; %.2f + %.2f + %.2f s%s)" % (
        seconds, modular["primes"], modular["modular_ms"] / 1000, modular["lift_ms"] / 1000,
        modular["verify_ms"] / 1000, "" if modular["proven"] else ", NOT PROVEN")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--min-seconds", type=float, default=1)
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin", "implicitizer"))
    parser.add_argument("--before", default="")
    parser.add_argument("--proofs", default="exact")
    parser.add_argument("--ideals", default="", help="only these surfaces' ideals (default: every one)")
    args = parser.parse_args()
    only = set(filter(None, args.ideals.split(",")))
    proofs = args.proofs.split(",")
    binaries = ([("before", args.before)] if args.before else []) + [("now", args.bin)]
    columns = [(label if proof == "exact" else "%s, %s" % (label, proof), binary, proof)
               for proof in proofs for label, binary in binaries]
    print("| ideal | " + " | ".join("%s: whole run (primes; modulo p + lift + proof)" % label
                                    for label, _, _ in columns) + " |")
    print("|---" * (1 + len(columns)) + "|")
    for name, variables, polys, eliminated in surface_ideals(args.bin):
        if only and name not in only:
            continue
        cells = [eliminate(binary, proof, variables, polys, eliminated, args.timeout) for _, binary, proof in columns]
        seconds = cells[len(binaries) - 1][0]
        if seconds is not None and seconds < args.min_seconds:
            continue
        print("| %s | %s |" % (name, " | ".join(cell(s, m, args.timeout) for s, m in cells)), flush=True)


if __name__ == "__main__":
    main()
