"""bench/run ros2: what the ROS 2 face costs. Rounds, each with its own daemon and face:

  pair       a plain rclpy publisher -> subscriber pair (std_msgs/String, best effort), 100 Hz: the floor
  socket     robot stamp -> daemon -> a habla client on the socket, 100 Hz
  face       robot stamp -> daemon -> face -> rclpy subscriber, 100 Hz
  1 kHz      the face at 1000 Hz on one topic: sent, received, lost
  10 x 200   the face at 200 Hz on each of 10 topics: sent, received, lost

The robot is an interface program (robot.py) stamping each reading with the wall clock; the daemon relays it
through a channel and two pass-throughs to a socket; the subscriber takes the stamp from the sample's JSON.
Latency is the subscriber's clock minus the stamp. Usage: face_bench.py [--seconds S]
"""

import argparse
import json
import os
import random
import socket
import subprocess
import sys
import tempfile
import threading
import time

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

HERE = os.path.dirname(os.path.abspath(__file__))
HOME = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(HOME, "clients", "python", "src"))
import habla  # noqa: E402

PYTHONPATH = os.pathsep.join([os.path.join(HOME, "clients", "python", "src"),
                              os.path.join(HOME, "clients", "python-ros2", "src")])
START_S = 90
LISTENER_DEPTH = 1000     # the subscriber's history: a burst while its callback is busy is kept, not dropped
SETTLE_S = 1.0            # after the publishers are matched, before the robot starts


def free_port():
    """A free port below the ephemeral range, so that no connection made meanwhile takes it."""
    for _ in range(200):
        port = random.randint(20000, 32000)
        with socket.socket() as s:
            s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            try:
                s.bind(("127.0.0.1", port))
                return port
            except OSError:
                continue
    raise RuntimeError("no free port found")


def wait_port(port, proc, timeout_s=START_S):
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            raise RuntimeError("a bench process stopped (exit %s)" % proc.returncode)
        try:
            socket.create_connection(("127.0.0.1", port), 0.5).close()
            return
        except OSError:
            time.sleep(0.1)
    raise TimeoutError("port %d did not open" % port)


def percentiles(values):
    v = sorted(values)
    if not v:
        return {"n": 0}
    pick = lambda q: v[min(len(v) - 1, int(q * len(v)))]  # noqa: E731
    return {"n": len(v), "p50": pick(0.5), "p90": pick(0.9), "p99": pick(0.99), "max": v[-1]}


class Listener:
    """An rclpy subscriber on topics of JSON samples: latency from the stamp, and which numbers arrived."""

    def __init__(self, topics):
        self.node = Node("bench_listener_%d" % os.getpid())
        self.lock = threading.Lock()
        self.latencies_us, self.seen = [], [set() for _ in topics]
        qos = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=LISTENER_DEPTH, reliability=ReliabilityPolicy.BEST_EFFORT)
        self.subs = [self.node.create_subscription(String, t, lambda m, i=i: self.take(i, m), qos)
                     for i, t in enumerate(topics)]
        self.states = {}
        latched = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.subs += [self.node.create_subscription(String, t + "/state", lambda m, t=t: self.state(t, m), latched)
                      for t in topics]
        self.executor = SingleThreadedExecutor()
        self.executor.add_node(self.node)
        self.running = True
        self.thread = threading.Thread(target=self.spin, daemon=True)
        self.thread.start()

    def spin(self):
        while self.running:
            self.executor.spin_once(timeout_sec=0.05)

    def take(self, i, msg):
        now = time.time_ns() // 1000
        line = json.loads(msg.data)
        with self.lock:
            self.latencies_us.append(now - line["t"])
            self.seen[i].add(line["value"]["n"])

    def state(self, topic, msg):
        with self.lock:
            self.states[topic] = json.loads(msg.data)

    def close(self):
        self.running = False
        self.thread.join(5)
        self.executor.shutdown()
        self.node.destroy_node()


