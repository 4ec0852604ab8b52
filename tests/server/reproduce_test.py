#!/usr/bin/env python3
"""The `reproduce` scripts of /v1/implicitize answers, run with the real Singular and
Macaulay2: each must print one generator equal to the server's `implicit` up to a
non-zero scalar. Usage: reproduce_test.py SERVER SINGULAR M2
Registered with ctest as server.reproduce (server/CMakeLists.txt)."""

import os
import re
import subprocess
import sys
import tempfile
from fractions import Fraction

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Server  # noqa: E402

SURFACES = [
    ("unit sphere", {"x": "2*s/(1+s^2+t^2)", "y": "2*t/(1+s^2+t^2)", "z": "(1-s^2-t^2)/(1+s^2+t^2)"}),
    ("paraboloid", {"x": "s", "y": "t", "z": "s^2+t^2"}),
    ("cone", {"x": "s*t", "y": "s*(1-t^2)/(1+t^2)", "z": "s"}),
    ("whitney umbrella", {"x": "u*v", "y": "u", "z": "v^2"}),
    ("enneper", {"x": "3*u+3*u*v^2-u^3", "y": "3*v+3*u^2*v-v^3", "z": "3*u^2-3*v^2"}),
]

TERM = re.compile(r"([+-]?)([^+-]+)")


def parse_expanded(text):
    """An expanded polynomial with rational coefficients (`3/4*x^2*y-z+1`), as a dict
    from exponent tuples over (x, y, z) to Fractions."""
    text = text.replace(" ", "")
    poly = {}
    for sign, body in TERM.findall(text):
        coefficient = Fraction(-1 if sign == "-" else 1)
        exponents = [0, 0, 0]
        for factor in body.split("*"):
            if re.fullmatch(r"\d+(/\d+)?", factor):
                coefficient *= Fraction(factor)
                continue
            name, _, power = factor.partition("^")
            if name not in ("x", "y", "z"):
                raise ValueError("unexpected factor %r in %r" % (factor, text))
            exponents["xyz".index(name)] += int(power or 1)
        key = tuple(exponents)
        poly[key] = poly.get(key, 0) + coefficient
    return {k: v for k, v in poly.items() if v != 0}


def same_up_to_scalar(p, q):
    if not p or set(p) != set(q):
        return False
    key = next(iter(p))
    ratio = q[key] / p[key]
    return all(q[k] == ratio * p[k] for k in p)


def run(command, script, suffix):
    with tempfile.NamedTemporaryFile("w", suffix=suffix, delete=False) as f:
        f.write(script)
    try:
        out = subprocess.run(command + [f.name], capture_output=True, text=True, timeout=120)
        return out.returncode, out.stdout, out.stderr
    finally:
        os.unlink(f.name)


def main():
    server_bin, singular, m2 = sys.argv[1], sys.argv[2], sys.argv[3]
    for tool in (singular, m2):
        if not tool or not os.access(tool, os.X_OK):
            print("missing tool %r (install singular and macaulay2: scripts/install-deps.sh)" % tool)
            return 1
    failures = []
    s = Server(server_bin, "--quiet")
    try:
        for name, surface in SURFACES:
            status, _, body = s.post_json("/v1/implicitize", surface)
            if status != 200:
                failures.append("%s: status %s %r" % (name, status, body))
                continue
            ours = parse_expanded(body["implicit"])
            for system, command, script, suffix in (
                    ("Singular", [singular, "-q"], body["reproduce"]["singular"], ".sing"),
                    ("Macaulay2", [m2, "--script"], body["reproduce"]["macaulay2"], ".m2")):
                code, out, err = run(command, script, suffix)
                lines = [line.strip() for line in out.splitlines() if line.strip()]
                if code != 0 or len(lines) != 1:
                    failures.append("%s/%s: exit %s, output %r, stderr %r" % (name, system, code, out, err[-300:]))
                    continue
                theirs = parse_expanded(lines[0])
                if not same_up_to_scalar(ours, theirs):
                    failures.append("%s/%s: %s != %s" % (name, system, body["implicit"], lines[0]))
                else:
                    print("ok   %-17s %-9s %s" % (name, system, lines[0]))
    finally:
        s.close()
    for f in failures:
        print("FAIL:", f)
    print("%d surfaces, %d failures" % (len(SURFACES), len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
