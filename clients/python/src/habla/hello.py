"""What a socket says about itself (its hello) and what it streams (samples), as typed values."""

import collections

from .errors import BadHelloError

PROTOCOL = "habla-control/1"

Output = collections.namedtuple("Output", "name kind unit fields doc")
Output.__doc__ = "One output a socket streams: its name, payload kind, unit, record fields and a sentence."

Input = collections.namedtuple("Input", "name kind")
Input.__doc__ = "One control input a client may write: its name and payload kind."


class Hello:
    """A socket's hello line: its name, the method behind it, what it streams and what it takes.

    `auth_required` is true for the short hello of a socket that wants authentication first; the full hello
    that answers the auth line has everything else and says which `client` and `role` the daemon granted."""

    def __init__(self, line):
        if line.get("type") != "hello":
            raise BadHelloError("expected a hello line, got %s" % _short(line))
        if line.get("protocol") != PROTOCOL:
            raise BadHelloError("the peer speaks %r, not %r" % (line.get("protocol"), PROTOCOL))
        self.line = line
        self.socket = _text(line, "socket")
        self.auth_required = line.get("auth") == "required"
        self.limits = line.get("limits") if isinstance(line.get("limits"), dict) else {}
        if self.auth_required:
            self.method = self.layer = self.direction = None
            self.outputs, self.inputs = [], []
            self.stale = False
            self.client = self.role = None
            return
        self.method = _text(line, "method")
        self.layer = _text(line, "layer")
        self.direction = _text(line, "direction")
        if self.direction not in ("in", "out", "both"):
            raise BadHelloError("the hello's direction is %r, not in, out or both" % (self.direction,))
        self.outputs = [_output(o) for o in _list(line, "outputs")]
        self.inputs = [Input(_text(i, "name"), _text(i, "kind")) for i in _list(line, "inputs")]
        self.stale = bool(line.get("stale", False))
        self.client = line.get("client")
        self.role = line.get("role")

    def output(self, name):
        """The output of that name, or None."""
        return next((o for o in self.outputs if o.name == name), None)

    @property
    def idle_timeout_s(self):
        """The daemon's idle deadline for this connection in seconds (0: none)."""
        ms = self.limits.get("idleTimeoutMs") or 0
        return ms / 1000.0 if isinstance(ms, (int, float)) else 0.0

    def __repr__(self):
        return "Hello(socket=%r, method=%r, direction=%r, outputs=%r)" % (
            self.socket, self.method, self.direction, [o.name for o in self.outputs])


class Sample:
    """One sample of an output: `value` (or `data`, the bytes of an audio chunk or image), its `seq` number
    on that output, `t_us` the source time of the raw reading it came from (microseconds since the epoch,
    carried through the daemon's layers) and whether it is `stale` (a link it depends on is down)."""

    __slots__ = ("output", "seq", "t_us", "stale", "kind", "value", "data", "line")

    def __init__(self, line):
        self.line = line
        self.output = line.get("output")
        self.seq = line.get("seq")
        self.t_us = line.get("t")
        self.stale = bool(line.get("stale", False))
        self.kind = line.get("kind")
        self.value = line.get("value")
        self.data = line.get("_bytes")

    @property
    def t(self):
        """The source time in seconds since the epoch (as time.time() counts), or None."""
        return self.t_us / 1e6 if isinstance(self.t_us, (int, float)) else None

    def __repr__(self):
        shown = self.value if self.data is None else "<%d bytes>" % len(self.data)
        return "Sample(output=%r, seq=%r, t_us=%r, stale=%r, value=%r)" % (
            self.output, self.seq, self.t_us, self.stale, shown)


def _output(node):
    if not isinstance(node, dict):
        raise BadHelloError("an output of the hello is not an object: %s" % _short(node))
    fields = node.get("fields") if isinstance(node.get("fields"), list) else []
    return Output(_text(node, "name"), _text(node, "kind"), node.get("unit") or "", list(fields), node.get("doc") or "")


def _text(node, key):
    value = node.get(key) if isinstance(node, dict) else None
    if not isinstance(value, str):
        raise BadHelloError("the hello has no text %r: %s" % (key, _short(node)))
    return value


def _list(node, key):
    value = node.get(key, [])
    if not isinstance(value, list):
        raise BadHelloError("the hello's %r is not an array" % key)
    return value


def _short(obj):
    s = repr(obj)
    return s if len(s) <= 120 else s[:117] + "..."