def daemon_config(folder, channels, robot_port, status_port):
    ports = [free_port() for _ in range(channels)]
    methods = []
    for i in range(channels):
        methods += [
            {"id": "in%d" % i, "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@robot.c%d" % i},
             "params": {"kind": "record", "delivery": "queue"}},
            {"id": "up%d" % i, "type": "pass-through", "layer": "processing", "inputs": {"in": "in%d.out" % i},
             "params": {"kind": "record", "delivery": "queue"}},
            {"id": "p%d" % i, "type": "pass-through", "layer": "virtual", "inputs": {"in": "up%d.out" % i},
             "params": {"kind": "record", "delivery": "queue"}, "expose": {"port": ports[i], "name": "p%d" % i}}]
    root = {"system": "bench", "status": {"port": status_port},
            "interfaces": [{"id": "robot", "driver": "habla", "address": "127.0.0.1:%d" % robot_port,
                            "params": {"channels": [{"name": "c%d" % i, "direction": "reading", "kind": "record"}
                                                    for i in range(channels)]}}],
            "methods": methods}
    path = os.path.join(folder, "bench-%d.json" % channels)
    with open(path, "w") as f:
        json.dump(root, f)
    return path, ports


class FaceRig:
    """Robot, daemon and face for one round."""

    def __init__(self, folder, channels, hz, seconds, face=True):
        self.procs = []
        robot_port, status_port = free_port(), free_port()
        self.config, self.ports = daemon_config(folder, channels, robot_port, status_port)
        log = open(os.path.join(folder, "bench-%d-%g.log" % (channels, hz)), "ab")
        self.robot = self.start([sys.executable, os.path.join(HERE, "robot.py"), str(robot_port), str(channels),
                                 str(hz), str(seconds)], stdout=subprocess.PIPE, stdin=subprocess.PIPE)
        self.robot.stdout.readline()
        daemon = self.start([os.path.join(HOME, "habla"), "run", self.config], stdout=log)
        wait_port(self.ports[-1], daemon)
        if face:
            self.start([sys.executable, "-m", "habla_ros2", "face", self.config], stdout=log,
                       env=dict(os.environ, PYTHONPATH=PYTHONPATH))

    def start(self, args, stdout, env=None, stdin=None):
        p = subprocess.Popen(args, stdout=stdout, stderr=subprocess.STDOUT if stdout is not subprocess.PIPE else None,
                             env=env, cwd=HOME, stdin=stdin)
        self.procs.append(p)
        return p

    def go(self):
        """Waits until HABLA has the robot's hello, then lets the robot stream."""
        assert self.robot.stdout.readline().strip() == b"connected"
        time.sleep(SETTLE_S)
        self.robot.stdin.write(b"go\n")
        self.robot.stdin.flush()

    def sent(self):
        return json.loads(self.robot.stdout.readline())["sent"]

    def cpu_s(self, index):
        """CPU seconds (user + system) a started process has used so far."""
        fields = open("/proc/%d/stat" % self.procs[index].pid).read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    def close(self):
        for p in reversed(self.procs):
            if p.poll() is None:
                p.terminate()
                try:
                    p.wait(10)
                except subprocess.TimeoutExpired:
                    p.kill()


def await_publishers(listener, topics, timeout_s=60):
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if all(listener.node.count_publishers(t) > 0 for t in topics):
            return
        time.sleep(0.05)
    raise TimeoutError("no publisher on %s" % topics)


def face_round(folder, channels, hz, seconds):
    topics = ["/habla/bench/p%d" % i for i in range(channels)]
    listener = Listener(topics)
    rig = FaceRig(folder, channels, hz, seconds)
    try:
        await_publishers(listener, topics + [t + "/state" for t in topics])
        face_cpu0 = rig.cpu_s(2)
        rig.go()
        sent = rig.sent()
        time.sleep(0.5)
        face_cpu = rig.cpu_s(2) - face_cpu0
    finally:
        rig.close()
        listener.close()
    received = [len(s) for s in listener.seen]
    states = listener.states.values()
    return {"latencyUs": percentiles(listener.latencies_us), "sent": sum(sent), "received": sum(received),
            "lost": sum(sent) - sum(received), "socketDropped": sum(st["dropped"] for st in states),
            "facePublished": sum(st["samples"] for st in states),
            "faceCpuUsPerSample": round(1e6 * face_cpu / max(1, sum(st["samples"] for st in states)))}


