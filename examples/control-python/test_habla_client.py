"""Unit tests of habla_client against a scripted daemon on loopback: python3 -m unittest test_habla_client"""

import json
import socket
import threading
import time
import unittest

from habla_client import ControlError, ControlSocket

HELLO = {"type": "hello", "protocol": "habla-control/1", "socket": "ranges", "method": "ranges",
         "layer": "virtual", "direction": "both", "outputs": [], "inputs": [], "stale": False}


class ScriptedDaemon:
    """A one-connection server that sends the given bytes on connect and records every line it receives."""

    def __init__(self, *chunks, answer=None):
        self.chunks = chunks
        self.answer = answer  # function(request dict) -> bytes to send back, or None
        self.received = []
        self.pings = 0
        self.conn = None
        self.server = socket.socket()
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(1)
        self.port = self.server.getsockname()[1]
        self.done = threading.Event()
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        self.server.settimeout(5)
        try:
            conn, _ = self.server.accept()
        except OSError:
            return
        self.conn = conn
        with conn:
            conn.settimeout(5)
            for c in self.chunks:
                conn.sendall(c)
            buf = b""
            try:
                while not self.done.is_set():
                    data = conn.recv(65536)
                    if not data:
                        break
                    buf += data
                    while b"\n" in buf:
                        line, buf = buf.split(b"\n", 1)
                        request = json.loads(line)
                        if request == {"op": "ping"}:
                            self.pings += 1  # the client announces itself (and keeps alive) with pings
                            continue
                        self.received.append(request)
                        if self.answer:
                            conn.sendall(self.answer(request))
            except OSError:
                pass

    def await_pings(self, n, timeout=5.0):
        """Waits (bounded) until the client's first n pings have been read, so that none is left unread."""
        deadline = time.monotonic() + timeout
        while self.pings < n and time.monotonic() < deadline:
            time.sleep(0.01)
        return self.pings >= n

    def close(self):
        self.done.set()
        self.server.close()
        if self.conn is not None:
            try:
                self.conn.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
        self.thread.join(5)


def line(obj):
    return (json.dumps(obj) + "\n").encode("utf-8")


def sample(seq, value):
    return line({"type": "sample", "output": "out", "seq": seq, "t": 1, "stale": False, "kind": "vector",
                 "value": value})


