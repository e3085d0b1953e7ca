"""Staying connected: back-off between tries, and a socket that connects again when its link is lost."""

import random
import threading

from .control import ControlSocket
from .errors import AuthError, BadHelloError, LinkLostError, RefusedError, TlsError

RETRIED_CODES = ("too_many_clients", "evicted", "idle_timeout")


class Backoff:
    """Waits between connection tries: initial_s, then `factor` times longer each try up to max_s, each
    spread by up to `jitter` of itself so that many clients do not return in step. reset() after a session
    was up, so that the next loss is retried at once."""

    def __init__(self, initial_s=0.2, max_s=5.0, factor=2.0, jitter=0.1, rng=None):
        if not (0 < initial_s <= max_s) or factor < 1 or not (0 <= jitter < 1):
            raise ValueError("back-off needs 0 < initial_s <= max_s, factor >= 1 and 0 <= jitter < 1")
        self.initial_s, self.max_s, self.factor, self.jitter = initial_s, max_s, factor, jitter
        self._rng = rng or random.Random()
        self._next = initial_s

    def next(self):
        """The wait before the next try, in seconds; the one after it is longer."""
        wait = self._next
        self._next = min(self.max_s, self._next * self.factor)
        return wait * (1 + self.jitter * (2 * self._rng.random() - 1))

    def reset(self):
        self._next = self.initial_s


class Reconnecting:
    """One socket kept connected. samples() yields samples across losses of the link: when the daemon goes
    away it waits (with back-off) and connects again; on_link(up, why) is told each time the link comes up
    or goes down. Refusals that will not change by trying again (a bad hello, failed authentication or TLS) are
    raised, not retried. close() from any thread ends it."""

    def __init__(self, host, port, backoff=None, on_link=None, **connect_args):
        self.host, self.port = host, port
        self.backoff = backoff or Backoff()
        self.connect_args = connect_args
        self.sessions = 0
        self.socket = None
        self._on_link = on_link or (lambda up, why: None)
        self._closed = threading.Event()
        self._lock = threading.Lock()

    def connect(self):
        """The connected socket, connecting (and waiting between tries) until it is up; None once closed."""
        with self._lock:
            if self.socket is not None:
                return self.socket
        while not self._closed.is_set():
            try:
                s = ControlSocket(self.host, self.port, **self.connect_args)
            except (AuthError, BadHelloError, TlsError):
                raise
            except RefusedError as e:
                if e.code not in RETRIED_CODES:
                    raise
                why = str(e)
            except (LinkLostError, TimeoutError) as e:
                why = str(e)
            else:
                with self._lock:
                    if self._closed.is_set():
                        s.close()
                        return None
                    self.socket = s
                    self.sessions += 1
                self.backoff.reset()
                self._on_link(True, "connected to %s:%s" % (self.host, self.port))
                return s
            self._closed.wait(self.backoff.next())
        return None

    def lost(self, why):
        """Drops the current socket (after a read or write failed); the next connect() makes a new one."""
        with self._lock:
            s, self.socket = self.socket, None
        if s is not None:
            s.close()
            self._on_link(False, why)

    def samples(self, timeout=None):
        """Samples from whichever connection is up, until close(). A timeout (no sample within timeout
        seconds) raises TimeoutError and keeps the connection."""
        while True:
            s = self.connect()
            if s is None:
                return
            try:
                while True:
                    yield s.next_sample(timeout)
            except LinkLostError as e:
                self.lost(str(e))

    def close(self):
        self._closed.set()
        with self._lock:
            s, self.socket = self.socket, None
        if s is not None:
            s.shutdown()
            s.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
