"""A scripted stand-in for a daemon, for the tests of framing and error handling that a real daemon does
not produce on demand (garbage lines, a bad hello, a refusal): a loopback server that sends given bytes to
each connection and answers the requests it reads."""

import json
import socket
import threading


def line(obj):
    return (json.dumps(obj) + "\n").encode("utf-8")


HELLO = {"type": "hello", "protocol": "habla-control/1", "socket": "ranges", "method": "ranges",
         "layer": "virtual", "direction": "both", "outputs": [{"name": "out", "kind": "vector"}],
         "inputs": [{"name": "in", "kind": "vector"}], "stale": False}


def sample(seq, value):
    return line({"type": "sample", "output": "out", "seq": seq, "t": 1, "stale": False, "kind": "vector",
                 "value": value})


class ScriptedDaemon:
    """Serves connections one after the other: sends `chunks`, then answers each request line with
    answer(request) (bytes, or None for nothing); pings are counted, not answered. close_after closes each
    connection after that many requests."""

    def __init__(self, *chunks, answer=None):
        self.chunks = chunks
        self.answer = answer
        self.received = []
        self.pings = 0
        self.connections = 0
        self._cv = threading.Condition()
        self._conns = []
        self.server = socket.socket()
        self.server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(4)
        self.port = self.server.getsockname()[1]
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        while True:
            try:
                conn, _ = self.server.accept()
            except OSError:
                return
            with self._cv:
                self.connections += 1
                self._conns.append(conn)
                self._cv.notify_all()
            threading.Thread(target=self._talk, args=(conn,), daemon=True).start()

    def _talk(self, conn):
        try:
            for c in self.chunks:
                conn.sendall(c)
            buf = b""
            while True:
                data = conn.recv(65536)
                if not data:
                    return
                buf += data
                while b"\n" in buf:
                    raw, buf = buf.split(b"\n", 1)
                    request = json.loads(raw)
                    with self._cv:
                        if request == {"op": "ping"}:
                            self.pings += 1
                        else:
                            self.received.append(request)
                        self._cv.notify_all()
                    if request != {"op": "ping"} and self.answer:
                        reply = self.answer(request)
                        if reply:
                            conn.sendall(reply)
        except OSError:
            pass

    def wait_for(self, predicate, timeout_s=5.0):
        with self._cv:
            return self._cv.wait_for(predicate, timeout_s)

    def drop_connections(self):
        """Closes every open connection (the daemon went away), keeping the port listening."""
        with self._cv:
            conns, self._conns = self._conns, []
        for c in conns:
            try:
                c.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            c.close()

    def close(self):
        self.server.close()
        self.drop_connections()
