"""A blocking client of one HABLA control socket.

    import habla
    with habla.connect("127.0.0.1", 7002) as s:
        print(s.hello.outputs)
        for sample in s.samples():
            print(sample.seq, sample.t_us, sample.stale, sample.value)
    with habla.connect("127.0.0.1", 7004) as action:
        action.write_and_wait("forward")        # the daemon's ok, or RefusedError (busy, bad_value, ...)

Threads: one thread reads (samples, read_frame, request); any thread may send (write, ping, take).
"""

import collections
import os
import socket
import ssl
import threading
import time

from .errors import AuthError, LinkLostError, RefusedError, TlsError
from .framing import FrameReader, encode
from .hello import Hello, Sample

KEEP_ALIVE_S = 60.0      # keep_alive() pings at most this often (or a third of the hello's idleTimeoutMs);
                         # the daemon lets a newcomer push out a client silent for evictableIdleMs (2 min)
EVENTS_KEPT = 256        # non-sample lines remembered in .events
SAMPLES_HELD = 256       # samples held while request() waits for its answer (the daemon's default queue)
RECV_BYTES = 65536


def connect(host, port, timeout=5.0, client=None, token=None, tls=None, announce=True):
    """Connects to one socket and reads its hello (authenticating first where the socket requires it).

    client, token: the credentials for a socket that requires authentication (default: the HABLA_CLIENT and
    HABLA_TOKEN environment variables). tls: None for plain TCP, the lab certificate file to trust, or an
    ssl.SSLContext. announce: send one ping at once, so the daemon counts this connection as a client rather
    than a pending connection that newcomers may push out."""
    return ControlSocket(host, port, timeout, client, token, tls, announce)


def tls_context(tls):
    """An SSL context that trusts the given certificate file (or the context itself)."""
    return tls if isinstance(tls, ssl.SSLContext) else ssl.create_default_context(cafile=str(tls))


