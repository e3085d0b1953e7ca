"""habla-ros2 body: a ROS 2 mobile base as a HABLA body.

It speaks HABLA's interface protocol (habla-interface/1, docs/protocol.md) as the interface program of a robot
does: it listens, the daemon's `habla` driver connects, and it announces three channels --
  scan       reading  vector (m)  the base's laser as a ring of sectors on its edge (sectors.py)
  odometry   reading  record      {xM, yM, thetaRad, vMps, wRadps} from the base's odometry
  motion     command  vector      [vMps, wRadps], sent to the base as geometry_msgs/Twist
-- and speaks ROS 2 to the base as REP-105 has it: /scan (sensor_msgs/LaserScan), /odom (nav_msgs/Odometry),
/cmd_vel (geometry_msgs/Twist), names configurable. A motion is sent again every --cmd-period while it is not
zero (a base controller stops when commands stop coming); a stop from HABLA, HABLA's bye, or a lost connection
sends zero at once. The daemon's safety (movement-safety, the motion watchdog) works as for any body: a silent
controller is stopped by the daemon's stop.
"""

import json
import math
import socket
import threading
import time

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
from sensor_msgs.msg import LaserScan

from habla.errors import FrameError
from habla.framing import FrameReader, encode

from .sectors import SectorRing

PROTOCOL = "habla-interface/1"
SEND_TIMEOUT_S = 1.0      # a daemon that takes nothing for this long has lost its link
RECV_BYTES = 65536


def channels(ring, max_vel, max_rot_vel):
    """The channels this body announces (and a config lists: `habla-ros2 body --print-channels`)."""
    return [
        {"name": "scan", "direction": "reading", "kind": "vector", "unit": "m", "meta": ring.meta()},
        {"name": "odometry", "direction": "reading", "kind": "record", "unit": ""},
        {"name": "motion", "direction": "command", "kind": "vector", "unit": "m/s, rad/s", "motion": True,
         "meta": {"maxVelMps": max_vel, "maxRotVelRadps": max_rot_vel}},
    ]


def stamp_us(header):
    t = header.stamp.sec * 1_000_000 + header.stamp.nanosec // 1000
    return t if t > 0 else time.time_ns() // 1000


class Body(Node):
    def __init__(self, a):
        super().__init__("habla_body")
        self.a = a
        self.ring = SectorRing(a.sectors, a.radius, a.max_range, tuple(a.laser_pose))
        self._conn = None
        self._send_lock = threading.Lock()
        self._motion = (0.0, 0.0)
        self.counts = {"scans": 0, "odometry": 0, "commands": 0, "stops": 0, "malformed": 0}
        self.cmd_pub = self.create_publisher(Twist, a.cmd_vel, QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE))
        self.create_subscription(LaserScan, a.scan, self.on_scan, qos_profile_sensor_data)
        self.create_subscription(Odometry, a.odom, self.on_odom,
                                 QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT))
        self.create_timer(a.cmd_period, self.resend)

    # -- ROS 2 -> HABLA ------------------------------------------------------------------------------------
    def on_scan(self, msg):
        value = self.ring.readings(msg.angle_min, msg.angle_increment, msg.ranges, msg.range_min, msg.range_max)
        self.counts["scans"] += 1
        self.send({"type": "reading", "channel": "scan", "t": stamp_us(msg.header), "value": value})

    def on_odom(self, msg):
        p, q, tw = msg.pose.pose.position, msg.pose.pose.orientation, msg.twist.twist
        theta = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
        self.counts["odometry"] += 1
        self.send({"type": "reading", "channel": "odometry", "t": stamp_us(msg.header),
                   "value": {"xM": p.x, "yM": p.y, "thetaRad": theta, "vMps": tw.linear.x, "wRadps": tw.angular.z}})

    # -- HABLA -> ROS 2 ------------------------------------------------------------------------------------
    def command(self, frame):
        kind = frame.get("type")
        if kind == "command" and frame.get("channel") == "motion":
            v = frame.get("value")
            if (isinstance(v, list) and len(v) == 2 and all(isinstance(x, (int, float)) and not isinstance(x, bool)
                                                          and math.isfinite(x) for x in v)):
                self.counts["commands"] += 1
                self.drive(float(v[0]), float(v[1]))
            else:
                self.counts["malformed"] += 1
                self.get_logger().warn("a motion that is not [vMps, wRadps] was ignored: %r" % (v,))
        elif kind == "stop":
            self.counts["stops"] += 1
            self.drive(0.0, 0.0)
        elif kind == "ping":
            self.send({"type": "pong"})
        elif kind == "bye":
            self.drive(0.0, 0.0)
        elif kind == "invalid":
            self.counts["malformed"] += 1

    def drive(self, v, w):
        self._motion = (v, w)
        self._publish_motion()

    def resend(self):
        if self._motion != (0.0, 0.0):
            self._publish_motion()

    def _publish_motion(self):
        t = Twist()
        t.linear.x, t.angular.z = self._motion
        self.cmd_pub.publish(t)

    # -- the daemon's connection ---------------------------------------------------------------------------
    def send(self, obj):
        with self._send_lock:
            conn = self._conn
            if conn is None:
                return
            try:
                conn.sendall(encode(obj))
            except OSError:
                self._conn = None
                try:
                    conn.shutdown(socket.SHUT_RDWR)
                except OSError:
                    pass

    def serve(self, listener, stop):
        while not stop.is_set():
            try:
                conn, peer = listener.accept()
            except socket.timeout:
                continue
            self.get_logger().info("HABLA connected from %s:%d" % peer[:2])
            conn.settimeout(SEND_TIMEOUT_S)
            with self._send_lock:
                self._conn = conn
            self.send({"type": "hello", "protocol": PROTOCOL, "robot": self.a.robot,
                       "channels": channels(self.ring, self.a.max_vel, self.a.max_rot_vel)})
            self._talk(conn, stop)
            with self._send_lock:
                self._conn = None
            conn.close()
            self.drive(0.0, 0.0)      # no HABLA, no motion
            self.get_logger().info("HABLA's connection ended; the base is stopped")

    def _talk(self, conn, stop):
        reader = FrameReader(max_line_bytes=65536, max_binary_bytes=0)
        while not stop.is_set():
            try:
                chunk = conn.recv(RECV_BYTES)
            except socket.timeout:
                continue
            except OSError:
                return
            if not chunk:
                return
            try:
                frames = reader.feed(chunk)
            except FrameError as e:
                self.get_logger().warn("HABLA's stream cannot be read: %s" % e)
                return
            for f in frames:
                self.command(f)
                if f.get("type") == "bye":
                    return


