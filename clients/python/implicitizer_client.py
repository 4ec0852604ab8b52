#!/usr/bin/env python3
"""Python client of implicitizer-server (docs/api.md), standard library only.

As a library::

    from implicitizer_client import Client, ImplicitizerError
    client = Client("http://127.0.0.1:8080")
    client.implicitize("2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(1-s^2-t^2)/(1+s^2+t^2)")["implicit"]
    # 'x^2+y^2+z^2-1'

As a command line mirroring build/bin/implicitizer (docs/cli.md)::

    implicitizer_client.py [--url URL] implicitize --x E --y E [--z E] [--params s,t] [--json]

Every answer is the endpoint's JSON object as a dict; every refusal raises
ImplicitizerError with the server's error code. clients/python/README.md lists the
commands, exit statuses and the client's own error codes.
"""

import argparse
import base64
import http.client
import json
import math
import os
import socket
import sys
import time
import urllib.parse
from typing import NamedTuple

__all__ = ["Client", "ImplicitizerError", "RenderResult", "DEFAULT_URL", "exit_status", "main"]

#: Where the client goes without an explicit url: $IMPLICITIZER_URL, else this.
DEFAULT_URL = "http://127.0.0.1:8080"

#: Seconds the client waits for an answer by default: above the server's largest
#: computation budget (60 s, `--max-timeout-ms`), so that the server's 504 comes first.
DEFAULT_TIMEOUT_SECONDS = 90.0

PROG = "implicitizer_client.py"

# Exit statuses of the command line: those of build/bin/implicitizer (docs/cli.md).
EXIT_OK = 0
EXIT_INTERNAL = 1  # a server bug (500), a failed connection, an unexpected answer
EXIT_USAGE = 2
EXIT_INVALID_INPUT = 3
EXIT_NO_SINGLE_EQUATION = 4
EXIT_LIMIT = 5


class ImplicitizerError(Exception):
    """A refusal of the server, or a failure to get an answer from it.

    `code` is the stable error code (docs/api.md, "Errors"), `message` the human
    message, `status` the HTTP status (None when no answer came). `position` (0-based,
    in the field's text or the body), `field` ("x", "polynomials[2]"), `generators`
    (no_single_equation), `limit` ("time", "size", "cancelled") and `retry_after`
    (seconds, from a 503's Retry-After header) are None when the server did not give
    them. `error` is the whole error object, as the server sent it.

    Codes of the client itself: `connection_failed` (the server could not be reached,
    or closed the connection without an answer) and `client_timeout` (no answer
    within the client's timeout), both with status None, and `bad_response` (an
    answer that is not the API's JSON, e.g. a proxy's error page; its status).
    """

    def __init__(self, code, message, status=None, position=None, field=None, generators=None, limit=None,
                 retry_after=None, error=None):
        super().__init__(message)
        self.code = code
        self.message = message
        self.status = status
        self.position = position
        self.field = field
        self.generators = generators
        self.limit = limit
        self.retry_after = retry_after
        self.error = error if error is not None else {"code": code, "message": message}

    def __str__(self):
        """`CODE at position N in FIELD: MESSAGE (HTTP STATUS)`, the optional parts when known."""
        text = self.code
        if self.position is not None:
            text += " at position %d" % self.position
        if self.field is not None:
            text += " in %s" % self.field
        text += ": " + self.message
        if self.status is not None:
            text += " (HTTP %d)" % self.status
        return text


class RenderResult(NamedTuple):
    """What `Client.render` returns: the PNG file's bytes and the render statistics
    (`width`, `height`, `method`, `mode`, `precision`, `rays`, `hits`, `out_of_steps`,
    `mean_evaluations`, `max_evaluations`, `elapsed_ms`, ...; docs/api.md)."""

    png: bytes
    stats: dict


def _error_from_answer(status, headers, body):
    """The ImplicitizerError of an HTTP answer with an error status."""
    retry_after = None
    try:
        retry_after = int(headers.get("retry-after", ""))
    except ValueError:
        pass
    try:
        error = json.loads(body)["error"]
        code, message = error["code"], error["message"]
        if not isinstance(code, str) or not isinstance(message, str):
            raise TypeError("code and message must be strings")
    except (ValueError, TypeError, KeyError):
        snippet = body[:200].decode("utf-8", errors="replace").strip()
        return ImplicitizerError("bad_response", "HTTP %d without the API's error object: %r" % (status, snippet),
                                 status=status, retry_after=retry_after)
    return ImplicitizerError(code, message, status=status, position=error.get("position"), field=error.get("field"),
                             generators=error.get("generators"), limit=error.get("limit"), retry_after=retry_after,
                             error=error)


def _parse_json_answer(status, body):
    """The JSON object of a successful answer; bad_response when it is not one."""
    try:
        answer = json.loads(body)
    except ValueError as e:
        raise ImplicitizerError("bad_response", "the answer is not JSON: %s" % e, status=status) from None
    if not isinstance(answer, dict):
        raise ImplicitizerError("bad_response", "the answer is not a JSON object", status=status)
    return answer


def _header_value(text):
    """An X-Render-* header's value as an int, a float or the string itself."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _render_stats(headers):
    """The render statistics of a PNG answer's X-Render-* headers, keys in snake_case."""
    prefix = "x-render-"
    return {k[len(prefix):].replace("-", "_"): _header_value(v) for k, v in headers.items() if k.startswith(prefix)}


