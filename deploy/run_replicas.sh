#!/usr/bin/env bash
# Runs two implicitizer-server replicas behind Debian's nginx on loopback, with
# deploy/nginx.conf, and checks the balancing (issue 3, item 11; docs/deploy.md):
#   - /healthz answers through nginx;
#   - distinct bodies are spread: both replicas answer /v1/implicitize requests
#     (their own /metrics counters, read directly from each replica);
#   - an identical body goes to the same replica: the access log names the same
#     upstream for both copies, and the second copy is a hit in that replica's cache;
#   - a body above 1 MiB gets nginx's 413 in the error shape of docs/api.md;
#   - with redis-server installed, the replicas share a Redis job store (issue 22): a
#     job submitted through nginx is polled through nginx (whichever replica
#     answers) until done, and its event stream comes through nginx;
#   - everything stops cleanly (replicas exit 0 on SIGTERM, nginx on SIGQUIT).
# Exit 0: all checks passed; 1: a check failed; 77: nginx is not installed (ctest
# reports the test as skipped).
#
# usage: deploy/run_replicas.sh [SERVER_BINARY]   (default build/bin/implicitizer-server)
# Needs no root: nginx runs in the foreground with a temporary prefix holding its
# config, pid, logs and temp files, on ports above 1023. KEEP_LOGS=1 keeps that
# directory.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/.." && pwd)
SERVER=${1:-${SERVER:-$root/build/bin/implicitizer-server}}
NGINX=${NGINX:-$(command -v nginx || echo /usr/sbin/nginx)}
REDIS_SERVER=${REDIS_SERVER:-$(command -v redis-server || true)}

die() { echo "run_replicas: FAIL: $*" >&2; exit 1; }
say() { echo "run_replicas: $*" >&2; }

if [[ ! -x "$NGINX" ]]; then
  echo "run_replicas: SKIP: nginx not installed (Debian package nginx)" >&2
  exit 77
fi
command -v curl >/dev/null 2>&1 || die "curl not found"
command -v python3 >/dev/null 2>&1 || die "python3 not found (picks nginx's free port)"
[[ -x "$SERVER" ]] || die "no server binary at $SERVER"

work=$(mktemp -d "${TMPDIR:-/tmp}/implicitizer-deploy.XXXXXX")
# As root, nginx's workers run as nobody: they must be able to enter the prefix.
chmod 755 "$work"
mkdir -p "$work/logs" "$work/temp"

