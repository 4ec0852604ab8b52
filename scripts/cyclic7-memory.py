#!/usr/bin/env python3
"""Issue 16's memory reproducer: cyclic-7 in lex by Buchberger on a 60 s budget
(it held 1.8 GB before memory had a limit), sent to a server started with
--max-memory-mb 512 and to one with the default limit. Prints the status, the error,
the answer time, the server's peak RSS and its RSS 2 s after the answer (freed memory
given back by malloc_trim). About 75 s. Not a test: docs/api.md ("Reliability") has a
run. Usage: scripts/cyclic7-memory.py build/bin/implicitizer-server"""

import os
import sys
import time

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "server"))
from server_harness import Server  # noqa: E402


def rss_mib(server, field):
    with open("/proc/%d/status" % server.proc.pid) as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1]) // 1024
    return -1


variables = "abcdefg"
cyclic7 = ["+".join("*".join(variables[(i + j) % 7] for j in range(k)) for i in range(7)) for k in range(1, 7)]
cyclic7.append("a*b*c*d*e*f*g-1")
for flags in (["--max-memory-mb", "512"], []):
    server = Server(sys.argv[1], "--quiet", *flags)
    try:
        start = time.monotonic()
        status, _, body = server.post_json("/v1/groebner", {"polynomials": cyclic7, "order": "lex",
                                                            "method": "buchberger", "timeout_ms": 60000}, timeout=200)
        seconds = time.monotonic() - start
        peak = rss_mib(server, "VmHWM")
        time.sleep(2)  # not synchronisation: the RSS a while after the answer is the measurement
        error = (body or {}).get("error", {})
        print("%-22s %d %s %.1f s, peak RSS %d MiB, %d MiB after: %s"
              % (" ".join(flags) or "default limit", status, error.get("code", "ok"), seconds, peak,
                 rss_mib(server, "VmRSS"), error.get("message", "")[:100]))
    finally:
        server.close()