def _without_none(**fields):
    """The request object: the given fields, without those left at None (the server's defaults)."""
    return {k: v for k, v in fields.items() if v is not None}


class Client:
    """A connection-less client of one implicitizer-server (a new connection per call).

    `url` is the server's base address (`http://HOST:PORT`, optionally with a path
    prefix when it sits behind a proxy); None means $IMPLICITIZER_URL or DEFAULT_URL.
    `timeout` is how many seconds to wait for the connection and for each answer.
    Raises ValueError for a url that is not http:// or https://. Safe to share
    between threads (it keeps no connection).
    """

    def __init__(self, url=None, timeout=DEFAULT_TIMEOUT_SECONDS):
        self.url = url or os.environ.get("IMPLICITIZER_URL") or DEFAULT_URL
        self.timeout = timeout
        parts = urllib.parse.urlsplit(self.url)
        if parts.scheme not in ("http", "https") or not parts.hostname:
            raise ValueError("not an http:// or https:// URL: %r" % self.url)
        try:
            port = parts.port
        except ValueError:
            raise ValueError("bad port in URL %r" % self.url) from None
        self._scheme = parts.scheme
        self._host = parts.hostname
        self._port = port or (443 if parts.scheme == "https" else 80)
        self._prefix = parts.path.rstrip("/")

    # ---- the endpoints ----------------------------------------------------

    def health(self):
        """GET /healthz: `{"status": "ok"}` when the server is up."""
        status, _, body = self._exchange("GET", "/healthz")
        return _parse_json_answer(status, body)

    def metrics_text(self):
        """GET /metrics: the Prometheus text (format 0.0.4), as the server sent it."""
        _, _, body = self._exchange("GET", "/metrics")
        return body.decode("utf-8")

    def metrics(self):
        """GET /metrics, parsed: a dict from each sample as written, with its labels
        (`implicitizer_cache_hits_total`, `implicitizer_http_requests_total{endpoint="/healthz",status="200"}`),
        to its value as a float. Comment lines are left out."""
        samples = {}
        for line in self.metrics_text().splitlines():
            if line and not line.startswith("#"):
                name, _, value = line.rpartition(" ")
                samples[name] = float(value)
        return samples

    def implicitize(self, x, y, z=None, parameters=None, method=None, timeout_ms=None):
        """POST /v1/implicitize: the implicit equation of x(params), y(params), z(params).

        Without `z` the parametrization is plane and the answer is its implicit curve.
        `parameters` (a list of names) defaults to the identifiers other than x, y, z;
        `method` is "auto" (default), "groebner", "resultant" or "interpolation"; `timeout_ms` the
        computation budget (server default 10 s, at most 60 s). Returns the response
        object: `implicit`, `degree`, `variables`, `method`, `verified`, `elapsed_ms`,
        `stats`, `reproduce`. A curve or point image raises ImplicitizerError
        `no_single_equation` (status 422) with its `generators`.
        """
        return self._post_json("/v1/implicitize", _without_none(
            x=x, y=y, z=z, parameters=parameters, method=method, timeout_ms=timeout_ms))

    def groebner(self, polynomials, variables=None, order=None, weights=None, eliminate=None, timeout_ms=None,
                 method=None, proof=None):
        """POST /v1/groebner: the reduced Gröbner basis of the ideal of `polynomials`.

        `variables` (largest first) defaults to the identifiers in order of first
        appearance; `order` is "lex", "grlex" or "grevlex" (default); `weights` (one
        integer per variable) makes it a weighted order; `eliminate` lists variables
        to eliminate, adding `elimination_ideal` to the answer; `method` is "auto"
        (default), "buchberger", "modular" or "f4"; `proof` "exact" (default) or
        "random_primes" (faster, not proven: the answer says `proven` false). Returns
        `basis`, `order`, `method`, `proven`, `stats`, `elapsed_ms` (and
        `elimination_ideal`).
        """
        return self._post_json("/v1/groebner", _without_none(
            polynomials=list(polynomials), variables=variables, order=order, weights=weights, eliminate=eliminate,
            timeout_ms=timeout_ms, method=method, proof=proof))

    def resultant(self, f, g, variable, timeout_ms=None):
        """POST /v1/resultant: Res_variable(f, g). Returns `resultant`, `variables`,
        `degree` (-1 for 0), `method`, `elapsed_ms`."""
        return self._post_json("/v1/resultant", _without_none(
            polynomials=[f, g], variable=variable, timeout_ms=timeout_ms))

    def sdf(self, implicit=None, scene=None, x=None, y=None, z=None, parameters=None, shape=None, domain=None,
            mode=None, box=None, name=None, timeout_ms=None, tolerance=None):
        """POST /v1/sdf: the GLSL distance function of `implicit` (a polynomial in x,
        y, z; without z a plane curve), of the parametric `x`, `y`, `z` (with
        `parameters`; without `z` a plane curve) or of `scene` (a dict: the scene tree
        of docs/sdf.md); give one.

        `shape` is "auto" (default), "sheet" or "solid"; `domain` the parameter domain
        [s0, s1, t0, t1], lo and hi for each parameter in the order of `parameters`
        (without them, the order of first appearance; numbers or exact strings like "1/3");
        `mode` is "fast" (default) or "safe" (a proven lower bound); `box` six numbers
        x0, y0, z0, x1, y1, z1 (four for a curve; default [-2, 2]³, fitted to a patch);
        `name` the prefix of the function (default "surface"); `tolerance` EPS in
        (0, 0.5] approximates a parametric patch within EPS × its box's diagonal, both
        ways (default: the exact equation; a bound the server cannot reach raises
        `tolerance_not_met`, 422, its `error["best_bound"]` the bound reached). Returns `glsl`
        (defining `float NAME_sdf(vec3 p)`, `vec2 p` for a curve), `function`, `mode`,
        `shape` (the one picked), `dimension`, `box` (the box used), `degree`,
        `uniforms` (for a scene also `nodes` and `leaves`), and with a tolerance
        `approximation` (`degree`, `pieces`, `glsl_lines`, `patch_to_surface` and
        `surface_to_patch` with their `bound` and `method`).
        """
        return self._post_json("/v1/sdf", _without_none(
            implicit=implicit, scene=scene, x=x, y=y, z=z, parameters=parameters, shape=shape, domain=domain,
            tolerance=tolerance, mode=mode, box=box, name=name, timeout_ms=timeout_ms))

    def render(self, implicit=None, scene=None, x=None, y=None, z=None, parameters=None, shape=None, domain=None,
               mode=None, box=None, name=None, width=None, height=None, method=None, aa=None, eye=None, target=None, precision=None,
               format=None, timeout_ms=None, tolerance=None):  # pylint: disable=redefined-builtin
        """POST /v1/render: a PNG preview. Returns RenderResult(png, stats).

        The object is given as for `sdf` (`implicit`, `scene`, or the parametric `x`,
        `y`, `z` with `parameters`; give one), with `shape`, `domain`, `tolerance`,
        `mode`, `box`, `name`; a plane curve is drawn in the plane. `width`,
        `height` in pixels (1 to 4096, default 256), `method` "sphere" (default),
        "enhanced", "newton", "forward_newton" or "exact", `aa` AA×AA samples per
        pixel (1 to 8, default 2), `eye` and `target` three numbers each,
        `precision` "float" or "double". With `format` "png" (the default) the
        statistics come from the X-Render-* headers (keys in snake_case:
        `out_of_steps`); with "json" they are the answer's object, which also has
        `shading_evaluations` and `threads`, and the PNG is decoded from it.
        More than 4194304 rays (width·height·aa²) raises `render_too_large` (413).
        """
        request = _without_none(
            implicit=implicit, scene=scene, x=x, y=y, z=z, parameters=parameters, shape=shape, domain=domain,
            tolerance=tolerance, mode=mode, box=box, name=name, width=width, height=height, method=method, aa=aa, eye=eye, target=target, precision=precision,
            format=format, timeout_ms=timeout_ms)
        status, headers, body = self._exchange("POST", "/v1/render", request)
        if format == "json":
            stats = _parse_json_answer(status, body)
            try:
                png = base64.b64decode(stats.pop("png_base64"), validate=True)
            except (KeyError, TypeError, ValueError) as e:
                raise ImplicitizerError("bad_response", "no PNG in the answer: %s" % e, status=status) from None
            return RenderResult(png, stats)
        return RenderResult(body, _render_stats(headers))

    # ---- jobs: long computations (POST /v1/jobs) --------------------------------

    def submit(self, kind, request):
        """POST /v1/jobs: runs `request` (the dict the endpoint `kind` takes:
        "implicitize", "groebner", "resultant", "sdf" or "render") as a job. Returns
        the job's state (`id`, `status`, `progress`, ...). A request the endpoint
        refuses raises its ImplicitizerError at once; too many jobs of this client
        raises `too_many_jobs` (429, with `retry_after`)."""
        return self._post_json("/v1/jobs", {"kind": kind, "request": request})

    def job(self, job_id):
        """GET /v1/jobs/ID: the job's state: `status` (queued, running, done, failed,
        cancelled), `progress` (`phase`, `fraction` or None, `done`, `total`, `stage`,
        `elapsed_ms`) and, once finished, `http_status` and `result`. Raises
        `job_not_found` (404) for an unknown or expired id."""
        status, _, body = self._exchange("GET", "/v1/jobs/" + job_id)
        return _parse_json_answer(status, body)

    def cancel(self, job_id):
        """DELETE /v1/jobs/ID: cancels a queued or running job (its computation stops
        within a second) and returns its state; removes a finished job and returns None."""
        status, _, body = self._exchange("DELETE", "/v1/jobs/" + job_id)
        return _parse_json_answer(status, body) if status == 202 else None

    def wait(self, job_id, progress=None, poll_seconds=0.25, timeout=None):
        """Polls job `job_id` until it finishes and returns what its endpoint answered:
        the response object, or RenderResult for a render. `progress(state)` is called
        with each new state (the job() dict) while it waits. A failed job raises the
        endpoint's ImplicitizerError; a cancelled one raises `cancelled`; `timeout`
        seconds (None: no limit) without the end raises `client_timeout` (the job
        goes on: cancel() it if it is no longer wanted)."""
        deadline = None if timeout is None else time.monotonic() + timeout
        last = None
        while True:
            state = self.job(job_id)
            if progress is not None and state != last:
                progress(state)
            last = state
            if state["status"] in ("done", "failed"):
                return self._job_answer(job_id, state)
            if state["status"] == "cancelled":
                raise ImplicitizerError("cancelled", "job %s was cancelled" % job_id, status=None, limit="cancelled")
            if deadline is not None and time.monotonic() >= deadline:
                raise ImplicitizerError("client_timeout", "job %s did not finish within %g s" % (job_id, timeout))
            time.sleep(poll_seconds)

    def run_as_job(self, kind, request, progress=None, poll_seconds=0.25, timeout=None):
        """submit() then wait(): the endpoint's answer, computed as a job."""
        return self.wait(self.submit(kind, request)["id"], progress, poll_seconds, timeout)

    def _job_answer(self, job_id, state):
        """The answer of a finished job, as the endpoint's method would return it."""
        status, headers, body = self._exchange("GET", "/v1/jobs/%s/result" % job_id, allow_error=True)
        if not 200 <= status < 300:
            raise _error_from_answer(status, headers, body)
        if state["kind"] == "render" and headers.get("content-type") == "image/png":
            return RenderResult(body, _render_stats(headers))
        return _parse_json_answer(status, body)

    # ---- HTTP ----------------------------------------------------------------

    def _post_json(self, path, request):
        """The JSON object answered to POST `request` (a dict) at `path`."""
        status, _, body = self._exchange("POST", path, request)
        return _parse_json_answer(status, body)

    def _exchange(self, method, path, request=None, allow_error=False):
        """(status, headers with lower-case names, body bytes) of a 2xx answer (of
        any answer with `allow_error`); raises ImplicitizerError for any other answer
        and for no answer at all."""
        kind = http.client.HTTPSConnection if self._scheme == "https" else http.client.HTTPConnection
        connection = kind(self._host, self._port, timeout=self.timeout)
        headers = {"Accept": "application/json, image/png, text/plain", "Connection": "close",
                   "User-Agent": "implicitizer-python-client"}
        body = None
        if request is not None:
            body = json.dumps(request, ensure_ascii=False, allow_nan=False).encode("utf-8")
            headers["Content-Type"] = "application/json"
        try:
            connection.request(method, self._prefix + path, body=body, headers=headers)
            response = connection.getresponse()
            data = response.read()
            status = response.status
            answer_headers = {k.lower(): v for k, v in response.getheaders()}
        except socket.timeout:
            raise ImplicitizerError("client_timeout", "no answer from %s within %g s" % (self.url, self.timeout)) \
                from None
        except (OSError, http.client.HTTPException) as e:
            raise ImplicitizerError("connection_failed", "cannot reach %s: %s" % (self.url, e)) from None
        finally:
            connection.close()
        if not allow_error and not 200 <= status < 300:
            raise _error_from_answer(status, answer_headers, data)
        return status, answer_headers, data


