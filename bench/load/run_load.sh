#!/usr/bin/env bash
# Load benchmark of implicitizer-server (issue 3, item 10). A benchmark, not a test:
# ctest does not run it; `make load` does.
#
# Starts the server on a free loopback port (--port 0) and drives it with wrk for a
# bounded time per scenario:
#   healthz      GET /healthz
#   uncached     POST /v1/implicitize of the unit sphere, a different text every request
#                (implicitize_varied.lua), so every request is computed
#   cached       POST /v1/implicitize of the unit sphere, the same body (one miss, then hits)
#   overload     a second server with 1 worker, a queue of 4 and no cache, hit by many
#                connections posting a slow surface (biquadratic_patch, 10-30 ms);
#                run OVERLOAD_PASSES times, reading the server's VmRSS around each pass
# and prints one Markdown table (throughput, p50/p99 latency, statuses).
#
# It fails (exit 1) when an overload answer is neither 200 nor 503, when wrk reports a
# socket error there, when a server dies or stops answering /healthz, when an uncached
# request hits the cache, or when the overloaded server's RSS keeps growing (see
# check_rss_stable). Times are not checked.
#
# Environment (defaults in brackets):
#   SERVER                 server binary [build/bin/implicitizer-server]
#   DURATION               wrk -d per run [10s]
#   WRK_THREADS            wrk -t [2]
#   CONNECTIONS            wrk -c for healthz/uncached/cached [16]
#   OVERLOAD_CONNECTIONS   wrk -c for the overload runs [64]
#   OVERLOAD_WORKERS       --threads of the overloaded server [1]
#   OVERLOAD_QUEUE         --queue-size of the overloaded server [4]
#   OVERLOAD_PASSES        overload runs on the same server [3]
#   OUT                    also write the table (and the notes) to this file [none]
#   KEEP_LOGS              1: keep the wrk outputs and server logs [0]
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)

SERVER=${SERVER:-$root/build/bin/implicitizer-server}
DURATION=${DURATION:-10s}
WRK_THREADS=${WRK_THREADS:-2}
CONNECTIONS=${CONNECTIONS:-16}
OVERLOAD_CONNECTIONS=${OVERLOAD_CONNECTIONS:-64}
OVERLOAD_WORKERS=${OVERLOAD_WORKERS:-1}
OVERLOAD_QUEUE=${OVERLOAD_QUEUE:-4}
OVERLOAD_PASSES=${OVERLOAD_PASSES:-3}
OUT=${OUT:-}
KEEP_LOGS=${KEEP_LOGS:-0}

die() { echo "run_load: $*" >&2; exit 1; }

command -v wrk >/dev/null 2>&1 || die "wrk not found (Debian package wrk; scripts/install-deps.sh installs it)"
command -v curl >/dev/null 2>&1 || die "curl not found"
[[ -x "$SERVER" ]] || die "no server binary at $SERVER (build it, or set SERVER)"

work=$(mktemp -d "${TMPDIR:-/tmp}/implicitizer-load.XXXXXX")
server_pids=()
cleanup() {
  local pid
  for pid in "${server_pids[@]}"; do
    kill -TERM "$pid" 2>/dev/null || true
  done
  for pid in "${server_pids[@]}"; do
    wait "$pid" 2>/dev/null || true
  done
  if [[ "$KEEP_LOGS" == 1 ]]; then
    echo "run_load: logs kept in $work" >&2
  else
    rm -rf "$work"
  fi
}
trap cleanup EXIT

