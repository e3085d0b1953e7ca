"""A small client for HABLA's control sockets, in Python 3 with the standard library only.

Every exposed method of a HABLA daemon has its own TCP port. On connect the daemon sends a hello
line describing the method; then it streams one JSON object per line. A line may declare
"bytes": N, in which case N raw bytes (audio, images) follow its newline.

    from habla_client import ControlSocket
    with ControlSocket("127.0.0.1", 7002) as s:
        print(s.hello["outputs"])
        sample = s.next_sample(timeout=2.0)
        print(sample["value"])
    with ControlSocket("127.0.0.1", 7004) as action:
        action.write("forward")

Where the daemon requires authentication (its hello says "auth": "required"), the client sends its name and
token first: give client= and token=, or set HABLA_CLIENT and HABLA_TOKEN. For a socket that speaks TLS give
tls= the lab's certificate file (or an ssl.SSLContext) (docs/security.md):

    with ControlSocket("robot.lab", 7002, client="mdb", token=TOKEN, tls="lab.crt") as s:
        print(s.next_sample())
"""

import json
import os
import socket
import ssl
import threading
import time

# How often keep_alive() pings a quiet socket at most; on a full socket the daemon lets a new client push out a
# client that has sent nothing and been sent nothing for limits.evictableIdleMs (2 minutes by default).
KEEP_ALIVE_S = 60.0


class ControlError(Exception):
    """The daemon answered with an error line."""

    def __init__(self, line):
        super().__init__("%s: %s" % (line.get("code"), line.get("message")))
        self.code = line.get("code")
        self.line = line


def _parse(line):
    """One line as a dict; a line that is not a JSON object becomes an "invalid" report instead."""
    raw = line.decode("utf-8", errors="replace")
    try:
        text = line.decode("utf-8")
    except UnicodeDecodeError as e:
        return _invalid("bad_utf8", "the line is not valid UTF-8: %s" % e, raw)
    try:
        obj = json.loads(text)
    except ValueError as e:
        return _invalid("bad_json", "the line is not JSON: %s" % e, raw)
    if not isinstance(obj, dict):
        return _invalid("not_object", "a line must be a JSON object, was %s" % _json_type(obj), raw)
    return obj


def _json_type(value):
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, (int, float)):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "an array"
    return "null"


def _invalid(code, message, raw):
    return {"type": "invalid", "code": code, "message": message, "raw": raw[:200]}