# ---- the command line ----------------------------------------------------------

class _UsageError(Exception):
    """A wrong command line: status 2."""


class _Parser(argparse.ArgumentParser):
    """argparse with the C++ CLI's way of failing (`error: ...` and a hint, status 2),
    knowing which of its options take a value (`value_options`), which do not
    (`flag_options`) and whether it takes positional arguments."""

    def __init__(self, **kwargs):
        super().__init__(allow_abbrev=False, **kwargs)
        self.value_options = set()
        self.flag_options = {"--help"}
        self.takes_positionals = False

    def add_argument(self, *args, **kwargs):
        """argparse's add_argument; a name without `--` is a positional argument."""
        if not args[0].startswith("-"):
            self.takes_positionals = True
        return super().add_argument(*args, **kwargs)

    def error(self, message):
        raise _UsageError(message)


class _Once(argparse.Action):
    """Stores an option's value (or True for a flag), refusing it a second time and a
    value outside `allowed`, in the C++ CLI's words ("option --x given twice")."""

    def __init__(self, option_strings, dest, flag=False, allowed=None, **kwargs):
        super().__init__(option_strings, dest, nargs=0 if flag else None, default=False if flag else None, **kwargs)
        self.flag = flag
        self.allowed = allowed

    def __call__(self, parser, namespace, values, option_string=None):
        given = namespace.__dict__.setdefault("_given", set())
        if self.dest in given:
            raise _UsageError("option %s given twice" % self.option_strings[0])
        given.add(self.dest)
        if self.allowed is not None and values not in self.allowed:
            raise _UsageError("unknown %s '%s' (expected %s or %s)" % (
                self.option_strings[0], values, ", ".join(self.allowed[:-1]), self.allowed[-1]))
        setattr(namespace, self.dest, True if self.flag else values)