def run(a):
    ring = SectorRing(a.sectors, a.radius, a.max_range, tuple(a.laser_pose))
    if a.print_channels:
        print(json.dumps(channels(ring, a.max_vel, a.max_rot_vel), indent=1))
        return 0
    host, _, port = a.listen.rpartition(":")
    listener = socket.create_server((host or "127.0.0.1", int(port)))
    listener.settimeout(0.5)
    rclpy.init()
    body = Body(a)
    print("habla-ros2 body: listening on %s:%d for HABLA; %s, %s -> HABLA; HABLA -> %s" % (
        listener.getsockname()[:2] + (a.scan, a.odom, a.cmd_vel)), flush=True)
    stop = threading.Event()
    executor = SingleThreadedExecutor()
    executor.add_node(body)
    spinner = threading.Thread(target=lambda: _spin(executor, stop), daemon=True)
    spinner.start()
    try:
        body.serve(listener, stop)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        stop.set()
        body.drive(0.0, 0.0)
        spinner.join(2)
        listener.close()
        executor.shutdown()
        body.destroy_node()
        rclpy.try_shutdown()
    return 0


def _spin(executor, stop):
    try:
        while not stop.is_set():
            executor.spin_once(timeout_sec=0.1)
    except ExternalShutdownException:
        pass


def add_arguments(p):
    p.add_argument("--listen", default="127.0.0.1:7600", help="where HABLA's habla driver connects (HOST:PORT)")
    p.add_argument("--robot", default="ros2-base", help="the robot's name in the hello")
    p.add_argument("--scan", default="/scan", help="the base's sensor_msgs/LaserScan topic")
    p.add_argument("--odom", default="/odom", help="the base's nav_msgs/Odometry topic")
    p.add_argument("--cmd-vel", default="/cmd_vel", help="the base's geometry_msgs/Twist command topic")
    p.add_argument("--sectors", type=int, default=72, help="sectors of the laser's ring (at most 256)")
    p.add_argument("--radius", type=float, default=0.25, help="the base's footprint radius, m")
    p.add_argument("--max-range", type=float, default=4.75, help="the ring's reach from the edge, m")
    p.add_argument("--laser-pose", type=float, nargs=3, default=[0.0, 0.0, 0.0], metavar=("X", "Y", "THETA"),
                   help="the laser's pose in base_link (m, m, rad)")
    p.add_argument("--max-vel", type=float, default=0.75, help="the base's top speed, m/s (the motion channel's metadata)")
    p.add_argument("--max-rot-vel", type=float, default=1.74, help="the base's top turn rate, rad/s")
    p.add_argument("--cmd-period", type=float, default=0.1, help="a motion is sent again this often, s")
    p.add_argument("--print-channels", action="store_true", help="print the channels for a config's interface, and exit")
