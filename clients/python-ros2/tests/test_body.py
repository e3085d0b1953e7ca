"""A ROS 2 base as a HABLA body: the simulated ROS 2 base, habla-ros2 body and the daemon with
config/ros2-base.json; what the control contract's sockets say and do, checked on the sim's ground truth."""

import argparse
import json
import math
import os

import pytest

import habla
from base_rig import BaseRig
from deployment import HOME
from habla_ros2 import body
from habla_ros2.sectors import SectorRing

WAIT_S = 30


def long_actions(root):
    """An action held for 20 s, so that only the motion watchdog can stop a silent controller's base."""
    for m in root["methods"]:
        if m["id"] == "action":
            m["params"]["durationMs"] = 20000


@pytest.fixture(scope="module")
def rig(tmp_path_factory):
    r = BaseRig(str(tmp_path_factory.mktemp("base")), tweak=long_actions)
    try:
        yield r.start()
    finally:
        r.close()


def read_config(name):
    with open(os.path.join(HOME, "config", name)) as f:
        return json.load(f)


def test_the_config_lists_the_channels_the_body_announces():
    p = argparse.ArgumentParser()
    body.add_arguments(p)
    a = p.parse_args([])
    announced = body.channels(SectorRing(a.sectors, a.radius, a.max_range), a.max_vel, a.max_rot_vel)
    robot = next(i for i in read_config("ros2-base.json")["interfaces"] if i["id"] == "robot")
    assert robot["params"]["channels"] == announced


def test_the_base_exposes_the_sockets_of_the_pioneer():
    def sockets(name):
        return {m["expose"].get("name", m["id"]): (m["expose"]["port"], m["type"])
                for m in read_config(name)["methods"] if "expose" in m}
    assert sockets("ros2-base.json") == sockets("pioneer.json")


def test_the_ring_reads_the_distance_from_the_edge_in_the_sector_of_the_bearing():
    ring = SectorRing(8, 0.25, 4.75)
    ranges = [math.inf] * 360
    ranges[180 + 45] = 1.25          # a point 1.25 m from the centre at +45 degrees
    got = ring.readings(-math.pi, 2 * math.pi / 360, ranges, 0.05, 5.0)
    assert got[5] == pytest.approx(1.0) and all(v == 4.75 for i, v in enumerate(got) if i != 5)


def test_distance_angle_reports_the_object_as_the_ground_truth_has_it(rig):
    with habla.connect("127.0.0.1", rig.ports["distance_angle"]) as da:
        for x, y, theta in ((5.5, 7.0, 0.0), (6.0, 6.0, 0.3), (7.4, 5.6, 2.2), (8.0, 7.6, -2.0)):
            rig.truth.place(x, y, theta)
            rig.truth.after(0.5)
            v = [da.next_sample(10) for _ in range(8)][-1].value
            truth = rig.truth.latest()
            assert v["seen"]
            assert abs(v["distanceM"] - truth["distanceM"]) <= 0.05, (x, y, v, truth)
            assert abs(math.remainder(v["angleRad"] - truth["angleRad"], 2 * math.pi)) <= math.radians(5), (v, truth)


def test_an_action_moves_the_base_and_a_silent_controller_is_stopped(rig):
    before = rig.truth.place(4.0, 4.0, 0.0)
    with habla.connect("127.0.0.1", rig.ports["action"]) as action:
        action.write_and_wait("forward")
        moving = rig.truth.after(1.5)
        assert moving["robot"]["xM"] - before["robot"]["xM"] > 0.1
        # silent from now on: the watchdog (3 s) stops the base although the action is held for 20 s
        rig.truth.after(4.0)
        a = rig.truth.latest()["robot"]
        b = rig.truth.after(1.0)["robot"]
    assert math.hypot(b["xM"] - a["xM"], b["yM"] - a["yM"]) < 0.005, (a, b)


def test_movement_safety_vetoes_driving_into_the_object(rig):
    rig.truth.place(6.35, 7.0, 0.0)     # facing the object, 0.2 m from its edge
    with habla.connect("127.0.0.1", rig.ports["action"]) as action:
        rig.truth.after(0.5)
        action.write_and_wait("forward")
        seen = []
        while not any(e.get("notice") == "veto" for e in seen):
            try:
                action.next_sample(timeout=WAIT_S)
            except TimeoutError:
                break
            seen = list(action.events)
        veto = next(e for e in seen if e.get("notice") == "veto")
        after = rig.truth.after(1.0)
        action.write_and_wait("stop")
    assert veto["detail"]["reason"] == "obstacle_ahead"
    assert after["distanceM"] >= 0.15, after


def test_the_teachers_note_and_reward_reach_the_contracts_sockets(rig):
    with habla.connect("127.0.0.1", rig.ports["command"]) as command, \
            habla.connect("127.0.0.1", rig.ports["reward"]) as reward:
        rig.truth.send({"op": "note", "label": "right"})
        rig.truth.send({"op": "reward", "value": 1})
        assert command.next_sample(WAIT_S).value == "right"
        assert reward.next_sample(WAIT_S).value == 1.0
