#!/usr/bin/env bash
# The renderer's per-method table of docs/benchmarks.md ("Preview renderer"): every
# public surface, drawn from its implicit equation in shared/bench/expected/, with
# each marching method (sphere, enhanced, newton, forward_newton, exact), 256×256 at
# AA 1 (65536 primary rays), mode fast, fp32, all cores, the default camera; the
# best of REPEAT runs of `implicitizer render --json` (its elapsed_ms: the render,
# not parsing or compiling). Prints Markdown: a row per surface, a cell per method
# with ms, mean evaluations per primary ray and, where any, the rays out of steps.
#
#   scripts/render-methods-bench.sh [--binary PATH] [--repeat N] [--methods LIST]
#
# Defaults: build/bin/implicitizer, 3 runs, all five methods. Boxes: the default
# [-2, 2]^3, except torus_R2_r1 ([-3, 3]^2 x [-1, 1]) and steiner_roman ([-1/2, 1/2]^3),
# which it frames. Times are only comparable within one run of this script (same
# machine, same load); evaluation counts are deterministic.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
binary="$root/build/bin/implicitizer"
repeat=3
methods="sphere enhanced newton forward_newton exact"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --binary) binary=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --methods) methods=${2//,/ }; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "render-methods-bench.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ -x "$binary" ]] || { echo "render-methods-bench.sh: no executable $binary" >&2; exit 2; }
expected="$root/../shared/bench/expected"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

box_of() {
  case "$1" in
    torus_R2_r1) echo -3,-3,-1,3,3,1 ;;
    steiner_roman) echo -0.5,-0.5,-0.5,0.5,0.5,0.5 ;;
    *) echo -2,-2,-2,2,2,2 ;;
  esac
}

header="| surface | hits |"
rule="|---|---|"
for m in $methods; do header+=" $m |"; rule+="---|"; done
echo "$header"
echo "$rule"
for f in "$expected"/*.txt; do
  name=$(basename "$f" .txt)
  row="| $name |"
  hits=""
  for m in $methods; do
    best=""
    for ((run = 0; run < repeat; ++run)); do
      "$binary" render --implicit "$(cat "$f")" --box="$(box_of "$name")" --size 256x256 --aa 1 \
        --method "$m" -o "$work/out.png" --json >"$work/run.json"
      best=$(python3 - "$work/run.json" "$best" <<'EOF'
import json, sys
j = json.load(open(sys.argv[1]))
line = "%s %s %s %s" % (j["elapsed_ms"], j["mean_evaluations"], j["out_of_steps"], j["hits"])
if not sys.argv[2] or float(sys.argv[2].split()[0]) > j["elapsed_ms"]:
    print(line)
else:
    print(sys.argv[2])
EOF
)
    done
    read -r ms evals oos h <<<"$best"
    [[ -z "$hits" ]] && hits=$h
    cell=$(printf '%.0f ms, %.1f' "$ms" "$evals")
    [[ "$oos" != 0 ]] && cell+=", $oos oos"
    row+=" $cell |"
  done
  echo "| $name | $hits |${row#"| $name |"}"
done
