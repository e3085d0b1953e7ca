"""End-to-end test client: reads a virtual method's socket, then drives the wheels and goes silent.

Prints one JSON object per line on stdout for the Java test to check:
  {"event": "hello", ...}, {"event": "sample", ...} x3, {"event": "wrote", "t": ...}, {"event": "done"}
"""
import argparse
import json
import time

import habla  # clients/python/src, on PYTHONPATH


def say(**kv):
    print(json.dumps(kv), flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ranges", type=int, required=True)
    ap.add_argument("--wheels", type=int, required=True)
    ap.add_argument("--silence", type=float, default=1.5)
    a = ap.parse_args()

    with habla.connect("127.0.0.1", a.ranges) as ranges:
        say(event="hello", **ranges.hello.line)
        for _ in range(3):
            s = ranges.next_sample(timeout=5.0)
            say(event="sample", **{k: v for k, v in s.line.items() if not k.startswith("_")})

    with habla.connect("127.0.0.1", a.wheels) as wheels:
        say(event="wheels-hello", **wheels.hello.line)
        wheels.request({"op": "write", "value": [0.3, 0.3]})
        say(event="wrote", t=time.time())
        time.sleep(a.silence)  # silent, connection open: the watchdog must stop the robot
    say(event="done")


if __name__ == "__main__":
    main()
