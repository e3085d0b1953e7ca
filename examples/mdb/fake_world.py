"""A tiny world behind the four sockets of HABLA's control contract, for trying a control architecture
without a daemon or a robot.

A point robot on an open plane, a round target, and a teacher that follows the contract's rules: while
present, every `command_every_s` it gives the command that brings the robot towards the target
(|angle| > 0.35 rad: left/right, else forward), then after `judge_after_s` rewards +1 if the robot moved
as commanded (heading change of that sign for a turn, displacement along the old heading for
forward/back) and -1 otherwise. The sockets speak the daemon's control protocol: a hello line, then one
JSON sample per line; the action socket takes `{"op":"write","value":"forward"}` (or `{"value":...}`),
moves the robot for `duration_ms`, and echoes the label. Bad lines get an error line; the connection
and the world carry on.

The teacher leaves after `teacher_commands` commands (never, if None); then the target is put at a new
random place and the world notes when (in world seconds) the robot reaches it. While the teacher is
present, a reached target is moved to a new random place, so teaching goes on.

Time runs `speed` times faster than the wall clock, all of it: motion, samples, the teacher. It starts
when the first client connects to the action socket, so a controller that is slow to start misses nothing.

    python3 fake_world.py --seed 3 --command-port 7001   # then run mdb.py against it
"""

import argparse
import json
import math
import random
import socket
import sys
import threading
import time

LABELS = ("forward", "left", "right", "back", "stop")
MAX_LINE = 65536
TURN_THRESHOLD_RAD = 0.35


def wrap(angle):
    return math.atan2(math.sin(angle), math.cos(angle))


class _Client:
    def __init__(self, sock):
        self.sock = sock
        self.lock = threading.Lock()
        self.alive = True

    def send(self, obj):
        return self.send_raw((json.dumps(obj) + "\n").encode("utf-8"))

    def send_raw(self, data):
        with self.lock:
            if not self.alive:
                return False
            try:
                self.sock.sendall(data)
                return True
            except OSError:
                self.alive = False
                return False

    def close(self):
        self.alive = False
        try:
            self.sock.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self.sock.close()


class _Server:
    """One contract socket: accepts clients, says hello, broadcasts samples, answers requests."""

    def __init__(self, world, name, kind, writable, host, port):
        self.world, self.name, self.kind, self.writable = world, name, kind, writable
        self.listener = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            self.listener.bind((host, port))
        except OSError:
            self.listener.close()
            raise
        self.listener.listen(8)
        self.port = self.listener.getsockname()[1]
        self.clients = []
        self.seq = 0
        self.lock = threading.Lock()
        self.closed = False

    def start(self):
        threading.Thread(target=self._accept, name="world-" + self.name, daemon=True).start()

    def hello(self):
        return {"type": "hello", "protocol": "habla-control/1", "socket": self.name, "method": self.name,
                "layer": "virtual", "direction": "both" if self.writable else "out",
                "outputs": [{"name": "out", "kind": self.kind, "unit": "", "fields": [], "doc": ""}],
                "inputs": [{"name": "in", "kind": "text"}] if self.writable else [],
                "stale": False, "limits": {"maxLineBytes": MAX_LINE, "maxBinaryBytes": 0, "clientQueueSamples": 64}}

    def _accept(self):
        while not self.closed:
            try:
                sock, _ = self.listener.accept()
            except OSError:
                return
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            sock.settimeout(2.0)
            client = _Client(sock)
            if not client.send(self.hello()):
                continue
            with self.lock:
                self.clients.append(client)
            threading.Thread(target=self._serve, args=(client,), daemon=True).start()

    def publish(self, value):
        with self.lock:
            self.seq += 1
            line = {"type": "sample", "output": "out", "seq": self.seq, "t": int(time.monotonic() * 1e6),
                    "stale": False, "kind": self.kind, "value": value}
            clients = list(self.clients)
        for c in clients:
            if not c.send(line):
                with self.lock:
                    if c in self.clients:
                        self.clients.remove(c)

    def _serve(self, client):
        buf = b""
        try:
            while client.alive and not self.closed:
                try:
                    chunk = client.sock.recv(4096)
                except socket.timeout:
                    continue
                if not chunk:
                    break
                buf += chunk
                while b"\n" in buf:
                    line, buf = buf.split(b"\n", 1)
                    if line.strip():
                        client.send(self._answer(line))
                if len(buf) > MAX_LINE:
                    client.send({"type": "error", "code": "line_too_long",
                                 "message": "a line is longer than %d bytes" % MAX_LINE})
                    break
        except OSError:
            pass
        finally:
            client.close()
            with self.lock:
                if client in self.clients:
                    self.clients.remove(client)

    def _answer(self, raw):
        try:
            req = json.loads(raw.decode("utf-8"))
            if not isinstance(req, dict):
                raise ValueError("a request is a JSON object")
        except (ValueError, UnicodeDecodeError) as e:
            return {"type": "error", "code": "bad_json", "message": str(e)}
        rid = req.get("id")
        op = req.get("op", "write" if "value" in req else "")
        if op == "ping":
            return {"type": "pong", "id": rid}
        if op != "write":
            return {"type": "error", "code": "unknown_op", "message": "ops are write, ping", "id": rid}
        if not self.writable:
            return {"type": "error", "code": "read_only", "message": "socket '%s' takes no values" % self.name,
                    "id": rid}
        value = req.get("value")
        if value not in LABELS:
            return {"type": "error", "code": "bad_value", "message": "expected one of %s" % (LABELS,), "id": rid}
        self.world.act(value)
        self.publish(value)
        return {"type": "ok", "id": rid}

    def close(self):
        self.closed = True
        try:
            self.listener.shutdown(socket.SHUT_RDWR)  # wakes the accepting thread, which close() alone does not
        except OSError:
            pass
        self.listener.close()
        with self.lock:
            clients, self.clients = self.clients, []
        for c in clients:
            c.close()


