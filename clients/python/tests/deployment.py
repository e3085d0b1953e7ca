"""A HABLA set-up for tests, as a user deploys one: a simulated robot and the daemon, each its own process,
on a block of free loopback ports; the ground truth read from the simulator.

How `habla` is run: HABLA_COMMAND (a JSON list, e.g. the java command a JUnit test passes) or else the
checkout's ./habla launcher. HABLA_TEST_PORT_OFFSET fixes the port offset; otherwise a free block is found.
"""

import json
import os
import random
import socket
import subprocess
import threading
import time

HOME = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
DEFAULT_PORTS = (7001, 7002, 7003, 7004, 7010, 7011, 7012, 7013, 7098, 7099, 7600, 8101, 8110, 8111, 8120, 8199)
START_S = 90.0   # a new JVM on a busy 2-core machine may take tens of seconds to open its first port


def habla_command():
    raw = os.environ.get("HABLA_COMMAND")
    return json.loads(raw) if raw else [os.path.join(HOME, "habla")]


def free_offset():
    """A port offset whose whole block of HABLA ports is free (below the ephemeral range)."""
    if os.environ.get("HABLA_TEST_PORT_OFFSET"):
        offset = int(os.environ["HABLA_TEST_PORT_OFFSET"])
        taken = [p + offset for p in DEFAULT_PORTS if not port_free(p + offset)]
        if taken:
            raise RuntimeError("HABLA_TEST_PORT_OFFSET=%d: ports %s are taken" % (offset, taken))
        return offset
    rng = random.Random()
    for _ in range(50):
        offset = 100 * rng.randint(10, 224)
        if all(port_free(p + offset) for p in DEFAULT_PORTS):
            return offset
    raise RuntimeError("no free block of ports found")


def port_free(port):
    with socket.socket() as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)   # as the servers bind: TIME_WAIT is no obstacle
        try:
            s.bind(("127.0.0.1", port))
            return True
        except OSError:
            return False


def await_port(port, timeout_s, proc=None):
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if proc is not None and proc.poll() is not None:
            raise RuntimeError("the process for port %d stopped (exit %s)" % (port, proc.returncode))
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.5).close()
            return
        except OSError:
            time.sleep(0.1)
    raise TimeoutError("port %d did not open within %.0f s" % (port, timeout_s))


def derive_config(config, offset, speed, out, tweak=None):
    """The robot's config with every port moved by offset (as habla scenario derives it); tweak(root) may
    change it further. Returns the path written."""
    with open(config) as f:
        root = json.load(f)
    root.pop("$schema", None)
    for iface in root.get("interfaces", []):
        host, _, port = iface.get("address", "").rpartition(":")
        if host and port.isdigit():
            iface["address"] = "%s:%d" % (host, int(port) + offset)
        if iface.get("driver") == "pioneer":
            iface.setdefault("params", {}).setdefault("keepAlivePeriodMs", max(10, round(500 / speed)))
    for m in root.get("methods", []):
        if isinstance(m.get("expose"), dict) and "port" in m["expose"]:
            m["expose"]["port"] += offset
    status = root.setdefault("status", {"port": 7099})
    status["port"] = status.get("port", 7099) + offset
    if status.get("monitorPort", 0) > 0:
        status["monitorPort"] += offset
    if tweak is not None:
        tweak(root)
    with open(out, "w") as f:
        json.dump(root, f, indent=2)
    return out


def exposed(config_path):
    """socket name -> expose object of a config."""
    with open(config_path) as f:
        root = json.load(f)
    return {m["expose"].get("name", m["id"]): m["expose"] for m in root.get("methods", [])
            if isinstance(m.get("expose"), dict)}