class ControlSocket:
    """One connection to one method's control socket."""

    def __init__(self, host, port, timeout=5.0, client=None, token=None, tls=None, announce=True):
        self.address = (host, port)
        self.events = collections.deque(maxlen=EVENTS_KEPT)
        self.stale = False
        self.dropped = 0          # samples the daemon dropped for this client, as its dropped lines said
        self.commander = None     # on an actuating socket: the holder of the last control line
        self._held = collections.deque(maxlen=SAMPLES_HELD)
        self._reader = FrameReader()
        self._frames = collections.deque()
        self._send_lock = threading.Lock()
        self._last_sent = time.monotonic()
        self._next_id = 0
        try:
            self._sock = socket.create_connection((host, port), timeout=timeout)
        except OSError as e:
            raise LinkLostError("cannot connect to %s:%s: %s" % (host, port, e)) from e
        try:
            if tls is not None:
                try:
                    self._sock = tls_context(tls).wrap_socket(self._sock, server_hostname=host)
                except ssl.SSLError as e:
                    raise TlsError("TLS with %s:%s failed: %s" % (host, port, e)) from e
            first = self.read_frame(timeout)
            if first.get("type") == "error":
                raise RefusedError(first)
            self.hello = Hello(first)
            if self.hello.auth_required:
                self._authenticate(client or os.environ.get("HABLA_CLIENT"), token or os.environ.get("HABLA_TOKEN"),
                                   timeout)
            elif announce:
                self.ping()
            self.stale = self.hello.stale
        except BaseException:
            self.close()
            raise

    def _authenticate(self, client, token, timeout):
        if not client or not token:
            raise AuthError({"code": "auth_required", "message": "socket %r requires authentication: give client= "
                             "and token= (or HABLA_CLIENT and HABLA_TOKEN)" % self.hello.socket})
        self.send({"op": "auth", "client": client, "token": token})
        deadline = time.monotonic() + timeout
        while True:
            answer = self.read_frame(max(0.0, deadline - time.monotonic()))
            if answer.get("type") in ("hello", "error"):
                break
            # A daemon may let a sample or a notice (a control line) overtake the hello: keep it for later.
            if answer.get("type") == "sample":
                self._held.append(Sample(answer))
            else:
                self.events.append(answer)
        if answer.get("type") == "error":
            raise AuthError(answer)
        self.hello = Hello(answer)

    # -- reading --------------------------------------------------------------------------------------------
    def read_frame(self, timeout=None):
        """The next line as a dict (a binary block under "_bytes"). Raises TimeoutError when none comes within
        timeout seconds (None: wait as long as it takes) and LinkLostError when the connection ends."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while not self._frames:
            self._fill(deadline)
        frame = self._frames.popleft()
        self._note(frame)
        return frame

    def next_sample(self, timeout=None):
        """The next sample; other lines go to .events (and update .stale, .dropped, .commander)."""
        if self._held:
            return self._held.popleft()
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            frame = self.read_frame(None if deadline is None else max(0.0, deadline - time.monotonic()))
            if frame.get("type") == "sample":
                return Sample(frame)
            self.events.append(frame)

    def samples(self, timeout=None):
        """Every sample as it comes, until the connection ends (LinkLostError) or none comes within timeout."""
        while True:
            yield self.next_sample(timeout)

    __iter__ = samples

    def _fill(self, deadline):
        if deadline is not None:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise TimeoutError("nothing from %s:%s in time" % self.address)
            self._sock.settimeout(remaining)
        else:
            self._sock.settimeout(None)
        try:
            chunk = self._sock.recv(RECV_BYTES)
        except socket.timeout as e:
            raise TimeoutError("nothing from %s:%s in time" % self.address) from e
        except OSError as e:
            raise LinkLostError("the connection to %s:%s broke: %s" % (self.address + (e,))) from e
        if not chunk:
            cut = " inside a frame" if self._reader.mid_frame() else ""
            raise LinkLostError("the daemon closed the connection to %s:%s%s" % (self.address + (cut,)))
        self._frames.extend(self._reader.feed(chunk))

    def _note(self, frame):
        kind = frame.get("type")
        if kind == "stale":
            self.stale = bool(frame.get("stale"))
        elif kind == "dropped" and isinstance(frame.get("count"), int):
            self.dropped += frame["count"]
        elif kind == "control":
            self.commander = frame.get("holder")

    # -- writing --------------------------------------------------------------------------------------------
    def send(self, obj):
        """Sends one request line."""
        data = encode(obj)
        with self._send_lock:
            try:
                self._sock.sendall(data)
            except OSError as e:
                raise LinkLostError("the connection to %s:%s broke: %s" % (self.address + (e,))) from e
            self._last_sent = time.monotonic()

    def write(self, value, input=None, id=None):
        """Writes a value to the socket's control input (the only one, unless input names it); no answer is
        awaited (an error line, if any, comes later among .events)."""
        req = {"op": "write", "value": value}
        if input is not None:
            req["input"] = input
        if id is not None:
            req["id"] = id
        self.send(req)

    def request(self, obj, timeout=5.0):
        """Sends a request with an id and returns the daemon's answer (ok, pong); an error answer raises
        RefusedError. Samples that arrive meanwhile are kept for next_sample()."""
        req = dict(obj)
        req.setdefault("id", self.new_id())
        self.send(req)
        deadline = time.monotonic() + timeout
        while True:
            frame = self.read_frame(max(0.0, deadline - time.monotonic()))
            if frame.get("type") == "sample":
                self._held.append(Sample(frame))
            elif frame.get("id") == req["id"] and frame.get("type") in ("ok", "error", "pong"):
                if frame["type"] == "error":
                    raise RefusedError(frame)
                return frame
            else:
                self.events.append(frame)

    def write_and_wait(self, value, input=None, timeout=5.0):
        """Writes a value and waits for the daemon's answer: its ok line, or RefusedError with the code."""
        req = {"op": "write", "value": value}
        if input is not None:
            req["input"] = input
        return self.request(req, timeout)

    def new_id(self):
        """A request id unique on this connection."""
        with self._send_lock:
            self._next_id += 1
            return self._next_id

    def ping(self):
        self.send({"op": "ping"})

    def take(self, timeout=5.0):
        """Makes this client the commander of an actuating socket."""
        return self.request({"op": "take"}, timeout)

    def release(self, timeout=5.0):
        """Gives control back (the robot is stopped)."""
        return self.request({"op": "release"}, timeout)

    def rate(self, max_hz, timeout=5.0):
        """At most max_hz samples a second per output on this connection (0 lifts the limit)."""
        return self.request({"op": "rate", "maxHz": max_hz}, timeout)

    def keep_alive(self):
        """Pings if nothing was sent for a while, so that a client of a quiet socket is not the idle one that gives
        way to a newcomer on a full socket (limits.evictableIdleMs) nor closed as idle (limits.idleTimeoutMs);
        sends at most one line per KEEP_ALIVE_S, or per a third of the hello's idle deadline."""
        idle = self.hello.idle_timeout_s
        every = KEEP_ALIVE_S if not idle else min(KEEP_ALIVE_S, idle / 3.0)
        if time.monotonic() - self._last_sent >= every:
            self.ping()

    # -- life cycle -----------------------------------------------------------------------------------------
    def shutdown(self):
        """Ends the connection from any thread: a read blocked on it raises LinkLostError at once."""
        try:
            self._sock.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass

    def close(self):
        try:
            self._sock.close()
        except (OSError, AttributeError):
            pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
