#!/usr/bin/env python3
"""End-to-end tests of implicitizer-server: the real binary on an ephemeral loopback
port, spoken to over real sockets (no mocks). Usage: server_test.py PATH/TO/implicitizer-server
Registered with ctest as server.integration (server/CMakeLists.txt)."""

import json
import os
import socket
import sys
import tempfile
import threading
import time
import traceback

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import LOAD_ALLOWANCE_S, Checks, Server, decode_png, error_code, pixel  # noqa: E402

BIN = sys.argv[1]
SPHERE = {"x": "2*s/(1+s^2+t^2)", "y": "2*t/(1+s^2+t^2)", "z": "(1-s^2-t^2)/(1+s^2+t^2)"}
# Takes far longer than any timeout used here (> 15 s by Buchberger, which it forces:
# it has base points, so auto would take the same route anyway).
SLOW = {"x": "s^3+t^2*s", "y": "t^3-s", "z": "s*t^2+t^4", "method": "groebner"}
SECRET = "top-secret-outside-static"
CHECKS = Checks()
check = CHECKS.check
failures = CHECKS.failures


def make_static_tree():
    base = tempfile.mkdtemp(prefix="implicitizer-static-")
    root = os.path.join(base, "web")
    os.makedirs(os.path.join(root, "sub"))
    with open(os.path.join(root, "index.html"), "w") as f:
        f.write("<!doctype html><title>t</title>home")
    with open(os.path.join(root, "app.js"), "w") as f:
        f.write("console.log(1);")
    with open(os.path.join(base, "secret.txt"), "w") as f:
        f.write(SECRET)
    os.symlink(os.path.join(base, "secret.txt"), os.path.join(root, "escape.txt"))
    os.symlink(base, os.path.join(root, "escape_dir"))
    return base, root


# ---- the main server ------------------------------------------------------

def test_healthz_and_static(s):
    status, headers, body = s.request("GET", "/healthz")
    check(status == 200 and json.loads(body) == {"status": "ok"}, "healthz: %s %r" % (status, body))
    check(headers.get("content-type") == "application/json", "healthz content type")
    status, headers, body = s.request("HEAD", "/healthz")
    check(status == 200 and body == b"" and headers.get("content-length") == "15", "HEAD /healthz")
    status, headers, body = s.request("GET", "/")
    check(status == 200 and b"home" in body and headers["content-type"].startswith("text/html"), "GET /")
    status, headers, body = s.request("GET", "/app.js")
    check(status == 200 and headers["content-type"].startswith("text/javascript"), "GET /app.js")


def test_implicitize_sphere(s):
    status, headers, body = s.post_json("/v1/implicitize", SPHERE)
    check(status == 200, "sphere status %s %r" % (status, body))
    check(body["implicit"] == "x^2+y^2+z^2-1", "sphere equation %r" % body.get("implicit"))
    check(body["verified"] is True and body["degree"] == 2 and body["variables"] == ["x", "y", "z"],
          "sphere verified/degree/variables")
    # Degree ≤ 4: auto's first rule answers by interpolation (docs/algorithms.md).
    check(body["method"] == "interpolation" and isinstance(body["elapsed_ms"], (int, float)), "sphere method, elapsed")
    check(body["stats"].get("route") == "interpolation: the degree is at most 4, tried first", "sphere route")
    for key in ("pairs", "product_criterion", "chain_criterion", "reductions", "zero_reductions"):
        check(key in body["stats"], "stats has " + key)
    check("eliminate" in body["reproduce"]["singular"] and "eliminate" in body["reproduce"]["macaulay2"],
          "reproduce scripts")
    check(headers.get("x-cache") == "miss", "first sphere request misses the cache")


def test_implicitize_routes_and_curves(s):
    status, _, body = s.post_json("/v1/implicitize", {"x": "t^2-1", "y": "t^3-t"})
    check(status == 200 and body.get("implicit") == "x^3+x^2-y^2" and body.get("variables") == ["x", "y"]
          and body.get("method") == "resultant", "plane curve without z: %s %r" % (status, body))
    status, _, body = s.post_json("/v1/implicitize", dict(SPHERE, method="resultant"))
    check(status == 422 and error_code(body) == "base_points", "base points refused: %s %r" % (status, body))
    status, _, body = s.post_json("/v1/implicitize", {"x": "s*t", "y": "s", "z": "t", "method": "resultant"})
    check(status == 200 and body.get("stats", {}).get("resultant", {}).get("formulation") == "dixon",
          "bilinear patch by Dixon: %s %r" % (status, body))
    status, _, body = s.post_json("/v1/implicitize", {"x": "s", "y": "t", "z": "u", "method": "resultant"})
    check(status == 400 and error_code(body) == "method_not_applicable", "three parameters: %s %r" % (status, body))


