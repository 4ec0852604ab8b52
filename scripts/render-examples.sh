#!/usr/bin/env bash
# Renders the example images of docs/render.md ("Gallery"): every public surface of
# shared/bench/surfaces_public.json (given parametrically: --x --y --z, implicitized by
# the library) and the second thesis's scenes (bench/scenes/*.json), with
# `implicitizer render`, 256×256, AA 2, method sphere, mode safe, into
# docs/images/<name>.png.
#
#   scripts/render-examples.sh [--binary PATH] [--out DIR] [--surfaces FILE]
#
# Defaults: --binary build/bin/implicitizer, --out docs/images,
# --surfaces ../shared/bench/surfaces_public.json. Each surface is framed by the box
# the benchmarks use (bench/render_accuracy.cpp, tests/sdf/reference_distance.hpp's
# public_surface_box): [-4, 4]^3 for the torus and Enneper's surface, [-1, 1]^3 for
# Steiner's, [-2, 6]x[-4, 4]^2 for the biquadratic patch, [-2, 2]^3 otherwise.
#
# Idempotent: the renderer is deterministic (an image does not depend on the number
# of threads), so a second run rewrites the same bytes; each line says whether the
# file is new, changed or unchanged, and the command that made it. Exit status 1 if
# any render fails (the others are still made).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
binary="$root/build/bin/implicitizer"
out="$root/docs/images"
surfaces="$root/../shared/bench/surfaces_public.json"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --binary) binary=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --surfaces) surfaces=$2; shift 2 ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    *) echo "render-examples.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
if [[ ! -x "$binary" ]]; then
  echo "render-examples.sh: no executable $binary (build it: cmake --build build --target implicitizer)" >&2
  exit 2
fi
[[ -r "$surfaces" ]] || { echo "render-examples.sh: cannot read $surfaces" >&2; exit 2; }
mkdir -p "$out"
cd "$root"  # so that the commands printed name bench/scenes/… relative to the repository

common=(--size 256x256 --aa 2 --method sphere --mode safe)
failed=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# box_of NAME: the --box argument for a public surface ("" for the default box).
box_of() {
  case "$1" in
    torus_R2_r1|enneper) echo "-4,-4,-4,4,4,4" ;;
    steiner_roman) echo "-1,-1,-1,1,1,1" ;;
    biquadratic_patch) echo "-2,-4,-4,6,4,4" ;;
    *) echo "" ;;
  esac
}

# render NAME ARGS...: renders into a temporary file, then replaces docs/images/NAME.png
# only if the bytes differ, and reports what it did.
render() {
  local name=$1
  shift
  local target="$out/$name.png" tmp="$work/$name.png" status
  if ! "$binary" render "$@" "${common[@]}" -o "$tmp" 2>"$work/$name.log"; then
    echo "FAILED  $name: $(tail -n 3 "$work/$name.log" | tr '\n' ' ')" >&2
    failed=1
    return
  fi
  if [[ ! -e "$target" ]]; then
    status=new
  elif cmp -s "$tmp" "$target"; then
    status=unchanged
  else
    status=changed
  fi
  [[ "$status" == unchanged ]] || cp "$tmp" "$target"
  printf '%-9s %s  (%s)\n' "$status" "${target#"$root"/}" "$(sed -n 's/^wrote [^ ]* (\(.*\))$/\1/p' "$work/$name.log")"
  local words=() word
  for word in "$@" "${common[@]}"; do
    if [[ "$word" =~ ^[A-Za-z0-9_./,+=-]+$ ]]; then words+=("$word"); else words+=("'$word'"); fi
  done
  echo "          implicitizer render ${words[*]} -o ${target#"$root"/}"
}

# The public surfaces, one "name<TAB>x<TAB>y<TAB>z" line each (Python 3 reads the JSON).
while IFS=$'\t' read -r name x y z; do
  box=$(box_of "$name")
  if [[ -n "$box" ]]; then
    render "$name" --x "$x" --y "$y" --z "$z" --box "$box"
  else
    render "$name" --x "$x" --y "$y" --z "$z"
  fi
done < <(python3 -c '
import json, sys
for s in json.load(open(sys.argv[1])):
    print("\t".join([s["name"], s["x"], s["y"], s["z"]]))
' "$surfaces")

for scene in rounded_box tunnel five_spheres; do
  render "$scene" --scene "bench/scenes/$scene.json"
done

total=$(du -cb "$out"/*.png | tail -n 1 | cut -f 1)
echo "docs/images: $(ls "$out"/*.png | wc -l) images, $total bytes"
exit $failed
