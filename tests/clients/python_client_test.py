#!/usr/bin/env python3
"""End-to-end tests of clients/python/implicitizer_client.py: its library API and its
command line against the real implicitizer-server on an ephemeral loopback port (no
mocks). Usage: python_client_test.py PATH/TO/implicitizer-server [unittest options]
Registered with ctest as clients.python (clients/python/CMakeLists.txt)."""

import json
import os
import socket
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "server"))
sys.path.insert(0, os.path.join(ROOT, "clients", "python"))
from server_harness import Server, decode_png, pixel  # noqa: E402
import implicitizer_client as ic  # noqa: E402

CLIENT = os.path.join(ROOT, "clients", "python", "implicitizer_client.py")
BIN = None  # argv[1], set in __main__
server = None  # the Server of this run (setUpModule)
URL = None

SPHERE = {"x": "2*s/(1+s^2+t^2)", "y": "2*t/(1+s^2+t^2)", "z": "(1-s^2-t^2)/(1+s^2+t^2)"}
TORUS = {"x": "(2+(1-t^2)/(1+t^2))*(1-s^2)/(1+s^2)", "y": "(2+(1-t^2)/(1+t^2))*2*s/(1+s^2)", "z": "2*t/(1+t^2)"}
# The README's answer for TORUS.
TORUS_EQUATION = "x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9"
TWISTED_CUBIC = {"x": "t", "y": "t^2", "z": "t^3"}
TWISTED_CUBIC_GENERATORS = ["y^2-x*z", "x*y-z", "x^2-y"]
# Far slower than any budget used here by Buchberger (> 15 s; tests/server/server_test.py).
SLOW = {"x": "s^3+t^2*s", "y": "t^3-s", "z": "s*t^2+t^4"}
# The README's scene.
SCENE = {"type": "smooth_union", "k": 0.3, "children": [
    {"type": "sphere", "radius": 1, "name": "ball", "uniforms": ["radius"]},
    {"type": "translate", "offset": [1.5, 0, 0], "child": {"type": "torus", "major": 1, "minor": 0.25}}]}
RENDER_STATS_KEYS = ["width", "height", "method", "mode", "precision", "rays", "mean_evaluations", "max_evaluations",
                     "out_of_steps", "hits", "shading_evaluations", "threads", "elapsed_ms", "shape", "dimension"]


def setUpModule():
    global server, URL
    server = Server(BIN, "--quiet")
    URL = "http://127.0.0.1:%d" % server.port


def tearDownModule():
    status = server.stop()
    server.close()
    if status != 0:
        raise AssertionError("the server exited with %r after SIGTERM" % status)


def refused_url():
    """A loopback URL whose port is bound but not listening: connecting is refused.
    Returns (url, socket); keep the socket open while using the url."""
    s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    s.bind(("127.0.0.1", 0))
    return "http://127.0.0.1:%d" % s.getsockname()[1], s


