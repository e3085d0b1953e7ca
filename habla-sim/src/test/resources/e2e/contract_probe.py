"""A control program for the end-to-end tests: talks to the control contract's sockets like any
client would, and prints what it saw as JSON lines on stdout.

    contract_probe.py sample PORT N [TIMEOUT]      the values of the next N samples
    contract_probe.py first PORT TIMEOUT            the first sample, with the wall time it arrived
    contract_probe.py act PORT LABEL HOLD_S          write LABEL, then stay connected and silent HOLD_S seconds
"""

import json
import sys
import time

import habla  # clients/python/src, on PYTHONPATH


def out(obj):
    sys.stdout.write(json.dumps(obj) + "\n")
    sys.stdout.flush()


def main(argv):
    cmd, port = argv[0], int(argv[1])
    if cmd == "sample":
        n = int(argv[2])
        timeout = float(argv[3]) if len(argv) > 3 else 10.0
        with habla.connect("127.0.0.1", port, timeout=timeout) as s:
            for _ in range(n):
                try:
                    sample = s.next_sample(timeout)
                except habla.LinkLostError:
                    break
                out({"value": sample.value, "stale": sample.stale})
    elif cmd == "first":
        timeout = float(argv[2])
        with habla.connect("127.0.0.1", port, timeout=timeout) as s:
            out({"ready": True, "wall": time.time()})
            try:
                value = s.next_sample(timeout).value
            except habla.LinkLostError:
                value = None
            out({"value": value, "wall": time.time()})
    elif cmd == "act":
        label, hold = argv[2], float(argv[3])
        with habla.connect("127.0.0.1", port, timeout=5.0) as s:
            s.write(label)
            out({"wrote": label, "wall": time.time()})
            end = time.monotonic() + hold
            while time.monotonic() < end:
                try:
                    line = s.read_frame(max(0.01, end - time.monotonic()))
                except (TimeoutError, habla.LinkLostError):
                    break
                out({"line": line})
    else:
        raise SystemExit("unknown command " + cmd)


if __name__ == "__main__":
    main(sys.argv[1:])