def test_sdf(s):
    status, headers, body = s.post_json("/v1/sdf", {"implicit": "x^2+y^2+z^2-1", "name": "ball"})
    check(status == 200 and body.get("function") == "ball_sdf" and "float ball_sdf(vec3 p)" in body.get("glsl", "")
          and "pow" not in body.get("glsl", "") and body.get("mode") == "fast" and body.get("degree") == 2
          and body.get("box") == [-2, -2, -2, 2, 2, 2], "sdf sphere: %s %r" % (status, body))
    check(headers.get("x-cache") == "miss", "first sdf request misses the cache")
    status, _, body = s.post_json("/v1/sdf", {"implicit": "x^2+y^2+z^2-1e-12", "box": [-1e-6, -1e-6, -1e-6,
                                                                                       1e-6, 1e-6, 1e-6]})
    check(status == 200 and body.get("box", [0])[0] == -1e-6, "sdf tiny box: %s %r" % (status, body))
    status, _, body = s.post_json("/v1/sdf", {"implicit": "x^2+y^2+z^2-1", "mode": "safe", "name": "ball"})
    check(status == 200 and body.get("mode") == "safe" and "float ball_sdf(vec3 p)" in body.get("glsl", "")
          and "safe distance bound" in body.get("glsl", "") and "pow" not in body.get("glsl", ""),
          "sdf safe sphere: %s %r" % (status, body))
    scene = {"type": "smooth_union", "k": 0.3, "children": [
        {"type": "sphere", "radius": 1, "name": "ball", "uniforms": ["radius"]},
        {"type": "translate", "offset": [1.5, 0, 0], "child": {"type": "torus", "major": 1, "minor": 0.25}}]}
    status, _, body = s.post_json("/v1/sdf", {"scene": scene, "name": "demo", "mode": "safe"})
    glsl = body.get("glsl", "")
    check(status == 200 and body.get("function") == "demo_sdf" and "float demo_sdf(vec3 p)" in glsl
          and "uniform float ball_radius;" in glsl and "demo_torus" in glsl and "demo_box" not in glsl
          and body.get("nodes") == 4 and body.get("uniforms") == [{"name": "ball_radius", "type": "float", "default": 1.0}],
          "sdf scene: %s %r" % (status, body))
    # The deepest scene the decoder accepts nests 2 JSON levels per node: more than
    # the other endpoints' 32 levels.
    deep = {"type": "sphere", "radius": 1}
    for _ in range(40):
        deep = {"type": "translate", "offset": [0.01, 0, 0], "child": deep}
    status, _, body = s.post_json("/v1/sdf", {"scene": deep})
    check(status == 200 and body.get("nodes") == 41, "sdf deep scene: %s %r" % (status, str(body)[:200]))
    for request, code, field in [({"implicit": "x^2", "name": "a(){}; void b"}, "invalid_name", "name"),
                                 ({"implicit": "x^60+y", "mode": "safe"}, "degree_too_high", "implicit"),
                                 ({"implicit": "x^2", "mode": "exact"}, "invalid_value", "mode"),
                                 ({"implicit": "x^2", "scene": {}}, "invalid_value", "scene"),
                                 ({"scene": {"type": "sphere"}}, "missing_parameter", "scene.radius"),
                                 ({"scene": {"type": "union", "children": [{"type": "sphere", "radius": 1},
                                                                            {"type": "cube"}]}},
                                  "unknown_node_type", "scene.children[1].type"),
                                 ({"scene": {"type": "sphere", "radius": 1, "name": "a; } void main() {"}},
                                  "invalid_name", "scene.name"),
                                 # Issue 16: "gl" would give gl_sdf, gl_sphere, gl_radius (reserved).
                                 ({"scene": {"type": "sphere", "radius": 1}, "name": "gl"}, "invalid_name", "name"),
                                 ({"implicit": "x^2+y^2+z^2-1", "name": "gl"}, "invalid_name", "name"),
                                 ({"scene": {"type": "sphere", "radius": 1, "name": "gl", "uniforms": ["radius"]}},
                                  "invalid_name", "scene.name"),
                                 ({"implicit": "x^2+s"}, "unknown_variable", "implicit"),
                                 ({"implicit": "x^2", "box": [0, 0, 0, 1, 1]}, "invalid_box", "box"),
                                 ({"x": "s", "y": "t", "z": "s*t", "domain": [0, 1, 0]}, "invalid_domain", "domain"),
                                 ({"x": "s", "y": "t", "z": "s*t", "domain": [0, 1, 1, 1]}, "invalid_domain",
                                  "domain[2]"),
                                 ({"x": "s", "y": "t", "z": "s*t", "domain": [0, "1/0", 0, 1]}, "invalid_domain",
                                  "domain[1]"),
                                 ({"implicit": "x^2+y^2+z^2-1", "domain": [0, 1]}, "invalid_domain", "domain"),
                                 ({"implicit": "x^2+y^2+z^2-1", "shape": "hollow"}, "invalid_value", "shape"),
                                 ({"scene": {"type": "sphere", "radius": 1}, "shape": "sheet"}, "invalid_value",
                                  "shape"),
                                 ({"scene": {"type": "parametric", "x": "s", "y": "t", "z": "s*t",
                                             "domain": [[0, 1], [1, 0]]}}, "invalid_domain", "scene.domain[1]"),
                                 ({"x": "s", "z": "t"}, "missing_field", "y")]:
        status, _, body = s.post_json("/v1/sdf", request)
        check(status == 400 and error_code(body) == code and body["error"].get("field") == field,
              "sdf %r: %s %r" % (request, status, body))
    # Issue 18: a patch, its fitted box and the shape picked; the domain and the shape
    # are part of the cache key.
    patch = {"x": "s", "y": "t", "z": "s*t", "domain": [0, 1, 0, 1]}
    status, headers, body = s.post_json("/v1/sdf", patch)
    check(status == 200 and body.get("shape") == "sheet" and body.get("dimension") == 3 and headers.get("x-cache") ==
          "miss" and [round(b, 9) for b in body.get("box", [])] == [-0.0001, -0.0001, -0.0001, 1.0001, 1.0001, 1.0001],
          "sdf patch: %s %r" % (status, {k: v for k, v in body.items() if k != "glsl"}))
    status, headers, body = s.post_json("/v1/sdf", dict(patch, domain=[0, 1, 0, 0.5]))
    check(status == 200 and headers.get("x-cache") == "miss" and round(body["box"][4], 9) == 0.5001,
          "sdf patch, another domain: not the cached answer: %s %r" % (status, headers))
    status, headers, _ = s.post_json("/v1/sdf", dict(patch, shape="solid"))
    check(headers.get("x-cache") == "miss", "sdf patch, another shape: not the cached answer %r" % headers)
    status, _, body = s.post_json("/v1/sdf", {"x": "t", "y": "t^2", "z": "t^3"})
    check(status == 422 and error_code(body) == "no_single_equation" and len(body["error"].get("generators", [])) == 3,
          "sdf space curve: %s %r" % (status, body))