class PngChecks:
    """Checks of a rendered sphere: the size, and a picture that is not blank."""

    def assert_sphere_picture(self, png, width, height):
        w, h, rows = decode_png(png)
        self.assertEqual((w, h), (width, height))
        colours = {pixel(rows, x, y) for y in range(h) for x in range(w)}
        self.assertGreater(len(colours), 20, "a shaded sphere has many colours")
        # The camera looks at the sphere's centre: the middle pixel is the surface,
        # the corner the background.
        self.assertNotEqual(pixel(rows, w // 2, h // 2), pixel(rows, 0, 0))


class LibraryTest(unittest.TestCase, PngChecks):
    """Client's methods, one per endpoint, and ImplicitizerError."""

    def setUp(self):
        self.client = ic.Client(URL, timeout=60)

    def test_health(self):
        self.assertEqual(self.client.health(), {"status": "ok"})

    def test_metrics_count_requests(self):
        self.client.health()
        samples = self.client.metrics()
        self.assertGreaterEqual(samples['implicitizer_http_requests_total{endpoint="/healthz",status="200"}'], 1)
        self.assertEqual(samples["implicitizer_cache_capacity"], 256)
        self.assertIn("# TYPE implicitizer_http_requests_total counter", self.client.metrics_text())

    def test_implicitize_sphere(self):
        answer = self.client.implicitize(**SPHERE)
        self.assertEqual(answer["implicit"], "x^2+y^2+z^2-1")
        self.assertEqual(answer["degree"], 2)
        self.assertEqual(answer["variables"], ["x", "y", "z"])
        self.assertIs(answer["verified"], True)
        self.assertIn("singular", answer["reproduce"])

    def test_parameters_name_and_order_the_domain(self):
        # Issue 20: the parameters, as the JSON API takes them, name the parametrization's
        # variables and order the domain's intervals (t in [0, 1/2], s in [-1, 1]: the
        # box of x = s spans [-1, 1], that of y = t [0, 1/2]).
        answer = self.client.sdf(x="s", y="t", z="s*t", parameters=["t", "s"], domain=[0, "1/2", -1, 1])
        self.assertLess(answer["box"][0], -0.99)
        self.assertLess(answer["box"][4], 0.51)
        self.assertGreater(answer["box"][1], -0.01)
        answer = self.client.implicitize("u", "v", "u^2-v^2", parameters=["u", "v"])
        self.assertEqual(answer["implicit"], "x^2-y^2-z")
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.implicitize("u", "w", "u*w", parameters=["u", "v"])
        self.assertEqual((caught.exception.code, caught.exception.field, caught.exception.position, caught.exception.status),
                         ("unknown_variable", "y", 0, 400))
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.implicitize("u", "v", "u*v", parameters=["u", "z"])
        self.assertEqual((caught.exception.code, caught.exception.field), ("parameter_is_space_variable", "parameters"))

    def test_implicitize_torus_is_the_readme_equation(self):
        answer = self.client.implicitize(TORUS["x"], TORUS["y"], TORUS["z"])
        self.assertEqual(answer["implicit"], TORUS_EQUATION)
        self.assertEqual(answer["degree"], 4)

    def test_implicitize_plane_curve(self):
        answer = self.client.implicitize("t^2-1", "t^3-t")
        self.assertEqual(answer["implicit"], "x^3+x^2-y^2")
        self.assertEqual(answer["variables"], ["x", "y"])

    def test_implicitize_parameters_method_timeout(self):
        answer = self.client.implicitize(parameters=["t", "s"], method="groebner", timeout_ms=20000, **SPHERE)
        self.assertEqual((answer["implicit"], answer["method"]), ("x^2+y^2+z^2-1", "groebner"))
        answer = self.client.implicitize("t^2-1", "t^3-t", parameters=["t"], method="resultant")
        self.assertEqual((answer["implicit"], answer["method"]), ("x^3+x^2-y^2", "resultant"))
        self.assertEqual(answer["stats"]["resultant"]["formulation"], "sylvester")

    def test_groebner_lex(self):
        answer = self.client.groebner(["x^2+y^2+z^2-1", "x-y", "y-z^2"], order="lex")
        self.assertEqual(answer["basis"], ["z^4+1/2*z^2-1/2", "y-z^2", "x-z^2"])
        self.assertEqual(answer["order"], "lex")
        self.assertNotIn("elimination_ideal", answer)

    def test_groebner_variables_eliminate_weights(self):
        answer = self.client.groebner(["x-s^2", "y-s^3"], variables=["s", "x", "y"], eliminate=["s"])
        self.assertEqual(answer["elimination_ideal"], ["x^3-y^2"])
        weighted = self.client.groebner(["x^2+y", "y^2-x"], variables=["x", "y"], weights=[1, 2])
        self.assertTrue(weighted["order"].startswith("weighted(1,2"), weighted["order"])

    def test_groebner_unproven(self):
        exact = self.client.groebner(["x^2+y", "y^2-x"], method="f4")
        unproven = self.client.groebner(["x^2+y", "y^2-x"], method="f4", proof="random_primes")
        self.assertEqual((exact["proven"], unproven["proven"]), (True, False))
        self.assertEqual(unproven["basis"], exact["basis"])
        self.assertEqual(len(unproven["stats"]["modular"]["random_primes"]), 2)

    def test_resultant(self):
        answer = self.client.resultant("t^2+x", "y*t+1", "t")
        self.assertEqual(answer["resultant"], "x*y^2+1")
        self.assertEqual((answer["variables"], answer["degree"]), (["x", "y"], 3))

    def test_sdf_implicit(self):
        answer = self.client.sdf(implicit="x^2+y^2+z^2-1", mode="fast", box=[-2, -2, -2, 2, 2, 2], name="ball")
        self.assertIn("float ball_sdf(vec3 p)", answer["glsl"])
        self.assertEqual((answer["function"], answer["mode"], answer["degree"]), ("ball_sdf", "fast", 2))
        self.assertEqual(answer["box"], [-2, -2, -2, 2, 2, 2])

    def test_sdf_patch_shape_and_domain(self):
        # Issue 18: a parametric patch with its domain; the box is fitted to it and the
        # answer says which shape was picked.
        answer = self.client.sdf(x="s", y="t", z="s*t", parameters=["s", "t"], domain=[0, 1, 0, "1/2"])
        self.assertEqual((answer["shape"], answer["dimension"], answer["degree"]), ("sheet", 3, 2))
        self.assertAlmostEqual(answer["box"][4], 0.5 + 0.0001, places=12)
        solid = self.client.sdf(implicit="x^2+y^2+z^2-1", shape="solid")
        self.assertEqual(solid["shape"], "solid")
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.sdf(x="s", y="t", z="s*t", domain=[1, 0, 0, 1])
        self.assertEqual((caught.exception.status, caught.exception.code, caught.exception.field),
                         (400, "invalid_domain", "domain[0]"))

    def test_sdf_and_render_with_a_tolerance(self):
        # Issue 19: Enneper's surface approximated within 1e-2 of its box's diagonal (one
        # low-degree piece is shorter GLSL than its exact equation).
        patch = dict(x="s-s^3/3+s*t^2", y="t-t^3/3+s^2*t", z="s^2-t^2", domain=[0, 1, 0, 1])
        answer = self.client.sdf(tolerance=0.01, **patch)
        a = answer["approximation"]
        self.assertEqual((a["tolerance"], a["exact"]), (0.01, False))
        self.assertEqual(a["glsl_lines"], len(answer["glsl"].splitlines()))
        self.assertLessEqual(a["patch_to_surface"]["bound"], 0.01)
        self.assertLessEqual(a["surface_to_patch"]["bound"], 0.01)
        self.assertNotIn("approximation", self.client.sdf(**patch))
        png, stats = self.client.render(tolerance=0.01, width=24, height=24, aa=1, **patch)
        self.assertEqual(decode_png(png)[:2], (24, 24))
        self.assertEqual((stats["tolerance"], stats["pieces"]), (0.01, a["pieces"]))
        self.assertIn(str(stats["patch_to_surface"]).split()[1], ("certified", "measured"), stats)
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.sdf(tolerance=0.75, **patch)
        self.assertEqual((caught.exception.status, caught.exception.code, caught.exception.field),
                         (400, "invalid_tolerance", "tolerance"))

    def test_sdf_scene_safe(self):
        answer = self.client.sdf(scene=SCENE, mode="safe", name="demo")
        self.assertIn("float demo_sdf(vec3 p)", answer["glsl"])
        self.assertIn("uniform float ball_radius;", answer["glsl"])
        self.assertEqual([u["name"] for u in answer["uniforms"]], ["ball_radius"])
        self.assertEqual(answer["mode"], "safe")

    def test_render_png_with_header_statistics(self):
        png, stats = self.client.render(implicit="x^2+y^2+z^2-1", width=64, height=48, aa=1)
        self.assert_sphere_picture(png, 64, 48)
        self.assertEqual((stats["width"], stats["height"], stats["rays"]), (64, 48, 64 * 48))
        self.assertEqual((stats["method"], stats["mode"], stats["precision"]), ("sphere", "fast", "float"))
        self.assertGreater(stats["hits"], 0)
        self.assertLess(stats["hits"], stats["rays"])
        self.assertIsInstance(stats["mean_evaluations"], float)

    def test_render_json_format_gives_the_same_image(self):
        request = dict(implicit="x^2+y^2+z^2-1", width=40, height=30, aa=2, method="enhanced", precision="double",
                       eye=[3, 3, 5], target=[0, 0, 0], box=[-2, -2, -2, 2, 2, 2], mode="fast", timeout_ms=20000)
        png, header_stats = self.client.render(**request)
        json_png, stats = self.client.render(format="json", **request)
        self.assertEqual(json_png, png, "the renderer is deterministic")
        self.assertEqual(list(stats), RENDER_STATS_KEYS)
        for key in ("width", "height", "method", "mode", "precision", "rays", "hits", "out_of_steps", "shape",
                    "dimension"):
            self.assertEqual(stats[key], header_stats[key], key)
        self.assertEqual(stats["rays"], 40 * 30 * 4)

    def test_render_parametric(self):
        png, stats = self.client.render(width=32, height=32, aa=1, method="exact", **SPHERE)
        self.assert_sphere_picture(png, 32, 32)
        self.assertEqual(stats["method"], "exact")

    # ---- refusals ------------------------------------------------------

    def test_parse_error_has_code_position_field(self):
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.implicitize("s+$", "t", "s*t")
        e = caught.exception
        self.assertEqual((e.status, e.code, e.position, e.field), (400, "unexpected_character", 2, "x"))
        self.assertEqual(str(e), "unexpected_character at position 2 in x: %s (HTTP 400)" % e.message)
        self.assertIn("$", e.message)

    def test_no_single_equation(self):
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.implicitize(**TWISTED_CUBIC)
        e = caught.exception
        self.assertEqual((e.status, e.code), (422, "no_single_equation"))
        self.assertEqual(e.generators, TWISTED_CUBIC_GENERATORS)
        self.assertIsNone(e.position)

    def test_base_points(self):
        # The sphere's parametrization has base points: the resultant route refuses it.
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.implicitize(method="resultant", **SPHERE)
        e = caught.exception
        self.assertEqual((e.status, e.code), (422, "base_points"))
        self.assertIn("use method groebner or auto", e.message)

    def test_time_limit(self):
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.implicitize(method="groebner", timeout_ms=50, **SLOW)
        e = caught.exception
        self.assertEqual((e.status, e.code, e.limit), (504, "time_limit_exceeded", "time"))

    def test_render_too_large(self):
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.render(implicit="x^2+y^2+z^2-1", width=4096, height=4096, aa=8)
        self.assertEqual((caught.exception.status, caught.exception.code), (413, "render_too_large"))

    def test_unknown_method(self):
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.implicitize(method="bogus", **SPHERE)
        e = caught.exception
        self.assertEqual((e.status, e.code, e.field), (400, "unknown_method", "method"))
        self.assertEqual(ic.exit_status(e), ic.EXIT_USAGE)  # as build/bin/implicitizer: status 2

    def test_input_errors_name_their_field(self):
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.resultant("t^2+x", "y*t+1", "w")
        self.assertEqual((caught.exception.code, caught.exception.field), ("unknown_variable", "variable"))
        with self.assertRaises(ic.ImplicitizerError) as caught:
            self.client.sdf(implicit="x^2+y^2+z^2-1", scene=SCENE)
        self.assertEqual((caught.exception.code, caught.exception.field), ("invalid_value", "scene"))

    def test_connection_refused(self):
        url, holder = refused_url()
        with holder, self.assertRaises(ic.ImplicitizerError) as caught:
            ic.Client(url, timeout=10).health()
        e = caught.exception
        self.assertEqual((e.code, e.status), ("connection_failed", None))
        self.assertIn(url, e.message)

    def test_url_path_prefix_and_not_found(self):
        with self.assertRaises(ic.ImplicitizerError) as caught:
            ic.Client(URL + "/prefix/").health()
        e = caught.exception
        self.assertEqual((e.status, e.code), (404, "not_found"))

    def test_bad_url(self):
        for url in ("ftp://127.0.0.1", "127.0.0.1:8080", "http://127.0.0.1:notaport"):
            with self.assertRaises(ValueError, msg=url):
                ic.Client(url)


class CommandLineTest(unittest.TestCase, PngChecks):
    """implicitizer_client.py, run as a program: outputs, messages, exit statuses."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="implicitizer-client-test-")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def run_client(self, *args, url=True, env=None):
        command = [sys.executable, CLIENT] + (["--url", URL] if url else []) + list(args)
        environment = dict(os.environ, PYTHONDONTWRITEBYTECODE="1", **(env or {}))
        return subprocess.run(command, capture_output=True, text=True, timeout=120, env=environment)

    def assert_ok(self, result):
        self.assertEqual(result.returncode, 0, result.stderr)
        return result.stdout

    def test_sdf_command_shape_and_domain(self):
        answer = json.loads(self.assert_ok(self.run_client(
            "sdf", "--x", "s", "--y", "t", "--z", "s*t", "--domain", "0,1,0,1", "--shape", "sheet", "--json")))
        self.assertEqual((answer["shape"], answer["dimension"]), ("sheet", 3))
        result = self.run_client("sdf", "--x", "s", "--y", "t", "--z", "s*t", "--domain", "0,1,0")
        self.assertEqual(result.returncode, 3, result.stderr)
        self.assertIn("invalid_domain", result.stderr)
        self.assertEqual(self.run_client("sdf", "--implicit", "x", "--shape", "hollow").returncode, 2)

    def test_sdf_command_tolerance(self):
        patch = ["--x", "s", "--y", "t", "--z", "s^3-s*t^2", "--domain", "0,1,0,1"]
        answer = json.loads(self.assert_ok(self.run_client("sdf", *patch, "--tolerance", "0.01", "--json")))
        self.assertEqual(answer["approximation"]["tolerance"], 0.01)
        for bad in ("nan", "0", "small"):
            result = self.run_client("sdf", *patch, "--tolerance", bad)
            self.assertEqual(result.returncode, 3, result.stderr)
            self.assertIn("invalid_tolerance", result.stderr)

    def test_params_option_is_the_parameters_list(self):
        # Issue 20: --params is the JSON API's parameters, errors exit 3 with a caret.
        result = self.run_client("implicitize", "--x", "u", "--y", "w", "--z", "u*w", "--params", "u, v")
        self.assertEqual(result.returncode, 3, result.stderr)
        self.assertIn("unknown_variable at position 0 in y", result.stderr)
        self.assertIn("  y = w\n      ^", result.stderr)
        glsl = self.assert_ok(self.run_client("sdf", "--x", "u", "--y", "v", "--z", "u*v", "--params", "v,u",
                                              "--domain", "0,1/2,-1,1", "--json"))
        self.assertLess(json.loads(glsl)["box"][4], 0.51)

    def test_implicitize_plain_and_json(self):
        self.assertEqual(self.assert_ok(self.run_client(
            "implicitize", "--x", SPHERE["x"], "--y", SPHERE["y"], "--z", SPHERE["z"])), "x^2+y^2+z^2-1\n")
        answer = json.loads(self.assert_ok(self.run_client(
            "implicitize", "--x", TORUS["x"], "--y", TORUS["y"], "--z", TORUS["z"], "--json")))
        self.assertEqual((answer["implicit"], answer["degree"], answer["verified"]), (TORUS_EQUATION, 4, True))

    def test_implicitize_options(self):
        # --opt=value, a value starting with '-', --params, --method, --timeout.
        self.assertEqual(self.assert_ok(self.run_client(
            "implicitize", "--x=t^2-1", "--y", "t^3-t", "--method", "groebner", "--timeout", "20")), "x^3+x^2-y^2\n")
        self.assertEqual(self.assert_ok(self.run_client(
            "implicitize", "--x", "-s", "--y", "t", "--z", "s*t", "--params", "s, t")), "x*y+z\n")

    def test_groebner(self):
        self.assertEqual(self.assert_ok(self.run_client(
            "groebner", "--order", "lex", "x^2+y^2+z^2-1", "x-y", "y-z^2")), "z^4+1/2*z^2-1/2\ny-z^2\nx-z^2\n")
        # A polynomial may start with '-'.
        self.assertEqual(self.assert_ok(self.run_client("groebner", "--order", "lex", "-x^2-y", "y^2-x")),
                         "y^4+y\nx-y^2\n")
        self.assertEqual(self.assert_ok(self.run_client(
            "groebner", "--eliminate", "s,t", "x-s-t", "y-s*t", "z-s^2")), "x^2*z-y^2-2*y*z-z^2\n")
        answer = json.loads(self.assert_ok(self.run_client(
            "groebner", "--vars", "s,x,y", "--eliminate", "s", "--json", "x-s^2", "y-s^3")))
        self.assertEqual(answer["elimination_ideal"], ["x^3-y^2"])
        self.assertIn("basis", answer)

    def test_resultant(self):
        self.assertEqual(self.assert_ok(self.run_client("resultant", "--var", "t", "t^2+x", "y*t+1")), "x*y^2+1\n")
        answer = json.loads(self.assert_ok(self.run_client("resultant", "--var=t", "--json", "t^2+x", "y*t+1")))
        self.assertEqual((answer["resultant"], answer["method"]), ("x*y^2+1", "subresultant"))

    def test_sdf(self):
        glsl = self.assert_ok(self.run_client("sdf", "--implicit", "x^2+y^2+z^2-1", "--name", "ball"))
        self.assertIn("float ball_sdf(vec3 p) {", glsl.splitlines())
        scene = os.path.join(self.tmp.name, "scene.json")
        with open(scene, "w") as f:
            json.dump(SCENE, f)
        glsl = self.assert_ok(self.run_client("sdf", "--scene", scene, "--mode", "safe", "--name", "demo"))
        declarations = [line for line in glsl.splitlines() if line.startswith(("uniform", "float"))]
        self.assertEqual(declarations, ["uniform float ball_radius;", "float demo_sphere(vec3 p, float r) {",
                                        "float demo_smin2(float a, float b, float k) {",
                                        "float demo_torus(vec3 p, float major, float minor) {",
                                        "float demo_sdf(vec3 p) {"])
        answer = json.loads(self.assert_ok(self.run_client(
            "sdf", "--implicit", "x^2+y^2+z^2-1", "--box=-3,-3,-3,3,3,3", "--json")))
        self.assertEqual((answer["function"], answer["box"]), ("surface_sdf", [-3, -3, -3, 3, 3, 3]))

    def test_render(self):
        out = os.path.join(self.tmp.name, "sphere.png")
        stats = json.loads(self.assert_ok(self.run_client(
            "render", "--implicit", "x^2+y^2+z^2-1", "--size", "64x48", "--aa", "1", "-o", out, "--json")))
        self.assertEqual(list(stats), RENDER_STATS_KEYS)
        self.assertEqual((stats["width"], stats["height"], stats["rays"]), (64, 48, 64 * 48))
        with open(out, "rb") as f:
            self.assert_sphere_picture(f.read(), 64, 48)
        # Parametric, without --json: a summary on stderr, nothing on stdout.
        out = os.path.join(self.tmp.name, "parametric.png")
        result = self.run_client("render", "--x", SPHERE["x"], "--y", SPHERE["y"], "--z", SPHERE["z"],
                                 "--size=32x32", "--method", "newton", "--output", out)
        self.assertEqual(self.assert_ok(result), "")
        self.assertTrue(result.stderr.startswith("wrote %s (32x32, " % out), result.stderr)
        with open(out, "rb") as f:
            self.assert_sphere_picture(f.read(), 32, 32)

    def test_health_metrics_and_environment_url(self):
        result = self.run_client("health", url=False, env={"IMPLICITIZER_URL": URL})
        self.assertEqual(json.loads(self.assert_ok(result)), {"status": "ok"})
        self.assertIn("implicitizer_http_requests_total{", self.assert_ok(self.run_client("metrics")))

    # ---- refusals ------------------------------------------------------

    def test_parse_error_exit_3(self):
        result = self.run_client("implicitize", "--x", "s+$", "--y", "t", "--z", "s*t")
        self.assertEqual(result.returncode, 3, result.stderr)
        self.assertEqual(result.stdout, "")
        self.assertEqual(result.stderr.splitlines(), [
            "error: unexpected_character at position 2 in x: unexpected character '$'",
            "  x = s+$",
            "        ^"])
        result = self.run_client("implicitize", "--x", "s+$", "--y", "t", "--z", "s*t", "--json")
        self.assertEqual(result.returncode, 3)
        self.assertEqual(json.loads(result.stdout)["error"],
                         {"code": "unexpected_character", "message": "unexpected character '$'", "position": 2,
                          "field": "x"})

    def test_no_single_equation_exit_4(self):
        result = self.run_client("implicitize", "--x", "t", "--y", "t^2", "--z", "t^3")
        self.assertEqual(result.returncode, 4, result.stderr)
        lines = result.stderr.splitlines()
        self.assertTrue(lines[0].startswith("error: no_single_equation: no single implicit equation"), lines[0])
        self.assertEqual(lines[1:], ["generators of the elimination ideal:"] +
                         ["  " + g for g in TWISTED_CUBIC_GENERATORS])

    def test_base_points_exit_4(self):
        result = self.run_client("implicitize", "--x", SPHERE["x"], "--y", SPHERE["y"], "--z", SPHERE["z"],
                                 "--method", "resultant")
        self.assertEqual(result.returncode, 4, result.stderr)
        lines = result.stderr.splitlines()
        self.assertEqual(len(lines), 1, lines)
        self.assertTrue(lines[0].startswith("error: base_points: the auxiliary resultant vanishes"), lines[0])

    def test_time_limit_exit_5(self):
        result = self.run_client("implicitize", "--x", SLOW["x"], "--y", SLOW["y"], "--z", SLOW["z"],
                                 "--method", "groebner", "--timeout", "0.05", "--json")
        self.assertEqual(result.returncode, 5, result.stderr)
        self.assertTrue(result.stderr.startswith("error: time_limit_exceeded (time limit): "), result.stderr)
        self.assertEqual(json.loads(result.stdout)["error"]["limit"], "time")

    def test_json_is_the_endpoint_object(self):
        # A cache hit answers the very object (elapsed_ms included) the library got.
        answer = ic.Client(URL).groebner(["x-s^2", "y-s^3"], variables=["s", "x", "y"], order="lex")
        printed = self.assert_ok(self.run_client("groebner", "--vars", "s,x,y", "--order", "lex", "--json",
                                                 "x-s^2", "y-s^3"))
        self.assertEqual(json.loads(printed), answer)
        self.assertEqual(printed, json.dumps(answer, separators=(",", ":")) + "\n")

    def test_scene_file_errors(self):
        bad = os.path.join(self.tmp.name, "bad.json")
        with open(bad, "w") as f:
            f.write('{"type": "sphere", "radius": 1,}')
        result = self.run_client("sdf", "--scene", bad)
        self.assertEqual(result.returncode, 3, result.stderr)
        self.assertTrue(result.stderr.startswith("error: invalid_json at position 31: invalid JSON: "), result.stderr)
        # The server's scene errors name the node.
        with open(bad, "w") as f:
            json.dump({"type": "union", "children": [{"type": "sphere", "radius": 1}, {"type": "blob"}]}, f)
        result = self.run_client("sdf", "--scene", bad, "--json")
        self.assertEqual(result.returncode, 3, result.stderr)
        error = json.loads(result.stdout)["error"]
        self.assertEqual((error["code"], error["field"]), ("unknown_node_type", "scene.children[1].type"))

    def test_render_too_large_exit_3(self):
        out = os.path.join(self.tmp.name, "never.png")
        result = self.run_client("render", "--implicit", "x^2+y^2+z^2-1", "--size", "4096x4096", "--aa", "8",
                                 "-o", out)
        self.assertEqual(result.returncode, 3, result.stderr)
        self.assertTrue(result.stderr.startswith("error: render_too_large in width: "), result.stderr)
        self.assertFalse(os.path.exists(out))

    def test_connection_refused_exit_1(self):
        url, holder = refused_url()
        with holder:
            result = self.run_client("health", url=False, env={"IMPLICITIZER_URL": url})
        self.assertEqual(result.returncode, 1)
        self.assertTrue(result.stderr.startswith("error: connection_failed: cannot reach %s: " % url), result.stderr)

    def test_usage_errors_exit_2(self):
        cases = [
            ("implicitize", "--y", "t"),  # missing --x
            ("implicitize", "--x", "t", "--x", "s", "--y", "t"),  # given twice
            ("implicitize", "--x", "t", "--y", "t", "--frobnicate", "1"),  # unknown option
            ("implicitize", "--x", "t", "--y", "t", "--timeout", "0"),
            ("implicitize", "--x", "t", "--y"),  # missing value
            ("groebner", "--order", "lexicographic", "x"),
            ("groebner", "--vars", "x,,y", "x"),
            ("resultant", "--var", "t", "t^2+x"),
            ("sdf", "--implicit", "x", "--scene", "s.json"),
            ("sdf", "--scene", os.path.join(self.tmp.name, "missing.json")),
            ("render", "--implicit", "x^2+y^2+z^2-1"),  # no -o
            ("render", "--x", "s", "--z", "t", "-o", "a.png"),  # no --y
            ("render", "--implicit", "x^2+y^2+z^2-1", "--size", "64", "-o", "a.png"),
            ("frobnicate",),
        ]
        for args in cases:
            result = self.run_client(*args)
            self.assertEqual(result.returncode, 2, "%r: %s" % (args, result.stderr))
            self.assertTrue(result.stderr.startswith("error: "), "%r: %s" % (args, result.stderr))
            self.assertIn("--help' for usage", result.stderr)

    def test_help_exit_0(self):
        self.assertIn("--eliminate", self.assert_ok(self.run_client("groebner", "--help")))
        self.assertIn("implicitize --x E --y E", self.assert_ok(self.run_client("-h")))


class TrigonometricTest(unittest.TestCase):
    """Issue 20 through the client: trigonometric and hyperbolic parametrizations are
    answered with the substitution and the rational form; refusals raise
    ImplicitizerError with the code, the field, the position and the function's name."""

    def setUp(self):
        self.client = ic.Client(URL, timeout=60)

    def test_accepted_forms(self):
        cases = [
            (("cos(u)*cos(v)", "cos(u)*sin(v)", "sin(u)"), "x^2+y^2+z^2-1", ["tu = tan(u/2)", "tv = tan(v/2)"]),
            # Parameters in order of first appearance: v comes first here.
            (("(2+cos(v))*cos(u)", "(2+cos(v))*sin(u)", "sin(v)"), TORUS_EQUATION,
             ["tv = tan(v/2)", "tu = tan(u/2)"]),
            (("cosh(u)*cos(v)", "cosh(u)*sin(v)", "sinh(u)"), "x^2+y^2-z^2-1", ["eu = exp(u)", "tv = tan(v/2)"]),
            (("cos(2*t)", "sin(t)", None), "2*y^2+x-1", ["tt = tan(t/2)"]),
            (("cos(t)^3", "sin(t)^3", None),
             "x^6+3*x^4*y^2+3*x^2*y^4+y^6-3*x^4+21*x^2*y^2-3*y^4+3*x^2+3*y^2-1", ["tt = tan(t/2)"]),
        ]
        for (x, y, z), implicit, formulas in cases:
            answer = self.client.implicitize(x, y, z)
            self.assertEqual(answer["implicit"], implicit, x)
            self.assertEqual([sub["formula"] for sub in answer["substitution"]], formulas)
            rational = answer["rational_parametrization"]
            self.assertEqual(rational["parameters"], [f.split(" ")[0] for f in formulas])
            self.assertIn("made rational by", answer["reproduce"]["singular"])

    def test_parameters_name_and_order_the_angles(self):
        answer = self.client.implicitize("cos(b)*cos(a)", "cos(b)*sin(a)", "sin(b)", parameters=["a", "b"])
        self.assertEqual(answer["implicit"], "x^2+y^2+z^2-1")
        self.assertEqual(answer["rational_parametrization"]["parameters"], ["ta", "tb"])

    def test_refusals(self):
        cases = [
            (("u*cos(u)", "sin(u)", "v"), ("parameter_inside_and_outside", "x", 2, "cos")),
            (("cos(s*t)", "sin(t)", "s"), ("nonlinear_argument", "x", 0, "cos")),
            (("s", "sqrt(t)", "s"), ("function_not_rational", "y", 0, "sqrt")),
            (("s", "t", "exp(s)"), ("function_not_rational", "z", 0, "exp")),
            (("log(s)", "t", "s"), ("function_not_rational", "x", 0, "log")),
            (("s", "t", "s*bar(t)"), ("unknown_function", "z", 2, "bar")),
        ]
        for (x, y, z), (code, field, position, name) in cases:
            with self.assertRaises(ic.ImplicitizerError) as caught:
                self.client.implicitize(x, y, z)
            e = caught.exception
            self.assertEqual((e.status, e.code, e.field, e.position), (400, code, field, position), x)
            self.assertIn("'%s'" % name, e.message)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: python_client_test.py PATH/TO/implicitizer-server [unittest options]")
    BIN = sys.argv[1]
    unittest.main(argv=[sys.argv[0]] + sys.argv[2:], verbosity=2)
