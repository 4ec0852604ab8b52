#!/usr/bin/env bash
# Installs what implicitizer needs on Debian (bookworm): the compiler and CMake, the
# number libraries (GMP, MPFR, FLINT, CGAL), Boost (Beast is header-only inside
# libboost-dev), RapidJSON, libpng (the preview renderer's PNG), SQLite and hiredis
# with redis-server (the jobs API's stores, --store sqlite:PATH | redis://HOST:PORT;
# the tests start their own redis-server on loopback), GoogleTest, the
# oracles the tests compare against (Singular, Macaulay2), Giac's library for the
# peer drivers the benchmarks build (bench/groebner_peers.py), glslang for checking
# generated GLSL, EGL/OpenGL ES and Mesa's drivers for running it on llvmpipe
# (tests/sdf/glsl_execution_test.cpp), Python 3 and clang (libFuzzer, clang-format),
# and for the web client's browser tests (tests/web) Chromium, Node.js and npm, then
# the tests' one npm package (playwright-core, pinned by tests/web/package-lock.json).
#
# Idempotent: asks dpkg which packages are missing and only then runs apt-get, and
# runs `npm ci` only when tests/web/node_modules is missing or was installed from
# another lock file, so a machine that has everything is left alone (no apt-get
# update, no network).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

packages=(
  build-essential cmake make pkg-config g++
  libgmp-dev libmpfr-dev libflint-dev libcgal-dev libeigen3-dev
  libboost-dev rapidjson-dev
  libpng-dev
  libsqlite3-dev libhiredis-dev redis-server
  googletest libgtest-dev libgmock-dev
  singular macaulay2
  libgiac-dev
  glslang-tools
  libegl-dev libgles-dev libgl1-mesa-dri
  python3 python3-yaml
  clang clang-format libclang-rt-dev
  wrk nginx
  chromium fonts-dejavu-core nodejs
)
# Debian's npm, unless an npm is already there: NodeSource's nodejs bundles its own and
# conflicts with Debian's npm package.
command -v npm >/dev/null 2>&1 || packages+=(npm)

# tests/web/node_modules from the lock file: `npm ci` when it is missing or stale (the
# stamp records the lock file it was installed from). playwright-core downloads no
# browser (the tests drive Debian's /usr/bin/chromium).
install_node_modules() {
  local dir="$root/tests/web"
  local lock="$dir/package-lock.json" stamp="$dir/node_modules/.installed-from-lock"
  [[ -f "$lock" ]] || return 0
  if [[ -f "$stamp" ]] && cmp -s "$lock" "$stamp"; then
    return 0
  fi
  if ! command -v npm >/dev/null 2>&1; then
    echo "install-deps: no npm: cannot install tests/web/node_modules (the browser tests will be skipped)" >&2
    return 0
  fi
  echo "install-deps: npm ci in tests/web"
  PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --prefix "$dir" --no-audit --no-fund --loglevel=error
  cp "$lock" "$stamp"
}

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps: not a Debian system (no dpkg/apt-get); install these by hand if the build fails:" >&2
  echo "  ${packages[*]}" >&2
  install_node_modules
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  if [[ "$status" != "install ok installed" ]]; then
    missing+=("$p")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#packages[@]} packages are installed"
  install_node_modules
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
  else
    echo "install-deps: missing packages and not root (and no sudo): ${missing[*]}" >&2
    exit 1
  fi
fi

export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}" </dev/null
echo "install-deps: installed ${missing[*]}"
install_node_modules
