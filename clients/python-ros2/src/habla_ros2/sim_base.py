"""habla-ros2 sim-base: a simulated ROS 2 mobile base in one of habla-sim's worlds.

On ROS 2 it is a base as REP-105 describes one: it publishes /scan (sensor_msgs/LaserScan, a 360-degree laser
at the base's centre, 10 Hz) and /odom (nav_msgs/Odometry, frame odom -> base_link, 20 Hz), and takes
/cmd_vel (geometry_msgs/Twist), stopping by itself when none comes for cmd_timeout_s. Beside it, the world of
the Pioneer's experiment, served as `habla sim pioneer` serves it: the teacher's notes on the microphone's
PCM stream, the rewards on the keyboard's lines, and the same ground-truth lines and operations
(docs/simulator.md). Sim time runs --speed times faster than the wall clock; ROS stamps are wall-clock time.
"""

import json
import math
import threading
import time

import numpy as np
import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
from sensor_msgs.msg import LaserScan

from .sim import servers
from .sim.base import Base
from .sim.teacher import Teacher, bearing
from .sim.world import World, find_world

STEP_S = 0.01             # sim time per physics step
TRUTH_PERIOD_S = 0.1      # a ground-truth line every 0.1 s of sim time, as habla-sim
SCAN_PERIOD_S = 0.1
ODOM_PERIOD_S = 0.05
LASER_BEAMS = 360
LASER_MIN_M = 0.05


def stamp_now(msg):
    ns = time.time_ns()
    msg.header.stamp.sec, msg.header.stamp.nanosec = ns // 1_000_000_000, ns % 1_000_000_000


class SimBase(Node):
    def __init__(self, a):
        super().__init__("habla_sim_base")
        self.a = a
        self.world = World(find_world(a.world))
        self.base = Base(radius_m=a.radius, cmd_timeout_s=a.cmd_timeout)
        self.base.place(*self.world.start)
        self.rng = np.random.default_rng(a.seed)
        self.lock = threading.Lock()
        self.now = 0.0
        self.episode = 0
        self.mic_server = servers.Server("microphone", a.mic_port)
        self.keys = servers.Server("keyboard", a.keys_port)
        self.mic = servers.Microphone(self.mic_server, a.seed)
        settings = dict(self.world.teacher, present=a.teacher == "on")
        self.teacher = Teacher(settings, servers.Voice(settings["notes"], self.mic, self.keys))
        self.truth = servers.Server("ground-truth", a.truth_port, self.operate)
        self.scan_pub = self.create_publisher(LaserScan, a.scan, qos_profile_sensor_data)
        self.odom_pub = self.create_publisher(Odometry, a.odom, QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE))
        self.create_subscription(Twist, a.cmd_vel, self.on_cmd_vel,
                                 QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT))
        self.angles = -math.pi + 2 * math.pi * np.arange(LASER_BEAMS) / LASER_BEAMS

    def on_cmd_vel(self, msg):
        with self.lock:
            self.base.command(msg.linear.x, msg.angular.z, self.now)

    # -- the world's clock ------------------------------------------------------------------------------
    def run_world(self, stop):
        wall0, steps = time.monotonic(), 0
        next_truth = next_scan = next_odom = 0.0
        while not stop.is_set() and (self.a.duration <= 0 or self.now < self.a.duration):
            with self.lock:
                self.now = steps * STEP_S
                self.base.step(STEP_S, self.world, self.now)
                pose = (self.base.x, self.base.y, self.base.theta)
                self.teacher.step(self.now, pose, self.world.target)
                self.mic.step(STEP_S)
                if self.now + 1e-9 >= next_truth:
                    next_truth = self.now + TRUTH_PERIOD_S
                    line = servers.json_line(self.truth_line())
                    self.truth.line(line)
            if self.now + 1e-9 >= next_scan:
                next_scan = self.now + SCAN_PERIOD_S
                self.scan_pub.publish(self.scan(pose))
            if self.now + 1e-9 >= next_odom:
                next_odom = self.now + ODOM_PERIOD_S
                self.odom_pub.publish(self.odometry())
            steps += 1
            delay = wall0 + steps * STEP_S / self.a.speed - time.monotonic()
            if delay > 0:
                stop.wait(delay)

    def scan(self, pose):
        msg = LaserScan()
        stamp_now(msg)
        msg.header.frame_id = "base_link"
        msg.angle_min, msg.angle_increment = float(self.angles[0]), 2 * math.pi / LASER_BEAMS
        msg.angle_max = float(self.angles[-1])
        msg.scan_time, msg.time_increment = SCAN_PERIOD_S / self.a.speed, 0.0
        msg.range_min, msg.range_max = LASER_MIN_M, float(self.a.laser_range)
        r = self.world.ranges(pose[0], pose[1], self.angles + pose[2], self.a.laser_range * 2)
        r = r + self.rng.normal(0, self.a.laser_noise, len(r))
        msg.ranges = np.where(r > self.a.laser_range, np.inf, np.maximum(r, LASER_MIN_M)).astype(float).tolist()
        return msg

    def odometry(self):
        msg = Odometry()
        stamp_now(msg)
        msg.header.frame_id, msg.child_frame_id = "odom", "base_link"
        with self.lock:
            x, y, th = self.base.odom
            v, w = self.base.v, self.base.w
        msg.pose.pose.position.x, msg.pose.pose.position.y = x, y
        msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = math.sin(th / 2), math.cos(th / 2)
        msg.twist.twist.linear.x, msg.twist.twist.angular.z = v, w
        return msg

    # -- the ground truth ---------------------------------------------------------------------------------
    def truth_line(self):
        b, (tx, ty, tr) = self.base, self.world.target
        distance = max(0.0, math.hypot(tx - b.x, ty - b.y) - tr - b.radius_m)
        c, p, m = self.teacher.episode
        return {"t": round(self.now, 3),
                "robot": {"xM": round(b.x, 4), "yM": round(b.y, 4), "thetaRad": round(b.theta, 4)},
                "target": {"xM": tx, "yM": ty, "radiusM": tr}, "distanceM": round(distance, 4),
                "angleRad": round(bearing((b.x, b.y, b.theta), tx, ty), 4), "stalled": b.stalled,
                "teacher": {"present": self.teacher.present, "lastCommand": self.teacher.last_command,
                            "lastReward": self.teacher.last_reward, "commands": c, "plus": p, "minus": m},
                "episode": self.episode}

    def operate(self, line):
        """One ground-truth operation line -> its reply line (habla-sim's TruthServer operations)."""
        try:
            op = json.loads(line)
        except ValueError as e:
            return servers.json_line({"error": "not a JSON object: %s" % e})
        if not isinstance(op, dict):
            return servers.json_line({"error": "an operation must be a JSON object with an \"op\""})
        try:
            with self.lock:
                self._apply(op)
        except (ValueError, TypeError, KeyError) as e:
            return servers.json_line({"error": str(e)})
        return servers.json_line({"ok": True})

    def _apply(self, op):
        name = op.get("op")
        if name == "reset":
            r, t = op.get("robot") or {}, op.get("target") or {}
            sx, sy, st = self.world.start
            now = self.world.target
            target = (float(t.get("xM", now[0])), float(t.get("yM", now[1])), float(t.get("radiusM", now[2])))
            pose = (float(r.get("xM", sx)), float(r.get("yM", sy)), float(r.get("thetaRad", st)))
            self.world.target = target
            if self.world.clearance(pose[0], pose[1]) < self.base.radius_m:
                self.world.target = now
                raise ValueError("the robot would overlap a wall or the target at (%s, %s)" % pose[:2])
            self.base.place(*pose)
            self.teacher.new_episode()
            self.episode += 1
        elif name == "teacher":
            if not isinstance(op.get("present"), bool):
                raise ValueError("teacher needs \"present\": true or false")
            self.teacher.set_present(op["present"])
        elif name in ("say", "note"):
            self.teacher.command_now(str(op.get("label", "")), (self.base.x, self.base.y, self.base.theta))
        elif name == "reward":
            value = op.get("value")
            if not isinstance(value, (int, float)) or isinstance(value, bool):
                raise ValueError("reward needs a numeric \"value\" in [-1, 1]")
            self.teacher.reward_now(float(value))
        elif name == "touch":
            raise ValueError("this robot has no touch sensors")
        else:
            raise ValueError("unknown op '%s' (ops: reset, teacher, say, note, reward, touch)" % name)

    def close(self):
        for s in (self.truth, self.mic_server, self.keys):
            s.close()


