"""The bench's robot: an interface program (habla-interface/1) that streams a record reading on each of N
channels at a fixed rate, each stamped with the time it was made, and counts what it sent.
    python3 robot.py PORT CHANNELS HZ SECONDS       (prints {"sent": [...]} when done)
It says "connected" once HABLA has taken its hello, and starts streaming when a line comes on its stdin."""

import json
import select
import socket
import sys
import time


def main(port, channels, hz, seconds):
    server = socket.create_server(("127.0.0.1", port))
    print("listening", flush=True)
    conn, _ = server.accept()
    conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    hello = {"type": "hello", "protocol": "habla-interface/1", "robot": "bench",
             "channels": [{"name": "c%d" % i, "direction": "reading", "kind": "record"} for i in range(channels)]}
    conn.sendall((json.dumps(hello) + "\n").encode())
    print("connected", flush=True)
    # Until told to go, answer HABLA's pings: a program silent for three of them is taken as lost.
    while True:
        ready, _, _ = select.select([sys.stdin, conn], [], [])
        if sys.stdin in ready:
            sys.stdin.readline()
            break
        if b"ping" in conn.recv(65536):
            conn.sendall(b'{"type":"pong"}\n')
    sent = [0] * channels
    period = 1.0 / hz
    start = time.monotonic()
    n = 0
    while time.monotonic() - start < seconds:
        due = start + n * period
        delay = due - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        lines = []
        for i in range(channels):
            sent[i] += 1
            lines.append(json.dumps({"type": "reading", "channel": "c%d" % i, "t": time.time_ns() // 1000,
                                     "value": {"n": sent[i]}}, separators=(",", ":")))
        conn.sendall(("\n".join(lines) + "\n").encode())
        n += 1
    time.sleep(2.0)   # the tail reaches the subscriber before the connection ends
    print(json.dumps({"sent": sent}), flush=True)
    conn.close()


if __name__ == "__main__":
    main(int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]))