class FakeWorld:
    """The world, its teacher and its four sockets; `start()` it, read `results()`, `stop()` it."""

    def __init__(self, seed=0, speed=1.0, host="127.0.0.1", ports=None, command_every_s=3.0, judge_after_s=1.5,
                 teacher_commands=None, forward_mps=0.2, back_mps=0.15, turn_radps=0.6, duration_ms=1000,
                 reach_m=0.1, robot_radius_m=0.2, target_radius_m=0.1, place_distance_m=(1.2, 2.2),
                 noise_m=0.01, noise_rad=0.02, publish_hz=10.0):
        if speed < 1.0:
            raise ValueError("speed must be at least 1")
        self.rng = random.Random(seed)
        self.speed = speed
        self.command_every_s, self.judge_after_s = command_every_s, judge_after_s
        self.teacher_commands = teacher_commands
        self.speeds = {"forward": (forward_mps, 0.0), "back": (-back_mps, 0.0), "left": (0.0, turn_radps),
                       "right": (0.0, -turn_radps), "stop": (0.0, 0.0)}
        self.duration_s = duration_ms / 1000.0
        self.reach_m, self.robot_radius_m, self.target_radius_m = reach_m, robot_radius_m, target_radius_m
        self.place_distance_m = place_distance_m
        self.noise_m, self.noise_rad = noise_m, noise_rad
        self.publish_period_s = 1.0 / publish_hz
        self.lock = threading.RLock()
        self.x, self.y, self.theta = 0.0, 0.0, self.rng.uniform(-math.pi, math.pi)
        self.v = self.w = 0.0
        self.motion_until = 0.0
        self.target = (0.0, 0.0)
        self._place_target()
        self.now = 0.0
        self.teacher_present = True
        self.commands_given = 0
        self.rewards = []  # (world time, command, value)
        self.reached_while_teaching = 0
        self.teacher_left_at = None
        self.left_distance_m = None
        self.reached_at = None  # world seconds after the teacher left
        self.actions = 0
        ports = ports or {}
        self.servers = {
            "command": _Server(self, "command", "text", False, host, ports.get("command", 0)),
            "distance_angle": _Server(self, "distance_angle", "record", False, host, ports.get("distance_angle", 0)),
            "reward": _Server(self, "reward", "number", False, host, ports.get("reward", 0)),
            "action": _Server(self, "action", "text", True, host, ports.get("action", 0)),
        }
        self.ports = {n: s.port for n, s in self.servers.items()}
        self._running = False
        self._thread = threading.Thread(target=self._run, name="world-clock", daemon=True)

    # -- geometry ----------------------------------------------------------------------------------
    def _place_target(self):
        d = self.rng.uniform(*self.place_distance_m) + self.robot_radius_m + self.target_radius_m
        bearing = self.theta + self.rng.uniform(-math.pi, math.pi)
        self.target = (self.x + d * math.cos(bearing), self.y + d * math.sin(bearing))

    def distance_angle(self):
        """The true surface distance (m) and bearing (rad, + left) of the target from the robot."""
        dx, dy = self.target[0] - self.x, self.target[1] - self.y
        d = max(0.0, math.hypot(dx, dy) - self.robot_radius_m - self.target_radius_m)
        return d, wrap(math.atan2(dy, dx) - self.theta)

    # -- inputs --------------------------------------------------------------------------------------
    def act(self, label):
        with self.lock:
            self.v, self.w = self.speeds[label]
            self.motion_until = self.now + (0.0 if label == "stop" else self.duration_s)
            self.actions += 1

    # -- life cycle ----------------------------------------------------------------------------------
    def start(self):
        for s in self.servers.values():
            s.start()
        self._running = True
        self._thread.start()
        return self

    def stop(self):
        self._running = False
        self._thread.join(timeout=5.0)
        for s in self.servers.values():
            s.close()

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.stop()

    def results(self):
        with self.lock:
            return {"now": self.now, "commandsGiven": self.commands_given, "actions": self.actions,
                    "rewards": list(self.rewards), "teacherLeftAt": self.teacher_left_at,
                    "leftDistanceM": self.left_distance_m, "reachedAfterS": self.reached_at,
                    "reachedWhileTeaching": self.reached_while_teaching,
                    "distanceM": self.distance_angle()[0]}

    # -- the clock ------------------------------------------------------------------------------------
    def _run(self):
        while self._running and not self.servers["action"].clients:
            time.sleep(0.01)  # the world starts when a controller is there to live in it
        t0 = time.monotonic()
        next_publish = 0.0
        next_command = self.command_every_s / 2.0
        judge = None  # (at, label, x, y, theta)
        while self._running:
            time.sleep(0.004)
            now = (time.monotonic() - t0) * self.speed
            with self.lock:
                self._advance(now)
                d, a = self.distance_angle()
                if d <= self.reach_m:
                    if self.teacher_present:
                        self.reached_while_teaching += 1
                        self._place_target()
                    elif self.reached_at is None:
                        self.reached_at = now - self.teacher_left_at
                say = reward = None
                if judge is not None and now >= judge[0]:
                    reward = self._judge(*judge[1:])
                    self.rewards.append((round(now, 3), judge[1], reward))
                    judge = None
                if self.teacher_present and now >= next_command:
                    if self.teacher_commands is not None and self.commands_given >= self.teacher_commands:
                        self.teacher_present = False
                        self.teacher_left_at = now
                        self._place_target()
                        self.left_distance_m = self.distance_angle()[0]
                    else:
                        say = "forward" if abs(a) <= TURN_THRESHOLD_RAD else "left" if a > 0 else "right"
                        judge = (now + self.judge_after_s, say, self.x, self.y, self.theta)
                        self.commands_given += 1
                        next_command = now + self.command_every_s
                publish = now >= next_publish
                if publish:
                    next_publish = now + self.publish_period_s
                    d, a = self.distance_angle()
                    sample = {"distanceM": max(0.0, d + self.rng.gauss(0.0, self.noise_m)),
                              "angleRad": wrap(a + self.rng.gauss(0.0, self.noise_rad)), "seen": True}
            if say is not None:
                self.servers["command"].publish(say)
            if reward is not None:
                self.servers["reward"].publish(reward)
            if publish:
                self.servers["distance_angle"].publish(sample)

    def _advance(self, now):
        while self.now < now:
            dt = min(0.01, now - self.now)
            if self.now >= self.motion_until:
                self.v = self.w = 0.0
            self.theta = wrap(self.theta + self.w * dt)
            self.x += self.v * dt * math.cos(self.theta)
            self.y += self.v * dt * math.sin(self.theta)
            self.now += dt

    def _judge(self, label, x0, y0, theta0):
        along = (self.x - x0) * math.cos(theta0) + (self.y - y0) * math.sin(theta0)
        turned = wrap(self.theta - theta0)
        obeyed = {"forward": along > 0.02, "back": along < -0.02, "left": turned > 0.05,
                  "right": turned < -0.05}[label]
        return 1 if obeyed else -1