# start_server NAME FLAGS... : starts the server on a free port; sets server_pid and
# server_url. The port comes from the line the server prints on start.
start_server() {
  local name=$1
  shift
  "$SERVER" --host 127.0.0.1 --port 0 --quiet "$@" >"$work/$name.out" 2>"$work/$name.err" &
  server_pid=$!
  server_pids+=("$server_pid")
  local line=
  for _ in $(seq 100); do
    line=$(grep -m1 'listening on http://' "$work/$name.out" 2>/dev/null || true)
    [[ -n "$line" ]] && break
    kill -0 "$server_pid" 2>/dev/null || die "server $name exited on start: $(cat "$work/$name.err")"
    sleep 0.1
  done
  [[ -n "$line" ]] || die "server $name did not print its address within 10 s"
  server_url=${line##*listening on }
}

# stop_server PID: SIGTERM, then checks the graceful exit status 0.
stop_server() {
  local pid=$1 status=0
  kill -TERM "$pid"
  wait "$pid" || status=$?
  [[ $status -eq 0 ]] || die "server $pid exited with status $status after SIGTERM"
}

rss_kib() { awk '/^VmRSS:/ { print $2 }' "/proc/$1/status"; }

check_alive() {
  local pid=$1 url=$2 what=$3
  kill -0 "$pid" 2>/dev/null || die "server died during $what"
  local code
  code=$(curl -s -o /dev/null -w '%{http_code}' --max-time 5 "$url/healthz" || true)
  [[ "$code" == 200 ]] || die "server does not answer /healthz after $what (got '$code')"
}

# run_wrk NAME CONNECTIONS SCRIPT URL [SCRIPT ARGS...]: one wrk run; its output is
# kept in $work/NAME.wrk and the LOAD* lines of status_counts.lua are parsed into
# the globals r_rps, r_p50, r_p99, r_requests, r_status, r_xcache, r_sockerr.
run_wrk() {
  local name=$1 conns=$2 script=$3 url=$4
  shift 4
  local args=()
  [[ $# -gt 0 ]] && args=(-- "$@")
  echo "run_load: $name: wrk -t$WRK_THREADS -c$conns -d$DURATION -s $(basename "$script") $url ${args[*]} (load average $(cut -d' ' -f1-3 /proc/loadavg))" >&2
  wrk -t"$WRK_THREADS" -c"$conns" -d"$DURATION" --timeout 10s -s "$script" "$url" "${args[@]}" >"$work/$name.wrk" 2>&1 \
    || die "wrk failed on $name: $(cat "$work/$name.wrk")"
  local load
  load=$(grep '^LOAD ' "$work/$name.wrk") || die "no summary from wrk on $name: $(cat "$work/$name.wrk")"
  r_requests=$(sed -n 's/.*requests=\([0-9]*\).*/\1/p' <<<"$load")
  r_rps=$(sed -n 's/.*rps=\([0-9.]*\).*/\1/p' <<<"$load")
  r_p50=$(sed -n 's/.*p50_ms=\([0-9.]*\).*/\1/p' <<<"$load")
  r_p99=$(sed -n 's/.*p99_ms=\([0-9.]*\).*/\1/p' <<<"$load")
  r_status=$(sed -n 's/^LOAD_STATUS //p' "$work/$name.wrk")
  r_xcache=$(sed -n 's/^LOAD_XCACHE //p' "$work/$name.wrk")
  r_sockerr=$(sed -n 's/^LOAD_SOCKET_ERRORS //p' "$work/$name.wrk")
}

rows=()
add_row() { # scenario connections [extra]
  rows+=("| $1 | $2 | $r_requests | $r_rps | $r_p50 | $r_p99 | $r_status | $r_xcache | $r_sockerr | ${3:-} |")
}

# --- (a), (b): one server with the default pool, queue and cache ----------------------
start_server main
main_pid=$server_pid
main_url=$server_url
main_rss_start=$(rss_kib "$main_pid")

run_wrk healthz "$CONNECTIONS" "$here/status_counts.lua" "$main_url/healthz"
check_alive "$main_pid" "$main_url" healthz
add_row "GET /healthz" "$CONNECTIONS"

run_wrk uncached "$CONNECTIONS" "$here/implicitize_varied.lua" "$main_url/v1/implicitize"
check_alive "$main_pid" "$main_url" "uncached implicitize"
[[ "$r_xcache" =~ ^miss=[0-9]+$ ]] || die "uncached run hit the cache: $r_xcache"
[[ "$r_status" =~ ^200=[0-9]+$ ]] || die "uncached run answered other than 200: $r_status"
add_row "POST /v1/implicitize, sphere, uncached" "$CONNECTIONS"

run_wrk cached "$CONNECTIONS" "$here/implicitize.lua" "$main_url/v1/implicitize" sphere
check_alive "$main_pid" "$main_url" "cached implicitize"
[[ "$r_status" =~ ^200=[0-9]+$ ]] || die "cached run answered other than 200: $r_status"
add_row "POST /v1/implicitize, sphere, cached" "$CONNECTIONS"

main_rss_end=$(rss_kib "$main_pid")
stop_server "$main_pid"

# --- (c): overload beyond the queue --------------------------------------------------
start_server overload --threads "$OVERLOAD_WORKERS" --queue-size "$OVERLOAD_QUEUE" --cache-size 0
over_pid=$server_pid
over_url=$server_url
rss_list=("$(rss_kib "$over_pid")")
for pass in $(seq "$OVERLOAD_PASSES"); do
  run_wrk "overload$pass" "$OVERLOAD_CONNECTIONS" "$here/implicitize.lua" "$over_url/v1/implicitize" biquadratic
  # Statuses other than 200 and 503, or sockets the server broke, are the failure
  # this scenario looks for.
  [[ "$r_status" =~ ^(200=[0-9]+)?\ ?(503=[0-9]+)?$ ]] || die "overload pass $pass: statuses other than 200/503: $r_status"
  [[ "$r_sockerr" == "connect=0 read=0 write=0 timeout=0" ]] || die "overload pass $pass: socket errors: $r_sockerr"
  check_alive "$over_pid" "$over_url" "overload pass $pass"
  rss_list+=("$(rss_kib "$over_pid")")
  add_row "overload pass $pass: biquadratic_patch, --threads $OVERLOAD_WORKERS --queue-size $OVERLOAD_QUEUE --cache-size 0" \
    "$OVERLOAD_CONNECTIONS" "RSS after: ${rss_list[-1]} KiB"
done
rejections=$(curl -s --max-time 5 "$over_url/metrics" | awk '/^implicitizer_queue_rejections_total/ { print $2 }')
stop_server "$over_pid"

# RSS after the first pass (allocator arenas and connection buffers warmed up)
# against after the last: stable means less than 10 % and 4 MiB more.
check_rss_stable() {
  local first=${rss_list[1]} last=${rss_list[-1]}
  if (( last > first + first / 10 && last > first + 4096 )); then
    echo "GROWING"
  else
    echo "stable"
  fi
}
rss_verdict=$(check_rss_stable)

report() {
  echo "Server: $SERVER"
  echo "Commit: $(git -C "$root" log -1 --format='%h %s' 2>/dev/null || echo unknown)$(git -C "$root" diff --quiet 2>/dev/null || echo ' (plus uncommitted changes)')"
  echo "wrk: $(wrk --version 2>&1 | head -1 | cut -d' ' -f1-2), -t$WRK_THREADS -d$DURATION; nproc $(nproc); load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
  echo "| scenario | connections | requests | req/s | p50 ms | p99 ms | statuses | X-Cache | wrk socket errors | note |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  printf '%s\n' "${rows[@]}"
  echo
  echo "Default server VmRSS: ${main_rss_start} KiB at start, ${main_rss_end} KiB after the three runs."
  echo "Overloaded server VmRSS (KiB): start ${rss_list[0]}, after each pass ${rss_list[*]:1} -> $rss_verdict; 503 overloaded (metrics): ${rejections:-?}."
}
report
[[ -n "$OUT" ]] && report >"$OUT"
[[ "$rss_verdict" == stable ]] || die "the overloaded server's RSS keeps growing: ${rss_list[*]} KiB"
echo "run_load: ok" >&2
