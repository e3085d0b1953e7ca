"""The naming rule and the sample -> message mapping, without a daemon."""

import math

import pytest

import habla
from habla_ros2 import mapping, names


@pytest.mark.parametrize("name, token", [("pioneer-2dx", "pioneer_2dx"), ("distance_angle", "distance_angle"),
                                         ("2d.lidar", "n2d_lidar"), ("--a--b--", "a_b"), ("", "unnamed"),
                                         ("Rover 7", "Rover_7")])
def test_names_become_valid_ros_2_tokens(name, token):
    assert names.token(name) == token


def test_a_sockets_main_output_takes_its_topic_and_the_others_go_under_it():
    assert names.main_output("action", ["motion", "action"]) == "action"
    assert names.main_output("ranges", ["out"]) == "out"
    assert names.output_topic("pioneer-2dx", "action", "motion", False) == "/habla/pioneer_2dx/action/motion"
    assert names.output_topic("x", "s", "state", False) == "/habla/x/s/state_out"
    assert names.set_topic("pioneer-2dx", "action", "action", True) == "/habla/pioneer_2dx/action/set"


def sample(value, t_us=1_700_000_000_123_456, **extra):
    return habla.Sample(dict({"type": "sample", "output": "o", "seq": 3, "t": t_us, "stale": False, "value": value},
                             **extra))


def test_a_motion_vector_is_a_twist_and_a_pose_record_a_stamped_pose():
    twist = mapping.carrier_of(habla.Output("motion", "vector", "m/s, rad/s", ["vMps", "wRadps"], ""))
    assert twist.name == "geometry_msgs/Twist" and not twist.stamped
    m = twist.message(sample([0.25, -0.6]), "base_link")
    assert (m.linear.x, m.angular.z) == (0.25, -0.6)
    pose = mapping.carrier_of(habla.Output("pose", "record", "", ["xM", "yM", "thetaRad"], ""))
    p = pose.message(sample({"xM": 1.0, "yM": 2.0, "thetaRad": 0.5}), "odom")
    assert (p.header.stamp.sec, p.header.stamp.nanosec) == (1_700_000_000, 123_456_000)
    assert 2 * math.atan2(p.pose.orientation.z, p.pose.orientation.w) == pytest.approx(0.5)


def test_an_evenly_spaced_ring_is_a_laser_scan_and_an_uneven_one_is_binned_by_bearing():
    n, radius = 8, 0.25
    poses = [{"xM": radius * math.cos(a), "yM": radius * math.sin(a), "thetaRad": a}
             for a in (-math.pi + 2 * math.pi * i / n for i in range(n))]
    carrier = mapping.carrier_of(habla.Output("scan", "record", "", ["rangesM", "valid", "maxRangesM", "poses?"], ""))
    msg = carrier.message(sample({"rangesM": [1.0] * n, "valid": [True] * (n - 1) + [False], "maxRangesM": [5.0] * n,
                                  "poses": poses}), "base_link")
    assert msg.angle_min == pytest.approx(-math.pi) and msg.angle_increment == pytest.approx(2 * math.pi / n)
    assert list(msg.ranges[:-1]) == pytest.approx([1.25] * (n - 1)) and math.isinf(msg.ranges[-1])
    poses[3]["thetaRad"] += 0.3
    poses[3]["yM"] += 0.1
    uneven = carrier.message(sample({"rangesM": [1.0] * n, "valid": [True] * n, "maxRangesM": [5.0] * n,
                                     "poses": poses}), "base_link")
    assert len(uneven.ranges) == 360 and sum(1 for r in uneven.ranges if math.isfinite(r)) == n


def test_any_other_record_travels_as_the_samples_json():
    carrier = mapping.carrier_of(habla.Output("link", "record", "", ["connected"], ""))
    assert carrier.name == "std_msgs/String (JSON)" and carrier.stamped
    assert '"seq":3' in carrier.message(sample({"connected": True}), "x").data