def test_tolerance(s):
    # Issue 19: Enneper's surface approximated within a tolerance of its box's diagonal
    # (one low-degree piece is shorter GLSL than its exact equation); the tolerance is
    # part of the cache key; bad ones are 400 invalid_tolerance by name.
    patch = {"x": "s-s^3/3+s*t^2", "y": "t-t^3/3+s^2*t", "z": "s^2-t^2", "domain": [0, 1, 0, 1]}
    status, headers, body = s.post_json("/v1/sdf", dict(patch, tolerance=0.01))
    a = body.get("approximation", {}) if status == 200 else {}
    check(status == 200 and headers.get("x-cache") == "miss" and a.get("tolerance") == 0.01 and a.get("exact") is False
          and a.get("glsl_lines") == len(body["glsl"].splitlines()) and a["patch_to_surface"]["bound"] <= 0.01
          and a["surface_to_patch"]["bound"] <= 0.01 and body.get("degree") == a.get("degree"),
          "sdf tolerance: %s %r" % (status, a or body))
    status, headers, _ = s.post_json("/v1/sdf", dict(patch, tolerance=0.02))
    check(status == 200 and headers.get("x-cache") == "miss", "sdf, another tolerance: not the cached answer")
    status, headers, body = s.post_json("/v1/sdf", patch)
    check(status == 200 and headers.get("x-cache") == "miss" and "approximation" not in body,
          "sdf without a tolerance: the exact answer, not the cached approximation")
    status, headers, _ = s.post_json("/v1/sdf", dict(patch, tolerance=0.01))
    check(status == 200 and headers.get("x-cache") == "hit", "sdf tolerance repeated: a hit %r" % headers)
    for request, field in [(dict(patch, tolerance=0), "tolerance"), (dict(patch, tolerance=-1), "tolerance"),
                           (dict(patch, tolerance=0.6), "tolerance"), (dict(patch, tolerance="1e-3"), "tolerance"),
                           ({"implicit": "x^2+y^2+z^2-1", "tolerance": 0.01}, "tolerance"),
                           ({"scene": {"type": "sphere", "radius": 1}, "tolerance": 0.01}, "tolerance"),
                           ({"scene": {"type": "implicit", "equation": "x", "tolerance": 0.01}}, "scene.tolerance")]:
        for path in ("/v1/sdf", "/v1/render"):
            status, _, body = s.post_json(path, request)
            check(status == 400 and error_code(body) == "invalid_tolerance" and body["error"].get("field") == field,
                  "%s %r: %s %r" % (path, request, status, body))
    # Below double's rounding no approximation exists; the exact equation meets it.
    status, _, body = s.post_json("/v1/sdf", {"x": "s", "y": "t", "z": "s*t^2", "domain": [0, 1, 0, 1],
                                              "tolerance": 1e-300})
    a = body.get("approximation", {}) if status == 200 else {}
    check(status == 200 and a.get("exact") is True and body.get("degree") == 3 and "exact" in a.get("reason", ""),
          "sdf tolerance beyond any approximation: %s %r" % (status, body))
    status, headers, data = s.request("POST", "/v1/render", dict(patch, tolerance=0.01, width=24, height=24, aa=1),
                                      {"Content-Type": "application/json"})
    check(status == 200 and headers.get("x-render-tolerance") == "0.01" and int(headers.get("x-render-pieces", 0)) >= 1
          and (headers.get("x-render-patch-to-surface", "") + " ?").split()[1] in ("certified", "measured")
          and int(headers.get("x-render-hits", 0)) > 0, "render tolerance headers: %s %r" % (status, headers))


def test_render(s):
    import base64
    status, headers, data = s.request("POST", "/v1/render", {"implicit": "x^2+y^2+z^2-1", "width": 40, "height": 30,
                                                             "aa": 1}, {"Content-Type": "application/json"})
    check(status == 200 and headers.get("content-type") == "image/png", "render: %s %r" % (status, headers))
    width, height, rows = decode_png(data)
    check((width, height) == (40, 30), "render size %dx%d" % (width, height))
    grey = bytes((242, 242, 242))
    check(pixel(rows, 0, 0) == grey, "render background is the seed's grey 0.95: %r" % (pixel(rows, 0, 0),))
    check(pixel(rows, 20, 15) != grey, "render: the sphere is in the middle")
    rays, hits = int(headers.get("x-render-rays", -1)), int(headers.get("x-render-hits", -1))
    background = sum(1 for y in range(height) for x in range(width) if pixel(rows, x, y) == grey)
    check(rays == 1200 and background == rays - hits and headers.get("x-render-method") == "sphere"
          and float(headers.get("x-render-mean-evaluations", 0)) > 1, "render headers: %r" % headers)
    # The JSON variant: the same image in base64, with the statistics.
    status, _, body = s.post_json("/v1/render", {"x": "s*t", "y": "s", "z": "t^2", "width": 24, "height": 24,
                                                 "method": "exact", "format": "json"})
    check(status == 200 and body.get("method") == "exact" and body.get("rays") == 24 * 24 * 4,
          "render json: %s %r" % (status, str(body)[:300]))
    if status == 200:
        check(decode_png(base64.b64decode(body["png_base64"]))[:2] == (24, 24), "render json: the PNG decodes")
    for request, want_status, want_code in [
            ({"implicit": "x^2+y^2+z^2-1", "width": 4096, "height": 4096}, 413, "render_too_large"),
            ({"scene": {"type": "sphere", "radius": 1}, "method": "exact"}, 400, "method_not_applicable"),
            ({"implicit": "x^2+y^2+z^2-1", "method": "bisection"}, 400, "invalid_value"),
            ({"implicit": "x^2+y^2+z^2-1", "eye": [0, 0, 0]}, 400, "invalid_camera"),
            ({"implicit": "x^2+", "width": 8}, 400, "unexpected_end"),
            ({"x": "s", "z": "t"}, 400, "missing_field"),
            ({"x": "s", "y": "t", "z": "s*t", "domain": [0, 1, 1, 0]}, 400, "invalid_domain"),
            ({"implicit": "x^2+y^2+z^2-1", "shape": "hollow"}, 400, "invalid_value"),
            ({"x": "t", "y": "t^2", "z": "t^3"}, 422, "no_single_equation")]:
        status, _, body = s.post_json("/v1/render", request)
        check(status == want_status and error_code(body) == want_code,
              "render %r: %s %r" % (request, status, body))


def test_cache(s):
    hits = s.metric("implicitizer_cache_hits_total")
    # Same request, other key order, spacing and timeout: the same canonical request.
    body = '{ "z": "%s", "y": "%s", "x": "%s", "timeout_ms": 9000 }' % (SPHERE["z"], SPHERE["y"], SPHERE["x"])
    status, headers, data = s.request("POST", "/v1/implicitize", body)
    check(status == 200 and headers.get("x-cache") == "hit", "repeated request is a cache hit: %s" % headers)
    check(json.loads(data)["implicit"] == "x^2+y^2+z^2-1", "cached answer")
    check(s.metric("implicitizer_cache_hits_total") == hits + 1, "metrics count the hit")
    check(s.metric("implicitizer_cache_entries") >= 1, "metrics show the cache size")