class Process:
    """One started program, its output in a log file; stop() sends SIGTERM, then kills."""

    def __init__(self, name, args, log_path, env=None):
        self.name, self.log_path = name, log_path
        self._log = open(log_path, "ab")
        self.proc = subprocess.Popen(args, stdout=self._log, stderr=subprocess.STDOUT, cwd=HOME,
                                     env=dict(os.environ, **(env or {})))

    def alive(self):
        return self.proc.poll() is None

    def log(self):
        with open(self.log_path, errors="replace") as f:
            return f.read()

    def stop(self, grace_s=10.0):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(grace_s)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(5)
        self._log.close()


class Truth:
    """The simulator's ground truth: state lines every 0.1 s of sim time, operations answered ok or error."""

    def __init__(self, port, timeout_s=START_S):
        deadline = time.monotonic() + timeout_s
        while True:
            try:
                self._sock = socket.create_connection(("127.0.0.1", port), timeout=2)
                break
            except OSError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.2)
        self._sock.settimeout(None)
        self._cv = threading.Condition()
        self._latest = None
        self._replies = []
        self._open = True
        threading.Thread(target=self._read, daemon=True, name="truth").start()

    def _read(self):
        buf = b""
        try:
            while True:
                chunk = self._sock.recv(65536)
                if not chunk:
                    break
                buf += chunk
                while b"\n" in buf:
                    line, buf = buf.split(b"\n", 1)
                    obj = json.loads(line)
                    with self._cv:
                        if "ok" in obj or "error" in obj:
                            # the state lines after a reply were made after its operation was carried out
                            obj["_after_t"] = self._latest["t"] if self._latest else -1.0
                            self._replies.append(obj)
                        else:
                            self._latest = obj
                        self._cv.notify_all()
        except OSError:
            pass
        with self._cv:
            self._open = False
            self._cv.notify_all()

    def latest(self):
        with self._cv:
            return self._latest

    def await_time(self, t, timeout_s):
        """The first state line at sim time t or later; TimeoutError otherwise."""
        deadline = time.monotonic() + timeout_s
        with self._cv:
            while self._latest is None or self._latest["t"] < t:
                remaining = deadline - time.monotonic()
                if remaining <= 0 or not self._open:
                    raise TimeoutError("no ground truth at t >= %.1f s (latest %r)" % (t, self._latest))
                self._cv.wait(remaining)
            return self._latest

    def after(self, seconds, timeout_s=30.0):
        return self.await_time(self.await_time(0, timeout_s)["t"] + seconds, timeout_s + seconds)

    def send(self, op, timeout_s=10.0):
        with self._cv:
            n = len(self._replies)
        self._sock.sendall((json.dumps(op) + "\n").encode())
        deadline = time.monotonic() + timeout_s
        with self._cv:
            while len(self._replies) <= n:
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    raise TimeoutError("no answer to %r" % (op,))
                self._cv.wait(remaining)
            reply = self._replies[n]
        if "error" in reply:
            raise RuntimeError("the simulator refused %r: %s" % (op, reply["error"]))
        return reply

    def place(self, x, y, theta):
        """Puts the robot there; returns the first state line made after it."""
        reply = self.send({"op": "reset", "robot": {"xM": x, "yM": y, "thetaRad": theta}})
        return self.await_time(reply["_after_t"] + 0.05, 30)

    def close(self):
        try:
            self._sock.close()
        except OSError:
            pass


