"""Starts build/bin/implicitizer-server on an ephemeral loopback port and talks HTTP to
it with the standard library only (http.client, socket), and reads back the PNGs it
renders. Shared by server_test.py, reproduce_test.py and
tests/clients/python_client_test.py."""

import http.client
import json
import os
import signal
import socket
import struct
import subprocess
import tempfile
import threading
import time
import zlib


# Added to every time bound of the end-to-end tests: what a loaded 2-core CI machine
# may take beyond the limit under test (the bound still fails a limit that does not
# hold: those took minutes or never answered).
LOAD_ALLOWANCE_S = 10.0


class Checks:
    """The verdicts of one test script: `check(condition, message)` counts a check and
    prints a failure as it happens; `summary()` is the closing line."""

    def __init__(self):
        self.count = 0
        self.failures = []

    def check(self, condition, message):
        self.count += 1
        if not condition:
            self.failures.append(message)
            print("FAIL:", message)

    def summary(self):
        return "%d passed, %d failed" % (self.count - len(self.failures), len(self.failures))


def run_tests(checks, tests):
    """Runs each test (a callable); an exception fails that test, and the others still run."""
    import traceback
    for test in tests:
        try:
            test()
        except Exception:  # noqa: BLE001 - a crash of one test is a failure, the others still run
            checks.failures.append(traceback.format_exc())
            print("FAIL (exception):", traceback.format_exc())


def close_showing_log(server, checks):
    """Closes `server`, first printing its log's tail when a check has failed."""
    if checks.failures:
        print("---- server log (tail) ----")
        print(server.log_text()[-3000:])
    server.close()


def error_code(body):
    """The `error.code` of a JSON error body, or None."""
    try:
        return body["error"]["code"]
    except (TypeError, KeyError):
        return None


class Server:
    """A running implicitizer-server; `port` is the one it printed on its first line."""

    def __init__(self, binary, *flags):
        self.log = tempfile.NamedTemporaryFile(prefix="implicitizer-server-", suffix=".log", delete=False)
        self.proc = subprocess.Popen([binary, "--host", "127.0.0.1", "--port", "0", *flags],
                                     stdout=subprocess.PIPE, stderr=self.log, text=True)
        line = [None]

        def read_first_line():
            line[0] = self.proc.stdout.readline()

        reader = threading.Thread(target=read_first_line, daemon=True)
        reader.start()
        reader.join(20)
        if not line[0] or "listening on" not in line[0]:
            self.proc.kill()
            raise RuntimeError("server did not start: %r; log:\n%s" % (line[0], self.log_text()))
        self.port = int(line[0].strip().rsplit(":", 1)[1])

    def log_text(self):
        with open(self.log.name, encoding="utf-8", errors="replace") as f:
            return f.read()

    def stop(self, timeout=20):
        """SIGTERM, then the exit status (None if it had to be killed)."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                return self.proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
                return None
        return self.proc.returncode

    def close(self):
        self.stop()
        os.unlink(self.log.name)

    # ---- HTTP -----------------------------------------------------------

    def request(self, method, path, body=None, headers=None, timeout=60):
        """(status, headers as a lower-cased dict, body bytes) of one request."""
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        try:
            if isinstance(body, (dict, list)):
                body = json.dumps(body)
            conn.request(method, path, body=body, headers=headers or {})
            response = conn.getresponse()
            return response.status, {k.lower(): v for k, v in response.getheaders()}, response.read()
        finally:
            conn.close()

    def post_json(self, path, body, timeout=60):
        status, headers, data = self.request("POST", path, body, {"Content-Type": "application/json"}, timeout)
        return status, headers, json.loads(data) if data else None

    def raw(self, data, timeout=10):
        """Sends raw bytes, returns every byte the server sends until it closes."""
        with socket.create_connection(("127.0.0.1", self.port), timeout=timeout) as s:
            s.sendall(data)
            chunks = []
            try:
                while True:
                    chunk = s.recv(65536)
                    if not chunk:
                        break
                    chunks.append(chunk)
            except (ConnectionResetError, socket.timeout):
                pass
            return b"".join(chunks)

    def metric(self, name):
        """The value of an unlabelled metric line `name V`, or of the sum of `name{...} V` lines."""
        _, _, body = self.request("GET", "/metrics")
        total = None
        for line in body.decode().splitlines():
            if line.startswith(name + " ") or line.startswith(name + "{"):
                total = (total or 0) + float(line.rsplit(" ", 1)[1])
        return total


class Redis:
    """A redis-server on a free loopback port, no persistence, in a temporary directory
    (jobs_redis_test.py, slow_store_test.py)."""

    def __init__(self, binary):
        self.dir = tempfile.mkdtemp(prefix="implicitizer-redis-")
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            self.port = s.getsockname()[1]
        self.proc = subprocess.Popen([binary, "--port", str(self.port), "--bind", "127.0.0.1", "--save", "",
                                      "--appendonly", "no", "--dir", self.dir],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        end = time.monotonic() + 30
        while time.monotonic() < end:
            try:
                with socket.create_connection(("127.0.0.1", self.port), timeout=1) as c:
                    c.sendall(b"PING\r\n")
                    if c.recv(16).startswith(b"+PONG"):
                        return
            except OSError:
                time.sleep(0.05)
        raise RuntimeError("redis-server did not answer on port %d" % self.port)

    def count_keys(self, pattern):
        """How many keys match `pattern` (KEYS: fine on a test's small database)."""
        with socket.create_connection(("127.0.0.1", self.port), timeout=30) as c:
            c.sendall(b"*2\r\n$4\r\nKEYS\r\n$%d\r\n%s\r\n" % (len(pattern), pattern.encode()))
            reply = b""
            while b"\r\n" not in reply:
                chunk = c.recv(4096)
                if not chunk:
                    break
                reply += chunk
        if not reply.startswith(b"*"):
            raise RuntimeError("KEYS answered %r" % reply[:100])
        return int(reply[1:reply.index(b"\r\n")])

    def close(self):
        self.proc.send_signal(signal.SIGCONT)  # a test may have stopped it
        self.proc.terminate()
        self.proc.wait(30)


def decode_png(data):
    """(width, height, rows) of an 8-bit RGB, non-interlaced PNG, each row `3 * width`
    bytes, after checking the signature, every chunk's CRC and undoing the filters."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise AssertionError("not a PNG signature: %r" % data[:8])
    pos, chunks = 8, []
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        payload = data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        if crc != zlib.crc32(kind + payload):
            raise AssertionError("bad CRC in chunk %r" % kind)
        chunks.append((kind, payload))
        pos += 12 + length
    if chunks[0][0] != b"IHDR" or chunks[-1][0] != b"IEND":
        raise AssertionError("chunks %r" % [k for k, _ in chunks])
    width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunks[0][1])
    if (depth, colour, interlace) != (8, 2, 0):
        raise AssertionError("not 8-bit RGB non-interlaced: %r" % ((depth, colour, interlace),))
    raw = zlib.decompress(b"".join(p for k, p in chunks if k == b"IDAT"))
    stride = 3 * width
    if len(raw) != height * (stride + 1):
        raise AssertionError("IDAT holds %d bytes for %dx%d" % (len(raw), width, height))
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b = previous[i]
            c = previous[i - 3] if i >= 3 else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
            elif kind != 0:
                raise AssertionError("unknown filter %d in row %d" % (kind, y))
        rows.append(bytes(line))
        previous = line
    return width, height, rows


def pixel(rows, x, y):
    """The (r, g, b) bytes of pixel (x, y) of decode_png's rows."""
    return rows[y][3 * x:3 * x + 3]
