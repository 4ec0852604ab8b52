#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with Debian's clang in a build directory of
# their own (the main build uses g++) and runs each for a bounded time, starting from
# the seed corpus in fuzz/corpus/<target>/. See docs/fuzzing.md.
#
#   scripts/fuzz.sh [--seconds N] [--build-dir DIR] [--jobs N] [TARGET ...]
#
# --seconds is per target (default 20: `make test` runs this). New corpus entries go
# to DIR/corpus/<target>/ (the seeds in the source tree are only read); a crash,
# sanitizer report, leak or timeout leaves DIR/artifacts/<target>/crash-… (or
# leak-…, timeout-…, oom-…) and makes the script exit 1. Without a clang that can
# link -fsanitize=fuzzer the script says so and exits 0, so that `make test` still
# passes on a machine without clang.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
seconds=20
build_dir="$root/build-fuzz"
jobs=2
targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seconds) seconds=$2; shift 2 ;;
    --build-dir) build_dir=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[[ ${#targets[@]} -gt 0 ]] || targets=(parser_fuzzer request_fuzzer)
[[ "$build_dir" = /* ]] || build_dir="$PWD/$build_dir"

cc=${FUZZ_CC:-clang}
cxx=${FUZZ_CXX:-clang++}
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' >"$probe/probe.cpp"
if ! command -v "$cxx" >/dev/null 2>&1 \
    || ! "$cxx" -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" >/dev/null 2>&1; then
  echo "fuzz.sh: SKIPPED: $cxx cannot link -fsanitize=fuzzer (install clang and libclang-rt-dev: make deps)"
  exit 0
fi

if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  CC=$cc CXX=$cxx cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DIMPLICITIZER_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
fi
cmake --build "$build_dir" --target "${targets[@]}" -j"$jobs" >/dev/null

status=0
for target in "${targets[@]}"; do
  corpus="$build_dir/corpus/$target"
  artifacts="$build_dir/artifacts/$target"
  log="$build_dir/$target.log"
  mkdir -p "$corpus" "$artifacts"
  dict=()
  [[ -f "$root/fuzz/$target.dict" ]] && dict=(-dict="$root/fuzz/$target.dict")
  # -timeout: one input may take 10 s (the targets' own budgets stop at 0.5 s);
  # -rss_limit_mb: a memory blow-up is a finding, not a machine in swap.
  # -seed: FUZZ_SEED fixes the mutation sequence (make test sets 1, so that CI
  # replays the same short run); unset or 0 means a random seed, as libFuzzer does.
  set +e
  "$build_dir/bin/$target" -seed="${FUZZ_SEED:-0}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -print_final_stats=1 "${dict[@]}" -artifact_prefix="$artifacts/" "$corpus" "$root/fuzz/corpus/$target" \
    >"$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  # No coverage line when a seed fails before the first report: grep's status must
  # not end the script (pipefail) before it names the artifact.
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1 || true)
  units=$(find "$corpus" -type f | wc -l)
  if [[ $rc -eq 0 ]]; then
    echo "fuzz.sh: $target: ok, ${seconds}s, ${runs:-?} runs (${speed:-?}/s), ${cov:-cov ?}, corpus $units files"
  else
    status=1
    echo "fuzz.sh: $target: FAILED (exit $rc); log $log; artifacts:" >&2
    ls -1 "$artifacts" >&2 || true
    grep -m1 -A25 -E '^==[0-9]+==ERROR|runtime error|parser_fuzzer:|request_fuzzer:|deadly signal|uncaught exception' "$log" >&2 || tail -30 "$log" >&2
  fi
done
exit $status
