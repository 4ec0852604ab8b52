#!/usr/bin/env python3
"""Times reduced Gröbner bases (grevlex) of the classic ideals, ours beside Giac's,
Singular's and Macaulay2's, in one run, each as a whole process.

    python3 bench/groebner_peers.py [--ideals cyclic5,katsura5,...] [--timeout S]
        [--methods modular,auto,f4:random_primes] [--giac /tmp/giac_gbasis] [--bin build/bin/implicitizer]
        [--peers giac,giac-certified,singular,m2]
        [--giac-certified /tmp/giac_gbasis_certified] [--before OTHER/build/bin/implicitizer]

Ours runs `implicitizer groebner --order grevlex --method M --json` (a method M:P adds
`--proof P`: f4:random_primes is the labelled unproven mode) and the table also
shows, from its JSON, the time of the runs modulo primes and of the proof over Q.
With --before, every method also runs with that binary (another commit's build),
just before ours on the same ideal, so that the two are compared within one run.
Giac's driver is /work/shared/bench/peers/giac_gbasis.cpp built into /tmp (its
README), run with one thread; "giac-certified" is bench/peers/giac_gbasis_certified.cpp
(built the same way), Giac told to prove its basis (proba_epsilon:=0), the like of
ours, which is always proven; Singular runs `std` with redSB and redTail; Macaulay2
`gb`. A run past --timeout prints "> T". The ideals are ../shared/bench/gb/ideals.json.
With --rounds R, each ideal runs R times, every column once a round one after the
other (so that a machine whose speed drifts slows them alike), and a cell is the
median of its R times with their range; the notes give, per round, each ours column's
time over Giac's, and the medians of our phases. Prints a Markdown table
(docs/benchmarks.md records it with the command).
"""

import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
IDEALS = os.path.join(ROOT, "..", "shared", "bench", "gb", "ideals.json")
if not os.path.exists(IDEALS):
    IDEALS = "/work/shared/bench/gb/ideals.json"