def test_groebner(s):
    status, _, body = s.post_json("/v1/groebner", {"polynomials": ["x^2+y^2-1", "x-y"], "order": "lex"})
    check(status == 200 and body["basis"] == ["y^2-1/2", "x-y"] and body["order"] == "lex", "groebner %r" % body)
    check(set(body["stats"]) >= {"pairs", "product_criterion", "chain_criterion", "reductions", "zero_reductions"},
          "groebner stats")
    status, _, body = s.post_json("/v1/groebner", {"polynomials": ["x-s^2", "y-s^3"], "variables": ["s", "x", "y"],
                                                   "eliminate": ["s"]})
    check(status == 200 and body.get("elimination_ideal") == ["x^3-y^2"], "groebner elimination %r" % body)
    # The labelled unproven mode: never served from an exact answer's cache entry, nor
    # an exact request from its entry.
    katsura = {"polynomials": ["a+2*b+2*c-1", "a^2+2*b^2+2*c^2-a", "2*a*b+2*b*c-b"], "method": "f4"}
    status, headers, exact = s.post_json("/v1/groebner", katsura)
    check(status == 200 and exact["proven"] is True and exact["stats"]["modular"]["random_primes"] == [],
          "groebner proven by default %r" % exact)
    status, headers, unproven = s.post_json("/v1/groebner", dict(katsura, proof="random_primes"))
    check(status == 200 and headers.get("x-cache") == "miss", "an unproven request misses the exact answer: %s" % headers)
    check(unproven["proven"] is False and unproven["basis"] == exact["basis"]
          and len(unproven["stats"]["modular"]["random_primes"]) == 2, "groebner unproven %r" % unproven)
    status, headers, again = s.post_json("/v1/groebner", katsura)
    check(status == 200 and headers.get("x-cache") == "hit" and again["proven"] is True, "the exact answer stays cached")
    status, _, body = s.post_json("/v1/groebner", dict(katsura, proof="probably"))
    check(status == 400 and body["error"]["code"] == "unknown_proof" and body["error"]["field"] == "proof",
          "unknown proof %r" % body)


# Degrees 12 and 11 in t with dense coefficients: minutes of work, so any timeout here stops it.
SLOW_RESULTANT = {"polynomials": ["(x+y+z+1)^6*t^12+(x-y)^5*t^7+x*y*z*t+1",
                                  "(x-2*y+z)^6*t^11+(y+z)^4*t^5+x*t^2+7"], "variable": "t"}


def test_resultant(s):
    request = {"polynomials": ["t^2+x", "y*t+1"], "variable": "t"}
    status, headers, body = s.post_json("/v1/resultant", request)
    check(status == 200 and body.get("resultant") == "x*y^2+1", "resultant: %s %r" % (status, body))
    check(body.get("variables") == ["x", "y"] and body.get("degree") == 3 and body.get("method") == "subresultant"
          and isinstance(body.get("elapsed_ms"), (int, float)), "resultant fields: %r" % body)
    check(headers.get("x-cache") == "miss", "first resultant misses the cache")
    status, headers, again = s.post_json("/v1/resultant", dict(request, timeout_ms=5000))
    check(status == 200 and headers.get("x-cache") == "hit" and again == body, "repeated resultant is a cache hit")
    # Exact rationals, and a variable that is not the last one.
    status, _, body = s.post_json("/v1/resultant", {"polynomials": ["3/2*t+1/3", "t^2-1/5"], "variable": "t"})
    check(status == 200 and body.get("resultant") == "-61/180" and body.get("degree") == 0, "rational: %r" % body)
    status, _, body = s.post_json("/v1/resultant", {"polynomials": ["x^2+y", "x-y*z"], "variable": "x"})
    check(status == 200 and body.get("resultant") == "y^2*z^2+y" and body.get("variables") == ["y", "z"],
          "eliminating x: %r" % body)
    status, _, body = s.post_json("/v1/resultant", {"polynomials": ["(t-x)*(t+1)", "(t-x)*y"], "variable": "t"})
    check(status == 200 and body.get("resultant") == "0" and body.get("degree") == -1, "common factor: %r" % body)

    cases = [
        (b'{"polynomials": ["t"], "variable": "t"}', "wrong_number_of_polynomials", "polynomials"),
        (b'{"polynomials": ["t", "x", "y"], "variable": "t"}', "wrong_number_of_polynomials", "polynomials"),
        (b'{"polynomials": ["t", "x"]}', "missing_field", "variable"),
        (b'{"variable": "t"}', "missing_field", "polynomials"),
        (b'{"polynomials": ["t", 2], "variable": "t"}', "wrong_type", "polynomials[1]"),
        (b'{"polynomials": ["t", "x"], "variable": "t", "var": "t"}', "unknown_field", "var"),
        (b'{"polynomials": ["t", "x"], "variable": "s"}', "unknown_variable", "variable"),
        (b'{"polynomials": ["t", "x"], "variable": "2t"}', "invalid_variables", "variable"),
        (b'{"polynomials": ["t", "1/x"], "variable": "t"}', "non_constant_denominator", "polynomials[1]"),
        (b'{"polynomials": ["t", "x"], "variable": "t", "timeout_ms": -5}', "invalid_value", "timeout_ms"),
        (b'{"polynomials": ["t", "x"], "variable": ', "invalid_json", None),
    ]
    for raw, code, field in cases:
        status, _, data = s.request("POST", "/v1/resultant", raw)
        err = json.loads(data).get("error", {})
        check(status == 400 and err.get("code") == code and err.get("field") == field,
              "resultant %r: %s %r, want %s in %s" % (raw[:50], status, err, code, field))
    _, _, data = s.request("POST", "/v1/resultant", b'{"polynomials": ["t+x", "t+*y"], "variable": "t"}')
    err = json.loads(data)["error"]
    check(err.get("code") == "unexpected_token" and err.get("position") == 2 and err.get("field") == "polynomials[1]",
          "resultant parse error position: %r" % err)

    start = time.time()
    status, _, body = s.post_json("/v1/resultant", dict(SLOW_RESULTANT, timeout_ms=300))
    check(status == 504 and error_code(body) == "time_limit_exceeded", "resultant timeout: %s %r" % (status, body))
    check(time.time() - start < 0.3 + 1 + LOAD_ALLOWANCE_S,
          "resultant timeout answered in %.1f s" % (time.time() - start))


