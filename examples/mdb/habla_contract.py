"""The control contract of a HABLA daemon, as a control architecture sees it: four sockets.

    command         out  text, one of forward/left/right/back, once per teacher command
    distance_angle  out  record {"distanceM", "angleRad", "seen"} to the target, robot frame, ~10 Hz
    reward          out  number in [-1, 1], once per teacher reward
    action          in   text, one of forward/left/right/back/stop (the daemon echoes it out)

`ContractLink` connects to all four with the packaged client `habla` (clients/python: one JSON object per
line, a hello line first), reads each in a background thread, keeps the latest distance/angle and numbered
lists of the commands and rewards heard, and writes actions. When any socket drops (the daemon stops
or restarts) it closes the rest and connects again every `retry_s` until the daemon is back; the
caller sees `connected` turn False and back True, and never an exception from a reader.
"""

import collections
import os
import sys
import threading
import time

try:
    import habla
except ImportError:  # not installed: the client of this checkout
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "clients", "python", "src"))
    import habla

DEFAULT_PORTS = {"command": 7001, "distance_angle": 7002, "reward": 7003, "action": 7004}
SAMPLES_KEPT = 32  # distance_angle samples remembered, for a caller that smooths over a few
EVENTS_KEPT = 256  # commands and rewards remembered; older ones are dropped (numbering goes on)


class Event(collections.namedtuple("Event", "number arrived value")):
    """One command or reward: its running number, its arrival (time.monotonic()) and its value."""


class DistanceAngle(collections.namedtuple("DistanceAngle", "distance_m angle_rad seen number arrived stale")):
    """The latest distance_angle sample, numbered in arrival order."""