class ControlSocket:
    """One connection to one method's control socket."""

    def __init__(self, host, port, timeout=5.0, max_line=1 << 20, announce=True, client=None, token=None,
                 tls=None):
        """Connects and reads the hello. With announce (the default) it sends one ping at once: a connection
        that has sent no request is only "pending" for the daemon, which lets newcomers push it out when the port
        is crowded (docs/protocol.md).

        Where the hello says authentication is required, it authenticates as client with token (default: the
        HABLA_CLIENT and HABLA_TOKEN environment variables) and self.hello is the full hello that follows. tls
        is None for plain TCP, a certificate file to trust, or an ssl.SSLContext."""
        self._sock = socket.create_connection((host, port), timeout=timeout)
        if tls is not None:
            context = tls if isinstance(tls, ssl.SSLContext) else ssl.create_default_context(cafile=tls)
            try:
                self._sock = context.wrap_socket(self._sock, server_hostname=host)
            except BaseException:
                self._sock.close()
                raise
        self._buf = b""
        self._max_line = max_line
        self._send_lock = threading.Lock()
        self._last_sent = time.monotonic()
        self.events = []  # stale / dropped / error / invalid lines seen while waiting for samples
        try:
            self.hello = self.read_line(timeout)
            if self.hello is None:
                raise ConnectionError("the daemon closed the connection before its hello")
            if self.hello.get("type") == "error":
                raise ControlError(self.hello)
            if self.hello.get("type") != "hello":
                raise ConnectionError("expected a hello line, got %r" % (self.hello,))
            if self.hello.get("auth") == "required":
                self._authenticate(client or os.environ.get("HABLA_CLIENT"),
                                   token or os.environ.get("HABLA_TOKEN"), timeout)
            elif announce:
                self.send({"op": "ping"})
        except BaseException:
            self.close()
            raise

    def _authenticate(self, client, token, timeout):
        """Sends the auth line and reads the full hello that answers it, or raises the daemon's error."""
        if not client or not token:
            raise ControlError({"code": "auth_required", "message": "socket %r requires authentication: give "
                                "client= and token= (or HABLA_CLIENT and HABLA_TOKEN)" % self.hello.get("socket")})
        self.send({"op": "auth", "client": client, "token": token})
        answer = self.read_line(timeout)
        if answer is None:
            raise ConnectionError("the daemon closed the connection instead of answering the auth line")
        if answer.get("type") == "error":
            raise ControlError(answer)
        if answer.get("type") != "hello":
            raise ConnectionError("expected the full hello after authenticating, got %r" % (answer,))
        self.hello = answer

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        try:
            self._sock.close()
        except OSError:
            pass

    def _fill(self, deadline):
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            raise socket.timeout("timed out")
        self._sock.settimeout(remaining)
        chunk = self._sock.recv(65536)
        if not chunk:
            return False
        self._buf += chunk
        return True

    def read_line(self, timeout=5.0):
        """The next line as a dict (with its binary block under "_bytes"), or None at end of stream.

        A line that is not a JSON object (not UTF-8, not JSON, or JSON such as [1, 2] or "x") does not
        stop the client: it comes back as {"type": "invalid", "code": ..., "message": ..., "raw": ...},
        with the codes the daemon itself uses (bad_utf8, bad_json, not_object).
        """
        deadline = time.monotonic() + timeout
        while b"\n" not in self._buf:
            if len(self._buf) > self._max_line:
                raise ValueError("line longer than %d bytes" % self._max_line)
            if not self._fill(deadline):
                return None
        line, self._buf = self._buf.split(b"\n", 1)
        obj = _parse(line)
        n = obj.get("bytes")
        if type(n) is int and n > 0:  # not bool: True is an int in Python
            while len(self._buf) < n:
                if not self._fill(deadline):
                    return None
            obj["_bytes"], self._buf = self._buf[:n], self._buf[n:]
        return obj

    def next_sample(self, timeout=5.0):
        """The next sample line; other lines (stale, dropped, errors, invalid lines) are kept in self.events."""
        deadline = time.monotonic() + timeout
        while True:
            line = self.read_line(max(0.0, deadline - time.monotonic()))
            if line is None:
                return None
            if line.get("type") == "sample":
                return line
            self.events.append(line)

    def send(self, obj):
        """Sends one request line (safe to call from several threads)."""
        data = (json.dumps(obj) + "\n").encode("utf-8")
        with self._send_lock:
            self._sock.sendall(data)
            self._last_sent = time.monotonic()

    def keep_alive(self):
        """Sends a ping if nothing was sent for a while, so that a client of a quiet socket is not the idle one
        that gives way to a new client when the socket is full. Call it now and then (e.g. whenever a read times out); it sends at most one line per
        KEEP_ALIVE_S, or per a third of the hello's idleTimeoutMs if that is shorter."""
        idle_ms = (self.hello.get("limits") or {}).get("idleTimeoutMs") or 0
        every = KEEP_ALIVE_S if not idle_ms else min(KEEP_ALIVE_S, idle_ms / 3000.0)
        if time.monotonic() - self._last_sent >= every:
            self.send({"op": "ping"})

    def write(self, value, input_name=None, request_id=None):
        """Writes a value to the method's control input (the only one, unless input_name names it)."""
        req = {"op": "write", "value": value}
        if input_name is not None:
            req["input"] = input_name
        if request_id is not None:
            req["id"] = request_id
        self.send(req)

    def request(self, obj, timeout=5.0):
        """Sends a request with an id and waits for its ok or error line."""
        rid = obj.setdefault("id", int(time.monotonic() * 1e6))
        self.send(obj)
        deadline = time.monotonic() + timeout
        while True:
            line = self.read_line(max(0.0, deadline - time.monotonic()))
            if line is None:
                raise ConnectionError("closed while waiting for the answer to %r" % (obj,))
            if line.get("id") == rid:
                if line.get("type") == "error":
                    raise ControlError(line)
                return line
            if line.get("type") != "sample":
                self.events.append(line)
