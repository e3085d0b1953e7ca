"""Which ROS 2 message carries a socket's samples, and how a sample becomes one (and a message a value).

| the output's shape (from the hello)                          | message                     | stamp        |
| ------------------------------------------------------------ | --------------------------- | ------------ |
| number                                                       | std_msgs/Float64            | /sample JSON |
| text                                                         | std_msgs/String             | /sample JSON |
| vector of [vMps, wRadps] (fields, or unit "m/s, rad/s")      | geometry_msgs/Twist         | /sample JSON |
| other vector                                                 | std_msgs/Float64MultiArray  | /sample JSON |
| record with xM, yM, thetaRad and vMps, wRadps                | nav_msgs/Odometry           | header       |
| record with xM, yM, thetaRad                                 | geometry_msgs/PoseStamped   | header       |
| record of a range scan with poses (rangesM, valid, ...)       | sensor_msgs/LaserScan       | header       |
| image (jpeg, png)                                            | sensor_msgs/CompressedImage | header       |
| anything else (other records, audio)                         | std_msgs/String: the JSON   | in the JSON  |

Messages without a header cannot carry the source time: their topic gets a companion <topic>/sample, a
std_msgs/String with the sample's JSON line (output, seq, t, stale, value).
"""

import json
import math

from builtin_interfaces.msg import Time
from geometry_msgs.msg import PoseStamped, Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import CompressedImage, LaserScan
from std_msgs.msg import Float64, Float64MultiArray, String

MOTION_FIELDS = ["vMps", "wRadps"]
MOTION_UNIT = "m/s, rad/s"
POSE_FIELDS = {"xM", "yM", "thetaRad"}
SCAN_FIELDS = {"rangesM", "valid", "maxRangesM"}
EVEN_BEARINGS_RAD = 1e-3   # bearings this close to evenly spaced make a range scan's own LaserScan
UNEVEN_BINS = 360          # bearing bins (1 degree) of the LaserScan of a ring at uneven bearings


