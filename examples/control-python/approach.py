#!/usr/bin/env python3
"""A control architecture in a few lines, with the packaged client (clients/python, `import habla`): it reads
distance_angle and drives the robot towards what it perceives, turning first when that is off to a side,
until it is near. The robot is whichever the daemon drives: it knows only the control contract's sockets.

    python3 examples/control-python/approach.py --seconds 30
    (the client is found in clients/python of this checkout, or installed with pip install clients/python;
    a daemon that wants tokens takes them from HABLA_CLIENT and HABLA_TOKEN)
"""

import argparse
import os
import sys
import time

try:
    import habla
except ImportError:  # run from the checkout without installing the package
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "clients", "python", "src"))
    import habla

TURN_ABOVE_RAD = 0.3   # turn towards what is perceived when its bearing is beyond this
NEAR_M = 0.4           # stop when it is this near


def decide(value):
    """One action label for a distance_angle value."""
    if not value.get("seen") or value.get("distanceM") is None:
        return "left"                  # nothing perceived: look round
    if value["distanceM"] <= NEAR_M:
        return "stop"
    if abs(value["angleRad"]) > TURN_ABOVE_RAD:
        return "left" if value["angleRad"] > 0 else "right"
    return "forward"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--host", default="127.0.0.1")
    ap.add_argument("--distance-angle-port", type=int, default=7002)
    ap.add_argument("--action-port", type=int, default=7004)
    ap.add_argument("--seconds", type=float, default=60.0, help="stop after this long")
    ap.add_argument("--every", type=float, default=0.5, help="seconds between two decisions")
    a = ap.parse_args(argv)
    end = time.monotonic() + a.seconds
    with habla.connect(a.host, a.distance_angle_port) as seen, habla.connect(a.host, a.action_port) as action:
        last = 0.0
        while time.monotonic() < end:
            sample = seen.next_sample(timeout=5.0)
            if sample.stale or time.monotonic() - last < a.every:
                continue
            label = decide(sample.value)
            try:
                action.write_and_wait(label)
            except habla.RefusedError as e:    # busy (another client commands), forbidden (a read-only token), ...
                print("refused %s: %s" % (label, e), file=sys.stderr)
            print("%.2f m %+.2f rad -> %s" % (sample.value["distanceM"], sample.value["angleRad"], label), flush=True)
            last = time.monotonic()
            if label == "stop":
                return 0
        action.write_and_wait("stop")
    return 0


if __name__ == "__main__":
    sys.exit(main())
