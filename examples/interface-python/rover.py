#!/usr/bin/env python3
"""An imaginary robot that speaks HABLA's interface protocol (habla-interface/1).

The rover is a differential-drive robot, 0.2 m in radius, in a square room with four range sensors
(front, left, back, right). This program plays both the robot and its interface program: it listens on a
TCP port, HABLA's `habla` driver connects to it, and then

  - it announces its channels in a hello line,
  - it sends the four ranges ten times a second as a reading on channel "ranges",
  - it takes motion commands [vMps, wRadps] on channel "motion", and stops on "stop".

Standard library only:  python3 rover.py --port 7600
Then, beside it:        ./habla run examples/interface-python/habla.json
"""

import argparse
import json
import math
import random
import select
import socket
import sys
import time

PROTOCOL = "habla-interface/1"
RADIUS_M = 0.2
MAX_RANGE_M = 4.0
MAX_SPEED_MPS = 0.5
MAX_TURN_RADPS = 1.5
MAX_LINE_BYTES = 65536

# Sensor poses in the robot frame: x forward, y left, angle counter-clockwise from forward.
SENSORS = [("front", RADIUS_M, 0.0, 0.0),
           ("left", 0.0, RADIUS_M, math.pi / 2),
           ("back", -RADIUS_M, 0.0, math.pi),
           ("right", 0.0, -RADIUS_M, -math.pi / 2)]

CHANNELS = [
    {"name": "ranges", "direction": "reading", "kind": "vector", "unit": "m",
     "meta": {"order": [s[0] for s in SENSORS], "maxRangeM": MAX_RANGE_M,
              "poses": [{"xM": s[1], "yM": s[2], "thetaRad": round(s[3], 4)} for s in SENSORS]}},
    {"name": "motion", "direction": "command", "kind": "vector", "unit": "m/s, rad/s", "motion": True},
]


def log(message):
    print("rover: " + message, file=sys.stderr, flush=True)


class Rover:
    """The robot's body and its room: a pose, a commanded motion, walls at 0 and sizeM on both axes."""

    def __init__(self, size_m, x_m, y_m, theta_rad, noise_m=0.0, rng=None):
        self.size_m = size_m
        self.x_m, self.y_m, self.theta_rad = x_m, y_m, theta_rad
        self.v_mps, self.w_radps = 0.0, 0.0
        self.noise_m = noise_m
        self.rng = rng or random.Random(1)

    def command(self, value):
        """Takes [vMps, wRadps]; anything else is refused with a reason."""
        if (not isinstance(value, list) or len(value) != 2
                or not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in value)
                or not all(math.isfinite(x) for x in value)):
            raise ValueError("motion must be [vMps, wRadps], was %r" % (value,))
        self.v_mps = max(-MAX_SPEED_MPS, min(MAX_SPEED_MPS, float(value[0])))
        self.w_radps = max(-MAX_TURN_RADPS, min(MAX_TURN_RADPS, float(value[1])))

    def stop(self):
        self.v_mps, self.w_radps = 0.0, 0.0

    def step(self, dt_s):
        """Moves for dt_s seconds; the body stops at a wall instead of passing through it."""
        self.theta_rad = math.atan2(math.sin(self.theta_rad + self.w_radps * dt_s),
                                    math.cos(self.theta_rad + self.w_radps * dt_s))
        lo, hi = RADIUS_M, self.size_m - RADIUS_M
        self.x_m = max(lo, min(hi, self.x_m + self.v_mps * math.cos(self.theta_rad) * dt_s))
        self.y_m = max(lo, min(hi, self.y_m + self.v_mps * math.sin(self.theta_rad) * dt_s))

    def ranges(self):
        """The distance from each sensor to the wall it faces, capped at MAX_RANGE_M."""
        out = []
        c, s = math.cos(self.theta_rad), math.sin(self.theta_rad)
        for _, sx, sy, sa in SENSORS:
            px = self.x_m + sx * c - sy * s
            py = self.y_m + sx * s + sy * c
            a = self.theta_rad + sa
            d = min(self._to_wall(px, math.cos(a), self.size_m), self._to_wall(py, math.sin(a), self.size_m))
            if self.noise_m > 0:
                d += self.rng.gauss(0.0, self.noise_m)
            out.append(round(max(0.0, min(MAX_RANGE_M, d)), 4))
        return out

    @staticmethod
    def _to_wall(p, direction, size):
        if direction > 1e-9:
            return (size - p) / direction
        if direction < -1e-9:
            return -p / direction
        return math.inf