def main(argv=None):
    p = argparse.ArgumentParser(description="A point robot, a target and a teacher behind the control contract.")
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--command-port", type=int, default=7001)
    p.add_argument("--distance-angle-port", type=int, default=7002)
    p.add_argument("--reward-port", type=int, default=7003)
    p.add_argument("--action-port", type=int, default=7004)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--speed", type=float, default=1.0)
    p.add_argument("--command-every-s", type=float, default=3.0)
    p.add_argument("--judge-after-s", type=float, default=1.5)
    p.add_argument("--teacher-commands", type=int, help="the teacher leaves after this many (default: stays)")
    p.add_argument("--max-seconds", type=float, help="wall seconds to run (default: until killed)")
    args = p.parse_args(argv)
    ports = {"command": args.command_port, "distance_angle": args.distance_angle_port,
             "reward": args.reward_port, "action": args.action_port}
    world = FakeWorld(seed=args.seed, speed=args.speed, host=args.host, ports=ports,
                      command_every_s=args.command_every_s, judge_after_s=args.judge_after_s,
                      teacher_commands=args.teacher_commands)
    print(json.dumps({"ports": world.ports}), flush=True)
    world.start()
    deadline = None if args.max_seconds is None else time.monotonic() + args.max_seconds
    try:
        while deadline is None or time.monotonic() < deadline:
            time.sleep(1.0)
            print(json.dumps(world.results()), flush=True)
    except KeyboardInterrupt:
        pass
    finally:
        world.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