class ContractLink:
    """The four contract sockets of one daemon, read in the background and reconnected on loss."""

    def __init__(self, host="127.0.0.1", ports=None, connect_timeout_s=2.0, retry_s=0.5, on_event=None):
        self.host = host
        self.ports = dict(DEFAULT_PORTS)
        self.ports.update(ports or {})
        self.connect_timeout_s = connect_timeout_s
        self.retry_s = retry_s
        self._on_event = on_event or (lambda kind, detail: None)
        self._cv = threading.Condition()
        self._closed = False
        self._sockets = {}
        self._connected = False
        self.connections = 0  # how many times all four sockets came up
        self.distance_angle = None
        self._recent = collections.deque(maxlen=SAMPLES_KEPT)
        self._commands = collections.deque(maxlen=EVENTS_KEPT)
        self._rewards = collections.deque(maxlen=EVENTS_KEPT)
        self.commands_heard = 0
        self.rewards_heard = 0
        self.samples_seen = 0
        self.errors = []  # error lines the daemon sent (e.g. a rejected action)
        self._supervisor = threading.Thread(target=self._supervise, name="contract-link", daemon=True)

    # -- life cycle ---------------------------------------------------------------------------------
    def start(self):
        self._supervisor.start()
        return self

    def close(self):
        with self._cv:
            self._closed = True
            self._cv.notify_all()
        self._drop_sockets()
        self._supervisor.join(timeout=5.0)

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.close()

    @property
    def connected(self):
        with self._cv:
            return self._connected

    def wait_connected(self, timeout_s):
        return self.wait_until(lambda: self._connected, timeout_s)

    # -- reading --------------------------------------------------------------------------------------
    def wait_until(self, predicate, timeout_s):
        """Waits (bounded) until predicate() holds, re-checking on every sample; returns its last value.

        The predicate runs with the link's lock held and may read its fields."""
        deadline = time.monotonic() + timeout_s
        with self._cv:
            while True:
                value = predicate()
                remaining = deadline - time.monotonic()
                if value or remaining <= 0 or self._closed:
                    return value
                self._cv.wait(min(remaining, 0.25))

    def samples_after(self, number):
        """The distance_angle samples numbered above `number` still remembered, oldest first."""
        with self._cv:
            return [e for e in self._recent if e.number > number]

    def commands_after(self, number):
        """The commands numbered above `number`, oldest first."""
        with self._cv:
            return [e for e in self._commands if e.number > number]

    def rewards_after(self, number):
        """The rewards numbered above `number`, oldest first."""
        with self._cv:
            return [e for e in self._rewards if e.number > number]

    def last_command(self):
        with self._cv:
            return self._commands[-1] if self._commands else None

    # -- writing --------------------------------------------------------------------------------------
    def act(self, label):
        """Writes an action label; False (and a reconnect) if the action socket is not up."""
        with self._cv:
            s = self._sockets.get("action") if self._connected else None
        if s is None:
            return False
        try:
            s.write(label)
            return True
        except OSError as e:
            self._on_event("write_failed", str(e))
            self._drop_sockets()
            return False

    # -- background -----------------------------------------------------------------------------------
    def _supervise(self):
        while not self._closed:
            try:
                opened = {}
                try:
                    for name, port in self.ports.items():
                        opened[name] = habla.connect(self.host, port, timeout=self.connect_timeout_s)
                except (OSError, habla.HablaError) as e:
                    for s in opened.values():
                        s.close()
                    raise ConnectionError("%s:%s %s" % (self.host, self.ports.get(name), e)) from e
                readers = [threading.Thread(target=self._read, args=(name, s), daemon=True,
                                            name="contract-" + name) for name, s in opened.items()]
                with self._cv:
                    if self._closed:
                        for s in opened.values():
                            s.close()
                        return
                    self._sockets = opened
                    self._connected = True
                    self.connections += 1
                    self._cv.notify_all()
                self._on_event("connected", {n: s.hello.method for n, s in opened.items()})
                for r in readers:
                    r.start()
                for r in readers:
                    r.join()
                self._on_event("disconnected", "a contract socket closed")
                with self._cv:
                    if not self._closed:
                        self._cv.wait(self.retry_s)
            except ConnectionError as e:
                with self._cv:
                    if not self._closed:
                        self._cv.wait(self.retry_s)
                if self.connections == 0 and not self._closed:
                    self._on_event("connect_failed", str(e))

    def _drop_sockets(self):
        with self._cv:
            sockets, self._sockets = self._sockets, {}
            self._connected = False
            self._cv.notify_all()
        for s in sockets.values():
            s.shutdown()
            s.close()

    def _read(self, name, sock):
        """Reads one socket until it closes or fails; then drops all four, so they reconnect together."""
        try:
            while not self._closed:
                try:
                    line = sock.read_frame(timeout=1.0)
                except TimeoutError:
                    sock.keep_alive()  # a client of a quiet socket (command, reward) must not be the idle one a full socket evicts
                    continue
                self._take(name, line)
        except (OSError, habla.HablaError) as e:  # the daemon went away, a reset, a frame over the limits: afresh
            self._on_event("read_failed", "%s: %s" % (name, e))
        finally:
            self._drop_sockets()

    def _take(self, name, line):
        kind = line.get("type")
        now = time.monotonic()
        with self._cv:
            if kind == "error":
                self.errors.append(line)
                del self.errors[:-EVENTS_KEPT]
            elif kind != "sample":
                return
            elif name == "distance_angle":
                value = line.get("value") or {}
                d, a = value.get("distanceM"), value.get("angleRad")
                if not isinstance(d, (int, float)) or not isinstance(a, (int, float)):
                    return  # NaN travels as null: not a usable sighting
                self.samples_seen += 1
                self.distance_angle = DistanceAngle(float(d), float(a), bool(value.get("seen", True)),
                                                    self.samples_seen, now, bool(line.get("stale")))
                self._recent.append(self.distance_angle)
            elif name == "command":
                value = line.get("value")
                if isinstance(value, str) and not line.get("stale"):
                    self.commands_heard += 1
                    self._commands.append(Event(self.commands_heard, now, value.strip()))
            elif name == "reward":
                value = line.get("value")
                if isinstance(value, (int, float)) and not line.get("stale"):
                    self.rewards_heard += 1
                    self._rewards.append(Event(self.rewards_heard, now, max(-1.0, min(1.0, float(value)))))
            self._cv.notify_all()