class Link:
    """One connection from HABLA: JSON lines in both directions."""

    def __init__(self, conn):
        self.conn = conn
        self.buf = b""

    def send(self, obj):
        self.conn.sendall((json.dumps(obj, separators=(",", ":")) + "\n").encode("utf-8"))

    def frames(self):
        """Reads what has arrived (call when the socket is readable) and returns every complete line,
        parsed; bad lines are logged and skipped. None once HABLA has closed the connection."""
        chunk = self.conn.recv(65536)
        if not chunk:
            return None
        self.buf += chunk
        out = []
        while b"\n" in self.buf:
            line, self.buf = self.buf.split(b"\n", 1)
            if not line.strip():
                continue
            try:
                obj = json.loads(line.decode("utf-8"))
            except (UnicodeDecodeError, ValueError) as e:
                log("skipping a line that is not JSON: %s" % e)
                continue
            if not isinstance(obj, dict):
                log("skipping a line that is not a JSON object: %r" % (obj,))
                continue
            out.append(obj)
        if len(self.buf) > MAX_LINE_BYTES:
            log("dropping %d bytes without a newline" % len(self.buf))
            self.buf = b""
        return out


def serve(rover, conn, period_s, robot_name):
    """Talks to one HABLA connection until it closes or says bye."""
    link = Link(conn)
    link.send({"type": "hello", "protocol": PROTOCOL, "robot": robot_name, "channels": CHANNELS})
    last = time.monotonic()
    next_reading = last
    while True:
        timeout = max(0.0, next_reading - time.monotonic())
        readable, _, _ = select.select([conn], [], [], timeout)
        if readable:
            frames = link.frames()
            if frames is None:
                log("HABLA closed the connection")
                return
            for f in frames:
                if handle(rover, f) == "bye":
                    log("HABLA said bye")
                    return
        now = time.monotonic()
        rover.step(now - last)
        last = now
        if now >= next_reading:
            next_reading += period_s
            if next_reading < now:
                next_reading = now + period_s
            link.send({"type": "reading", "channel": "ranges", "t": time.time_ns() // 1000,
                       "value": rover.ranges()})


def handle(rover, frame):
    kind = frame.get("type")
    if kind == "command":
        if frame.get("channel") != "motion":
            log("ignoring a command on unknown channel %r" % (frame.get("channel"),))
            return kind
        try:
            rover.command(frame.get("value"))
        except ValueError as e:
            log(str(e))
    elif kind == "stop":
        rover.stop()
    elif kind in ("ping", "bye"):
        pass
    else:
        log("ignoring a line of type %r" % (kind,))
    return kind


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--host", default="127.0.0.1", help="address to listen on (default 127.0.0.1)")
    ap.add_argument("--port", type=int, default=7600, help="port to listen on (default 7600; 0 picks one)")
    ap.add_argument("--room", type=float, default=4.0, help="side of the square room [m] (default 4)")
    ap.add_argument("--start", type=float, nargs=3, default=[1.0, 2.0, 0.0], metavar=("X", "Y", "THETA"),
                    help="start pose [m, m, rad] (default 1 2 0: facing the far wall)")
    ap.add_argument("--rate", type=float, default=10.0, help="readings per second (default 10)")
    ap.add_argument("--noise", type=float, default=0.0, help="range noise, standard deviation [m] (default 0)")
    a = ap.parse_args(argv)
    if a.rate <= 0 or a.room <= 2 * RADIUS_M:
        ap.error("--rate must be positive and --room larger than the robot")

    rover = Rover(a.room, *a.start, noise_m=a.noise)
    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    server.bind((a.host, a.port))
    server.listen(1)
    # The first line on stdout says where it listens, for whoever started it.
    print("rover listening on %s:%d" % server.getsockname()[:2], flush=True)
    try:
        while True:
            conn, peer = server.accept()
            log("HABLA connected from %s:%d" % peer[:2])
            try:
                serve(rover, conn, 1.0 / a.rate, "rover")
            except OSError as e:
                log("connection lost: %s" % e)
            finally:
                rover.stop()  # no HABLA, no motion
                conn.close()
    except KeyboardInterrupt:
        pass
    finally:
        server.close()


if __name__ == "__main__":
    main()
