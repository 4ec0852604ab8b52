#!/usr/bin/env bash
# Installs what implicitizer needs on Debian (bookworm): the compiler and CMake, the
# number libraries (GMP, MPFR, FLINT, CGAL), Boost (Beast is header-only inside
# libboost-dev), RapidJSON, libpng (the preview renderer's PNG), GoogleTest, the
# oracles the tests compare against (Singular, Macaulay2), glslang for checking
# generated GLSL, EGL/OpenGL ES and Mesa's drivers for running it on llvmpipe
# (tests/sdf/glsl_execution_test.cpp), Python 3 and clang (libFuzzer, clang-format).
#
# Idempotent: asks dpkg which packages are missing and only then runs apt-get, so a
# machine that has everything is left alone (no apt-get update, no network).
set -euo pipefail

packages=(
  build-essential cmake make pkg-config g++
  libgmp-dev libmpfr-dev libflint-dev libcgal-dev
  libboost-dev rapidjson-dev
  libpng-dev
  googletest libgtest-dev libgmock-dev
  singular macaulay2
  glslang-tools
  libegl-dev libgles-dev libgl1-mesa-dri
  python3 python3-yaml
  clang clang-format libclang-rt-dev
  wrk nginx
)

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps: not a Debian system (no dpkg/apt-get); install these by hand if the build fails:" >&2
  echo "  ${packages[*]}" >&2
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