def socket_round(folder, hz, seconds):
    rig = FaceRig(folder, 1, hz, seconds, face=False)
    latencies = []
    try:
        with habla.connect("127.0.0.1", rig.ports[0]) as s:
            rig.go()
            end = time.monotonic() + seconds
            while time.monotonic() < end:
                try:
                    sample = s.next_sample(timeout=1.0)
                except TimeoutError:
                    continue
                latencies.append(time.time_ns() // 1000 - sample.t_us)
    finally:
        rig.close()
    return {"latencyUs": percentiles(latencies)}


def pair_round(hz, seconds):
    topics = ["/bench/pair/c0"]
    listener = Listener(topics)
    pub = subprocess.Popen([sys.executable, os.path.join(HERE, "pair_pub.py"), "1", str(hz), str(seconds)],
                           stdout=subprocess.PIPE)
    try:
        pub.stdout.readline()
        sent = json.loads(pub.stdout.readline())["sent"]
    finally:
        pub.wait(30)
        listener.close()
    return {"latencyUs": percentiles(listener.latencies_us), "sent": sum(sent),
            "received": len(listener.seen[0]), "lost": sum(sent) - len(listener.seen[0])}


def ms(us):
    return "%.2f" % (us / 1000.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=10.0)
    a = ap.parse_args()
    rclpy.init()
    folder = tempfile.mkdtemp(prefix="habla-bench-ros2-")
    print("bench ros2: ROS_DOMAIN_ID=%s, load average %s, logs in %s" % (
        os.environ.get("ROS_DOMAIN_ID"), " ".join(open("/proc/loadavg").read().split()[:3]), folder), flush=True)
    results = {"pair": pair_round(100, a.seconds)}
    results["socket"] = socket_round(folder, 100, a.seconds)
    results["face"] = face_round(folder, 1, 100, a.seconds)
    results["face 1 kHz x 1"] = face_round(folder, 1, 1000, a.seconds)
    results["face 200 Hz x 10"] = face_round(folder, 10, 200, a.seconds)
    print("%-18s %6s %7s %7s %7s %7s %7s %8s %9s %9s %6s" % (
        "round", "n", "p50 ms", "p90 ms", "p99 ms", "max ms", "sent", "dropped", "published", "received", "lost"))
    for name, r in results.items():
        lat = r["latencyUs"]
        print("%-18s %6d %7s %7s %7s %7s %7s %8s %9s %9s %6s" % (
            name, lat["n"], ms(lat["p50"]), ms(lat["p90"]), ms(lat["p99"]), ms(lat["max"]), r.get("sent", "-"),
            r.get("socketDropped", "-"), r.get("facePublished", "-"), r.get("received", "-"), r.get("lost", "-")))
    for name, r in results.items():
        if "faceCpuUsPerSample" in r:
            print("%-18s the face used %d us of CPU per sample" % (name, r["faceCpuUsPerSample"]))
    print("dropped: by the daemon's socket for the face (a client that did not keep up); published: by the face;"
          " received: by the subscriber; lost: sent - received")
    pair, sock, face = (results[k]["latencyUs"]["p50"] for k in ("pair", "socket", "face"))
    added = face - sock
    print("the face adds %s ms at p50 (face %s - socket %s) = %.2f x the plain pair's p50 (%s ms); goal <= 1.5" % (
        ms(added), ms(face), ms(sock), added / pair, ms(pair)))
    print(json.dumps(results))
    rclpy.shutdown()


if __name__ == "__main__":
    main()
