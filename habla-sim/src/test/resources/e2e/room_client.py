"""A control program for the room, written from the control contract alone: it reads the occupancy and light
sockets, turns a lamp on and off through the action socket and watches the light it makes, then writes an action
the room does not have. One JSON line per finding on stdout.

    python3 room_client.py --occupancy 7201 --light 7202 --action 7205
"""

import argparse
import json
import sys
import time

import habla  # clients/python/src, on PYTHONPATH


def say(**finding):
    print(json.dumps(finding), flush=True)


def desk_lux(light, deadline):
    """The desk's illuminance from the next light sample."""
    while time.monotonic() < deadline:
        try:
            s = light.next_sample(timeout=max(0.1, deadline - time.monotonic()))
        except TimeoutError:
            continue
        if "desk" in s.value["lux"]:
            return s.value["lux"]["desk"]
    raise SystemExit("no light sample in time")


def occupancy(occ, seconds):
    """The first occupancy sample that has someone in a zone, or the last one seen when nobody shows in time: a
    zone the daemon has not heard from yet counts as empty, so the samples before its sensor's first report do."""
    deadline = time.monotonic() + seconds
    last = None
    while time.monotonic() < deadline:
        try:
            s = occ.next_sample(timeout=max(0.1, deadline - time.monotonic()))
        except TimeoutError:
            continue
        last = s
        if s.value["occupied"]:
            return s
    if last is None:
        raise SystemExit("no occupancy sample in time")
    return last


def wait_for(light, test, seconds):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        lux = desk_lux(light, deadline)
        if test(lux):
            return lux
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--occupancy", type=int, required=True)
    ap.add_argument("--light", type=int, required=True)
    ap.add_argument("--action", type=int, required=True)
    a = ap.parse_args()
    with habla.connect("127.0.0.1", a.occupancy) as occ, habla.connect("127.0.0.1", a.light) as light, \
            habla.connect("127.0.0.1", a.action) as action:
        occ.send({"op": "latest"})
        seen = occupancy(occ, 10)
        say(occupied=seen.value["occupied"], zones=seen.value["zones"], stale=seen.stale)
        action.request({"op": "write", "value": "all off"})
        dark = wait_for(light, lambda lux: lux < 100, 10)
        say(off=dark)
        action.request({"op": "write", "value": "desk on"})
        lit = wait_for(light, lambda lux: lux > dark + 300, 10)
        say(lit=lit)
        action.request({"op": "write", "value": "desk off"})
        say(off_again=wait_for(light, lambda lux: lux < dark + 100, 10))
        try:
            action.request({"op": "write", "value": "garage on"})
            say(refused=None)
        except habla.RefusedError as e:
            say(refused=e.code, message=str(e))


if __name__ == "__main__":
    sys.exit(main())