def test_input_errors(s):
    cases = [
        (b'{"x": "s", "y": ', "invalid_json"),
        (b'[1, 2]', "wrong_type"),
        (b'{"x": 1, "y": "t", "z": "s"}', "wrong_type"),
        (b'{"x": "s", "z": "t"}', "missing_field"),
        (b'{"x": "s", "y": "t", "z": "s", "colour": 1}', "unknown_field"),
        (b'{"x": "s", "x": "s", "y": "t", "z": "s"}', "duplicate_field"),
        (b'[' * 5000 + b']' * 5000, "json_too_deep"),
        (b'{"x": "\xff\xfe", "y": "t", "z": "s"}', "invalid_json"),
        (b'{"x": "s", "y": "t", "z": "s", "timeout_ms": -1}', "invalid_value"),
        (b'{"x": "s^", "y": "t", "z": "s"}', None),  # a parse error of the expression
        (b'{"x": "s", "y": "t", "z": "s", "method": "magic"}', "unknown_method"),
        (b'', "invalid_json"),
    ]
    for body, code in cases:
        status, headers, data = s.request("POST", "/v1/implicitize", body, {"Content-Type": "application/json"})
        parsed = json.loads(data)
        check(status == 400, "%r: status %s" % (body[:40], status))
        check(code is None or error_code(parsed) == code, "%r: code %r, want %r" % (body[:40], parsed, code))
        check(isinstance(parsed["error"].get("message"), str), "%r: message" % body[:40])
    _, _, data = s.request("POST", "/v1/implicitize", b'{"x": "s", "y": ')
    check(json.loads(data)["error"].get("position") == 16, "invalid JSON position: %r" % data)
    _, _, data = s.request("POST", "/v1/implicitize", b'{"x": "s+*t", "y": "t", "z": "s"}')
    err = json.loads(data)["error"]
    check(err.get("position") == 2 and err.get("field") == "x", "expression error position: %r" % err)


def test_trigonometric(s):
    """Issue 20: cos/sin/tan/cosh/sinh/tanh made rational, the answer says how; what
    cannot be made rational is a 400 with its code, position, field and function name."""
    accepted = [
        ({"x": "cos(u)*cos(v)", "y": "cos(u)*sin(v)", "z": "sin(u)"}, "x^2+y^2+z^2-1", ["tu", "tv"]),
        ({"x": "(2+cos(v))*cos(u)", "y": "(2+cos(v))*sin(u)", "z": "sin(v)", "parameters": ["u", "v"]},
         "x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9", ["tu", "tv"]),
        ({"x": "cosh(u)*cos(v)", "y": "cosh(u)*sin(v)", "z": "sinh(u)"}, "x^2+y^2-z^2-1", ["eu", "tv"]),
        ({"x": "cos(2*t)", "y": "sin(t)"}, "2*y^2+x-1", ["tt"]),
        ({"x": "cos(t)^3", "y": "sin(t)^3"},
         "x^6+3*x^4*y^2+3*x^2*y^4+y^6-3*x^4+21*x^2*y^2-3*y^4+3*x^2+3*y^2-1", ["tt"]),
    ]
    for request, implicit, parameters in accepted:
        status, _, body = s.post_json("/v1/implicitize", request)
        check(status == 200 and body.get("implicit") == implicit and body.get("verified") is True,
              "%r: %s %r" % (request, status, body))
        rational = body.get("rational_parametrization", {})
        check(rational.get("parameters") == parameters and all(k in rational for k in request if k in "xyz"),
              "%r: rational parametrization %r" % (request, rational))
        check([sub["variable"] for sub in body.get("substitution", [])] == parameters
              and "made rational by" in body["reproduce"]["singular"], "%r: substitution %r" % (request, body))
    # The rational parametrization given back is accepted as input and gives the same equation.
    _, _, body = s.post_json("/v1/implicitize", accepted[0][0])
    rational = body["rational_parametrization"]
    status, _, again = s.post_json("/v1/implicitize", {"x": rational["x"], "y": rational["y"], "z": rational["z"],
                                                       "parameters": rational["parameters"]})
    check(status == 200 and again.get("implicit") == "x^2+y^2+z^2-1" and "substitution" not in again,
          "rational form round trip: %s %r" % (status, again))
    refused = [
        ({"x": "u*cos(u)", "y": "sin(u)", "z": "v"}, "parameter_inside_and_outside", "x", 2, "cos"),
        ({"x": "s", "y": "cos(s*t)", "z": "t"}, "nonlinear_argument", "y", 0, "cos"),
        ({"x": "cos(u/2)", "y": "sin(u)"}, "non_integer_argument", "x", 0, "cos"),
        ({"x": "cos(u)*cosh(u)", "y": "u"}, "parameter_inside_and_outside", "x", 0, "cos"),
        ({"x": "cos(u)*cosh(u)", "y": "sin(u)"}, "mixed_function_kinds", "x", 7, "cosh"),
        ({"x": "s", "y": "t", "z": "sqrt(s)"}, "function_not_rational", "z", 0, "sqrt"),
        ({"x": "exp(s)", "y": "t", "z": "s"}, "function_not_rational", "x", 0, "exp"),
        ({"x": "s", "y": "1+log(t)", "z": "s"}, "function_not_rational", "y", 2, "log"),
        ({"x": "s", "y": "t", "z": "foo(s)"}, "unknown_function", "z", 0, "foo"),
    ]
    for request, code, field, position, name in refused:
        status, _, body = s.post_json("/v1/implicitize", request)
        err = body.get("error", {})
        check(status == 400 and err.get("code") == code and err.get("field") == field
              and err.get("position") == position and ("'%s'" % name) in err.get("message", ""),
              "%r: %s %r" % (request, status, body))
    status, _, body = s.post_json("/v1/groebner", {"polynomials": ["cos(x)+y"]})
    check(status == 400 and error_code(body) == "function_not_allowed", "groebner with cos: %s %r" % (status, body))
    # A patch's domain is in the input's parameters (angles): the arc 0 <= t <= 1.5 of the
    # unit circle lies in x >= cos(1.5) > 0; read as tan(t/2) in [0, 1.5] it would reach x < 0.
    status, _, body = s.post_json("/v1/sdf", {"x": "cos(t)", "y": "sin(t)", "domain": [0, 1.5]})
    box = body.get("box", [])
    check(status == 200 and len(box) == 4 and 0 < box[0] < 0.08 and 0.99 < box[3] < 1.0,
          "arc in angles: %s %r" % (status, box))
    status, _, body = s.post_json("/v1/sdf", {"x": "cos(t)", "y": "sin(t)", "domain": [0, 3.5]})
    err = body.get("error", {})
    check(status == 400 and err.get("code") == "domain_out_of_range" and err.get("field") == "domain",
          "angle beyond pi: %s %r" % (status, body))


def test_semantic_errors(s):
    status, _, body = s.post_json("/v1/implicitize", {"x": "t", "y": "t^2", "z": "t^3"})
    check(status == 422 and error_code(body) == "no_single_equation", "curve: %s %r" % (status, body))
    start = time.time()
    status, _, body = s.post_json("/v1/implicitize", dict(SLOW, timeout_ms=300))
    elapsed = time.time() - start
    check(status == 504 and error_code(body) == "time_limit_exceeded", "timeout: %s %r" % (status, body))
    check(elapsed < 0.3 + 1 + LOAD_ALLOWANCE_S, "timeout answered in %.1f s" % elapsed)