def timed(command, timeout, stdin=None):
    """(seconds, stdout) of a whole process, or (None, "") past the timeout."""
    start = time.monotonic()
    try:
        done = subprocess.run(command, input=stdin, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, ""
    elapsed = time.monotonic() - start
    if done.returncode != 0:
        return None, "exit %d: %s" % (done.returncode, done.stderr.strip()[:200])
    return elapsed, done.stdout


def ours(binary, ideal, method, timeout):
    """`method` is a --method, or METHOD:PROOF for a --proof (f4:random_primes)."""
    method, _, proof = method.partition(":")
    command = [binary, "groebner", "--vars", ",".join(ideal["vars"]), "--order", "grevlex", "--method", method,
               "--json", "--timeout", str(timeout)] + (["--proof", proof] if proof else []) + ideal["polys"]
    seconds, out = timed(command, timeout + 5)
    if seconds is None:
        return None, out
    answer = json.loads(out)
    modular = answer["stats"].get("modular", {})
    detail = "%d elements, route %s%s" % (len(answer["basis"]), answer.get("method", "?"),
                                           "" if answer.get("proven", True) else ", NOT proven")
    if modular:
        detail += ": %d primes (%d replayed), modular %.2f s, lift %.2f s, proof %.2f s" % (
            modular.get("primes", 0), modular.get("replayed_primes", 0), modular.get("modular_ms", 0) / 1000,
            modular.get("lift_ms", 0) / 1000, modular.get("verify_ms", 0) / 1000)
    phases = [modular.get(k, 0) / 1000 for k in ("modular_ms", "lift_ms", "verify_ms")] if modular else None
    return seconds, detail, phases


def giac(binary, ideal, timeout):
    """Either Giac driver: both take the polynomials, the variables and the threads."""
    seconds, out = timed([binary, ",".join(ideal["polys"]), ",".join(ideal["vars"]), "1"], timeout)
    return seconds, (out.split()[0] + " elements" if seconds is not None and out.split() else out)


def singular(ideal, timeout):
    script = ("ring r = 0, (%s), dp;\noption(redSB); option(redTail);\nideal I = %s;\nideal G = std(I);\n"
              "size(G);\nquit;\n") % (",".join(ideal["vars"]), ",".join(ideal["polys"]))
    seconds, out = timed(["Singular", "-q", "--no-rc"], timeout, stdin=script)
    return seconds, (out.strip() + " elements" if seconds is not None else out)


def macaulay2(ideal, timeout):
    script = ("R = QQ[%s, MonomialOrder => GRevLex];\nI = ideal(%s);\nG = gb I;\n"
              "print numcols gens G;\nexit 0;\n") % (",".join(ideal["vars"]), ",".join(ideal["polys"]))
    with tempfile.NamedTemporaryFile("w", suffix=".m2", delete=False) as f:
        f.write(script)
        path = f.name
    try:
        seconds, out = timed(["M2", "--script", path], timeout)
    finally:
        os.unlink(path)
    return seconds, (out.strip() + " elements" if seconds is not None else out)


def show(seconds, timeout):
    return "> %g s" % timeout if seconds is None else "%.2f s" % seconds


def run_peer(peer, args, ideal):
    if peer == "giac":
        return giac(args.giac, ideal, args.timeout)
    if peer == "giac-certified":
        return giac(args.giac_certified, ideal, args.timeout)
    if peer == "singular":
        return singular(ideal, args.timeout)
    return macaulay2(ideal, args.timeout)


def summary(times, timeout):
    """One run's time, or the median of several with their range."""
    if len(times) == 1:
        return show(times[0], timeout)
    if any(t is None for t in times):
        return "%d of %d past %g s" % (sum(t is None for t in times), len(times), timeout)
    return "%.2f s (%.2f–%.2f)" % (statistics.median(times), min(times), max(times))


def round_notes(name, columns, times, phases, before):
    """Per round, each of our columns over Giac's time; the medians of our phases."""
    notes = []
    giac_column = next((c for c, col in enumerate(columns) if col[:2] == ("peer", "giac")), None)
    for c, (kind, what, binary) in enumerate(columns):
        if kind != "ours":
            continue
        label = "ours (%s%s)" % (what, ", before" if binary == before else "")
        if giac_column is not None and None not in times[c] and None not in times[giac_column]:
            ratios = [t / g for t, g in zip(times[c], times[giac_column])]
            notes.append("%s, %s / giac per round: %s; ratio of the medians %.2f" % (
                name, label, ", ".join("%.2f" % r for r in ratios),
                statistics.median(times[c]) / statistics.median(times[giac_column])))
        if phases[c]:
            medians = [statistics.median(p[k] for p in phases[c]) for k in range(3)]
            notes.append("%s, %s: medians of modular %.3f s, lift %.3f s, proof %.3f s" % ((name, label) + tuple(medians)))
    return notes


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ideals", default="cyclic5,cyclic6,cyclic7,katsura5,katsura6,katsura7,katsura8")
    parser.add_argument("--methods", default="modular")
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--giac", default="/tmp/giac_gbasis")
    parser.add_argument("--giac-certified", default="/tmp/giac_gbasis_certified")
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin", "implicitizer"))
    parser.add_argument("--peers", default="giac,singular,m2")
    parser.add_argument("--before", default="")
    parser.add_argument("--rounds", type=int, default=1)
    args = parser.parse_args()
    with open(IDEALS) as f:
        ideals = {i["name"]: i for i in json.load(f)}
    methods = args.methods.split(",")
    peers = [p for p in args.peers.split(",") if p]
    ours_columns = [(m, b) for m in methods for b in ([args.before] if args.before else []) + [args.bin]]
    print("| ideal | " + " | ".join("ours (%s%s)" % (m, ", before" if b == args.before else "")
                                    for m, b in ours_columns) + " | " + " | ".join(peers) + " |")
    print("|---" * (1 + len(ours_columns) + len(peers)) + "|")
    notes = []
    for name in args.ideals.split(","):
        ideal = ideals[name]
        columns = [("ours", method, binary) for method, binary in ours_columns] + [("peer", p, None) for p in peers]
        times = [[] for _ in columns]  # per column, per round (None past the timeout)
        phases = [[] for _ in columns]
        for _ in range(args.rounds):
            for c, (kind, what, binary) in enumerate(columns):
                if kind == "ours":
                    seconds, detail, phase = ours(binary, ideal, what, args.timeout)
                    label = "ours (%s%s)" % (what, ", before" if binary == args.before else "")
                    if phase:
                        phases[c].append(phase)
                else:
                    seconds, detail = run_peer(what, args, ideal)
                    label = what
                times[c].append(seconds)
                if args.rounds == 1:
                    notes.append("%s, %s: %s" % (name, label, detail))
        cells = [summary(t, args.timeout) for t in times]
        print("| %s | %s |" % (name, " | ".join(cells)), flush=True)
        if args.rounds > 1:
            notes.extend(round_notes(name, columns, times, phases, args.before))
    print()
    for n in notes:
        print("- " + n)


if __name__ == "__main__":
    main()