def _option(parser, name, metavar=None, choices=None, help=None):  # pylint: disable=redefined-builtin
    """Adds `--name VALUE` (given at most once, one of `choices` when given)."""
    parser.value_options.add("--" + name)
    parser.add_argument("--" + name, action=_Once, metavar="|".join(choices) if choices else metavar or "VALUE",
                        help=help, dest=name, allowed=choices)


def _flag(parser, name, help):  # pylint: disable=redefined-builtin
    """Adds `--name` (no value, given at most once)."""
    parser.flag_options.add("--" + name)
    parser.add_argument("--" + name, action=_Once, flag=True, help=help, dest=name)


def _build_parsers():
    """The parser of each command, by name."""
    def command(name, description):
        return _Parser(prog="%s %s" % (PROG, name), description=description)

    parsers = {}
    p = parsers["implicitize"] = command("implicitize",
                                         "Print the implicit equation F(x,y,z) = 0 of a parametrization.")
    _option(p, "x", "E", help="x(params), required")
    _option(p, "y", "E", help="y(params), required")
    _option(p, "z", "E", help="z(params); without it, the implicit curve of a plane parametrization")
    _option(p, "params", "s,t", help="the parameters, in order")
    _option(p, "method", "M", ("auto", "groebner", "resultant", "interpolation"), help="default auto")
    _option(p, "timeout", "SECONDS", help="the computation budget (server default 10 s, at most 60 s)")
    _flag(p, "json", "print the /v1/implicitize response")

    p = parsers["groebner"] = command("groebner", "Print the reduced Gröbner basis of F..., one element per line.")
    _option(p, "vars", "x,y,z", help="the ring's variables, largest first")
    _option(p, "order", "O", ("lex", "grlex", "grevlex"), help="default grevlex")
    _option(p, "weights", "1,2,3", help="a weighted order, one integer per variable")
    _option(p, "eliminate", "s,t", help="print only the generators of the elimination ideal")
    _option(p, "timeout", "SECONDS", help="the computation budget")
    _flag(p, "json", "print the /v1/groebner response")
    p.add_argument("polynomials", nargs="*", metavar="F")

    p = parsers["resultant"] = command("resultant", "Print Res_t(F, G).")
    _option(p, "var", "t", help="the variable to eliminate, required")
    _option(p, "timeout", "SECONDS", help="the computation budget")
    _flag(p, "json", "print the /v1/resultant response")
    p.add_argument("polynomials", nargs="*", metavar="F G")

    p = parsers["sdf"] = command("sdf", "Print the GLSL distance function float NAME_sdf(vec3 p).")
    _object_options(p)
    _option(p, "box", "x0,y0,z0,x1,y1,z1", help="the box, default -2,-2,-2,2,2,2 (a curve: x0,y0,x1,y1)")
    _option(p, "name", "NAME", help="the function's prefix, default surface")
    _option(p, "timeout", "SECONDS", help="the computation budget")
    _flag(p, "json", "print the /v1/sdf response")

    p = parsers["render"] = command("render", "Write a PNG preview (sphere tracing by default).")
    _object_options(p)
    _option(p, "output", "FILE.png", help="where to write the PNG, required (also -o)")
    _option(p, "method", "M", ("sphere", "enhanced", "newton", "forward_newton", "exact"), help="default sphere")
    _option(p, "size", "WxH", help="pixels, default 256x256")
    _option(p, "aa", "N", help="NxN samples per pixel, 1 to 8, default 2")
    _option(p, "eye", "x,y,z", help="the camera")
    _option(p, "target", "x,y,z", help="the look-at point")
    _option(p, "box", "x0,y0,z0,x1,y1,z1", help="the scene box")
    _option(p, "name", "NAME", help="the prefix of the scene's functions")
    _option(p, "precision", "P", ("float", "double"), help="default float")
    _option(p, "timeout", "SECONDS", help="the computation budget")
    _flag(p, "json", "print the render statistics as JSON")

    parsers["health"] = command("health", "Print GET /healthz.")
    parsers["metrics"] = command("metrics", "Print GET /metrics (Prometheus text).")
    return parsers