def test_routing_errors(s):
    for path in ("/v1/nope", "/nope.html", "/v1"):
        status, _, body = s.request("GET", path)
        check(status == 404 and error_code(json.loads(body)) == "not_found", "404 %s: %s" % (path, status))
    status, headers, body = s.request("GET", "/v1/implicitize")
    check(status == 405 and headers.get("allow") == "POST, OPTIONS", "405 GET implicitize: %s %s" % (status, headers))
    check(error_code(json.loads(body)) == "method_not_allowed", "405 body")
    status, headers, _ = s.request("DELETE", "/healthz")
    check(status == 405 and headers.get("allow") == "GET, HEAD, OPTIONS", "405 DELETE healthz")
    status, headers, _ = s.request("PUT", "/index.html", b"x")
    check(status == 405, "405 PUT static: %s" % status)


def test_size_limits(s, max_body):
    big = b'{"x": "' + b"s+" * max_body + b's", "y": "t", "z": "s"}'
    status, _, data = s.request("POST", "/v1/implicitize", big)
    check(status == 413 and error_code(json.loads(data)) == "body_too_large", "413 body: %s %r" % (status, data[:80]))
    # The header alone announces too much: answered before the body is sent.
    raw = s.raw(b"POST /v1/groebner HTTP/1.1\r\nHost: x\r\nContent-Length: %d\r\n\r\n" % (max_body * 10))
    check(raw.startswith(b"HTTP/1.1 413"), "413 from Content-Length: %r" % raw[:40])
    status, _, data = s.request("GET", "/healthz", headers={"X-Big": "a" * 20000})
    check(status == 431 and error_code(json.loads(data)) == "headers_too_large", "431: %s" % status)
    raw = s.raw(b"GARBAGE\r\n\r\n")
    check(raw.startswith(b"HTTP/1.1 400") and b'"bad_request"' in raw, "malformed HTTP: %r" % raw[:60])
    status, _, body = s.post_json("/v1/groebner", {"polynomials": ["x^100000"]})
    check(status == 400 and error_code(body) == "exponent_too_large", "exponent limit: %s %r" % (status, body))


def read_until(sock, marker=None, limit=1 << 20):
    """Bytes received until `marker` has arrived (None: until the peer closes), the
    peer closed, or `limit` bytes; the socket's own timeout bounds every wait."""
    data = b""
    while (marker is None or marker not in data) and len(data) < limit:
        chunk = sock.recv(4096)
        if not chunk:
            break
        data += chunk
    return data