replica_pids=()
nginx_pid=
redis_pid=
cleanup() {
  local pid
  if [[ -n "$nginx_pid" ]]; then kill -QUIT "$nginx_pid" 2>/dev/null || true; fi
  for pid in "${replica_pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  if [[ -n "$nginx_pid" ]]; then wait "$nginx_pid" 2>/dev/null || true; fi
  for pid in "${replica_pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [[ -n "$redis_pid" ]]; then kill -TERM "$redis_pid" 2>/dev/null || true; wait "$redis_pid" 2>/dev/null || true; fi
  if [[ "${KEEP_LOGS:-0}" == 1 ]]; then say "logs kept in $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT

# start_replica N: a server on a free port (--port 0; the port is read from the line
# it prints on start). Appends to replica_pids and replica_ports.
replica_ports=()
start_replica() {
  local n=$1 line='' i
  "$SERVER" --host 127.0.0.1 --port 0 --quiet --threads 1 "${store_flags[@]}" \
    >"$work/replica$n.out" 2>"$work/replica$n.err" &
  replica_pids+=($!)
  # Polled for 30 s: a loaded 2-core machine may start a process slowly.
  for i in $(seq 300); do
    line=$(grep -m1 'listening on http://' "$work/replica$n.out" 2>/dev/null || true)
    [[ -n "$line" ]] && break
    kill -0 "${replica_pids[-1]}" 2>/dev/null || die "replica $n exited on start: $(cat "$work/replica$n.err")"
    sleep 0.1
  done
  [[ -n "$line" ]] || die "replica $n did not print its address within 30 s"
  replica_ports+=("${line##*:}")
}

free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

http_code() { curl -s -o /dev/null -w '%{http_code}' --max-time 10 "$@" || true; }

# start_nginx: writes the config with the replicas' ports and a free front port,
# starts nginx in the foreground, waits for /healthz through it. A port taken
# between free_port and nginx's bind is retried with another.
start_nginx() {
  local attempt i
  for attempt in 1 2 3; do
    front_port=$(free_port)
    sed -e "s/127\.0\.0\.1:8081\(.*# replica\)/127.0.0.1:${replica_ports[0]}\1/" \
        -e "s/127\.0\.0\.1:8082\(.*# replica\)/127.0.0.1:${replica_ports[1]}\1/" \
        -e "s/listen 127\.0\.0\.1:8080;\( *# front\)/listen 127.0.0.1:${front_port};\1/" \
        "$here/nginx.conf" >"$work/nginx.conf"
    [[ $(grep -c "127.0.0.1:${replica_ports[0]} .*# replica" "$work/nginx.conf") -eq 2 &&
       $(grep -c "127.0.0.1:${replica_ports[1]} .*# replica" "$work/nginx.conf") -eq 2 &&
       $(grep -c "listen 127.0.0.1:${front_port};" "$work/nginx.conf") -eq 1 ]] \
      || die "deploy/nginx.conf no longer has the marked replica/front lines this script rewrites"
    "$NGINX" -t -q -p "$work/" -c "$work/nginx.conf" 2>"$work/nginx-t.err" || die "nginx -t: $(cat "$work/nginx-t.err")"
    "$NGINX" -p "$work/" -c "$work/nginx.conf" -g 'daemon off;' >"$work/nginx.out" 2>&1 &
    nginx_pid=$!
    front="http://127.0.0.1:$front_port"
    for i in $(seq 300); do
      [[ $(http_code "$front/healthz") == 200 ]] && return 0
      kill -0 "$nginx_pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -QUIT "$nginx_pid" 2>/dev/null || true
    wait "$nginx_pid" 2>/dev/null || true
    nginx_pid=
    say "nginx did not come up on port $front_port (attempt $attempt): $(tail -n 3 "$work/logs/error.log" "$work/nginx.out" 2>/dev/null)"
  done
  die "nginx did not start"
}

# The unit sphere with numerator and denominator multiplied by k: the same surface
# for every k, but a different body, hence a different hash and cache key.
# With PAD > 0 the body ends with PAD spaces of JSON whitespace (larger than nginx's
# default 8-16 KiB client_body_buffer_size, which would send it to a temporary file
# and leave $request_body empty).
sphere_body() {
  local k=$1 pad=${2:-0}
  printf '{"x":"2*%s*s/(%s*(s^2+t^2+1))","y":"2*%s*t/(%s*(s^2+t^2+1))","z":"%s*(s^2+t^2-1)/(%s*(s^2+t^2+1))"%*s}' \
    "$k" "$k" "$k" "$k" "$k" "$k" "$pad" ""
}

# post_through_nginx BODY: POST /v1/implicitize through nginx; prints the X-Cache
# header of a 200 answer (fails otherwise).
post_through_nginx() {
  local headers code
  headers=$(curl -s -D - -o "$work/answer.json" --max-time 30 -X POST \
    -H 'Content-Type: application/json' --data-binary @- "$front/v1/implicitize" <<<"$1") || die "curl failed"
  code=$(head -n1 <<<"$headers" | cut -d' ' -f2)
  [[ "$code" == 200 ]] || die "POST through nginx answered $code: $(cat "$work/answer.json")"
  grep -q '"implicit":"x^2+y^2+z^2-1"' "$work/answer.json" || die "wrong answer: $(cat "$work/answer.json")"
  tr -d '\r' <<<"$headers" | awk -F': ' 'tolower($1) == "x-cache" { print $2 }'
}

# The port of the replica that answered the last /v1/ request, from the access log.
last_upstream_port() {
  grep '"POST /v1/implicitize' "$work/logs/access.log" | tail -n1 | sed -n 's/.*upstream=127\.0\.0\.1:\([0-9]*\) .*/\1/p'
}

implicitize_count() { # PORT: 200 answers of /v1/implicitize counted by that replica
  curl -s --max-time 10 "http://127.0.0.1:$1/metrics" |
    awk '/^implicitizer_http_requests_total\{endpoint="\/v1\/implicitize",status="200"\}/ { n += $2 } END { print n + 0 }'
}

# start_redis: a redis-server on a free loopback port, no persistence; sets store_flags
# so that the replicas share it.
store_flags=()
start_redis() {
  local port i
  port=$(free_port)
  "$REDIS_SERVER" --port "$port" --bind 127.0.0.1 --save '' --appendonly no --dir "$work" \
    >"$work/redis.out" 2>&1 &
  redis_pid=$!
  for i in $(seq 300); do
    python3 -c 'import socket, sys; c = socket.create_connection(("127.0.0.1", int(sys.argv[1])), 1); c.sendall(b"PING\r\n"); sys.exit(0 if c.recv(8).startswith(b"+PONG") else 1)' "$port" 2>/dev/null && break
    kill -0 "$redis_pid" 2>/dev/null || die "redis-server exited: $(cat "$work/redis.out")"
    sleep 0.1
  done
  store_flags=(--store "redis://127.0.0.1:$port" --client-ip-header X-Real-IP)
  say "redis-server on port $port"
}

# check_jobs: a job submitted through nginx, polled through nginx until done, its
# event stream read through nginx.
check_jobs() {
  local answer id i state events
  answer=$(curl -s --max-time 30 -X POST --data-binary \
    '{"kind": "groebner", "request": {"polynomials": ["x^2+y^2-1", "x-y"], "order": "lex"}}' "$front/v1/jobs") \
    || die "job submission failed"
  id=$(python3 -c 'import json, sys; print(json.loads(sys.argv[1])["id"])' "$answer" 2>/dev/null) \
    || die "no job id in $answer"
  for i in $(seq 600); do
    state=$(curl -s --max-time 10 "$front/v1/jobs/$id" || true)
    [[ "$state" == *'"status":"done"'* ]] && break
    sleep 0.1
  done
  [[ "$state" == *'"result":{"basis":["y^2-1/2","x-y"]'* ]] || die "job $id through nginx: $state"
  events=$(curl -s -N --max-time 30 "$front/v1/jobs/$id/events" || true)
  [[ "$events" == *'event: end'*'"status":"done"'* ]] || die "events of job $id through nginx: $events"
  say "a job through nginx: submitted, polled and streamed across the replicas"
}

if [[ -n "$REDIS_SERVER" ]]; then
  start_redis
else
  say "no redis-server: the replicas keep jobs in memory, the jobs check is skipped"
fi
start_replica 1
start_replica 2
start_nginx
say "replicas on ports ${replica_ports[*]}, nginx on $front_port"

# Distinct bodies until each replica has answered at least twice (8 bodies at least,
# 64 at most: with two replicas, 64 bodies all on one would be a broken hash). Each
# body is sent twice; both copies must reach the same replica, the second as a hit.
# Then the same with bodies of 200 KB (in memory thanks to client_body_buffer_size).
declare -A seen=()
sent=0
check_spread() { # PAD FIRST_K
  local pad=$1 k0=$2 k body first_cache first_port second_cache second_port
  local -A here_seen=()
  for k in $(seq "$k0" $((k0 + 63))); do
    body=$(sphere_body "$k" "$pad")
    first_cache=$(post_through_nginx "$body")
    first_port=$(last_upstream_port)
    second_cache=$(post_through_nginx "$body")
    second_port=$(last_upstream_port)
    sent=$((sent + 2))
    [[ -n "$first_port" ]] || die "no upstream in the access log: $(tail -n1 "$work/logs/access.log")"
    [[ "$first_port" == "$second_port" ]] || die "body k=$k went to $first_port, then to $second_port"
    [[ "$first_cache" == miss && "$second_cache" == hit ]] \
      || die "body k=$k: X-Cache $first_cache then $second_cache (expected miss, hit)"
    seen[$first_port]=$(( ${seen[$first_port]:-0} + 1 ))
    here_seen[$first_port]=$(( ${here_seen[$first_port]:-0} + 1 ))
    if (( k >= k0 + 7 && ${here_seen[${replica_ports[0]}]:-0} >= 2 && ${here_seen[${replica_ports[1]}]:-0} >= 2 )); then
      say "bodies of ${#body} bytes: replica ${replica_ports[0]} got ${here_seen[${replica_ports[0]}]}, replica ${replica_ports[1]} got ${here_seen[${replica_ports[1]}]}"
      return 0
    fi
  done
  die "64 distinct bodies of ${#body} bytes did not reach both replicas twice: ${here_seen[*]}"
}
check_spread 0 2
check_spread 200000 1000

# A body above the limit is refused by nginx itself, in the replicas' error shape.
code=$(sphere_body 1 1100000 | curl -s -o "$work/too_large.json" -w '%{http_code}' --max-time 30 \
  -X POST --data-binary @- "$front/v1/implicitize" || true)
if [[ "$code" != 413 ]] || ! grep -q '"code":"body_too_large"' "$work/too_large.json"; then
  die "a 1.1 MB body answered $code: $(head -c 300 "$work/too_large.json")"
fi

count1=$(implicitize_count "${replica_ports[0]}")
count2=$(implicitize_count "${replica_ports[1]}")
say "sent $sent requests ($((sent / 2)) distinct bodies, each twice): replica ${replica_ports[0]} answered $count1, replica ${replica_ports[1]} answered $count2"
(( count1 > 0 && count2 > 0 )) || die "not both replicas answered ($count1, $count2)"
(( count1 + count2 == sent )) || die "the replicas counted $((count1 + count2)) answers, $sent were sent"
(( count1 == 2 * ${seen[${replica_ports[0]}]:-0} )) || die "replica ${replica_ports[0]}'s count disagrees with the access log"

if [[ -n "$REDIS_SERVER" ]]; then check_jobs; fi

# Stop: nginx first (graceful), then the replicas, which must exit 0.
kill -QUIT "$nginx_pid"
wait "$nginx_pid" || die "nginx exited with status $?"
nginx_pid=
for i in "${!replica_pids[@]}"; do
  kill -TERM "${replica_pids[$i]}"
  status=0
  wait "${replica_pids[$i]}" || status=$?
  [[ $status -eq 0 ]] || die "replica $((i + 1)) exited with status $status after SIGTERM"
done
replica_pids=()
say "ok"