_COMMAND_HELP = """commands:
  implicitize --x E --y E [--z E] [--params s,t] [--method M] [--timeout S] [--json]
  groebner [--vars x,y] [--order lex|grlex|grevlex] [--weights 1,2] [--eliminate s] [--json] F...
  resultant --var t [--json] F G
  sdf (--implicit E | --x E --y E [--z E] | --scene FILE.json) [--shape auto|sheet|solid]
      [--domain s0,s1[,t0,t1]] [--tolerance EPS] [--mode fast|safe] [--box ...] [--name NAME] [--json]
  render (--implicit E | --x E --y E [--z E] | --scene FILE.json) -o FILE.png [--shape S] [--domain D]
         [--tolerance EPS]
         [--method M] [--size WxH]
         [--aa N] [--eye x,y,z] [--target x,y,z] [--precision float|double] [--json]
  health, metrics, help [COMMAND]

The server is --url URL, else $IMPLICITIZER_URL, else %s.
Exit status: 0 ok, 1 internal error or no answer, 2 usage, 3 invalid input,
4 no single implicit equation or tolerance not met, 5 time or size limit
(clients/python/README.md).
""" % DEFAULT_URL


def _object_options(p):
    """The options of the object `sdf` and `render` share, with its shape, domain and mode."""
    _option(p, "implicit", "E", help="the polynomial F(x,y,z) (without z: a plane curve)")
    _option(p, "x", "E", help="a parametric surface: x(params), with --y and --z (no --z: a plane curve)")
    _option(p, "y", "E")
    _option(p, "z", "E")
    _option(p, "params", "s,t", help="the parametrization's parameters, in order")
    _option(p, "scene", "FILE.json", help="a scene (docs/sdf.md, \"Scenes\")")
    _option(p, "shape", "S", ("auto", "sheet", "solid"), help="default auto")
    _option(p, "domain", "s0,s1[,t0,t1]", help="the parameter domain (exact numbers)")
    _option(p, "tolerance", "EPS", help="approximate the patch within EPS x its box's diagonal (0 < EPS <= 0.5)")
    _option(p, "mode", "M", ("fast", "safe"), help="default fast")