def status(port, client=None, token=None, timeout_s=5.0):
    """The daemon's status snapshot (authenticating where the endpoint asks for it)."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout_s) as s:
        f = s.makefile("rwb")
        first = json.loads(f.readline())
        if first.get("auth") == "required":
            f.write((json.dumps({"op": "auth", "client": client, "token": token}) + "\n").encode())
            f.flush()
            first = json.loads(f.readline())
        return first


def await_ready(port, timeout_s, client=None, token=None):
    """Waits until every method is ready and every interface link is up, as the status endpoint tells."""
    deadline = time.monotonic() + timeout_s
    missing = "?"
    while time.monotonic() < deadline:
        try:
            snap = status(port, client, token)
            missing = [m["id"] for m in snap.get("methods", []) if not m.get("ready")] + \
                      ["link:" + i["id"] for i in snap.get("interfaces", []) if not i.get("up")]
            if not missing:
                return snap
        except (OSError, ValueError) as e:
            missing = str(e)
        time.sleep(0.2)
    raise TimeoutError("the daemon was not ready within %.0f s: %s" % (timeout_s, missing))


TOKENS = {"tester": "tester-token-0123456789abcdef", "viewer": "viewer-token-0123456789abcdef"}


def lab_security(folder):
    """A lab certificate for 127.0.0.1 (made with openssl, as docs/security.md says) and a credentials file:
    'tester' commands every socket and reads the status, 'viewer' only reads. Returns the security object."""
    key, crt = os.path.join(folder, "lab.key"), os.path.join(folder, "lab.crt")
    subprocess.run(["openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes",
                    "-days", "2", "-keyout", key, "-out", crt, "-subj", "/CN=habla-test",
                    "-addext", "subjectAltName=IP:127.0.0.1"], check=True, capture_output=True)
    os.chmod(key, 0o600)
    creds = os.path.join(folder, "lab.credentials.json")
    with open(os.open(creds, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600), "w") as f:
        json.dump({"clients": [
            {"name": "tester", "token": TOKENS["tester"], "roles": {"*": "command", "@status": "read"}},
            {"name": "viewer", "token": TOKENS["viewer"], "roles": {"*": "read"}}]}, f)
    return {"credentials": "lab.credentials.json", "loopback": "authenticated",
            "tls": {"certificate": "lab.crt", "key": "lab.key"}}


class PioneerRig:
    """The simulated Pioneer (the open hall, teacher away) and the daemon with config/pioneer.json, its ports
    moved to a free block; with security on, every socket wants a token and `tls_socket` speaks TLS."""

    def __init__(self, folder, speed=1.0, secure=True, tls_socket="pose"):
        self.folder, self.speed = folder, speed
        self.offset = free_offset()
        self.security = lab_security(folder) if secure else None
        self.certificate = os.path.join(folder, "lab.crt") if secure else None

        def tweak(root):
            if secure:
                root["security"] = self.security
                for m in root["methods"]:
                    if m.get("expose", {}).get("name") == tls_socket:
                        m["expose"]["tls"] = True
            root["status"].pop("monitorPort", None)
        self.config = derive_config(os.path.join(HOME, "config", "pioneer.json"), self.offset, speed,
                                    os.path.join(folder, "daemon.json"), tweak)
        self.ports = {name: e["port"] for name, e in exposed(self.config).items()}
        self.status_port = 7099 + self.offset
        self.truth_port = 8199 + self.offset
        self.sim = self.daemon = self.truth = None

    def start_simulator(self):
        o = self.offset
        self.sim = Process("simulator", habla_command() + [
            "sim", "pioneer", "--world", "pioneer-hall", "--speed", "%g" % self.speed, "--seed", "7", "--teacher", "off",
            "--truth-port", str(self.truth_port), "--port", str(8101 + o), "--mic-port", str(8110 + o),
            "--keys-port", str(8111 + o)], os.path.join(self.folder, "simulator.log"))
        self.truth = Truth(self.truth_port)
        self.truth.await_time(0, START_S)

    def start_daemon(self):
        self.daemon = Process("daemon", habla_command() + ["run", self.config, "--time-scale", "%g" % self.speed],
                              os.path.join(self.folder, "daemon.log"))
        await_port(self.ports["distance_angle"], START_S, self.daemon.proc)

    def await_ready(self, timeout_s=START_S):
        return await_ready(self.status_port, timeout_s, "tester", TOKENS["tester"])

    def stop_simulator(self):
        if self.truth is not None:
            self.truth.close()
        if self.sim is not None:
            self.sim.stop()

    def stop_daemon(self):
        if self.daemon is not None:
            self.daemon.stop()

    def close(self):
        self.stop_daemon()
        self.stop_simulator()