def stamp(t_us):
    """A source time in microseconds since the epoch as a ROS 2 time."""
    t_us = int(t_us or 0)
    return Time(sec=t_us // 1_000_000, nanosec=(t_us % 1_000_000) * 1000)


def _fields(output):
    return {f.rstrip("?") for f in output.fields}


class Carrier:
    """How one output travels: its message type, whether the message carries the source time (in a header or
    in the JSON), and sample -> message."""

    def __init__(self, name, msg_type, convert, stamped):
        self.name, self.msg_type, self._convert, self.stamped = name, msg_type, convert, stamped

    def message(self, sample, frame_id):
        """The sample as this carrier's message, or None where this sample does not fit (it goes as JSON)."""
        return self._convert(sample, frame_id)


def carrier_of(output):
    """The carrier of an output of a socket's hello."""
    fields = _fields(output)
    if output.kind == "number":
        return Carrier("std_msgs/Float64", Float64, lambda s, f: Float64(data=_float(s.value)), False)
    if output.kind == "text":
        return Carrier("std_msgs/String", String, lambda s, f: String(data=str(s.value)), False)
    if output.kind == "vector" and (output.fields == MOTION_FIELDS or output.unit == MOTION_UNIT):
        return Carrier("geometry_msgs/Twist", Twist, _twist, False)
    if output.kind == "vector":
        return Carrier("std_msgs/Float64MultiArray", Float64MultiArray,
                       lambda s, f: Float64MultiArray(data=[_float(x) for x in s.value or []]), False)
    if output.kind == "record" and POSE_FIELDS <= fields and {"vMps", "wRadps"} <= fields:
        return Carrier("nav_msgs/Odometry", Odometry, _odometry, True)
    if output.kind == "record" and POSE_FIELDS <= fields:
        return Carrier("geometry_msgs/PoseStamped", PoseStamped, _pose, True)
    if output.kind == "record" and SCAN_FIELDS <= fields:
        return Carrier("sensor_msgs/LaserScan", LaserScan, _scan, True)
    if output.kind == "image":
        return Carrier("sensor_msgs/CompressedImage", CompressedImage, _image, True)
    return json_carrier()


def json_carrier():
    return Carrier("std_msgs/String (JSON)", String, lambda s, f: String(data=sample_json(s)), True)


def sample_json(sample):
    """The sample's line as the daemon sent it, without a binary body."""
    line = {k: v for k, v in sample.line.items() if k != "_bytes"}
    return json.dumps(line, separators=(",", ":"))


def _float(x):
    return float(x) if isinstance(x, (int, float)) and not isinstance(x, bool) else math.nan


def _twist(sample, frame_id):
    v = sample.value if isinstance(sample.value, list) else []
    msg = Twist()
    msg.linear.x = _float(v[0]) if len(v) > 0 else math.nan
    msg.angular.z = _float(v[1]) if len(v) > 1 else math.nan
    return msg


def _pose_into(pose, value):
    pose.position.x = _float(value.get("xM"))
    pose.position.y = _float(value.get("yM"))
    theta = _float(value.get("thetaRad"))
    pose.orientation.z = math.sin(theta / 2)
    pose.orientation.w = math.cos(theta / 2)


def _pose(sample, frame_id):
    msg = PoseStamped()
    msg.header.stamp = stamp(sample.t_us)
    msg.header.frame_id = frame_id
    _pose_into(msg.pose, sample.value or {})
    return msg


def _odometry(sample, frame_id):
    msg = Odometry()
    msg.header.stamp = stamp(sample.t_us)
    msg.header.frame_id = frame_id
    msg.child_frame_id = "base_link"
    value = sample.value or {}
    _pose_into(msg.pose.pose, value)
    msg.twist.twist.linear.x = _float(value.get("vMps"))
    msg.twist.twist.angular.z = _float(value.get("wRadps"))
    return msg


def _scan(sample, frame_id):
    """A range scan as seen from the robot's centre: a ring at evenly spaced bearings keeps its layout; any other
    ring's echoes are put in 1-degree bins round the robot (the nearest echo of each, inf where none)."""
    value = sample.value or {}
    ranges, valid, reach, poses = (value.get(k) or [] for k in ("rangesM", "valid", "maxRangesM", "poses"))
    n = len(ranges)
    if n < 2 or len(poses) != n or len(valid) != n or len(reach) != n:
        return None
    points, bearings = [], []
    for r, p in zip(ranges, poses):
        c, s = math.cos(p["thetaRad"]), math.sin(p["thetaRad"])
        points.append((p["xM"] + r * c, p["yM"] + r * s))
        bearings.append(math.atan2(p["yM"], p["xM"]) if (p["xM"] or p["yM"]) else p["thetaRad"])
    unwrapped = [bearings[0]]
    for b in bearings[1:]:
        d = math.remainder(b - unwrapped[-1], 2 * math.pi)
        unwrapped.append(unwrapped[-1] + d)
    step = (unwrapped[-1] - unwrapped[0]) / (n - 1)
    msg = LaserScan()
    msg.header.stamp = stamp(sample.t_us)
    msg.header.frame_id = frame_id
    msg.range_min = 0.0
    msg.range_max = float(max(math.hypot(p["xM"], p["yM"]) + m for p, m in zip(poses, reach)))
    if step != 0 and all(abs(unwrapped[0] + i * step - b) <= EVEN_BEARINGS_RAD for i, b in enumerate(unwrapped)):
        msg.angle_min, msg.angle_increment = unwrapped[0], step
        msg.ranges = [math.hypot(x, y) if ok else math.inf for (x, y), ok in zip(points, valid)]
    else:   # a ring of sensors at uneven bearings (a sonar ring): its echoes, binned by bearing round the robot
        bins = [math.inf] * UNEVEN_BINS
        msg.angle_min, msg.angle_increment = -math.pi, 2 * math.pi / UNEVEN_BINS
        for (x, y), ok in zip(points, valid):
            if ok:
                k = int((math.atan2(y, x) + math.pi) / msg.angle_increment) % UNEVEN_BINS
                bins[k] = min(bins[k], math.hypot(x, y))
        msg.ranges = bins
    msg.angle_max = msg.angle_min + msg.angle_increment * (len(msg.ranges) - 1)
    return msg


def _image(sample, frame_id):
    if sample.data is None:
        return None
    msg = CompressedImage()
    msg.header.stamp = stamp(sample.t_us)
    msg.header.frame_id = frame_id
    msg.format = str(sample.line.get("encoding", "jpeg"))
    msg.data = sample.data
    return msg


def setter_of(kind):
    """The message type a control input of that kind takes on its /set topic, and message -> value."""
    if kind == "number":
        return "std_msgs/Float64", Float64, lambda m: m.data
    if kind == "text":
        return "std_msgs/String", String, lambda m: m.data
    if kind == "vector":
        return "std_msgs/Float64MultiArray", Float64MultiArray, lambda m: list(m.data)
    return "std_msgs/String (JSON)", String, lambda m: json.loads(m.data)