def run(a):
    if a.speed < 1:
        raise SystemExit("habla-ros2 sim-base: --speed must be 1 or more")
    rclpy.init()
    sim = SimBase(a)
    print("simulated ROS 2 base in '%s' at %gx: %s, %s, %s; microphone %d, keyboard %d, ground truth %d" % (
        sim.world.name, a.speed, a.scan, a.odom, a.cmd_vel, sim.mic_server.port, sim.keys.port, sim.truth.port),
        flush=True)
    stop = threading.Event()
    executor = SingleThreadedExecutor()
    executor.add_node(sim)
    spinner = threading.Thread(target=lambda: _spin(executor, stop), daemon=True)
    spinner.start()
    try:
        sim.run_world(stop)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        stop.set()
        spinner.join(2)
        sim.close()
        executor.shutdown()
        sim.destroy_node()
        rclpy.try_shutdown()
    return 0


def _spin(executor, stop):
    try:
        while not stop.is_set():
            executor.spin_once(timeout_sec=0.1)
    except (ExternalShutdownException, rclpy.executors.ShutdownException):
        pass


def add_arguments(p):
    p.add_argument("--world", default="pioneer-room", help="a world file or a built-in world of habla-sim")
    p.add_argument("--speed", type=float, default=1.0, help="sim time runs S times faster than the wall clock")
    p.add_argument("--seed", type=int, default=1, help="seed of the laser's and the microphone's noise")
    p.add_argument("--teacher", choices=("on", "off"), default="on", help="whether the teacher is there at the start")
    p.add_argument("--truth-port", type=int, default=8199)
    p.add_argument("--mic-port", type=int, default=8110)
    p.add_argument("--keys-port", type=int, default=8111)
    p.add_argument("--scan", default="/scan")
    p.add_argument("--odom", default="/odom")
    p.add_argument("--cmd-vel", default="/cmd_vel")
    p.add_argument("--radius", type=float, default=0.25, help="the base's radius, m")
    p.add_argument("--laser-range", type=float, default=5.0, help="the laser's reach, m")
    p.add_argument("--laser-noise", type=float, default=0.01, help="standard deviation of the laser's noise, m")
    p.add_argument("--cmd-timeout", type=float, default=0.5,
                   help="sim seconds without /cmd_vel after which the base stops")
    p.add_argument("--duration", type=float, default=0, help="stop after S seconds of sim time (0: never)")