def _top_parser():
    """The parser of what comes before the command."""
    p = _Parser(prog=PROG, description="Client of implicitizer-server (docs/api.md).", epilog=_COMMAND_HELP,
                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--url", help="the server (default: $IMPLICITIZER_URL or %s)" % DEFAULT_URL)
    p.add_argument("command", help="implicitize, groebner, resultant, sdf, render, health, metrics or help")
    p.add_argument("arguments", nargs=argparse.REMAINDER, help=argparse.SUPPRESS)
    return p


def _normalize_words(words, parser, short_options):
    """Rewrites one command's words so that argparse reads them as the C++ CLI does
    (clients/cli/arguments.cpp): only words starting with `--` are options (`-h` and
    `short_options` aside), so `groebner -x^2+y y^2-x` has two polynomials; an option
    that takes a value takes the next word unless it starts with `--` (`--x -s`);
    `--` ends the options. Refuses, in the C++ CLI's words, an unknown option, a
    missing value, a value given to a flag and an argument where none is taken."""
    options, positionals = [], []
    i = 0
    while i < len(words):
        word = short_options.get(words[i], words[i])
        if word == "--":
            positionals.extend(words[i + 1:])
            break
        if word == "-h":
            options.append("--help")
        elif word.startswith("--"):
            name, equals, _ = word.partition("=")
            if name not in parser.value_options and name not in parser.flag_options:
                raise _UsageError("unknown option " + name)
            if name in parser.flag_options:
                if equals:
                    raise _UsageError("option %s takes no value" % name)
                options.append(word)
            elif equals:
                options.append(word)
            elif i + 1 < len(words) and not words[i + 1].startswith("--"):
                options.append(word + "=" + words[i + 1])
                i += 1
            else:
                raise _UsageError("option %s needs a value" % name)
        else:
            positionals.append(word)
        i += 1
    if positionals and not parser.takes_positionals:
        raise _UsageError("unexpected argument '%s'" % positionals[0])
    return options + (["--"] + positionals if positionals else [])


def _split_list(text, flag):
    """`s, t` → ["s", "t"]; blank → []; an empty item is a usage error (as the C++ CLI)."""
    if not text.strip():
        return []
    items = [item.strip() for item in text.split(",")]
    if any(not item for item in items):
        raise _UsageError("--%s: empty item in the list '%s'" % (flag, text))
    return items


def _parse_numbers(text, flag, count=None):
    """`1,2,3` → [1.0, 2.0, 3.0], finite numbers (`count` of them when given: a point)."""
    numbers = []
    for item in _split_list(text, flag):
        try:
            value = float(item)
        except ValueError:
            value = math.nan
        if not math.isfinite(value):
            raise _UsageError("--%s: '%s' is not a finite number" % (flag, item))
        numbers.append(value)
    if count is not None and len(numbers) != count:
        raise _UsageError("--%s must be three numbers x,y,z" % flag)
    return numbers


def _list_option(args, flag):
    """The list of option `--flag`, or None when it is not given."""
    text = getattr(args, flag)
    return None if text is None else _split_list(text, flag)


def _numbers_option(args, flag, count=None):
    """The numbers of option `--flag` (`count` of them when given), or None."""
    text = getattr(args, flag)
    return None if text is None else _parse_numbers(text, flag, count)


def _parse_count(text, flag):
    """A non-negative integer, as the C++ CLI reads `--aa` and `--size`."""
    text = text.strip()
    if not (text.isascii() and text.isdigit()):
        raise _UsageError("--%s needs a non-negative integer, not '%s'" % (flag, text))
    return int(text)


def _parse_int(text, flag):
    """An integer with an optional sign (`--weights`: the server checks the range)."""
    digits = text.strip().lstrip("+-")
    if not (digits.isascii() and digits.isdigit()) or len(text.strip()) - len(digits) > 1:
        raise _UsageError("--%s needs integers, not '%s'" % (flag, text))
    return int(text)


def _timeout_ms(args):
    """`--timeout SECONDS` (a number > 0) as the request's timeout_ms, or None."""
    if args.timeout is None:
        return None
    try:
        seconds = float(args.timeout)
    except ValueError:
        seconds = math.nan
    if not math.isfinite(seconds) or seconds <= 0:
        raise _UsageError("--timeout needs a positive number of seconds, not '%s'" % args.timeout)
    return seconds * 1000.0


def _read_scene(path):
    """(text, scene) of a --scene file: unreadable is a usage error; bad JSON, NaN or
    a key given twice is invalid input (status 3), as the C++ CLI reads it."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        raise _UsageError("cannot read scene file '%s' (%s)" % (path, e.strerror)) from None
    except UnicodeDecodeError:
        raise _UsageError("cannot read scene file '%s' (not UTF-8)" % path) from None

    def refuse_constant(name):
        raise ValueError("%s is not JSON" % name)

    def refuse_duplicates(pairs):
        keys = [k for k, _ in pairs]
        for k in keys:
            if keys.count(k) > 1:
                raise ImplicitizerError("invalid_scene", "key '%s' is given twice" % k, field="scene")
        return dict(pairs)

    try:
        return text, json.loads(text, parse_constant=refuse_constant, object_pairs_hook=refuse_duplicates)
    except ValueError as e:
        raise ImplicitizerError("invalid_json", "invalid JSON: %s" % getattr(e, "msg", e),
                                position=getattr(e, "pos", None)) from None


def _print_json(answer):
    """Prints `answer` as compact JSON on one line, as the C++ CLI prints the endpoint's object."""
    print(json.dumps(answer, ensure_ascii=False, separators=(",", ":")))


def _run_implicitize(client, args, field_texts):
    """`implicitize`: the equation on one line."""
    for coordinate in ("x", "y"):
        if getattr(args, coordinate) is None:
            raise _UsageError("missing --" + coordinate)
    field_texts.update(x=args.x, y=args.y, z=args.z)
    answer = client.implicitize(args.x, args.y, args.z, _list_option(args, "params"), args.method, _timeout_ms(args))
    if args.json:
        _print_json(answer)
    else:
        print(answer["implicit"])


def _run_groebner(client, args, field_texts):
    """`groebner`: the basis (with --eliminate the elimination ideal), one element per line."""
    if not args.polynomials:
        raise _UsageError("no polynomials given")
    weights = None
    if args.weights is not None:
        weights = [_parse_int(w, "weights") for w in _split_list(args.weights, "weights")]
    field_texts.update(("polynomials[%d]" % i, f) for i, f in enumerate(args.polynomials))
    answer = client.groebner(args.polynomials, _list_option(args, "vars"), args.order, weights,
                             _list_option(args, "eliminate"), _timeout_ms(args))
    if args.json:
        _print_json(answer)
    else:
        for g in answer.get("elimination_ideal", answer["basis"]):
            print(g)


def _run_resultant(client, args, field_texts):
    """`resultant`: Res_t(F, G) on one line."""
    if args.var is None:
        raise _UsageError("missing --var (the variable to eliminate)")
    if len(args.polynomials) != 2:
        raise _UsageError("a resultant needs exactly two polynomials F G, got %d" % len(args.polynomials))
    f, g = args.polynomials
    field_texts.update({"variable": args.var, "polynomials[0]": f, "polynomials[1]": g})
    answer = client.resultant(f, g, args.var, _timeout_ms(args))
    if args.json:
        _print_json(answer)
    else:
        print(answer["resultant"])


def _tolerance(args):
    """--tolerance as a JSON number; a text that is not a finite number is sent as is,
    so that the server refuses it as the C++ CLI does (invalid_tolerance, status 3)."""
    if args.tolerance is None:
        return None
    try:
        value = float(args.tolerance)
    except ValueError:
        return args.tolerance
    return value if math.isfinite(value) else args.tolerance


def _object_of(args, field_texts):
    """The request fields naming the object (implicit, scene, or x, y[, z]) and its
    shape and domain, as the C++ CLI reads them (clients/cli/scene_flags.cpp)."""
    parametric = any(getattr(args, c) is not None for c in "xyz")
    given = (args.implicit is not None) + (args.scene is not None) + parametric
    if given != 1:
        raise _UsageError("give exactly one of --implicit E, --x E --y E [--z E], or --scene FILE.json")
    if args.params is not None and not parametric:
        raise _UsageError("--params goes with --x --y [--z]")
    fields = {"shape": args.shape, "domain": _list_option(args, "domain"), "tolerance": _tolerance(args)}
    if args.scene is not None:
        text, scene = _read_scene(args.scene)
        field_texts["scene"] = text
        return dict(fields, scene=scene)
    if args.implicit is not None:
        field_texts["implicit"] = args.implicit
        return dict(fields, implicit=args.implicit)
    if args.x is None or args.y is None:
        raise _UsageError("a parametric surface needs --x, --y and --z, a plane curve --x and --y")
    field_texts.update(x=args.x, y=args.y, z=args.z or "")
    return dict(fields, x=args.x, y=args.y, z=args.z, parameters=_list_option(args, "params"))


def _run_sdf(client, args, field_texts):
    """`sdf`: the GLSL source."""
    surface = _object_of(args, field_texts)
    answer = client.sdf(mode=args.mode, box=_numbers_option(args, "box"), name=args.name,
                        timeout_ms=_timeout_ms(args), **surface)
    if args.json:
        _print_json(answer)
    else:
        sys.stdout.write(answer["glsl"])


def _run_render(client, args, field_texts):
    """`render`: writes the PNG; the statistics as JSON (--json) or a summary on stderr."""
    surface = _object_of(args, field_texts)
    if args.output is None:
        raise _UsageError("missing -o FILE.png (where to write the image)")
    width = height = aa = None
    if args.size is not None:
        w, sep, h = args.size.partition("x")
        if not sep:
            raise _UsageError("--size must be WIDTHxHEIGHT, e.g. 256x256, not '%s'" % args.size)
        width, height = _parse_count(w, "size"), _parse_count(h, "size")
    if args.aa is not None:
        aa = _parse_count(args.aa, "aa")
        if not 1 <= aa <= 8:
            raise _UsageError("--aa must be 1 to 8")
    # format json: the statistics then include shading_evaluations and threads, as
    # `implicitizer render --json` prints them.
    png, stats = client.render(
        mode=args.mode, box=_numbers_option(args, "box"), name=args.name, width=width, height=height,
        method=args.method, aa=aa, eye=_numbers_option(args, "eye", 3), target=_numbers_option(args, "target", 3),
        precision=args.precision, format="json", timeout_ms=_timeout_ms(args), **surface)
    try:
        with open(args.output, "wb") as f:
            f.write(png)
    except OSError as e:
        print("error: cannot write '%s' (%s)" % (args.output, e.strerror), file=sys.stderr)
        return EXIT_USAGE
    if args.json:
        _print_json(stats)
    else:
        print("wrote %s (%sx%s, %s of %s rays hit, %s evaluations per ray, %s ms)" % (
            args.output, stats.get("width"), stats.get("height"), stats.get("hits"), stats.get("rays"),
            stats.get("mean_evaluations"), stats.get("elapsed_ms")), file=sys.stderr)


def _run_health(client, args, field_texts):
    """`health`: GET /healthz's object."""
    _print_json(client.health())


def _run_metrics(client, args, field_texts):
    """`metrics`: GET /metrics's text."""
    sys.stdout.write(client.metrics_text())


# Each command's runner: prints the answer, returns None (status 0) or an exit status;
# raises _UsageError or ImplicitizerError. `field_texts` collects the text of each
# request field, for the caret under an error's position.
_RUNNERS = {"implicitize": _run_implicitize, "groebner": _run_groebner, "resultant": _run_resultant,
            "sdf": _run_sdf, "render": _run_render, "health": _run_health, "metrics": _run_metrics}


def exit_status(error):
    """The command line's exit status for an ImplicitizerError (also for scripts that
    use the library and want the CLI's statuses), as build/bin/implicitizer
    would end on the same refusal: 3 invalid input (400, and render_too_large),
    4 no single equation, base points or tolerance_not_met (422), 5 a time, size or cancellation limit
    (504, 413, 431, 503 cancelled, client_timeout), 2 unknown_method (the C++ CLI's
    usage error), 1 anything else (500, 503 overloaded, 404, connection_failed,
    bad_response)."""
    by_code = {"unknown_method": EXIT_USAGE, "render_too_large": EXIT_INVALID_INPUT,
               "invalid_json": EXIT_INVALID_INPUT, "invalid_scene": EXIT_INVALID_INPUT,
               "cancelled": EXIT_LIMIT, "client_timeout": EXIT_LIMIT}
    by_status = {400: EXIT_INVALID_INPUT, 413: EXIT_LIMIT, 422: EXIT_NO_SINGLE_EQUATION, 431: EXIT_LIMIT,
                 504: EXIT_LIMIT}
    return by_code.get(error.code, by_status.get(error.status, EXIT_INTERNAL))


def _usage(message, command=None):
    """Prints a usage error as the C++ CLI does; returns 2."""
    print("error: %s\nrun '%s %s--help' for usage" % (message, PROG, command + " " if command else ""),
          file=sys.stderr)
    return EXIT_USAGE


def _report_error(error, status, field_texts, json_output):
    """Prints a refusal as build/bin/implicitizer does (clients/cli/error_report.cpp)."""
    if json_output:
        _print_json({"error": error.error})
    if status == EXIT_INVALID_INPUT:
        line = "error: " + error.code
        if error.position is not None:
            line += " at position %d" % error.position
        if error.field is not None:
            line += " in " + error.field
        print(line + ": " + error.message, file=sys.stderr)
        text = field_texts.get(error.field)
        if error.position is not None and text is not None and "\n" not in text and error.position <= len(text):
            prefix = "  %s = " % error.field
            print(prefix + text + "\n" + " " * (len(prefix) + error.position) + "^", file=sys.stderr)
    elif error.limit is not None:
        print("error: %s (%s limit): %s" % (error.code, error.limit, error.message), file=sys.stderr)
    else:
        print("error: %s: %s" % (error.code, error.message), file=sys.stderr)
        if error.code == "no_single_equation" and error.generators is not None:
            if error.generators:
                print("generators of the elimination ideal:", file=sys.stderr)
                for g in error.generators:
                    print("  " + g, file=sys.stderr)
            else:
                print("the elimination ideal is zero", file=sys.stderr)
        elif error.retry_after is not None:
            print("retry after %d s" % error.retry_after, file=sys.stderr)


def main(argv=None):
    """Runs the command line on `argv` (default sys.argv[1:]); returns the exit status."""
    argv = sys.argv[1:] if argv is None else list(argv)
    top = _top_parser()
    parsers = _build_parsers()
    try:
        if not argv or argv[0] in ("-h", "--help"):
            top.print_help()
            return EXIT_OK if argv else EXIT_USAGE
        head = top.parse_args(argv)
    except _UsageError as e:
        return _usage(str(e))
    if head.command == "help":
        topic = head.arguments[0] if head.arguments else None
        if topic is not None and topic not in parsers:
            return _usage("no help for unknown command '%s'" % topic)
        (parsers[topic] if topic is not None else top).print_help()
        return EXIT_OK
    if head.command not in parsers:
        return _usage("unknown command '%s'" % head.command)
    parser = parsers[head.command]
    field_texts = {}
    json_output = False
    try:
        args = parser.parse_args(_normalize_words(head.arguments, parser, {"-o": "--output"}
                                                  if head.command == "render" else {}))
        json_output = getattr(args, "json", False)
        try:
            client = Client(head.url)
        except ValueError as e:  # a --url that is not one
            raise _UsageError(str(e)) from None
        status = _RUNNERS[head.command](client, args, field_texts)
    except _UsageError as e:
        return _usage(str(e), head.command)
    except ImplicitizerError as e:
        status = exit_status(e)
        if status == EXIT_USAGE:
            if json_output:
                _print_json({"error": e.error})
            return _usage(e.message, head.command)
        _report_error(e, status, field_texts, json_output)
        return status
    sys.stdout.flush()
    return EXIT_OK if status is None else status


if __name__ == "__main__":
    sys.exit(main())
