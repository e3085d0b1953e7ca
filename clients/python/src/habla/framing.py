"""HABLA's framing, incrementally: bytes in, frames out, for blocking and asyncio clients alike.

    +--------------------------------------------------+----+  +-------------------------------------+
    | {"type":"sample", ... ,"bytes":N}   (UTF-8 JSON) | \\n |  | N raw bytes (only if "bytes" given) |
    +--------------------------------------------------+----+  +-------------------------------------+

A frame is one JSON object per line; a line that declares "bytes": N is followed by exactly N raw bytes,
which the frame carries under "_bytes". A line that is not a JSON object (not UTF-8, not JSON, or JSON such
as [1, 2]) does not stop the reader: it becomes {"type": "invalid", "code": ..., "message": ..., "raw": ...}
with the codes the daemon itself uses (bad_utf8, bad_json, not_object). Blank lines are skipped. A line
longer than max_line_bytes, or a block over max_binary_bytes, raises FrameError: the stream cannot go on.
"""

import json
import math

from .errors import FrameError

MAX_LINE_BYTES = 1 << 20      # the daemon's own default limit is 64 KiB; a client is more lenient
MAX_BINARY_BYTES = 64 << 20   # the daemon sends at most limits.maxBinaryBytes (8 MiB by default)
RAW_KEPT = 200                # characters of a bad line kept in its "invalid" frame


class FrameReader:
    """Turns the bytes of one connection into frames; feed() what arrives, take the frames it returns."""

    def __init__(self, max_line_bytes=MAX_LINE_BYTES, max_binary_bytes=MAX_BINARY_BYTES):
        self._buf = bytearray()
        self._pending = None  # a frame waiting for its binary block
        self._max_line = max_line_bytes
        self._max_binary = max_binary_bytes

    def feed(self, data):
        """Adds bytes and returns every frame they complete, in order."""
        self._buf += data
        frames = []
        while True:
            if self._pending is not None:
                need = self._pending["bytes"]
                if len(self._buf) < need:
                    break
                self._pending["_bytes"] = bytes(self._buf[:need])
                del self._buf[:need]
                frames.append(self._pending)
                self._pending = None
                continue
            end = self._buf.find(b"\n")
            if end < 0:
                if len(self._buf) > self._max_line:
                    raise FrameError("a line longer than %d bytes" % self._max_line)
                break
            line = bytes(self._buf[:end])
            del self._buf[:end + 1]
            if line.endswith(b"\r"):
                line = line[:-1]
            if not line.strip():
                continue
            frame = parse_line(line)
            n = frame.get("bytes")
            if type(n) is int and n > 0:  # not bool: True is an int in Python
                if n > self._max_binary:
                    raise FrameError("a binary block of %d bytes, over the limit of %d" % (n, self._max_binary))
                self._pending = frame
                continue
            frames.append(frame)
        return frames

    def mid_frame(self):
        """Whether bytes of an unfinished frame are buffered (an end of stream now would cut it)."""
        return bool(self._buf) or self._pending is not None


def parse_line(line):
    """One line (without its newline) as a dict; a line that is not a JSON object becomes an "invalid" frame."""
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


def encode(obj):
    """One request as the bytes of its line; a non-finite number travels as null, as JSON has no NaN."""
    return (json.dumps(_finite(obj), separators=(",", ":"), allow_nan=False) + "\n").encode("utf-8")


def _finite(value):
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value


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
    return {"type": "invalid", "code": code, "message": message, "raw": raw[:RAW_KEPT]}