def test_expect_continue(s, max_body):
    # Issue 16: a client that sends `Expect: 100-continue` waits for the interim 100
    # before it sends the body; without it, it waited for its own timeout.
    body = json.dumps({"polynomials": ["x^2+y^2-1", "x-y"], "order": "lex"}).encode()
    with socket.create_connection(("127.0.0.1", s.port), timeout=10) as sock:
        sock.sendall(b"POST /v1/groebner HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                     b"Expect: 100-Continue\r\nConnection: close\r\nContent-Length: %d\r\n\r\n" % len(body))
        interim = read_until(sock, b"\r\n\r\n")
        check(interim == b"HTTP/1.1 100 Continue\r\n\r\n", "Expect: 100-continue gets the interim 100: %r"
              % interim[:80])
        sock.sendall(body)
        final = read_until(sock)  # until the server closes
    head, _, data = final.partition(b"\r\n\r\n")
    check(head.startswith(b"HTTP/1.1 200") and json.loads(data).get("basis") == ["y^2-1/2", "x-y"],
          "the answer after 100 Continue: %r" % final[:200])
    # A declared body above --max-body-bytes is refused at once: 413, never 100, and
    # the client need not send the body.
    with socket.create_connection(("127.0.0.1", s.port), timeout=10) as sock:
        sock.sendall(b"POST /v1/groebner HTTP/1.1\r\nHost: x\r\nExpect: 100-continue\r\n"
                     b"Content-Length: %d\r\n\r\n" % (max_body + 1))
        answer = read_until(sock)
    check(answer.startswith(b"HTTP/1.1 413") and b"100 Continue" not in answer and b'"body_too_large"' in answer,
          "Expect with a too large Content-Length gets 413 without 100: %r" % answer[:120])
    # Nothing to continue: a request without a body is answered directly.
    with socket.create_connection(("127.0.0.1", s.port), timeout=10) as sock:
        sock.sendall(b"GET /healthz HTTP/1.1\r\nHost: x\r\nExpect: 100-continue\r\nConnection: close\r\n\r\n")
        answer = read_until(sock)
    check(answer.startswith(b"HTTP/1.1 200") and b"100 Continue" not in answer,
          "Expect without a body: no 100: %r" % answer[:80])


def test_path_traversal(s):
    targets = ["/../secret.txt", "/sub/../../secret.txt", "/%2e%2e/secret.txt", "/%2E%2E/%2E%2E/secret.txt",
               "/..%2fsecret.txt", "/..%5csecret.txt", "/escape.txt", "/escape_dir/secret.txt",
               "/%2fetc%2fpasswd", "//etc/passwd", "/app.js%00", "/.%2e/secret.txt"]
    for target in targets:
        raw = s.raw(b"GET " + target.encode() + b" HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        status = raw[9:12]
        check(status in (b"400", b"404") and SECRET.encode() not in raw,
              "traversal %s answered %r" % (target, raw[:60]))
    raw = s.raw(b"GET http://evil/secret.txt HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
    check(raw[9:12] == b"400", "absolute-form target: %r" % raw[:40])


def test_slow_headers_dropped(s, read_timeout_s):
    with socket.create_connection(("127.0.0.1", s.port), timeout=10) as sock:
        sock.sendall(b"GET /healthz HTTP/1.1\r\nHost: x\r\n")  # never finishes the header
        start = time.time()
        data = sock.recv(1024)
        elapsed = time.time() - start
    check(data == b"" and read_timeout_s * 0.5 < elapsed < read_timeout_s + LOAD_ALLOWANCE_S,
          "slow headers dropped after %.2f s (got %r)" % (elapsed, data[:40]))
    # Trickling bytes does not help: the timeout covers the whole header.
    with socket.create_connection(("127.0.0.1", s.port), timeout=10) as sock:
        start = time.time()
        closed = False
        for ch in b"GET /healthz HTTP/1.1\r\nX-Slow: " + b"a" * 100:
            try:
                sock.sendall(bytes([ch]))
            except OSError:
                closed = True
                break
            time.sleep(0.1)
            if time.time() - start > read_timeout_s + LOAD_ALLOWANCE_S:
                break
        if not closed:
            try:
                closed = sock.recv(1024) == b""
            except OSError:
                closed = True
        check(closed and time.time() - start < read_timeout_s + LOAD_ALLOWANCE_S, "trickling client dropped")


def test_keep_alive_cap(s, cap):
    import http.client
    conn = http.client.HTTPConnection("127.0.0.1", s.port, timeout=10)
    closes = []
    for _ in range(cap):
        conn.request("GET", "/healthz")
        r = conn.getresponse()
        r.read()
        closes.append(r.getheader("Connection"))
    conn.close()
    check(closes[:-1] == [None] * (cap - 1) and closes[-1] == "close", "keep-alive cap: %r" % closes)


def test_cors(s):
    status, headers, _ = s.request("OPTIONS", "/v1/implicitize", headers={
        "Origin": "https://example.org", "Access-Control-Request-Method": "POST",
        "Access-Control-Request-Headers": "content-type"})
    check(status == 204 and headers.get("access-control-allow-origin") == "*"
          and "POST" in headers.get("access-control-allow-methods", "")
          and "Content-Type" in headers.get("access-control-allow-headers", ""), "preflight: %s %s" % (status, headers))
    status, headers, _ = s.request("POST", "/v1/groebner", b'{"polynomials": ["x"]}',
                                   {"Origin": "https://example.org", "Content-Type": "application/json"})
    check(status == 200 and headers.get("access-control-allow-origin") == "*", "CORS on POST")
    # A page on another origin reads the render statistics from the headers.
    exposed = [h.strip().lower() for h in headers.get("access-control-expose-headers", "").split(",")]
    check("x-render-rays" in exposed and "x-render-mean-evaluations" in exposed and "x-cache" in exposed,
          "CORS exposes the X-Render-* headers: %r" % exposed)


def test_disconnect_cancels(s):
    before = s.metric("implicitizer_computations_cancelled_total")
    body = json.dumps(dict(SLOW, timeout_ms=30000)).encode()
    with socket.create_connection(("127.0.0.1", s.port), timeout=10) as sock:
        sock.sendall(b"POST /v1/implicitize HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                     b"Content-Length: %d\r\n\r\n" % len(body) + body)
        # Leave once the computation runs (polled: a loaded machine may take a while).
        deadline = time.time() + 30
        while time.time() < deadline and s.metric("implicitizer_workers_busy") == 0:
            time.sleep(0.02)
    start = time.time()
    while time.time() < start + 30 and s.metric("implicitizer_computations_cancelled_total") == before:
        time.sleep(0.1)
    _, _, text = s.request("GET", "/metrics")
    outcomes = [line for line in text.decode().splitlines() if line.startswith("implicitizer_computations_total")]
    check(s.metric("implicitizer_computations_cancelled_total") == before + 1,
          "disconnect cancels the computation (after %.1f s): %s" % (time.time() - start, outcomes))
    # The outcome is counted just before the worker is released: allow it a moment.
    deadline = time.time() + 30
    while time.time() < deadline and s.metric("implicitizer_workers_busy") != 0:
        time.sleep(0.05)
    check(s.metric("implicitizer_workers_busy") == 0, "the worker is free again")


def test_concurrent_clients(s, n=64):
    results = [None] * n

    def client(k):
        try:
            status, _, body = s.post_json("/v1/implicitize", {"x": "s", "y": "t", "z": "s^2+%d*t^2" % (k + 2)})
            results[k] = (status, body.get("implicit"))
        except Exception as e:  # noqa: BLE001 - reported as a failure below
            results[k] = ("exception", repr(e))

    threads = [threading.Thread(target=client, args=(k,)) for k in range(n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(120)
    wrong = [(k, r) for k, r in enumerate(results) if r != (200, "x^2+%d*y^2-z" % (k + 2))]
    check(not wrong, "%d concurrent clients, wrong answers: %r" % (n, wrong[:5]))


def test_metrics_format(s):
    status, headers, body = s.request("GET", "/metrics")
    text = body.decode()
    check(status == 200 and headers["content-type"].startswith("text/plain"), "metrics status/type")
    for needle in ('implicitizer_http_requests_total{endpoint="/v1/implicitize",status="200"}',
                   'implicitizer_http_requests_total{endpoint="other",status="404"}',
                   'implicitizer_http_request_duration_seconds_bucket{endpoint="/healthz",le="+Inf"}',
                   'implicitizer_computation_duration_seconds_count{endpoint="/v1/implicitize"}',
                   "# TYPE implicitizer_queue_depth gauge", "implicitizer_cache_misses_total",
                   "implicitizer_queue_rejections_total"):
        check(needle in text, "metrics contain " + needle)
    for line in text.splitlines():
        if line and not line.startswith("#"):
            name_labels, value = line.rsplit(" ", 1)
            try:
                float(value)
            except ValueError:
                check(False, "metrics line with a non-numeric value: " + line)


# ---- a server with one worker and a queue of one ---------------------------

def test_overload():
    s = Server(BIN, "--threads", "1", "--queue-size", "1", "--retry-after", "2", "--quiet")
    try:
        body = json.dumps(dict(SLOW, timeout_ms=20000)).encode()
        socks = []
        for _ in range(2):  # one runs, one waits
            sock = socket.create_connection(("127.0.0.1", s.port), timeout=30)
            sock.sendall(b"POST /v1/implicitize HTTP/1.1\r\nHost: x\r\nContent-Length: %d\r\n\r\n" % len(body) + body)
            socks.append(sock)
        deadline = time.time() + 30
        while time.time() < deadline and s.metric("implicitizer_queue_depth") != 1:
            time.sleep(0.05)
        check(s.metric("implicitizer_queue_depth") == 1, "one computation runs and one waits")
        status, headers, data = s.post_json("/v1/implicitize", dict(SLOW, timeout_ms=20000))
        check(status == 503 and headers.get("retry-after") == "2" and error_code(data) == "overloaded",
              "full queue: %s %s %r" % (status, headers, data))
        status, _, _ = s.request("GET", "/healthz")
        check(status == 200, "healthz answers while the workers are busy")
        for sock in socks:
            sock.close()
        check(s.metric("implicitizer_queue_rejections_total") == 1, "rejection counted")
    finally:
        s.close()


# ---- a server with a small term limit ----------------------------------------

def test_term_limit():
    # Its own server: with a small --max-terms the slow surface of the other tests
    # would stop early on the size limit instead of running.
    s = Server(BIN, "--max-terms", "2000", "--quiet")
    try:
        status, _, body = s.post_json("/v1/groebner", {"polynomials": ["(x+y+z+1)^30"]})
        check(status == 413 and error_code(body) == "size_limit_exceeded", "size limit: %s %r" % (status, body))
        status, _, body = s.post_json("/v1/resultant", SLOW_RESULTANT)
        check(status == 413 and error_code(body) == "size_limit_exceeded",
              "resultant size limit: %s %r" % (status, body))
        status, _, body = s.post_json("/v1/implicitize", SPHERE)
        check(status == 200, "small problems pass under the term limit: %s" % status)
    finally:
        s.close()


# ---- graceful shutdown -------------------------------------------------------

def test_shutdown():
    s = Server(BIN, "--threads", "1", "--shutdown-grace-ms", "300", "--quiet")
    answer = {}

    def client():
        answer["r"] = s.post_json("/v1/implicitize", dict(SLOW, timeout_ms=30000), timeout=30)

    t = threading.Thread(target=client)
    t.start()
    deadline = time.time() + 30
    while time.time() < deadline and s.metric("implicitizer_workers_busy") != 1:
        time.sleep(0.02)  # polled: SIGTERM once the computation runs
    start = time.time()
    code = s.stop(timeout=15)
    t.join(15)
    check(code == 0, "SIGTERM exits 0 (got %r)" % code)
    check(time.time() - start < 0.3 + 1 + LOAD_ALLOWANCE_S, "shutdown within the grace period and a second")
    status, _, body = answer.get("r", (None, None, None))
    check(status == 503 and error_code(body) == "cancelled", "in-flight request answered at shutdown: %s %r"
          % (status, body))
    os.unlink(s.log.name)


# One of issue 16's reproducers: before the library's loops all checked their budget,
# this ran 13.7 s past a 1 s timeout (measured 2026-12-02), so a shutdown had to give
# up on it. Its Gebauer-Moeller update now checks the budget, so the same test checks
# the ordinary path (WorkerPool.ShutdownGivesUpOnAJobThatIgnoresItsBudget keeps the
# other). 30 000 polynomials pass --max-polynomials only with the cap raised.
BUDGET_IGNORING_GROEBNER = {"polynomials": ["x"] * 30000, "timeout_ms": 60000}


def test_shutdown_ends_within_grace_and_a_second():
    grace_ms = 300
    s = Server(BIN, "--threads", "1", "--shutdown-grace-ms", str(grace_ms), "--max-polynomials", "100000", "--quiet")
    body = json.dumps(BUDGET_IGNORING_GROEBNER).encode()
    sock = socket.create_connection(("127.0.0.1", s.port), timeout=30)
    try:
        sock.sendall(b"POST /v1/groebner HTTP/1.1\r\nHost: x\r\nContent-Length: %d\r\n\r\n" % len(body) + body)
        deadline = time.time() + 30
        while time.time() < deadline and s.metric("implicitizer_workers_busy") != 1:
            time.sleep(0.05)  # polling the condition, not waiting for it blindly
        check(s.metric("implicitizer_workers_busy") == 1, "the long computation runs")
        start = time.time()
        # grace + 1 s is the promise; 10 s more for a loaded CI machine.
        code = s.stop(timeout=grace_ms / 1000 + 1 + 10)
        elapsed = time.time() - start
        log = s.log_text()
        print("shutdown with a computation running that ignores its budget: exit %r after %.2f s (grace %.1f s)"
              % (code, elapsed, grace_ms / 1000))
        check(code is not None, "the server exited by itself after SIGTERM (it had to be killed after %.1f s)" % elapsed)
        check(code in (0, 3), "exit status 0, or 3 when a computation did not stop (got %r)" % code)
        check(code != 3 or "1 computation did not stop" in log, "exit 3 says why: %r" % log[-300:])
        check(elapsed < grace_ms / 1000 + 1 + 10, "shutdown took %.2f s" % elapsed)
    finally:
        sock.close()
        os.unlink(s.log.name)


def main():
    base, root = make_static_tree()
    max_body = 65536
    read_timeout_ms = 1000
    keep_alive = 5
    s = Server(BIN, "--static", root, "--threads", "2", "--max-body-bytes", str(max_body),
               "--read-timeout-ms", str(read_timeout_ms), "--keep-alive-requests", str(keep_alive),
               "--cache-size", "16")
    tests = [
        lambda: test_healthz_and_static(s),
        lambda: test_implicitize_sphere(s),
        lambda: test_implicitize_routes_and_curves(s),
        lambda: test_sdf(s),
        lambda: test_render(s),
        lambda: test_tolerance(s),
        lambda: test_cache(s),
        lambda: test_groebner(s),
        lambda: test_resultant(s),
        lambda: test_input_errors(s),
        lambda: test_trigonometric(s),
        lambda: test_semantic_errors(s),
        lambda: test_routing_errors(s),
        lambda: test_size_limits(s, max_body),
        lambda: test_expect_continue(s, max_body),
        lambda: test_path_traversal(s),
        lambda: test_slow_headers_dropped(s, read_timeout_ms / 1000),
        lambda: test_keep_alive_cap(s, keep_alive),
        lambda: test_cors(s),
        lambda: test_disconnect_cancels(s),
        lambda: test_concurrent_clients(s),
        lambda: test_metrics_format(s),
        test_overload,
        test_term_limit,
        test_shutdown,
        test_shutdown_ends_within_grace_and_a_second,
    ]
    try:
        for test in tests:
            try:
                test()
            except Exception:  # noqa: BLE001 - a crash of one test is a failure, the others still run
                failures.append(traceback.format_exc())
                print("FAIL (exception):", traceback.format_exc())
        alive = s.proc.poll() is None
        check(alive, "the server survived everything")
        code = s.stop()
        check(code == 0, "main server exits 0 on SIGTERM (got %r)" % code)
        log = s.log_text()
        lines = [line for line in log.splitlines() if line.startswith("{")]
        check(lines and all(set(json.loads(line)) == {"method", "path", "status", "ms", "bytes"} for line in lines),
              "access log is JSON lines")
    finally:
        if failures:
            print("---- server log (tail) ----")
            print(s.log_text()[-3000:])
        s.close()
        import shutil
        shutil.rmtree(base, ignore_errors=True)
    print(CHECKS.summary())
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
