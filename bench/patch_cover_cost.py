#!/usr/bin/env python3
"""What trimming a patch to its domain costs: for every parametric surface of
../shared/bench (public and hard) on D = [0, 1]², the cover's leaves, the GLSL lines
of `implicitizer sdf` in both modes, and the single-thread time of a preview of the
trimmed sheet against the untrimmed solid of the same equation in the same box.

    python3 bench/patch_cover_cost.py [--bin build/bin/implicitizer] [--size 96]
        [--runs 3] [--surfaces enneper,tp_22]

The preview is `implicitizer render --size NxN --aa 1 --threads 1 --json` (its
`elapsed_ms`, the best of --runs runs, sheet and solid interleaved), mode fast, both
in the box fitted to the patch. The CPU walk skips the clusters and leaves no nearer
than the best so far, as a GPU that branches per group of pixels does; SwiftShader
runs every leaf, which bench/web/frame_time.mjs measures. Only the ratio within a row
means anything: the times depend on the machine's load. Prints a Markdown table.
"""

import argparse
import json
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(ROOT, "..", "shared", "bench")


def surfaces(names):
    out = []
    for f in ("surfaces_public.json", "surfaces_hard.json"):
        with open(os.path.join(SHARED, f), encoding="utf-8") as handle:
            for s in json.load(handle):
                if "x" in s and (not names or s["name"] in names):
                    out.append(s)
    return out


def run_json(command):
    r = subprocess.run(command, capture_output=True, text=True, check=False)
    if r.returncode != 0:
        raise RuntimeError(" ".join(command[:3]) + ": " + r.stderr.strip()[:200])
    return json.loads(r.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin", "implicitizer"))
    parser.add_argument("--size", type=int, default=96)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--surfaces", default="")
    args = parser.parse_args()
    names = [n for n in args.surfaces.split(",") if n]

    print("| surface | leaves | GLSL lines, fast | GLSL lines, safe | preview ms, sheet / solid | ratio |")
    print("|---|---|---|---|---|---|")
    for s in surfaces(names):
        patch = ["--x", s["x"], "--y", s["y"], "--z", s["z"], "--domain", "0,1,0,1"]
        fast = run_json([args.bin, "sdf", *patch, "--json"])
        safe = run_json([args.bin, "sdf", *patch, "--mode", "safe", "--json"])
        render = [args.bin, "render", *patch, "--size", f"{args.size}x{args.size}", "--aa", "1",
                  "--threads", "1", "--json", "-o", os.devnull]
        sheet = solid = float("inf")
        for _ in range(args.runs):
            sheet = min(sheet, run_json(render)["elapsed_ms"])
            solid = min(solid, run_json(render + ["--shape", "solid"])["elapsed_ms"])
        leaves = fast.get("trimming", {}).get("leaves", "-")
        print(f"| {s['name']} | {leaves} | {fast['glsl'].count(chr(10))} | {safe['glsl'].count(chr(10))} | "
              f"{sheet:.0f} / {solid:.0f} | {sheet / solid:.2f} |", flush=True)


if __name__ == "__main__":
    main()
