#!/usr/bin/env python3
"""Two builds of implicitizer-bench side by side on `--routes`: the two binaries run
the same command alternately (OLD first, then NEW first, and so on) RUNS times each,
so that both see the same load; prints a Markdown row per surface and route with the
median over the runs of each binary's time and their ratio (NEW / OLD), then the
geometric mean of the ratios per route, and whether the columns that are not times
(matrix and primes of each route, the route auto took, the answers) agree between
the builds in every run. Compare ratios, not times across runs.
Usage: scripts/compare-bench-routes.py OLD/bin/implicitizer-bench NEW/bin/implicitizer-bench RUNS [BENCH FLAGS]
(for example --suite public --budget 20; --routes --markdown --no-singular are added).
Its runs for issue 17 (one lift across primes) are in the history of docs/benchmarks.md."""

import re
import statistics
import subprocess
import sys

old, new, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
flags = sys.argv[4:]
ROUTES = ["groebner", "resultant", "interpolation", "auto"]
SHAPE = ["resultant matrix", "interpolation matrix", "auto took", "answers"]
MS_PER_UNIT = {"ns": 1e-6, "µs": 1e-3, "ms": 1.0, "s": 1000.0}


def milliseconds(cell):
    """The time of a cell such as "1.96 ms", or None ("> 60 s", "base points", "—")."""
    m = re.match(r"^([\d.]+) (ns|µs|ms|s)$", cell)
    return float(m.group(1)) * MS_PER_UNIT[m.group(2)] if m else None


def table(binary):
    """The rows of one run, by surface: {column: cell}."""
    out = subprocess.run([binary, "--routes", "--markdown", "--no-singular"] + flags, capture_output=True,
                         text=True, check=True).stdout
    header, rows = None, {}
    for line in out.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("| surface"):
            header = cells
        elif header and line.startswith("| ") and not line.startswith("| ---"):
            rows[cells[0]] = dict(zip(header, cells))
    return rows


times = {"old": {}, "new": {}}
shapes = {"old": {}, "new": {}}
for run in range(runs):
    for label, binary in ([("old", old), ("new", new)] if run % 2 == 0 else [("new", new), ("old", old)]):
        for surface, row in table(binary).items():
            for route in ROUTES:
                times[label].setdefault((surface, route), []).append(milliseconds(row[route]))
            shapes[label].setdefault(surface, set()).add(tuple(row[c] for c in SHAPE))
    print(f"run {run + 1} of {runs} done", file=sys.stderr, flush=True)

print("| surface | route | old (median) | new (median) | new / old |")
print("| --- | --- | --- | --- | --- |")
ratios = {route: [] for route in ROUTES}
for (surface, route), values in times["old"].items():
    o = [v for v in values if v is not None]
    n = [v for v in times["new"].get((surface, route), []) if v is not None]
    if not o or not n:
        continue
    mo, mn = statistics.median(o), statistics.median(n)
    ratios[route].append(mn / mo)
    print(f"| {surface} | {route} | {mo:.3f} ms | {mn:.3f} ms | {mn / mo:.2f} |")
print()
for route, r in ratios.items():
    if r:
        print(f"- {route}: geometric mean of new / old {statistics.geometric_mean(r):.3f} over {len(r)} surfaces")
surfaces = set(shapes["old"]) | set(shapes["new"])
differ = [s for s in surfaces if shapes["old"].get(s) != shapes["new"].get(s)]
print(f"- matrix, primes, auto's route and answers: {'identical' if not differ else 'differ on ' + ', '.join(differ)}")
