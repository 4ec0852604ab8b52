#!/usr/bin/env bash
# Renders the example images of docs/render.md ("Gallery"): every example of the web
# page's menu (clients/web/examples.json: the public surfaces of shared/bench, given
# parametrically, and the page's own bicubic patch and plane curve) and the second
# thesis's scenes (bench/scenes/*.json), with `implicitizer render`, 256×256, AA 2,
# method sphere, mode safe, into docs/images/<name>.png.
#
#   scripts/render-examples.sh [--binary PATH] [--out DIR] [--examples FILE]
#
# Defaults: --binary build/bin/implicitizer, --out docs/images,
# --examples clients/web/examples.json. Each example is drawn as the patch X(D) over
# its domain (examples.json "domain"; absent: the default domain, docs/sdf.md
# "Patches") in the box the library fits to the patch, with shape auto: so the
# gallery shows what the page's menu shows, and one table (scripts/make-web-examples.mjs)
# says which domain each surface gets.
#
# Idempotent: the renderer is deterministic (an image does not depend on the number
# of threads), so a second run rewrites the same bytes; each line says whether the
# file is new, changed or unchanged, and the command that made it. Exit status 1 if
# any render fails (the others are still made).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
binary="$root/build/bin/implicitizer"
out="$root/docs/images"
examples="$root/clients/web/examples.json"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --binary) binary=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --examples) examples=$2; shift 2 ;;
    -h|--help) sed -n '2,21p' "$0"; exit 0 ;;
    *) echo "render-examples.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
if [[ ! -x "$binary" ]]; then
  echo "render-examples.sh: no executable $binary (build it: cmake --build build --target implicitizer)" >&2
  exit 2
fi
[[ -r "$examples" ]] || { echo "render-examples.sh: cannot read $examples" >&2; exit 2; }
mkdir -p "$out"
cd "$root"  # so that the commands printed name bench/scenes/… relative to the repository

common=(--size 256x256 --aa 2 --method sphere --mode safe)
failed=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

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

# The examples, one "name<TAB>x<TAB>y<TAB>z<TAB>domain" line each (Python 3 reads the
# JSON; z and domain may be empty: a plane curve, the default domain).
while IFS=$'\t' read -r name x y z domain; do
  args=(--x "$x" --y "$y")
  [[ -n "$z" ]] && args+=(--z "$z")
  [[ -n "$domain" ]] && args+=(--domain "$domain")
  render "$name" "${args[@]}"
done < <(python3 -c '
import json, sys
for e in json.load(open(sys.argv[1]))["examples"]:
    print("\t".join([e["name"], e["x"], e["y"], e.get("z", ""), ",".join(e.get("domain", []))]))
' "$examples")

for scene in rounded_box tunnel five_spheres; do
  render "$scene" --scene "bench/scenes/$scene.json"
done

total=$(du -cb "$out"/*.png | tail -n 1 | cut -f 1)
echo "docs/images: $(ls "$out"/*.png | wc -l) images, $total bytes"
exit $failed