class ControlSocketTest(unittest.TestCase):

    def connect(self, daemon):
        self.addCleanup(daemon.close)
        s = ControlSocket("127.0.0.1", daemon.port, timeout=5)
        self.addCleanup(s.close)
        return s

    def test_hello_is_read_on_connect(self):
        s = self.connect(ScriptedDaemon(line(HELLO)))
        self.assertEqual("habla-control/1", s.hello["protocol"])
        self.assertEqual("ranges", s.hello["socket"])

    def test_the_client_announces_itself_with_one_ping_and_keeps_a_quiet_socket_alive(self):
        hello = dict(HELLO, limits={"idleTimeoutMs": 30})  # a third of it: ping after 10 ms of silence
        daemon = ScriptedDaemon(line(hello))
        s = self.connect(daemon)
        s.keep_alive()  # sent a moment ago: nothing to do yet, unless 10 ms have passed
        deadline = time.monotonic() + 5
        while daemon.pings < 2 and time.monotonic() < deadline:
            s.keep_alive()
            daemon.thread.join(0.02)
        self.assertGreaterEqual(daemon.pings, 2)
        self.assertEqual([], daemon.received)

    def test_json_that_is_not_an_object_is_reported_and_reading_goes_on(self):
        s = self.connect(ScriptedDaemon(line(HELLO), b"[1, 2]\n", b'"forward"\n', b"5\n", b"null\n",
                                        sample(1, [0.5, 0.25])))
        got = s.next_sample(timeout=5)
        self.assertEqual([0.5, 0.25], got["value"])
        self.assertEqual(["not_object"] * 4, [e["code"] for e in s.events])
        self.assertEqual(["invalid"] * 4, [e["type"] for e in s.events])
        self.assertIn("an array", s.events[0]["message"])
        self.assertIn("a string", s.events[1]["message"])
        self.assertEqual("[1, 2]", s.events[0]["raw"])

    def test_a_line_that_is_not_json_or_not_utf8_is_reported_and_reading_goes_on(self):
        s = self.connect(ScriptedDaemon(line(HELLO), b"{not json\n", b"\xff\xfe\n", sample(2, [1.0])))
        got = s.next_sample(timeout=5)
        self.assertEqual(2, got["seq"])
        self.assertEqual(["bad_json", "bad_utf8"], [e["code"] for e in s.events])

    def test_a_hello_that_is_not_an_object_is_a_connection_error_not_a_crash(self):
        daemon = ScriptedDaemon(b"[\"hello\"]\n")
        self.addCleanup(daemon.close)
        with self.assertRaises(ConnectionError) as caught:
            ControlSocket("127.0.0.1", daemon.port, timeout=5)
        self.assertIn("not_object", str(caught.exception))

    def test_an_error_instead_of_a_hello_raises_control_error(self):
        daemon = ScriptedDaemon(line({"type": "error", "code": "too_many_clients", "message": "full"}))
        self.addCleanup(daemon.close)
        with self.assertRaises(ControlError) as caught:
            ControlSocket("127.0.0.1", daemon.port, timeout=5)
        self.assertEqual("too_many_clients", caught.exception.code)

    def test_binary_block_is_read_after_its_line(self):
        pcm = bytes(range(10)) + b"\n\n{"
        header = line({"type": "sample", "output": "audio", "seq": 1, "t": 1, "stale": False, "kind": "audio",
                       "rateHz": 16000, "channels": 1, "bits": 16, "bytes": len(pcm)})
        s = self.connect(ScriptedDaemon(line(HELLO), header + pcm, sample(2, [3.0])))
        first = s.next_sample(timeout=5)
        self.assertEqual(pcm, first["_bytes"])
        self.assertEqual([3.0], s.next_sample(timeout=5)["value"])

    def test_bytes_true_is_not_a_binary_block(self):
        s = self.connect(ScriptedDaemon(line(HELLO), line({"type": "sample", "seq": 1, "bytes": True}),
                                        sample(2, [4.0])))
        first = s.next_sample(timeout=5)
        self.assertNotIn("_bytes", first)
        self.assertEqual([4.0], s.next_sample(timeout=5)["value"])

    def test_write_sends_one_request_line(self):
        daemon = ScriptedDaemon(line(HELLO))
        s = self.connect(daemon)
        s.write("forward", input_name="action", request_id=7)
        s.close()
        for _ in range(50):
            if daemon.received:
                break
            daemon.thread.join(0.1)
        self.assertEqual([{"op": "write", "value": "forward", "input": "action", "id": 7}], daemon.received)

    def test_request_returns_ok_and_raises_on_error(self):
        def answer(request):
            if request.get("op") == "rate":
                return line({"type": "error", "code": "bad_value", "message": "maxHz", "id": request["id"]})
            return b"[]\n" + sample(9, [1.0]) + line({"type": "ok", "id": request["id"]})
        s = self.connect(ScriptedDaemon(line(HELLO), answer=answer))
        self.assertEqual("ok", s.request({"op": "write", "value": [0.1, 0.0]})["type"])
        self.assertEqual(["not_object"], [e["code"] for e in s.events])
        with self.assertRaises(ControlError) as caught:
            s.request({"op": "rate", "maxHz": -1})
        self.assertEqual("bad_value", caught.exception.code)

    def test_a_client_with_a_token_authenticates_first_and_keeps_the_full_hello(self):
        full = dict(HELLO, auth="ok", client="mdb", role="command")
        daemon = ScriptedDaemon(
            json.dumps({"type": "hello", "protocol": "habla-control/1", "socket": "ranges",
                        "auth": "required"}).encode() + b"\n",
            answer=lambda req: (json.dumps(full) + "\n").encode() if req.get("op") == "auth" else b"")
        self.addCleanup(daemon.close)
        with ControlSocket("127.0.0.1", daemon.port, timeout=5, client="mdb", token="t" * 20) as s:
            self.assertEqual(s.hello["client"], "mdb")
            self.assertEqual(daemon.received[0], {"op": "auth", "client": "mdb", "token": "t" * 20})

    def test_a_refused_token_raises_the_daemons_error(self):
        daemon = ScriptedDaemon(
            json.dumps({"type": "hello", "protocol": "habla-control/1", "socket": "ranges",
                        "auth": "required"}).encode() + b"\n",
            answer=lambda req: b'{"type":"error","code":"auth_failed","message":"no"}\n')
        self.addCleanup(daemon.close)
        with self.assertRaises(ControlError) as caught:
            ControlSocket("127.0.0.1", daemon.port, timeout=5, client="mdb", token="wrong-token-wrong")
        self.assertEqual(caught.exception.code, "auth_failed")

    def test_end_of_stream_gives_none(self):
        daemon = ScriptedDaemon(line(HELLO), sample(1, [1.0]))
        s = self.connect(daemon)
        self.assertIsNotNone(s.next_sample(timeout=5))
        # a socket closed with the client's ping still unread is reset, not ended: let the daemon read it first
        self.assertTrue(daemon.await_pings(1))
        daemon.close()
        self.assertIsNone(s.next_sample(timeout=5))


if __name__ == "__main__":
    unittest.main()
