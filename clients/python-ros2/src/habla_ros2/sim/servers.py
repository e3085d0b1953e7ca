"""The simulated world's TCP servers on loopback, as habla-sim serves them: the ground truth and the keyboard
(JSON or text lines to every client; the ground truth takes operations back), and the laptop's microphone
(raw PCM, 16 kHz, signed 16-bit little-endian, mono). A client that does not keep up loses what it did not
read in time; nothing queues without bound."""

import json
import queue
import re
import socket
import threading

import numpy as np

CLIENT_QUEUE = 256        # lines or audio chunks waiting for one slow client before the oldest are dropped
SAMPLE_RATE = 16000
NOTE_S, NOTE_LEVEL, NOISE_LEVEL, EDGE_S = 0.4, 0.3, 0.003, 0.01
NOTES = {"C": 0, "D": 2, "E": 4, "F": 5, "G": 7, "A": 9, "B": 11}


def note_hz(name):
    """Scientific pitch (A4 = 440 Hz): C5 -> 523.25."""
    m = re.fullmatch(r"([A-Ga-g])([#b]?)(-?\d+)", name)
    if m is None:
        raise ValueError("'%s' is not a note such as C5, F#4 or Bb3" % name)
    semis = NOTES[m.group(1).upper()] + {"#": 1, "b": -1, "": 0}[m.group(2)]
    return 440.0 * 2 ** ((semis - 9 + 12 * (int(m.group(3)) - 4)) / 12)


class Server:
    """Listens on 127.0.0.1:port; every client gets a bounded queue and a writer thread; on_line(text) -> reply
    handles what a client writes (None: the server takes nothing)."""

    def __init__(self, name, port, on_line=None):
        self.name, self._on_line = name, on_line
        self._listener = socket.create_server(("127.0.0.1", port))
        self.port = self._listener.getsockname()[1]
        self._clients = []
        self._lock = threading.Lock()
        threading.Thread(target=self._accept, daemon=True, name=name + "-accept").start()

    def listening(self):
        with self._lock:
            return bool(self._clients)

    def _accept(self):
        while True:
            try:
                conn, _ = self._listener.accept()
            except OSError:
                return
            q = queue.Queue(CLIENT_QUEUE)
            with self._lock:
                self._clients.append((conn, q))
            threading.Thread(target=self._write, args=(conn, q), daemon=True, name=self.name + "-write").start()
            if self._on_line is not None:
                threading.Thread(target=self._read, args=(conn, q), daemon=True, name=self.name + "-read").start()

    def send(self, data):
        with self._lock:
            clients = list(self._clients)
        for _, q in clients:
            try:
                q.put_nowait(data)
            except queue.Full:       # a slow client: its oldest waiting data goes
                try:
                    q.get_nowait()
                    q.put_nowait(data)
                except (queue.Empty, queue.Full):
                    pass

    def line(self, text):
        self.send((text + "\n").encode())

    def _write(self, conn, q):
        try:
            while True:
                data = q.get()
                if data is None:
                    break
                conn.sendall(data)
        except OSError:
            pass
        self._drop(conn)

    def _read(self, conn, q):
        buf = b""
        try:
            while True:
                chunk = conn.recv(65536)
                if not chunk:
                    break
                buf += chunk
                while b"\n" in buf:
                    raw, buf = buf.split(b"\n", 1)
                    if raw.strip():
                        q.put((self._on_line(raw.decode("utf-8", "replace")) + "\n").encode())
        except OSError:
            pass
        self._drop(conn)
        q.put(None)

    def _drop(self, conn):
        with self._lock:
            self._clients = [(c, q) for c, q in self._clients if c is not conn]
        try:
            conn.close()
        except OSError:
            pass

    def close(self):
        self._listener.close()
        with self._lock:
            clients, self._clients = self._clients, []
        for c, _ in clients:
            c.close()


class Microphone:
    """The laptop's microphone: background noise, and a note (0.4 s sine with 10 ms soft edges) when played;
    step(dt) makes dt seconds of samples and sends them to the PCM server."""

    def __init__(self, server, seed=1):
        self.server = server
        self._rng = np.random.default_rng(seed)
        self._owed = 0.0
        self._tone_hz = 0.0
        self._tone_at = -1       # samples of the sounding note already made; -1: none sounds
        self._phase = 0.0

    def play(self, hz):
        self._tone_hz, self._tone_at, self._phase = hz, 0, 0.0
        return NOTE_S

    def step(self, dt):
        self._owed += dt * SAMPLE_RATE
        n = int(self._owed)
        self._owed -= n
        if n == 0:
            return
        length = int(round(NOTE_S * SAMPLE_RATE))
        if not self.server.listening():
            if self._tone_at >= 0:
                self._tone_at = -1 if self._tone_at + n >= length else self._tone_at + n
            return
        s = self._rng.standard_normal(n) * NOISE_LEVEL
        if self._tone_at >= 0:
            k = min(n, length - self._tone_at)
            idx = np.arange(self._tone_at, self._tone_at + k)
            t = idx / SAMPLE_RATE
            edge = np.minimum(1.0, np.minimum(t, NOTE_S - t) / EDGE_S)
            phases = self._phase + 2 * np.pi * self._tone_hz / SAMPLE_RATE * np.arange(k)
            s[:k] += NOTE_LEVEL * edge * np.sin(phases)
            self._phase = float(phases[-1] + 2 * np.pi * self._tone_hz / SAMPLE_RATE) if k else self._phase
            self._tone_at = -1 if self._tone_at + k >= length else self._tone_at + k
        pcm = np.round(np.clip(s, -1, 1) * 32767).astype("<i2").tobytes()
        self.server.send(pcm)


class Voice:
    """How the teacher reaches the base, as the Pioneer's teacher: notes on the microphone, rewards typed."""

    def __init__(self, notes, microphone, keyboard):
        self.notes = {label: note_hz(n) for label, n in notes.items()}
        self.microphone, self.keyboard = microphone, keyboard

    def command(self, label):
        return self.microphone.play(self.notes[label])

    def reward(self, value):
        magnitude = "%d" % abs(value) if value == int(value) else repr(abs(value))
        self.keyboard.line(("-" if value < 0 else "+") + magnitude)


def json_line(obj):
    return json.dumps(obj, separators=(",", ":"))
